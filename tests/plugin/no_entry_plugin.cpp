// A shared library that is no strategy plug-in: it lacks the entry point, and `argus` must say
// so, naming the file, and exit 2.
extern "C" int argus_not_a_strategy() {
  return 0;
}

// Fuzzes the scenario loader (config::parse_scenario) on any text.
//
// A text either loads or is refused with config::scenario_error; any other exception escapes
// and the fuzzer reports it. What loads must survive config::to_yaml: written and read back, it
// is the same scenario (config/scenario_writer.hpp promises so).

#include <string>

#include "config/scenario_loader.hpp"
#include "config/scenario_writer.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace argus::config;
  const std::string source = "fuzz.yaml";
  scenario loaded;
  try {
    loaded = parse_scenario(argus::fuzz::text_of(data, size), source);
  } catch (const scenario_error&) {
    return 0;
  }
  const auto written = to_yaml(loaded);
  scenario again;
  try {
    again = parse_scenario(written, source);
  } catch (const scenario_error& e) {
    std::fprintf(stderr, "to_yaml wrote a scenario that does not load:\n%s\n---\n%s\n", e.what(),
                 written.c_str());
    ARGUS_FUZZ_CHECK(!"to_yaml's output loads");
  }
  ARGUS_FUZZ_CHECK(again == loaded);
  return 0;
}

// Fuzzes the station layout loader (world::parse_layout) on any text: it loads or is refused
// with config::scenario_error; any other exception escapes and the fuzzer reports it.

#include <string>

#include "tests/fuzz/fuzz_check.hpp"
#include "world/layout_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)argus::world::parse_layout(argus::fuzz::text_of(data, size), "fuzz_layout.yaml");
  } catch (const argus::config::scenario_error&) {
  }
  return 0;
}

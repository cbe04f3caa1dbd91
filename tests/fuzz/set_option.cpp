// Fuzzes `--set KEY=VALUE` (apps/set_option.hpp): the texts as config::parse_field_override
// reads them, put into a small scenario's YAML tree by the loader (config::parse_scenario with
// overrides).
//
// Input: one KEY=VALUE a line. A line that is not KEY=VALUE is refused on the command line
// (add_set_option's check) and left out here. The scenario then loads or is refused with
// config::scenario_error; any other exception escapes and the fuzzer reports it.

#include <string>
#include <vector>

#include "config/field_override.hpp"
#include "config/scenario_loader.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

// scenarios/minimal.yaml with a list of each kind, so that paths like tasks.0.at,
// cameras.*.imaging.noise_sigma and faults.1.length reach something.
constexpr const char* base_scenario = R"(name: fuzz_set
run: {seed: 1, duration: 20 s, tick: 1/15 s, speed: 0}
world: {population: 20, spawn_rate_per_min: 30, partitions: 1}
cameras:
  - {id: 1, position: [1, 1], pan_deg: 36, imaging: {noise_sigma: 2}}
  - {id: 2, position: [39, 1], pan_deg: 144}
  - {id: 3, position: [39, 29], pan_deg: -144, type: static}
network: {communication_range_m: 60, adjacency: [[1, 2], [2, 3]]}
controller: {solver: bound_solv}
tasks:
  - {at: 2 s, first_to_enter: 1, cameras_wanted: 2}
  - {at: 3 s, pixel: [160, 120], camera: 2, cancel_at: 10 s}
faults:
  - {at: 10 s, kind: crash_and_recover, camera: 3, length: 5 s}
  - {at: 12 s, kind: link_cut, camera: 1, peer: 2}
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace argus::config;
  const auto input = argus::fuzz::text_of(data, size);
  std::vector<field_override> overrides;
  std::size_t at = 0;
  while (at <= input.size() && overrides.size() < 16) {
    const auto end = std::min(input.find('\n', at), input.size());
    if (auto parsed = parse_field_override(input.substr(at, end - at))) {
      ARGUS_FUZZ_CHECK(!parsed->path.empty());
      overrides.push_back(std::move(*parsed));
    }
    at = end + 1;
  }
  try {
    (void)parse_scenario(base_scenario, "fuzz_set.yaml", overrides);
  } catch (const scenario_error&) {
  }
  return 0;
}

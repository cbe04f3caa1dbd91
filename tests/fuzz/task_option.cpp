// Fuzzes `--task SPEC` (apps/task_option.hpp): apps::load_with_tasks with the fuzzer's specs
// added to a small scenario file.
//
// Input: one SPEC a line (`at=10s,camera=7,pixel=160x120`). A spec is accepted, refused on the
// command line (CLI::ValidationError naming --task) or refused by the loader
// (config::scenario_error); any other exception escapes and the fuzzer reports it.

#include "apps/task_option.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "CLI/CLI.hpp"
#include "config/scenario_error.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

constexpr const char* base_scenario = R"(name: fuzz_task
run: {seed: 1, duration: 20 s, tick: 1/15 s, speed: 0}
world: {population: 20, spawn_rate_per_min: 30, partitions: 1}
cameras:
  - {id: 1, position: [1, 1], pan_deg: 36}
  - {id: 7, position: [39, 1], pan_deg: 144}
network: {communication_range_m: 60}
tasks:
  - {at: 2 s, first_to_enter: 1, cameras_wanted: 2}
)";

/// The scenario file, written once into a fresh temporary folder and removed at exit.
const std::string& scenario_file() {
  static const std::string path = [] {
    std::string folder = (std::filesystem::temp_directory_path() / "argus_fuzz_task.XXXXXX");
    if (::mkdtemp(folder.data()) == nullptr) std::abort();
    const auto file = folder + "/scenario.yaml";
    std::ofstream(file) << base_scenario;
    static const std::string remove = folder;
    std::atexit([] { std::filesystem::remove_all(remove); });
    return file;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto input = argus::fuzz::text_of(data, size);
  std::vector<std::string> tasks;
  std::size_t at = 0;
  while (at <= input.size() && tasks.size() < 8) {
    const auto end = std::min(input.find('\n', at), input.size());
    tasks.emplace_back(input.substr(at, end - at));
    at = end + 1;
  }
  try {
    const auto loaded = argus::apps::load_with_tasks(scenario_file(), {}, tasks);
    ARGUS_FUZZ_CHECK(loaded.tasks.size() == 1 + tasks.size());
  } catch (const CLI::ValidationError&) {
  } catch (const argus::config::scenario_error&) {
  }
  return 0;
}

#pragma once

// What the surveillance tests share: the emulated Penn Station, cut short, and a run's events.

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "actors/run_scenario.hpp"
#include "config/scenario_loader.hpp"
#include "nlohmann/json.hpp"

namespace argus::actors::surveillance_runs {

inline config::scenario station(double seconds, const std::string& out) {
  auto s = config::load_scenario(std::filesystem::path(ARGUS_SOURCE_DIR) /
                                 "scenarios/penn_station_emulated.yaml");
  s.run.duration = config::seconds{seconds};
  s.run.threads = 2;
  s.run.output_dir = (std::filesystem::temp_directory_path() / out).string();
  return s;
}

inline std::vector<nlohmann::json> events_of(const run_outcome& o) {
  std::vector<nlohmann::json> events;
  std::ifstream in(o.output_dir / "events.jsonl");
  for (std::string line; std::getline(in, line);) events.push_back(nlohmann::json::parse(line));
  return events;
}

}  // namespace argus::actors::surveillance_runs

#include "actors/recorder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "actors/system_config.hpp"
#include "nlohmann/json.hpp"

namespace argus::actors {
namespace {

std::vector<std::string> lines_of(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

sim_event event(std::int64_t tick, std::string source, std::string kind, std::string fields) {
  sim_event e;
  e.tick = tick;
  e.source = std::move(source);
  e.kind = std::move(kind);
  e.fields_json = std::move(fields);
  return e;
}

TEST(recorder, writes_one_json_object_per_event_and_a_summary_only_when_done) {
  auto dir =
      std::filesystem::temp_directory_path() / ("argus-recorder-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  system_config cfg(1);
  caf::actor_system sys{cfg};
  recorder_settings rs;
  rs.output_dir = dir;
  rs.scenario = "unit";
  rs.seed = 9;
  rs.tick_seconds = 0.5;
  auto rec = spawn_recorder(sys, rs);
  caf::scoped_actor self{sys};
  std::vector<sim_event> batch{event(3, "camera/7", "node_up", R"("camera":7)"),
                               event(3, "script", "task_issued", "")};
  self->request(rec, caf::infinite, record_atom_v, std::int64_t{3}, batch)
      .receive([](recorded_atom, std::int64_t tick) { EXPECT_EQ(tick, 3); },
               [](caf::error& err) { ADD_FAILURE() << to_string(err); });
  // Nothing final exists before the run is done: no half-written outputs.
  EXPECT_FALSE(std::filesystem::exists(dir / "events.jsonl"));
  EXPECT_FALSE(std::filesystem::exists(dir / "summary.json"));
  run_result r;
  r.ticks = 10;
  r.virtual_seconds = 5.0;
  r.wall_seconds = 0.5;
  self->request(rec, caf::infinite, done_atom_v, r)
      .receive(
          [&](run_result& done) {
            EXPECT_EQ(done.events_total, 2u);
            EXPECT_EQ(done.events_by_kind.at("node_up"), 1u);
          },
          [](caf::error& err) { ADD_FAILURE() << to_string(err); });
  auto lines = lines_of(dir / "events.jsonl");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], R"({"t":1.500000,"tick":3,"source":"camera/7","kind":"node_up","camera":7})");
  auto second = nlohmann::json::parse(lines[1]);
  EXPECT_EQ(second["kind"], "task_issued");
  std::ifstream summary_in(dir / "summary.json");
  auto summary = nlohmann::json::parse(summary_in);
  EXPECT_EQ(summary["scenario"], "unit");
  EXPECT_EQ(summary["seed"], 9);
  EXPECT_EQ(summary["ticks"], 10);
  EXPECT_EQ(summary["events_total"], 2);
  EXPECT_EQ(summary["events_by_kind"]["task_issued"], 1);
  EXPECT_DOUBLE_EQ(summary["speed_ratio"].get<double>(), 10.0);
  EXPECT_FALSE(std::filesystem::exists(dir / "events.jsonl.partial"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace argus::actors

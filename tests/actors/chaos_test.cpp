// Chaos on real threads: random node crashes, a crash-and-recover, a link cut and heal, a loss
// burst and a delay spike. The clock must never stall, every message must be accounted for, and the
// event log must not depend on the thread count.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "actors/run_scenario.hpp"
#include "nlohmann/json.hpp"

namespace argus::actors {
namespace {

config::scenario chaos(const std::filesystem::path& out, unsigned threads) {
  config::scenario s;
  s.name = "chaos";
  s.run.seed = 99;
  s.run.duration = config::seconds{60.0};
  s.run.threads = threads;
  s.run.output_dir = out.string();
  s.world.population = 10;
  for (int i = 0; i < 12; ++i) {  // a 4 x 3 grid, 20 m apart; range 25 m: grid neighbours
    config::camera_settings c;
    c.id = i + 1;
    c.position = {20.0 * (i % 4), 20.0 * (i / 4)};
    s.cameras.push_back(c);
  }
  s.network.communication_range_m = 25.0;
  s.network.node_failure_probability = 0.02;  // per second: most nodes die within the minute
  s.network.duplicate_probability = 0.05;
  config::fault recover;
  recover.at = config::seconds{10.0};
  recover.kind = config::fault_kind::crash_and_recover;
  recover.camera = 6;
  recover.length = config::seconds{10.0};
  config::fault cut;
  cut.at = config::seconds{5.0};
  cut.kind = config::fault_kind::link_cut;
  cut.camera = 1;
  cut.peer = 2;
  config::fault heal = cut;
  heal.at = config::seconds{25.0};
  heal.kind = config::fault_kind::link_heal;
  config::fault burst;
  burst.at = config::seconds{15.0};
  burst.kind = config::fault_kind::loss_burst;
  burst.camera = 7;
  burst.length = config::seconds{5.0};
  burst.loss_probability = 0.9;
  config::fault spike;
  spike.at = config::seconds{30.0};
  spike.kind = config::fault_kind::delay_spike;
  spike.camera = 5;
  spike.length = config::seconds{10.0};
  spike.delay = config::seconds{2.0};
  s.faults = {recover, cut, heal, burst, spike};
  return s;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(chaos, random_crashes_never_stall_the_clock_and_every_message_is_accounted_for) {
  auto base =
      std::filesystem::temp_directory_path() / ("argus-chaos-" + std::to_string(::getpid()));
  std::filesystem::remove_all(base);
  std::string reference;
  for (unsigned threads : {1u, 2u, 4u}) {
    auto dir = base / std::to_string(threads);
    auto outcome = run_scenario(chaos(dir, threads), false);
    EXPECT_EQ(outcome.result.ticks, 900) << threads << " threads";
    EXPECT_TRUE(outcome.result.unexpected_down.empty());
    std::ifstream summary_in(dir / "summary.json");
    auto summary = nlohmann::json::parse(summary_in);
    EXPECT_EQ(summary["network"]["invariant_holds"], true);
    EXPECT_GT(summary["network"]["totals"]["dropped"].get<int>(), 0);  // crashed nodes
    EXPECT_GT(summary["network"]["totals"]["lost"].get<int>(), 0);
    EXPECT_GT(summary["network"]["totals"]["duplicated"].get<int>(), 0);
    auto events = slurp(dir / "events.jsonl");
    EXPECT_NE(events.find(R"("random":true)"), std::string::npos);
    EXPECT_NE(events.find("node_recovered"), std::string::npos);
    EXPECT_NE(events.find("neighbour_lost"), std::string::npos);
    if (reference.empty())
      reference = events;
    else
      EXPECT_EQ(events, reference) << "event log differs with " << threads << " threads";
  }
  std::filesystem::remove_all(base);
}

}  // namespace
}  // namespace argus::actors

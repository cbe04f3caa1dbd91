// Same seed, same event log, whatever the thread count and pacing: a real multithreaded run
// of participants that exchange randomised mail across phases and threads.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "actors/clock.hpp"
#include "actors/recorder.hpp"
#include "actors/system_config.hpp"
#include "tests/actors/chatter.hpp"
#include "tests/actors/file_text.hpp"

namespace argus::actors::testing {
namespace {

struct run_spec {
  unsigned threads = 1;
  double speed = 0.0;
  std::uint64_t seed = 42;
  std::int64_t ticks = 150;
  bool clock_thread = false;  // the clock on a thread of its own
};

// Runs 32 chatters (8 per phase; every other one on demand) and returns events.jsonl.
std::string run_chatters(const run_spec& spec, const std::string& tag) {
  auto dir = std::filesystem::temp_directory_path() /
             ("argus-determinism-" + std::to_string(::getpid()) + "-" + tag);
  std::filesystem::remove_all(dir);
  {
    system_config cfg(spec.threads);
    caf::actor_system sys{cfg};
    recorder_settings rs;
    rs.output_dir = dir;
    rs.scenario = "chatter";
    rs.seed = spec.seed;
    auto recorder = spawn_recorder(sys, rs);
    clock_settings cs;
    cs.end_tick = spec.ticks;
    cs.speed = spec.speed;
    cs.own_thread = spec.clock_thread;
    auto clock = spawn_clock(sys, cs, recorder, caf::actor{});
    auto peers = std::make_shared<peer_directory>();
    std::vector<participant_info> infos;
    for (std::uint64_t i = 0; i < 32; ++i) {
      participant_info info;
      info.id = 100 + i * 7;  // sparse, so that order by id differs from spawn order
      info.name = "chatter/" + std::to_string(i);
      info.tick_phase = static_cast<phase>(i % phase_count);
      info.mode = (i / phase_count) % 2 == 0 ? wake_mode::every_tick : wake_mode::on_demand;
      infos.push_back(info);
    }
    for (const auto& info : infos)
      (*peers)[info.id] =
          sys.spawn(chatter, info, spec.seed, std::shared_ptr<const peer_directory>(peers));
    for (const auto& info : infos) caf::anon_send(clock, join_atom_v, peers->at(info.id), info);
    caf::scoped_actor self{sys};
    bool ok = false;
    self->request(clock, caf::infinite, start_atom_v)
        .receive([&](run_result& r) { ok = r.ticks == spec.ticks; },
                 [&](caf::error& err) { ADD_FAILURE() << sys.render(err); });
    EXPECT_TRUE(ok);
    peers->clear();  // break the cycle actor -> directory -> actor
  }
  auto events = file_text(dir / "events.jsonl");
  std::filesystem::remove_all(dir);
  return events;
}

TEST(determinism, same_seed_same_event_log_for_any_thread_count) {
  auto reference = run_chatters({.threads = 1}, "t1");
  ASSERT_FALSE(reference.empty());
  // Mail was actually exchanged and read (not a log of empty ticks).
  EXPECT_NE(reference.find("\"read\":2"), std::string::npos);
  for (unsigned threads : {2u, 4u, 8u}) {
    auto log = run_chatters({.threads = threads}, "t" + std::to_string(threads));
    EXPECT_EQ(log, reference) << "event log differs with " << threads << " threads";
  }
}

TEST(determinism, same_event_log_with_the_clock_on_its_own_thread) {
  auto reference = run_chatters({.threads = 1}, "worker");
  for (unsigned threads : {2u, 4u}) {
    auto log =
        run_chatters({.threads = threads, .clock_thread = true}, "own" + std::to_string(threads));
    EXPECT_EQ(log, reference) << "event log differs with the clock on its own thread, " << threads
                              << " workers";
  }
}

TEST(determinism, same_event_log_when_paced) {
  auto reference = run_chatters({.threads = 2, .ticks = 45}, "free");
  auto paced = run_chatters({.threads = 2, .speed = 15.0, .ticks = 45}, "paced");
  EXPECT_EQ(paced, reference);
}

TEST(determinism, another_seed_gives_another_log) {
  auto a = run_chatters({.threads = 2, .seed = 1, .ticks = 30}, "s1");
  auto b = run_chatters({.threads = 2, .seed = 2, .ticks = 30}, "s2");
  EXPECT_NE(a, b);
}

}  // namespace
}  // namespace argus::actors::testing

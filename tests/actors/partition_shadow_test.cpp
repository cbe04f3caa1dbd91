// The coordinator's shadow of a crowd partition on a worker (actors/partition_shadow.hpp):
// stepped again from its last checkpoint, it gives the partition's pedestrians as the worker
// holds them, mind and generator included, at every tick.
//
//   world::crowd (the truth)      partition 1's pedestrians at the start of each tick
//   shadow: checkpoint, then (snapshot, arrivals) a tick --replay--> the same bytes

#include "actors/partition_shadow.hpp"

#include <gtest/gtest.h>

#include <set>

#include "actors/wire_world.hpp"
#include "caf/binary_serializer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::actors {
namespace {

// Every field a worker would send, as the bytes it would send.
std::vector<char> wire_bytes(std::vector<world::pedestrian> pedestrians) {
  std::vector<char> out;
  caf::binary_serializer sink{nullptr, out};
  EXPECT_FALSE(sink(pedestrians));
  return out;
}

TEST(partition_shadow, replays_a_partition_from_its_checkpoints_bit_for_bit) {
  world::crowd_settings settings;
  settings.run_seed = 7;
  settings.population = 300;
  settings.spawn_rate_per_min = 120;
  settings.partitions = 4;
  world::crowd crowd(world::station::load(world::builtin_layout_path()), settings);
  const std::size_t index = 1;
  partition_shadow shadow(crowd.owned()[index]);
  std::size_t arrived = 0;
  std::size_t longest_replay = 0;
  for (int k = 0; k < 15 * 40; ++k) {
    const auto previous = crowd.current();
    std::set<int> before;
    for (const auto& p : crowd.owned()[index]) before.insert(p.state.id);
    crowd.step();
    // What the worker's partition kept comes first, then what the coordinator sent it.
    const auto& now = crowd.owned()[index];
    std::size_t kept = 0;
    while (kept < now.size() && before.count(now[kept].state.id) != 0) ++kept;
    std::vector<world::pedestrian> whole(now.begin(), now.begin() + kept);
    std::vector<world::pedestrian> arrivals(now.begin() + kept, now.end());
    arrived += arrivals.size();
    const bool checkpoint = is_checkpoint_tick(static_cast<std::int64_t>(previous->tick()), index);
    shadow.stepped(previous, checkpoint ? &whole : nullptr, std::move(arrivals));
    longest_replay = std::max(longest_replay, shadow.ticks_since_checkpoint());
    ASSERT_EQ(wire_bytes(shadow.replay(crowd.where(), crowd.bounds()[index], settings.behaviour)),
              wire_bytes(now))
        << "tick " << previous->tick();
  }
  // The run must hand pedestrians over to the partition and replay several ticks.
  EXPECT_GT(arrived, 30u);
  EXPECT_EQ(longest_replay, static_cast<std::size_t>(partition_checkpoint_ticks - 1));
}

}  // namespace
}  // namespace argus::actors

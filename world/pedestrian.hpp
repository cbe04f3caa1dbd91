#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "config/clothing.hpp"
#include "world/layout.hpp"
#include "world/rng.hpp"

namespace argus::world {

/// What a pedestrian is doing, as ground truth for the recorder and the evaluation. The
/// "waiting" activities (queueing .. meeting) are the ones where standing still is normal.
enum class activity : std::uint8_t {
  walking,                ///< heading for an intermediate goal
  queueing,               ///< in a line at a ticket booth or vending machine
  buying_ticket,          ///< at the head of a ticket line, being served
  using_vending_machine,  ///< at a vending machine
  sitting,                ///< resting on a bench
  meeting,                ///< waiting for someone at a meeting point
  leaving,                ///< heading for a platform or a street exit
};

/// The name of an activity ("buying_ticket"), as written in trajectories.csv.
std::string_view to_string(activity a) noexcept;

/// Whether standing still is expected in activity `a`.
constexpr bool is_waiting(activity a) noexcept {
  return a != activity::walking && a != activity::leaving;
}

/// The goals a pedestrian pursues (Section II: buy a ticket, rest on a bench when tired, use
/// a vending machine when hungry or thirsty, meet someone, and eventually go down to the
/// platforms or leave).
enum class goal_kind : std::uint8_t {
  buy_ticket,
  rest_on_bench,
  use_vending_machine,
  meet_in_waiting_room,
  go_to_platform,
  leave_station,
};

/// Number of goal kinds.
inline constexpr std::size_t goal_kind_count = 6;

/// The name of a goal kind ("rest_on_bench").
std::string_view to_string(goal_kind g) noexcept;

/// An 8-bit sRGB colour.
struct rgb8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const rgb8&, const rgb8&) = default;
};

/// What a camera can see of a pedestrian: the colours colour indexing works on (Section
/// III-B) and the body's size. Palettes deliberately hold near-twins (two reds, two navy
/// blues) so that trackers can confuse pedestrians, as the paper notes.
struct appearance {
  rgb8 shirt;
  rgb8 trousers;
  rgb8 skin;
  rgb8 hair;
  double height_m = 1.7;
  /// Shoulder width; the body's collision disc has radius girth_m / 2 when it has room (see
  /// pedestrian_state::squeeze_m).
  double girth_m = 0.46;
  friend bool operator==(const appearance&, const appearance&) = default;
};

/// Draws an appearance: from the palettes, or with `varied` clothes of random colours (skin and
/// hair from their palettes either way).
appearance draw_appearance(rng& random, config::clothing clothes = config::clothing::palette);

/// The public, per-tick state of one pedestrian: ground truth (id, position, velocity,
/// heading, activity, body) plus what others need to coordinate deterministically (which
/// line it stands in and since when, which seat it claims). This is what a snapshot holds.
struct pedestrian_state {
  int id = 0;
  activity doing = activity::walking;
  goal_kind goal = goal_kind::go_to_platform;
  /// Service counter whose line this pedestrian is in, or -1.
  int counter = -1;
  /// Seat claimed (walking to it or sitting), or -1.
  int seat = -1;
  vec2 position{0.0, 0.0};
  vec2 velocity{0.0, 0.0};
  /// The last velocity faster than 0.1 m/s (zero before the first): the body faces along it.
  vec2 facing{0.0, 0.0};
  /// The heading drawn at placement, faced until the first step faster than 0.1 m/s.
  double placed_heading_rad = 0.0;
  appearance look;
  /// Tick it joined that line: the line is served in (join tick, id) order.
  std::uint64_t queue_join_tick = 0;
  /// Walking distance left to the current goal, metres.
  double distance_to_goal_m = 0.0;
  /// The distance field it descends (station::target), -1 when none: walkers on the same
  /// route compare distance_to_goal_m to know who is ahead.
  int route = -1;
  /// Incremented at every goal change, so observers can tell goals apart.
  std::uint32_t goal_serial = 0;
  /// How much narrower than its shoulders the body stands: a disc as wide as the shoulders
  /// overstates a torso's area by about 70 %, and people pressed together turn sideways
  /// (behaviour_settings::body_squeeze), so a slow body gives up part of its radius.
  double squeeze_m = 0.0;

  /// Radius of the collision disc.
  double radius_m() const noexcept { return look.girth_m / 2.0 - squeeze_m; }

  friend bool operator==(const pedestrian_state&, const pedestrian_state&) = default;
  /// Direction the body faces, radians from +x, counter-clockwise. Kept as a velocity and
  /// turned into an angle only when asked (the renderer, the trajectory file): in most ticks
  /// nobody asks, and an atan2 per walker per tick was 5 % of the crowd's step.
  double heading_rad() const noexcept {
    if (facing.x() == 0.0 && facing.y() == 0.0) return placed_heading_rad;
    return std::atan2(facing.y(), facing.x());
  }
};

/// A pedestrian's full state, owned by the partition that steps it: the public state plus
/// its private mind (agenda, current target, timers) and its own RNG.
struct pedestrian {
  pedestrian_state state;
  rng random;
  /// Goals to pursue in order; the last is always go_to_platform or leave_station.
  std::array<goal_kind, 6> agenda{};
  std::uint8_t agenda_size = 0;
  std::uint8_t agenda_next = 0;
  /// Preferred walking speed, m/s.
  double preferred_speed_mps = 1.3;
  /// The distance field being descended (see station::target), or -1.
  int field = -1;
  /// Index of the portal, stairs, counter, bench or meeting point targeted.
  int target_index = -1;
  /// A point to stop at (seat, queue slot, meeting spot); used when `has_point`.
  vec2 point{0.0, 0.0};
  bool has_point = false;
  /// Time left in the current waiting activity, seconds.
  double timer_s = 0.0;
  /// Progress watchdog: best distance to the goal so far and time since it improved.
  double best_distance_m = 0.0;
  double stalled_s = 0.0;
  /// Portal it came in by (-1 for stairs), so it does not leave by the same door at once.
  int entry_portal = -1;
  /// Stairs it came up by (-1 for a street portal), so it does not go straight back down.
  int entry_stairs = -1;
  /// The portal a flow pedestrian (see world/flow.hpp) leaves by, or -1.
  int flow_exit = -1;
  /// Time it has wanted to walk but stood (nearly) still: an arch or a deadlock forming.
  double blocked_s = 0.0;
  /// Time spent in a line without reaching the service point.
  double queued_s = 0.0;
};

}  // namespace argus::world

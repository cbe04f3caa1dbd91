#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "world/event.hpp"
#include "world/pedestrian.hpp"

namespace argus::world {

class snapshot;
class station;

/// Parameters of the pedestrians' locomotion (social-force model, Helbing & Molnar 1995,
/// with the anisotropy of Helbing et al. 2000) and of their minds.
struct behaviour_settings {
  /// Length of one tick (one video frame).
  double tick_s = 1.0 / 15.0;
  /// Relaxation time towards the desired velocity.
  double relaxation_s = 0.5;
  /// Pedestrian-pedestrian repulsion strength (m/s^2) and range (m).
  double social_strength = 2.0;
  double social_range_m = 0.3;
  /// Weight of interactions behind a pedestrian (1 = isotropic).
  double anisotropy = 0.3;
  /// Wall repulsion strength (m/s^2) and range (m).
  double wall_strength = 3.0;
  double wall_range_m = 0.2;
  /// Within this distance of a point target, steer straight at it instead of along the field.
  double direct_steering_m = 3.0;
  /// A walking pedestrian whose distance to its goal has not dropped by `progress_m` for
  /// `give_up_s` gives the goal up (or, for a final goal, picks another exit).
  double progress_m = 0.5;
  double give_up_s = 20.0;
};

/// Creates pedestrian `id` at `position`, drawing its appearance, speed and agenda from its
/// own RNG (seeded with config::derive_seed from `run_seed` and `id`). `entry_portal` is
/// the street portal it came in by, or -1 (stairs, or placed at start). Its first goal
/// begins at its first step.
pedestrian make_pedestrian(int id, std::uint64_t run_seed, const vec2& position, int entry_portal,
                           bool from_platform);

/// One tick of one pedestrian, phase one of the two-phase step: decides (behaviour state
/// machine) and moves (social force plus non-penetration constraints) using only `previous`
/// and the pedestrian's own state, so every pedestrian can be stepped in any order, on any
/// thread, with the same result. Returns nothing when it left the station. Appends its
/// events to `events`.
///
/// Behaviour state machine (activity, by goal):
///
/// ```
///  spawn -> walking --near counter--> queueing --head of line--> buying_ticket /
///             |  ^                       (rank from snapshot)    using_vending_machine
///             |  +---------- served / rested / met --------------------+
///             |--seat won, reached--> sitting --rested--> (next goal)
///             |--meeting spot reached--> meeting --waited--> (next goal)
///             '--last goal--> leaving --in stairs / street portal--> (gone)
/// ```
///
/// Non-penetration: each neighbour j at gap g adds the half-plane v.n <= g / (2 dt) (each of
/// the pair takes at most half the gap; v = 0 always satisfies it), each wall at gap g adds
/// v.n <= g / dt. The velocity is projected onto the violated half-planes, then scaled down
/// until all hold, so no two discs overlap and no one crosses a wall, by construction.
std::optional<pedestrian> step_pedestrian(const station& where, const snapshot& previous,
                                          const pedestrian& current,
                                          const behaviour_settings& settings,
                                          std::vector<event>& events);

}  // namespace argus::world

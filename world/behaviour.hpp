#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "world/event.hpp"
#include "world/pedestrian.hpp"
#include "world/speed_distribution.hpp"

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
  /// Short and stiff: stronger than the driving force at contact, so people in a jam keep a
  /// few centimetres apart and keep room to slide past each other instead of locking into
  /// arches. About half the range of Helbing et al. 2000 (25 m/s^2 over 0.08 m): over 0.08 m
  /// (at 8 m/s^2) a standing crowd kept about 10 cm apart and its densest area reached 4.8
  /// /m^2 by the Voronoi method; with these it reaches Weidmann's jam density, 5.4 /m^2, and
  /// the bottleneck flows stay in the published range (bench/RESULTS.md).
  double social_strength = 6.0;
  double social_range_m = 0.045;
  /// Beyond this many ranges the repulsion (below 5e-5 of its strength) is left out.
  double social_cutoff_ranges = 10.0;
  /// Weight of interactions behind a pedestrian (1 = isotropic).
  double anisotropy = 0.3;
  /// Compressible bodies: standing, a body's collision disc is this fraction narrower than its
  /// shoulders (people in a press turn sideways: a torso, about 0.46 m x 0.28 m, covers the
  /// area of a disc 0.77 as wide as the shoulders); walking at `body_full_speed_mps` or faster
  /// it takes its full width. The radius changes by at most `body_change_mps` and grows only
  /// into free room, so no two discs overlap. Rigid discs as wide as the shoulders pack at
  /// most about 4.2 /m^2 at random (the densest area measured with them: 4.25 /m^2), short
  /// of Weidmann's jam density, 5.4 /m^2 (bench/RESULTS.md has what these reach).
  double body_squeeze = 0.23;
  double body_full_speed_mps = 0.3;
  double body_change_mps = 0.1;
  /// Wall repulsion strength (m/s^2) and range (m).
  double wall_strength = 3.0;
  double wall_range_m = 0.2;
  /// Time gap kept to the pedestrian ahead: the desired speed is at most the free path ahead
  /// (before touching someone in one's way) over this time, the collision-free speed model's
  /// V(s) = min(v0, s / T) (Tordeux, Chraibi & Seyfried 2016, as JuPedSim uses it). In single
  /// file it gives the headway d = contact + T v; Seyfried et al. 2005 measured
  /// d = 0.36 m + 1.06 s v. Chosen with the lane below on bench/steady_flow's seed 1
  /// (bench/RESULTS.md has them on held-out seeds): 0.1 s, the value until issue 49,
  /// let dense streams walk near free speed (2.6 /(m s) at 3.3 /m^2).
  double headway_s = 0.85;
  /// Who counts as in one's way for the headway: someone whose centre lies within a fraction
  /// of body contact across one's heading (the free path is still measured to their whole
  /// body). The fraction is `headway_lane_slow` standing and grows linearly to `headway_lane`
  /// at `headway_lane_speed_mps`: slow in a press, people turn their shoulders and fit beside
  /// the one ahead; at speed whoever overlaps one's path holds one back. Chosen on
  /// bench/steady_flow's seed 1 (bench/RESULTS.md): with 0.6 at every speed a stream's core at
  /// 2.5 /m^2 walked 0.3 m/s over Weidmann's speed and bottlenecks under 1.6 m passed
  /// 1.0-1.1 /(m s), under the published 1.2-1.9; with the whole contact at speed (1.0)
  /// streams under 1 /m^2 walked 0.18 m/s under it. Standing, 0.2 (0.3 until 2026-12-07):
  /// with 0.3 the 0.8 m exit passed 1.18 /(m s) on average over 40 seeds, under the published
  /// range, and streams at 0.5-1 /m^2 walked 0.15 m/s under Weidmann (bench/RESULTS.md, "The
  /// lane standing").
  double headway_lane = 0.9;
  double headway_lane_slow = 0.2;
  double headway_lane_speed_mps = 1.0;
  /// How far ahead a walker looks, for the headway and for the heading to take (see
  /// step_pedestrian): within the neighbour index's reach (snapshot::neighbour_cell_m), and
  /// farther than headway_s times the fastest preferred speed, or the fastest never slow.
  double look_ahead_m = 2.0;
  /// A turned heading is taken only with at least this free path along it: sliding into a
  /// narrower gap is no way around anyone, and in a jam it turns the push away from the exit.
  double turn_min_free_m = 0.5;
  /// Someone coming the other way within this distance ahead, and within body contact plus
  /// the margin across one's path, makes one step aside (to the right when head on).
  double sidestep_horizon_m = 2.0;
  double sidestep_margin_m = 0.3;
  /// Within this distance of a point target, steer straight at it instead of along the field.
  double direct_steering_m = 3.0;
  /// A walking pedestrian whose distance to its goal has not dropped by `progress_m` for
  /// `give_up_s` gives the goal up (or, for a final goal, picks another exit).
  double progress_m = 0.5;
  double give_up_s = 20.0;
  /// A pedestrian in a line that has not been served after this long leaves the line.
  double queue_give_up_s = 180.0;
  /// A pedestrian that wants to walk but has stood still this long, pressed against others
  /// who stand still too, yields to the one nearest its goal (see step_pedestrian).
  double yield_after_s = 1.0;
  /// Speed at which a yielding pedestrian steps back from the one it gives way to.
  double yield_step_back_mps = 0.3;
};

/// Creates pedestrian `id` at `position`, drawing its appearance and agenda from its own RNG
/// (seeded with config::derive_seed from `run_seed` and `id`) and its preferred speed from
/// `speeds` with a second stream of its own (so the speed distribution can change without
/// changing anyone's looks or errands). `entry_portal` is the street portal it came in by and
/// `entry_stairs` the stairs it came up (an arriving passenger), each -1 when not. Its first
/// goal begins at its first step.
pedestrian make_pedestrian(int id, std::uint64_t run_seed, const vec2& position, int entry_portal,
                           int entry_stairs, const speed_distribution& speeds = {},
                           config::clothing clothes = config::clothing::palette);

/// Creates a flow pedestrian (world/flow.hpp): appearance and speed as make_pedestrian, and
/// one goal, leaving by portal `exit_portal`.
pedestrian make_flow_pedestrian(int id, std::uint64_t run_seed, const vec2& position,
                                int exit_portal, const speed_distribution& speeds = {},
                                config::clothing clothes = config::clothing::palette);

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
/// Speed: the desired speed is at most the free path s ahead (before touching someone in
/// one's way) over the headway time T, V(s) = min(v0, s / T) (the collision-free speed
/// model, Tordeux et al. 2016), so walkers slow smoothly as the gaps close and stand at
/// contact, the jam density.
///
/// Heading: a walker weighs the way itself and the way turned by 15, 30 and 45 degrees to
/// either side, each with its free path within the look-ahead H (people whose centre lies
/// within headway_lane of contact across it; walls, for the turned ones), and walks the one
/// that brings it nearest the goal after H: the least H^2 + f^2 - 2 H f cos(turn) (Moussaid,
/// Helbing & Theraulaz 2011). So a stream fans out around a slower walker into the room
/// beside it; at a free path s along the chosen heading the speed is V(s) above.
///
/// Non-penetration: each neighbour j at gap g adds the half-plane v.n <= (g / 2 - d) / dt
/// (each of the pair takes at most half the gap, less what its own radius grows by, d; v = 0
/// always satisfies it, since d is at most g / 2), each wall at gap g adds
/// v.n <= (g - d) / dt. The velocity is the point of the feasible polygon closest to the
/// social-force velocity (an incremental 2-D linear program, as RVO2 solves its ORCA
/// half-planes), so no two discs overlap and no one crosses a wall, by construction.
///
/// Merging: walkers on the same route keep their headway only to those nearer the goal
/// (ties: lower id), so two converging on a doorway do not both stop for each other.
///
/// Arches: a pedestrian that has wanted to walk but stood still for yield_after_s, pressed
/// against others ahead who stand still too, yields (steps back at yield_step_back_mps,
/// ignoring the crowd's repulsion) unless it is the one of them nearest its goal (ties:
/// lowest id). Decided from the snapshot only, so it is deterministic; one member of every
/// arch keeps pushing, the others give it room, and the arch breaks.
std::optional<pedestrian> step_pedestrian(const station& where, const snapshot& previous,
                                          const pedestrian& current,
                                          const behaviour_settings& settings,
                                          std::vector<event>& events);

}  // namespace argus::world

#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "config/scenario_error.hpp"
#include "world/field_set.hpp"
#include "world/layout.hpp"
#include "world/solid_index.hpp"

namespace argus::world {

/// A solid line segment pedestrians may not cross: a wall piece, an obstacle edge, a bench.
struct segment {
  vec2 a{0.0, 0.0};
  vec2 b{0.0, 0.0};
  /// The point of the segment closest to `p`.
  vec2 closest_point(const vec2& p) const;
};

/// A seat on a bench.
struct seat {
  vec2 position{0.0, 0.0};
  int bench = 0;
};

/// What a navigation target leads to; a pedestrian's route is the descent of the target's
/// distance field.
enum class target_kind { portal, stairs, counter, bench, meeting_point };

/// Tunables of the navigation grid.
struct navigation_settings {
  /// Grid cell size: half a shoulder width resolves the station's portals (4-6 m wide) well.
  double cell_m = 0.5;
  /// Cells whose centre is closer than this to a wall are blocked.
  double clearance_m = 0.2;
  /// Extra cost per metre walked at a wall, falling linearly to 0 at `wall_band_m` from it, so
  /// routes keep off walls.
  double wall_penalty = 0.6;
  double wall_band_m = 0.8;
  /// Whether to compute the distance fields (and check reachability with them). Off for a
  /// station that is only looked at — rendered, or seen through for visibility — as a
  /// distributed run's workers do (docs/distributed.md): then no walker may use it, and
  /// target(), distance_to() and direction_to() must not be called.
  bool fields = true;
  /// Threads that compute the distance fields side by side (0: one per core). The fields are
  /// the same for any count.
  unsigned threads = 0;
  /// Where the fields are kept between processes (world/field_cache.hpp); empty: nowhere, they
  /// are computed. Runs use field_cache::default_dir(). The fields are the same either way.
  std::filesystem::path field_cache;
};

/// The immutable station: its layout plus everything derived from it once, shared by every
/// crowd partition (read-only, so safe from any thread): solid segments with a uniform-grid
/// index, seats, and one navigation distance field per target (portal, stairs, ticket booth
/// or vending machine, bench, meeting point). The distance fields are the global path
/// planner: Dijkstra from the target over an 8-connected grid, computed once, so planning a
/// route costs a lookup (cf. Shao & Terzopoulos' precomputed path maps, paper ref. [1]).
class station {
 public:
  /// Builds everything from `plan` and checks that it can be walked; throws
  /// config::scenario_error listing every problem, each naming the layout file, the element
  /// (`stairs[6]`) and what is wrong:
  /// - every portal, stairs, counter, bench and meeting point is reachable on foot from every
  ///   entrance (street portal and stairs), and portals and stairs hold walkable floor inside
  ///   their box (a pedestrian leaves only inside it);
  /// - every slot of every counter's line (max_queue_length of them) is on walkable floor,
  ///   clear of walls, and in sight of the previous one;
  /// - street portals touch the edge of the walkable floor, internal portals join two
  ///   regions.
  explicit station(layout plan, navigation_settings settings = {});
  /// Not copied: its counters point into its own layout, so a copy's would point into the
  /// original's. A move keeps the layout's storage, and with it those pointers.
  station(const station&) = delete;
  station& operator=(const station&) = delete;
  station(station&&) = default;
  station& operator=(station&&) = default;

  /// load_layout + construct, shared for the partitions.
  static std::shared_ptr<const station> load(const std::filesystem::path& file,
                                             navigation_settings settings = {});

  /// The layout this station was built from.
  const layout& plan() const noexcept { return plan_; }

  /// All solid segments.
  const std::vector<segment>& segments() const noexcept { return segments_; }

  /// Indices of the segments that may lie within `segment_reach_m` of `p` (a superset).
  std::span<const std::uint32_t> segments_near(const vec2& p) const;

  /// Segments within this distance of a point are always in `segments_near`.
  static constexpr double segment_reach_m = 1.5;

  /// Distance from `p` to the nearest solid segment within reach (`segment_reach_m` if none).
  double wall_clearance(const vec2& p) const;

  /// Whether `p` is inside a walkable region and not inside an obstacle or a footprint.
  bool walkable(const vec2& p) const;

  /// Whether a body of `radius_m` fits at `p`: walkable, off the navigation grid's blocked
  /// cells and clear of every wall.
  bool fits(const vec2& p, double radius_m) const;

  /// Whether the straight line from `a` to `b` (at most segment_reach_m long) crosses no
  /// solid segment.
  bool line_clear(const vec2& a, const vec2& b) const;

  /// Whether the straight line from `a` to `b`, of any length, crosses no solid segment.
  bool sight_clear(const vec2& a, const vec2& b) const;

  /// Ticket booths then vending machines, numbered together as "counters".
  std::size_t counter_count() const noexcept { return counters_.size(); }
  /// Counter `index` (booths first).
  const service_counter& counter(std::size_t index) const { return *counters_[index]; }
  /// Whether counter `index` is a vending machine (else a ticket booth).
  bool is_vending_machine(std::size_t index) const noexcept {
    return index >= plan_.ticket_booths.size();
  }

  /// Every seat of every bench.
  const std::vector<seat>& seats() const noexcept { return seats_; }

  /// The distance field of target `kind`/`index`, for distance_to / direction_to.
  int target(target_kind kind, std::size_t index) const;

  /// Walking distance from `p` to target `field`, in metres (+inf where unreachable).
  double distance_to(int field, const vec2& p) const;

  /// Unit direction of steepest descent of target `field` at `p`: the way to walk, the
  /// field's gradient at the cell centres around `p` interpolated bilinearly (continuous
  /// between cells, up to walls and jambs). Zero at the target.
  vec2 direction_to(int field, const vec2& p) const;

  /// Asks the processor to fetch the rows of target `field` that distance_to and
  /// direction_to will read around `p`; changes nothing. The fields are large and read at
  /// scattered places, one walker after another: a walker's rows fetched while the one
  /// before it steps arrive in time instead of stalling its step.
  void prefetch_route(int field, const vec2& p) const;

  /// The region containing `p` (the first listed), or nullptr.
  const region* region_at(const vec2& p) const;

  /// The speed factor of the region containing `p` (1 outside every region, and everywhere
  /// when no region sets one).
  double speed_factor(const vec2& p) const {
    if (!has_speed_factors_) return 1.0;
    const region* r = region_at(p);
    return r != nullptr ? r->speed_factor : 1.0;
  }

  /// Whether the distance fields were read from navigation_settings::field_cache rather than
  /// computed, and what went wrong storing them there (empty: nothing), for the run's log.
  bool fields_from_cache() const noexcept { return fields_from_cache_; }
  const std::string& field_cache_problem() const noexcept { return field_cache_problem_; }

  /// Navigation grid geometry (for drawing and tests).
  int grid_width() const noexcept { return grid_w_; }
  int grid_height() const noexcept { return grid_h_; }
  double cell_m() const noexcept { return settings_.cell_m; }
  bool blocked(int cx, int cy) const { return blocked_[cy * grid_w_ + cx] != 0; }
  /// Target `field`'s walking distance from the centre of grid cell (cx, cy): +inf off the
  /// grid and where unreachable.
  float field_at(int field, int cx, int cy) const;

 private:
  int cell_index(const vec2& p) const;
  void build_segments();
  void build_segment_index();
  void build_grid();
  void build_fields();
  void check_lines(std::vector<config::problem>& problems) const;
  void check_portals(std::vector<config::problem>& problems) const;
  /// One field per entry of `sources` (an empty one: unreachable everywhere), computed on
  /// navigation_settings::threads threads.
  std::vector<std::vector<float>> distance_fields(
      const std::vector<std::vector<int>>& sources) const;
  /// distance_fields, read from the field cache when it holds them, and stored there when not.
  field_set cached_or_computed_fields(const std::vector<std::vector<int>>& sources);
  std::vector<float> dijkstra(const std::vector<int>& sources) const;
  // The lower-left of the four cells whose centres surround `p`: where direction_to's
  // bilinear stencil starts (and what prefetch_route fetches around).
  std::pair<int, int> stencil_corner(const vec2& p) const;

  layout plan_;
  navigation_settings settings_;
  std::vector<segment> segments_;
  std::vector<const service_counter*> counters_;
  solid_index solids_;
  std::vector<seat> seats_;
  // Segment index: uniform grid of `index_cell_m` cells, CSR layout.
  static constexpr double index_cell_m = 1.0;
  int index_w_ = 0;
  int index_h_ = 0;
  std::vector<std::uint32_t> index_start_;
  std::vector<std::uint32_t> index_items_;
  // Navigation grid.
  int grid_w_ = 0;
  int grid_h_ = 0;
  std::vector<std::uint8_t> blocked_;
  std::vector<std::uint8_t> near_wall_;
  // Cost factor of walking through each cell: 1 in the open, up to 1 + wall_penalty at a wall.
  std::vector<float> wall_cost_;
  // Bit d set: the grid edge from this cell in direction d (of the 8) crosses a wall.
  std::vector<std::uint8_t> edge_blocked_;
  field_set fields_;
  std::vector<int> field_base_;  // first field of each target_kind
  bool fields_from_cache_ = false;
  std::string field_cache_problem_;
  bool has_speed_factors_ = false;
};

}  // namespace argus::world

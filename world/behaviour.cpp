#include "world/behaviour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "config/derive_seed.hpp"
#include "opencv2/imgproc.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"
#include "world/turned_lanes.hpp"

namespace argus::world {

std::string_view to_string(activity a) noexcept {
  switch (a) {
    case activity::walking:
      return "walking";
    case activity::queueing:
      return "queueing";
    case activity::buying_ticket:
      return "buying_ticket";
    case activity::using_vending_machine:
      return "using_vending_machine";
    case activity::sitting:
      return "sitting";
    case activity::meeting:
      return "meeting";
    case activity::leaving:
      return "leaving";
  }
  return "?";
}

std::string_view to_string(goal_kind g) noexcept {
  switch (g) {
    case goal_kind::buy_ticket:
      return "buy_ticket";
    case goal_kind::rest_on_bench:
      return "rest_on_bench";
    case goal_kind::use_vending_machine:
      return "use_vending_machine";
    case goal_kind::meet_in_waiting_room:
      return "meet_in_waiting_room";
    case goal_kind::go_to_platform:
      return "go_to_platform";
    case goal_kind::leave_station:
      return "leave_station";
  }
  return "?";
}

std::string_view to_string(event_kind kind) noexcept {
  switch (kind) {
    case event_kind::spawned:
      return "spawned";
    case event_kind::left:
      return "left";
    case event_kind::goal_started:
      return "goal_started";
    case event_kind::goal_completed:
      return "goal_completed";
    case event_kind::goal_abandoned:
      return "goal_abandoned";
    case event_kind::joined_queue:
      return "joined_queue";
    case event_kind::service_started:
      return "service_started";
    case event_kind::service_finished:
      return "service_finished";
    case event_kind::sat_down:
      return "sat_down";
    case event_kind::stood_up:
      return "stood_up";
  }
  return "?";
}

namespace {

/// Stream tag that separates pedestrian RNGs from other actors' (camera ids are small too).
constexpr std::uint64_t pedestrian_stream = 0x7065646573747269ULL;  // "pedestri"

// Palettes. Near-twins on purpose (crimson/red, navy/dark blue, two greys): the trackers
// must sometimes confuse pedestrians (Section III-B).
constexpr std::array<rgb8, 16> shirts{{{200, 30, 40},
                                       {176, 24, 36},
                                       {30, 60, 150},
                                       {24, 48, 128},
                                       {40, 140, 60},
                                       {240, 240, 235},
                                       {230, 200, 40},
                                       {120, 120, 125},
                                       {105, 105, 110},
                                       {250, 130, 30},
                                       {130, 60, 150},
                                       {20, 20, 22},
                                       {90, 170, 210},
                                       {220, 120, 160},
                                       {110, 80, 50},
                                       {60, 110, 100}}};
constexpr std::array<rgb8, 8> trousers{{{30, 35, 60},
                                        {25, 30, 52},
                                        {20, 20, 22},
                                        {90, 90, 95},
                                        {150, 130, 100},
                                        {60, 80, 130},
                                        {80, 60, 40},
                                        {200, 190, 170}}};
constexpr std::array<rgb8, 6> skins{{{255, 220, 190},
                                     {240, 195, 160},
                                     {205, 150, 110},
                                     {170, 115, 80},
                                     {120, 80, 55},
                                     {85, 55, 40}}};
constexpr std::array<rgb8, 6> hairs{
    {{20, 15, 10}, {60, 40, 25}, {110, 75, 40}, {200, 170, 110}, {150, 60, 30}, {170, 170, 170}}};

// Hue in degrees, saturation and value in [0, 1].
rgb8 from_hsv(double hue_deg, double saturation, double value) {
  cv::Mat3f colour(1, 1,
                   cv::Vec3f(static_cast<float>(hue_deg), static_cast<float>(saturation),
                             static_cast<float>(value)));
  cv::cvtColor(colour, colour, cv::COLOR_HSV2RGB);
  const auto rgb = colour(0, 0);
  auto byte = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  return {byte(rgb[0]), byte(rgb[1]), byte(rgb[2])};
}

template <class T, std::size_t N>
T pick(rng& random, const std::array<T, N>& from) {
  return from[random.below(static_cast<std::uint32_t>(N))];
}

}  // namespace

appearance draw_appearance(rng& random, config::clothing clothes) {
  appearance look;
  if (clothes == config::clothing::varied) {
    // Shirts bright or dark, plain or vivid; trousers mostly muted and darker, as people dress.
    look.shirt =
        from_hsv(random.uniform(0.0, 360.0), random.uniform(0.15, 0.9), random.uniform(0.25, 0.95));
    look.trousers =
        from_hsv(random.uniform(0.0, 360.0), random.uniform(0.05, 0.6), random.uniform(0.1, 0.75));
  } else {
    look.shirt = pick(random, shirts);
    look.trousers = pick(random, trousers);
  }
  look.skin = pick(random, skins);
  look.hair = pick(random, hairs);
  look.height_m = random.uniform(1.52, 1.95);
  look.girth_m = random.uniform(0.40, 0.54);
  return look;
}

namespace {

/// Stream tag of the preferred-speed draws, apart from the pedestrian's main stream.
constexpr std::uint64_t speed_stream = 0x7370656564737472ULL;  // "speedstr"

/// Seeds `p`'s generator, draws its looks, speed and heading.
pedestrian make_body(int id, std::uint64_t run_seed, const vec2& position,
                     const speed_distribution& speeds, config::clothing clothes) {
  pedestrian p;
  p.random = rng(config::derive_seed(config::derive_seed(run_seed, pedestrian_stream),
                                     static_cast<std::uint64_t>(id)));
  p.state.id = id;
  p.state.position = position;
  p.state.look = draw_appearance(p.random, clothes);
  rng speed_random(config::derive_seed(config::derive_seed(run_seed, speed_stream),
                                       static_cast<std::uint64_t>(id)));
  p.preferred_speed_mps = speeds.draw(speed_random);
  p.state.placed_heading_rad = p.random.uniform(-M_PI, M_PI);
  return p;
}

}  // namespace

pedestrian make_pedestrian(int id, std::uint64_t run_seed, const vec2& position, int entry_portal,
                           int entry_stairs, const speed_distribution& speeds,
                           config::clothing clothes) {
  pedestrian p = make_body(id, run_seed, position, speeds, clothes);
  p.entry_portal = entry_portal;
  p.entry_stairs = entry_stairs;
  // The agenda: errands in the station, then the platform or the street.
  auto add = [&](goal_kind g) { p.agenda[p.agenda_size++] = g; };
  if (entry_stairs >= 0) {
    // Arriving passengers: a snack or a meeting, then out to the street.
    if (p.random.chance(0.3)) add(goal_kind::use_vending_machine);
    if (p.random.chance(0.3)) add(goal_kind::meet_in_waiting_room);
    add(p.random.chance(0.9) ? goal_kind::leave_station : goal_kind::go_to_platform);
  } else {
    if (p.random.chance(0.55)) add(goal_kind::buy_ticket);
    std::array<goal_kind, 3> errands{goal_kind::rest_on_bench, goal_kind::use_vending_machine,
                                     goal_kind::meet_in_waiting_room};
    constexpr std::array<double, 3> odds{0.3, 0.3, 0.25};
    // Random order of the optional errands (Fisher-Yates with the pedestrian's own RNG).
    for (std::size_t i = errands.size() - 1; i > 0; --i) {
      std::swap(errands[i], errands[p.random.below(static_cast<std::uint32_t>(i + 1))]);
    }
    for (const auto g : errands) {
      if (p.random.chance(odds[static_cast<std::size_t>(g) - 1])) add(g);
    }
    add(p.random.chance(0.85) ? goal_kind::go_to_platform : goal_kind::leave_station);
  }
  p.state.goal = p.agenda[0];
  return p;
}

pedestrian make_flow_pedestrian(int id, std::uint64_t run_seed, const vec2& position,
                                int exit_portal, const speed_distribution& speeds,
                                config::clothing clothes) {
  pedestrian p = make_body(id, run_seed, position, speeds, clothes);
  p.flow_exit = exit_portal;
  p.agenda[p.agenda_size++] = goal_kind::leave_station;
  p.state.goal = p.agenda[0];
  return p;
}

namespace {

/// One pedestrian's tick; a small object so the state machine reads as named steps.
class stepper {
 public:
  stepper(const station& where, const snapshot& previous, pedestrian& self,
          const behaviour_settings& settings, std::vector<event>& events)
      : where_(where),
        previous_(previous),
        self_(self),
        s_(self.state),
        settings_(settings),
        events_(events),
        tick_(previous.tick() + 1) {
    // nop
  }

  /// Returns false when the pedestrian left the station.
  bool run() {
    if (self_.field < 0) begin_goal(self_.agenda[self_.agenda_next]);
    if (!decide()) return false;
    move();
    watch_progress();
    return true;
  }

 private:
  void emit(event_kind kind, int resource = -1) {
    events_.push_back({tick_, s_.id, kind, s_.goal, resource});
  }

  bool is_final(goal_kind g) const {
    return g == goal_kind::go_to_platform || g == goal_kind::leave_station;
  }

  void begin_goal(goal_kind g) {
    s_.goal = g;
    ++s_.goal_serial;
    s_.doing = is_final(g) ? activity::leaving : activity::walking;
    self_.has_point = false;
    self_.stalled_s = 0.0;
    self_.best_distance_m = std::numeric_limits<double>::infinity();
    emit(event_kind::goal_started);
    bool ok = true;
    switch (g) {
      case goal_kind::buy_ticket:
        ok = choose_counter(false);
        break;
      case goal_kind::use_vending_machine:
        ok = choose_counter(true);
        break;
      case goal_kind::rest_on_bench:
        ok = choose_seat();
        break;
      case goal_kind::meet_in_waiting_room:
        ok = choose_meeting_point();
        break;
      case goal_kind::go_to_platform:
        ok = choose_stairs();
        break;
      case goal_kind::leave_station:
        ok = choose_exit();
        break;
    }
    if (!ok) {
      abandon_goal();
      return;
    }
    s_.distance_to_goal_m = goal_distance();
  }

  void next_goal() {
    if (self_.agenda_next + 1 < self_.agenda_size) ++self_.agenda_next;
    begin_goal(self_.agenda[self_.agenda_next]);
  }

  void complete_goal() {
    emit(event_kind::goal_completed);
    next_goal();
  }

  /// Gives the current goal up; a final goal is retried with another target.
  void abandon_goal() {
    emit(event_kind::goal_abandoned);
    s_.seat = -1;
    s_.counter = -1;
    if (is_final(s_.goal)) {
      // A last goal cannot be skipped: try the other kind of way out.
      const auto other = s_.goal == goal_kind::go_to_platform ? goal_kind::leave_station
                                                              : goal_kind::go_to_platform;
      self_.agenda[self_.agenda_next] = other;
      begin_goal(other);
      return;
    }
    next_goal();
  }

  bool choose_counter(bool vending) {
    int best = -1;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t q = 0; q < where_.counter_count(); ++q) {
      if (where_.is_vending_machine(q) != vending) continue;
      const auto& c = where_.counter(q);
      const auto length = previous_.queue_length(static_cast<int>(q));
      if (length >= c.max_queue_length) continue;
      // Shortest expected wait plus walk: a person in line costs about a service time.
      const double cost = where_.distance_to(where_.target(target_kind::counter, q), s_.position) /
                              self_.preferred_speed_mps +
                          static_cast<double>(length) * (c.min_service_s + c.max_service_s) / 2.0;
      if (cost < best_cost) {
        best_cost = cost;
        best = static_cast<int>(q);
      }
    }
    if (best < 0) return false;
    self_.target_index = best;
    self_.field = where_.target(target_kind::counter, static_cast<std::size_t>(best));
    const auto& c = where_.counter(static_cast<std::size_t>(best));
    self_.point = c.service_point + c.queue_direction * c.queue_spacing_m *
                                        static_cast<double>(previous_.queue_length(best));
    self_.has_point = true;
    return true;
  }

  bool choose_seat() {
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    const auto& seats = where_.seats();
    for (std::size_t i = 0; i < seats.size(); ++i) {
      if (previous_.seat_holder(static_cast<int>(i)) >= 0) continue;
      const double d = (seats[i].position - s_.position).norm();
      if (d < best_distance) {
        best_distance = d;
        best = static_cast<int>(i);
      }
    }
    if (best < 0) return false;
    s_.seat = best;
    self_.target_index = best;
    self_.field = where_.target(target_kind::bench, static_cast<std::size_t>(seats[best].bench));
    self_.point = seats[best].position;
    self_.has_point = true;
    return true;
  }

  bool choose_meeting_point() {
    const auto& points = where_.plan().meeting_points;
    if (points.empty()) return false;
    const auto index = self_.random.below(static_cast<std::uint32_t>(points.size()));
    const auto& m = points[index];
    self_.point = m.position;
    for (int attempt = 0; attempt < 5; ++attempt) {
      const double angle = self_.random.uniform(0.0, 2.0 * M_PI);
      const double r = m.radius_m * std::sqrt(self_.random.uniform());
      const vec2 spot = m.position + r * vec2{std::cos(angle), std::sin(angle)};
      if (where_.fits(spot, 0.35)) {
        self_.point = spot;
        break;
      }
    }
    self_.has_point = true;
    self_.target_index = static_cast<int>(index);
    self_.field = where_.target(target_kind::meeting_point, index);
    self_.timer_s = self_.random.uniform(20.0, 90.0);
    return true;
  }

  bool choose_stairs() {
    const auto& stairs = where_.plan().stairways;
    // An arriving passenger does not go straight back down the stairs it came up.
    const bool skip_entry = self_.entry_stairs >= 0 && stairs.size() > 1;
    const auto choices = stairs.size() - (skip_entry ? 1 : 0);
    if (choices == 0) return false;
    std::size_t index = self_.random.below(static_cast<std::uint32_t>(choices));
    if (skip_entry && index >= static_cast<std::size_t>(self_.entry_stairs)) ++index;
    self_.target_index = static_cast<int>(index);
    self_.field = where_.target(target_kind::stairs, index);
    return true;
  }

  bool choose_exit() {
    if (self_.flow_exit >= 0) {
      self_.target_index = self_.flow_exit;
      self_.field = where_.target(target_kind::portal, static_cast<std::size_t>(self_.flow_exit));
      return true;
    }
    std::vector<std::size_t> streets;
    const auto& portals = where_.plan().portals;
    for (std::size_t i = 0; i < portals.size(); ++i) {
      if (portals[i].kind == portal_kind::street && static_cast<int>(i) != self_.entry_portal) {
        streets.push_back(i);
      }
    }
    if (streets.empty() && self_.entry_portal >= 0) streets.push_back(self_.entry_portal);
    if (streets.empty()) return false;
    const auto index = streets[self_.random.below(static_cast<std::uint32_t>(streets.size()))];
    self_.target_index = static_cast<int>(index);
    self_.field = where_.target(target_kind::portal, index);
    return true;
  }

  double goal_distance() const {
    if (self_.has_point) {
      const double straight = (self_.point - s_.position).norm();
      if (straight < settings_.direct_steering_m) return straight;
    }
    return where_.distance_to(self_.field, s_.position);
  }

  /// The behaviour state machine; false when the pedestrian left.
  bool decide() {
    const double dt = settings_.tick_s;
    switch (s_.doing) {
      case activity::walking:
      case activity::leaving:
        return arrive();
      case activity::queueing: {
        const auto& c = where_.counter(static_cast<std::size_t>(s_.counter));
        const auto rank = previous_.queue_rank(s_.counter, s_.queue_join_tick, s_.id);
        self_.point =
            c.service_point + c.queue_direction * c.queue_spacing_m * static_cast<double>(rank);
        self_.queued_s += dt;
        if (self_.queued_s > settings_.queue_give_up_s) {
          // Waited too long (a line that does not move): leave it and go on.
          abandon_goal();
          return true;
        }
        if (rank == 0 && (s_.position - c.service_point).norm() < 0.25) {
          s_.doing = where_.is_vending_machine(static_cast<std::size_t>(s_.counter))
                         ? activity::using_vending_machine
                         : activity::buying_ticket;
          self_.timer_s = self_.random.uniform(c.min_service_s, c.max_service_s);
          emit(event_kind::service_started, s_.counter);
        }
        return true;
      }
      case activity::buying_ticket:
      case activity::using_vending_machine:
        self_.timer_s -= dt;
        if (self_.timer_s <= 0.0) {
          emit(event_kind::service_finished, s_.counter);
          s_.counter = -1;
          complete_goal();
        }
        return true;
      case activity::sitting:
        self_.timer_s -= dt;
        if (self_.timer_s <= 0.0) {
          emit(event_kind::stood_up, s_.seat);
          s_.seat = -1;
          complete_goal();
        }
        return true;
      case activity::meeting:
        self_.timer_s -= dt;
        if (self_.timer_s <= 0.0) complete_goal();
        return true;
    }
    return true;
  }

  /// Walking states: has the pedestrian reached what it walks to?
  bool arrive() {
    const double to_point = (self_.point - s_.position).norm();
    switch (s_.goal) {
      case goal_kind::buy_ticket:
      case goal_kind::use_vending_machine: {
        const auto& c = where_.counter(static_cast<std::size_t>(self_.target_index));
        // Join the line on coming within 10 m of it on foot (not through an obstacle); from
        // then on the snapshot ranks the line.
        // A cheap test first: the field's distance is never shorter than the straight one by
        // more than a grid cell's diagonal (0.71 m), so this excludes no one it would admit.
        if ((s_.position - c.service_point).norm() < 11.0 &&
            where_.distance_to(self_.field, s_.position) < 10.0) {
          if (previous_.queue_length(self_.target_index) >= c.max_queue_length) {
            abandon_goal();
            return true;
          }
          s_.counter = self_.target_index;
          s_.queue_join_tick = tick_;
          self_.queued_s = 0.0;
          s_.doing = activity::queueing;
          emit(event_kind::joined_queue, s_.counter);
          const auto rank = previous_.queue_rank(s_.counter, tick_, s_.id);
          self_.point =
              c.service_point + c.queue_direction * c.queue_spacing_m * static_cast<double>(rank);
        }
        return true;
      }
      case goal_kind::rest_on_bench: {
        const int holder = previous_.seat_holder(s_.seat);
        if (holder >= 0 && holder != s_.id) {
          // Someone with a lower id claimed the same seat in the same tick: pick another.
          s_.seat = -1;
          if (!choose_seat()) abandon_goal();
          return true;
        }
        if (to_point < 0.2) {
          s_.doing = activity::sitting;
          s_.velocity = vec2::Zero();
          self_.timer_s = self_.random.uniform(30.0, 120.0);
          emit(event_kind::sat_down, s_.seat);
        }
        return true;
      }
      case goal_kind::meet_in_waiting_room:
        if (to_point < 0.5) s_.doing = activity::meeting;
        return true;
      case goal_kind::go_to_platform:
        if (where_.plan().stairways[static_cast<std::size_t>(self_.target_index)].area.contains(
                s_.position)) {
          emit(event_kind::goal_completed);
          emit(event_kind::left, -1 - self_.target_index);
          return false;
        }
        return true;
      case goal_kind::leave_station:
        if (where_.plan().portals[static_cast<std::size_t>(self_.target_index)].area.contains(
                s_.position)) {
          emit(event_kind::goal_completed);
          emit(event_kind::left, self_.target_index);
          return false;
        }
        return true;
    }
    return true;
  }

  struct half_plane {
    vec2 normal;
    double limit;
  };

  /// The point of { v : n_k . v <= limit_k for all k } closest to `preferred`: an incremental
  /// 2-D linear program (Seidel; RVO2's linearProgram2 with the distance objective). Every
  /// half-plane contains v = 0, so the set is never empty; the planes are visited in their
  /// fixed order, so the result is deterministic.
  static vec2 closest_feasible(const vec2& preferred, const half_plane* planes, std::size_t count) {
    vec2 v = preferred;
    for (std::size_t i = 0; i < count; ++i) {
      const vec2& n = planes[i].normal;
      if (n.dot(v) <= planes[i].limit) continue;
      // The optimum of planes 0..i lies on line i: p + t d.
      const vec2 p = n * planes[i].limit;
      const vec2 d{-n.y(), n.x()};
      double low = -std::numeric_limits<double>::infinity();
      double high = std::numeric_limits<double>::infinity();
      bool empty = false;
      for (std::size_t j = 0; j < i; ++j) {
        const double denominator = planes[j].normal.dot(d);
        const double numerator = planes[j].limit - planes[j].normal.dot(p);
        if (std::abs(denominator) < 1e-12) {
          // Parallel lines: empty only if plane j excludes line i by more than rounding.
          if (numerator < -1e-9) empty = true;
          continue;
        }
        const double t = numerator / denominator;
        if (denominator > 0.0) {
          high = std::min(high, t);
        } else {
          low = std::max(low, t);
        }
      }
      if (empty || low > high) return vec2::Zero();  // numerically degenerate: stand
      v = p + std::clamp(d.dot(preferred - p), low, high) * d;
    }
    return v;
  }

  /// The heading (index into `directions`, the first being the way itself) whose free path
  /// `path` (from others; cut here where walls stand in a turned heading: the way itself
  /// follows the distance field, which keeps off walls) brings one nearest the goal after the
  /// look-ahead H: the least H^2 + f^2 - 2 H f cos(turn) (Moussaid et al. 2011's distance to
  /// the destination). Ties keep the earlier heading.
  template <std::size_t N>
  std::size_t choose_heading(const std::array<vec2, N>& directions, std::array<double, N>& path,
                             std::size_t count) const {
    if (count <= 1) return 0;
    const double radius = s_.radius_m();
    for (const auto index : where_.segments_near(s_.position)) {
      const segment& wall = where_.segments()[index];
      for (std::size_t k = 1; k < count; ++k) {
        if (path[k] < settings_.turn_min_free_m) continue;
        path[k] = std::min(path[k], wall_free_path(wall, s_.position, directions[k], radius));
      }
    }
    const double h = settings_.look_ahead_m;
    std::size_t best = 0;
    double best_score = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < count; ++k) {
      if (k > 0 && path[k] < settings_.turn_min_free_m) continue;
      const double cos_turn = directions[k].dot(directions[0]);
      const double score = h * h + path[k] * path[k] - 2.0 * h * path[k] * cos_turn;
      if (score < best_score - 1e-12) {
        best_score = score;
        best = k;
      }
    }
    return best;
  }

  /// How far a disc of `radius` at `from` can go along unit `direction` before touching
  /// `wall` (its line or one of its ends); infinity when never.
  static double wall_free_path(const segment& wall, const vec2& from, const vec2& direction,
                               double radius) {
    double path = std::numeric_limits<double>::infinity();
    for (const vec2& end : {wall.a, wall.b}) {
      const vec2 offset = end - from;
      const double ahead = offset.dot(direction);
      const double aside = std::abs(offset.x() * direction.y() - offset.y() * direction.x());
      if (ahead > 0.0 && aside < radius) {
        path = std::min(path, std::max(ahead - std::sqrt(radius * radius - aside * aside), 0.0));
      }
    }
    const vec2 along = wall.b - wall.a;
    const double denominator = direction.x() * along.y() - direction.y() * along.x();
    if (std::abs(denominator) < 1e-12) return path;
    const vec2 to_a = wall.a - from;
    const double t = (to_a.x() * along.y() - to_a.y() * along.x()) / denominator;
    const double u = (to_a.x() * direction.y() - to_a.y() * direction.x()) / denominator;
    if (t > 0.0 && u >= 0.0 && u <= 1.0) {
      // The disc touches the line where its centre is `radius` from it.
      const double sine = std::abs(denominator) / along.norm();
      path = std::min(path, std::max(t - radius / sine, 0.0));
    }
    return path;
  }

  /// Social force plus constraints, integrated over one tick (semi-implicit Euler).
  void move() {
    const double dt = settings_.tick_s;
    if (s_.doing == activity::sitting || s_.doing == activity::buying_ticket ||
        s_.doing == activity::using_vending_machine) {
      // Being served or seated: planted. v = 0 satisfies everyone's constraints.
      s_.velocity = vec2::Zero();
      self_.blocked_s = 0.0;
      return;
    }
    // Stairs and other slow floor scale the preferred speed (RiMEA tests 2 and 3).
    const double v0 = self_.preferred_speed_mps * where_.speed_factor(s_.position);
    vec2 desired = vec2::Zero();
    const double to_point = self_.has_point ? (self_.point - s_.position).norm() : 1e9;
    // Steer straight at a seat, slot or spot only when it is in sight; a line's slot behind an
    // obstacle is reached along the counter's distance field like any route.
    const bool direct =
        (to_point < settings_.direct_steering_m || s_.doing == activity::queueing) &&
        where_.sight_clear(s_.position, self_.point);
    if (direct) {
      // Arrival: slow down over the last metre.
      if (to_point > 0.03)
        desired = (self_.point - s_.position) / to_point * v0 * std::min(1.0, to_point);
    } else {
      desired = where_.direction_to(self_.field, s_.position) * v0;
    }
    const double desired_speed = desired.norm();
    const vec2 desired_direction =
        desired_speed > 1e-9 ? vec2(desired / desired_speed) : vec2(vec2::Zero());
    const vec2 heading =
        s_.velocity.norm() > 0.05 ? vec2(s_.velocity.normalized()) : desired_direction;
    std::array<half_plane, 48> planes;
    std::size_t plane_count = 0;
    const double radius = s_.radius_m();
    const bool in_line = s_.counter >= 0 && s_.doing == activity::queueing;
    const bool wants_to_walk = !in_line && desired_speed > 0.3 * v0;
    // Arch breaking: pressed for a while against others who stand still ahead, the one
    // nearest its goal goes on and the others step back from it.
    bool yield = false;
    const bool stuck = wants_to_walk && self_.blocked_s > settings_.yield_after_s;
    vec2 repulsion = vec2::Zero();
    vec2 sidestep = vec2::Zero();
    const double social_cutoff_m = settings_.social_cutoff_ranges * settings_.social_range_m;
    double room_m = std::numeric_limits<double>::infinity();
    const double near_gap_m = std::max(social_cutoff_m, 0.6) + 1e-6;
    // Headings: the way itself and, for someone who wants to walk, the way turned by up to
    // 45 degrees to either side; each with its free path (before touching someone in it, up to
    // the look-ahead). One walks the heading that brings one nearest the goal after the
    // look-ahead (Moussaid, Helbing & Theraulaz 2011), so walkers fan out around a slower one
    // into the room beside it instead of queueing behind it.
    constexpr std::size_t turns = 7;
    constexpr std::array<double, turns> turn_cos{1.0,
                                                 0.9659258262890683,
                                                 0.9659258262890683,
                                                 0.8660254037844387,
                                                 0.8660254037844387,
                                                 0.7071067811865476,
                                                 0.7071067811865476};
    constexpr std::array<double, turns> turn_sin{
        0.0,  0.25881904510252074, -0.25881904510252074, 0.5,
        -0.5, 0.7071067811865476,  -0.7071067811865476};
    // Walking slowly in a press, people turn their shoulders and fit beside the one ahead;
    // at speed the one ahead holds back whoever overlaps them by more.
    const double lane_fraction =
        settings_.headway_lane_slow +
        (settings_.headway_lane - settings_.headway_lane_slow) *
            std::min(1.0, s_.velocity.norm() / settings_.headway_lane_speed_mps);
    const std::size_t headings = wants_to_walk ? turns : 1;
    std::array<vec2, turns> heading_directions;
    std::array<double, turns> free_path_m;
    for (std::size_t k = 0; k < headings; ++k) {
      heading_directions[k] = {
          turn_cos[k] * desired_direction.x() - turn_sin[k] * desired_direction.y(),
          turn_sin[k] * desired_direction.x() + turn_cos[k] * desired_direction.y()};
      free_path_m[k] = settings_.look_ahead_m;
    }
    // Who can change this step (neighbour_sieve); the turned headings' free paths, needed
    // only when the way's is short, take a second look below.
    constexpr double reach_squared = snapshot::neighbour_cell_m * snapshot::neighbour_cell_m;
    const double look_m = settings_.look_ahead_m + 1e-6;
    const double lane_margin_m = settings_.sidestep_margin_m + 1e-9;
    const bool turning = headings > 1;
    // Who may stand in a turned heading's way, kept during the visit and weighed after it only
    // when the way's own free path is short. A cone 2.9 m long holds about 40 people at
    // 6 /m^2.
    turned_lanes in_turned_lanes(settings_.turn_min_free_m);
    const neighbour_sieve matters{s_.position, desired_direction, radius, near_gap_m, reach_squared,
                                  look_m,      lane_margin_m,     turning};
    previous_.for_each_sifted(s_.position, matters, [&](const neighbour& other) {
      const vec2 offset = other.position - s_.position;
      const double distance_squared = offset.squaredNorm();
      const double contact = radius + other.radius_m();
      // Beyond the repulsion's cutoff and the constraints' reach only the headway and the
      // side step matter, and they need no unit vector: most neighbours skip the sqrt and the
      // division (a third of the step when everyone was given them).
      const double near_m = contact + near_gap_m;
      double gap = std::numeric_limits<double>::infinity();
      vec2 n = vec2::Zero();
      if (distance_squared < near_m * near_m) {
        const double distance = std::sqrt(distance_squared);
        n = offset / distance;
        gap = distance - radius - other.radius_m();
      }
      // People in the same line stand close on purpose; only the constraint keeps them apart.
      const bool same_line = in_line && other.counter == s_.counter;
      if (!same_line && gap < social_cutoff_m) {
        const double cos_phi = heading.dot(n);
        const double weight =
            settings_.anisotropy + (1.0 - settings_.anisotropy) * (1.0 + cos_phi) / 2.0;
        repulsion -=
            n * (settings_.social_strength * weight * std::exp(-gap / settings_.social_range_m));
      }
      // Merging into one way (a doorway), each of two walkers has the other across its path:
      // were both to keep their headway to the other, both would stop. The one farther from
      // the goal keeps it; the one nearer goes on (ties: the lower id), as a zipper merges.
      const bool behind_me =
          other.route == s_.route && s_.route >= 0 &&
          (other.distance_to_goal_m > s_.distance_to_goal_m ||
           (other.distance_to_goal_m == s_.distance_to_goal_m && other.id > s_.id));
      if (!same_line && !behind_me) {
        // Headway: the free path along the way before touching someone in it.
        free_path_m[0] =
            free_path_to(offset, contact, heading_directions[0], lane_fraction, free_path_m[0]);
        if (turning) in_turned_lanes.keep(offset, contact, distance_squared);
        const double along = offset.dot(desired_direction);
        if (along > 0.0) {
          const double across =
              std::abs(offset.x() * desired_direction.y() - offset.y() * desired_direction.x());
          // Someone bound elsewhere coming the other way in one's path (not a neighbour in a
          // jam stepping back): step aside early, away from them and, head on, to the right
          // (everyone the same side, so opposing streams form lanes instead of meeting face
          // to face and stopping: counter_flow.yaml had 34 of 120 stuck after 90 s).
          const double reach = contact + settings_.sidestep_margin_m;
          if (across < reach && along < settings_.sidestep_horizon_m && other.route != s_.route &&
              other.velocity.dot(desired_direction) < -0.1) {
            const double cross =
                desired_direction.x() * offset.y() - desired_direction.y() * offset.x();
            const vec2 right{desired_direction.y(), -desired_direction.x()};
            const double urgency =
                (1.0 - along / settings_.sidestep_horizon_m) * (1.0 - across / reach);
            sidestep += (cross >= -0.05 ? right : vec2(-right)) * urgency;
          }
        }
      }
      if (stuck && gap < 0.05 && desired_direction.dot(n) > 0.0 &&
          other.velocity.squaredNorm() < 0.01 && !is_waiting(other.doing) &&
          (other.distance_to_goal_m < s_.distance_to_goal_m ||
           (other.distance_to_goal_m == s_.distance_to_goal_m && other.id < s_.id))) {
        yield = true;
      }
      if (gap < 0.6) {
        // Until the body's growth is known, a plane's limit holds its share of the room.
        const double room = std::max(gap - 0.01, 0.0) / 2.0;
        room_m = std::min(room_m, room);
        if (plane_count < planes.size()) planes[plane_count++] = {n, room};
      }
    });
    const double way_free_m = free_path_m[0];
    // A turned heading scores at least H^2 sin^2(15 deg) (at f = H cos(turn)), the way itself
    // (H - f)^2: with the way's free path beyond H (1 - sin 15 deg) no turn can win, and
    // the others' free paths need not be looked for.
    const bool may_turn = headings > 1 && way_free_m < settings_.look_ahead_m * (1.0 - turn_sin[1]);
    if (may_turn) {
      // Only what can change the choice is worked out: a heading whose best score (H^2
      // sin^2(turn)) cannot beat the way's, or whose free path is already under the least a
      // turn needs, is out (its path left at 0).
      const double h = settings_.look_ahead_m;
      const double way_score = (h - way_free_m) * (h - way_free_m);
      for (std::size_t k = 1; k < headings; ++k) {
        if (h * h * turn_sin[k] * turn_sin[k] >= way_score) {
          free_path_m[k] = 0.0;
          continue;
        }
        free_path_m[k] =
            in_turned_lanes.free_path(heading_directions[k], lane_fraction, free_path_m[k]);
      }
    }
    const std::size_t chosen =
        may_turn ? choose_heading(heading_directions, free_path_m, headings) : 0;
    desired = heading_directions[chosen] * desired_speed;
    if (sidestep.squaredNorm() > 0.0) {
      const double speed = desired.norm();
      const vec2 turned =
          heading_directions[chosen] + sidestep.normalized() * std::min(1.0, sidestep.norm());
      desired = turned.normalized() * speed;
    }
    // The way itself follows the walls already (the distance field); along it only people
    // slow one. A turned heading may run into a wall: there its free path counts them too.
    const double free_m = chosen == 0 ? way_free_m : free_path_m[chosen];
    if (free_m < settings_.look_ahead_m) {
      desired *= std::min(1.0, free_m / (settings_.headway_s * v0));
    }
    // Yielding: step back a little, deaf to the crowd's push. Merely standing, the yielder
    // stays wedged: the repulsion of those behind presses it into the arch (two walkers side
    // by side in a door too narrow for both, each against a jamb, stood so for minutes).
    if (yield) {
      desired = -settings_.yield_step_back_mps * desired_direction;
      repulsion = vec2::Zero();
    }
    vec2 acceleration = (desired - s_.velocity) / settings_.relaxation_s + repulsion;
    // A corner where segments meet is one obstacle: counted once per segment it would push
    // twice as hard at a doorway's jamb, and its two identical half-planes leave the linear
    // program a parallel pair that rounding can declare empty (pinning a walker at the jamb).
    std::array<vec2, 16> corners;
    std::size_t corner_count = 0;
    for (const auto index : where_.segments_near(s_.position)) {
      const segment& wall = where_.segments()[index];
      const vec2 closest = wall.closest_point(s_.position);
      const vec2 offset = closest - s_.position;
      const double distance = offset.norm();
      if (distance > station::segment_reach_m || distance < 1e-9) continue;
      if (closest == wall.a || closest == wall.b) {
        const auto seen = corners.begin() + static_cast<std::ptrdiff_t>(corner_count);
        if (std::find(corners.begin(), seen, closest) != seen) continue;
        if (corner_count < corners.size()) corners[corner_count++] = closest;
      }
      const vec2 n = offset / distance;
      const double gap = distance - radius;
      acceleration -= n * (settings_.wall_strength * std::exp(-gap / settings_.wall_range_m));
      if (gap < 0.6) {
        const double room = std::max(gap - 0.01, 0.0);
        room_m = std::min(room_m, room);
        if (plane_count < planes.size()) planes[plane_count++] = {n, room};
      }
    }
    // The body grows only into room nobody else may take this tick (each neighbour keeps to
    // its half of the gap), so growing discs never overlap; shrinking frees room at once.
    const double squeeze_max = settings_.body_squeeze * s_.look.girth_m / 2.0;
    const double squeeze_wanted =
        squeeze_max * (1.0 - std::min(1.0, s_.velocity.norm() / settings_.body_full_speed_mps));
    const double step_m = settings_.body_change_mps * dt;
    double growth = std::clamp(s_.squeeze_m - squeeze_wanted, -step_m, step_m);
    if (growth > 0.0) growth = std::min(growth, room_m);
    s_.squeeze_m -= growth;
    for (std::size_t k = 0; k < plane_count; ++k) planes[k].limit = (planes[k].limit - growth) / dt;
    vec2 velocity = s_.velocity + acceleration * dt;
    const double max_speed = 1.4 * v0;
    if (velocity.norm() > max_speed) velocity *= max_speed / velocity.norm();
    velocity = closest_feasible(velocity, planes.data(), plane_count);
    // Guard against rounding in the program: scale down until every half-plane holds (each
    // contains v = 0, so a shorter velocity along the same line stays feasible).
    double scale = 1.0;
    for (std::size_t k = 0; k < plane_count; ++k) {
      const double along = velocity.dot(planes[k].normal);
      if (along > planes[k].limit) scale = std::min(scale, planes[k].limit / along);
    }
    velocity *= std::max(scale, 0.0);
    s_.velocity = velocity;
    s_.position += velocity * dt;
    if (velocity.norm() > 0.1) s_.facing = velocity;
    if (wants_to_walk && velocity.norm() < 0.1 * v0) {
      self_.blocked_s += dt;
    } else if (!yield) {
      self_.blocked_s = 0.0;
    }
  }

  /// Watchdog: no progress for give_up_s means the route is blocked; choose again.
  void watch_progress() {
    s_.distance_to_goal_m = goal_distance();
    // A point of one's own (seat, slot, spot) makes distances to it incomparable with others'.
    s_.route = self_.has_point ? -1 : self_.field;
    if (is_waiting(s_.doing)) {
      self_.stalled_s = 0.0;
      self_.best_distance_m = s_.distance_to_goal_m;
      return;
    }
    if (s_.distance_to_goal_m < self_.best_distance_m - settings_.progress_m) {
      self_.best_distance_m = s_.distance_to_goal_m;
      self_.stalled_s = 0.0;
      return;
    }
    self_.stalled_s += settings_.tick_s;
    if (self_.stalled_s <= settings_.give_up_s) return;
    if (is_final(s_.goal)) {
      // A way out that is slow to reach is usually a jam in front of it (the layout check
      // guarantees it can be reached): turning back through the crowd to another exit only
      // makes the jam worse, so keep going and start a new watch.
      self_.stalled_s = 0.0;
      self_.best_distance_m = s_.distance_to_goal_m;
      return;
    }
    abandon_goal();
  }

  const station& where_;
  const snapshot& previous_;
  pedestrian& self_;
  pedestrian_state& s_;
  const behaviour_settings& settings_;
  std::vector<event>& events_;
  std::uint64_t tick_;
};

}  // namespace

std::optional<pedestrian> step_pedestrian(const station& where, const snapshot& previous,
                                          const pedestrian& current,
                                          const behaviour_settings& settings,
                                          std::vector<event>& events) {
  pedestrian next = current;
  if (!stepper(where, previous, next, settings, events).run()) return std::nullopt;
  return next;
}

}  // namespace argus::world

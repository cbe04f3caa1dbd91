#include "world/station.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>

#include "world/field_cache.hpp"
#include "world/layout_loader.hpp"
#include "world/open_cells.hpp"

namespace argus::world {

namespace {

constexpr float unreachable = std::numeric_limits<float>::infinity();

/// Even-odd point-in-polygon test.
bool segments_intersect(const vec2& p, const vec2& q, const segment& s) {
  auto cross = [](const vec2& a, const vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  const vec2 r = q - p;
  const vec2 e = s.b - s.a;
  const double denominator = cross(r, e);
  if (std::abs(denominator) < 1e-12) return false;
  const double t = cross(s.a - p, e) / denominator;
  const double u = cross(s.a - p, r) / denominator;
  return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
}

constexpr int step_x[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int step_y[8] = {0, 1, 1, 1, 0, -1, -1, -1};

}  // namespace

bool station::line_clear(const vec2& a, const vec2& b) const {
  for (const auto s : segments_near(a)) {
    if (segments_intersect(a, b, segments_[s])) return false;
  }
  return true;
}

bool station::sight_clear(const vec2& a, const vec2& b) const {
  // line_clear sees segments within segment_reach_m of its start: walk in 1 m pieces.
  const double length = (b - a).norm();
  const int pieces = std::max(1, static_cast<int>(std::ceil(length)));
  vec2 from = a;
  for (int k = 1; k <= pieces; ++k) {
    const vec2 to = a + (b - a) * (static_cast<double>(k) / pieces);
    if (!line_clear(from, to)) return false;
    from = to;
  }
  return true;
}

vec2 segment::closest_point(const vec2& p) const {
  const vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 <= 0.0) return a;
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return a + t * ab;
}

station::station(layout plan, navigation_settings settings)
    : plan_(std::move(plan)), settings_(settings) {
  for (const auto& booth : plan_.ticket_booths) counters_.push_back(&booth);
  for (const auto& machine : plan_.vending_machines) counters_.push_back(&machine);
  for (std::size_t b = 0; b < plan_.benches.size(); ++b) {
    const auto& each = plan_.benches[b];
    const vec2 along = each.to - each.from;
    for (unsigned s = 0; s < each.seats; ++s) {
      // Seats sit 0.45 m in front of the bench line: a sitter's centre, clear of the bench.
      const vec2 at = each.from + along * ((s + 0.5) / each.seats) + 0.45 * each.facing;
      seats_.push_back({at, static_cast<int>(b)});
    }
  }
  has_speed_factors_ = std::any_of(plan_.regions.begin(), plan_.regions.end(),
                                   [](const region& r) { return r.speed_factor != 1.0; });
  build_segments();
  solids_ = solid_index(plan_, counters_);
  build_segment_index();
  build_grid();
  if (settings_.fields) build_fields();
}

std::shared_ptr<const station> station::load(const std::filesystem::path& file,
                                             navigation_settings settings) {
  return std::make_shared<const station>(load_layout(file), settings);
}

void station::build_segments() {
  for (const auto& w : plan_.walls) {
    for (std::size_t i = 1; i < w.points.size(); ++i)
      segments_.push_back({w.points[i - 1], w.points[i]});
  }
  auto add_polygon = [&](const std::vector<vec2>& polygon) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      segments_.push_back({polygon[i], polygon[(i + 1) % polygon.size()]});
    }
  };
  for (const auto& o : plan_.obstacles) add_polygon(o.polygon);
  for (const auto* c : counters_) {
    const box& f = c->footprint;
    add_polygon({f.min, {f.max.x(), f.min.y()}, f.max, {f.min.x(), f.max.y()}});
  }
  for (const auto& b : plan_.benches) segments_.push_back({b.from, b.to});
}

void station::build_segment_index() {
  index_w_ = static_cast<int>(std::ceil(plan_.size_m.x() / index_cell_m)) + 1;
  index_h_ = static_cast<int>(std::ceil(plan_.size_m.y() / index_cell_m)) + 1;
  std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(index_w_ * index_h_));
  // A segment within reach of any point of a cell is within reach + half a diagonal of its
  // centre.
  const double reach = segment_reach_m + index_cell_m * std::sqrt(0.5);
  for (std::uint32_t s = 0; s < segments_.size(); ++s) {
    const auto& seg = segments_[s];
    const int x0 =
        std::max(0, static_cast<int>((std::min(seg.a.x(), seg.b.x()) - reach) / index_cell_m));
    const int x1 = std::min(
        index_w_ - 1, static_cast<int>((std::max(seg.a.x(), seg.b.x()) + reach) / index_cell_m));
    const int y0 =
        std::max(0, static_cast<int>((std::min(seg.a.y(), seg.b.y()) - reach) / index_cell_m));
    const int y1 = std::min(
        index_h_ - 1, static_cast<int>((std::max(seg.a.y(), seg.b.y()) + reach) / index_cell_m));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const vec2 centre{(x + 0.5) * index_cell_m, (y + 0.5) * index_cell_m};
        if ((seg.closest_point(centre) - centre).norm() <= reach)
          cells[y * index_w_ + x].push_back(s);
      }
    }
  }
  index_start_.assign(cells.size() + 1, 0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    index_start_[c + 1] = index_start_[c] + static_cast<std::uint32_t>(cells[c].size());
    index_items_.insert(index_items_.end(), cells[c].begin(), cells[c].end());
  }
}

std::span<const std::uint32_t> station::segments_near(const vec2& p) const {
  const int x = std::clamp(static_cast<int>(p.x() / index_cell_m), 0, index_w_ - 1);
  const int y = std::clamp(static_cast<int>(p.y() / index_cell_m), 0, index_h_ - 1);
  const auto c = static_cast<std::size_t>(y * index_w_ + x);
  return {index_items_.data() + index_start_[c], index_start_[c + 1] - index_start_[c]};
}

double station::wall_clearance(const vec2& p) const {
  double best = segment_reach_m;
  for (const auto s : segments_near(p)) {
    best = std::min(best, (segments_[s].closest_point(p) - p).norm());
  }
  return best;
}

bool station::walkable(const vec2& p) const {
  const region* r = region_at(p);
  if (r == nullptr || r->kind == region_kind::tracks) return false;
  return !solids_.inside_solid(p);
}

bool station::fits(const vec2& p, double radius_m) const {
  if (p.x() < 0.0 || p.y() < 0.0 || p.x() >= plan_.size_m.x() || p.y() >= plan_.size_m.y()) {
    return false;
  }
  const int c = cell_index(p);
  return blocked_[c] == 0 && walkable(p) && wall_clearance(p) > radius_m + 0.05;
}

const region* station::region_at(const vec2& p) const {
  for (const auto& r : plan_.regions) {
    if (r.area.contains(p)) return &r;
  }
  return nullptr;
}

int station::cell_index(const vec2& p) const {
  const int x = std::clamp(static_cast<int>(p.x() / settings_.cell_m), 0, grid_w_ - 1);
  const int y = std::clamp(static_cast<int>(p.y() / settings_.cell_m), 0, grid_h_ - 1);
  return y * grid_w_ + x;
}

void station::build_grid() {
  grid_w_ = static_cast<int>(std::ceil(plan_.size_m.x() / settings_.cell_m));
  grid_h_ = static_cast<int>(std::ceil(plan_.size_m.y() / settings_.cell_m));
  blocked_.assign(static_cast<std::size_t>(grid_w_ * grid_h_), 1);
  near_wall_.assign(blocked_.size(), 0);
  wall_cost_.assign(blocked_.size(), 1.0f);
  for (int y = 0; y < grid_h_; ++y) {
    for (int x = 0; x < grid_w_; ++x) {
      const vec2 centre{(x + 0.5) * settings_.cell_m, (y + 0.5) * settings_.cell_m};
      const double clearance = wall_clearance(centre);
      const auto c = static_cast<std::size_t>(y * grid_w_ + x);
      blocked_[c] = !walkable(centre) || clearance < settings_.clearance_m;
      near_wall_[c] = clearance < settings_.wall_band_m;
      // The cost of walking rises smoothly towards a wall (a step would put a kink in the
      // field that turns the descent direction across the route at the band's edge).
      wall_cost_[c] = static_cast<float>(
          1.0 + settings_.wall_penalty * std::max(0.0, 1.0 - clearance / settings_.wall_band_m));
    }
  }
  // Walls have no thickness: cells on both sides of one can both be free, so every grid
  // edge is checked against the walls it might cross.
  edge_blocked_.assign(blocked_.size(), 0);
  for (int y = 0; y < grid_h_; ++y) {
    for (int x = 0; x < grid_w_; ++x) {
      const auto c = static_cast<std::size_t>(y * grid_w_ + x);
      if (!near_wall_[c]) continue;
      const vec2 centre{(x + 0.5) * settings_.cell_m, (y + 0.5) * settings_.cell_m};
      for (int d = 0; d < 8; ++d) {
        const vec2 other{(x + step_x[d] + 0.5) * settings_.cell_m,
                         (y + step_y[d] + 0.5) * settings_.cell_m};
        if (!line_clear(centre, other)) edge_blocked_[c] |= static_cast<std::uint8_t>(1u << d);
      }
    }
  }
}

std::vector<std::vector<float>> station::distance_fields(
    const std::vector<std::vector<int>>& sources) const {
  std::vector<std::vector<float>> fields(sources.size());
  // Each field is a Dijkstra of its own over the same read-only grid: they are computed side
  // by side, and each comes out the same whichever thread computes it. A large station's
  // 164 fields were nearly all of its loading time on one core.
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const auto threads = static_cast<unsigned>(
      std::min<std::size_t>(settings_.threads != 0 ? settings_.threads : hardware, sources.size()));
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failed(sources.size());
  auto work = [&] {
    for (std::size_t i = next++; i < sources.size(); i = next++) {
      try {
        fields[i] = sources[i].empty() ? std::vector<float>(blocked_.size(), unreachable)
                                       : dijkstra(sources[i]);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (unsigned t = 1; t < threads; ++t) helpers.emplace_back(work);
    work();
  }
  for (const auto& e : failed)
    if (e) std::rethrow_exception(e);
  return fields;
}

field_set station::cached_or_computed_fields(const std::vector<std::vector<int>>& sources) {
  if (settings_.field_cache.empty()) return field_set(distance_fields(sources));
  // Everything the fields are computed from; the cell size gives the step costs.
  field_key key;
  key.add_value(field_cache::version);
  key.add_value(grid_w_);
  key.add_value(grid_h_);
  key.add_value(settings_.cell_m);
  key.add_values(std::span<const std::uint8_t>(blocked_));
  key.add_values(std::span<const std::uint8_t>(edge_blocked_));
  key.add_values(std::span<const float>(wall_cost_));
  key.add_value(sources.size());
  for (const auto& cells : sources) {
    key.add_value(cells.size());
    key.add_values(std::span<const int>(cells));
  }
  const auto hex = key.hex();
  const field_cache cache(settings_.field_cache);
  const auto kept = [&] {
    auto fields = cache.load(hex, sources.size(), blocked_.size());
    fields_from_cache_ = fields.has_value();
    return fields;
  };
  if (auto fields = kept()) return std::move(*fields);
  // One process computes, the others wait and read what it stored (a distributed run's
  // processes load the station side by side).
  const auto computing = cache.lock_to_compute();
  if (auto fields = kept()) return std::move(*fields);
  auto fields = distance_fields(sources);
  field_cache_problem_ = cache.store(hex, fields);
  return field_set(std::move(fields));
}

std::vector<float> station::dijkstra(const std::vector<int>& sources) const {
  std::vector<float> distance(blocked_.size(), unreachable);
  open_cells open;
  for (const int s : sources) {
    distance[s] = 0.0f;
    open.push(0.0f, s);
  }
  const float cell = static_cast<float>(settings_.cell_m);
  const float diagonal = cell * std::sqrt(2.0f);
  while (!open.empty()) {
    const auto [d, c] = open.pop();
    if (d > distance[c]) continue;
    const int cx = c % grid_w_;
    const int cy = c / grid_w_;
    for (int direction = 0; direction < 8; ++direction) {
      const int dx = step_x[direction];
      const int dy = step_y[direction];
      const int nx = cx + dx;
      const int ny = cy + dy;
      if (nx < 0 || ny < 0 || nx >= grid_w_ || ny >= grid_h_) continue;
      const int n = ny * grid_w_ + nx;
      if (blocked_[n] || (edge_blocked_[c] & (1u << direction))) continue;
      // No corner cutting: a diagonal step needs both side cells free.
      if (dx != 0 && dy != 0 && (blocked_[cy * grid_w_ + nx] || blocked_[ny * grid_w_ + cx])) {
        continue;
      }
      // Mean cost of the two cells the step joins.
      const float step =
          (dx != 0 && dy != 0 ? diagonal : cell) * 0.5f * (wall_cost_[c] + wall_cost_[n]);
      if (d + step < distance[n]) {
        distance[n] = d + step;
        open.push(distance[n], n);
      }
    }
  }
  return distance;
}

void station::build_fields() {
  auto nearest_free = [&](const vec2& p) {
    const int c = cell_index(p);
    if (!blocked_[c]) return c;
    const int cx = c % grid_w_;
    const int cy = c / grid_w_;
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int r = 1; r <= 8 && best < 0; ++r) {
      for (int y = std::max(0, cy - r); y <= std::min(grid_h_ - 1, cy + r); ++y) {
        for (int x = std::max(0, cx - r); x <= std::min(grid_w_ - 1, cx + r); ++x) {
          if (blocked_[y * grid_w_ + x]) continue;
          const vec2 centre{(x + 0.5) * settings_.cell_m, (y + 0.5) * settings_.cell_m};
          const double d = (centre - p).norm();
          if (d < best_distance) {
            best_distance = d;
            best = y * grid_w_ + x;
          }
        }
      }
    }
    return best;
  };
  // The columns (or rows) whose centres may lie in [lo, hi], a cell wider on each side so that
  // the rounding of the division cannot leave one out; the centre test below decides. Scanning
  // the whole grid for each of the large station's 160 targets was 0.1 s of every load.
  auto centres_within = [&](double lo, double hi, int count) {
    const auto index = [&](double at) {
      return static_cast<int>(std::clamp(std::floor(at / settings_.cell_m - 0.5), -2.0,
                                         static_cast<double>(count) + 1.0));
    };
    return std::pair{std::max(0, index(lo) - 1), std::min(count - 1, index(hi) + 2)};
  };
  auto box_cells = [&](const box& b) {
    std::vector<int> cells;
    const auto [x0, x1] = centres_within(b.min.x(), b.max.x(), grid_w_);
    const auto [y0, y1] = centres_within(b.min.y(), b.max.y(), grid_h_);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const vec2 centre{(x + 0.5) * settings_.cell_m, (y + 0.5) * settings_.cell_m};
        if (b.contains(centre) && !blocked_[y * grid_w_ + x]) cells.push_back(y * grid_w_ + x);
      }
    }
    if (cells.empty()) {
      if (const int c = nearest_free(b.center()); c >= 0) cells.push_back(c);
    }
    return cells;
  };
  // Each target: its element path for problems, its name, and its source cells.
  struct target_cells {
    std::string element;
    std::string name;
    std::vector<int> cells;
  };
  std::vector<target_cells> targets;
  std::vector<config::problem> problems;
  auto report = [&](const std::string& element, std::string message) {
    problems.push_back({plan_.source_path, 0, 0, element, std::move(message)});
  };
  auto element = [](const char* list, std::size_t index) {
    return fmt::format("{}[{}]", list, index);
  };
  field_base_.assign(5, 0);
  field_base_[0] = 0;
  // Portals and stairs: a pedestrian leaves only inside the box, so its own cells, no snapping.
  auto exit_cells = [&](const std::string& where, const std::string& name, const box& b) {
    auto cells = box_cells(b);
    if (cells.size() == 1 && !b.contains({(cells[0] % grid_w_ + 0.5) * settings_.cell_m,
                                          (cells[0] / grid_w_ + 0.5) * settings_.cell_m})) {
      report(where, fmt::format("'{}' has no walkable floor inside its box (a pedestrian leaves "
                                "only inside it; the nearest free floor is outside)",
                                name));
    }
    return cells;
  };
  for (std::size_t i = 0; i < plan_.portals.size(); ++i) {
    const auto& p = plan_.portals[i];
    targets.push_back(
        {element("portals", i), p.name, exit_cells(element("portals", i), p.name, p.area)});
  }
  field_base_[1] = static_cast<int>(targets.size());
  for (std::size_t i = 0; i < plan_.stairways.size(); ++i) {
    const auto& st = plan_.stairways[i];
    targets.push_back(
        {element("stairs", i), st.name, exit_cells(element("stairs", i), st.name, st.area)});
  }
  field_base_[2] = static_cast<int>(targets.size());
  for (std::size_t i = 0; i < counters_.size(); ++i) {
    const auto* c = counters_[i];
    const int cell = nearest_free(c->service_point);
    const auto where = i < plan_.ticket_booths.size()
                           ? element("ticket_booths", i)
                           : element("vending_machines", i - plan_.ticket_booths.size());
    targets.push_back({where, c->name, cell >= 0 ? std::vector<int>{cell} : std::vector<int>{}});
  }
  field_base_[3] = static_cast<int>(targets.size());
  for (std::size_t b = 0; b < plan_.benches.size(); ++b) {
    std::vector<int> cells;
    for (const auto& s : seats_) {
      if (s.bench != static_cast<int>(b)) continue;
      if (const int c = nearest_free(s.position); c >= 0) cells.push_back(c);
    }
    targets.push_back({element("benches", b), plan_.benches[b].name, cells});
  }
  field_base_[4] = static_cast<int>(targets.size());
  for (std::size_t i = 0; i < plan_.meeting_points.size(); ++i) {
    const auto& m = plan_.meeting_points[i];
    const int cell = nearest_free(m.position);
    targets.push_back({element("meeting_points", i), m.name,
                       cell >= 0 ? std::vector<int>{cell} : std::vector<int>{}});
  }
  // Entrances: street portals and stairs (arriving passengers come up there).
  std::vector<std::size_t> entrances;
  for (std::size_t i = 0; i < plan_.portals.size(); ++i) {
    if (plan_.portals[i].kind == portal_kind::street) entrances.push_back(i);
  }
  for (std::size_t i = 0; i < plan_.stairways.size(); ++i) {
    entrances.push_back(static_cast<std::size_t>(field_base_[1]) + i);
  }
  const auto free_cells = std::count(blocked_.begin(), blocked_.end(), std::uint8_t{0});
  std::vector<std::vector<int>> sources;
  sources.reserve(targets.size());
  for (const auto& target : targets) sources.push_back(target.cells);
  fields_ = cached_or_computed_fields(sources);
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const auto& target = targets[t];
    const auto field = fields_[t];
    if (target.cells.empty()) {
      report(target.element,
             fmt::format("'{}' lies on no walkable floor (navigation grid)", target.name));
      continue;
    }
    bool cut_off = false;
    for (const auto e : entrances) {
      const auto& from = targets[e];
      if (&from == &target || from.cells.empty()) continue;
      const bool reached = std::any_of(from.cells.begin(), from.cells.end(),
                                       [&](int c) { return field[c] < unreachable; });
      if (!reached) {
        cut_off = true;
        report(target.element, fmt::format("'{}' cannot be reached on foot from entrance '{}' ({})",
                                           target.name, from.name, from.element));
      }
    }
    const auto reached =
        std::count_if(field.begin(), field.end(), [](float d) { return d < unreachable; });
    // A target cut off from most of the floor means a wall closes a portal by mistake.
    if (!cut_off && reached * 2 < free_cells) {
      report(target.element,
             fmt::format("'{}' is reachable from only {} of {} walkable navigation cells",
                         target.name, reached, free_cells));
    }
  }
  check_lines(problems);
  check_portals(problems);
  if (!problems.empty()) throw config::scenario_error(std::move(problems));
}

void station::check_lines(std::vector<config::problem>& problems) const {
  for (std::size_t i = 0; i < counters_.size(); ++i) {
    const auto& c = *counters_[i];
    const auto where = i < plan_.ticket_booths.size()
                           ? fmt::format("ticket_booths[{}]", i)
                           : fmt::format("vending_machines[{}]", i - plan_.ticket_booths.size());
    vec2 previous = c.service_point;
    for (unsigned k = 0; k < c.max_queue_length; ++k) {
      const vec2 slot = c.service_point + c.queue_direction * c.queue_spacing_m * k;
      std::string wrong;
      if (!walkable(slot)) {
        wrong = "is not on walkable floor";
      } else if (wall_clearance(slot) < settings_.clearance_m + 0.05) {
        wrong = "is closer than a body to a wall or obstacle";
      } else if (!sight_clear(previous, slot)) {
        wrong = "is cut off from the slot before it by a wall or obstacle";
      }
      if (!wrong.empty()) {
        problems.push_back(
            {plan_.source_path, 0, 0, where,
             fmt::format("'{}': slot {} of its line (of max_queue_length {}) at [{}, {}] {}",
                         c.name, k, c.max_queue_length, slot.x(), slot.y(), wrong)});
        break;
      }
      previous = slot;
    }
  }
}

void station::check_portals(std::vector<config::problem>& problems) const {
  for (std::size_t i = 0; i < plan_.portals.size(); ++i) {
    const auto& p = plan_.portals[i];
    const box& b = p.area;
    if (p.kind == portal_kind::street) {
      // A door to the outside has floor that is not walkable (outside every hall, or off the
      // plan) just beyond one of its sides.
      constexpr double beyond_m = 0.25;
      bool at_edge = false;
      for (int k = 0; k <= 8 && !at_edge; ++k) {
        const double fx = b.min.x() + (b.max.x() - b.min.x()) * k / 8.0;
        const double fy = b.min.y() + (b.max.y() - b.min.y()) * k / 8.0;
        for (const vec2& q : {vec2{fx, b.min.y() - beyond_m}, vec2{fx, b.max.y() + beyond_m},
                              vec2{b.min.x() - beyond_m, fy}, vec2{b.max.x() + beyond_m, fy}}) {
          if (!walkable(q)) at_edge = true;
        }
      }
      if (!at_edge) {
        problems.push_back(
            {plan_.source_path, 0, 0, fmt::format("portals[{}]", i),
             fmt::format("street portal '{}' does not touch the edge of the walkable floor "
                         "(a door to the outside must lie on the boundary)",
                         p.name)});
      }
    } else {
      int regions = 0;
      for (const auto& r : plan_.regions) {
        if (r.kind == region_kind::tracks) continue;
        if (r.area.min.x() < b.max.x() && b.min.x() < r.area.max.x() &&
            r.area.min.y() < b.max.y() && b.min.y() < r.area.max.y()) {
          ++regions;
        }
      }
      if (regions < 2) {
        problems.push_back(
            {plan_.source_path, 0, 0, fmt::format("portals[{}]", i),
             fmt::format("internal portal '{}' overlaps {} walkable region(s); an opening "
                         "between halls must overlap two",
                         p.name, regions)});
      }
    }
  }
}

int station::target(target_kind kind, std::size_t index) const {
  return field_base_[static_cast<int>(kind)] + static_cast<int>(index);
}

}  // namespace argus::world

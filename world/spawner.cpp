#include "world/spawner.hpp"

#include <algorithm>

#include "config/derive_seed.hpp"
#include "world/behaviour.hpp"
#include "world/station.hpp"

namespace argus::world {

namespace {

constexpr std::uint64_t spawner_stream = 0x737061776e657221ULL;  // "spawner!"

/// Whether a disc at `p` of `radius` keeps clear of everyone.
bool clear_of(const vec2& p, double radius, std::span<const pedestrian_state> present,
              const std::vector<pedestrian>& fresh) {
  auto too_close = [&](const pedestrian_state& other) {
    return (other.position - p).norm() < radius + other.radius_m() + 0.1;
  };
  return std::none_of(present.begin(), present.end(), too_close) &&
         std::none_of(fresh.begin(), fresh.end(),
                      [&](const pedestrian& f) { return too_close(f.state); });
}

}  // namespace

spawner::spawner(spawner_settings settings)
    : settings_(settings),
      random_(config::derive_seed(settings.run_seed, spawner_stream)),
      flow_spawned_(settings_.flows.size(), 0),
      flow_credit_(settings_.flows.size(), 0.0) {
  // nop
}

std::vector<pedestrian> spawner::populate(const station& where, std::uint64_t tick,
                                          std::vector<event>& events) {
  std::vector<pedestrian> out;
  out.reserve(settings_.population);
  const auto& regions = where.plan().regions;
  std::vector<const region*> floors;
  std::vector<double> cumulative;
  double area = 0.0;
  for (const auto& r : regions) {
    if (r.kind == region_kind::tracks) continue;
    const vec2 size = r.area.max - r.area.min;
    area += size.x() * size.y();
    floors.push_back(&r);
    cumulative.push_back(area);
  }
  if (floors.empty()) return out;
  // A coarse occupancy grid keeps placement linear in the population.
  const double cell = 1.0;
  const int w = static_cast<int>(where.plan().size_m.x() / cell) + 1;
  const int h = static_cast<int>(where.plan().size_m.y() / cell) + 1;
  std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(w * h));
  int failures = 0;
  while (out.size() < settings_.population && failures < 200000) {
    const double pick = random_.uniform(0.0, area);
    const auto which =
        std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin();
    const box& b =
        floors[static_cast<std::size_t>(std::min<std::ptrdiff_t>(which, floors.size() - 1))]->area;
    const vec2 p{random_.uniform(b.min.x(), b.max.x()), random_.uniform(b.min.y(), b.max.y())};
    auto candidate = make_pedestrian(next_id_, settings_.run_seed, p, -1, -1, settings_.speeds,
                                     settings_.clothes);
    const double radius = candidate.state.radius_m();
    bool ok = where.fits(p, radius);
    const int cx = std::clamp(static_cast<int>(p.x() / cell), 0, w - 1);
    const int cy = std::clamp(static_cast<int>(p.y() / cell), 0, h - 1);
    for (int y = std::max(0, cy - 1); ok && y <= std::min(h - 1, cy + 1); ++y) {
      for (int x = std::max(0, cx - 1); ok && x <= std::min(w - 1, cx + 1); ++x) {
        for (const auto k : grid[y * w + x]) {
          const auto& other = out[k].state;
          if ((other.position - p).norm() < radius + other.radius_m() + 0.1) {
            ok = false;
            break;
          }
        }
      }
    }
    if (!ok) {
      ++failures;
      continue;
    }
    grid[cy * w + cx].push_back(static_cast<std::uint32_t>(out.size()));
    events.push_back({tick, next_id_, event_kind::spawned, candidate.state.goal, -1});
    out.push_back(std::move(candidate));
    ++next_id_;
  }
  return out;
}

bool spawner::place(const station& where, std::span<const pedestrian_state> present,
                    const std::vector<pedestrian>& fresh, std::uint64_t tick,
                    std::vector<pedestrian>& out, std::vector<event>& events) {
  const auto& plan = where.plan();
  std::vector<int> doors;  // portal index, or -1 - stairs index
  for (std::size_t i = 0; i < plan.portals.size(); ++i) {
    if (plan.portals[i].kind == portal_kind::street) doors.push_back(static_cast<int>(i));
  }
  const auto street_count = doors.size();
  for (std::size_t i = 0; i < plan.stairways.size(); ++i) doors.push_back(-1 - static_cast<int>(i));
  if (doors.empty()) return false;
  // Six in ten come in from the street, four up from the trains.
  std::size_t pick = 0;
  if (street_count > 0 && (street_count == doors.size() || random_.chance(0.6))) {
    pick = random_.below(static_cast<std::uint32_t>(street_count));
  } else {
    pick = street_count + random_.below(static_cast<std::uint32_t>(doors.size() - street_count));
  }
  const int door = doors[pick];
  const box& area = door >= 0 ? plan.portals[door].area : plan.stairways[-1 - door].area;
  const vec2 p{random_.uniform(area.min.x(), area.max.x()),
               random_.uniform(area.min.y(), area.max.y())};
  auto candidate = make_pedestrian(next_id_, settings_.run_seed, p, door >= 0 ? door : -1,
                                   door < 0 ? -1 - door : -1, settings_.speeds, settings_.clothes);
  if (!where.fits(p, candidate.state.radius_m()) ||
      !clear_of(p, candidate.state.radius_m(), present, fresh)) {
    return false;
  }
  events.push_back({tick, next_id_, event_kind::spawned, candidate.state.goal, door});
  out.push_back(std::move(candidate));
  ++next_id_;
  return true;
}

std::vector<pedestrian> spawner::spawn(const station& where,
                                       std::span<const pedestrian_state> present,
                                       std::uint64_t tick, std::vector<event>& events) {
  std::vector<pedestrian> out;
  const double now_s = static_cast<double>(tick) * settings_.tick_s;
  for (std::size_t i = 0; i < settings_.flows.size(); ++i) {
    const auto& f = settings_.flows[i];
    if (now_s < f.start_s || flow_spawned_[i] >= f.count) continue;
    unsigned wanted = f.count - flow_spawned_[i];
    if (f.rate_per_s > 0.0) {
      flow_credit_[i] += f.rate_per_s * settings_.tick_s;
      wanted = std::min(wanted, static_cast<unsigned>(flow_credit_[i]));
    }
    // A few tries per newcomer; the spot may be taken (it then waits for a later tick).
    for (unsigned placed = 0, tries = 0; placed < wanted && tries < 20 * wanted; ++tries) {
      const box& area = f.spawn_area;
      const vec2 p{random_.uniform(area.min.x(), area.max.x()),
                   random_.uniform(area.min.y(), area.max.y())};
      auto candidate = make_flow_pedestrian(next_id_, settings_.run_seed, p, f.exit_portal,
                                            settings_.speeds, settings_.clothes);
      if (!where.fits(p, candidate.state.radius_m()) ||
          !clear_of(p, candidate.state.radius_m(), present, out)) {
        continue;
      }
      events.push_back({tick, next_id_, event_kind::spawned, candidate.state.goal, -1});
      out.push_back(std::move(candidate));
      ++next_id_;
      ++placed;
      ++flow_spawned_[i];
      if (f.rate_per_s > 0.0) flow_credit_[i] -= 1.0;
    }
  }
  if (present.size() + out.size() >= settings_.population) {
    credit_ = 0.0;
    return out;
  }
  credit_ = std::min(credit_ + settings_.spawn_rate_per_min / 60.0 * settings_.tick_s, 5.0);
  int attempts = 0;
  while (credit_ >= 1.0 && present.size() + out.size() < settings_.population && attempts < 8) {
    ++attempts;
    if (place(where, present, out, tick, out, events)) credit_ -= 1.0;
  }
  return out;
}

}  // namespace argus::world

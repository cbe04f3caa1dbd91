#include "actors/snapshot_delta.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <span>
#include <stdexcept>
#include <utility>

#include "caf/binary_deserializer.hpp"
#include "caf/binary_serializer.hpp"
#include "fmt/format.h"

namespace argus::actors {

namespace {

using world::pedestrian_state;

// Bits, not values: -0.0 == 0.0, yet a heading drawn from a -0.0 facing is not the one drawn
// from 0.0, and a worker must see what the coordinator has.
std::uint64_t bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

bool same(double a, double b) {
  return bits_of(a) == bits_of(b);
}

bool same(const world::rgb8& a, const world::rgb8& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

bool same(const world::appearance& a, const world::appearance& b) {
  return same(a.shirt, b.shirt) && same(a.trousers, b.trousers) && same(a.skin, b.skin) &&
         same(a.hair, b.hair) && same(a.height_m, b.height_m) && same(a.girth_m, b.girth_m);
}

double from_bits(std::uint64_t x) {
  return std::bit_cast<double>(x);
}

// A field added to pedestrian_state must be added to its inspector (wire_world.hpp), and to
// moved_state or the comparison below, or a worker would keep a stale value of it.
static_assert(sizeof(pedestrian_state) == 144,
              "pedestrian_state changed: update its inspector, moved_state and same_slow()");

// Everything but what a step changes.
bool same_slow(const pedestrian_state& a, const pedestrian_state& b) {
  return a.id == b.id && a.doing == b.doing && a.goal == b.goal && a.counter == b.counter &&
         a.seat == b.seat && same(a.placed_heading_rad, b.placed_heading_rad) &&
         same(a.look, b.look) && a.queue_join_tick == b.queue_join_tick && a.route == b.route &&
         a.goal_serial == b.goal_serial;
}

moved_state moved_of(const pedestrian_state& p) {
  return {{bits_of(p.position.x()), bits_of(p.position.y()), bits_of(p.velocity.x()),
           bits_of(p.velocity.y()), bits_of(p.facing.x()), bits_of(p.facing.y()),
           bits_of(p.distance_to_goal_m), bits_of(p.squeeze_m)}};
}

void move(pedestrian_state& p, const moved_state& m) {
  const auto& b = m.bits;
  p.position = {from_bits(b[0]), from_bits(b[1])};
  p.velocity = {from_bits(b[2]), from_bits(b[3])};
  p.facing = {from_bits(b[4]), from_bits(b[5])};
  p.distance_to_goal_m = from_bits(b[6]);
  p.squeeze_m = from_bits(b[7]);
}

[[noreturn]] void out_of_step(const std::string& what) {
  throw std::invalid_argument("a snapshot delta does not fit the snapshot before it: " + what);
}

// How `p` differs from `q`, the same pedestrian a tick before, with the record that says so
// appended to `moved` or `whole`.
pedestrian_change change_of(const pedestrian_state& p, const pedestrian_state& q,
                            std::vector<moved_state>& moved, std::vector<pedestrian_state>& whole) {
  if (!same_slow(p, q)) {
    whole.push_back(p);
    return pedestrian_change::changed;
  }
  auto m = moved_of(p);
  if (m == moved_of(q)) return pedestrian_change::kept;
  moved.push_back(m);
  return pedestrian_change::moved;
}

// A delta's records, taken in order; out of step when they run out or some are left over.
class record_reader {
 public:
  record_reader(const std::vector<moved_state>& moved, std::vector<pedestrian_state>& whole)
      : moved_(moved), whole_(whole) {}
  // `was` after the change `c` (kept, moved or changed).
  pedestrian_state after(pedestrian_change c, const pedestrian_state& was) {
    switch (c) {
      case pedestrian_change::kept:
        return was;
      case pedestrian_change::moved: {
        if (next_moved_ == moved_.size()) out_of_step("fewer moves than moved pedestrians");
        auto is = was;
        move(is, moved_[next_moved_++]);
        return is;
      }
      case pedestrian_change::changed: {
        auto& is = next_whole();
        if (is.id != was.id)
          out_of_step(fmt::format("pedestrian {} changed in the place of {}", is.id, was.id));
        return std::move(is);
      }
      default:
        out_of_step(fmt::format("unknown change {}", static_cast<int>(c)));
    }
  }
  pedestrian_state& next_whole() {
    if (next_whole_ == whole_.size()) out_of_step("fewer whole pedestrians than changes");
    return whole_[next_whole_++];
  }
  void all_read() const {
    if (next_moved_ != moved_.size() || next_whole_ != whole_.size())
      out_of_step("records left over");
  }

 private:
  const std::vector<moved_state>& moved_;
  std::vector<pedestrian_state>& whole_;
  std::size_t next_moved_ = 0;
  std::size_t next_whole_ = 0;
};

}  // namespace

serialized_delta serialize(snapshot_delta& delta) {
  serialized_delta out;
  caf::binary_serializer sink{nullptr, out.bytes};
  if (auto err = sink(delta))
    throw std::runtime_error("cannot serialise a snapshot delta: " + caf::to_string(err));
  return out;
}

snapshot_delta deserialize(const serialized_delta& bytes) {
  snapshot_delta out;
  caf::binary_deserializer source{nullptr, bytes.bytes};
  if (auto err = source(out))
    throw std::invalid_argument("a snapshot delta that cannot be read: " + caf::to_string(err));
  return out;
}

snapshot_delta delta_between(const world::snapshot* before, const world::snapshot& now) {
  const std::span<const pedestrian_state> old =
      before ? before->pedestrians() : std::span<const pedestrian_state>{};
  const auto current = now.pedestrians();
  snapshot_delta d;
  d.tick = now.tick();
  d.time_s = now.time().count();
  d.gone.assign(old.size(), 1);
  d.changes.reserve(current.size());
  d.moved.reserve(current.size());
  d.events.assign(now.events().begin(), now.events().end());
  // Both in id order: one walk through the two finds who stayed.
  std::size_t j = 0;
  for (const auto& p : current) {
    while (j < old.size() && old[j].id < p.id) ++j;
    if (j == old.size() || old[j].id != p.id) {
      d.changes.push_back(static_cast<std::uint8_t>(pedestrian_change::arrived));
      d.whole.push_back(p);
      continue;
    }
    d.gone[j] = 0;
    d.changes.push_back(static_cast<std::uint8_t>(change_of(p, old[j++], d.moved, d.whole)));
  }
  return d;
}

std::shared_ptr<const world::snapshot> apply_delta(const world::station& where,
                                                   const world::snapshot* before,
                                                   snapshot_delta delta) {
  const std::span<const pedestrian_state> old =
      before ? before->pedestrians() : std::span<const pedestrian_state>{};
  if (delta.gone.size() != old.size())
    out_of_step(fmt::format("it is for {} pedestrians, the snapshot before (tick {}) has {}",
                            delta.gone.size(), before ? before->tick() : 0, old.size()));
  std::vector<pedestrian_state> people;
  people.reserve(delta.changes.size());
  record_reader records(delta.moved, delta.whole);
  std::size_t j = 0;
  const auto stayed = [&]() -> const pedestrian_state& {
    while (j < old.size() && delta.gone[j] != 0) ++j;
    if (j == old.size()) out_of_step("more pedestrians stayed than were there");
    return old[j++];
  };
  for (auto c : delta.changes) {
    const auto change = static_cast<pedestrian_change>(c);
    people.push_back(change == pedestrian_change::arrived ? std::move(records.next_whole())
                                                          : records.after(change, stayed()));
  }
  while (j < old.size() && delta.gone[j] != 0) ++j;
  if (j != old.size()) out_of_step("a pedestrian before is neither gone nor in it");
  records.all_read();
  return std::make_shared<const world::snapshot>(where, delta.tick,
                                                 std::chrono::duration<double>{delta.time_s},
                                                 std::move(people), std::move(delta.events));
}

subset_delta subset_between(const world::snapshot& before, std::span<const world::pedestrian> now) {
  const auto old = before.pedestrians();
  subset_delta d;
  d.changes.assign(old.size(), subset_delta::absent);
  d.moved.reserve(now.size());
  std::size_t j = 0;
  for (const auto& each : now) {
    const auto& p = each.state;
    while (j < old.size() && old[j].id < p.id) ++j;
    if (j == old.size() || old[j].id != p.id)
      throw std::invalid_argument(
          fmt::format("pedestrian {} is not in the snapshot of tick {}, or out of id order", p.id,
                      before.tick()));
    d.changes[j] = static_cast<std::uint8_t>(change_of(p, old[j], d.moved, d.whole));
    ++j;
  }
  return d;
}

std::vector<std::vector<pedestrian_state>> apply_subsets(const world::snapshot& before,
                                                         std::vector<subset_delta> deltas) {
  const auto old = before.pedestrians();
  for (const auto& delta : deltas)
    if (delta.changes.size() != old.size())
      out_of_step(
          fmt::format("a partition's states are for {} pedestrians, the snapshot of tick {} "
                      "has {}",
                      delta.changes.size(), before.tick(), old.size()));
  std::vector<std::vector<pedestrian_state>> out(deltas.size());
  std::vector<record_reader> records;
  records.reserve(deltas.size());
  for (std::size_t d = 0; d < deltas.size(); ++d) {
    const auto& changes = deltas[d].changes;
    out[d].reserve(static_cast<std::size_t>(std::count_if(
        changes.begin(), changes.end(), [](std::uint8_t c) { return c != subset_delta::absent; })));
    records.emplace_back(deltas[d].moved, deltas[d].whole);
  }
  // One pass over `before` for all the subsets: each on its own reached into it at scattered
  // places, a cache miss per pedestrian (about 0.8 ms a tick for the large station's 10,000).
  for (std::size_t j = 0; j < old.size(); ++j)
    for (std::size_t d = 0; d < deltas.size(); ++d)
      if (const auto c = deltas[d].changes[j]; c != subset_delta::absent)
        out[d].push_back(records[d].after(static_cast<pedestrian_change>(c), old[j]));
  for (const auto& r : records) r.all_read();
  return out;
}

}  // namespace argus::actors

#include "protocol/group_messages.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <tuple>
#include <type_traits>

namespace argus::protocol {
namespace {

// Bodies are little-endian fixed-width fields, vectors prefixed by a 16-bit count. Nothing
// here is aligned or padded: a body is as small as its fields.
constexpr std::size_t max_count = 65535;
// A signature's bins multiply out to at most this many (16 x 16 x 16).
constexpr std::size_t max_signature_bins = 4096;
// Set in a signature's count of filled bins when its halves follow: a signature without them
// is encoded as before halves existed, byte for byte.
constexpr std::uint16_t halves_follow = 0x8000;

class writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out_.append(bytes, sizeof(T));
  }
  void put(bool value) { put<std::uint8_t>(value ? 1 : 0); }
  template <class T>
  void put_vector(const std::vector<T>& values) {
    put(static_cast<std::uint16_t>(std::min(values.size(), max_count)));
    for (std::size_t i = 0; i < std::min(values.size(), max_count); ++i) put(values[i]);
  }
  // Sparse: a pedestrian's histogram fills few of its bins.
  void put(const signature& s) {
    put(s.hue_bins);
    put(s.saturation_bins);
    put(s.value_bins);
    const bool halves = !s.upper.empty() || !s.lower.empty();
    put_sparse(s.values, halves ? halves_follow : 0);
    if (!halves) return;
    put_sparse(s.upper, 0);
    put_sparse(s.lower, 0);
  }
  void put_sparse(const std::vector<float>& values, std::uint16_t flags) {
    std::uint16_t filled = 0;
    for (float v : values) filled += v != 0.0f ? 1 : 0;
    put(static_cast<std::uint16_t>(filled | flags));
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i] == 0.0f) continue;
      put(static_cast<std::uint16_t>(i));
      put(values[i]);
    }
  }
  void put(const task_description& t) {
    put(t.task);
    put(t.target);
    put(t.min_cameras);
    put(t.max_cameras);
  }
  void put(const camera_relevance& c) {
    put(c.camera);
    put(c.relevance);
  }
  void put(const conflict_claim& c) {
    put(c.task);
    put(c.leader);
    put(c.term);
    put(c.relevance);
  }
  void put(const csp_assignment& a) {
    put(a.task);
    put(a.leader);
    put(a.term);
    put(a.previous);
    put(a.relevance);
    put_vector(a.members);
    put(a.minimum);
  }
  // Longer strings are refused by encode: a note is never cut short.
  void put(const std::string& bytes) {
    put(static_cast<std::uint16_t>(bytes.size()));
    out_.append(bytes);
  }
  template <class T>
  void put_any(const T& x) {
    put(x);
  }
  template <class T>
  void put_any(const std::vector<T>& x) {
    put_vector(x);
  }
  template <class T>
  void put_any(const std::optional<T>& x) {
    put(x.has_value());
    put(x.value_or(T{}));
  }
  std::string take() && { return std::move(out_); }

 private:
  std::string out_;
};

class reader {
 public:
  explicit reader(std::string_view in) : in_(in) {}

  template <class T>
  bool get(T& value) {
    static_assert(std::is_arithmetic_v<T>);
    if (in_.size() - at_ < sizeof(T)) return false;
    std::memcpy(&value, in_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    if constexpr (std::is_floating_point_v<T>) return std::isfinite(value);
    return true;
  }
  bool get(bool& value) {
    std::uint8_t b = 0;
    if (!get(b) || b > 1) return false;
    value = b == 1;
    return true;
  }
  template <class T>
  bool get_vector(std::vector<T>& values) {
    std::uint16_t n = 0;
    if (!get(n)) return false;
    values.resize(n);
    for (auto& v : values)
      if (!get(v)) return false;
    return true;
  }
  bool get(signature& s) {
    if (!get(s.hue_bins) || !get(s.saturation_bins) || !get(s.value_bins)) return false;
    const std::size_t bins = std::size_t{s.hue_bins} * s.saturation_bins * s.value_bins;
    if (bins == 0 || bins > max_signature_bins) return false;
    bool halves = false;
    if (!get_sparse(s.values, bins, &halves)) return false;
    s.upper.clear();
    s.lower.clear();
    return !halves || (get_sparse(s.upper, bins, nullptr) && get_sparse(s.lower, bins, nullptr));
  }
  // `halves` receives the flag; where none may be set (nullptr), a set flag is malformed.
  bool get_sparse(std::vector<float>& values, std::size_t bins, bool* halves) {
    std::uint16_t filled = 0;
    if (!get(filled)) return false;
    const bool flagged = (filled & halves_follow) != 0;
    if (flagged && !halves) return false;
    if (halves) *halves = flagged;
    filled = static_cast<std::uint16_t>(filled & ~halves_follow);
    if (filled > bins) return false;
    values.assign(bins, 0.0f);
    for (std::uint16_t k = 0; k < filled; ++k) {
      std::uint16_t index = 0;
      float value = 0.0f;
      if (!get(index) || !get(value) || index >= bins || value < 0.0f) return false;
      values[index] = value;
    }
    return true;
  }
  bool get(task_description& t) {
    return get(t.task) && get(t.target) && get(t.min_cameras) && get(t.max_cameras) &&
           t.min_cameras <= t.max_cameras;
  }
  bool get(camera_relevance& c) { return get(c.camera) && get(c.relevance); }
  bool get(conflict_claim& c) {
    return get(c.task) && get(c.leader) && get(c.term) && get(c.relevance);
  }
  bool get(csp_assignment& a) {
    return get(a.task) && get(a.leader) && get(a.term) && get(a.previous) && get(a.relevance) &&
           get_vector(a.members) && get(a.minimum);
  }
  bool get(std::string& bytes) {
    std::uint16_t n = 0;
    if (!get(n) || in_.size() - at_ < n) return false;
    bytes.assign(in_.data() + at_, n);
    at_ += n;
    return true;
  }
  template <class T>
  bool get_any(T& x) {
    return get(x);
  }
  template <class T>
  bool get_any(std::vector<T>& x) {
    return get_vector(x);
  }
  template <class T>
  bool get_any(std::optional<T>& x) {
    bool present = false;
    T value{};
    if (!get(present) || !get(value)) return false;
    if (present) x = value;
    return true;
  }
  bool done() const noexcept { return at_ == in_.size(); }

 private:
  std::string_view in_;
  std::size_t at_ = 0;
};

// Each message's fields, in wire order: the one list both directions use.
auto fields(query_relevance& m) {
  return std::tie(m.task, m.leader, m.term, m.auction, m.relay);
}
auto fields(relevance_bid& m) {
  return std::tie(m.task, m.leader, m.term, m.auction, m.bidder, m.relevance, m.busy, m.locked,
                  m.other_task, m.other_leader);
}
auto fields(join& m) {
  return std::tie(m.task, m.leader, m.term, m.invitee, m.reassign);
}
auto fields(status& m) {
  return std::tie(m.task, m.sender, m.leader, m.term, m.relevance, m.min_cameras, m.max_cameras,
                  m.members, m.leaving);
}
auto fields(handover& m) {
  return std::tie(m.task, m.old_leader, m.new_leader, m.term, m.members);
}
auto fields(demotion& m) {
  return std::tie(m.task, m.sender, m.term, m.members);
}
auto fields(csp_conflict& m) {
  return std::tie(m.camera, m.claims);
}
auto fields(csp_query& m) {
  return std::tie(m.solver_task, m.solver, m.term, m.round);
}
auto fields(csp_data& m) {
  return std::tie(m.task, m.leader, m.term, m.round, m.candidates, m.members, m.pinned);
}
auto fields(csp_result& m) {
  return std::tie(m.solver_task, m.solver, m.term, m.round, m.groups);
}
auto fields(task_cancel& m) {
  return std::tie(m.task, m.sender);
}
auto fields(note& m) {
  return std::tie(m.task, m.sender, m.topic, m.body);
}

bool is_relevance(double r) {
  return r >= 0.0 && r <= 1.0;
}

// What a whole message must also satisfy, beyond each field's own checks.
template <class T>
bool valid(const T&) {
  return true;
}
bool valid(const relevance_bid& m) {
  return is_relevance(m.relevance);
}
bool valid(const status& m) {
  return is_relevance(m.relevance);
}
bool valid(const csp_data& m) {
  return std::all_of(m.candidates.begin(), m.candidates.end(),
                     [](const camera_relevance& c) { return is_relevance(c.relevance); });
}
bool valid(const csp_result& m) {
  return std::all_of(m.groups.begin(), m.groups.end(), [](const csp_assignment& a) {
    return is_relevance(a.relevance) &&
           std::all_of(a.members.begin(), a.members.end(),
                       [](const camera_relevance& c) { return is_relevance(c.relevance); });
  });
}
bool valid(const csp_conflict& m) {
  return m.claims.size() >= 2 &&
         std::all_of(m.claims.begin(), m.claims.end(),
                     [](const conflict_claim& c) { return is_relevance(c.relevance); });
}

template <class T>
void write(writer& w, const T& m) {
  // The writer only reads the fields; fields() takes them mutable for the reader's sake.
  std::apply([&w](const auto&... x) { (w.put_any(x), ...); }, fields(const_cast<T&>(m)));
}

template <class T>
bool read(reader& r, T& m) {
  return std::apply([&r](auto&... x) { return (r.get_any(x) && ...); }, fields(m)) && valid(m);
}

std::string_view demotion_kind(demotion_step step) {
  switch (step) {
    case demotion_step::demote:
      return "demote";
    case demotion_step::ack:
      return "demoteack";
    case demotion_step::nack:
      return "demotenack";
    case demotion_step::retry:
      return "demoteretry";
  }
  return "demote";
}

template <class T>
std::optional<group_message> read_whole(std::string_view body) {
  T m;
  reader r(body);
  if (!read(r, m) || !r.done()) return std::nullopt;
  return group_message{std::move(m)};
}

}  // namespace

std::string_view kind_of(const group_message& m) {
  struct namer {
    std::string_view operator()(const query_relevance&) const { return "queryrelevance"; }
    std::string_view operator()(const relevance_bid&) const { return "relevance"; }
    std::string_view operator()(const join&) const { return "join"; }
    std::string_view operator()(const status&) const { return "status"; }
    std::string_view operator()(const handover&) const { return "handover"; }
    std::string_view operator()(const demotion& d) const { return demotion_kind(d.step); }
    std::string_view operator()(const csp_conflict&) const { return "cspconflict"; }
    std::string_view operator()(const csp_query&) const { return "cspquery"; }
    std::string_view operator()(const csp_data&) const { return "cspdata"; }
    std::string_view operator()(const csp_result&) const { return "cspresult"; }
    std::string_view operator()(const task_cancel&) const { return "cancel"; }
    std::string_view operator()(const note&) const { return "note"; }
  };
  return std::visit(namer{}, m);
}

task_id task_of(const group_message& m) {
  struct finder {
    task_id operator()(const query_relevance& x) const { return x.task.task; }
    task_id operator()(const relevance_bid& x) const { return x.task; }
    task_id operator()(const join& x) const { return x.task.task; }
    task_id operator()(const status& x) const { return x.task; }
    task_id operator()(const handover& x) const { return x.task.task; }
    task_id operator()(const demotion& x) const { return x.task; }
    task_id operator()(const csp_query& x) const { return x.solver_task; }
    task_id operator()(const csp_conflict& x) const {
      task_id lowest = x.claims.empty() ? 0 : x.claims.front().task;
      for (const auto& c : x.claims) lowest = std::min(lowest, c.task);
      return lowest;
    }
    task_id operator()(const csp_data& x) const { return x.task.task; }
    task_id operator()(const csp_result& x) const { return x.solver_task; }
    task_id operator()(const task_cancel& x) const { return x.task; }
    task_id operator()(const note& x) const { return x.task; }
  };
  return std::visit(finder{}, m);
}

bool is_group_kind(std::string_view kind) {
  for (std::string_view k : {"queryrelevance", "relevance", "join", "status", "handover", "demote",
                             "demoteack", "demotenack", "demoteretry", "cspconflict", "cspquery",
                             "cspdata", "cspresult", "cancel", "note"})
    if (kind == k) return true;
  return false;
}

std::string encode(const group_message& m) {
  if (const auto* n = std::get_if<note>(&m);
      n != nullptr && (n->topic.size() > max_count || n->body.size() > max_count))
    throw std::length_error("a note's topic and body are at most 65,535 bytes each");
  writer w;
  std::visit([&w](const auto& x) { write(w, x); }, m);
  return std::move(w).take();
}

std::optional<group_message> decode(std::string_view kind, std::string_view body) {
  if (kind == "queryrelevance") return read_whole<query_relevance>(body);
  if (kind == "relevance") return read_whole<relevance_bid>(body);
  if (kind == "join") return read_whole<join>(body);
  if (kind == "status") return read_whole<status>(body);
  if (kind == "handover") return read_whole<handover>(body);
  if (kind == "cspconflict") return read_whole<csp_conflict>(body);
  if (kind == "cspquery") return read_whole<csp_query>(body);
  if (kind == "cspdata") return read_whole<csp_data>(body);
  if (kind == "cspresult") return read_whole<csp_result>(body);
  if (kind == "cancel") return read_whole<task_cancel>(body);
  if (kind == "note") return read_whole<note>(body);
  for (auto step :
       {demotion_step::demote, demotion_step::ack, demotion_step::nack, demotion_step::retry}) {
    if (kind != demotion_kind(step)) continue;
    auto m = read_whole<demotion>(body);
    if (m) std::get<demotion>(*m).step = step;
    return m;
  }
  return std::nullopt;
}

}  // namespace argus::protocol

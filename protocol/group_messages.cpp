#include "protocol/group_messages.hpp"

#include <cmath>
#include <cstring>
#include <type_traits>

namespace argus::protocol {
namespace {

// Bodies are little-endian fixed-width fields, vectors prefixed by a 16-bit count. Nothing
// here is aligned or padded: a body is as small as its fields.
constexpr std::size_t max_count = 65535;
// A signature's bins multiply out to at most this many (16 x 16 x 16).
constexpr std::size_t max_signature_bins = 4096;

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
    std::uint16_t filled = 0;
    for (float v : s.values) filled += v != 0.0f ? 1 : 0;
    put(filled);
    for (std::size_t i = 0; i < s.values.size(); ++i) {
      if (s.values[i] == 0.0f) continue;
      put(static_cast<std::uint16_t>(i));
      put(s.values[i]);
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
    std::uint16_t filled = 0;
    if (!get(s.hue_bins) || !get(s.saturation_bins) || !get(s.value_bins) || !get(filled))
      return false;
    const std::size_t bins = std::size_t{s.hue_bins} * s.saturation_bins * s.value_bins;
    if (bins == 0 || bins > max_signature_bins || filled > bins) return false;
    s.values.assign(bins, 0.0f);
    for (std::uint16_t k = 0; k < filled; ++k) {
      std::uint16_t index = 0;
      float value = 0.0f;
      if (!get(index) || !get(value) || index >= bins || value < 0.0f) return false;
      s.values[index] = value;
    }
    return true;
  }
  bool get(task_description& t) {
    return get(t.task) && get(t.target) && get(t.min_cameras) && get(t.max_cameras) &&
           t.min_cameras <= t.max_cameras;
  }
  bool get(camera_relevance& c) { return get(c.camera) && get(c.relevance); }
  bool done() const noexcept { return at_ == in_.size(); }

 private:
  std::string_view in_;
  std::size_t at_ = 0;
};

void write(writer& w, const query_relevance& m) {
  w.put(m.task);
  w.put(m.leader);
  w.put(m.auction);
  w.put(m.relay);
}
bool read(reader& r, query_relevance& m) {
  return r.get(m.task) && r.get(m.leader) && r.get(m.auction) && r.get(m.relay);
}

void write(writer& w, const relevance_bid& m) {
  w.put(m.task);
  w.put(m.leader);
  w.put(m.auction);
  w.put(m.bidder);
  w.put(m.relevance);
  w.put(m.busy);
  w.put(m.locked);
  w.put(m.other_task.has_value());
  w.put(m.other_task.value_or(0));
  w.put(m.other_leader);
}
bool read(reader& r, relevance_bid& m) {
  bool has_other = false;
  task_id other = 0;
  if (!(r.get(m.task) && r.get(m.leader) && r.get(m.auction) && r.get(m.bidder) &&
        r.get(m.relevance) && r.get(m.busy) && r.get(m.locked) && r.get(has_other) &&
        r.get(other) && r.get(m.other_leader)))
    return false;
  if (has_other) m.other_task = other;
  return m.relevance >= 0.0 && m.relevance <= 1.0;
}

void write(writer& w, const join& m) {
  w.put(m.task);
  w.put(m.leader);
  w.put(m.invitee);
  w.put(m.reassign);
}
bool read(reader& r, join& m) {
  return r.get(m.task) && r.get(m.leader) && r.get(m.invitee) && r.get(m.reassign);
}

void write(writer& w, const status& m) {
  w.put(m.task);
  w.put(m.sender);
  w.put(m.leader);
  w.put(m.relevance);
  w.put(m.min_cameras);
  w.put(m.max_cameras);
  w.put_vector(m.members);
}
bool read(reader& r, status& m) {
  return r.get(m.task) && r.get(m.sender) && r.get(m.leader) && r.get(m.relevance) &&
         r.get(m.min_cameras) && r.get(m.max_cameras) && r.get_vector(m.members) &&
         m.relevance >= 0.0 && m.relevance <= 1.0;
}

void write(writer& w, const handover& m) {
  w.put(m.task);
  w.put(m.old_leader);
  w.put(m.new_leader);
  w.put_vector(m.members);
}
bool read(reader& r, handover& m) {
  return r.get(m.task) && r.get(m.old_leader) && r.get(m.new_leader) && r.get_vector(m.members);
}

void write(writer& w, const demotion& m) {
  w.put(m.task);
  w.put(m.sender);
  w.put_vector(m.members);
}
bool read(reader& r, demotion& m) {
  return r.get(m.task) && r.get(m.sender) && r.get_vector(m.members);
}

void write(writer& w, const csp_query& m) {
  w.put(m.solver_task);
  w.put(m.solver);
  w.put(m.round);
}
bool read(reader& r, csp_query& m) {
  return r.get(m.solver_task) && r.get(m.solver) && r.get(m.round);
}

void write(writer& w, const csp_data& m) {
  w.put(m.task);
  w.put(m.leader);
  w.put(m.round);
  w.put(m.min_cameras);
  w.put(m.max_cameras);
  w.put_vector(m.candidates);
  w.put_vector(m.pinned);
}
bool read(reader& r, csp_data& m) {
  if (!(r.get(m.task) && r.get(m.leader) && r.get(m.round) && r.get(m.min_cameras) &&
        r.get(m.max_cameras) && r.get_vector(m.candidates) && r.get_vector(m.pinned)))
    return false;
  for (const auto& c : m.candidates)
    if (c.relevance < 0.0 || c.relevance > 1.0) return false;
  return m.min_cameras <= m.max_cameras;
}

void write(writer& w, const csp_result& m) {
  w.put(m.task);
  w.put(m.solver);
  w.put_vector(m.cameras);
  w.put(m.minimum);
}
bool read(reader& r, csp_result& m) {
  return r.get(m.task) && r.get(m.solver) && r.get_vector(m.cameras) && r.get(m.minimum);
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
    std::string_view operator()(const csp_query&) const { return "cspquery"; }
    std::string_view operator()(const csp_data&) const { return "cspdata"; }
    std::string_view operator()(const csp_result&) const { return "cspresult"; }
  };
  return std::visit(namer{}, m);
}

bool is_group_kind(std::string_view kind) {
  for (std::string_view k :
       {"queryrelevance", "relevance", "join", "status", "handover", "demote", "demoteack",
        "demotenack", "demoteretry", "cspquery", "cspdata", "cspresult"})
    if (kind == k) return true;
  return false;
}

std::string encode(const group_message& m) {
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
  if (kind == "cspquery") return read_whole<csp_query>(body);
  if (kind == "cspdata") return read_whole<csp_data>(body);
  if (kind == "cspresult") return read_whole<csp_result>(body);
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

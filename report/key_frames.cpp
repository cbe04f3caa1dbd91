#include "report/key_frames.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "fmt/format.h"

namespace argus::report {

namespace {

bool applied(const nlohmann::json& e) {
  return !e.contains("applied") || e.value("applied", false);
}

// The key event `e` stands for, if any (key_events_of's table).
std::optional<key_event> key_event_of(const nlohmann::json& e) {
  const std::string kind = text_field(e, "kind");
  const auto tick = integer_field(e, "tick");
  const int camera = static_cast<int>(integer_field(e, "camera"));
  if (tick < 0) return std::nullopt;
  key_event out;
  out.time_s = e.contains("t") && e["t"].is_number() ? e["t"].get<double>() : 0.0;
  out.tick = tick;
  out.task = static_cast<int>(integer_field(e, "task"));
  const auto seen = world_tick_seen_at(tick);
  if (kind == "task_created") {
    if (camera < 0) return std::nullopt;
    out.kind = kind;
    out.detail = fmt::format("camera {}", camera);
    out.frames.push_back({camera, seen, false});
  } else if (kind == "handoff") {
    const int from = static_cast<int>(integer_field(e, "from", camera));
    const int to = static_cast<int>(integer_field(e, "to"));
    if (from < 0 || to < 0) return std::nullopt;
    out.kind = kind;
    out.detail = fmt::format("{} -> {}", from, to);
    out.frames.push_back({from, seen, false});
    out.frames.push_back({to, seen, false});
  } else if (kind == "leader_changed") {
    const int leader = static_cast<int>(integer_field(e, "leader", camera));
    if (leader < 0) return std::nullopt;
    out.kind = kind;
    const auto previous = integer_field(e, "previous");
    const auto reason = text_field(e, "reason");
    out.detail = fmt::format("leader {}", leader);
    if (previous >= 0 && !reason.empty())
      out.detail += fmt::format(" (was {}, {})", previous, reason);
    else if (previous >= 0)
      out.detail += fmt::format(" (was {})", previous);
    else if (!reason.empty())
      out.detail += fmt::format(" ({})", reason);
    out.frames.push_back({leader, seen, false});
  } else if (kind == "fault") {
    const auto fault = text_field(e, "fault");
    if ((fault != "crash" && fault != "crash_and_recover") || !applied(e) || camera < 0)
      return std::nullopt;
    out.kind = "camera_failed";
    out.task = -1;
    out.detail =
        fmt::format("camera {} {}", camera, fault == "crash" ? "crashed" : "crashed (to recover)");
    out.frames.push_back({camera, tick, true});
  } else if (kind == "node_recovered") {
    if (!applied(e) || camera < 0) return std::nullopt;
    out.kind = "camera_recovered";
    out.task = -1;
    out.detail = fmt::format("camera {} back", camera);
    out.frames.push_back({camera, seen, false});
  } else {
    return std::nullopt;
  }
  return out;
}

std::size_t frames_of(const std::vector<key_event>& events, const std::vector<std::size_t>& at) {
  std::size_t n = 0;
  for (auto k : at) n += events[k].frames.size();
  return n;
}

// k indices spread evenly over 0 .. n - 1, first and last included (k <= n).
std::vector<std::size_t> evenly(std::size_t n, std::size_t k) {
  std::vector<std::size_t> out;
  if (k == 0 || n == 0) return out;
  if (k == 1) return {0};
  for (std::size_t i = 0; i < k; ++i) {
    const auto at = static_cast<std::size_t>(std::llround(
        static_cast<double>(i) * static_cast<double>(n - 1) / static_cast<double>(k - 1)));
    if (out.empty() || out.back() != at) out.push_back(at);
  }
  return out;
}

}  // namespace

std::vector<key_event> key_events_of(const event_log& log) {
  std::vector<key_event> out;
  for (const auto& e : log.events)
    if (auto k = key_event_of(e)) out.push_back(std::move(*k));
  // A run logs in time order; a log put together otherwise still reads in time order.
  std::stable_sort(out.begin(), out.end(),
                   [](const key_event& a, const key_event& b) { return a.tick < b.tick; });
  return out;
}

key_event_selection select_key_events(std::vector<key_event> events, std::size_t max_frames) {
  key_event_selection out;
  std::size_t total_frames = 0;
  for (const auto& e : events) total_frames += e.frames.size();
  if (total_frames <= max_frames) {
    out.shown = std::move(events);
    return out;
  }
  // Each event has at least one frame, so at most max_frames events fit; fewer when some have
  // two. The largest even spread whose frames fit.
  std::vector<std::size_t> chosen;
  for (std::size_t k = std::min(events.size(), max_frames); k > 0; --k) {
    chosen = evenly(events.size(), k);
    if (frames_of(events, chosen) <= max_frames) break;
    chosen.clear();
  }
  std::size_t shown_frames = 0;
  for (auto k : chosen) {
    shown_frames += events[k].frames.size();
    out.shown.push_back(std::move(events[k]));
  }
  out.events_left_out = events.size() - out.shown.size();
  out.frames_left_out = total_frames - shown_frames;
  return out;
}

}  // namespace argus::report

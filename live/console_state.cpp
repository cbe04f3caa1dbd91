#include "live/console_state.hpp"

#include <chrono>

#include "fmt/format.h"

namespace argus::live {
namespace {

// How many positions a tasked target's trail keeps (one per snapshot, 15 per second).
constexpr std::size_t trail_points = 600;
// How many notable events the page's log shows.
constexpr std::size_t recent_events = 40;

int camera_of(const std::string& source) {
  constexpr std::string_view prefix = "camera/";
  if (source.rfind(prefix, 0) != 0) return -1;
  return std::atoi(source.c_str() + prefix.size());
}

int int_field(const nlohmann::json& f, const char* key, int fallback = -1) {
  const auto it = f.find(key);
  return it != f.end() && it->is_number_integer() ? it->get<int>() : fallback;
}

double wall_now() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

}  // namespace

console_state::console_state(const config::scenario& scenario)
    : tick_seconds_(scenario.run.tick.count()),
      end_tick_(static_cast<std::int64_t>(scenario.run.duration / scenario.run.tick + 0.5)) {
  for (const auto& c : scenario.cameras) {
    auto& e = cameras_[c.id];
    e.x_m = c.position.x_m;
    e.y_m = c.position.y_m;
    e.pan_deg = c.pan_deg;
    e.tilt_deg = c.tilt_deg;
    e.field_of_view_deg = c.field_of_view_deg;
    e.frame.camera = c.id;
  }
}

void console_state::publish_snapshot(std::shared_ptr<const world::snapshot> frame) {
  std::lock_guard<std::mutex> guard(mutex_);
  tick_ = static_cast<std::int64_t>(frame->tick());
  for (auto& [task, t] : tasks_) {
    if (t.pedestrian < 0 || t.status != "observed") continue;
    if (const auto* who = frame->find(t.pedestrian)) {
      t.trail.push_back({who->position.x(), who->position.y()});
      if (t.trail.size() > trail_points) t.trail.pop_front();
    }
  }
  snapshot_ = std::move(frame);
}

void console_state::publish_camera(int camera, std::int64_t tick, double pan_deg, double tilt_deg,
                                   double field_of_view_deg, const cv::Mat& image,
                                   std::vector<cv::Rect2d> boxes) {
  std::lock_guard<std::mutex> guard(mutex_);
  auto it = cameras_.find(camera);
  if (it == cameras_.end()) return;
  auto& e = it->second;
  e.pan_deg = pan_deg;
  e.tilt_deg = tilt_deg;
  e.field_of_view_deg = field_of_view_deg;
  if (image.empty()) return;
  e.frame.tick = tick;
  ++e.frame.sequence;
  e.frame.image = image;  // shares the node's buffer: the node never writes a sensed frame again
  e.frame.boxes = std::move(boxes);
}

void console_state::record_events(std::span<const event_line> events) {
  std::lock_guard<std::mutex> guard(mutex_);
  for (const auto& ev : events) apply(ev);
}

void console_state::note(std::string line) {
  std::lock_guard<std::mutex> guard(mutex_);
  recent_.push_back(std::move(line));
  if (recent_.size() > recent_events) recent_.pop_front();
}

void console_state::apply(const event_line& ev) {
  static const std::set<std::string> shown{
      "task_issued", "task_cancelled", "task_refused",   "task_target", "task_created",
      "joined",      "left_task",      "leader_changed", "fault",       "node_recovered",
      "handoff",     "group_vanished", "render_failed"};
  if (shown.count(ev.kind) != 0) {
    recent_.push_back(fmt::format("t={:.1f}s {} {} {}",
                                  static_cast<double>(ev.tick) * tick_seconds_, ev.source, ev.kind,
                                  ev.fields_json));
    if (recent_.size() > recent_events) recent_.pop_front();
  }
  if (ev.kind == "net_sent" || ev.kind == "net_received") return;
  const auto f = nlohmann::json::parse("{" + ev.fields_json + "}", nullptr, false);
  if (f.is_discarded()) return;
  const int camera = int_field(f, "camera", camera_of(ev.source));
  const int task = int_field(f, "task");
  auto cam = cameras_.find(camera);
  if (ev.kind == "node_state" && cam != cameras_.end() && f.contains("to")) {
    cam->second.state = f["to"].get<std::string>();
    if (cam->second.state == "idle") cam->second.tracking.clear();
  } else if (ev.kind == "tracking" && cam != cameras_.end() && f.contains("state")) {
    cam->second.tracking = f["state"].get<std::string>();
  } else if (ev.kind == "task_issued" && task >= 0) {
    auto& t = tasks_[task];
    t.camera = camera;
    t.issued_tick = ev.tick;
    t.status = "issued";
    t.pedestrian = int_field(f, "pedestrian");
  } else if (ev.kind == "task_target" && task >= 0) {
    tasks_[task].pedestrian = int_field(f, "pedestrian");
    tasks_[task].status = "observed";
  } else if (ev.kind == "task_refused" && task >= 0) {
    tasks_[task].status = "refused: " + f.value("reason", std::string("?"));
  } else if (ev.kind == "task_cancelled" && task >= 0) {
    tasks_[task].status = "cancelled";
  } else if (ev.kind == "task_created" && task >= 0) {
    groups_[task] = group_entry{camera, {camera}};
  } else if (ev.kind == "joined" && task >= 0) {
    auto& g = groups_[task];
    g.members.insert(camera);
    g.leader = int_field(f, "leader", g.leader);
  } else if (ev.kind == "left_task" && task >= 0) {
    auto g = groups_.find(task);
    if (g != groups_.end()) {
      g->second.members.erase(camera);
      if (g->second.leader == camera) g->second.leader = 0;
      if (g->second.members.empty()) groups_.erase(g);
    }
  } else if (ev.kind == "leader_changed" && task >= 0) {
    auto& g = groups_[task];
    g.members.insert(camera);
    g.leader = int_field(f, "leader", g.leader);
  } else if (ev.kind == "fault" && f.value("applied", false) && cam != cameras_.end() &&
             f.value("fault", std::string()) == "crash") {
    cam->second.alive = false;
    cam->second.state = "crashed";
    cam->second.tracking.clear();
    cam->second.frame.image = cv::Mat();
    for (auto it = groups_.begin(); it != groups_.end();) {
      it->second.members.erase(camera);
      it = it->second.members.empty() ? groups_.erase(it) : std::next(it);
    }
  } else if (ev.kind == "node_recovered" && f.value("applied", false) && cam != cameras_.end()) {
    cam->second.alive = true;
    cam->second.state = "idle";
  }
}

nlohmann::json console_state::state_json() const {
  nlohmann::json out;
  std::lock_guard<std::mutex> guard(mutex_);
  const auto now = wall_now();
  const auto sent = sent_.load(std::memory_order_relaxed);
  const auto received = received_.load(std::memory_order_relaxed);
  if (samples_.empty() || now - samples_.back().wall_s >= 0.2)
    samples_.push_back({now, tick_, sent, received});
  while (samples_.size() > 2 && now - samples_.front().wall_s > 3.0) samples_.pop_front();
  const auto& first = samples_.front();
  const double span_s = now - first.wall_s;
  const auto per_s = [&](double count) { return span_s > 0.0 ? count / span_s : 0.0; };
  out["tick"] = tick_;
  out["t"] = static_cast<double>(tick_) * tick_seconds_;
  out["end_t"] = static_cast<double>(end_tick_) * tick_seconds_;
  out["finished"] = finished_.load();
  out["speed_ratio"] = per_s(static_cast<double>(tick_ - first.tick) * tick_seconds_);
  out["messages"] = {{"sent", sent},
                     {"received", received},
                     {"sent_per_s", per_s(static_cast<double>(sent - first.sent))},
                     {"received_per_s", per_s(static_cast<double>(received - first.received))},
                     {"lost_or_in_flight", sent > received ? sent - received : 0}};
  auto& pedestrians = out["pedestrians"] = nlohmann::json::array();
  if (snapshot_) {
    for (const auto& p : snapshot_->pedestrians()) {
      const auto& shirt = p.look.shirt;
      pedestrians.push_back({p.id, std::round(p.position.x() * 100.0) / 100.0,
                             std::round(p.position.y() * 100.0) / 100.0,
                             fmt::format("#{:02x}{:02x}{:02x}", shirt.r, shirt.g, shirt.b)});
    }
  }
  auto& cameras = out["cameras"] = nlohmann::json::array();
  for (const auto& [id, c] : cameras_) {
    int group = -1;
    for (const auto& [task, g] : groups_)
      if (g.members.count(id) != 0) group = task;
    cameras.push_back({{"id", id},
                       {"x", c.x_m},
                       {"y", c.y_m},
                       {"pan", c.pan_deg},
                       {"tilt", c.tilt_deg},
                       {"fov", c.field_of_view_deg},
                       {"alive", c.alive},
                       {"state", c.state},
                       {"tracking", c.tracking},
                       {"task", group},
                       {"frame", c.frame.sequence},
                       {"has_frame", !c.frame.image.empty()}});
  }
  auto& groups = out["groups"] = nlohmann::json::array();
  for (const auto& [task, g] : groups_)
    groups.push_back({{"task", task},
                      {"leader", g.leader},
                      {"members", std::vector<int>(g.members.begin(), g.members.end())}});
  auto& tasks = out["tasks"] = nlohmann::json::array();
  for (const auto& [index, t] : tasks_) {
    nlohmann::json trail = nlohmann::json::array();
    // Every 5th point: the page draws a line, not each frame.
    for (std::size_t i = 0; i < t.trail.size(); i += 5) trail.push_back(t.trail[i]);
    tasks.push_back({{"task", index},
                     {"camera", t.camera},
                     {"pedestrian", t.pedestrian},
                     {"status", t.status},
                     {"issued_t", static_cast<double>(t.issued_tick) * tick_seconds_},
                     {"trail", std::move(trail)}});
  }
  out["recent"] = std::vector<std::string>(recent_.rbegin(), recent_.rend());
  return out;
}

std::optional<feed_frame> console_state::feed(int camera) const {
  std::lock_guard<std::mutex> guard(mutex_);
  const auto it = cameras_.find(camera);
  if (it == cameras_.end() || it->second.frame.image.empty()) return std::nullopt;
  return it->second.frame;
}

std::optional<camera_pose> console_state::pose(int camera) const {
  std::lock_guard<std::mutex> guard(mutex_);
  const auto it = cameras_.find(camera);
  if (it == cameras_.end()) return std::nullopt;
  const auto& c = it->second;
  return camera_pose{tick_, c.pan_deg, c.tilt_deg, c.field_of_view_deg, c.alive};
}

}  // namespace argus::live

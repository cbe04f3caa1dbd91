#pragma once

// A handful of camera controllers on an ideal, fully connected network with a fixed delay, for
// testing the protocol's logic frame by frame without actors. Sensing is a function the test
// gives: where (if anywhere) camera c sees the target of task t at tick k. Messages go through
// encode/decode, as on the wire; a test can drop any of them.

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "controller/camera_controller.hpp"
#include "protocol/net_message.hpp"

namespace argus::controller::testing {

/// A frame of 320 x 240; limits wide enough that a centred box scores near 1.
inline config::camera_settings test_camera(int id) {
  config::camera_settings c;
  c.id = id;
  c.pan_deg = 0.0;
  c.tilt_deg = -30.0;
  c.field_of_view_deg = 35.0;
  c.pan_limits = {-90.0, 90.0};
  c.tilt_limits = {-60.0, 0.0};
  c.field_of_view_limits = {10.0, 60.0};
  c.imaging.width_px = 320;
  c.imaging.height_px = 240;
  return c;
}

/// A box the camera of test_camera() scores about 1 for (centred, half the frame high).
inline cv::Rect2d centred_box() {
  return {150.0, 60.0, 20.0, 120.0};
}

/// A box it scores lower for: off-centre and small (the pose that centres it is far from
/// the middle of the camera's ranges).
inline cv::Rect2d poor_box() {
  return {280.0, 30.0, 6.0, 40.0};
}

/// A scenario with `ids` cameras, ticks of 1/10 s and eq. (1) spreads wide enough that
/// relevance varies smoothly over the test boxes.
inline config::scenario test_scenario(const std::vector<int>& ids) {
  config::scenario s;
  s.run.tick = config::seconds{0.1};
  for (int id : ids) s.cameras.push_back(test_camera(id));
  s.controller.relevance_sigma_fov_deg = 20.0;
  s.controller.relevance_sigma_pan_deg = 30.0;
  s.controller.relevance_sigma_tilt_deg = 20.0;
  s.controller.bidding_timeout = config::seconds{10.0};
  return s;
}

/// The task every test observes: pedestrian "A" with 2 cameras.
inline protocol::task_description test_task(std::uint16_t min = 2, std::uint16_t max = 2) {
  protocol::task_description t;
  t.task = 7;
  t.target.values.assign(256, 0.0f);
  t.target.values[3] = 1.0f;
  t.min_cameras = min;
  t.max_cameras = max;
  return t;
}

class protocol_harness {
 public:
  using sight = std::function<std::optional<cv::Rect2d>(int camera, task_id task, std::int64_t)>;
  using dropper = std::function<bool(int from, int to, const protocol::group_message&)>;

  explicit protocol_harness(config::scenario s, std::int64_t delay_ticks = 3)
      : scenario_(std::move(s)), delay_(delay_ticks) {
    for (const auto& c : scenario_.cameras) {
      nodes_.emplace(c.id, camera_controller(node_identity::from(c), scenario_));
      poses_[c.id] = node_identity::from(c).home;
    }
  }

  /// Where cameras see targets; by default nowhere.
  sight sees = [](int, task_id, std::int64_t) { return std::nullopt; };
  /// Which messages are lost; by default none.
  dropper drop = [](int, int, const protocol::group_message&) { return false; };
  /// Which messages arrive twice (a tick apart); by default none.
  dropper duplicate = [](int, int, const protocol::group_message&) { return false; };

  /// The operator asks `camera` to observe `task`'s target, seen at `box`, at tick `at`.
  void operator_query_at(std::int64_t at, int camera, protocol::task_description task,
                         cv::Rect2d box = centred_box()) {
    queries_[at].emplace_back(camera, operator_query{std::move(task), box});
  }

  /// Camera `id` stops (a crash): it neither runs nor receives from now on.
  void crash(int id) { down_.insert(id); }
  /// Whether camera `id` crashed.
  bool down(int id) const { return down_.count(id) != 0; }
  /// The ids of every camera, ascending.
  std::vector<int> ids() const {
    std::vector<int> out;
    for (const auto& [id, n] : nodes_) out.push_back(id);
    return out;
  }

  /// Runs ticks [now, until).
  void run_until(std::int64_t until) {
    for (; now_ < until; ++now_) step();
  }

  camera_controller& node(int id) { return nodes_.at(id); }
  /// The last pose camera `id` was commanded to, if any.
  std::optional<vision::ptz_state> last_command(int id) const {
    auto it = commands_.find(id);
    if (it == commands_.end()) return std::nullopt;
    return it->second;
  }
  std::int64_t now() const { return now_; }

  /// Events logged so far, as "kind camera fields" lines, for searching.
  const std::vector<std::pair<int, controller_event>>& events() const { return events_; }
  /// How many events of `kind` camera `camera` (0: any) logged.
  std::size_t count(const std::string& kind, int camera = 0) const {
    std::size_t n = 0;
    for (const auto& [c, e] : events_)
      if (e.kind == kind && (camera == 0 || c == camera)) ++n;
    return n;
  }
  /// Leaders of `task` now, among live cameras.
  std::set<int> leaders(task_id task) {
    std::set<int> out;
    for (auto& [id, n] : nodes_)
      if (down_.count(id) == 0 && n.task() == task && n.role() == group_role::leader)
        out.insert(id);
    return out;
  }
  /// Messages of `kind` sent so far.
  std::size_t sent(const std::string& kind) const {
    auto it = sent_.find(kind);
    return it == sent_.end() ? 0 : it->second;
  }

 private:
  void step() {
    for (auto& [id, node] : nodes_) {
      if (down_.count(id) != 0) continue;
      controller_input in;
      in.tick = now_;
      in.pose = poses_[id];
      for (const auto& l : looks_[id]) {
        auto box = sees(id, l.task, now_);
        in.looks.push_back(
            {l.task, box.has_value(), box.value_or(cv::Rect2d{}), box ? 0.8 : 0.0, std::nullopt});
      }
      if (auto q = queries_.find(now_); q != queries_.end())
        for (const auto& [camera, query] : q->second)
          if (camera == id) in.queries.push_back(query);
      auto due = inbox_.find({now_, id});
      if (due != inbox_.end()) {
        in.messages = std::move(due->second);
        inbox_.erase(due);
      }
      auto out = node.step(in);
      for (auto& e : out.events) events_.emplace_back(id, std::move(e));
      looks_[id] = std::move(out.looks);
      if (out.command) commands_[id] = poses_[id] = *out.command;  // an ideal head
      for (const auto& m : out.messages) deliver(id, m);
    }
  }

  void deliver(int from, const outgoing_message& m) {
    const auto kind = std::string(protocol::kind_of(m.message));
    ++sent_[kind];
    auto decoded = protocol::decode(kind, protocol::encode(m.message));
    if (!decoded) throw std::logic_error("a message did not survive its encoding: " + kind);
    for (const auto& [id, node] : nodes_) {
      if (id == from || (m.destination != protocol::broadcast && m.destination != id)) continue;
      if (down_.count(id) != 0 || drop(from, id, *decoded)) continue;
      inbox_[{now_ + delay_, id}].push_back(received_message{from, *decoded});
      if (duplicate(from, id, *decoded))
        inbox_[{now_ + delay_ + 1, id}].push_back(received_message{from, *decoded});
    }
  }

  config::scenario scenario_;
  std::int64_t delay_;
  std::int64_t now_ = 0;
  std::map<int, camera_controller> nodes_;
  std::map<int, vision::ptz_state> poses_;
  std::map<int, vision::ptz_state> commands_;
  std::map<int, std::vector<look_request>> looks_;
  std::map<std::pair<std::int64_t, int>, std::vector<received_message>> inbox_;
  std::map<std::int64_t, std::vector<std::pair<int, operator_query>>> queries_;
  std::set<int> down_;
  std::vector<std::pair<int, controller_event>> events_;
  std::map<std::string, std::size_t> sent_;
};

}  // namespace argus::controller::testing

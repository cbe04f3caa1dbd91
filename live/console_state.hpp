#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "config/scenario.hpp"
#include "events/event.hpp"
#include "nlohmann/json.hpp"
#include "opencv2/core.hpp"
#include "world/snapshot.hpp"

namespace argus::live {

/// One event of the log as the console reads it (actors::sim_event without its ordering keys).
struct event_line {
  std::int64_t tick = 0;
  std::string source;
  std::string kind;
  /// JSON members without braces, as in events.jsonl.
  std::string fields_json;
};

/// One camera's latest frame as the console shows it: the node's own degraded image (shared,
/// never written again) and the tracker's boxes in it.
struct feed_frame {
  int camera = 0;
  std::int64_t tick = 0;
  /// Counts the frames published for this camera: a client sends a frame once.
  std::uint64_t sequence = 0;
  cv::Mat image;
  std::vector<cv::Rect2d> boxes;
  /// The frame as JPEG, when it came so from a worker (`image` is then decoded from it by
  /// `console_state::feed`, on the reader's thread).
  std::vector<unsigned char> jpeg;
};

/// Where a camera points now, as the console knows it.
struct camera_pose {
  /// The run's latest tick.
  std::int64_t tick = 0;
  double pan_deg = 0.0;
  double tilt_deg = 0.0;
  double field_of_view_deg = 0.0;
  bool alive = true;
};

/// What a live run shows its operator, published by the run as it goes and read by the server.
/// Display only: every publisher copies out what it already had (a snapshot pointer, the
/// node's own frame, its pose, the log's events); nothing here feeds back into the simulation,
/// and a reader holds the lock only to copy.
class console_state {
 public:
  /// For the run of `scenario` (its cameras and tick length).
  explicit console_state(const config::scenario& scenario);

  /// The world's latest snapshot (phase network of each tick); the tasked targets' trails grow.
  void publish_snapshot(std::shared_ptr<const world::snapshot> frame);

  /// Camera `camera`'s pose after its turn at `tick`, and the frame it sensed then (empty when
  /// it looked at nothing) with the tracker's boxes.
  void publish_camera(int camera, std::int64_t tick, double pan_deg, double tilt_deg,
                      double field_of_view_deg, const cv::Mat& image,
                      std::vector<cv::Rect2d> boxes);

  /// The same for a camera on a worker (`argus serve --workers`): its frame as JPEG (empty when
  /// it looked at nothing). It is decoded only when the page asks for it.
  void publish_camera_jpeg(int camera, std::int64_t tick, double pan_deg, double tilt_deg,
                           double field_of_view_deg, std::vector<unsigned char> jpeg,
                           std::vector<cv::Rect2d> boxes);

  /// Counts network messages: `sent` put on links, `received` delivered to nodes.
  void add_traffic(std::uint64_t sent, std::uint64_t received) noexcept {
    sent_.fetch_add(sent, std::memory_order_relaxed);
    received_.fetch_add(received, std::memory_order_relaxed);
  }

  /// One tick's events, in log order (from the recorder): groups, node states, tasks, faults.
  void record_events(std::span<const event_line> events);

  /// Adds `line` to the page's log (e.g. a command the run refused when it came to it).
  void note(std::string line);

  /// The run has ended (the page says so).
  void finished() { finished_.store(true); }

  /// Everything the page draws, as one JSON object (see docs/serve.md).
  nlohmann::json state_json() const;

  /// Camera `camera`'s latest frame, or nothing when it has not sensed yet or is unknown.
  std::optional<feed_frame> feed(int camera) const;

  /// A page asked for camera `camera`'s feed (at `now`).
  void watch(int camera,
             std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now());

  /// The cameras whose feed a page asked for within `feed_watch_window` before `now`, in
  /// order: on workers, only these cameras' frames cross to the console.
  std::vector<int> watched(
      std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now()) const;

  /// How long a camera stays watched after a page last asked for its feed. The page asks for
  /// the next frame as soon as it has shown one, about 15 times a second.
  static constexpr std::chrono::seconds feed_watch_window{2};

  /// Camera `camera`'s pose now, or nothing for an unknown camera.
  std::optional<camera_pose> pose(int camera) const;

  /// The world's latest snapshot (null before the first).
  std::shared_ptr<const world::snapshot> snapshot() const {
    std::lock_guard<std::mutex> guard(mutex_);
    return snapshot_;
  }

 private:
  struct camera_entry {
    double x_m = 0.0;
    double y_m = 0.0;
    double pan_deg = 0.0;
    double tilt_deg = 0.0;
    double field_of_view_deg = 0.0;
    bool alive = true;
    std::string state = "idle";
    std::string tracking;
    feed_frame frame;
  };
  struct group_entry {
    int leader = 0;
    std::set<int> members;
  };
  struct task_entry {
    int camera = 0;
    int pedestrian = -1;
    std::int64_t issued_tick = 0;
    std::string status = "issued";
    std::deque<std::array<double, 2>> trail;
  };

  // A camera's pose (pan, tilt, field of view) and, when it sensed one, its frame: `image`, or
  // `jpeg` to be decoded when asked for.
  void put_camera(int camera, std::int64_t tick, std::array<double, 3> pose, cv::Mat image,
                  std::vector<unsigned char> jpeg, std::vector<cv::Rect2d> boxes);
  void apply(const event_line& ev);
  // What each kind changes in the tables; the others change nothing.
  void take(const events::node_state& e, const event_line& ev);
  void take(const events::tracking& e, const event_line& ev);
  void take(const events::task_issued& e, const event_line& ev);
  void take(const events::task_target& e, const event_line& ev);
  void take(const events::task_refused& e, const event_line& ev);
  void take(const events::task_cancelled& e, const event_line& ev);
  void take(const events::task_created& e, const event_line& ev);
  void take(const events::joined& e, const event_line& ev);
  void take(const events::left_task& e, const event_line& ev);
  void take(const events::leader_changed& e, const event_line& ev);
  void take(const events::fault_event& e, const event_line& ev);
  void take(const events::node_recovered& e, const event_line& ev);
  template <class Other>
  void take(const Other&, const event_line&) {}

  double tick_seconds_ = 1.0 / 15.0;
  std::int64_t end_tick_ = 0;
  mutable std::mutex mutex_;
  std::shared_ptr<const world::snapshot> snapshot_;
  std::map<int, camera_entry> cameras_;
  std::map<int, group_entry> groups_;
  std::map<int, task_entry> tasks_;
  std::map<int, std::chrono::steady_clock::time_point> watched_;
  std::deque<std::string> recent_;  // the latest notable events, for the page's log
  std::int64_t tick_ = 0;
  // (wall seconds, tick, sent, received) as the readers saw them: the speed ratio and message
  // rates over the last seconds. Wall time is read here, on the display side, never in the run.
  struct sample {
    double wall_s = 0.0;
    std::int64_t tick = 0;
    std::uint64_t sent = 0;
    std::uint64_t received = 0;
  };
  mutable std::deque<sample> samples_;
  std::atomic<std::uint64_t> sent_{0};
  std::atomic<std::uint64_t> received_{0};
  std::atomic<bool> finished_{false};
};

}  // namespace argus::live

#pragma once

// What the camera nodes' runtime, the operator, the network, the fault injector, the scenario
// script, the world and the video recorder log (docs/events.md), and a strategy's own events.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "events/members.hpp"

namespace argus::events {

// --- the camera node (source camera/<id>) -----------------------------------------------------

struct node_up {
  static constexpr std::string_view name = "node_up";
  int camera = 0;
  std::string type;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("type", type);
  }
};

struct render_failed {
  static constexpr std::string_view name = "render_failed";
  int camera = 0;
  int error_code = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("error_code", error_code);
  }
};

struct strategy_failed {
  static constexpr std::string_view name = "strategy_failed";
  int camera = 0;
  json_text error;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("error", error);
  }
};

struct task_target {
  static constexpr std::string_view name = "task_target";
  int camera = 0;
  std::uint32_t task = 0;
  int pedestrian = 0;
  std::string by;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("pedestrian", pedestrian), f("by", by);
  }
};

struct task_refused {
  static constexpr std::string_view name = "task_refused";
  int camera = 0;
  std::uint32_t task = 0;
  int pedestrian = 0;
  std::string reason;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("task", task), f("pedestrian", pedestrian), f("reason", reason);
  }
};

// --- the network (source camera/<id>) ---------------------------------------------------------

/// neighbour_up or neighbour_lost (`up`).
struct neighbour_change {
  static constexpr std::string_view name = "neighbour_up";
  bool up = true;
  int camera = 0;
  int neighbour = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("neighbour", neighbour);
  }
};

struct bad_message {
  static constexpr std::string_view name = "bad_message";
  int camera = 0, origin = 0;
  std::string message;
  std::uint64_t bytes = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("origin", origin), f("message", message), f("bytes", bytes);
  }
};

struct net_received {
  static constexpr std::string_view name = "net_received";
  int camera = 0, origin = 0;
  std::string message;
  int hops = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("origin", origin), f("message", message), f("hops", hops);
  }
};

struct net_sent {
  static constexpr std::string_view name = "net_sent";
  int camera = 0, destination = 0;
  std::string message;
  std::uint64_t id = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("destination", destination), f("message", message), f("id", id);
  }
};

struct peer_failed {
  static constexpr std::string_view name = "peer_failed";
  int camera = 0, peer = 0;
  std::string request;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("peer", peer), f("request", request);
  }
};

// --- faults and the operator's script (sources faults, script) --------------------------------

struct fault_event {
  static constexpr std::string_view name = "fault";
  std::string fault;
  int camera = 0;
  std::optional<int> peer;
  bool random = false;
  bool applied = false;
  /// Whether it took its camera down (an applied crash or crash_and_recover, or the loss of
  /// the worker that hosted it under `--on-worker-loss crash-nodes`).
  bool takes_camera_down() const {
    return applied && (fault == "crash" || fault == "crash_and_recover" || fault == "worker_lost");
  }
  template <class F>
  void members(F&& f) {
    f("fault", fault), f("camera", camera), f("peer", peer), f("random", random),
        f("applied", applied);
  }
};

struct node_recovered {
  static constexpr std::string_view name = "node_recovered";
  int camera = 0;
  bool applied = false;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("applied", applied);
  }
};

/// The operator issues a task: at a pedestrian, a pixel or the first to enter the view.
struct task_issued {
  static constexpr std::string_view name = "task_issued";
  std::uint32_t task = 0;
  std::string by;
  std::optional<int> pedestrian;
  std::optional<std::vector<double>> pixel;
  int camera = 0;
  unsigned cameras_wanted = 1;
  template <class F>
  void members(F&& f) {
    f("task", task), f("by", by), f("pedestrian", pedestrian), f("pixel", pixel),
        f("camera", camera), f("cameras_wanted", cameras_wanted);
  }
};

struct task_cancelled {
  static constexpr std::string_view name = "task_cancelled";
  std::uint32_t task = 0;
  int camera = 0;
  template <class F>
  void members(F&& f) {
    f("task", task), f("camera", camera);
  }
};

// --- the world (sources world, world/partition/<i>) -------------------------------------------

/// pedestrian_entered or pedestrian_left (`entered`), at a portal.
struct pedestrian_moved {
  static constexpr std::string_view name = "pedestrian_entered";
  bool entered = true;
  int pedestrian = 0;
  int at = 0;
  template <class F>
  void members(F&& f) {
    f("pedestrian", pedestrian), f("at", at);
  }
};

struct goal_completed {
  static constexpr std::string_view name = "goal_completed";
  int pedestrian = 0;
  std::string goal;
  template <class F>
  void members(F&& f) {
    f("pedestrian", pedestrian), f("goal", goal);
  }
};

struct world_partitions_missing {
  static constexpr std::string_view name = "world_partitions_missing";
  std::uint64_t reported = 0, partitions = 0;
  template <class F>
  void members(F&& f) {
    f("reported", reported), f("partitions", partitions);
  }
};

struct world_partition_adopted {
  static constexpr std::string_view name = "world_partition_adopted";
  std::uint64_t partition = 0;
  std::string worker;
  std::uint64_t replayed_ticks = 0;
  template <class F>
  void members(F&& f) {
    f("partition", partition), f("worker", worker), f("replayed_ticks", replayed_ticks);
  }
};

struct world_out_of_step {
  static constexpr std::string_view name = "world_out_of_step";
  std::uint64_t partition = 0;
  std::int64_t snapshot_tick = -1;
  template <class F>
  void members(F&& f) {
    f("partition", partition), f("snapshot_tick", snapshot_tick);
  }
};

// --- the runtime (sources video, and whoever died) --------------------------------------------

struct participant_down {
  static constexpr std::string_view name = "participant_down";
  bool expected = false;
  template <class F>
  void members(F&& f) {
    f("expected", expected);
  }
};

struct video_render_failed {
  static constexpr std::string_view name = "video_render_failed";
  int camera = 0;
  int error_code = 0;
  template <class F>
  void members(F&& f) {
    f("camera", camera), f("error_code", error_code);
  }
};

struct video_out_of_step {
  static constexpr std::string_view name = "video_out_of_step";
  std::int64_t tick = 0;
  template <class F>
  void members(F&& f) {
    f("tick", tick);
  }
};

/// A kind outside this vocabulary: a plug-in's or a Python strategy's own, with its members as
/// JSON text (without braces).
struct custom {
  std::string kind;
  std::string fields_json;
};

}  // namespace argus::events

#pragma once

// What a coordinator and its workers say to each other (docs/distributed.md). Every type has
// a CAF inspector and a type ID (actors/type_ids.hpp), so the middleman carries them.

#include <cstdint>
#include <string>
#include <vector>

#include "actors/video_tiles.hpp"
#include "actors/wire_live.hpp"
#include "actors/wire_log.hpp"
#include "caf/actor.hpp"
#include "eval/records.hpp"
#include "vision/ptz_camera.hpp"

namespace argus::actors {

/// A link a worker hosts: its index in the scenario's topology and its two cameras.
struct link_placement {
  std::uint64_t index = 0;
  int a = 0;
  int b = 0;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, link_placement& x) {
  return f(x.index, x.a, x.b);
}

/// What a worker needs to host its part of a run: the effective scenario (config::to_yaml),
/// the files it names (a worker may be on a machine without them), and the links it spawns.
struct worker_setup {
  std::string scenario_yaml;
  /// The station layout file's text.
  std::string layout_text;
  /// The emulated sensor's model file's text; empty for none.
  std::string sensor_model_text;
  /// Whether frames record everyone visible (`--mot`).
  bool with_visible = false;
  /// Whether the cameras leave their poses for the coordinator's video (`--video`).
  bool with_poses = false;
  /// The video's tiles this worker renders for its cameras (`--video`); off for none.
  video_tile_settings video;
  /// Whether the worker hands its cameras' log over with every gather (`worker_gather::log`)
  /// rather than all at the end: a run that survives a lost worker keeps its frames up to the
  /// loss.
  bool stream_log = false;
  /// Whether it steps crowd partitions (`placement.crowd: workers`): then it loads the station
  /// with the distance fields its walkers descend.
  bool steps_crowd = false;
  std::vector<link_placement> links;
  /// An actor that lives as long as the coordinator's run: when it goes (the run ended, the
  /// coordinator died or its connection broke), the worker ends what it hosted.
  caf::actor coordinator;
  /// Whether the run is live (`argus serve`): its cameras then read the operator's orders that
  /// come with the world's snapshot (`operator_orders_atom`), and it hands what the console shows
  /// of them over with every gather (`worker_gather::display`).
  bool live = false;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, worker_setup& x) {
  return f(x.scenario_yaml, x.layout_text, x.sensor_model_text, x.with_visible, x.with_poses,
           x.video, x.stream_log, x.steps_crowd, x.links, x.coordinator, x.live);
}

/// One of a camera's links, as the camera node is attached to it (attached_link).
struct neighbour_link {
  int neighbour = 0;
  std::uint64_t participant = 0;
  caf::actor handle;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, neighbour_link& x) {
  return f(x.neighbour, x.participant, x.handle);
}

/// A camera node a worker spawns, with its links (wherever they run).
struct camera_placement {
  int camera = 0;
  std::vector<neighbour_link> links;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, camera_placement& x) {
  return f(x.camera, x.links);
}

/// A pose a worker's camera left on its board (camera_pose_board): camera `camera`, in its turn
/// of clock tick `tick`, moved to `pose`.
struct pose_record {
  int camera = 0;
  std::int64_t tick = -1;
  vision::ptz_state pose;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, pose_record& x) {
  return f(x.camera, x.tick, x.pose);
}

/// A worker's answer to `gather_atom`: the picks its cameras made since it was last asked, by
/// task; in a run with `--video`, each of its cameras' latest pose; with
/// `worker_setup::stream_log`, what its cameras recorded since it was last asked; in a live run,
/// what the console shows of its cameras.
struct worker_gather {
  std::vector<eval::task_origin> picks;
  std::vector<pose_record> poses;
  eval::observation_log::contents log;
  live_display display;
};

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, worker_gather& x) {
  return f(x.picks, x.poses, x.log, x.display);
}

}  // namespace argus::actors

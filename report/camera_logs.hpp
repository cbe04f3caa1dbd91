#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace argus::report {

/// A run's CSV file that does not say what it must: the message names the file and the line
/// ("poses.csv:12: column pan: expected a number, got 'x'").
class camera_log_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A camera's pose from one world tick on (a row of poses.csv).
struct camera_pose {
  std::int64_t world_tick = 0;
  double pan_deg = 0.0;
  double tilt_deg = 0.0;
  double field_of_view_deg = 0.0;
  /// "idle", "computing_relevance", "performing_task" or "down" (its frames stopped).
  std::string state;
};

/// poses.csv (`tick,t,camera,pan,tilt,fov,state`: a row whenever a camera's pose or state
/// changes), to ask where a camera pointed at any tick.
class pose_history {
 public:
  /// Reads `file`; throws camera_log_error naming the file and line of the first bad row, or
  /// the file when it is missing or lacks a column.
  static pose_history read(const std::filesystem::path& file);

  /// Parses the text of a poses.csv; `name` is what errors call it.
  static pose_history parse(std::string_view text, const std::string& name);

  /// The pose camera `camera` had at world tick `world_tick`: its last row at or before it;
  /// nullptr when it has none yet.
  const camera_pose* at(int camera, std::int64_t world_tick) const;

  /// Camera `camera`'s rows in tick order (empty when it has none).
  const std::vector<camera_pose>& rows_of(int camera) const;

  /// The cameras that have rows, ascending.
  std::vector<int> cameras() const;

 private:
  std::map<int, std::vector<camera_pose>> by_camera_;  // each in tick order
};

/// A tracker's box in a camera's frame for a task (a row of tracks.csv).
struct track_box {
  int task = -1;
  /// Whether the tracker found anything; the box is meaningless when not.
  bool found = false;
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double height = 0.0;
  /// Whether the box holds the task's target (ground truth, the evaluation's label).
  bool observed = false;
};

/// tracks.csv (`tick,t,camera,task,role,found,x,y,w,h,score,truth,iou,observed`: one row per
/// camera, tick and task it performs), to ask what a camera's tracker reported at a tick.
class track_history {
 public:
  /// Reads `file`; throws camera_log_error as pose_history::read does.
  static track_history read(const std::filesystem::path& file);

  /// Parses the text of a tracks.csv; `name` is what errors call it.
  static track_history parse(std::string_view text, const std::string& name);

  /// The boxes camera `camera` reported at world tick `world_tick` (empty when none).
  std::vector<track_box> at(int camera, std::int64_t world_tick) const;

  /// The first world tick in [from, to] at which camera `camera` reported on task `task`, or -1.
  std::int64_t first_report(int camera, int task, std::int64_t from, std::int64_t to) const;

 private:
  std::map<std::pair<int, std::int64_t>, std::vector<track_box>> by_camera_tick_;
};

}  // namespace argus::report

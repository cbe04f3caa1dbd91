#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>

#include "config/scenario.hpp"
#include "eval/metrics.hpp"
#include "eval/observation_log.hpp"

namespace argus::eval {

/// `tracks.csv`: one row per camera, tick and task it performs
/// (tick,t,camera,task,role,found,x,y,w,h,score,truth,iou,observed).
void write_tracks(const std::filesystem::path& path, const observation_log::contents& log,
                  double tick_s);

/// `targets.csv`: one row per tick and task while its target is followed
/// (tick,t,task,pedestrian,x,y,present,reachable,observed_by).
void write_targets(const std::filesystem::path& path, const evaluation& result, double tick_s);

/// `poses.csv`: a row whenever a camera's pose or state changes, and `down` when its frames
/// stop (tick,t,camera,pan,tilt,fov,state).
void write_poses(const std::filesystem::path& path, const observation_log::contents& log,
                 double tick_s);

/// The metrics table printed at the end of a run.
void print_metrics_table(std::ostream& out, const evaluation& result);

}  // namespace argus::eval

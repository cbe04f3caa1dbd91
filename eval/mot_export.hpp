#pragma once

#include <filesystem>

#include "config/scenario.hpp"
#include "eval/observation_log.hpp"

namespace argus::eval {

/// The benchmark and split names of the export (TrackEval's --BENCHMARK and --SPLIT_TO_EVAL).
inline constexpr const char* mot_benchmark = "ARGUS";
inline constexpr const char* mot_split = "all";

/// The MOTChallenge sequence name of a camera ("cam07").
std::string mot_sequence(int camera);

/// Writes the run in MOTChallenge format under `dir` (DIR/mot), laid out as TrackEval reads it
/// (docs/metrics.md, "MOTChallenge export"):
///   gt/mot_challenge/ARGUS-all/camNN/gt/gt.txt and seqinfo.ini: every visible pedestrian,
///     `frame,id,left,top,width,height,1,1,visibility` (frame = tick + 1);
///   gt/mot_challenge/seqmaps/ARGUS-all.txt: the sequences;
///   trackers/mot_challenge/ARGUS-all/argus/data/camNN.txt: the camera's track boxes,
///     `frame,id,left,top,width,height,score,-1,-1,-1` (id = task + 1).
/// Needs frames recorded with everyone visible (observation_log::with_visible).
void write_mot(const std::filesystem::path& dir, const config::scenario& scenario,
               const observation_log::contents& log, std::int64_t ticks);

}  // namespace argus::eval

#pragma once

#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "config/scenario.hpp"
#include "report/camera_logs.hpp"
#include "report/key_frames.hpp"

namespace argus::world {
class station;
}  // namespace argus::world

namespace argus::report {

/// Moves each non-failed frame of a task's event to the first world tick, at most
/// `window_ticks` after it, at which its camera's tracker reported on the task (tracks.csv),
/// when it did not at the frame's own tick: a camera that creates a task takes its first look
/// on its next turn, and the picture of a task's start should show that look. Frames whose
/// camera reported nothing within the window stay where they are.
void settle_on_first_report(std::vector<key_event>& events, const track_history& tracks,
                            std::int64_t window_ticks);

/// Colours of the tracker's box on a key frame (BGR): pure green when the box holds the task's
/// target (tracks.csv's `observed`), pure red when it does not. Pure, so that a test can find
/// the box among the rendered pixels.
inline const cv::Scalar observed_box_colour(0, 255, 0);
inline const cv::Scalar unobserved_box_colour(0, 0, 255);

/// Renders every frame of `events` as its camera saw it, in event order then frame order:
///
/// - the station and the crowd at the frame's world tick, rebuilt by stepping the scenario's
///   crowd (world::crowd, which the run's partitions reproduce bit for bit) once from tick 0 to
///   the last tick wanted, rendering each tick's frames on the way;
/// - from the camera's pose at that tick (poses.csv; the scenario's default pose before its
///   first row), at its own resolution;
/// - degraded by the camera's imaging model as the run degrades its frames (colour response,
///   noise, dropout, JPEG, interlacing with the second field half a tick later). The noise is
///   drawn from a seed of the run, the camera and the tick: the run does not record its noise
///   generator's state frame by frame, so the noise pixels are like the run's, not the same;
/// - with the tracker's boxes of that camera and tick (tracks.csv) in observed_box_colour or
///   unobserved_box_colour, each labelled "task N" ("task N lost" when it found nothing), and
///   the camera's id in the top-left corner;
/// - a failed camera's last frame in grey, crossed and marked "FAILED".
///
/// A frame of a camera the scenario lacks is a dark tile saying so. Throws std::runtime_error
/// when no renderer can be made (no EGL device), naming why.
std::vector<std::vector<cv::Mat>> render_key_frames(
    const config::scenario& scenario, const std::shared_ptr<const world::station>& station,
    const std::vector<key_event>& events, const pose_history& poses, const track_history& tracks);

}  // namespace argus::report

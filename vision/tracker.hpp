#pragma once

// Colour-indexing tracker (Section III-B) and the child FSM of the camera controller,
// Track / Wait / Search (Fig. 10, inset).

#include <functional>
#include <optional>

#include "config/scenario.hpp"
#include "opencv2/core.hpp"
#include "vision/color_histogram.hpp"
#include "vision/fixate_zoom.hpp"
#include "vision/frame_size.hpp"
#include "vision/multiscale_localizer.hpp"
#include "vision/ptz_camera.hpp"
#include "vision/signature_halves.hpp"
#include "vision/signature_update.hpp"
#include "vision/tracking_state.hpp"

namespace argus::vision {

/// What the tracker saw in one frame.
struct track_observation {
  /// False when the track is lost in this frame.
  bool found = false;
  /// The target's box in pixels (the last known one when not found).
  cv::Rect box;
  /// Histogram intersection of the box with the target (Fig. 9, step 5).
  double score = 0.0;
};

/// Settings of the tracker.
struct tracker_settings {
  /// Acceptance threshold on the normalised histogram intersection.
  double rho = 0.4;
  /// The search window is the last box grown by this many box sizes on every side.
  double search_margin = 1.0;
  /// Look in the whole frame when the target is not in the search window.
  bool search_whole_frame = true;
  /// The localiser's kernel sizes: by default around the last box's size (the paper's
  /// frame-height scales until a box is known, or with scale_rule::paper).
  scale_settings scales;
  /// Follow the camera's own motion: the last box is carried along with the camera's pan,
  /// tilt and zoom between frames (follow_camera(), which the node's sensor calls: it knows
  /// the poses), and of the kernel sizes scoring near the best the one nearest that box's
  /// size is taken, not the largest. False: the paper's tracker, which knows no poses.
  bool ego_motion = false;
  /// Re-take the model the tracker looks for from the camera's own pixels (signature_update).
  /// Off: the paper's tracker, which looks for the signature it was given all along.
  bool update_signature = false;
  /// When and how it re-takes the model.
  signature_update_settings update;
  /// In a whole-frame search, the region found is taken only if its score exceeds the best
  /// other region's (a look-alike) by this much; 0: the paper's, the first region above rho.
  double reacquire_margin = 0.0;
  /// A lost track is looked for only in a window around its last box, grown by one more box
  /// size each frame, for this many frames before the whole frame is searched; 0: the paper's,
  /// the whole frame at once.
  int local_search_frames = 0;
  /// A box whose colours match the ring around it (surround_match()) more than this is taken
  /// for background, not her, and not accepted; 1: the paper's, no such test.
  double max_surround_match = 1.0;
  /// The first this many frames of a track started on the operator's pick (start()), found in
  /// the search window without a loss, are spared the figure-ground test: she was picked there,
  /// and at a few pixels wide her box matches its ring through blur and compression alone.
  int surround_grace_frames = 0;
  /// The same track is also spared the test while its box is less than this many pixels tall:
  /// until the camera has zoomed on her, her ring is a few pixels of floor, not a test.
  int surround_grace_height_px = 0;
  /// A live track's box in its search window is taken for background only once it has matched
  /// its surround in this many frames running; before that it is still hers. 1: at the first
  /// such frame. Her own box matches its ring for a frame now and then without being
  /// background: in a queue of people dressed like her, or near the camera, where she is wider
  /// than the kernel's 1 : 3 box and the ring holds her own sides; a rejection then sends the
  /// tracker to the whole frame, where a look-alike passes. Patience alone serves Fig. 19 worse
  /// (bench/RESULTS.md, "Her own box taken for background").
  int surround_patience_frames = 1;
  /// 0: the figure-ground test matches the box against its whole ring. K (1-4): against each
  /// of the ring's four sides on its own (surround_side_matches()), and the box is taken for
  /// background when K or more sides match it more than max_surround_match (or every side
  /// inside the image, where fewer than K are: a box in a corner has two). Her neighbours in a
  /// queue, or her own arms near the camera, fill two sides; the floor at her feet does not.
  /// By sides Fig. 19 is served worse (bench/RESULTS.md, "The figure-ground test by sides").
  int surround_sides = 0;
  /// A live track is kept on a box in its search window that scores above this; a find
  /// anywhere else (the whole frame, a lost track) must still score above rho. Unset: rho, the
  /// paper's one threshold.
  std::optional<double> track_rho;
  /// With the target's halves given (tracker's constructor), a find is taken only if its box's
  /// halves match them (halves_match()) above this, in every search: the tracker then weighs up
  /// to checked_candidates regions above rho and takes the first that passes. Unset: the
  /// paper's tracker, one histogram of the whole box.
  std::optional<double> halves_rho;
};

/// Follows one target frame to frame: backprojects its histogram in a window around the last
/// position (ratio histogram of that window, T scaled to the last box's area), re-localises
/// it with the multiscale localiser (Fig. 9) at kernel sizes around the last box's
/// (kernel_scales()) and accepts it by histogram intersection; if it is not there, looks in
/// the whole frame; otherwise reports the track lost.
class tracker {
 public:
  /// A tracker for the target with signature `target` and, for settings.halves_rho, her
  /// `halves` (each normalised).
  explicit tracker(color_histogram target, tracker_settings settings = {},
                   std::optional<signature_halves> halves = std::nullopt);

  /// Starts (or restarts) the track at `box` in the current frame.
  void start(const cv::Rect& box);

  /// Whether a box the tracker found is her (ground truth standing in for a perfect
  /// re-identification; sensing.identity).
  using find_check = std::function<bool(const cv::Rect&)>;

  /// How many regions above rho a search with a check weighs (the localiser's candidates).
  static constexpr int checked_candidates = 8;

  /// Processes one BGR frame. With `check`, the tracker weighs up to checked_candidates regions
  /// above rho, in the localiser's order, and takes the first the check accepts: a perfect
  /// re-identification among what its colour indexing finds. None accepted is no find.
  track_observation update(const cv::Mat& bgr, const find_check& check = {});

  /// The camera moved from `from` to `to` since the last frame: the last box is carried to
  /// where the same ray is now (reproject_box()), so the next search starts there.
  void follow_camera(const ptz_state& from, const ptz_state& to, const frame_size& frame);

  /// Whether the last update lost the target (or no track was started).
  bool lost() const noexcept { return lost_; }

  /// The last known box, if any.
  const std::optional<cv::Rect>& box() const noexcept { return box_; }

  /// The target's signature.
  const color_histogram& target() const noexcept { return target_; }

  /// What the tracker looks for: the signature, or with update_signature the signature blended
  /// with her pixels as this camera last saw her on a confirmed track.
  const color_histogram& model() const noexcept { return model_; }

  /// The halves it tests finds against (empty without halves), as model() is to target().
  const std::optional<signature_halves>& model_halves() const noexcept { return halves_; }

  /// How many times it has re-taken its model (update_signature).
  int model_updates() const noexcept { return model_updates_; }

 private:
  std::optional<track_observation> find_in(const cv::Mat& bin_indices, const cv::Rect& window,
                                           const localizer_settings& localizing, bool figure_ground,
                                           const find_check& check);
  std::optional<track_observation> find_in_frame(const cv::Mat& bin_indices,
                                                 const localizer_settings& localizing,
                                                 const find_check& check);

  void update_model(const cv::Mat& bin_indices, const cv::Rect& box);
  /// The figure-ground test (max_surround_match): `box` matches its ring too well to be her.
  bool taken_for_background(const cv::Mat& bin_indices, const cv::Rect& box) const;

  color_histogram target_;
  std::optional<signature_halves> halves_target_;
  // What finds' halves are tested against: her halves as given, or with update_signature
  // blended with hers as this camera last took its model.
  std::optional<signature_halves> halves_;
  color_histogram model_;
  tracker_settings settings_;
  multiscale_localizer localizer_;
  std::optional<cv::Rect> box_;
  // Her box as the camera's motion carried it, unrounded, and kept through finds of the same
  // kernel size (estimate_after_find): its size is the next search's expected size. Set
  // whenever box_ is. A zoom of a few per cent a frame grows a box a few pixels tall by less
  // than a pixel, which rounding to box_, or snapping to the size found, would undo every frame.
  std::optional<cv::Rect2d> carried_;
  bool lost_ = true;
  // Frames in a row the track has been lost.
  int lost_frames_ = 0;
  // Frames in a row found in the search window (a whole-frame find does not count).
  int confirmed_ = 0;
  // Whether every frame since start() found her in the window (confirmed_ counts them).
  bool on_pick_ = false;
  // Frames running whose window find matched its surround and was kept all the same
  // (surround_patience_frames).
  int surround_strikes_ = 0;
  // The box height the model was last taken at (0: a signature from a message, not yet found).
  int model_height_ = 0;
  int model_updates_ = 0;
};

/// Settings of the child FSM beyond Table 2's timeouts.
struct tracking_fsm_settings {
  /// In Track, fixate and zoom on the target (Fig. 7(b), (c)); false holds the camera still.
  bool follow_in_track = true;
  /// Fixate and zoom gains and set point.
  fixate_zoom_settings fixate;
  /// In Wait, the field of view widens at this rate (degrees per second).
  double wait_zoom_out_deg_per_s = 2.0;
  /// In Search, successive tilt rows overlap by this fraction of the field of view.
  double search_row_overlap = 0.2;
};

/// What the child FSM commands for the next frame.
struct tracking_command {
  tracking_state state = tracking_state::track;
  ptz_state pose;
};

/// The child FSM of Fig. 10 (inset):
///
///   track --lost--> wait --wait_timeout--> search --search_timeout--> failed
///     ^              |                        |
///     +----found-----+--------found-----------+
///
/// Track: fixate and zoom on the target. Wait: hold pan and tilt and widen the zoom gradually
/// to reacquire. Search: sweep pan across its limits (a full turn when pan wraps) at the widest
/// field of view, stepping tilt by a row at the end of each sweep and sweeping back. Every
/// command moves within the head's limits and slew rates (slew_towards()), so a static camera
/// holds its pose in every state. Timeouts are Table 2's (controller_settings). Time comes
/// from `dt` only.
class tracking_fsm {
 public:
  /// A child FSM for a head with `limits` (ranges, slew rates) with `controller`'s timeouts.
  tracking_fsm(const ptz_limits& limits, const config::controller_settings& controller,
               tracking_fsm_settings settings = {});

  /// One frame: the tracker's observation, the camera's pose, the frame size and the time
  /// since the last step.
  tracking_command step(const track_observation& observation, const ptz_state& current,
                        const frame_size& frame, config::seconds dt);

  /// The current state.
  tracking_state state() const noexcept { return state_; }

  /// Back to Track (e.g. when a new task starts).
  void reset();

 private:
  ptz_state search_step(const ptz_state& current, config::seconds dt);
  void next_search_row(const ptz_state& current);

  ptz_limits limits_;
  config::controller_settings controller_;
  tracking_fsm_settings settings_;
  tracking_state state_ = tracking_state::track;
  config::seconds in_state_{0.0};
  double sweep_direction_ = 1.0;
  double search_tilt_deg_ = 0.0;
  // When pan wraps: the pan of the last Search step and how far this sweep has turned.
  double search_pan_deg_ = 0.0;
  double swept_deg_ = 0.0;
};

}  // namespace argus::vision

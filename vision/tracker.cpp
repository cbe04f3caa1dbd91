#include "vision/tracker.hpp"

#include <algorithm>
#include <cmath>

#include "vision/backprojection.hpp"
#include "vision/ego_motion.hpp"
#include "vision/kernel_scales.hpp"
#include "vision/surround_match.hpp"

namespace argus::vision {

namespace {

/// `box` widened by `margin` of its width on either side and of its height above and below.
cv::Rect window_around(const cv::Rect& box, double margin) {
  const int dx = static_cast<int>(std::lround(margin * box.width));
  const int dy = static_cast<int>(std::lround(margin * box.height));
  return {box.x - dx, box.y - dy, box.width + 2 * dx, box.height + 2 * dy};
}

/// Her box after a find: `found`, unless it is the kernel size `estimate` rounds to, in which
/// case the estimate's size about `found`'s centre. The localiser's sizes are 6 px apart in
/// height; a box that snapped to the found size every frame would lose each frame's zoom (a few
/// per cent) to that rounding, and stay a size too small while the camera zooms in on her.
cv::Rect2d estimate_after_find(const cv::Rect2d& estimate, const cv::Rect& found) {
  const int l = static_cast<int>(std::lround(kernel_size_for(estimate.size())));
  if (found.size() != kernel_domain({0, 0}, l).size()) return cv::Rect2d(found);
  const double cx = found.x + found.width / 2.0;
  const double cy = found.y + found.height / 2.0;
  return {cx - estimate.width / 2.0, cy - estimate.height / 2.0, estimate.width, estimate.height};
}

}  // namespace

tracker::tracker(color_histogram target, tracker_settings settings,
                 std::optional<signature_halves> halves)
    : target_(std::move(target)),
      halves_target_(std::move(halves)),
      halves_(halves_target_),
      model_(target_),
      settings_(settings) {
  // nop
}

void tracker::start(const cv::Rect& box) {
  box_ = box;
  carried_ = cv::Rect2d(box);
  lost_ = false;
  lost_frames_ = 0;
  // The signature was taken from this box: the model is her at this size already.
  confirmed_ = 0;
  on_pick_ = true;
  surround_strikes_ = 0;
  model_height_ = box.height;
}

bool tracker::taken_for_background(const cv::Mat& bin_indices, const cv::Rect& box) const {
  if (settings_.max_surround_match >= 1.0) return false;
  if (settings_.surround_sides == 0)
    return surround_match(bin_indices, box, model_.bins()) > settings_.max_surround_match;
  return background_by_sides(surround_side_matches(bin_indices, box, model_.bins()),
                             settings_.max_surround_match, settings_.surround_sides);
}

void tracker::update_model(const cv::Mat& bin_indices, const cv::Rect& box) {
  if (!settings_.update_signature) return;
  // A signature from another camera is taken as hers at the size it was first found at: a
  // whole-frame find is as likely a look-alike, whom a model re-taken at once would cement.
  if (model_height_ == 0) model_height_ = box.height;
  if (!model_due(confirmed_, box.height, model_height_, settings_.update)) return;
  model_ = blended_model(target_, bin_indices, box, settings_.update);
  if (halves_target_)
    halves_ = blended_halves(*halves_target_, halves_in(bin_indices, box, target_.bins()),
                             settings_.update.own_weight);
  model_height_ = box.height;
  ++model_updates_;
}

std::optional<track_observation> tracker::find_in(const cv::Mat& bin_indices,
                                                  const cv::Rect& window,
                                                  const localizer_settings& localizing,
                                                  bool figure_ground, const find_check& check) {
  if (window.empty()) return std::nullopt;
  const cv::Mat indices = bin_indices(window);
  auto image =
      color_histogram::of_bin_indices(indices, {0, 0, window.width, window.height}, model_.bins());
  std::optional<double> area;
  if (box_) area = static_cast<double>(box_->area());
  auto b = backproject(indices, ratio_histogram(model_, image, area));
  localizer_ = multiscale_localizer(localizing);
  auto found = localizer_.localize(b, histogram_scorer(indices, model_));
  if (found.empty()) return std::nullopt;
  const auto background = [&](const cv::Rect& box) {
    return figure_ground && taken_for_background(bin_indices, box);
  };
  if (check) {
    for (const auto& region : found) {
      const cv::Rect box = region.box() + window.tl();
      if (!background(box) && check(box)) return track_observation{true, box, region.score};
    }
    return std::nullopt;
  }
  // A region only a little better than a look-alike elsewhere is as likely to be the other.
  if (found.size() > 1) {
    double other = 0.0;
    for (std::size_t i = 1; i < found.size(); ++i) other = std::max(other, found[i].score);
    if (found.front().score < other + settings_.reacquire_margin) return std::nullopt;
  }
  const cv::Rect box = found.front().box() + window.tl();
  if (background(box)) return std::nullopt;
  return track_observation{true, box, found.front().score};
}

std::optional<track_observation> tracker::find_in_frame(const cv::Mat& bin_indices,
                                                        const localizer_settings& localizing,
                                                        const find_check& check) {
  auto whole = localizing;
  if (settings_.reacquire_margin > 0.0 && !check) whole.max_regions = 2;
  return find_in(bin_indices, cv::Rect(0, 0, bin_indices.cols, bin_indices.rows), whole, true,
                 check);
}

void tracker::follow_camera(const ptz_state& from, const ptz_state& to, const frame_size& frame) {
  if (!box_ || from == to) return;
  const auto moved = reproject_box(*carried_, from, to, frame);
  if (!moved) return;
  carried_ = *moved;
  const cv::Rect rounded(static_cast<int>(std::lround(moved->x)),
                         static_cast<int>(std::lround(moved->y)),
                         std::max(1, static_cast<int>(std::lround(moved->width))),
                         std::max(1, static_cast<int>(std::lround(moved->height))));
  box_ = rounded;
}

track_observation tracker::update(const cv::Mat& bgr, const find_check& given_check) {
  const auto indices = bin_index_image(bgr, target_.bins());
  find_check check = given_check;
  if (halves_ && settings_.halves_rho) {
    check = [&](const cv::Rect& box) {
      return halves_match(*halves_, halves_in(indices, box, target_.bins())) >
                 *settings_.halves_rho &&
             (!given_check || given_check(box));
    };
  }
  const cv::Rect frame(0, 0, bgr.cols, bgr.rows);
  std::optional<cv::Size2d> size;
  if (carried_) size = carried_->size();
  const auto localizing = localizer_settings_for(settings_.scales, size, bgr.rows, settings_.rho,
                                                 check ? checked_candidates : 1);
  std::optional<track_observation> seen;
  bool in_window = false;
  // A lost track still within local_search_frames is looked for only around its last box.
  const bool searching_locally = box_ && lost_frames_ < settings_.local_search_frames;
  if (box_ && !lost_) {
    auto tracking = localizing;
    if (settings_.ego_motion) tracking.expected_scale = kernel_size_for(*size);
    tracking.rho = settings_.track_rho.value_or(settings_.rho);
    const bool in_grace = on_pick_ && (confirmed_ < settings_.surround_grace_frames ||
                                       box_->height < settings_.surround_grace_height_px);
    const bool patient = surround_strikes_ + 1 < settings_.surround_patience_frames;
    seen = find_in(indices, window_around(*box_, settings_.search_margin) & frame, tracking,
                   !in_grace && !patient, check);
    in_window = seen.has_value();
    // Kept without the test, the box counts a strike if it fails it; one that passes ends them.
    if (seen && !in_grace)
      surround_strikes_ =
          patient && taken_for_background(indices, seen->box) ? surround_strikes_ + 1 : 0;
  } else if (searching_locally) {
    // Where she was lost she is likely to reappear (from behind someone, or as the camera
    // stops); the whole frame holds look-alikes. The window grows by a box size a frame.
    const double margin = settings_.search_margin * (2 + lost_frames_);
    seen = find_in(indices, window_around(*box_, margin) & frame, localizing, true, check);
  }
  if (!seen && !searching_locally && (settings_.search_whole_frame || !box_)) {
    seen = find_in_frame(indices, localizing, check);
  }
  if (!seen) {
    on_pick_ = false;
    surround_strikes_ = 0;
    lost_ = true;
    ++lost_frames_;
    confirmed_ = 0;
    return {false, box_.value_or(cv::Rect{}), 0.0};
  }
  if (!in_window) surround_strikes_ = 0;
  lost_ = false;
  lost_frames_ = 0;
  box_ = seen->box;
  // Without ego motion nothing carries the box between frames: the paper's tracker, as it was.
  // A first find (no box before it) has no estimate to keep.
  carried_ = settings_.ego_motion && carried_ ? estimate_after_find(*carried_, seen->box)
                                              : cv::Rect2d(seen->box);
  confirmed_ = in_window ? confirmed_ + 1 : 0;
  on_pick_ = on_pick_ && in_window;
  update_model(indices, seen->box);
  return *seen;
}

tracking_fsm::tracking_fsm(const ptz_limits& limits, const config::controller_settings& controller,
                           tracking_fsm_settings settings)
    : limits_(limits), controller_(controller), settings_(settings) {
  // nop
}

void tracking_fsm::reset() {
  state_ = tracking_state::track;
  in_state_ = config::seconds{0.0};
}

void tracking_fsm::next_search_row(const ptz_state& current) {
  sweep_direction_ = -sweep_direction_;
  const double row = current.field_of_view_deg * (1.0 - settings_.search_row_overlap);
  search_tilt_deg_ += row;
  if (search_tilt_deg_ > limits_.tilt.max_deg)
    search_tilt_deg_ = limits_.tilt.min_deg + current.field_of_view_deg / 2.0;
}

ptz_state tracking_fsm::search_step(const ptz_state& current, config::seconds dt) {
  // Sweep pan to one limit, step tilt by a row, sweep back (Fig. 10 inset, Search).
  ptz_state goal = current;
  goal.field_of_view_deg = limits_.field_of_view.max_deg;
  if (limits_.pan_wraps()) {
    // No limit to reach: a sweep is one full turn, made by always aiming less than half a turn
    // ahead (slew_towards takes the shorter way).
    swept_deg_ += std::abs(std::remainder(current.pan_deg - search_pan_deg_, 360.0));
    search_pan_deg_ = current.pan_deg;
    if (swept_deg_ >= 360.0) {
      next_search_row(current);
      swept_deg_ = 0.0;
    }
    goal.pan_deg = current.pan_deg + sweep_direction_ * 90.0;
  } else {
    const auto& pan = limits_.pan;
    const double end = sweep_direction_ > 0 ? pan.max_deg : pan.min_deg;
    if (std::abs(current.pan_deg - end) < 1e-6) next_search_row(current);
    goal.pan_deg = sweep_direction_ > 0 ? pan.max_deg : pan.min_deg;
  }
  goal.tilt_deg = std::clamp(search_tilt_deg_, limits_.tilt.min_deg, limits_.tilt.max_deg);
  return slew_towards(current, goal, limits_, dt);
}

tracking_command tracking_fsm::step(const track_observation& observation, const ptz_state& current,
                                    const frame_size& frame, config::seconds dt) {
  auto enter = [this](tracking_state next) {
    state_ = next;
    in_state_ = config::seconds{0.0};
  };
  if (state_ == tracking_state::failed) return {state_, current};
  if (observation.found) {
    if (state_ != tracking_state::track) enter(tracking_state::track);
  } else if (state_ == tracking_state::track) {
    enter(tracking_state::wait);
  } else {
    in_state_ += dt;
    if (state_ == tracking_state::wait && in_state_ >= controller_.wait_timeout) {
      enter(tracking_state::search);
      sweep_direction_ = 1.0;
      search_tilt_deg_ = current.tilt_deg;
      search_pan_deg_ = current.pan_deg;
      swept_deg_ = 0.0;
    } else if (state_ == tracking_state::search && in_state_ >= controller_.search_timeout) {
      enter(tracking_state::failed);
      return {state_, current};
    }
  }
  switch (state_) {
    case tracking_state::track:
      if (!settings_.follow_in_track) return {state_, current};
      return {state_,
              fixate_zoom_step(current, observation.box, frame, limits_, dt, settings_.fixate)};
    case tracking_state::wait: {
      // Widen the zoom gradually to reacquire; pan and tilt hold.
      ptz_state goal = current;
      goal.field_of_view_deg += settings_.wait_zoom_out_deg_per_s * dt.count();
      return {state_, slew_towards(current, goal, limits_, dt)};
    }
    case tracking_state::search:
      return {state_, search_step(current, dt)};
    case tracking_state::failed:
      break;
  }
  return {state_, current};
}

}  // namespace argus::vision

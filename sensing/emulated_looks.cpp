#include "sensing/emulated_looks.hpp"

#include "sensing/signature.hpp"
#include "world/snapshot.hpp"

namespace argus::sensing {

emulated_looks::emulated_looks(vision::sensor_model model, std::uint64_t run_seed, int camera_id,
                               double min_match)
    : sensor_(vision::emulated_sensor::for_camera(std::move(model), run_seed, camera_id)),
      min_match_(min_match) {
  // nop
}

std::vector<controller::look_result> emulated_looks::look(
    const world::snapshot& frame, const world::station& where, const vision::camera_view& view,
    const std::vector<controller::look_request>& looks, const truth_check& is_target) {
  std::map<controller::task_id, int> kept;
  std::vector<controller::look_result> out;
  const auto seen = vision::visible_pedestrians(frame, where, view);
  for (const auto& l : looks) {
    const auto wanted = to_histogram(l.target);
    int best = -1;
    double best_match = min_match_;
    const auto followed = following_.find(l.task);
    for (const auto& v : seen) {
      const auto* who = frame.find(v.id);
      const double match = vision::normalized_intersection(wanted, signature_of(who->look));
      if (match < min_match_) continue;
      if (is_target) {
        // A perfect re-identification among the look-alikes: hers, if she is one of them.
        if (!is_target(l.task, v.id)) continue;
        best = v.id;
        break;
      }
      if (followed != following_.end() && followed->second == v.id) {
        best = v.id;
        break;
      }
      if (match > best_match) {
        best_match = match;
        best = v.id;
      }
    }
    controller::look_result r{l.task, false, {}, 0.0, std::nullopt};
    if (best >= 0) {
      const auto observed = sensor_.look_for(best, frame, seen, view);
      if (observed.found && (!is_target || is_target(l.task, observed.detection.pedestrian_id))) {
        r.found = true;
        r.box = cv::Rect2d(observed.detection.box);
        r.score = observed.detection.confidence;
        kept[l.task] = observed.detection.pedestrian_id;
      }
    }
    if (!r.found && followed != following_.end()) kept[l.task] = followed->second;
    out.push_back(r);
  }
  following_ = std::move(kept);
  return out;
}

const vision::color_histogram& emulated_looks::signature_of(const world::appearance& look) {
  for (const auto& [known, signature] : signatures_)
    if (known == look) return signature;
  return signatures_.emplace_back(look, vision::appearance_signature(look)).second;
}

protocol::signature emulated_looks::acquire(controller::task_id task, const world::snapshot& frame,
                                            int id) {
  following_[task] = id;
  return to_signature(signature_of(frame.find(id)->look));
}

}  // namespace argus::sensing

#include "vision/sensor_calibration.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "fmt/format.h"
#include "vision/backprojection.hpp"
#include "vision/multiscale_localizer.hpp"
#include "world/snapshot.hpp"

namespace argus::vision {
namespace {

// Largest similarity of pedestrian `index` of `seen` to another one not fully hidden.
double largest_similarity(std::span<const pedestrian_view> seen, std::size_t index,
                          const std::vector<color_histogram>& signatures, double max_occlusion) {
  double best = 0.0;
  for (std::size_t j = 0; j < seen.size(); ++j) {
    if (j == index || seen[j].occlusion > max_occlusion) continue;
    best = std::max(best, normalized_intersection(signatures[index], signatures[j]));
  }
  return best;
}

// Logistic regression by Newton's method: P(y = 1 | x) = logistic(w . x), with a small ridge
// term so that separable or tiny samples give finite weights.
Eigen::VectorXd fit_logistic(const Eigen::MatrixXd& x, const Eigen::VectorXd& y,
                             Eigen::VectorXd w) {
  const double ridge = 1e-3;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::VectorXd z = x * w;
    const Eigen::VectorXd p = z.unaryExpr([](double v) { return 1.0 / (1.0 + std::exp(-v)); });
    const Eigen::VectorXd gradient = x.transpose() * (p - y) + ridge * w;
    const Eigen::VectorXd weights = p.cwiseProduct((1.0 - p.array()).matrix());
    Eigen::MatrixXd hessian = x.transpose() * weights.asDiagonal() * x;
    hessian.diagonal().array() += ridge;
    const Eigen::VectorXd step = hessian.ldlt().solve(gradient);
    w -= step;
    if (step.norm() < 1e-8) break;
  }
  return w;
}

}  // namespace

std::vector<calibration_trial> pixel_trials(const cv::Mat& frame_bgr, const world::snapshot& frame,
                                            const world::station& where, const camera_view& view,
                                            double rho, const scale_settings& scales) {
  std::vector<calibration_trial> trials;
  const auto seen = visible_pedestrians(frame, where, view);
  std::vector<color_histogram> signatures;
  for (const auto& v : seen) signatures.push_back(appearance_signature(frame.find(v.id)->look));
  const cv::Rect2d image(0.0, 0.0, frame_bgr.cols, frame_bgr.rows);
  const sensor_model limits;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    calibration_trial trial;
    trial.occlusion = seen[i].occlusion;
    trial.height_px = seen[i].box.height;
    trial.similarity = largest_similarity(seen, i, signatures, limits.max_occlusion);
    const double area = (seen[i].box & image).area();
    const auto bp = backproject_target(frame_bgr, signatures[i], std::max(area, 1.0));
    multiscale_localizer localizer(
        localizer_settings_for(scales, seen[i].box.size(), frame_bgr.rows, rho, 1));
    const auto found =
        localizer.localize(bp.backprojection, histogram_scorer(bp.bin_indices, signatures[i]));
    trial.missed = true;
    if (!found.empty()) {
      const auto& box = found.front();
      const cv::Point2d centre(box.x + box.width / 2.0, box.y + box.height / 2.0);
      trial.score = box.score;
      if (seen[i].box.contains(centre)) {
        trial.missed = false;
        const cv::Point2d truth(seen[i].box.x + seen[i].box.width / 2.0,
                                seen[i].box.y + seen[i].box.height / 2.0);
        trial.centre_error = cv::norm(centre - truth) / seen[i].box.height;
      } else {
        // Nearest first: the one in front is the one the box shows.
        for (std::size_t j = 0; j < seen.size() && trial.missed; ++j)
          if (j != i && seen[j].box.contains(centre)) {
            trial.missed = false;
            trial.confused = true;
          }
      }
      if (trial.missed) trial.score = 0.0;
    }
    trials.push_back(trial);
  }
  return trials;
}

std::vector<calibration_trial> emulated_trials(emulated_sensor& sensor,
                                               const world::snapshot& frame,
                                               const world::station& where,
                                               const camera_view& view) {
  std::vector<calibration_trial> trials;
  const auto seen = visible_pedestrians(frame, where, view);
  std::vector<color_histogram> signatures;
  for (const auto& v : seen) signatures.push_back(appearance_signature(frame.find(v.id)->look));
  for (std::size_t i = 0; i < seen.size(); ++i) {
    calibration_trial trial;
    trial.occlusion = seen[i].occlusion;
    trial.height_px = seen[i].box.height;
    trial.similarity = largest_similarity(seen, i, signatures, sensor.model().max_occlusion);
    const auto looked = sensor.look_for(seen[i].id, frame, seen, view);
    trial.missed = !looked.found;
    trial.confused = looked.confused;
    trial.score = looked.found ? looked.detection.confidence : 0.0;
    trials.push_back(trial);
  }
  return trials;
}

sensor_model fit_sensor_model(std::span<const calibration_trial> trials, sensor_model start) {
  sensor_model model = start;
  std::vector<const calibration_trial*> usable;
  for (const auto& t : trials)
    if (t.occlusion <= start.max_occlusion && t.height_px >= start.min_height_px)
      usable.push_back(&t);
  model.samples = static_cast<int>(usable.size());
  if (usable.empty()) return model;

  Eigen::MatrixXd x(usable.size(), 3);
  Eigen::VectorXd y(usable.size());
  for (std::size_t k = 0; k < usable.size(); ++k) {
    x.row(k) << 1.0, usable[k]->occlusion, std::log(std::max(usable[k]->height_px, 1.0));
    y(k) = usable[k]->missed ? 1.0 : 0.0;
  }
  const Eigen::VectorXd miss = fit_logistic(x, y, Eigen::VectorXd::Zero(3));
  model.miss_bias = miss(0);
  model.miss_per_occlusion = miss(1);
  model.miss_per_log_height = miss(2);

  std::vector<const calibration_trial*> found;
  for (const auto* t : usable)
    if (!t->missed) found.push_back(t);
  if (!found.empty()) {
    Eigen::MatrixXd xs(found.size(), 2);
    Eigen::VectorXd ys(found.size());
    double error2 = 0.0, confidence = 0.0;
    int hits = 0;
    for (std::size_t k = 0; k < found.size(); ++k) {
      xs.row(k) << 1.0, found[k]->similarity;
      ys(k) = found[k]->confused ? 1.0 : 0.0;
      if (!found[k]->confused) {
        error2 += found[k]->centre_error * found[k]->centre_error;
        confidence += found[k]->score / std::max(1.0 - found[k]->occlusion, 0.1);
        ++hits;
      }
    }
    const Eigen::VectorXd confusion = fit_logistic(xs, ys, Eigen::VectorXd::Zero(2));
    model.confusion_bias = confusion(0);
    model.confusion_per_similarity = confusion(1);
    if (hits > 0) {
      // Centre error is 2-D; the model perturbs each axis with box_sigma.
      model.box_sigma = std::sqrt(error2 / hits / 2.0);
      model.confidence_unoccluded = std::clamp(confidence / hits, 0.0, 1.0);
    }
  }
  return model;
}

trial_rates rates_of(std::span<const calibration_trial> trials) {
  const sensor_model limits;
  trial_rates rates;
  int usable = 0, missed = 0, found = 0, confused = 0;
  for (const auto& t : trials) {
    if (t.occlusion > limits.max_occlusion || t.height_px < limits.min_height_px) continue;
    ++usable;
    if (t.missed) {
      ++missed;
    } else {
      ++found;
      confused += t.confused ? 1 : 0;
    }
  }
  rates.trials = usable;
  rates.miss = usable > 0 ? static_cast<double>(missed) / usable : 0.0;
  rates.confusion = found > 0 ? static_cast<double>(confused) / found : 0.0;
  return rates;
}

std::string describe(std::span<const calibration_trial> trials) {
  std::string text;
  auto table = [&](const char* title, auto key, std::span<const double> edges, bool confusion) {
    text += fmt::format("{}\n", title);
    for (std::size_t b = 0; b + 1 < edges.size(); ++b) {
      int n = 0, events = 0;
      for (const auto& t : trials) {
        const double v = key(t);
        if (v < edges[b] || v >= edges[b + 1]) continue;
        if (confusion && t.missed) continue;
        ++n;
        events += (confusion ? t.confused : t.missed) ? 1 : 0;
      }
      text += fmt::format("  [{:7.2f}, {:7.2f}): {:5d} trials, rate {:.3f}\n", edges[b],
                          edges[b + 1], n, n > 0 ? static_cast<double>(events) / n : 0.0);
    }
  };
  const double occlusion[] = {0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 1.01};
  const double height[] = {0.0, 10.0, 20.0, 40.0, 80.0, 160.0, 1e9};
  const double similarity[] = {0.0, 0.3, 0.5, 0.7, 0.8, 0.9, 1.01};
  table(
      "miss rate by occlusion", [](const auto& t) { return t.occlusion; }, occlusion, false);
  table(
      "miss rate by height (px)", [](const auto& t) { return t.height_px; }, height, false);
  table(
      "confusion rate by similarity", [](const auto& t) { return t.similarity; }, similarity, true);
  return text;
}

}  // namespace argus::vision

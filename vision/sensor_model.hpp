#pragma once

// Parameters of the emulated sensor's error model, fitted by `argus vision calibrate` and
// shipped as YAML (scenarios/sensor_model.yaml).

#include <string>

namespace argus::vision {

/// The error model of the emulated sensor (emulated_sensor.hpp). With
/// logistic(z) = 1 / (1 + exp(-z)), for a pedestrian in view with a fraction `occlusion` of
/// its box hidden (by the frame edge or nearer pedestrians) and an image height of h pixels:
///
///   P(miss)      = logistic(miss_bias + miss_per_occlusion * occlusion
///                           + miss_per_log_height * ln(h))
///   P(confusion) = logistic(confusion_bias + confusion_per_similarity * s)   (if not missed)
///
/// where s is the largest normalised histogram intersection of its signature with that of
/// another pedestrian in view; a confusion reports that other pedestrian's box instead.
/// Defaults are plausible values; fitted ones replace them.
struct sensor_model {
  /// Above this hidden fraction a pedestrian is never detected (fully occluded).
  double max_occlusion = 0.9;
  /// Below this image height (pixels) a pedestrian is never detected.
  double min_height_px = 6.0;
  /// Logistic miss model coefficients (see above).
  double miss_bias = 1.0;
  /// Growth of the miss log-odds per unit hidden fraction.
  double miss_per_occlusion = 4.0;
  /// Change of the miss log-odds per unit ln(height in pixels) (negative: big is easy).
  double miss_per_log_height = -1.0;
  /// Logistic confusion model coefficients (see above).
  double confusion_bias = -6.0;
  /// Growth of the confusion log-odds per unit similarity.
  double confusion_per_similarity = 5.0;
  /// Standard deviation of box centre and size errors, as a fraction of the box height.
  double box_sigma = 0.05;
  /// Confidence (acceptance score) of an unoccluded detection; it falls as 1 - occlusion.
  double confidence_unoccluded = 0.8;
  /// How many pixel-pipeline trials the fit used (0 for the defaults).
  int samples = 0;

  friend bool operator==(const sensor_model&, const sensor_model&) = default;
};

/// The model as a YAML mapping, one key per field (names as above).
std::string to_yaml(const sensor_model& model);

/// Parses to_yaml()'s output; keys left out keep their defaults. Throws std::runtime_error
/// naming the key on an unknown key or a value that is not a number.
sensor_model sensor_model_from_yaml(const std::string& text);

/// Reads a sensor model file (see sensor_model_from_yaml). Throws std::runtime_error.
sensor_model load_sensor_model(const std::string& path);

}  // namespace argus::vision

#include "vision/sensor_model.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace argus::vision {
namespace {

// Every field with its key, so that writing and reading cannot drift apart.
template <class Model, class Visitor>
void for_each_field(Model& model, Visitor&& visit) {
  visit("max_occlusion", model.max_occlusion);
  visit("min_height_px", model.min_height_px);
  visit("miss_bias", model.miss_bias);
  visit("miss_per_occlusion", model.miss_per_occlusion);
  visit("miss_per_log_height", model.miss_per_log_height);
  visit("confusion_bias", model.confusion_bias);
  visit("confusion_per_similarity", model.confusion_per_similarity);
  visit("box_sigma", model.box_sigma);
  visit("confidence_unoccluded", model.confidence_unoccluded);
  visit("samples", model.samples);
}

}  // namespace

std::string to_yaml(const sensor_model& model) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  for_each_field(model, [&](const char* key, const auto& value) {
    out << YAML::Key << key << YAML::Value << value;
  });
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

sensor_model sensor_model_from_yaml(const std::string& text) {
  sensor_model model;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(std::string("sensor model: ") + e.what());
  }
  if (root.IsNull()) return model;
  if (!root.IsMap()) throw std::runtime_error("sensor model: expected a mapping");
  for (const auto& pair : root) {
    const auto key = pair.first.as<std::string>();
    bool known = false;
    for_each_field(model, [&](const char* name, auto& value) {
      if (key != name) return;
      known = true;
      try {
        value = pair.second.as<std::remove_reference_t<decltype(value)>>();
      } catch (const YAML::Exception&) {
        throw std::runtime_error("sensor model: " + key + ": expected a number");
      }
    });
    if (!known) throw std::runtime_error("sensor model: unknown key '" + key + "'");
  }
  return model;
}

sensor_model load_sensor_model(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("sensor model: cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  return sensor_model_from_yaml(text.str());
}

}  // namespace argus::vision

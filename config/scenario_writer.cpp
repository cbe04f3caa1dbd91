#include "config/scenario_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "config/duration.hpp"
#include "config/enum_names.hpp"

namespace argus::config {

namespace {

/// A double-quoted YAML string: names and paths may hold characters (':', '#', leading
/// '*', "null", ...) that a plain scalar would misread.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const unsigned char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20 || c == 0x7f) {
          out += fmt::format("\\x{:02x}", c);
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
  return out;
}

// Whether `text` is a bare identifier, written as it is.
bool plain_name(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

/// fmt's default is the shortest decimal that reads back to the same double.
std::string number(double value) {
  return fmt::format("{}", value);
}

std::string duration(seconds value) {
  return format_duration(value);
}

std::string boolean(bool value) {
  return value ? "true" : "false";
}

std::string range(const degree_range& limits) {
  return fmt::format("[{}, {}]", number(limits.min_deg), number(limits.max_deg));
}

/// Builds the text line by line with an indentation level.
class yaml_text {
 public:
  void line(int indent, std::string_view text) {
    out_.append(static_cast<std::size_t>(indent) * 2, ' ');
    out_ += text;
    out_ += '\n';
  }

  void entry(int indent, std::string_view key, std::string_view value) {
    line(indent, fmt::format("{}: {}", key, value));
  }

  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

void write_color_response(yaml_text& out, const imaging_model& imaging) {
  const auto& values = imaging.response;
  // `off` is the readable form; the mapping with `enabled: false` keeps parameters that
  // were set but switched off, so the round trip stays exact.
  if (!imaging.color_response_enabled && values == color_response{}) {
    out.entry(3, "color_response", "off");
    return;
  }
  out.line(3, "color_response:");
  out.entry(4, "enabled", boolean(imaging.color_response_enabled));
  out.entry(4, "hue_offset_deg", number(values.hue_offset_deg));
  out.entry(4, "saturation_gain", number(values.saturation_gain));
  out.entry(4, "value_gain", number(values.value_gain));
  out.entry(4, "value_offset", number(values.value_offset));
  out.entry(4, "tint", number(values.tint));
  out.entry(4, "tone", number(values.tone));
  out.entry(4, "shade", number(values.shade));
}

void write_camera(yaml_text& out, const camera_settings& camera) {
  out.line(1, fmt::format("- id: {}", camera.id));
  out.entry(2, "position",
            fmt::format("{{x_m: {}, y_m: {}}}", number(camera.position.x_m),
                        number(camera.position.y_m)));
  out.entry(2, "height_m", number(camera.height_m));
  out.entry(2, "type", yaml_name(camera.type));
  out.entry(2, "pan_deg", number(camera.pan_deg));
  out.entry(2, "tilt_deg", number(camera.tilt_deg));
  out.entry(2, "field_of_view_deg", number(camera.field_of_view_deg));
  out.entry(2, "pan_limits", range(camera.pan_limits));
  out.entry(2, "tilt_limits", range(camera.tilt_limits));
  out.entry(2, "field_of_view_limits", range(camera.field_of_view_limits));
  out.entry(2, "pan_rate_deg_per_s", number(camera.pan_rate_deg_per_s));
  out.entry(2, "tilt_rate_deg_per_s", number(camera.tilt_rate_deg_per_s));
  out.entry(2, "zoom_rate_deg_per_s", number(camera.zoom_rate_deg_per_s));
  const auto& imaging = camera.imaging;
  out.line(2, "imaging:");
  out.entry(3, "resolution", fmt::format("[{}, {}]", imaging.width_px, imaging.height_px));
  write_color_response(out, imaging);
  out.entry(3, "noise_sigma", number(imaging.noise_sigma));
  out.entry(3, "dropout",
            fmt::format("{{fraction: {}, kind: {}}}", number(imaging.dropout_fraction),
                        yaml_name(imaging.dropout)));
  out.entry(3, "jpeg_quality", fmt::format("{}", imaging.jpeg_quality));
  out.entry(3, "interlace", boolean(imaging.interlace));
}

std::string adjacency(const std::vector<std::array<int, 2>>& links) {
  std::string text = "[";
  for (const auto& link : links) {
    if (text.size() > 1) text += ", ";
    text += fmt::format("[{}, {}]", link[0], link[1]);
  }
  return text + "]";
}

std::string task(const operator_task& each) {
  auto text = fmt::format("- {{at: {}, ", duration(each.at));
  switch (each.by) {
    case task_target::pedestrian:
      text += fmt::format("pedestrian: {}, camera: {}", each.pedestrian, each.camera);
      break;
    case task_target::pixel:
      text += fmt::format("pixel: [{}, {}], camera: {}", number(each.pixel.x_px),
                          number(each.pixel.y_px), each.camera);
      break;
    case task_target::first_to_enter:
      text += fmt::format("first_to_enter: {}", each.camera);
      break;
  }
  text += fmt::format(", cameras_wanted: {}", each.cameras_wanted);
  if (each.max_cameras != 0) text += fmt::format(", max_cameras: {}", each.max_cameras);
  if (each.cancel_at) text += fmt::format(", cancel_at: {}", duration(*each.cancel_at));
  return text + "}";
}

std::string fault_line(const fault& each) {
  auto text = fmt::format("- {{at: {}, kind: {}, camera: {}", duration(each.at),
                          yaml_name(each.kind), each.camera);
  if (each.peer) text += fmt::format(", peer: {}", *each.peer);
  text += fmt::format(", length: {}, loss_probability: {}", duration(each.length),
                      number(each.loss_probability));
  if (each.kind == fault_kind::delay_spike)
    text += fmt::format(", delay: {}", duration(each.delay));
  text += "}";
  return text;
}

}  // namespace

std::string to_yaml(const scenario& s) {
  yaml_text out;
  out.line(0, "# Effective configuration: every field, defaults included.");
  out.entry(0, "name", quoted(s.name));

  out.line(0, "run:");
  out.entry(1, "seed", fmt::format("{}", s.run.seed));
  out.entry(1, "duration", duration(s.run.duration));
  out.entry(1, "tick", duration(s.run.tick));
  out.entry(1, "speed", number(s.run.speed));
  out.entry(1, "threads", fmt::format("{}", s.run.threads));
  out.entry(1, "output_dir", quoted(s.run.output_dir));

  out.line(0, "world:");
  out.entry(1, "layout", quoted(s.world.layout));
  out.entry(1, "population", fmt::format("{}", s.world.population));
  out.entry(1, "spawn_rate_per_min", number(s.world.spawn_rate_per_min));
  out.entry(1, "partitions", fmt::format("{}", s.world.partitions));
  out.entry(1, "speed",
            fmt::format("{{mean_mps: {}, sd_mps: {}, min_mps: {}, max_mps: {}}}",
                        number(s.world.speed.mean_mps), number(s.world.speed.sd_mps),
                        number(s.world.speed.min_mps), number(s.world.speed.max_mps)));
  out.entry(1, "clothing", yaml_name(s.world.clothes));
  auto box_text = [](const plan_box& b) {
    return fmt::format("min: [{}, {}], max: [{}, {}]", number(b.min_x_m), number(b.min_y_m),
                       number(b.max_x_m), number(b.max_y_m));
  };
  out.line(1, s.world.flows.empty() ? "flows: []" : "flows:");
  for (const auto& f : s.world.flows) {
    out.line(2, fmt::format("- {{name: {}, {}, count: {}, rate_per_s: {}, start: {}, exit: {}}}",
                            quoted(f.name), box_text(f.spawn), f.count, number(f.rate_per_s),
                            duration(f.start), quoted(f.exit)));
  }
  out.line(1, s.world.measurement_areas.empty() ? "measurement_areas: []" : "measurement_areas:");
  for (const auto& a : s.world.measurement_areas) {
    out.line(2, fmt::format("- {{name: {}, {}}}", quoted(a.name), box_text(a.area)));
  }

  if (s.cameras.empty()) {
    out.line(0, "cameras: []");
  } else {
    out.line(0, "cameras:");
    for (const auto& camera : s.cameras) write_camera(out, camera);
  }

  const auto& network = s.network;
  out.line(0, "network:");
  out.entry(1, "loss_probability", number(network.loss_probability));
  out.entry(1, "min_delay", duration(network.min_delay));
  out.entry(1, "max_delay", duration(network.max_delay));
  out.entry(1, "node_failure_probability", number(network.node_failure_probability));
  out.entry(1, "max_hops", fmt::format("{}", network.max_hops));
  out.entry(1, "message_timeout", duration(network.message_timeout));
  out.entry(1, "communication_range_m", number(network.communication_range_m));
  out.entry(1, "adjacency", adjacency(network.adjacency));
  out.entry(1, "duplicate_probability", number(network.duplicate_probability));
  out.entry(1, "reorder", boolean(network.reorder));
  out.entry(1, "hello_interval", duration(network.hello_interval));
  out.entry(1, "neighbour_timeout", duration(network.neighbour_timeout));
  out.entry(1, "unicast", yaml_name(network.unicast));

  const auto& controller = s.controller;
  out.line(0, "controller:");
  out.entry(1, "wait_timeout", duration(controller.wait_timeout));
  out.entry(1, "search_timeout", duration(controller.search_timeout));
  out.entry(1, "min_relevance", number(controller.min_relevance));
  out.entry(1, "heartbeat_interval", duration(controller.heartbeat_interval));
  out.entry(1, "leader_failure_timeout", duration(controller.leader_failure_timeout));
  out.entry(1, "member_failure_timeout", duration(controller.member_failure_timeout));
  out.entry(1, "auction_relevance_threshold", number(controller.auction_relevance_threshold));
  out.entry(1, "min_task_duration", duration(controller.min_task_duration));
  out.entry(1, "membership_relevance_threshold", number(controller.membership_relevance_threshold));
  out.entry(1, "merge_timeout", duration(controller.merge_timeout));
  out.entry(1, "bidding_timeout", duration(controller.bidding_timeout));
  out.entry(1, "relevance_sigma_fov_deg", number(controller.relevance_sigma_fov_deg));
  out.entry(1, "relevance_sigma_pan_deg", number(controller.relevance_sigma_pan_deg));
  out.entry(1, "relevance_sigma_tilt_deg", number(controller.relevance_sigma_tilt_deg));
  out.entry(1, "solver", yaml_name(controller.solver));
  out.entry(1, "merge", yaml_name(controller.merge));
  out.entry(1, "strategy",
            plain_name(controller.strategy) ? controller.strategy : quoted(controller.strategy));
  out.entry(1, "oracle_signature", yaml_name(controller.oracle_signature_from));
  out.entry(1, "oracle_zoom", boolean(controller.oracle_zoom));
  out.entry(1, "zoom_in_track", boolean(controller.zoom_in_track));
  out.entry(1, "auction_window", duration(controller.auction_window));
  out.entry(1, "auction_interval", duration(controller.auction_interval));
  out.entry(1, "relevance_look_time", duration(controller.relevance_look_time));
  out.entry(1, "bid_evidence_time", duration(controller.bid_evidence_time));
  out.entry(1, "bid_min_found_fraction", number(controller.bid_min_found_fraction));
  out.entry(1, "bid_min_mean_score", number(controller.bid_min_mean_score));
  out.entry(1, "track_while_bidding", boolean(controller.track_while_bidding));
  out.entry(1, "share_model", boolean(controller.share_model));
  out.entry(1, "conflict_stay_bonus", number(controller.conflict_stay_bonus));
  out.entry(1, "demotion_backoff_max", duration(controller.demotion_backoff_max));

  out.line(0, "sensing:");
  out.entry(1, "mode", yaml_name(s.sensing.mode));
  out.entry(1, "sensor_model", quoted(s.sensing.sensor_model));
  out.entry(1, "tracker_scales", yaml_name(s.sensing.scales));
  out.entry(1, "ego_motion", boolean(s.sensing.ego_motion));
  out.entry(1, "signature_update", boolean(s.sensing.signature_update));
  out.entry(1, "reacquire_margin", number(s.sensing.reacquire_margin));
  out.entry(1, "local_search_frames", fmt::format("{}", s.sensing.local_search_frames));
  out.entry(1, "max_surround_match", number(s.sensing.max_surround_match));
  out.entry(1, "surround_grace_frames", fmt::format("{}", s.sensing.surround_grace_frames));
  out.entry(1, "surround_grace_height_px", fmt::format("{}", s.sensing.surround_grace_height_px));
  out.entry(1, "surround_patience_frames", fmt::format("{}", s.sensing.surround_patience_frames));
  out.entry(1, "surround_sides", fmt::format("{}", s.sensing.surround_sides));
  out.entry(1, "track_rho", number(s.sensing.track_rho));
  out.entry(1, "halves_rho", number(s.sensing.halves_rho));
  out.entry(1, "identity", yaml_name(s.sensing.identity));
  out.entry(1, "group_geometry", yaml_name(s.sensing.geometry));
  out.entry(1, "reappearance", yaml_name(s.sensing.reappearance));

  out.line(0, s.tasks.empty() ? "tasks: []" : "tasks:");
  for (const auto& each : s.tasks) out.line(1, task(each));

  out.line(0, s.faults.empty() ? "faults: []" : "faults:");
  for (const auto& each : s.faults) out.line(1, fault_line(each));

  out.line(0, "placement:");
  out.entry(1, "policy", yaml_name(s.placement.policy));
  out.entry(1, "crowd", yaml_name(s.placement.crowd));
  out.entry(1, "video", yaml_name(s.placement.video));
  return out.take();
}

}  // namespace argus::config

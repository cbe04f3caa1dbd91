#include "config/scenario_loader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "config/mapping_reader.hpp"
#include "config/utf8_text.hpp"
#include "config/yaml_guards.hpp"
#include "config/yaml_override.hpp"
#include "config/yaml_reader.hpp"

namespace argus::config {

namespace {

// The keys each mapping allows, in schema order (the order "expected one of" lists them).
constexpr std::array<std::string_view, 10> scenario_keys{
    "name",       "run",     "world", "cameras", "network",
    "controller", "sensing", "tasks", "faults",  "placement"};
constexpr std::array<std::string_view, 3> placement_keys{"policy", "crowd", "video"};
constexpr std::array<std::string_view, 17> sensing_keys{"mode",
                                                        "sensor_model",
                                                        "tracker_scales",
                                                        "ego_motion",
                                                        "signature_update",
                                                        "reacquire_margin",
                                                        "local_search_frames",
                                                        "max_surround_match",
                                                        "surround_grace_frames",
                                                        "surround_grace_height_px",
                                                        "surround_patience_frames",
                                                        "surround_sides",
                                                        "track_rho",
                                                        "halves_rho",
                                                        "identity",
                                                        "group_geometry",
                                                        "reappearance"};
constexpr std::array<std::string_view, 6> run_keys{"seed",  "duration", "tick",
                                                   "speed", "threads",  "output_dir"};
constexpr std::array<std::string_view, 8> world_keys{
    "layout",   "population", "spawn_rate_per_min", "partitions", "speed",
    "clothing", "flows",      "measurement_areas"};
constexpr std::array<std::string_view, 4> speed_keys{"mean_mps", "sd_mps", "min_mps", "max_mps"};
constexpr std::array<std::string_view, 7> flow_keys{"name",       "min",   "max", "count",
                                                    "rate_per_s", "start", "exit"};
constexpr std::array<std::string_view, 3> area_keys{"name", "min", "max"};
constexpr std::array<std::string_view, 14> camera_keys{"id",
                                                       "position",
                                                       "height_m",
                                                       "type",
                                                       "pan_deg",
                                                       "tilt_deg",
                                                       "field_of_view_deg",
                                                       "pan_limits",
                                                       "tilt_limits",
                                                       "field_of_view_limits",
                                                       "pan_rate_deg_per_s",
                                                       "tilt_rate_deg_per_s",
                                                       "zoom_rate_deg_per_s",
                                                       "imaging"};
constexpr std::array<std::string_view, 2> position_keys{"x_m", "y_m"};
constexpr std::array<std::string_view, 6> imaging_keys{
    "resolution", "color_response", "noise_sigma", "dropout", "jpeg_quality", "interlace"};
constexpr std::array<std::string_view, 8> color_response_keys{
    "enabled", "hue_offset_deg", "saturation_gain", "value_gain", "value_offset", "tint",
    "tone",    "shade"};
constexpr std::array<std::string_view, 2> dropout_keys{"fraction", "kind"};
constexpr std::array<std::string_view, 13> network_keys{"loss_probability",
                                                        "min_delay",
                                                        "max_delay",
                                                        "node_failure_probability",
                                                        "max_hops",
                                                        "message_timeout",
                                                        "communication_range_m",
                                                        "adjacency",
                                                        "duplicate_probability",
                                                        "reorder",
                                                        "hello_interval",
                                                        "neighbour_timeout",
                                                        "unicast"};
constexpr std::array<std::string_view, 30> controller_keys{"wait_timeout",
                                                           "search_timeout",
                                                           "min_relevance",
                                                           "heartbeat_interval",
                                                           "leader_failure_timeout",
                                                           "member_failure_timeout",
                                                           "auction_relevance_threshold",
                                                           "min_task_duration",
                                                           "membership_relevance_threshold",
                                                           "merge_timeout",
                                                           "bidding_timeout",
                                                           "relevance_sigma_fov_deg",
                                                           "relevance_sigma_pan_deg",
                                                           "relevance_sigma_tilt_deg",
                                                           "solver",
                                                           "merge",
                                                           "strategy",
                                                           "oracle_signature",
                                                           "oracle_zoom",
                                                           "zoom_in_track",
                                                           "auction_window",
                                                           "auction_interval",
                                                           "relevance_look_time",
                                                           "bid_evidence_time",
                                                           "bid_min_found_fraction",
                                                           "conflict_stay_bonus",
                                                           "bid_min_mean_score",
                                                           "track_while_bidding",
                                                           "share_model",
                                                           "demotion_backoff_max"};
constexpr std::array<std::string_view, 8> task_keys{
    "at",     "pedestrian",     "pixel",       "first_to_enter",
    "camera", "cameras_wanted", "max_cameras", "cancel_at"};
constexpr std::array<std::string_view, 7> fault_keys{
    "at", "kind", "camera", "peer", "length", "loss_probability", "delay"};

const auto probability = value_bounds::closed(0.0, 1.0);
const auto non_negative = value_bounds::at_least(0.0);
const auto positive = value_bounds::above(0.0);

std::string item(const std::string& path, std::size_t index) {
  return fmt::format("{}[{}]", path, index);
}

/// Reads a whole document into a scenario; the one place that knows the schema.
class scenario_parser {
 public:
  explicit scenario_parser(yaml_reader& reader) : reader_(reader) {
    // nop
  }

  void parse(const YAML::Node& root, scenario& out) {
    mapping_reader document(reader_, root, "", scenario_keys);
    if (document.read("name", out.name) && out.name.empty()) {
      reader_.report(*document.find("name"), "name", "expected a non-empty name");
    }
    // Cameras first: the network, tasks and faults refer to their ids.
    if (const auto node = document.find("cameras")) read_cameras(*node, out.cameras);
    if (const auto node = document.find("run")) read_run(*node, out.run);
    if (const auto node = document.find("world")) read_world(*node, out.world);
    if (const auto node = document.find("network")) read_network(*node, out.network);
    if (const auto node = document.find("controller")) read_controller(*node, out.controller);
    if (const auto node = document.find("sensing")) read_sensing(*node, out.sensing);
    if (const auto node = document.find("tasks")) read_tasks(*node, out.cameras, out.tasks);
    if (const auto node = document.find("faults")) read_faults(*node, out.faults);
    if (const auto node = document.find("placement")) read_placement(*node, out.placement);
  }

 private:
  void read_run(const YAML::Node& node, run_settings& out) {
    mapping_reader run(reader_, node, "run", run_keys);
    run.read("seed", out.seed);
    run.read("duration", out.duration, positive);
    // A tick is one video frame; longer than a second would starve the controller.
    run.read("tick", out.tick, value_bounds::left_open(0.0, 1.0));
    run.read("speed", out.speed, non_negative);
    run.read("threads", out.threads, value_bounds::closed(0, 256));
    run.read("output_dir", out.output_dir);
  }

  void read_world(const YAML::Node& node, world_settings& out) {
    mapping_reader world(reader_, node, "world", world_keys);
    world.read("layout", out.layout);
    world.read("population", out.population, value_bounds::closed(0, 1'000'000));
    world.read("spawn_rate_per_min", out.spawn_rate_per_min, non_negative);
    world.read("partitions", out.partitions, value_bounds::at_least(1));
    world.read("clothing", out.clothes);
    if (const auto node = world.find("speed")) {
      mapping_reader speed(reader_, *node, "world.speed", speed_keys);
      speed.read("mean_mps", out.speed.mean_mps, value_bounds::closed(0.1, 3.0));
      speed.read("sd_mps", out.speed.sd_mps, value_bounds::closed(0.0, 1.0));
      speed.read("min_mps", out.speed.min_mps, value_bounds::closed(0.1, 3.0));
      speed.read("max_mps", out.speed.max_mps, value_bounds::closed(0.1, 3.0));
      if (out.speed.min_mps > out.speed.mean_mps || out.speed.mean_mps > out.speed.max_mps) {
        reader_.report(*node, "world.speed",
                       fmt::format("expected min_mps <= mean_mps <= max_mps, got {} <= {} <= {}",
                                   out.speed.min_mps, out.speed.mean_mps, out.speed.max_mps));
      }
    }
    if (const auto node = world.find("flows")) {
      if (reader_.expect_list(*node, "world.flows")) {
        for (std::size_t index = 0; index < node->size(); ++index) {
          const auto path = item("world.flows", index);
          mapping_reader flow(reader_, (*node)[index], path, flow_keys);
          if (!flow.is_mapping()) continue;
          flow_settings f;
          flow.read("name", f.name);
          read_box(flow, f.spawn);
          if (flow.require("count")) flow.read("count", f.count, value_bounds::closed(1, 100'000));
          flow.read("rate_per_s", f.rate_per_s, non_negative);
          flow.read("start", f.start, non_negative);
          if (flow.require("exit", "the name of a portal of the layout")) {
            flow.read("exit", f.exit);
          }
          out.flows.push_back(std::move(f));
        }
      }
    }
    if (const auto node = world.find("measurement_areas")) {
      if (reader_.expect_list(*node, "world.measurement_areas")) {
        for (std::size_t index = 0; index < node->size(); ++index) {
          const auto path = item("world.measurement_areas", index);
          mapping_reader area(reader_, (*node)[index], path, area_keys);
          if (!area.is_mapping()) continue;
          measurement_area a;
          area.read("name", a.name);
          read_box(area, a.area);
          out.measurement_areas.push_back(std::move(a));
        }
      }
    }
  }

  /// `min` and `max` corners of a box in `map`, min < max on both axes.
  void read_box(mapping_reader& map, plan_box& out) {
    const bool has_min = map.require("min");
    const bool has_max = map.require("max");
    if (!has_min || !has_max) return;
    plan_point low;
    plan_point high;
    read_position(*map.find("min"), map.field("min"), low);
    read_position(*map.find("max"), map.field("max"), high);
    if (low.x_m >= high.x_m || low.y_m >= high.y_m) {
      reader_.report(*map.find("max"), map.field("max"),
                     fmt::format("expected max > min on both axes, got min [{}, {}], max [{}, {}]",
                                 low.x_m, low.y_m, high.x_m, high.y_m));
      return;
    }
    out = {low.x_m, low.y_m, high.x_m, high.y_m};
  }

  void read_cameras(const YAML::Node& node, std::vector<camera_settings>& out) {
    if (!reader_.expect_list(node, "cameras")) return;
    for (std::size_t index = 0; index < node.size(); ++index) {
      camera_settings camera;
      read_camera(node[index], item("cameras", index), camera);
      out.push_back(std::move(camera));
    }
  }

  void read_camera(const YAML::Node& node, const std::string& path, camera_settings& out) {
    mapping_reader camera(reader_, node, path, camera_keys);
    if (camera.require("id") && camera.read("id", out.id, value_bounds::at_least(1))) {
      const auto id_node = *camera.find("id");
      const auto [earlier, inserted] = camera_ids_.emplace(out.id, id_node.Mark());
      if (!inserted) {
        reader_.report(id_node, camera.field("id"),
                       fmt::format("duplicate camera id {} (first used at line {})", out.id,
                                   earlier->second.line + 1));
      }
    }
    if (camera.require("position")) {
      read_position(*camera.find("position"), camera.field("position"), out.position);
    }
    camera.read("height_m", out.height_m, positive);
    camera.read("type", out.type);
    read_pose(camera, "pan", out.pan_deg, out.pan_limits, value_bounds::any());
    read_pose(camera, "tilt", out.tilt_deg, out.tilt_limits, value_bounds::closed(-90.0, 90.0));
    read_pose(camera, "field_of_view", out.field_of_view_deg, out.field_of_view_limits,
              value_bounds::open(0.0, 180.0));
    camera.read("pan_rate_deg_per_s", out.pan_rate_deg_per_s, non_negative);
    camera.read("tilt_rate_deg_per_s", out.tilt_rate_deg_per_s, non_negative);
    camera.read("zoom_rate_deg_per_s", out.zoom_rate_deg_per_s, non_negative);
    if (const auto imaging = camera.find("imaging")) {
      read_imaging(*imaging, camera.field("imaging"), out.imaging);
    }
  }

  void read_position(const YAML::Node& node, const std::string& path, plan_point& out) {
    if (node.IsSequence()) {
      if (node.size() != 2) {
        reader_.report(
            node, path,
            fmt::format("expected a list [x_m, y_m] of 2 numbers, got a list of {}", node.size()));
        return;
      }
      reader_.read(node[0], item(path, 0), out.x_m);
      reader_.read(node[1], item(path, 1), out.y_m);
      return;
    }
    if (!node.IsMap()) {
      reader_.report(node, path,
                     "expected a mapping {x_m: ..., y_m: ...} or a list [x_m, y_m], got " +
                         yaml_reader::describe(node));
      return;
    }
    mapping_reader position(reader_, node, path, position_keys);
    if (position.require("x_m")) position.read("x_m", out.x_m);
    if (position.require("y_m")) position.read("y_m", out.y_m);
  }

  /// Reads `NAME_limits` (each end within `allowed`, min <= max) and then `NAME_deg`, which
  /// must lie within those limits, whether given or left at its default.
  void read_pose(mapping_reader& camera, const std::string& name, double& value_deg,
                 degree_range& limits, const value_bounds& allowed) {
    const auto limits_key = name + "_limits";
    const auto value_key = name + "_deg";
    bool limits_valid = true;
    if (const auto node = camera.find(limits_key)) {
      limits_valid = read_range(*node, camera.field(limits_key), limits, allowed);
    }
    if (!limits_valid) {
      camera.read(value_key, value_deg, allowed);
      return;
    }
    const auto within = value_bounds::closed(limits.min_deg, limits.max_deg);
    const auto note = "within " + limits_key;
    camera.read(value_key, value_deg, within, note);
    camera.check_default(value_key, value_deg, within, note);
  }

  /// A [min, max] list; returns whether it is valid.
  bool read_range(const YAML::Node& node, const std::string& path, degree_range& out,
                  const value_bounds& allowed) {
    if (!node.IsSequence() || node.size() != 2) {
      const auto got = node.IsSequence() ? fmt::format("a list of {}", node.size())
                                         : yaml_reader::describe(node);
      reader_.report(node, path, "expected a list [min, max] of 2 numbers, got " + got);
      return false;
    }
    degree_range range;
    const bool min_valid = reader_.read(node[0], item(path, 0), range.min_deg, allowed);
    const bool max_valid = reader_.read(node[1], item(path, 1), range.max_deg, allowed);
    if (!min_valid || !max_valid) return false;
    if (range.min_deg > range.max_deg) {
      reader_.report(node, path,
                     fmt::format("expected [min, max] with min <= max, got [{}, {}]",
                                 node[0].Scalar(), node[1].Scalar()));
      return false;
    }
    out = range;
    return true;
  }

  // controller.strategy: a name, `plugin:PATH` or `python:MODULE:CLASS`. Whether the name is
  // registered, or the library or module loads, is known only when the run starts.
  void check_strategy(mapping_reader& controller, const std::string& value) {
    auto report = [&](std::string message) {
      reader_.report(*controller.find("strategy"), controller.field("strategy"),
                     std::move(message));
    };
    auto is_name = [](std::string_view text) {
      return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
      });
    };
    if (value.starts_with("plugin:")) {
      if (value.size() == 7)
        report("expected plugin:PATH, the path of a shared library; got no path");
      return;
    }
    if (value.starts_with("python:")) {
      const auto rest = std::string_view(value).substr(7);
      const auto colon = rest.rfind(':');
      if (colon == std::string_view::npos || !is_name(rest.substr(0, colon)) ||
          !is_name(rest.substr(colon + 1)))
        report("expected python:MODULE:CLASS (e.g. python:my_strategies:Follow), got '" + value +
               "'");
      return;
    }
    if (!is_name(value) || value.find('.') != std::string::npos)
      report(
          "expected a strategy's name (paper, no_collaboration, oracle or one a plug-in "
          "registers), plugin:PATH or python:MODULE:CLASS; got '" +
          value + "'");
  }

  void read_imaging(const YAML::Node& node, const std::string& path, imaging_model& out) {
    mapping_reader imaging(reader_, node, path, imaging_keys);
    if (const auto resolution = imaging.find("resolution")) {
      read_resolution(*resolution, imaging.field("resolution"), out);
    }
    if (const auto response = imaging.find("color_response")) {
      read_color_response(*response, imaging.field("color_response"), out);
    }
    imaging.read("noise_sigma", out.noise_sigma, non_negative);
    if (const auto dropout = imaging.find("dropout")) {
      mapping_reader reader(reader_, *dropout, imaging.field("dropout"), dropout_keys);
      reader.read("fraction", out.dropout_fraction, probability);
      reader.read("kind", out.dropout);
    }
    imaging.read("jpeg_quality", out.jpeg_quality, value_bounds::closed(0, 100));
    imaging.read("interlace", out.interlace);
  }

  void read_resolution(const YAML::Node& node, const std::string& path, imaging_model& out) {
    if (!node.IsSequence() || node.size() != 2) {
      const auto got = node.IsSequence() ? fmt::format("a list of {}", node.size())
                                         : yaml_reader::describe(node);
      reader_.report(node, path, "expected a list [width, height] of 2 integers, got " + got);
      return;
    }
    const auto pixels = value_bounds::closed(16, 8192);
    reader_.read(node[0], item(path, 0), out.width_px, pixels);
    reader_.read(node[1], item(path, 1), out.height_px, pixels);
  }

  void read_color_response(const YAML::Node& node, const std::string& path, imaging_model& out) {
    // `color_response: off` (or on) switches the model without listing its parameters.
    if (node.IsScalar()) {
      reader_.read(node, path, out.color_response_enabled);
      return;
    }
    mapping_reader response(reader_, node, path, color_response_keys);
    if (!response.is_mapping()) return;
    out.color_response_enabled = true;
    response.read("enabled", out.color_response_enabled);
    auto& values = out.response;
    response.read("hue_offset_deg", values.hue_offset_deg);
    response.read("saturation_gain", values.saturation_gain, non_negative);
    response.read("value_gain", values.value_gain, non_negative);
    response.read("value_offset", values.value_offset);
    response.read("tint", values.tint, probability);
    response.read("tone", values.tone, probability);
    response.read("shade", values.shade, probability);
  }

  void read_network(const YAML::Node& node, network_settings& out) {
    mapping_reader network(reader_, node, "network", network_keys);
    network.read("loss_probability", out.loss_probability, probability);
    const bool min_valid =
        !network.find("min_delay") || network.read("min_delay", out.min_delay, non_negative);
    if (min_valid) {
      const auto after_min = value_bounds::at_least(out.min_delay.count());
      network.read("max_delay", out.max_delay, after_min, "at least min_delay");
      network.check_default("max_delay", out.max_delay, after_min, "at least min_delay");
    } else {
      network.read("max_delay", out.max_delay, non_negative);
    }
    network.read("node_failure_probability", out.node_failure_probability, probability);
    network.read("max_hops", out.max_hops, value_bounds::at_least(1));
    network.read("message_timeout", out.message_timeout, positive);
    network.read("communication_range_m", out.communication_range_m, non_negative);
    if (const auto adjacency = network.find("adjacency")) {
      read_adjacency(*adjacency, network.field("adjacency"), out.adjacency);
    }
    network.read("duplicate_probability", out.duplicate_probability, probability);
    network.read("reorder", out.reorder);
    const bool hello_valid = !network.find("hello_interval") ||
                             network.read("hello_interval", out.hello_interval, positive);
    if (hello_valid) {
      const auto after_hello = value_bounds::above(out.hello_interval.count());
      const auto note = "longer than hello_interval";
      network.read("neighbour_timeout", out.neighbour_timeout, after_hello, note);
      network.check_default("neighbour_timeout", out.neighbour_timeout, after_hello, note);
    } else {
      network.read("neighbour_timeout", out.neighbour_timeout, positive);
    }
    network.read("unicast", out.unicast);
  }

  void read_adjacency(const YAML::Node& node, const std::string& path,
                      std::vector<std::array<int, 2>>& out) {
    if (!reader_.expect_list(node, path)) return;
    for (std::size_t index = 0; index < node.size(); ++index) {
      const auto pair = node[index];
      const auto pair_path = item(path, index);
      if (!pair.IsSequence() || pair.size() != 2) {
        const auto got = pair.IsSequence() ? fmt::format("a list of {}", pair.size())
                                           : yaml_reader::describe(pair);
        reader_.report(pair, pair_path, "expected a pair [camera, camera], got " + got);
        continue;
      }
      std::array<int, 2> link{};
      const bool first_valid = read_camera_reference(pair[0], item(pair_path, 0), link[0]);
      if (read_camera_reference(pair[1], item(pair_path, 1), link[1]) && first_valid &&
          link[0] == link[1]) {
        reader_.report(pair[1], item(pair_path, 1),
                       fmt::format("camera {} cannot be its own neighbour", link[1]));
      }
      out.push_back(link);
    }
  }

  void read_controller(const YAML::Node& node, controller_settings& out) {
    mapping_reader controller(reader_, node, "controller", controller_keys);
    controller.read("wait_timeout", out.wait_timeout, positive);
    controller.read("search_timeout", out.search_timeout, positive);
    controller.read("min_relevance", out.min_relevance, probability);
    controller.read("heartbeat_interval", out.heartbeat_interval, positive);
    controller.read("leader_failure_timeout", out.leader_failure_timeout, positive);
    controller.read("member_failure_timeout", out.member_failure_timeout, positive);
    controller.read("auction_relevance_threshold", out.auction_relevance_threshold, probability);
    controller.read("min_task_duration", out.min_task_duration, non_negative);
    controller.read("membership_relevance_threshold", out.membership_relevance_threshold,
                    probability);
    controller.read("merge_timeout", out.merge_timeout, positive);
    controller.read("bidding_timeout", out.bidding_timeout, positive);
    controller.read("relevance_sigma_fov_deg", out.relevance_sigma_fov_deg, positive);
    controller.read("relevance_sigma_pan_deg", out.relevance_sigma_pan_deg, positive);
    controller.read("relevance_sigma_tilt_deg", out.relevance_sigma_tilt_deg, positive);
    controller.read("solver", out.solver);
    controller.read("merge", out.merge);
    if (controller.read("strategy", out.strategy)) check_strategy(controller, out.strategy);
    controller.read("oracle_signature", out.oracle_signature_from);
    controller.read("oracle_zoom", out.oracle_zoom);
    controller.read("zoom_in_track", out.zoom_in_track);
    controller.read("auction_window", out.auction_window, positive);
    controller.read("auction_interval", out.auction_interval, non_negative);
    controller.read("relevance_look_time", out.relevance_look_time, positive);
    controller.read("bid_evidence_time", out.bid_evidence_time, non_negative);
    controller.read("bid_min_found_fraction", out.bid_min_found_fraction, probability);
    controller.read("conflict_stay_bonus", out.conflict_stay_bonus, probability);
    controller.read("bid_min_mean_score", out.bid_min_mean_score, probability);
    controller.read("track_while_bidding", out.track_while_bidding);
    controller.read("share_model", out.share_model);
    controller.read("demotion_backoff_max", out.demotion_backoff_max, non_negative);
  }

  void read_placement(const YAML::Node& node, placement_settings& out) {
    mapping_reader placement(reader_, node, "placement", placement_keys);
    placement.read("policy", out.policy);
    placement.read("crowd", out.crowd);
    placement.read("video", out.video);
  }

  void read_sensing(const YAML::Node& node, sensing_settings& out) {
    mapping_reader sensing(reader_, node, "sensing", sensing_keys);
    sensing.read("mode", out.mode);
    sensing.read("sensor_model", out.sensor_model);
    sensing.read("tracker_scales", out.scales);
    sensing.read("ego_motion", out.ego_motion);
    sensing.read("signature_update", out.signature_update);
    sensing.read("reacquire_margin", out.reacquire_margin, value_bounds::closed(0.0, 1.0));
    sensing.read("local_search_frames", out.local_search_frames, value_bounds::closed(0, 10'000));
    sensing.read("max_surround_match", out.max_surround_match, value_bounds::closed(0.0, 1.0));
    sensing.read("surround_grace_frames", out.surround_grace_frames,
                 value_bounds::closed(0, 1'000'000));
    sensing.read("surround_grace_height_px", out.surround_grace_height_px,
                 value_bounds::closed(0, 100'000));
    sensing.read("surround_patience_frames", out.surround_patience_frames,
                 value_bounds::closed(1, 1'000'000));
    sensing.read("surround_sides", out.surround_sides, value_bounds::closed(0, 4));
    sensing.read("track_rho", out.track_rho, value_bounds::closed(0.0, 1.0));
    sensing.read("halves_rho", out.halves_rho, value_bounds::closed(0.0, 1.0));
    sensing.read("identity", out.identity);
    sensing.read("group_geometry", out.geometry);
    sensing.read("reappearance", out.reappearance);
  }

  void read_tasks(const YAML::Node& node, const std::vector<camera_settings>& cameras,
                  std::vector<operator_task>& out) {
    if (!reader_.expect_list(node, "tasks")) return;
    for (std::size_t index = 0; index < node.size(); ++index) {
      mapping_reader task(reader_, node[index], item("tasks", index), task_keys);
      operator_task read;
      if (task.require("at")) task.read("at", read.at, non_negative);
      read_task_target(task, node[index], cameras, read);
      task.read("cameras_wanted", read.cameras_wanted, value_bounds::at_least(1));
      // No fewer than it wants (checked after cameras_wanted is known).
      task.read("max_cameras", read.max_cameras,
                value_bounds::at_least(static_cast<double>(read.cameras_wanted)));
      if (const auto cancel = task.find("cancel_at")) {
        seconds at{0.0};
        if (task.read("cancel_at", at, value_bounds::above(read.at.count()))) read.cancel_at = at;
      }
      out.push_back(read);
    }
  }

  // Exactly one of `pedestrian`, `pixel` and `first_to_enter` names the target; the camera is
  // the one the operator looks through (for first_to_enter, the one watched).
  void read_task_target(mapping_reader& task, const YAML::Node& where,
                        const std::vector<camera_settings>& cameras, operator_task& read) {
    constexpr std::array<std::string_view, 3> ways{"pedestrian", "pixel", "first_to_enter"};
    std::vector<std::string_view> given;
    for (auto way : ways)
      if (task.find(way)) given.push_back(way);
    if (given.size() != 1) {
      reader_.report(where, task.field("pedestrian"),
                     given.empty()
                         ? "expected one of pedestrian (an id), pixel ([x, y] in the camera's "
                           "frame) or first_to_enter (a camera id)"
                         : fmt::format("expected only one of pedestrian, pixel and "
                                       "first_to_enter, got {}",
                                       fmt::join(given, " and ")));
      return;
    }
    if (given.front() == "first_to_enter") {
      read.by = task_target::first_to_enter;
      if (!read_camera_reference(*task.find("first_to_enter"), task.field("first_to_enter"),
                                 read.camera))
        return;
      if (const auto camera = task.find("camera")) {
        int named = 0;
        if (read_camera_reference(*camera, task.field("camera"), named) && named != read.camera)
          reader_.report(*camera, task.field("camera"),
                         fmt::format("first_to_enter watches camera {}; camera {} differs (leave "
                                     "camera out)",
                                     read.camera, named));
      }
      return;
    }
    if (!task.require("camera") ||
        !read_camera_reference(*task.find("camera"), task.field("camera"), read.camera))
      return;
    if (given.front() == "pedestrian") {
      read.by = task_target::pedestrian;
      task.read("pedestrian", read.pedestrian, value_bounds::at_least(1));
      return;
    }
    read.by = task_target::pixel;
    read_pixel(*task.find("pixel"), task.field("pixel"), cameras, read);
  }

  void read_pixel(const YAML::Node& node, const std::string& path,
                  const std::vector<camera_settings>& cameras, operator_task& read) {
    if (!node.IsSequence() || node.size() != 2) {
      reader_.report(node, path, "expected [x, y], a pixel in the camera's frame");
      return;
    }
    const auto camera = std::find_if(cameras.begin(), cameras.end(),
                                     [&](const auto& c) { return c.id == read.camera; });
    const double width = camera->imaging.width_px;
    const double height = camera->imaging.height_px;
    reader_.read(node[0], item(path, 0), read.pixel.x_px, value_bounds::right_open(0.0, width));
    reader_.read(node[1], item(path, 1), read.pixel.y_px, value_bounds::right_open(0.0, height));
  }

  void read_faults(const YAML::Node& node, std::vector<fault>& out) {
    if (!reader_.expect_list(node, "faults")) return;
    for (std::size_t index = 0; index < node.size(); ++index) {
      mapping_reader entry(reader_, node[index], item("faults", index), fault_keys);
      fault read;
      if (entry.require("at")) entry.read("at", read.at, non_negative);
      const bool kind_valid = entry.require("kind") && entry.read("kind", read.kind);
      const bool camera_valid =
          entry.require("camera") &&
          read_camera_reference(*entry.find("camera"), entry.field("camera"), read.camera);
      const auto kind_name = std::string{yaml_name(read.kind)};
      const bool is_link = read.kind == fault_kind::link_cut || read.kind == fault_kind::link_heal;
      const bool has_length = read.kind == fault_kind::crash_and_recover ||
                              read.kind == fault_kind::loss_burst ||
                              read.kind == fault_kind::delay_spike;
      if (const auto peer = entry.find("peer")) {
        int id = 0;
        if (read_camera_reference(*peer, entry.field("peer"), id)) {
          read.peer = id;
          if (camera_valid && id == read.camera) {
            reader_.report(*peer, entry.field("peer"),
                           fmt::format("camera {} cannot have a link to itself", id));
          }
        }
      } else if (kind_valid && is_link) {
        entry.require("peer", "needed by " + kind_name);
      }
      if (kind_valid && has_length) {
        if (entry.require("length", "needed by " + kind_name)) {
          entry.read("length", read.length, positive);
        }
      } else {
        entry.read("length", read.length, non_negative);
      }
      entry.read("loss_probability", read.loss_probability, probability);
      if (kind_valid && read.kind == fault_kind::delay_spike) {
        if (entry.require("delay", "needed by delay_spike"))
          entry.read("delay", read.delay, positive);
      } else {
        entry.read("delay", read.delay, non_negative);
      }
      out.push_back(read);
    }
  }

  /// An integer naming one of the cameras; returns whether it does.
  bool read_camera_reference(const YAML::Node& node, const std::string& path, int& out) {
    int id = 0;
    if (!reader_.read(node, path, id)) return false;
    if (!camera_ids_.contains(id)) {
      std::vector<int> known;
      for (const auto& [each, mark] : camera_ids_) known.push_back(each);
      reader_.report(
          node, path,
          fmt::format("no camera has id {} (camera ids: {})", id,
                      known.empty() ? "none" : fmt::format("{}", fmt::join(known, ", "))));
      return false;
    }
    out = id;
    return true;
  }

  yaml_reader& reader_;
  /// Camera id -> where it was defined, for duplicate and reference checks.
  std::map<int, YAML::Mark> camera_ids_;
};

problem whole_file_problem(const std::string& file, std::string message) {
  return problem{file, 0, 0, {}, std::move(message)};
}

void refuse_bytes_yaml_misreads(std::string_view yaml_text, const std::string& source_name) {
  if (const auto bad = first_non_utf8(yaml_text))
    throw scenario_error({not_utf8(source_name, *bad)});
  if (auto nul = nul_byte(source_name, yaml_text)) throw scenario_error({std::move(*nul)});
}

[[noreturn]] void throw_syntax_error(const YAML::Exception& error, const std::string& source_name) {
  // yaml-cpp marks are 0-based; -1 (unknown) becomes 0.
  throw scenario_error(
      {problem{source_name, error.mark.line + 1, error.mark.column + 1, {}, error.msg}});
}

scenario scenario_of(YAML::Node document, const std::string& source_name,
                     std::span<const field_override> overrides) {
  apply_overrides(document, overrides, source_name);
  scenario out;
  out.name = std::filesystem::path{source_name}.stem().string();
  out.source_path = source_name;
  yaml_reader reader(source_name);
  scenario_parser(reader).parse(document, out);
  // The name goes into every JSON output, which holds only UTF-8; a `name:` in the file was
  // checked with the file's text, a name taken from the file's own name was not.
  if (const auto bad = first_non_utf8(out.name)) {
    reader.report(YAML::Mark::null_mark(), "name",
                  fmt::format("the scenario has no name: and its file name is not UTF-8 text "
                              "(byte 0x{:02X}); give it a name:",
                              bad->byte));
  }
  if (!reader.problems().empty()) throw scenario_error(reader.take_problems());
  return out;
}

}  // namespace

scenario parse_scenario(std::string_view yaml_text, const std::string& source_name) {
  return parse_scenario(yaml_text, source_name, {});
}

scenario parse_scenario(std::string_view yaml_text, const std::string& source_name,
                        std::span<const field_override> overrides) {
  refuse_bytes_yaml_misreads(yaml_text, source_name);
  std::vector<YAML::Node> documents;
  try {
    const std::string text{yaml_text};
    refuse_stuck_documents(text);
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& error) {
    throw_syntax_error(error, source_name);
  }
  if (documents.size() > 1) {
    throw scenario_error(
        {problem{source_name,
                 documents[1].Mark().line + 1,
                 1,
                 {},
                 fmt::format("expected one YAML document, got {}", documents.size())}});
  }
  return scenario_of(documents.empty() ? YAML::Node{} : documents.front(), source_name, overrides);
}

scenario parse_written_scenario(std::string_view yaml_text, const std::string& source_name) {
  refuse_bytes_yaml_misreads(yaml_text, source_name);
  YAML::Node document;
  try {
    // Load reads one document only, so the guard's endless case cannot arise.
    document = YAML::Load(std::string{yaml_text});
  } catch (const YAML::Exception& error) {
    throw_syntax_error(error, source_name);
  }
  return scenario_of(std::move(document), source_name, {});
}

scenario load_scenario(const std::filesystem::path& file) {
  return load_scenario(file, {});
}

scenario load_scenario(const std::filesystem::path& file,
                       std::span<const field_override> overrides) {
  const auto name = file.string();
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream{std::fopen(name.c_str(), "rb"),
                                                               &std::fclose};
  if (!stream) {
    throw scenario_error(
        {whole_file_problem(name, fmt::format("cannot open file: {}", std::strerror(errno)))});
  }
  std::string text;
  std::array<char, 65536> buffer{};
  std::size_t count = 0;
  while ((count = std::fread(buffer.data(), 1, buffer.size(), stream.get())) > 0) {
    text.append(buffer.data(), count);
  }
  // A directory opens fine on Linux; reading it fails with EISDIR.
  if (std::ferror(stream.get())) {
    throw scenario_error(
        {whole_file_problem(name, fmt::format("cannot open file: {}", std::strerror(errno)))});
  }
  return parse_scenario(text, name, overrides);
}

}  // namespace argus::config

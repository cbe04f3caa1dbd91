#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "config/scenario.hpp"

namespace argus::config {

/// One enumerator and how scenario files spell it.
template <class Enum>
struct enum_entry {
  Enum value;
  std::string_view name;
};

/// The YAML spelling of every enumerator of `Enum`, in declaration order; specialised below
/// for each enum a scenario file can name.
template <class Enum>
struct enum_names;

/// Names for the `type` of a camera.
template <>
struct enum_names<camera_type> {
  static constexpr std::array<enum_entry<camera_type>, 2> entries{{
      {camera_type::static_camera, "static"},
      {camera_type::ptz, "ptz"},
  }};
};

/// Names for the `kind` of imaging dropout.
template <>
struct enum_names<dropout_kind> {
  static constexpr std::array<enum_entry<dropout_kind>, 3> entries{{
      {dropout_kind::snow, "snow"},
      {dropout_kind::bit_flip, "bit_flip"},
      {dropout_kind::salt_and_pepper, "salt_and_pepper"},
  }};
};

/// Names for the `solver` of the controller.
template <>
struct enum_names<conflict_solver> {
  static constexpr std::array<enum_entry<conflict_solver>, 4> entries{{
      {conflict_solver::best_solv, "best_solv"},
      {conflict_solver::all_solv, "all_solv"},
      {conflict_solver::optimistic_solv, "optimistic_solv"},
      {conflict_solver::bound_solv, "bound_solv"},
  }};
};

/// Names for the `kind` of a fault.
template <>
struct enum_names<fault_kind> {
  static constexpr std::array<enum_entry<fault_kind>, 7> entries{{
      {fault_kind::crash, "crash"},
      {fault_kind::crash_and_recover, "crash_and_recover"},
      {fault_kind::link_cut, "link_cut"},
      {fault_kind::link_heal, "link_heal"},
      {fault_kind::loss_burst, "loss_burst"},
      {fault_kind::delay_spike, "delay_spike"},
      {fault_kind::recover, "recover"},
  }};
};

/// The YAML name of `value`, e.g. "ptz"; empty for a value outside the enumeration.
template <class Enum>
constexpr std::string_view yaml_name(Enum value) {
  for (const auto& entry : enum_names<Enum>::entries) {
    if (entry.value == value) return entry.name;
  }
  return {};
}

/// The enumerator a YAML name stands for; nullopt for an unknown name.
template <class Enum>
constexpr std::optional<Enum> from_yaml_name(std::string_view name) {
  for (const auto& entry : enum_names<Enum>::entries) {
    if (entry.name == name) return entry.value;
  }
  return std::nullopt;
}

/// All YAML names of `Enum`, in declaration order.
template <class Enum>
constexpr auto yaml_names() {
  std::array<std::string_view, enum_names<Enum>::entries.size()> names{};
  for (std::size_t i = 0; i < names.size(); ++i) names[i] = enum_names<Enum>::entries[i].name;
  return names;
}

/// Names for the network's `unicast` routing.
template <>
struct enum_names<unicast_routing> {
  static constexpr std::array<enum_entry<unicast_routing>, 2> entries{{
      {unicast_routing::flood, "flood"},
      {unicast_routing::reverse_path, "reverse_path"},
  }};
};

/// Names for the sensing `group_geometry`.
template <>
struct enum_names<group_geometry> {
  static constexpr std::array<enum_entry<group_geometry>, 3> entries{{
      {group_geometry::none, "none"},
      {group_geometry::ground_truth, "ground_truth"},
      {group_geometry::calibrated, "calibrated"},
  }};
};

/// Names for the sensing `reappearance`.
template <>
struct enum_names<reappearance_model> {
  static constexpr std::array<enum_entry<reappearance_model>, 2> entries{{
      {reappearance_model::none, "none"},
      {reappearance_model::ground_truth, "ground_truth"},
  }};
};

/// Names for the oracle's `oracle_signature`.
template <>
struct enum_names<oracle_signature> {
  static constexpr std::array<enum_entry<oracle_signature>, 2> entries{{
      {oracle_signature::own_view, "own_view"},
      {oracle_signature::operator_pick, "operator"},
  }};
};

/// Names for the `merge` rule of the controller.
template <>
struct enum_names<merge_rule> {
  static constexpr std::array<enum_entry<merge_rule>, 2> entries{{
      {merge_rule::highest_id, "highest_id"},
      {merge_rule::negotiation, "negotiation"},
  }};
};

/// Names for the sensing `mode`.
template <>
struct enum_names<sensing_mode> {
  static constexpr std::array<enum_entry<sensing_mode>, 2> entries{{
      {sensing_mode::pixels, "pixels"},
      {sensing_mode::emulated, "emulated"},
  }};
};

/// Names for placement.policy.
template <>
struct enum_names<placement_policy> {
  static constexpr std::array<enum_entry<placement_policy>, 2> entries{{
      {placement_policy::region, "region"},
      {placement_policy::id, "id"},
  }};
};

/// Names for placement.crowd.
template <>
struct enum_names<crowd_placement> {
  static constexpr std::array<enum_entry<crowd_placement>, 2> entries{{
      {crowd_placement::workers, "workers"},
      {crowd_placement::coordinator, "coordinator"},
  }};
};

/// Names for placement.video.
template <>
struct enum_names<video_placement> {
  static constexpr std::array<enum_entry<video_placement>, 2> entries{{
      {video_placement::workers, "workers"},
      {video_placement::coordinator, "coordinator"},
  }};
};

/// How an operator task names its target, as the event log writes it.
template <>
struct enum_names<task_target> {
  static constexpr std::array<enum_entry<task_target>, 3> entries{{
      {task_target::pedestrian, "pedestrian"},
      {task_target::pixel, "pixel"},
      {task_target::first_to_enter, "first_to_enter"},
  }};
};

/// Names for the world's `clothing`.
template <>
struct enum_names<clothing> {
  static constexpr std::array<enum_entry<clothing>, 2> entries{{
      {clothing::palette, "palette"},
      {clothing::varied, "varied"},
  }};
};

/// Names for the controller's `strategy`.
/// Names for the sensing `tracker_scales`.
template <>
struct enum_names<tracker_scales> {
  static constexpr std::array<enum_entry<tracker_scales>, 2> entries{{
      {tracker_scales::target, "target"},
      {tracker_scales::paper, "paper"},
  }};
};

/// Names for the sensing `identity`.
template <>
struct enum_names<identity_source> {
  static constexpr std::array<enum_entry<identity_source>, 2> entries{{
      {identity_source::appearance, "appearance"},
      {identity_source::ground_truth, "ground_truth"},
  }};
};

}  // namespace argus::config

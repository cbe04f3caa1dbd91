#pragma once

/// Scenario files: YAML whose keys are the field names of scenario.hpp. Everything but the
/// keys marked "required" has a default (Table 2 of the paper for network and controller);
/// unknown keys are errors, so a typo never silently falls back to a default.
///
/// ```yaml
/// name: demo                       # optional, default: the file stem
/// run: {seed: 7, duration: 2 min, tick: 1/15 s, speed: 0, threads: 2, output_dir: out/demo}
/// world: {layout: stations/x.yaml, population: 100, spawn_rate_per_min: 60, partitions: 4}
/// cameras:
///   - id: 1                                  # required, unique, >= 1
///     position: {x_m: 10, y_m: 20}           # required; or the list form [10, 20]
///     height_m: 4
///     type: ptz                              # static | ptz
///     pan_deg: 0                             # default pose, within the limits below
///     tilt_deg: -20
///     field_of_view_deg: 45
///     pan_limits: [-180, 180]                # [min, max] degrees
///     tilt_limits: [-80, 10]                 # within [-90, 90]
///     field_of_view_limits: [5, 90]          # within (0, 180)
///     pan_rate_deg_per_s: 60
///     tilt_rate_deg_per_s: 30
///     zoom_rate_deg_per_s: 20
///     imaging:
///       resolution: [640, 480]               # each in [16, 8192]
///       color_response: {hue_offset_deg: 10, saturation_gain: 0.9, value_gain: 1.1,
///                        value_offset: 0, tint: 0, tone: 0, shade: 0.1}
///                                            # presence enables it; `off` disables it
///       noise_sigma: 4                       # 0 = off
///       dropout: {fraction: 0.01, kind: salt_and_pepper}   # snow | bit_flip | salt_and_pepper
///       jpeg_quality: 75                     # 1..100; 0 = off
///       interlace: true
/// network: {loss_probability: 0.1, min_delay: 200 ms, max_delay: 500 ms,
///           node_failure_probability: 0.001, max_hops: 3, message_timeout: 1500 ms,
///           communication_range_m: 40, adjacency: [[1, 2], [2, 3]],
///           duplicate_probability: 0, reorder: false,
///           hello_interval: 1 s, neighbour_timeout: 5 s,   # neighbour_timeout > hello_interval
///           unicast: flood}                               # flood | reverse_path
/// controller: {wait_timeout: 2 min, search_timeout: 5 min, min_relevance: 0.1,
///              heartbeat_interval: 1000 ms, leader_failure_timeout: 3000 ms,
///              member_failure_timeout: 5000 ms, auction_relevance_threshold: 0.5,
///              min_task_duration: 1 min, membership_relevance_threshold: 0.1,
///              merge_timeout: 5 min, bidding_timeout: 2 min, relevance_sigma_fov_deg: 5,
///              relevance_sigma_pan_deg: 5, relevance_sigma_tilt_deg: 5,
///              solver: optimistic_solv,        # optimistic_solv | best_solv | all_solv
///                                              # | bound_solv
///              merge: highest_id,              # highest_id | negotiation
///              strategy: paper}                # paper | no_collaboration | oracle
/// tasks:                       # at required, and one of pedestrian, pixel, first_to_enter
///   - {at: 10 s, pedestrian: 12, camera: 7, cameras_wanted: 2}      # by id, camera required
///   - {at: 20 s, pixel: [160, 120], camera: 7, cancel_at: 5 min}    # the operator's click
///   - {at: 0 s, first_to_enter: 2, max_cameras: 2}                  # Fig. 19
/// faults:                                    # at, kind, camera required
///   - {at: 60 s, kind: crash, camera: 7}
///   - {at: 90 s, kind: crash_and_recover, camera: 3, length: 30 s}     # length required
///   - {at: 100 s, kind: link_cut, camera: 1, peer: 2}                  # peer required
///   - {at: 110 s, kind: link_heal, camera: 1, peer: 2}                 # peer required
///   - {at: 120 s, kind: loss_burst, camera: 4, length: 5 s, loss_probability: 0.8}
///   - {at: 130 s, kind: delay_spike, camera: 4, length: 5 s, delay: 2 s}
///   - {at: 130 s, kind: recover, camera: 7}        # a crashed camera comes back
/// ```
///
/// Durations always carry a unit (ms, s, min, h; see duration.hpp).

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "config/field_override.hpp"
#include "config/scenario.hpp"
#include "config/scenario_error.hpp"

namespace argus::config {

/// Reads and validates the scenario in `file`. `name` defaults to the file stem and
/// `source_path` is `file` as given. Throws scenario_error listing every problem found
/// (including "cannot open file: REASON" and YAML syntax errors); never returns a partial
/// scenario.
scenario load_scenario(const std::filesystem::path& file);

/// load_scenario with `overrides` (`--set KEY=VALUE`) put into the YAML tree first, so they are
/// validated like the file's own values.
scenario load_scenario(const std::filesystem::path& file,
                       std::span<const field_override> overrides);

/// load_scenario for text already in memory; `source_name` names it in problems, gives
/// the default `name` (its stem) and becomes `source_path`.
scenario parse_scenario(std::string_view yaml_text, const std::string& source_name);

/// parse_scenario with `overrides` applied to the YAML tree before validation.
scenario parse_scenario(std::string_view yaml_text, const std::string& source_name,
                        std::span<const field_override> overrides);

/// parse_scenario for a scenario as `to_yaml` wrote it (a worker's copy of its coordinator's):
/// one YAML document, read in one pass. A file is read twice, because only a pass of its own
/// finds a second document without yaml-cpp's endless one (yaml_guards.hpp); for the large
/// station's 1,024 cameras each pass is 0.15 s of every worker's set-up. Whatever follows the
/// first document is not read, so text from anywhere else goes to parse_scenario.
scenario parse_written_scenario(std::string_view yaml_text, const std::string& source_name);

}  // namespace argus::config

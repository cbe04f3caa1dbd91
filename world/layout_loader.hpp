#pragma once

/// Station layout files: YAML with the fields of layout.hpp. Points are `[x, y]` in metres;
/// boxes are written `min: [x, y], max: [x, y]`. Unknown keys are errors.
///
/// ```yaml
/// name: penn_station
/// size_m: [200, 100]
/// walls: [[[22, 5], [65, 5], [65, 20]]]          # polylines, at least two points each
/// obstacles:                                     # polygon, or a box given by min/max
///   - {name: column, min: [35, 20], max: [36, 21]}
///   - {name: kiosk, polygon: [[150, 49], [152, 49], [152, 51]]}
/// regions:                                       # concourse | waiting_room | arcade |
///   - {name: waiting_room, kind: waiting_room, min: [65, 10], max: [140, 90]}  # platforms |
///   - {name: stairs_up, kind: other, min: [5, 0], max: [15, 2], speed_factor: 0.6}  # tracks |
/// portals:                                       # other; street | internal; speed_factor
///                                                # scales walking speed (stairs), 0.1-1.5
///   - {name: arcade_street, kind: street, min: [198, 42], max: [200, 58]}
/// ticket_booths:                                 # vending_machines take the same keys
///   - {name: booth_1, min: [78.5, 88], max: [81.5, 90], service_point: [80, 87.3],
///      queue_direction: [0, -1], queue_spacing_m: 0.8, max_queue_length: 15,
///      service_time_s: [8, 20]}
/// benches:
///   - {name: bench_1, from: [76, 22], to: [82, 22], seats: 6, facing: [0, -1]}
/// stairs:
///   - {name: platform_1, min: [22.3, 8], max: [26, 12]}
/// meeting_points:
///   - {name: clock, position: [100, 50], radius_m: 3}
/// ```

#include <filesystem>
#include <string>
#include <string_view>

#include "config/scenario.hpp"
#include "config/scenario_error.hpp"
#include "world/layout.hpp"

namespace argus::world {

/// Reads and validates the layout in `file`; throws config::scenario_error listing every
/// problem (file, line, field, what was expected).
layout load_layout(const std::filesystem::path& file);

/// load_layout for text in memory; `source_name` names it in problems.
layout parse_layout(std::string_view yaml_text, const std::string& source_name);

/// The shipped Penn Station layout (scenarios/stations/penn_station_layout.yaml), found
/// through the source path baked in at compile time.
std::filesystem::path builtin_layout_path();

/// The layout file a scenario uses: `world.layout` relative to the scenario file's folder,
/// or the built-in Penn Station when empty.
std::filesystem::path layout_path(const config::scenario& scenario);

}  // namespace argus::world

#pragma once

#include <string>

namespace argus::apps {

/// What `argus generate station` builds: a grid of halls, each 100 m x 60 m, joined by 8 m
/// openings, with street doors on the outer north and south walls, stairs down to the tracks
/// along the west wall, and in every hall four columns, a ticket booth or a vending machine,
/// a bench and a meeting point; the cameras spread evenly over the floor.
struct station_plan {
  std::string name = "large_station";
  unsigned halls_east = 8;
  unsigned halls_north = 4;
  unsigned cameras = 1024;
  unsigned pedestrians = 10000;
  /// Tasks on the next entrant of cameras spread over the network, all at 10 s.
  unsigned tasks = 16;
  /// Crowd partitions (actors).
  unsigned partitions = 8;
};

/// A generated station's two files, as YAML text.
struct generated_station {
  std::string layout_yaml;
  std::string scenario_yaml;
};

/// The layout and the scenario for `plan`; the scenario names its layout `layout_file` (relative
/// to the scenario's folder). Emulated sensing: pixels for a thousand cameras is not the point.
generated_station generate_station(const station_plan& plan, const std::string& layout_file);

}  // namespace argus::apps

#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace argus::world {

/// A point or direction on the station floor plan, in metres (x to the east, y to the north).
using vec2 = Eigen::Vector2d;

/// An axis-aligned rectangle on the floor plan; regions, portals and stairs are boxes because
/// the station (Fig. 1) is built from rectangular halls.
struct box {
  vec2 min{0.0, 0.0};
  vec2 max{0.0, 0.0};
  /// Whether `p` lies inside or on the edge.
  bool contains(const vec2& p) const {
    return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
  }
  /// The centre point.
  vec2 center() const { return (min + max) / 2.0; }
};

/// What a region of the station is used for (Fig. 1: concourse and tracks on the left, main
/// waiting room in the centre, shopping arcade on the right).
enum class region_kind { concourse, waiting_room, arcade, platforms, tracks, other };

/// A named area of the floor. Pedestrians walk only inside regions that are not `tracks`.
/// `speed_factor` scales the preferred speed of whoever walks in it: a flight of stairs in
/// this 2-D plan is a region where people walk slower (RiMEA tests 2 and 3; Fruin/Weidmann
/// give about 0.6 of the level speed upwards and 0.7 downwards).
struct region {
  std::string name;
  region_kind kind = region_kind::other;
  box area;
  double speed_factor = 1.0;
};

/// A `street` portal is a door to the outside where pedestrians enter and leave; an
/// `internal` portal is an opening between two halls (the yellow rectangles of Fig. 1).
enum class portal_kind { street, internal };

/// An entrance, exit or opening between halls.
struct portal {
  std::string name;
  portal_kind kind = portal_kind::internal;
  box area;
};

/// A wall: an open polyline of at least two points.
struct wall {
  std::vector<vec2> points;
};

/// A solid obstacle (column, kiosk, counter): a closed polygon.
struct obstacle {
  std::string name;
  std::vector<vec2> polygon;
};

/// A ticket booth or a vending machine: a solid footprint, the point where the customer being
/// served stands, and the direction the waiting line grows from there.
struct service_counter {
  std::string name;
  box footprint;
  vec2 service_point{0.0, 0.0};
  /// Unit vector from the service point towards the tail of the line.
  vec2 queue_direction{0.0, -1.0};
  double queue_spacing_m = 0.8;
  /// A pedestrian finding a line this long goes elsewhere.
  unsigned max_queue_length = 15;
  double min_service_s = 8.0;
  double max_service_s = 20.0;
};

/// A bench: a solid line from `from` to `to` with `seats` evenly spaced seats on the side
/// `facing` points to (pedestrians sit facing that way).
struct bench {
  std::string name;
  vec2 from{0.0, 0.0};
  vec2 to{0.0, 0.0};
  unsigned seats = 1;
  /// Unit vector from the bench line towards the seats.
  vec2 facing{0.0, -1.0};
};

/// Stairs down to a train platform: walking into the box means leaving the station (and
/// arriving passengers come up here).
struct stairs {
  std::string name;
  box area;
};

/// A spot in the waiting room where pedestrians wait to meet someone.
struct meeting_point {
  std::string name;
  vec2 position{0.0, 0.0};
  double radius_m = 2.0;
};

/// A whole station floor plan, as read from a layout file.
struct layout {
  std::string name;
  /// The file it came from (empty when built in code).
  std::string source_path;
  /// Extent of the plan: everything lies in [0, size_m.x()] x [0, size_m.y()].
  vec2 size_m{200.0, 100.0};
  std::vector<wall> walls;
  std::vector<obstacle> obstacles;
  std::vector<region> regions;
  std::vector<portal> portals;
  std::vector<service_counter> ticket_booths;
  std::vector<service_counter> vending_machines;
  std::vector<bench> benches;
  std::vector<stairs> stairways;
  std::vector<meeting_point> meeting_points;
};

/// The YAML name of a region kind ("waiting_room").
const char* to_string(region_kind kind) noexcept;

/// The YAML name of a portal kind ("street").
const char* to_string(portal_kind kind) noexcept;

}  // namespace argus::world

#pragma once

#include <chrono>
#include <map>
#include <ostream>
#include <vector>

#include "world/layout.hpp"

namespace argus::world {

class snapshot;

/// Writes pedestrian ground truth as CSV, one row per pedestrian per tick:
/// `tick,t,id,x,y,vx,vy,heading,activity` (metres, m/s, radians, activity name). Numbers are
/// written with enough digits to be read back exactly (shortest round-trip form).
class trajectory_writer {
 public:
  /// Writes the header line to `out`, which must outlive the writer.
  explicit trajectory_writer(std::ostream& out);

  /// Appends every pedestrian of `frame`.
  void write(const snapshot& frame);

 private:
  std::ostream& out_;
};

/// Recent positions of each pedestrian, for drawing trails on the plan view.
class trail_recorder {
 public:
  /// Keeps the positions of the last `length` of virtual time.
  explicit trail_recorder(std::chrono::duration<double> length) : length_(length) {
    // nop
  }

  /// Adds the positions of `frame` and forgets those older than the trail length or of
  /// pedestrians that left.
  void record(const snapshot& frame);

  /// Trails by pedestrian id, oldest point first.
  const std::map<int, std::vector<vec2>>& trails() const noexcept { return trails_; }

 private:
  struct sample {
    std::chrono::duration<double> time;
    vec2 position;
  };
  std::chrono::duration<double> length_;
  std::map<int, std::vector<sample>> samples_;
  std::map<int, std::vector<vec2>> trails_;
};

}  // namespace argus::world

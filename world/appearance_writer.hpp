#pragma once

#include <ostream>

namespace argus::world {

class snapshot;

/// Writes what each pedestrian looks like as CSV, one row per pedestrian, when first seen:
/// `id,first_tick,shirt,trousers,skin,hair,height_m,girth_m`, colours as `#rrggbb` (sRGB).
/// Colour indexing cannot tell two pedestrians of the same colours apart however well it
/// works, so who resembles whom is ground truth a run's figures need (bench/lookalikes.py).
class appearance_writer {
 public:
  /// Writes the header line to `out`, which must outlive the writer.
  explicit appearance_writer(std::ostream& out);

  /// Appends every pedestrian of `frame` not written before.
  void write(const snapshot& frame);

 private:
  std::ostream& out_;
  // The spawner numbers pedestrians 1, 2, 3, ... and never reuses an id: one above this is new.
  int last_written_ = 0;
};

}  // namespace argus::world

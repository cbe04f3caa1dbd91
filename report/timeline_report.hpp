#pragma once

#include <vector>

#include "report/group_timeline.hpp"

namespace argus::report {

/// timeline.png: for each task, one lane per camera that was ever in its group, a thin bar in
/// the camera's colour while it was a member and a thick outlined one while it led; hand-overs
/// as triangles above the task's lanes; crashes as red crosses on the camera's lane and red
/// lines across the chart, recoveries in green; a time axis below. A run without tasks still
/// shows its failures. Returns the PNG bytes.
std::vector<unsigned char> render_timeline(const group_timeline& timeline);

}  // namespace argus::report

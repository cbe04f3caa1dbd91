#pragma once

#include <span>
#include <vector>

#include "config/scenario.hpp"
#include "report/target_paths.hpp"

namespace argus::world {
class station;
}

namespace argus::report {

/// plan.png (paper Fig. 17): the station's plan view with its cameras, and each task target's
/// path coloured by the camera observing her at each moment (camera_colour), grey where no
/// camera did; each camera is ringed in its colour and a legend names the colours. Stretches
/// where she was out of the station are not drawn. Returns the PNG bytes.
std::vector<unsigned char> render_plan_report(const world::station& where,
                                              std::span<const config::camera_settings> cameras,
                                              const target_paths& paths);

}  // namespace argus::report

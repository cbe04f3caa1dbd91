#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <span>
#include <vector>

#include "config/scenario.hpp"
#include "world/layout.hpp"

namespace argus::world {

class snapshot;
class station;

/// How the plan view is drawn.
struct plan_view_options {
  double pixels_per_m = 7.0;
  /// Ground range at which field-of-view wedges are cut off (a PTZ camera sees farther, but
  /// longer wedges would hide the floor plan).
  double wedge_range_m = 30.0;
  bool labels = true;
};

/// Where the plan view draws the point `at` (metres on the plan): pixel column and row of the
/// image render_plan_view returns with the same options, for drawing over it.
std::array<int, 2> plan_pixel(const station& where, const plan_view_options& options,
                              const vec2& at);

/// Draws the plan view like the paper's Fig. 1 (north up): regions, walls and obstacles,
/// portals (yellow), ticket booths, benches, vending machines, stairs, the cameras with their
/// field-of-view wedges (from position, pan and field of view) and, if given, the pedestrians
/// (shirt colour) with their trails. Returns the PNG bytes.
std::vector<unsigned char> render_plan_view(const station& where,
                                            std::span<const config::camera_settings> cameras,
                                            const snapshot* frame,
                                            const std::map<int, std::vector<vec2>>* trails,
                                            const plan_view_options& options = {});

/// render_plan_view written to `png`; throws std::runtime_error when it cannot be written.
void write_plan_view(const std::filesystem::path& png, const station& where,
                     std::span<const config::camera_settings> cameras, const snapshot* frame,
                     const std::map<int, std::vector<vec2>>* trails,
                     const plan_view_options& options = {});

}  // namespace argus::world

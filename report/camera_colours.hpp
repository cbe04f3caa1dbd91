#pragma once

#include <array>

namespace argus::report {

/// An 8-bit colour in OpenCV's channel order.
struct bgr {
  unsigned char b = 0;
  unsigned char g = 0;
  unsigned char r = 0;
};

/// The colour that stands for camera `id` in every report picture (plan path, timeline bars,
/// legends), so one camera reads the same everywhere; ids beyond the palette reuse it.
bgr camera_colour(int id);

/// The colour of "no camera": the unobserved stretches of a path.
constexpr bgr unobserved_colour{170, 170, 170};

/// "#rrggbb" for HTML.
std::array<char, 8> html_colour(bgr colour);

}  // namespace argus::report

#include "report/camera_colours.hpp"

#include <cstdio>

namespace argus::report {

namespace {

// Twelve hues far enough apart to tell side by side (after ColorBrewer's "Paired" and
// Tableau's ten), none of them grey, so "unobserved" stays unambiguous.
constexpr std::array<bgr, 12> palette{{{180, 119, 31},
                                       {14, 127, 255},
                                       {44, 160, 44},
                                       {40, 39, 214},
                                       {189, 103, 148},
                                       {75, 86, 140},
                                       {194, 119, 227},
                                       {34, 189, 188},
                                       {207, 190, 23},
                                       {0, 0, 128},
                                       {128, 128, 0},
                                       {128, 0, 128}}};

}  // namespace

bgr camera_colour(int id) {
  const int index = ((id % static_cast<int>(palette.size())) + static_cast<int>(palette.size())) %
                    static_cast<int>(palette.size());
  return palette[static_cast<std::size_t>(index)];
}

std::array<char, 8> html_colour(bgr colour) {
  std::array<char, 8> out{};
  std::snprintf(out.data(), out.size(), "#%02x%02x%02x", colour.r, colour.g, colour.b);
  return out;
}

}  // namespace argus::report

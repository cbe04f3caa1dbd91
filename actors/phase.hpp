#pragma once

#include <cstdint>
#include <string_view>

namespace argus::actors {

/// The phases of one tick, run in this order; every participant due in a phase acknowledges
/// before the next phase starts (docs/runtime.md, "A tick").
enum class phase : std::uint8_t {
  faults = 0,   ///< scheduled faults and operator tasks take effect
  world = 1,    ///< crowd partitions step pedestrians and publish a snapshot
  network = 2,  ///< the world coordinator hands out the snapshot (links are never ticked)
  cameras = 3,  ///< camera nodes sense, run their controller, send into links
};

/// Number of phases in a tick.
inline constexpr std::uint8_t phase_count = 4;

/// Lower-case name of a phase, as written in logs.
constexpr std::string_view to_string(phase p) noexcept {
  switch (p) {
    case phase::faults:
      return "faults";
    case phase::world:
      return "world";
    case phase::network:
      return "network";
    case phase::cameras:
      return "cameras";
  }
  return "unknown";
}

}  // namespace argus::actors

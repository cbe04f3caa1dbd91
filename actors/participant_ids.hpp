#pragma once

#include <cstddef>
#include <cstdint>

namespace argus::actors {

/// Stable participant ids, derived from the scenario rather than spawn order, so that the
/// canonical order of ticks, mail and events is the same in every run. Ranges do not overlap.
namespace participant_ids {

/// The scenario script (operator tasks and scheduled faults).
inline constexpr std::uint64_t script = 1;

/// Camera node with scenario id `camera_id` (>= 1).
constexpr std::uint64_t camera(int camera_id) noexcept {
  return 1'000'000ULL + static_cast<std::uint64_t>(camera_id);
}

/// The scenario id of the camera whose participant id is `id`, or 0 when `id` is no camera's.
constexpr int camera_of(std::uint64_t id) noexcept {
  return id > 1'000'000ULL && id < 2'000'000'000ULL ? static_cast<int>(id - 1'000'000ULL) : 0;
}

/// The fault injector.
inline constexpr std::uint64_t fault_injector = 2;

/// Link number `index` in the topology's sorted link list.
constexpr std::uint64_t link(std::size_t index) noexcept {
  return 2'000'000'000ULL + static_cast<std::uint64_t>(index);
}

/// The world coordinator: gathers the crowd partitions' results, spawns, publishes snapshots.
inline constexpr std::uint64_t world_coordinator = 3;

/// The video recorder of `argus run --video`: renders every camera each tick into a mosaic.
inline constexpr std::uint64_t video_recorder = 4;

/// Crowd partition number `index` (vertical strips, west to east).
constexpr std::uint64_t crowd_partition(std::size_t index) noexcept {
  return 3'000'000'000ULL + static_cast<std::uint64_t>(index);
}

}  // namespace participant_ids
}  // namespace argus::actors

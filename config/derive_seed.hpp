#pragma once

#include <cstdint>

namespace argus::config {

/// Derives the seed of one actor's private RNG from the run seed and the actor's stable id,
/// so that every actor draws an independent, reproducible stream whatever thread runs it.
/// SplitMix64 finaliser over both words: cheap, and well mixed even for adjacent ids.
constexpr std::uint64_t derive_seed(std::uint64_t run_seed, std::uint64_t actor_id) noexcept {
  std::uint64_t z = run_seed + 0x9e3779b97f4a7c15ULL * (actor_id + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace argus::config

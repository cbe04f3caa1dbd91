#pragma once

#include <array>
#include <cstdint>

namespace argus::world {

/// A small, copyable random generator (xoshiro256**, seeded through SplitMix64). Each
/// pedestrian and the spawner own one, seeded with config::derive_seed, so draws depend only
/// on the run seed and the owner's id — never on stepping order, partitions or threads. Its
/// own distributions keep the streams identical across standard libraries (std::uniform_*
/// are implementation-defined).
class rng {
 public:
  /// Seeds the four state words from `seed`.
  explicit rng(std::uint64_t seed = 1) noexcept {
    for (auto& word : state_) {
      seed += 0x9e3779b97f4a7c15ULL;
      std::uint64_t z = seed;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      word = z ^ (z >> 31);
    }
  }

  /// The next 64 random bits.
  std::uint64_t next() noexcept {
    const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  /// Uniform in [0, 1).
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Uniform in [low, high).
  double uniform(double low, double high) noexcept { return low + (high - low) * uniform(); }

  /// Uniform integer in [0, count); count > 0.
  std::uint32_t below(std::uint32_t count) noexcept {
    return static_cast<std::uint32_t>((next() >> 32) * count >> 32);
  }

  /// true with probability `p`.
  bool chance(double p) noexcept { return uniform() < p; }

  /// The four state words: a generator carried to another process goes on with the same draws.
  std::array<std::uint64_t, 4>& words() noexcept { return state_; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }

  std::array<std::uint64_t, 4> state_;
};

}  // namespace argus::world

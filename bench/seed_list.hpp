#pragma once

// The seeds a bench runs, from its command line after OUT.png: whole numbers from 1, 1 and 2
// when none are given. Shared by bench/steady_flow and bench/fundamental_diagram, so that
// `OUT.png $(seq 1 20)` means the same seeds in both.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

namespace argus::bench {

/// argv[first..argc) as seeds; nullopt, after printing `usage` and the bad value to stderr,
/// when one is not a whole number from 1.
inline std::optional<std::vector<std::uint64_t>> seed_list(int argc, char** argv, int first,
                                                           const char* usage) {
  std::vector<std::uint64_t> seeds;
  for (int i = first; i < argc; ++i) {
    char* rest = nullptr;
    seeds.push_back(std::strtoull(argv[i], &rest, 10));
    if (rest == argv[i] || *rest != 0 || seeds.back() == 0) {
      std::fprintf(stderr, "usage: %s: seeds are whole numbers from 1, got %s\n", usage, argv[i]);
      return std::nullopt;
    }
  }
  if (seeds.empty()) seeds = {1, 2};
  return seeds;
}

}  // namespace argus::bench

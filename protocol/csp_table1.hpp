#pragma once

// The instances of Table 1 (Section IV-B): two groups, three sensors each, a fixed number of
// relevant cameras per group with random relevances. protocol::solve's benchmark input.
//
// The overlap is derived from the paper's own counts. With n relevant cameras per group, s of
// them shared, and min = max = 3, AllSolv's number of solutions does not depend on the
// relevances: sum over the C(n, 3) values of group 1 of C(n - j, 3), j the shared cameras it
// takes. n = 12, s = 7 gives exactly Table 1's 29290; n = 16, s = 9 exactly its 221347 (and
// domains of exactly 220 and 560, so every group has exactly n relevant cameras).
//
// Generator (seeded, deterministic on every platform): a pool of 2n - s cameras; a
// PCG64 stream (pcg-cpp) shuffles the pool (Fisher-Yates, unbiased bounded draws); group 0's
// relevant cameras are the first n of the shuffled pool, group 1's the last n, so the middle
// s are shared and the shared ones are spread over the camera indices. Each relevant
// (group, camera) pair then draws its relevance uniformly in [threshold, 1) (53-bit draws,
// group 0 then group 1, cameras ascending); every other pair has relevance 0.

#include <cstdint>

#include "protocol/csp.hpp"

namespace argus::protocol {

/// One setting of Table 1.
struct table1_setting {
  /// Relevant cameras of each of the two groups.
  unsigned relevant_per_group = 12;
  /// How many of them both groups share.
  unsigned shared = 7;
  /// min_cameras = max_cameras of each group ("number of sensors per group").
  unsigned cameras_per_group = 3;
  double threshold = 0.1;
};

/// Test cases 1-2 (12 relevant sensors per group) and 3-4 (16).
inline constexpr table1_setting table1_cases_1_2{12, 7, 3, 0.1};
inline constexpr table1_setting table1_cases_3_4{16, 9, 3, 0.1};

/// One random instance of `setting` (see above for the generator).
csp_problem make_table1_instance(const table1_setting& setting, std::uint64_t seed);

}  // namespace argus::protocol

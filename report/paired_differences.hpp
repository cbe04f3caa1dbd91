#pragma once

#include <string>
#include <vector>

#include "report/confidence_interval.hpp"
#include "report/sweep_results.hpp"

namespace argus::report {

/// A swept value against the parameter's first value (the baseline), run by run: each run at
/// the value is paired with the baseline's run of the same seed and the same values of every
/// other parameter. Seeds differ far more than most settings do (one seed's pedestrian may be
/// easy to follow and the next's not), so the difference within a pair measures a setting's
/// effect with a fraction of the spread of two pooled means (docs/sweep.md).
struct paired_difference {
  /// The value compared, and the baseline it is compared with.
  std::string value;
  std::string baseline;
  /// The metric at the value minus at the baseline, over the pairs in which both runs have it:
  /// count (the pairs), mean, standard error and 95% confidence interval (Student's t).
  mean_interval difference;
  /// Pairs in which the value's metric is higher, lower, equal (within the tolerance given).
  std::size_t higher = 0;
  std::size_t lower = 0;
  std::size_t equal = 0;
  /// The two-sided exact sign test over the pairs that differ (sign_test_p).
  double sign_test_p = 1.0;
};

/// One paired_difference for each value of parameter `parameter_index` after its first, in the
/// order given; a run without the metric (failed, not run, null) pairs with nothing. A pair
/// whose difference is within the results' `equal_within` counts as equal, for the counts and
/// the sign test; the mean and its interval take every pair.
std::vector<paired_difference> paired_differences(const sweep_results& results,
                                                  const std::string& metric,
                                                  std::size_t parameter_index);

/// The two-sided exact sign (binomial) test: were higher and lower equally likely, the
/// probability of a split at least as uneven as `higher` to `lower`; 1 when both are 0.
double sign_test_p(std::size_t higher, std::size_t lower);

}  // namespace argus::report

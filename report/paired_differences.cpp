#include "report/paired_differences.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace argus::report {

namespace {

// What pairs two runs: the seed and the values of every parameter but the one compared.
struct pair_key {
  std::uint64_t seed = 0;
  std::vector<std::string> others;
  auto operator<=>(const pair_key&) const = default;
};

pair_key key_of(const sweep_run& run, std::size_t parameter_index) {
  pair_key key{run.seed, run.values};
  key.others.erase(key.others.begin() + static_cast<std::ptrdiff_t>(parameter_index));
  return key;
}

}  // namespace

double sign_test_p(std::size_t higher, std::size_t lower) {
  const std::size_t n = higher + lower;
  if (n == 0) return 1.0;
  // 2 * P(X <= min) for X ~ Binomial(n, 1/2), each term in logarithms so that no factorial
  // overflows however many seeds.
  const double log_half_n = static_cast<double>(n) * std::log(0.5);
  const double ln_n_factorial = std::lgamma(static_cast<double>(n) + 1.0);
  double tail = 0.0;
  for (std::size_t i = 0; i <= std::min(higher, lower); ++i)
    tail += std::exp(ln_n_factorial - std::lgamma(static_cast<double>(i) + 1.0) -
                     std::lgamma(static_cast<double>(n - i) + 1.0) + log_half_n);
  return std::min(1.0, 2.0 * tail);
}

std::vector<paired_difference> paired_differences(const sweep_results& results,
                                                  const std::string& metric,
                                                  std::size_t parameter_index) {
  const double tie = std::abs(results.equal_within);
  const auto& values = results.parameters.at(parameter_index).values;
  std::vector<paired_difference> out;
  if (values.size() < 2) return out;
  std::map<pair_key, double> baseline;
  for (const auto& run : results.runs)
    if (run.values.at(parameter_index) == values.front())
      if (const auto m = run.metric(metric)) baseline.emplace(key_of(run, parameter_index), *m);
  for (std::size_t v = 1; v < values.size(); ++v) {
    paired_difference d{values[v], values.front(), {}, 0, 0, 0, 1.0};
    std::vector<double> differences;
    for (const auto& run : results.runs) {
      if (run.values.at(parameter_index) != values[v]) continue;
      const auto m = run.metric(metric);
      const auto partner = baseline.find(key_of(run, parameter_index));
      if (!m || partner == baseline.end()) continue;
      const double difference = *m - partner->second;
      differences.push_back(difference);
      (difference > tie ? d.higher : difference < -tie ? d.lower : d.equal) += 1;
    }
    d.difference = mean_with_ci95(differences);
    d.sign_test_p = sign_test_p(d.higher, d.lower);
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace argus::report

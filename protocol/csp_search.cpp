#include "protocol/csp_search.hpp"

namespace argus::protocol::csp_search {

std::vector<std::vector<std::size_t>> relevant_cameras(const csp_problem& problem) {
  std::vector<std::vector<std::size_t>> relevant(problem.groups.size());
  for (std::size_t g = 0; g < problem.groups.size(); ++g) {
    const auto& relevance = problem.groups[g].relevance;
    for (std::size_t c = 0; c < relevance.size(); ++c)
      if (relevance[c] >= problem.threshold) relevant[g].push_back(c);  // false for NaN
  }
  return relevant;
}

double canonical_weight(const round_problem& round, const assignment& chosen) {
  double weight = 0.0;
  for (std::size_t g = 0; g < chosen.size(); ++g)
    for (std::size_t c : chosen[g]) weight += round.relevance(g, c);
  return weight;
}

bool incumbent::offer(const round_problem& round, const assignment& chosen, double estimate) {
  if (!may_take(estimate)) return false;
  const double weight = canonical_weight(round, chosen);
  if (found_ && (weight < weight_ || (weight == weight_ && !(chosen < best_)))) return false;
  found_ = true;
  weight_ = weight;
  best_ = chosen;
  return true;
}

}  // namespace argus::protocol::csp_search

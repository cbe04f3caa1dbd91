#include "report/target_paths.hpp"

#include <algorithm>

namespace argus::report {

target_paths target_paths_from(const csv_table& targets) {
  target_paths out;
  const auto t = targets.column("t");
  const auto task = targets.column("task");
  const auto x = targets.column("x");
  const auto y = targets.column("y");
  const auto present = targets.column("present");
  const auto observed_by = targets.column("observed_by");
  if (!t || !task || !x || !y) return out;
  for (const auto& row : targets.rows()) {
    target_sample s;
    s.t_s = csv_table::number(row, *t);
    s.x_m = csv_table::number(row, *x);
    s.y_m = csv_table::number(row, *y);
    s.present = !present || csv_table::number(row, *present) != 0.0;
    s.observed_by = observed_by ? static_cast<int>(csv_table::number(row, *observed_by, -1)) : -1;
    out[static_cast<int>(csv_table::number(row, *task))].push_back(s);
  }
  for (auto& [id, samples] : out)
    std::stable_sort(samples.begin(), samples.end(),
                     [](const target_sample& a, const target_sample& b) { return a.t_s < b.t_s; });
  return out;
}

}  // namespace argus::report

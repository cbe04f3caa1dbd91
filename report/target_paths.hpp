#pragma once

#include <map>
#include <vector>

#include "report/csv_table.hpp"

namespace argus::report {

/// Where a task's target was at one tick and which camera observed her (targets.csv).
struct target_sample {
  double t_s = 0.0;
  double x_m = 0.0;
  double y_m = 0.0;
  bool present = false;
  /// The camera whose box counts as observing her; -1 when none does.
  int observed_by = -1;
};

/// Each task's target path, by task id, samples in time order.
using target_paths = std::map<int, std::vector<target_sample>>;

/// Reads targets.csv's columns `t,task,x,y,present,observed_by`; rows of a file without them
/// give no paths.
target_paths target_paths_from(const csv_table& targets);

}  // namespace argus::report

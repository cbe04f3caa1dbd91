#pragma once

#include <string>
#include <vector>

#include "report/html_report.hpp"
#include "report/sweep_results.hpp"

namespace argus::report {

/// sweep.html (docs/sweep.md): one self-contained page of a sweep, as report.html is of a run
/// (plots inlined, nothing fetched, the same self-check on #status): the grid; the results'
/// `compare` metric at each value with its paired comparison and its two plots, for every
/// parameter with two values or more; the paired comparison of every metric, the rows whose
/// interval leaves out zero marked; every other plot, folded; and every run.
std::string render_sweep_page(const sweep_results& results, const std::vector<report_image>& plots);

}  // namespace argus::report

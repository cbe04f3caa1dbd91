#include "report/sweep_page.hpp"

#include <algorithm>
#include <optional>

#include "fmt/format.h"
#include "report/html_report_assets.hpp"
#include "report/paired_differences.hpp"

namespace argus::report {

namespace {

std::string number_cell(const std::optional<double>& value, const char* format = "{:.4g}") {
  if (!value) return "<td>&ndash;</td>";
  return fmt::format("<td class=\"number\">{}</td>", fmt::format(fmt::runtime(format), *value));
}

std::string text_cell(const std::string& text) {
  return "<td>" + html_escape(text) + "</td>";
}

// A difference's interval shows its signs; a mean's does not.
std::string interval_cell(const mean_interval& m, bool difference) {
  if (!m.half_width) return "<td>&ndash;</td>";
  return fmt::format(fmt::runtime(difference ? "<td class=\"number\">{:+.4g} to {:+.4g}</td>"
                                             : "<td class=\"number\">{:.4g} to {:.4g}</td>"),
                     *m.low(), *m.high());
}

bool clear_of_zero(const mean_interval& m) {
  return m.half_width && (*m.low() > 0.0 || *m.high() < 0.0);
}

std::string grid_section(const sweep_results& results) {
  std::size_t done = 0;
  std::size_t failed = 0;
  for (const auto& run : results.runs) {
    done += run.exit_status ? 1 : 0;
    failed += run.exit_status && *run.exit_status != 0 ? 1 : 0;
  }
  std::string html =
      "<table>\n<tr><th>parameter</th><th>values (the first is the baseline)</th></tr>\n";
  for (const auto& p : results.parameters) {
    std::string values;
    for (const auto& v : p.values) values += (values.empty() ? "" : ", ") + html_escape(v);
    html += "<tr>" + text_cell(p.key) + "<td>" + values + "</td></tr>\n";
  }
  html += fmt::format(
      "</table>\n<p>Seeds 1 to {} at every point of the grid: {} runs, {} done, {} failed. "
      "Paired differences within {} of zero count as equal.</p>\n",
      results.seeds, results.runs.size(), done, failed, results.equal_within);
  return html;
}

// The compare metric at each value of parameter k, and each value after the first paired
// with the first.
std::string comparison_table(const sweep_results& results, std::size_t k) {
  const auto points = results.metric_points(results.compare, k);
  const auto differences = paired_differences(results, results.compare, k);
  std::string html =
      "<table>\n<tr><th>value</th><th>runs</th><th>mean</th><th>95% CI</th><th>pairs</th>"
      "<th>paired difference</th><th>95% CI</th><th>standard error</th>"
      "<th>higher / lower / equal</th><th>sign test p</th></tr>\n";
  for (std::size_t v = 0; v < points.size(); ++v) {
    const auto& m = points[v].metric;
    html += "<tr>" + text_cell(points[v].value) +
            fmt::format("<td class=\"number\">{}</td>", m.count) + number_cell(m.defined_mean()) +
            interval_cell(m, false);
    if (v == 0) {
      html += "<td colspan=\"6\">baseline</td></tr>\n";
      continue;
    }
    const auto& d = differences[v - 1];
    html += fmt::format("<td class=\"number\">{}</td>", d.difference.count) +
            number_cell(d.difference.defined_mean(), "{:+.4g}") +
            interval_cell(d.difference, true) + number_cell(d.difference.standard_error) +
            fmt::format("<td class=\"number\">{} / {} / {}</td>", d.higher, d.lower, d.equal) +
            number_cell(d.sign_test_p, "{:.3g}") + "</tr>\n";
  }
  return html + "</table>\n";
}

// Every metric's paired differences for parameter k.
std::string paired_table(const sweep_results& results, std::size_t k) {
  std::string html =
      "<div class=\"scroll\"><table>\n<tr><th>metric</th><th>value</th><th>pairs</th>"
      "<th>mean difference</th><th>95% CI</th><th>higher / lower / equal</th>"
      "<th>sign test p</th></tr>\n";
  for (const auto& metric : results.metric_names()) {
    for (const auto& d : paired_differences(results, metric, k)) {
      html += clear_of_zero(d.difference) ? "<tr class=\"clear\">" : "<tr>";
      html += text_cell(metric) + text_cell(d.value) +
              fmt::format("<td class=\"number\">{}</td>", d.difference.count) +
              number_cell(d.difference.defined_mean(), "{:+.4g}") +
              interval_cell(d.difference, true) +
              fmt::format("<td class=\"number\">{} / {} / {}</td>", d.higher, d.lower, d.equal) +
              number_cell(d.sign_test_p, "{:.3g}") + "</tr>\n";
    }
  }
  return html + "</table></div>\n";
}

std::string runs_table(const sweep_results& results) {
  std::string html = "<div class=\"scroll\"><table>\n<tr><th>run</th>";
  for (const auto& p : results.parameters) html += "<th>" + html_escape(p.key) + "</th>";
  html += "<th>seed</th><th>exit status</th><th>wall (s)</th><th>" + html_escape(results.compare) +
          "</th></tr>\n";
  for (const auto& run : results.runs) {
    html += "<tr>" + text_cell(run.id);
    for (const auto& v : run.values) html += text_cell(v);
    html += fmt::format("<td class=\"number\">{}</td>", run.seed);
    html += run.exit_status ? fmt::format("<td class=\"number\">{}</td>", *run.exit_status)
                            : std::string("<td>not done</td>");
    html += run.exit_status ? number_cell(run.wall_s, "{:.1f}") : std::string("<td></td>");
    html += number_cell(run.metric(results.compare)) + "</tr>\n";
  }
  return html + "</table></div>\n";
}

// The figures of `metric` against `key`: the pooled plot, then the paired one.
std::string figures_of(const std::vector<report_image>& plots, const std::string& metric,
                       const std::string& key) {
  const std::string pooled = metric + " vs " + key;
  std::vector<report_image> chosen;
  for (const auto& wanted : {pooled, pooled + ", paired"})
    for (const auto& p : plots)
      if (p.caption == wanted) chosen.push_back(p);
  return html_figures(chosen);
}

}  // namespace

std::string render_sweep_page(const sweep_results& results,
                              const std::vector<report_image>& plots) {
  const std::string title = "Sweep of " + results.scenario;
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>{0}</title>\n<style>{1}\ntr.clear td {{ background: #eef6ee; }}</style>\n"
      "<script>{2}</script>\n</head>\n<body>\n<h1>{0}</h1>\n"
      "<p id=\"status\" data-ready=\"no\"></p>\n",
      html_escape(title), report_style, report_error_catcher);
  html += "<h2>Grid</h2>\n" + grid_section(results);
  std::vector<std::size_t> varied;
  for (std::size_t k = 0; k < results.parameters.size(); ++k)
    if (results.parameters[k].values.size() >= 2) varied.push_back(k);
  const auto metrics = results.metric_names();
  const bool has_compare =
      std::find(metrics.begin(), metrics.end(), results.compare) != metrics.end();
  for (const auto k : varied) {
    const auto& key = results.parameters[k].key;
    html += fmt::format("<h2>{} by {}</h2>\n", html_escape(results.compare), html_escape(key));
    if (!has_compare) {
      html += "<p>No run reported this metric.</p>\n";
      continue;
    }
    html +=
        "<p>Each value's mean over its runs, and its runs paired with the baseline's of the "
        "same seed and the same other values.</p>\n" +
        comparison_table(results, k);
    html += figures_of(plots, results.compare, key);
  }
  for (const auto k : varied) {
    const auto& key = results.parameters[k].key;
    html += fmt::format(
        "<h2>Every metric by {}, paired by seed with {}</h2>\n<p>Shaded: the 95% interval of "
        "the difference leaves out zero.</p>\n",
        html_escape(key), html_escape(results.parameters[k].values.front()));
    html += paired_table(results, k);
    html += "<details><summary>Every metric's plots</summary>\n";
    for (const auto& metric : metrics)
      if (metric != results.compare) html += figures_of(plots, metric, key);
    html += "</details>\n";
  }
  html += "<h2>Runs</h2>\n" + runs_table(results);
  html += fmt::format("<script>{}</script>\n</body>\n</html>\n", report_script);
  return html;
}

}  // namespace argus::report

#include "report/sweep_outputs.hpp"

#include <algorithm>
#include <optional>

#include "fmt/format.h"
#include "report/binary_file.hpp"
#include "report/paired_differences.hpp"
#include "report/sweep_page.hpp"

namespace argus::report {

namespace {

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number_text(const nlohmann::json& value) {
  if (value.is_number_integer() || value.is_number_unsigned()) return value.dump();
  if (value.is_number()) return fmt::format("{}", value.get<double>());
  return {};
}

// A file name from a metric or key: anything but letters, digits, '.', '-' and '_' becomes '_'.
std::string file_name_part(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_') c = '_';
  return out;
}

nlohmann::json number_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

std::string optional_text(const std::optional<double>& value) {
  return value ? fmt::format("{}", *value) : std::string{};
}

// The parameters a paired comparison exists for: those with two values or more.
bool compared(const swept_parameter& parameter) {
  return parameter.values.size() >= 2;
}

}  // namespace

std::string paired_csv(const sweep_results& results) {
  std::string csv =
      "metric,parameter,value,baseline,pairs,mean_difference,standard_error,ci95_low,ci95_high,"
      "higher,lower,equal,equal_within,sign_test_p\n";
  for (const auto& metric : results.metric_names()) {
    for (std::size_t k = 0; k < results.parameters.size(); ++k) {
      if (!compared(results.parameters[k])) continue;
      for (const auto& d : paired_differences(results, metric, k)) {
        csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", csv_field(metric),
                           csv_field(results.parameters[k].key), csv_field(d.value),
                           csv_field(d.baseline), d.difference.count,
                           optional_text(d.difference.defined_mean()),
                           optional_text(d.difference.standard_error),
                           optional_text(d.difference.low()), optional_text(d.difference.high()),
                           d.higher, d.lower, d.equal, results.equal_within, d.sign_test_p);
      }
    }
  }
  return csv;
}

std::string sweep_csv(const sweep_results& results) {
  const auto metrics = results.metric_names();
  std::string csv = "run";
  for (const auto& p : results.parameters) (csv += ',') += csv_field(p.key);
  csv += ",seed,exit_status,wall_s";
  for (const auto& m : metrics) (csv += ',') += csv_field(m);
  csv += '\n';
  for (const auto& run : results.runs) {
    csv += csv_field(run.id);
    for (const auto& v : run.values) (csv += ',') += csv_field(v);
    csv += fmt::format(",{},{},{}", run.seed,
                       run.exit_status ? std::to_string(*run.exit_status) : std::string{},
                       run.exit_status ? fmt::format("{:.3f}", run.wall_s) : std::string{});
    for (const auto& m : metrics) {
      csv += ',';
      if (run.summary.is_object())
        if (auto it = run.summary.find(m); it != run.summary.end()) csv += number_text(*it);
    }
    csv += '\n';
  }
  return csv;
}

nlohmann::json sweep_json(const sweep_results& results) {
  nlohmann::json j;
  j["scenario"] = results.scenario;
  j["seeds"] = results.seeds;
  j["parameters"] = nlohmann::json::array();
  for (const auto& p : results.parameters)
    j["parameters"].push_back({{"key", p.key}, {"values", p.values}});
  j["runs"] = nlohmann::json::array();
  for (const auto& run : results.runs) {
    nlohmann::json r{{"run", run.id}, {"seed", run.seed}, {"summary", run.summary}};
    r["values"] = nlohmann::json::object();
    for (std::size_t k = 0; k < results.parameters.size(); ++k)
      r["values"][results.parameters[k].key] = run.values.at(k);
    r["exit_status"] = run.exit_status ? nlohmann::json(*run.exit_status) : nlohmann::json();
    r["wall_s"] = run.exit_status ? nlohmann::json(run.wall_s) : nlohmann::json();
    j["runs"].push_back(std::move(r));
  }
  auto& statistics = j["statistics"] = nlohmann::json::object();
  for (const auto& metric : results.metric_names()) {
    for (std::size_t k = 0; k < results.parameters.size(); ++k) {
      auto& rows = statistics[metric][results.parameters[k].key] = nlohmann::json::array();
      for (const auto& point : results.metric_points(metric, k)) {
        nlohmann::json row{{"value", point.value}, {"n", point.metric.count}};
        row["mean"] = number_or_null(point.metric.defined_mean());
        row["ci95_low"] = number_or_null(point.metric.low());
        row["ci95_high"] = number_or_null(point.metric.high());
        rows.push_back(std::move(row));
      }
    }
  }
  auto& paired = j["paired"] = nlohmann::json::object();
  for (const auto& metric : results.metric_names()) {
    for (std::size_t k = 0; k < results.parameters.size(); ++k) {
      if (!compared(results.parameters[k])) continue;
      auto& rows = paired[metric][results.parameters[k].key] = nlohmann::json::array();
      for (const auto& d : paired_differences(results, metric, k)) {
        rows.push_back({{"value", d.value},
                        {"baseline", d.baseline},
                        {"pairs", d.difference.count},
                        {"mean_difference", number_or_null(d.difference.defined_mean())},
                        {"standard_error", number_or_null(d.difference.standard_error)},
                        {"ci95_low", number_or_null(d.difference.low())},
                        {"ci95_high", number_or_null(d.difference.high())},
                        {"higher", d.higher},
                        {"lower", d.lower},
                        {"equal", d.equal},
                        {"equal_within", results.equal_within},
                        {"sign_test_p", d.sign_test_p}});
      }
    }
  }
  return j;
}

std::vector<std::filesystem::path> write_sweep_outputs(const std::filesystem::path& dir,
                                                       const sweep_results& results) {
  std::vector<std::filesystem::path> written;
  write_file(dir / "sweep.csv", sweep_csv(results));
  written.push_back(dir / "sweep.csv");
  write_file(dir / "sweep.json", sweep_json(results).dump(2) + "\n");
  written.push_back(dir / "sweep.json");
  write_file(dir / "paired.csv", paired_csv(results));
  written.push_back(dir / "paired.csv");
  std::vector<report_image> plots;
  auto add_plot = [&](std::string file, std::string caption, std::vector<unsigned char> png) {
    std::filesystem::create_directories(dir / "plots");
    write_file(dir / "plots" / file, png);
    written.push_back(dir / "plots" / file);
    plots.push_back({"plots/" + file, std::move(caption), std::move(png), {}});
  };
  for (const auto& metric : results.metric_names()) {
    for (std::size_t k = 0; k < results.parameters.size(); ++k) {
      const auto& parameter = results.parameters[k];
      if (!compared(parameter)) continue;
      const auto points = results.metric_points(metric, k);
      if (std::none_of(points.begin(), points.end(),
                       [](const metric_point& p) { return p.metric.count > 0; }))
        continue;  // null in every run (undefined, e.g. a ratio to zero): nothing to draw
      const auto name = file_name_part(metric) + "_vs_" + file_name_part(parameter.key);
      add_plot(name + ".png", metric + " vs " + parameter.key,
               render_metric_plot(fmt::format("{} vs {} (mean, 95% CI)", metric, parameter.key),
                                  parameter.key, points));
      // The same against the baseline, run by run: the baseline at 0, each other value at its
      // mean paired difference.
      std::vector<metric_point> paired_points{{parameter.values.front(), {}}};
      for (const auto& d : paired_differences(results, metric, k)) {
        paired_points.push_back({d.value, d.difference});
        paired_points.front().metric.count =
            std::max(paired_points.front().metric.count, d.difference.count);
      }
      if (paired_points.front().metric.count == 0) continue;
      add_plot(name + "_paired.png", metric + " vs " + parameter.key + ", paired",
               render_metric_plot(fmt::format("{} minus at {}, paired by seed (mean, 95% CI)",
                                              metric, parameter.values.front()),
                                  parameter.key, paired_points));
    }
  }
  write_file(dir / "sweep.html", render_sweep_page(results, plots));
  written.push_back(dir / "sweep.html");
  return written;
}

}  // namespace argus::report

#include "report/sweep_outputs.hpp"

#include <algorithm>

#include "fmt/format.h"
#include "report/binary_file.hpp"

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

}  // namespace

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
        row["mean"] = point.metric.count > 0 ? nlohmann::json(point.metric.mean) : nlohmann::json();
        if (point.metric.half_width) {
          row["ci95_low"] = point.metric.mean - *point.metric.half_width;
          row["ci95_high"] = point.metric.mean + *point.metric.half_width;
        } else {
          row["ci95_low"] = nullptr;
          row["ci95_high"] = nullptr;
        }
        rows.push_back(std::move(row));
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
  const auto plots = dir / "plots";
  for (const auto& metric : results.metric_names()) {
    for (std::size_t k = 0; k < results.parameters.size(); ++k) {
      const auto& parameter = results.parameters[k];
      if (parameter.values.size() < 2) continue;
      const auto points = results.metric_points(metric, k);
      if (std::none_of(points.begin(), points.end(),
                       [](const metric_point& p) { return p.metric.count > 0; }))
        continue;  // null in every run (undefined, e.g. a ratio to zero): nothing to draw
      std::filesystem::create_directories(plots);
      const auto file =
          plots / (file_name_part(metric) + "_vs_" + file_name_part(parameter.key) + ".png");
      write_file(file, render_metric_plot(metric, parameter.key, points));
      written.push_back(file);
    }
  }
  return written;
}

}  // namespace argus::report

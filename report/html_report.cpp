#include "report/html_report.hpp"

#include <algorithm>
#include <set>

#include "fmt/format.h"
#include "report/base64.hpp"
#include "report/html_report_assets.hpp"

namespace argus::report {

namespace {

// A table cell for one JSON value: numbers right-aligned, nested values summarised.
std::string cell(const nlohmann::json& value) {
  if (value.is_null()) return "<td>&ndash;</td>";
  if (value.is_number_float())
    return fmt::format("<td class=\"number\">{:.4g}</td>", value.get<double>());
  if (value.is_number()) return fmt::format("<td class=\"number\">{}</td>", value.dump());
  if (value.is_string()) return "<td>" + html_escape(value.get<std::string>()) + "</td>";
  if (value.is_array())
    return fmt::format("<td>{} {}</td>", value.size(), value.size() == 1 ? "entry" : "entries");
  return "<td>" + html_escape(value.dump()) + "</td>";
}

// Columns of a list of objects: every key, nested objects one level deep ("group_size.mean"),
// the naming keys first, then in order of first appearance.
std::vector<std::pair<std::string, std::string>> columns_of(const nlohmann::json& rows) {
  std::vector<std::pair<std::string, std::string>> out;
  std::set<std::string> seen;
  // What names a row comes first; JSON objects arrive with their keys sorted.
  for (const char* key : {"task", "pedestrian", "camera"})
    for (const auto& row : rows)
      if (row.is_object() && row.contains(key) && seen.insert(key).second)
        out.emplace_back(key, "");
  for (const auto& row : rows) {
    if (!row.is_object()) continue;
    for (const auto& [key, value] : row.items()) {
      if (value.is_object()) {
        for (const auto& [inner, inner_value] : value.items())
          if (!inner_value.is_structured() && seen.insert(key + "." + inner).second)
            out.emplace_back(key, inner);
      } else if (seen.insert(key).second) {
        out.emplace_back(key, "");
      }
    }
  }
  return out;
}

std::string list_table(const nlohmann::json& rows) {
  const auto columns = columns_of(rows);
  std::string html = "<div class=\"scroll\"><table><tr>";
  for (const auto& [key, inner] : columns)
    html += "<th>" + html_escape(inner.empty() ? key : key + "." + inner) + "</th>";
  html += "</tr>\n";
  for (const auto& row : rows) {
    if (!row.is_object()) continue;
    html += "<tr>";
    for (const auto& [key, inner] : columns) {
      const auto it = row.find(key);
      if (it == row.end()) {
        html += "<td></td>";
      } else if (inner.empty()) {
        html += cell(*it);
      } else {
        const auto nested = it->is_object() ? it->find(inner) : it->end();
        html += it->is_object() && nested != it->end() ? cell(*nested) : "<td></td>";
      }
    }
    html += "</tr>\n";
  }
  return html + "</table></div>\n";
}

std::string key_value_table(const nlohmann::json& object) {
  std::string html = "<table>\n";
  for (const auto& [key, value] : object.items())
    if (!value.is_structured() || value.is_array())
      html += "<tr><th>" + html_escape(key) + "</th>" + cell(value) + "</tr>\n";
  return html + "</table>\n";
}

std::string metrics_section(const nlohmann::json& metrics) {
  if (!metrics.is_object()) return "<p>No metrics.json in this run's folder.</p>\n";
  std::string html;
  if (auto summary = metrics.find("summary"); summary != metrics.end() && summary->is_object())
    html += "<h3>Summary</h3>\n" + key_value_table(*summary);
  if (auto tasks = metrics.find("tasks");
      tasks != metrics.end() && tasks->is_array() && !tasks->empty())
    html += "<h3>Per task</h3>\n" + list_table(*tasks);
  return html;
}

// The event log as JSON inside a script element. '<' is written as \u003c so that no string
// in it can close the element.
std::string embedded_events(const event_log& log, std::size_t most) {
  const auto end =
      log.events.begin() + static_cast<std::ptrdiff_t>(std::min(most, log.events.size()));
  const std::string json =
      nlohmann::json(std::vector<nlohmann::json>(log.events.begin(), end)).dump();
  std::string out;
  out.reserve(json.size());
  for (char c : json) {
    if (c == '<')
      out += "\\u003c";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string html_figures(const std::vector<report_image>& images) {
  std::string html;
  for (const auto& image : images) {
    html += fmt::format(
        "<figure><img src=\"data:image/png;base64,{}\" alt=\"{}\"><figcaption>{}: {}"
        "</figcaption>",
        base64(image.png), html_escape(image.caption), html_escape(image.file),
        html_escape(image.caption));
    if (!image.details.empty()) {
      html += fmt::format("<details><summary>{} {}</summary><ol>", image.details.size(),
                          image.details.size() == 1 ? "frame" : "frames");
      for (const auto& line : image.details) html += "<li>" + html_escape(line) + "</li>";
      html += "</ol></details>";
    }
    html += "</figure>\n";
  }
  return html;
}

std::string render_html_report(const html_report_input& input) {
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>{0}</title>\n<style>{1}</style>\n<script>{2}</script>\n</head>\n<body>\n"
      "<h1>{0}</h1>\n<p id=\"status\" data-ready=\"no\"></p>\n",
      html_escape(input.title), report_style, report_error_catcher);
  if (input.run_summary.is_object()) html += "<h2>Run</h2>\n" + key_value_table(input.run_summary);
  html += "<h2>Metrics</h2>\n" + metrics_section(input.metrics);
  if (!input.images.empty()) html += "<h2>Pictures</h2>\n" + html_figures(input.images);
  html += "<h2>Event log</h2>\n";
  if (input.events != nullptr) {
    if (input.events->events.size() > input.max_events)
      html += fmt::format(
          "<p>The page holds the first {} of the run's {} events; events.jsonl has them all.</p>\n",
          input.max_events, input.events->events.size());
    html +=
        "<div id=\"log-controls\"><select id=\"log-kind\"><option value=\"\">every kind"
        "</option></select> <input id=\"log-text\" type=\"search\" "
        "placeholder=\"filter: words that must all appear, e.g. camera&quot;:7\"> "
        "<span id=\"log-count\"></span></div>\n"
        "<div class=\"scroll\"><table id=\"log\"><thead><tr><th>t (s)</th><th>tick</th>"
        "<th>source</th><th>kind</th><th>details</th></tr></thead><tbody id=\"log-body\">"
        "</tbody></table></div>\n<script type=\"application/json\" id=\"events-data\">" +
        embedded_events(*input.events, input.max_events) + "</script>\n";
  } else {
    html += "<p>No events.jsonl in this run's folder.</p>\n";
  }
  html += fmt::format("<script>{}</script>\n</body>\n</html>\n", report_script);
  return html;
}

}  // namespace argus::report

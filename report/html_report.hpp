#pragma once

#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "report/event_log.hpp"

namespace argus::report {

/// A picture of the report, inlined into the page.
struct report_image {
  /// The file it was written to (plan.png), shown under it.
  std::string file;
  std::string caption;
  std::vector<unsigned char> png;
  /// Lines listed under the picture, folded (a contact sheet's frame captions); none: no list.
  std::vector<std::string> details;
};

/// What report.html shows; every part is optional and left out when absent.
struct html_report_input {
  std::string title;
  std::vector<report_image> images;
  /// metrics.json: its "summary" object and "tasks" list become tables; null when absent.
  nlohmann::json metrics;
  /// summary.json: the run's own figures (ticks, wall time, speed); null when absent.
  nlohmann::json run_summary;
  /// events.jsonl, for the searchable log; null when absent.
  const event_log* events = nullptr;
  /// The most events the page embeds: a run of thousands of cameras logs millions, and a page
  /// of that size would not open. The page says when it holds fewer than the log.
  std::size_t max_events = 200000;
};

/// report.html: one self-contained page (images as base64 `data:` URIs, the event log as
/// embedded JSON, plain JavaScript, nothing fetched) with the pictures, the metrics tables and
/// an event log filtered by kind and by text. Once loaded, the page checks its own images and
/// records the outcome on `#status` (data-ready, data-images, data-broken, data-errors), which
/// the browser test reads.
std::string render_html_report(const html_report_input& input);

/// Each image as a <figure>, inlined (base64 `data:` URI), captioned "file: caption", its
/// details folded beneath it: report.html's pictures, and sweep.html's plots.
std::string html_figures(const std::vector<report_image>& images);

/// `text` with &, <, >, " and ' escaped for HTML.
std::string html_escape(const std::string& text);

}  // namespace argus::report

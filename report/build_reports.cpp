#include "report/build_reports.hpp"

#include <fstream>
#include <optional>

#include "config/scenario_error.hpp"
#include "config/scenario_loader.hpp"
#include "fmt/format.h"
#include "report/binary_file.hpp"
#include "report/event_log.hpp"
#include "report/group_timeline.hpp"
#include "report/html_report.hpp"
#include "report/key_frame_feeds.hpp"
#include "report/plan_report.hpp"
#include "report/target_paths.hpp"
#include "report/timeline_report.hpp"
#include "world/field_cache.hpp"
#include "world/layout_loader.hpp"
#include "world/station.hpp"

namespace argus::report {

namespace {

// The run's length: metrics.json's duration, else summary.json's simulated seconds; 0 when
// neither says (the timeline then ends at the last event).
double run_length_s(const nlohmann::json& metrics, const nlohmann::json& summary) {
  if (metrics.is_object() && metrics.contains("duration_s") && metrics["duration_s"].is_number())
    return metrics["duration_s"].get<double>();
  if (summary.is_object() && summary.contains("virtual_seconds") &&
      summary["virtual_seconds"].is_number())
    return summary["virtual_seconds"].get<double>();
  return 0.0;
}

std::string title_of(const std::filesystem::path& dir, const nlohmann::json& metrics,
                     const nlohmann::json& summary) {
  const nlohmann::json& named = metrics.is_object() ? metrics : summary;
  if (!named.is_object() || !named.contains("scenario")) return "argus run " + dir.string();
  std::string title = fmt::format("argus run: {}", named["scenario"].is_string()
                                                       ? named["scenario"].get<std::string>()
                                                       : named["scenario"].dump());
  if (named.contains("seed")) title += fmt::format(", seed {}", named["seed"].dump());
  if (metrics.is_object() && metrics.contains("strategy") && metrics["strategy"].is_string())
    title += ", strategy " + metrics["strategy"].get<std::string>();
  return title;
}

class report_builder {
 public:
  explicit report_builder(std::filesystem::path dir) : dir_(std::move(dir)) {}

  // The run's scenario and station, for the plan and the feeds; what is missing is said once
  // for each of them.
  void load_scenario(const config::scenario* given, const report_options& options) {
    const bool feeds = options.feeds;
    const auto leave_out = [&](const std::string& why) {
      outcome_.left_out.push_back(fmt::format("plan.png ({})", why));
      if (feeds) outcome_.left_out.push_back(fmt::format("feeds/ ({})", why));
    };
    if (given == nullptr) {
      const auto file = dir_ / "scenario.yaml";
      if (!std::filesystem::exists(file)) {
        leave_out("no scenario.yaml in the folder; give --scenario");
        return;
      }
      try {
        loaded_ = config::load_scenario(file);
      } catch (const config::scenario_error& e) {
        leave_out(e.what());
        return;
      }
      given = &*loaded_;
    }
    try {
      // The feeds' key frames walk the crowd again, so the fields are needed: after a run they
      // are in the field cache it has just filled, and read back instead of computed again.
      world::navigation_settings settings;
      settings.field_cache = world::field_cache::default_dir_or_none();
      station_ = options.station ? options.station
                                 : world::station::load(world::layout_path(*given), settings);
    } catch (const std::exception& e) {
      leave_out(fmt::format("station layout: {}", e.what()));
      return;
    }
    scenario_ = given;
  }

  void plan() {
    if (scenario_ == nullptr) return;
    target_paths paths;
    if (auto targets = csv_table::read(dir_ / "targets.csv"))
      paths = target_paths_from(*targets);
    else
      outcome_.left_out.push_back("target paths on plan.png (no targets.csv)");
    add_image("plan.png", "the targets' paths, coloured by the camera observing them",
              render_plan_report(*station_, scenario_->cameras, paths));
  }

  void feeds(const std::optional<event_log>& events) {
    // Whatever is drawn now, an earlier drawing's frames are not this one's.
    std::filesystem::remove_all(dir_ / "feeds");
    if (scenario_ == nullptr) return;  // said by load_scenario
    if (!events) {
      outcome_.left_out.push_back("feeds/ (no events.jsonl)");
      return;
    }
    auto drawn = write_feeds(dir_, *scenario_, station_, *events);
    for (auto& file : drawn.written) outcome_.written.push_back(std::move(file));
    for (auto& note : drawn.left_out) outcome_.left_out.push_back(std::move(note));
    if (drawn.sheet) images_.push_back(std::move(*drawn.sheet));
  }

  void timeline(const std::optional<event_log>& events, double length_s) {
    if (!events) {
      outcome_.left_out.push_back("timeline.png (no events.jsonl)");
      return;
    }
    add_image("timeline.png", "task groups, leaders and failures over time",
              render_timeline(group_timeline::from(*events, length_s)));
  }

  void page(html_report_input input) {
    input.images = std::move(images_);
    const auto file = dir_ / "report.html";
    write_file(file, render_html_report(input));
    outcome_.written.push_back(file);
  }

  report_outcome take() { return std::move(outcome_); }

 private:
  void add_image(std::string name, std::string caption, std::vector<unsigned char> png) {
    const auto file = dir_ / name;
    write_file(file, png);
    outcome_.written.push_back(file);
    images_.push_back({std::move(name), std::move(caption), std::move(png), {}});
  }

  std::filesystem::path dir_;
  std::optional<config::scenario> loaded_;
  const config::scenario* scenario_ = nullptr;
  std::shared_ptr<const world::station> station_;
  std::vector<report_image> images_;
  report_outcome outcome_;
};

}  // namespace

report_outcome build_reports(const std::filesystem::path& dir, const config::scenario* scenario,
                             const report_options& options) {
  if (!std::filesystem::is_directory(dir))
    throw std::runtime_error(fmt::format("{}: not a folder", dir.string()));
  const auto metrics = read_json(dir / "metrics.json");
  const auto summary = read_json(dir / "summary.json");
  const auto events = event_log::read(dir / "events.jsonl");
  report_builder builder(dir);
  builder.load_scenario(scenario, options);
  builder.plan();
  builder.timeline(events, run_length_s(metrics, summary));
  if (options.feeds) builder.feeds(events);
  html_report_input input;
  input.title = title_of(dir, metrics, summary);
  input.metrics = metrics;
  input.run_summary = summary;
  input.events = events ? &*events : nullptr;
  builder.page(std::move(input));
  return builder.take();
}

}  // namespace argus::report

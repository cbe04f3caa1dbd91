#include "apps/run_record.hpp"

#include <iostream>

#include "actors/run_scenario.hpp"
#include "config/scenario_writer.hpp"
#include "report/binary_file.hpp"
#include "report/build_reports.hpp"
#include "world/layout_loader.hpp"

namespace argus::apps {

namespace {

// The scenario as its copy in the output folder must say it: relative paths were relative to
// the original file's folder.
config::scenario with_absolute_paths(config::scenario s) {
  if (!s.world.layout.empty())
    s.world.layout = std::filesystem::absolute(world::layout_path(s)).lexically_normal().string();
  if (!s.sensing.sensor_model.empty())
    s.sensing.sensor_model =
        std::filesystem::absolute(actors::sensor_model_path(s)).lexically_normal().string();
  return s;
}

}  // namespace

std::optional<std::filesystem::path> record_run(const config::scenario& scenario,
                                                const std::filesystem::path& output_dir, bool feeds,
                                                std::shared_ptr<const world::station> station) {
  try {
    const auto copy = with_absolute_paths(scenario);
    report::write_file(output_dir / "scenario.yaml", config::to_yaml(copy));
    if (!feeds) std::filesystem::remove_all(output_dir / "feeds");
    report::report_options options;
    options.feeds = feeds;
    options.station = std::move(station);
    const auto outcome = report::build_reports(output_dir, &copy, options);
    // The key frames a user would look for and does not find are said; a run with no key event
    // simply has none.
    for (const auto& note : outcome.left_out)
      if (note.starts_with("feeds/") && !note.starts_with("feeds/ (no key event"))
        std::cerr << "argus run: left out " << note << '\n';
    return output_dir / "report.html";
  } catch (const std::exception& e) {
    std::cerr << "argus run: reports not written: " << e.what() << '\n';
    return std::nullopt;
  }
}

}  // namespace argus::apps

#pragma once
// A standard pedestrian-dynamics experiment for the tests and benchmarks: a scenario of
// scenarios/validation (or a layout built in code with flows), its crowd stepped tick by tick
// without cameras, with a look at every frame.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "config/scenario_loader.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world::testing {

/// scenarios/validation/`name`.
inline std::filesystem::path validation_scenario(const std::string& name) {
  return std::filesystem::path{ARGUS_SOURCE_DIR} / "scenarios" / "validation" / name;
}

/// A crowd to step: from a scenario file, or from a station and settings built in code.
class experiment {
 public:
  /// Loads `file` (and its layout); `edit` may change the scenario before the crowd is built.
  explicit experiment(const std::filesystem::path& file,
                      const std::function<void(config::scenario&)>& edit = {}) {
    scenario_ = config::load_scenario(file);
    if (edit) edit(scenario_);
    station_ = station::load(layout_path(scenario_));
    crowd_ = std::make_unique<crowd>(station_, crowd_settings::from(scenario_));
  }

  /// A crowd of `settings` in `plan`.
  experiment(layout plan, const crowd_settings& settings)
      : station_(std::make_shared<const station>(std::move(plan))),
        crowd_(std::make_unique<crowd>(station_, settings)) {
    // nop
  }

  /// Steps until `seconds` of virtual time have passed or, when `until_empty`, everyone who
  /// came has left; calls `look(previous, current)` after every tick. Returns the time.
  double run(double seconds, const std::function<void(const snapshot&, const snapshot&)>& look = {},
             bool until_empty = true) {
    while (crowd_->current()->time().count() < seconds) {
      const auto before = crowd_->current();
      crowd_->step();
      if (look) look(*before, *crowd_->current());
      if (until_empty && crowd_->current()->pedestrians().empty() &&
          crowd_->current()->tick() > 2) {
        break;
      }
    }
    return crowd_->current()->time().count();
  }

  const station& where() const { return *station_; }
  const crowd& people() const { return *crowd_; }
  const config::scenario& scenario() const { return scenario_; }

 private:
  config::scenario scenario_;
  std::shared_ptr<const station> station_;
  std::unique_ptr<crowd> crowd_;
};

/// Times at which pedestrians crossed the vertical line x = `x_m` eastwards.
class line_counter {
 public:
  explicit line_counter(double x_m) : x_m_(x_m) {
    // nop
  }
  void look(const snapshot& before, const snapshot& after) {
    for (const auto& p : after.pedestrians()) {
      const auto* was = before.find(p.id);
      if (was != nullptr && was->position.x() < x_m_ && p.position.x() >= x_m_) {
        times_s_.push_back(after.time().count());
      }
    }
  }
  const std::vector<double>& times_s() const { return times_s_; }
  /// Persons per second between the crossings of the first and the last `fraction` of them
  /// (the steady phase, without the start and the tail).
  double flow_per_s(double fraction = 0.1) const {
    if (times_s_.size() < 10) return 0.0;
    const auto first = static_cast<std::size_t>(fraction * times_s_.size());
    const auto last = times_s_.size() - 1 - first;
    const double span = times_s_[last] - times_s_[first];
    return span > 0.0 ? static_cast<double>(last - first) / span : 0.0;
  }

 private:
  double x_m_;
  std::vector<double> times_s_;
};

}  // namespace argus::world::testing

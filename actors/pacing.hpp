#pragma once

#include <atomic>
#include <cstdint>

namespace argus::actors {

/// The operator's pacing of a live run: its speed (virtual over wall seconds; 0 = as fast as
/// it goes) and whether it is paused. The server sets it; the clock reads it between ticks.
/// Pacing only ever delays the next tick: it never enters the simulation or its log.
class pacing {
 public:
  /// Starts at `speed`, running.
  explicit pacing(double speed = 1.0) : speed_(speed) {}

  /// Sets the speed (>= 0); the clock measures the new pace from the tick it reads it at.
  void speed(double ratio) {
    speed_.store(ratio);
    ++generation_;
  }
  /// The speed asked for.
  double speed() const noexcept { return speed_.load(); }

  /// Pauses (true) or resumes (false) the run between two ticks.
  void paused(bool on) {
    paused_.store(on);
    ++generation_;
  }
  /// Whether the run is paused.
  bool paused() const noexcept { return paused_.load(); }

  /// Changes with every setting, so the clock knows to measure its pace anew.
  std::uint64_t generation() const noexcept { return generation_.load(); }

 private:
  std::atomic<double> speed_;
  std::atomic<bool> paused_{false};
  std::atomic<std::uint64_t> generation_{0};
};

}  // namespace argus::actors

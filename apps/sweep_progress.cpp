#include "apps/sweep_progress.hpp"

#include <cmath>
#include <iostream>

#include "fmt/format.h"

namespace argus::apps {

namespace {

std::string duration_text(double s) {
  if (s < 90.0) return fmt::format("{:.0f} s", s);
  if (s < 5400.0)
    return fmt::format("{:.0f} min {:02.0f} s", std::floor(s / 60.0), std::fmod(s, 60.0));
  return fmt::format("{:.1f} h", s / 3600.0);
}

}  // namespace

sweep_progress::sweep_progress(std::size_t total, std::size_t done_before, bool terminal)
    : total_(total), done_(done_before), terminal_(terminal) {
  if (done_before > 0)
    std::cerr << fmt::format("argus sweep: {} of {} runs already done, not redone\n", done_before,
                             total);
  if (terminal_) std::cerr << bar() << std::flush;
}

std::string sweep_progress::bar() const {
  constexpr std::size_t width = 30;
  const std::size_t filled = total_ == 0 ? width : width * done_ / total_;
  std::string text(1, '[');
  text.append(filled, '#').append(width - filled, '.').append("] ");
  text += fmt::format("{}/{} runs", done_, total_);
  if (failed_ > 0) text += fmt::format(", {} failed", failed_);
  if (done_now_ > 0 && done_ < total_) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    text += ", ETA " + duration_text(elapsed / static_cast<double>(done_now_) *
                                     static_cast<double>(total_ - done_));
  }
  return text;
}

void sweep_progress::run_ended(const std::string& id, int exit_status, double wall_s) {
  ++done_;
  ++done_now_;
  if (exit_status != 0) ++failed_;
  if (terminal_) {
    if (exit_status != 0)
      std::cerr << fmt::format("\r\033[Krun {} failed (exit {}), see its stderr.txt\n", id,
                               exit_status);
    std::cerr << "\r\033[K" << bar() << std::flush;
  } else {
    std::cerr << fmt::format("{} {}: exit {} in {:.1f} s\n", bar(), id, exit_status, wall_s);
  }
}

void sweep_progress::finish() {
  if (terminal_) std::cerr << '\n';
}

}  // namespace argus::apps

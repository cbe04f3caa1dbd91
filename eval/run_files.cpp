#include "eval/run_files.hpp"

#include <ostream>

#include "config/whole_file.hpp"
#include "fmt/format.h"
#include "fmt/ostream.h"

namespace argus::eval {

using config::write_whole_file;

namespace {

std::string_view name_of(frame_state s) {
  switch (s) {
    case frame_state::idle:
      return "idle";
    case frame_state::computing_relevance:
      return "computing_relevance";
    case frame_state::performing_task:
      return "performing_task";
  }
  return "idle";
}

std::string percent(double v) {
  return fmt::format("{:5.1f}%", 100.0 * v);
}

}  // namespace

void write_tracks(const std::filesystem::path& path, const observation_log::contents& log,
                  double tick_s) {
  write_whole_file(path, [&](std::ostream& out) {
    out << "tick,t,camera,task,role,found,x,y,w,h,score,truth,iou,observed\n";
    // In tick order, cameras by id within a tick.
    std::map<std::int64_t, std::vector<const camera_frame*>> by_tick;
    for (const auto& [camera, frames] : log.frames)
      for (const auto& f : frames)
        if (!f.looks.empty()) by_tick[f.tick].push_back(&f);
    for (const auto& [tick, frames] : by_tick)
      for (const auto* f : frames)
        for (const auto& l : f->looks)
          fmt::print(out, "{},{:.6f},{},{},{},{},{:.1f},{:.1f},{:.1f},{:.1f},{:.4f},{},{:.4f},{}\n",
                     tick, tick * tick_s, f->camera, l.task, l.leader ? "leader" : "member",
                     l.found ? 1 : 0, l.box.x, l.box.y, l.box.width, l.box.height, l.score, l.truth,
                     l.iou, l.observed ? 1 : 0);
  });
}

void write_targets(const std::filesystem::path& path, const evaluation& result, double tick_s) {
  write_whole_file(path, [&](std::ostream& out) {
    out << "tick,t,task,pedestrian,x,y,present,reachable,observed_by\n";
    for (const auto& r : result.targets) {
      const auto& s = r.sample;
      fmt::print(out, "{},{:.6f},{},{},{:.3f},{:.3f},{},{},{}\n", s.tick, s.tick * tick_s, s.task,
                 s.pedestrian, s.x_m, s.y_m, s.present ? 1 : 0, r.reachable ? 1 : 0, r.observed_by);
    }
  });
}

void write_poses(const std::filesystem::path& path, const observation_log::contents& log,
                 double tick_s) {
  write_whole_file(path, [&](std::ostream& out) {
    out << "tick,t,camera,pan,tilt,fov,state\n";
    struct row {
      std::int64_t tick;
      int camera;
      std::string text;
    };
    std::vector<row> rows;
    for (const auto& [camera, frames] : log.frames) {
      const camera_frame* last = nullptr;
      for (const auto& f : frames) {
        if (last && f.tick > last->tick + 1)
          rows.push_back({last->tick + 1, camera,
                          fmt::format("{:.3f},{:.3f},{:.3f},down", last->pose.pan_deg,
                                      last->pose.tilt_deg, last->pose.field_of_view_deg)});
        const bool changed =
            !last || f.tick > last->tick + 1 || !(f.pose == last->pose) || f.state != last->state;
        if (changed)
          rows.push_back({f.tick, camera,
                          fmt::format("{:.3f},{:.3f},{:.3f},{}", f.pose.pan_deg, f.pose.tilt_deg,
                                      f.pose.field_of_view_deg, name_of(f.state))});
        last = &f;
      }
    }
    std::stable_sort(rows.begin(), rows.end(), [](const row& a, const row& b) {
      return std::tie(a.tick, a.camera) < std::tie(b.tick, b.camera);
    });
    for (const auto& r : rows)
      fmt::print(out, "{},{:.6f},{},{}\n", r.tick, r.tick * tick_s, r.camera, r.text);
  });
}

void print_metrics_table(std::ostream& out, const evaluation& result) {
  if (result.tasks.empty()) return;
  fmt::print(out, "{:>4} {:>6} {:>6} {:>9} {:>9} {:>7} {:>9} {:>8} {:>8} {:>7} {:>6}\n", "task",
             "target", "in_s", "coverage", "oracle", "of_orc", "identity", "handoffs", "switches",
             "leaders", "csp");
  for (const auto& m : result.tasks)
    fmt::print(out, "{:>4} {:>6} {:>6.1f} {:>9} {:>9} {:>7} {:>9} {:>8} {:>8} {:>7} {:>6}\n",
               m.task, m.pedestrian, m.time_in_station_s, percent(m.coverage),
               percent(m.oracle_bound),
               m.coverage_of_oracle ? percent(*m.coverage_of_oracle) : std::string("-"),
               m.correct_identity ? percent(*m.correct_identity) : std::string("-"),
               m.observation_handoffs, m.identity_switches, m.leader_changes, m.csp_invocations);
  // Where the rest of her time went (docs/metrics.md, `uncovered`).
  for (const auto& m : result.tasks) {
    const auto& u = m.uncovered;
    fmt::print(out,
               "task {} not covered: {:.1f}% on someone else, {:.1f}% on background, {:.1f}% "
               "lost, {:.1f}% with no camera, {:.1f}% beside her\n",
               m.task, 100.0 * u.other_person, 100.0 * u.background, 100.0 * u.lost,
               100.0 * u.no_camera, 100.0 * u.off_her);
  }
}

}  // namespace argus::eval

#include "world/trajectory_writer.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <iterator>
#include <string>

#include "world/snapshot.hpp"

namespace argus::world {

trajectory_writer::trajectory_writer(std::ostream& out) : out_(out) {
  out_ << "tick,t,id,x,y,vx,vy,heading,activity\n";
}

void trajectory_writer::write(const snapshot& frame) {
  std::string buffer;
  // Compiled: the format string parsed once, not per row; the same text, in about 0.6 of the
  // time (10,000 rows a tick in the large station).
  for (const auto& p : frame.pedestrians()) {
    fmt::format_to(std::back_inserter(buffer), FMT_COMPILE("{},{},{},{},{},{},{},{},{}\n"),
                   frame.tick(), frame.time().count(), p.id, p.position.x(), p.position.y(),
                   p.velocity.x(), p.velocity.y(), p.heading_rad(), to_string(p.doing));
  }
  out_ << buffer;
}

void trail_recorder::record(const snapshot& frame) {
  std::map<int, std::vector<sample>> kept;
  const auto now = frame.time();
  for (const auto& p : frame.pedestrians()) {
    auto& mine = kept[p.id];
    if (auto it = samples_.find(p.id); it != samples_.end()) {
      for (const auto& s : it->second) {
        if (now - s.time <= length_) mine.push_back(s);
      }
    }
    mine.push_back({now, p.position});
  }
  samples_ = std::move(kept);
  trails_.clear();
  for (const auto& [id, list] : samples_) {
    auto& trail = trails_[id];
    for (const auto& s : list) trail.push_back(s.position);
  }
}

}  // namespace argus::world

#include "eval/mot_export.hpp"

#include <cmath>
#include <ostream>

#include "config/whole_file.hpp"
#include "fmt/format.h"
#include "fmt/ostream.h"

namespace argus::eval {

using config::write_whole_file;

std::string mot_sequence(int camera) {
  return fmt::format("cam{:02}", camera);
}

void write_mot(const std::filesystem::path& dir, const config::scenario& scenario,
               const observation_log::contents& log, std::int64_t ticks) {
  const std::string split = fmt::format("{}-{}", mot_benchmark, mot_split);
  const auto gt_root = dir / "gt" / "mot_challenge";
  const auto tracker_root = dir / "trackers" / "mot_challenge" / split / "argus" / "data";
  std::filesystem::create_directories(gt_root / "seqmaps");
  std::filesystem::create_directories(tracker_root);
  const int rate = static_cast<int>(std::lround(1.0 / scenario.run.tick.count()));
  std::vector<std::string> sequences;
  for (const auto& camera : scenario.cameras) {
    const auto sequence = mot_sequence(camera.id);
    sequences.push_back(sequence);
    const auto seq_dir = gt_root / split / sequence;
    std::filesystem::create_directories(seq_dir / "gt");
    write_whole_file(seq_dir / "seqinfo.ini", [&](std::ostream& out) {
      fmt::print(out,
                 "[Sequence]\nname={}\nimDir=img1\nframeRate={}\nseqLength={}\nimWidth={}\n"
                 "imHeight={}\nimExt=.jpg\n",
                 sequence, rate, ticks, camera.imaging.width_px, camera.imaging.height_px);
    });
    const auto frames = log.frames.find(camera.id);
    write_whole_file(seq_dir / "gt" / "gt.txt", [&](std::ostream& out) {
      if (frames == log.frames.end()) return;
      for (const auto& f : frames->second) {
        if (f.tick >= ticks) break;
        for (const auto& v : f.visible) {
          // A sliver at the frame's edge would print as a 0.00-pixel box, which MOT rejects.
          if (v.box.width < 0.005 || v.box.height < 0.005) continue;
          fmt::print(out, "{},{},{:.2f},{:.2f},{:.2f},{:.2f},1,1,{:.4f}\n", f.tick + 1,
                     v.pedestrian, v.box.x, v.box.y, v.box.width, v.box.height, v.visibility);
        }
      }
    });
    write_whole_file(tracker_root / (sequence + ".txt"), [&](std::ostream& out) {
      if (frames == log.frames.end()) return;
      for (const auto& f : frames->second) {
        if (f.tick >= ticks) break;
        for (const auto& l : f.looks)
          if (l.found && l.box.width > 0.0 && l.box.height > 0.0)
            fmt::print(out, "{},{},{:.2f},{:.2f},{:.2f},{:.2f},{:.4f},-1,-1,-1\n", f.tick + 1,
                       l.task + 1, l.box.x, l.box.y, l.box.width, l.box.height, l.score);
      }
    });
  }
  write_whole_file(gt_root / "seqmaps" / (split + ".txt"), [&](std::ostream& out) {
    out << "name\n";
    for (const auto& s : sequences) out << s << "\n";
  });
}

}  // namespace argus::eval

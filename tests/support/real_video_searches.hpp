#pragma once

// The real-video evaluation set in tests/data/vtest (see its README.md): frames of a plaza
// with hand-checked boxes of the people in them, and the searches they make: a patch of a
// person cut from one frame, the same person searched for 5, 15 or 30 frames later.

#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmt/format.h"
#include "opencv2/core.hpp"
#include "opencv2/imgcodecs.hpp"

namespace argus::test_support {

/// One search: the patch `patch_box` of frame `from`, looked for in frame `to` where the
/// person is at `truth`.
struct real_video_search {
  std::string person;
  int from = 0;
  int to = 0;
  cv::Rect patch_box;
  cv::Rect truth;
  /// to - from.
  int interval() const { return to - from; }
};

/// The frames (by number) and searches of the set.
struct real_video_set {
  std::map<int, cv::Mat> frames;
  std::vector<real_video_search> searches;
};

/// The intervals searched, in frames (10 frames per second).
inline const std::vector<int>& real_video_intervals() {
  static const std::vector<int> intervals{5, 15, 30};
  return intervals;
}

/// Loads `directory`/boxes.txt ("FRAME PERSON X Y WIDTH HEIGHT" per line) and the frames
/// vtest_FRAME.jpg it names; every person boxed in frames f and f + interval is one search.
inline real_video_set load_real_video_set(const std::string& directory) {
  std::ifstream in(directory + "/boxes.txt");
  if (!in) throw std::runtime_error(fmt::format("cannot read {}/boxes.txt", directory));
  std::map<int, std::map<std::string, cv::Rect>> boxes;
  int frame = 0;
  std::string person;
  cv::Rect box;
  while (in >> frame >> person >> box.x >> box.y >> box.width >> box.height)
    boxes[frame][person] = box;
  real_video_set set;
  for (const auto& [number, people] : boxes) {
    const auto path = fmt::format("{}/vtest_{:03d}.jpg", directory, number);
    set.frames[number] = cv::imread(path, cv::IMREAD_COLOR);
    if (set.frames[number].empty()) throw std::runtime_error("cannot read " + path);
  }
  for (const auto& [from, people] : boxes)
    for (const int interval : real_video_intervals()) {
      const auto later = boxes.find(from + interval);
      if (later == boxes.end()) continue;
      for (const auto& [name, patch_box] : people) {
        const auto there = later->second.find(name);
        if (there != later->second.end())
          set.searches.push_back({name, from, from + interval, patch_box, there->second});
      }
    }
  return set;
}

/// Intersection over union of two boxes.
inline double overlap(const cv::Rect& a, const cv::Rect& b) {
  const double shared = (a & b).area();
  return shared > 0.0 ? shared / (a.area() + b.area() - shared) : 0.0;
}

}  // namespace argus::test_support

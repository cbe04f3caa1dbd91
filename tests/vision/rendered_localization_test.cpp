// Localisation of pedestrians in rendered frames across zoom settings (issue #5): a camera of
// Penn Station centres a pedestrian with the fixate/zoom geometry at three zooms (the
// pedestrian 30 %, 50 % and 80 % of the frame high), takes the target's signature from the
// middle view as a tracker would, and the Fig. 9 localiser with the paper's scales must find
// the pedestrian in every view — the scale l* adapts to the zoom.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "tests/support/walking_crowd.hpp"
#include "vision/backprojection.hpp"
#include "vision/color_histogram.hpp"
#include "vision/emulated_sensor.hpp"
#include "vision/fixate_zoom.hpp"
#include "vision/multiscale_localizer.hpp"
#include "vision/renderer.hpp"
#include "world/crowd.hpp"
#include "world/layout_loader.hpp"

namespace argus::vision {
namespace {

constexpr int width = 320;
constexpr int height = 240;

std::optional<pedestrian_view> seen(const world::snapshot& frame, const world::station& where,
                                    const camera_view& view, int id) {
  for (const auto& p : visible_pedestrians(frame, where, view))
    if (p.id == id) return p;
  return std::nullopt;
}

// The middle of the body box: what a tracker initialised on it would take as the signature.
cv::Rect core_of(const cv::Rect2d& box) {
  return cv::Rect(cv::Point(static_cast<int>(box.x + 0.25 * box.width),
                            static_cast<int>(box.y + 0.15 * box.height)),
                  cv::Point(static_cast<int>(box.x + 0.75 * box.width),
                            static_cast<int>(box.y + 0.85 * box.height))) &
         cv::Rect(0, 0, width, height);
}

bool contains_centre(const cv::Rect2d& truth, const localized_region& r) {
  return truth.contains(cv::Point2d(r.x + r.width / 2.0, r.y + r.height / 2.0));
}

TEST(rendered_localization, finds_the_target_at_every_zoom_with_the_paper_scales) {
  const auto& scene = ::argus::test_support::walking_crowd();
  const auto& frame = *scene.frame;
  const auto& station = scene.station;
  renderer render(station);
  // Camera 2 of scenarios/penn_station.yaml: north wall of the waiting room, looking south.
  const camera_view wide{{{103.0, 87.0, 8.0}}, {-90.0, -20.0, 60.0}, width, height};

  int targets = 0;
  int views = 0;
  int found = 0;
  int adapted = 0;  // targets found at all three zooms
  for (const auto& candidate : visible_pedestrians(frame, *station, wide)) {
    if (targets == 5) break;
    if (candidate.occlusion > 0.0 || candidate.box.height < 12.0) continue;
    // Three zooms on this pedestrian; keep it only if it stays unoccluded in all of them.
    std::vector<camera_view> zoomed;
    std::vector<cv::Rect2d> truth;
    for (double fraction : {0.3, 0.5, 0.8}) {
      camera_view view = wide;
      view.pose = centring_pose(wide.pose, candidate.box, {width, height}, fraction);
      const auto p = seen(frame, *station, view, candidate.id);
      if (!p || p->occlusion > 0.1) break;
      zoomed.push_back(view);
      truth.push_back(p->box);
    }
    if (zoomed.size() != 3) continue;
    ++targets;
    std::vector<cv::Mat> images;
    for (const auto& view : zoomed) images.push_back(render.render(view, frame, 10.0));
    const auto signature = color_histogram::of_region(images[1], core_of(truth[1]));
    multiscale_localizer localizer({{}, 0.4, 4});
    std::vector<int> scales;  // l* of each hit
    for (std::size_t z = 0; z < zoomed.size(); ++z) {
      ++views;
      const auto bp = backproject_target(images[z], signature, truth[z].area());
      const auto regions =
          localizer.localize(bp.backprojection, histogram_scorer(bp.bin_indices, signature));
      const bool hit = !regions.empty() && contains_centre(truth[z], regions.front());
      found += hit ? 1 : 0;
      if (hit) scales.push_back(regions.front().scale);
      if (!hit)
        cv::imwrite("rendered_localization_miss_" + std::to_string(candidate.id) + "_" +
                        std::to_string(z) + ".png",
                    images[z]);  // for a human to look at
    }
    // The sharpest scale grows with the zoom: the kernel follows the target's size.
    if (scales.size() == 3) {
      EXPECT_LT(scales.front(), scales.back()) << "pedestrian " << candidate.id;
      ++adapted;
    }
  }
  EXPECT_GE(adapted, 3);
  ASSERT_GE(targets, 3) << "too few unoccluded pedestrians in camera 2's view";
  // Rendered bodies share colours with the floor and with each other; most views must work.
  EXPECT_GE(found * 10, views * 8) << found << " of " << views << " views";
  std::printf("found %d of %d views (%d targets x 3 zooms)\n", found, views, targets);
}

}  // namespace
}  // namespace argus::vision

#include "report/plan_report.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "config/scenario_loader.hpp"
#include "report/camera_colours.hpp"
#include "world/layout_loader.hpp"
#include "world/plan_view.hpp"
#include "world/station.hpp"

namespace argus::report {
namespace {

const std::filesystem::path data_dir{ARGUS_REPORT_TEST_DATA_DIR};

// The fixture's target 0 is observed by camera 7 until 30 s, by nobody from 40 to 42 s
// (tests/report/data/run/targets.csv): her path must show camera 7's colour, then grey.
class plan_report_test : public testing::Test {
 protected:
  void SetUp() override {
    scenario_ = config::load_scenario(data_dir / "run" / "scenario.yaml");
    station_ = world::station::load(world::layout_path(scenario_));
    paths_ = target_paths_from(*csv_table::read(data_dir / "run" / "targets.csv"));
    image_ =
        cv::imdecode(render_plan_report(*station_, scenario_.cameras, paths_), cv::IMREAD_COLOR);
    ASSERT_FALSE(image_.empty());
  }

  // The colour drawn where task 0's target was at `t_s`.
  cv::Vec3b colour_at(double t_s) const {
    for (const auto& s : paths_.at(0))
      if (std::abs(s.t_s - t_s) < 1e-6) {
        const auto [column, row] = world::plan_pixel(*station_, {}, {s.x_m, s.y_m});
        return image_.at<cv::Vec3b>(row, column);
      }
    ADD_FAILURE() << "no sample at " << t_s;
    return {};
  }

  static void expect_near(const cv::Vec3b& got, bgr wanted) {
    EXPECT_NEAR(got[0], wanted.b, 12);
    EXPECT_NEAR(got[1], wanted.g, 12);
    EXPECT_NEAR(got[2], wanted.r, 12);
  }

  config::scenario scenario_;
  std::shared_ptr<const world::station> station_;
  target_paths paths_;
  cv::Mat image_;
};

TEST_F(plan_report_test, the_path_takes_the_observing_cameras_colour) {
  expect_near(colour_at(20.0), camera_colour(7));
  expect_near(colour_at(60.0), camera_colour(2));
  expect_near(colour_at(90.0), camera_colour(10));
}

TEST_F(plan_report_test, unobserved_stretches_are_grey) {
  expect_near(colour_at(41.5), unobserved_colour);
}

TEST_F(plan_report_test, the_plan_is_the_plan_views_size) {
  const auto plain = cv::imdecode(
      world::render_plan_view(*station_, scenario_.cameras, nullptr, nullptr), cv::IMREAD_COLOR);
  EXPECT_EQ(image_.size(), plain.size());
}

}  // namespace
}  // namespace argus::report

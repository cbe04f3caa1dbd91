// `argus vision localize`: every occurrence of a target patch's colour distribution in an
// image, by histogram backprojection and the multiscale localiser (paper Fig. 9).

#include <iostream>
#include <optional>

#include "CLI/CLI.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "opencv2/imgcodecs.hpp"
#include "vision/backprojection.hpp"
#include "vision/multiscale_localizer.hpp"

namespace argus::apps {
namespace {

constexpr int ok = 0;
constexpr int bad_input = 2;

struct localize_arguments {
  std::string image;
  std::string target;
  double rho = 0.5;
  std::optional<int> single_scale;
  int max_regions = 16;
};

int localize(const localize_arguments& args) {
  const cv::Mat image = cv::imread(args.image, cv::IMREAD_COLOR);
  if (image.empty()) {
    std::cerr << fmt::format("argus vision localize: --image: cannot read an image from '{}'\n",
                             args.image);
    return bad_input;
  }
  const cv::Mat patch = cv::imread(args.target, cv::IMREAD_COLOR);
  if (patch.empty()) {
    std::cerr << fmt::format("argus vision localize: --target: cannot read an image from '{}'\n",
                             args.target);
    return bad_input;
  }
  const auto target = vision::color_histogram::of_image(patch);
  const auto bp = vision::backproject_target(image, target);
  const auto score = vision::histogram_scorer(bp.bin_indices, target);
  std::vector<vision::localized_region> found;
  if (args.single_scale) {
    found = vision::localize_single_scale(bp.backprojection, *args.single_scale, score, args.rho,
                                          args.max_regions);
  } else {
    vision::multiscale_localizer localizer({{}, args.rho, args.max_regions});
    found = localizer.localize(bp.backprojection, score);
  }
  auto regions = nlohmann::json::array();
  for (const auto& r : found)
    regions.push_back(
        {{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}, {"score", r.score}});
  std::cout << regions.dump(2) << '\n';
  return ok;
}

}  // namespace

/// Adds `argus vision localize` to `app`; its callback sets `result` to the exit code.
void add_vision_command(CLI::App& app, int& result) {
  auto* vision = app.add_subcommand("vision", "Low-level visual routines on image files");
  vision->require_subcommand(1);
  auto args = std::make_shared<localize_arguments>();
  auto* cmd = vision->add_subcommand(
      "localize",
      "Localise every occurrence of a target patch's colours in an image (paper Fig. 9); "
      "prints a JSON array of {x, y, width, height, score} boxes in pixels");
  cmd->add_option("--image", args->image, "Image to search (any format OpenCV reads)")->required();
  cmd->add_option("--target", args->target, "Image of the target patch whose colours to find")
      ->required();
  cmd->add_option("--rho", args->rho, "Acceptance threshold on histogram intersection")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--single-scale", args->single_scale,
                  "Swain-Ballard single-scale localisation with kernel size L (pixels)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-regions", args->max_regions, "At most this many regions")
      ->check(CLI::PositiveNumber);
  cmd->callback([args, &result] { result = localize(*args); });
}

}  // namespace argus::apps

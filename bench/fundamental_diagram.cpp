// The crowd against the field's reference data (issue 18): the fundamental diagram (speed and
// specific flow against density, measured with the classic and the Voronoi method in a
// corridor, beside Weidmann's curve) and the specific flow through a bottleneck against its
// width (beside the range the experiments measured). Prints tables and draws them in a PNG.
//
//   fundamental_diagram [OUT.png [SEED...]]
//
// OUT.png defaults to fundamental_diagram.png. The bottleneck runs the seeds given (default 1 2;
// as bench/steady_flow takes them, e.g. $(seq 1 20); each run takes under half a second) and
// prints each width's mean, least and greatest: two seeds said little about an exit whose flow
// lies near the range's edge.

#include "tests/world/fundamental_diagram.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "bench/plot_panel.hpp"
#include "bench/seed_list.hpp"
#include "report/drawing.hpp"
#include "tests/world/experiment.hpp"
#include "world/experiment_layouts.hpp"

namespace {

using namespace argus;
using bench::panel;
using world::testing::diagram_point;

/// Specific flow through an exit `width_m` wide: 150 people leave a 10 m x 10 m room; the
/// flow between the 10th and the 90th percentile of their crossings, over the width.
double bottleneck_specific_flow(double width_m, std::uint64_t seed) {
  world::crowd_settings settings;
  settings.population = 0;
  settings.prefill = false;
  settings.run_seed = seed;
  world::flow occupants;
  occupants.spawn_area = world::bottleneck_room_area();
  occupants.count = 150;
  occupants.exit_portal = 0;
  settings.flows.push_back(occupants);
  world::testing::experiment room(world::bottleneck_room_layout(width_m), settings);
  world::testing::line_counter exit_line(11.2);
  room.run(400.0,
           [&](const world::snapshot& b, const world::snapshot& n) { exit_line.look(b, n); });
  return exit_line.flow_per_s() / width_m;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "fundamental_diagram.png";
  const auto parsed =
      argus::bench::seed_list(argc, argv, 2, "fundamental_diagram [OUT.png [SEED ...]]");
  if (!parsed) return 2;
  const std::vector<std::uint64_t>& seeds = *parsed;
  std::vector<diagram_point> block;
  std::printf(
      "Fundamental diagram, block of people in a corridor 4 m wide (area 4 m x 4 m, "
      "t = 2-6 s); classic method, then Voronoi method (cut-off 1 m)\n");
  std::printf("%8s %9s %7s %9s %7s   %9s %7s %9s %7s\n", "target", "density", "speed", "Weidmann",
              "flow", "V density", "V speed", "Weidmann", "V flow");
  for (const double density : {0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0}) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const auto p = world::testing::block_point(density, seed);
      const auto& v = p.voronoi;
      block.push_back(p);
      std::printf("%8.2f %9.2f %7.2f %9.2f %7.2f   %9.2f %7.2f %9.2f %7.2f\n", density,
                  p.density_per_m2, p.speed_mps,
                  world::testing::weidmann_speed_mps(p.density_per_m2), p.specific_flow_per_m_s,
                  v.density_per_m2, v.speed_mps,
                  world::testing::weidmann_speed_mps(v.density_per_m2), v.specific_flow_per_m_s);
    }
  }
  const auto jam = world::testing::jam_points();
  // Each method's points fall into the bins by that method's density.
  struct bin_sum {
    int count = 0;
    double speed = 0.0;
    double flow = 0.0;
    void add(double speed_mps, double flow_per_m_s) {
      ++count;
      speed += speed_mps;
      flow += flow_per_m_s;
    }
  };
  std::printf(
      "\nJam in front of a 1 m exit (rimea_04_fundamental_diagram), by density bin; classic "
      "method, then Voronoi method (cut-off 1 m)\n");
  std::printf("%12s %6s %7s %7s   %8s %7s %7s   %9s\n", "density", "points", "speed", "flow",
              "V points", "V speed", "V flow", "Weidmann");
  double densest = 0.0;
  double densest_voronoi = 0.0;
  for (const auto& p : jam) {
    densest = std::max(densest, p.density_per_m2);
    densest_voronoi = std::max(densest_voronoi, p.voronoi.density_per_m2);
  }
  for (int bin = 0; bin < std::ceil(std::max(densest, densest_voronoi)); ++bin) {
    bin_sum classic;
    bin_sum voronoi;
    const auto in_bin = [&](double density) { return density >= bin && density < bin + 1; };
    for (const auto& p : jam) {
      if (in_bin(p.density_per_m2)) classic.add(p.speed_mps, p.specific_flow_per_m_s);
      if (in_bin(p.voronoi.density_per_m2)) {
        voronoi.add(p.voronoi.speed_mps, p.voronoi.specific_flow_per_m_s);
      }
    }
    if (classic.count == 0 && voronoi.count == 0) continue;
    const auto mean = [](double sum, int count) { return count > 0 ? sum / count : 0.0; };
    std::printf("%5d - %4d %6d %7.2f %7.2f   %8d %7.2f %7.2f   %9.2f\n", bin, bin + 1,
                classic.count, mean(classic.speed, classic.count),
                mean(classic.flow, classic.count), voronoi.count,
                mean(voronoi.speed, voronoi.count), mean(voronoi.flow, voronoi.count),
                world::testing::weidmann_speed_mps(bin + 0.5));
  }
  std::printf("densest: %.2f /m^2 classic, %.2f /m^2 Voronoi\n", densest, densest_voronoi);
  std::printf(
      "\nBottleneck: 150 people leave a 10 m x 10 m room by an exit 1 m long; specific flow "
      "(1/(m s)), %zu seeds\n",
      seeds.size());
  std::printf("%10s %7s %7s %7s   %s\n", "width (m)", "mean", "least", "most", "by seed");
  std::vector<std::pair<double, double>> bottleneck;
  for (const double width : {0.8, 1.0, 1.2, 1.6, 2.0, 2.4}) {
    double sum = 0.0;
    double least = std::numeric_limits<double>::infinity();
    double most = 0.0;
    std::string by_seed;
    for (const auto seed : seeds) {
      const double f = bottleneck_specific_flow(width, seed);
      bottleneck.push_back({width, f});
      sum += f;
      least = std::min(least, f);
      most = std::max(most, f);
      by_seed += fmt::format(" {:.2f}", f);
    }
    std::printf("%10.1f %7.3f %7.2f %7.2f  %s\n", width, sum / static_cast<double>(seeds.size()),
                least, most, by_seed.c_str());
  }

  cv::Mat image(500, 1500, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Scalar reference(60, 60, 220);  // red: published
  const cv::Scalar ours(200, 110, 30);      // blue: Argus, free branch
  const cv::Scalar jammed(60, 160, 60);     // green: Argus, jam
  const cv::Scalar voronoi(0, 140, 255);    // orange: Argus, both, by the Voronoi method
  const panel speed{{70, 60, 400, 340}, 6.0, 1.6};
  speed.axes(image, "Speed against density", "density (1/m^2)", "speed (m/s)", 1.0, 0.2);
  const panel flow{{560, 60, 400, 340}, 6.0, 3.0};
  flow.axes(image, "Specific flow against density", "density (1/m^2)", "flow (1/(m s))", 1.0, 0.5);
  const panel width{{1050, 60, 400, 340}, 3.0, 2.5};
  width.axes(image, "Bottleneck: specific flow against width", "width (m)", "flow (1/(m s))", 0.5,
             0.5);
  for (double rho = 0.05; rho < 5.4; rho += 0.05) {
    const double next = rho + 0.05;
    cv::line(image, speed.at(rho, world::testing::weidmann_speed_mps(rho)),
             speed.at(next, world::testing::weidmann_speed_mps(next)), reference, 2);
    cv::line(image, flow.at(rho, rho * world::testing::weidmann_speed_mps(rho)),
             flow.at(next, next * world::testing::weidmann_speed_mps(next)), reference, 2);
  }
  // The same sizes as the classic points: small for the jam, large for the block.
  const auto plot = [&](const diagram_point& p, int size, const cv::Scalar& colour) {
    cv::circle(image, speed.at(p.density_per_m2, p.speed_mps), size, colour, cv::FILLED);
    cv::circle(image, flow.at(p.density_per_m2, p.specific_flow_per_m_s), size, colour, cv::FILLED);
  };
  const auto plot_voronoi = [&](const diagram_point& p, int size) {
    const auto& v = p.voronoi;
    plot({v.density_per_m2, v.speed_mps, v.specific_flow_per_m_s, {}}, size, voronoi);
  };
  for (const auto& p : jam) plot(p, 2, jammed);
  for (const auto& p : jam) plot_voronoi(p, 2);
  for (const auto& p : block) plot(p, 4, ours);
  for (const auto& p : block) plot_voronoi(p, 4);
  // The experiments' range: about 1.2-1.9 /(m s) for exits 0.8-2.5 m wide (Kretz et al. 2006,
  // Seyfried et al. 2009, Mueller 1981), drawn as a band, not as their individual points.
  cv::rectangle(image, width.at(0.8, 1.9), width.at(2.5, 1.2), cv::Scalar(200, 200, 250),
                cv::FILLED);
  cv::rectangle(image, width.at(0.8, 1.9), width.at(2.5, 1.2), reference, 1);
  for (const auto& [w, j] : bottleneck) cv::circle(image, width.at(w, j), 5, ours, cv::FILLED);
  report::draw_text(image, "red: Weidmann (1993) / published bottleneck range", {70, 460}, 0.45,
                    reference);
  report::draw_text(
      image, fmt::format("blue: Argus, block in a corridor; bottleneck ({} seeds)", seeds.size()),
      {560, 460}, 0.45, ours);
  report::draw_text(image, "green: Argus, jam before a 1 m exit", {1050, 460}, 0.45, jammed);
  report::draw_text(image,
                    "orange: the block (large) and the jam (small) by the Voronoi method, cut-off "
                    "1 m (blue, green: by the classic method)",
                    {70, 485}, 0.45, voronoi);
  if (!cv::imwrite(out, image)) {
    std::fprintf(stderr, "fundamental_diagram: cannot write %s\n", out.c_str());
    return 1;
  }
  std::printf("\nwritten %s\n", out.c_str());
  return 0;
}

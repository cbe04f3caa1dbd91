#include "world/plan_view.hpp"

#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "world/plan_view_image.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::world {

namespace {

constexpr int margin_px = 24;

class painter {
 public:
  painter(const station& where, const plan_view_options& options)
      : where_(where), options_(options) {
    const vec2 size = where.plan().size_m;
    image_ = cv::Mat(static_cast<int>(size.y() * options.pixels_per_m) + 2 * margin_px,
                     static_cast<int>(size.x() * options.pixels_per_m) + 2 * margin_px, CV_8UC3,
                     cv::Scalar(250, 250, 250));
  }

  cv::Point px(const vec2& p) const {
    const auto [column, row] = plan_pixel(where_, options_, p);
    return {column, row};
  }

  cv::Rect rect(const box& b) const {
    return {px({b.min.x(), b.max.y()}), px({b.max.x(), b.min.y()})};
  }

  void label(const std::string& text, const vec2& at, double scale, const cv::Scalar& colour,
             bool centred = true) {
    if (!options_.labels) return;
    int baseline = 0;
    const auto size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &baseline);
    cv::Point origin = px(at);
    if (centred) origin -= cv::Point(size.width / 2, -size.height / 2);
    cv::putText(image_, text, origin, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
  }

  void floor() {
    for (const auto& r : where_.plan().regions) {
      cv::Scalar fill(235, 235, 235);
      switch (r.kind) {
        case region_kind::concourse:
          fill = cv::Scalar(236, 226, 214);
          break;
        case region_kind::waiting_room:
          fill = cv::Scalar(214, 232, 244);
          break;
        case region_kind::arcade:
          fill = cv::Scalar(216, 240, 220);
          break;
        case region_kind::platforms:
          fill = cv::Scalar(210, 210, 210);
          break;
        case region_kind::tracks:
          fill = cv::Scalar(120, 120, 120);
          break;
        case region_kind::other:
          break;
      }
      cv::rectangle(image_, rect(r.area), fill, cv::FILLED);
      if (r.kind == region_kind::tracks) {
        // Rails, every 5 m.
        for (double y = r.area.min.y() + 2.5; y < r.area.max.y(); y += 5.0) {
          cv::line(image_, px({r.area.min.x(), y}), px({r.area.max.x(), y}), cv::Scalar(70, 70, 70),
                   1);
        }
      }
    }
    for (const auto& s : where_.plan().stairways) {
      cv::rectangle(image_, rect(s.area), cv::Scalar(160, 160, 175), cv::FILLED);
      for (double x = s.area.min.x(); x <= s.area.max.x(); x += 0.5) {
        cv::line(image_, px({x, s.area.min.y()}), px({x, s.area.max.y()}), cv::Scalar(90, 90, 100),
                 1);
      }
    }
  }

  void furniture() {
    const auto& plan = where_.plan();
    for (const auto& o : plan.obstacles) {
      std::vector<cv::Point> polygon;
      for (const auto& p : o.polygon) polygon.push_back(px(p));
      cv::fillPoly(image_, std::vector<std::vector<cv::Point>>{polygon}, cv::Scalar(110, 110, 110));
    }
    for (const auto& m : plan.meeting_points) {
      cv::circle(image_, px(m.position), static_cast<int>(m.radius_m * options_.pixels_per_m),
                 cv::Scalar(170, 90, 160), 1, cv::LINE_AA);
    }
    for (const auto& b : plan.benches) {
      cv::line(image_, px(b.from), px(b.to), cv::Scalar(40, 80, 140), 3);
    }
    for (const auto& s : where_.seats())
      cv::circle(image_, px(s.position), 1, cv::Scalar(40, 80, 140), cv::FILLED);
    for (const auto& c : plan.ticket_booths) {
      cv::rectangle(image_, rect(c.footprint), cv::Scalar(0, 140, 255), cv::FILLED);
      cv::rectangle(image_, rect(c.footprint), cv::Scalar(0, 70, 140), 1);
    }
    for (const auto& c : plan.vending_machines) {
      cv::rectangle(image_, rect(c.footprint), cv::Scalar(200, 60, 30), cv::FILLED);
    }
    for (const auto& w : plan.walls) {
      for (std::size_t i = 1; i < w.points.size(); ++i) {
        cv::line(image_, px(w.points[i - 1]), px(w.points[i]), cv::Scalar(20, 20, 20), 2,
                 cv::LINE_AA);
      }
    }
    for (const auto& p : plan.portals) {
      cv::rectangle(image_, rect(p.area), cv::Scalar(0, 215, 255), cv::FILLED);
      cv::rectangle(image_, rect(p.area), cv::Scalar(0, 140, 170), 1);
    }
    for (const auto& r : plan.regions) {
      const cv::Scalar colour =
          r.kind == region_kind::tracks ? cv::Scalar(240, 240, 240) : cv::Scalar(90, 90, 90);
      std::string name = r.name;
      for (auto& c : name) c = c == '_' ? ' ' : c;
      label(name, {r.area.center().x(), r.area.max.y() - 3.0}, 0.5, colour);
    }
  }

  void cameras(std::span<const config::camera_settings> list) {
    cv::Mat overlay = image_.clone();
    for (const auto& c : list) {
      const vec2 at{c.position.x_m, c.position.y_m};
      const double pan = c.pan_deg * M_PI / 180.0;
      const double half = c.field_of_view_deg * M_PI / 360.0;
      std::vector<cv::Point> wedge{px(at)};
      for (int k = 0; k <= 16; ++k) {
        const double a = pan - half + 2.0 * half * k / 16.0;
        wedge.push_back(px(at + options_.wedge_range_m * vec2{std::cos(a), std::sin(a)}));
      }
      cv::fillPoly(overlay, std::vector<std::vector<cv::Point>>{wedge}, cv::Scalar(60, 60, 230));
    }
    cv::addWeighted(overlay, 0.18, image_, 0.82, 0.0, image_);
    for (const auto& c : list) {
      const vec2 at{c.position.x_m, c.position.y_m};
      const double pan = c.pan_deg * M_PI / 180.0;
      cv::line(image_, px(at), px(at + 3.0 * vec2{std::cos(pan), std::sin(pan)}),
               cv::Scalar(0, 0, 180), 2, cv::LINE_AA);
      cv::circle(image_, px(at), 5, cv::Scalar(0, 0, 200), cv::FILLED, cv::LINE_AA);
      const std::string id = std::to_string(c.id);
      int baseline = 0;
      const auto size = cv::getTextSize(id, cv::FONT_HERSHEY_SIMPLEX, 0.5, 1, &baseline);
      // Label on the side away from where the camera looks.
      const vec2 back = at - 3.2 * vec2{std::cos(pan), std::sin(pan)};
      const cv::Point centre = px(back);
      const cv::Rect tag(centre.x - size.width / 2 - 3, centre.y - size.height / 2 - 3,
                         size.width + 6, size.height + 6);
      cv::rectangle(image_, tag, cv::Scalar(255, 255, 255), cv::FILLED);
      cv::rectangle(image_, tag, cv::Scalar(0, 0, 200), 1);
      cv::putText(image_, id, {tag.x + 3, tag.y + size.height + 3}, cv::FONT_HERSHEY_SIMPLEX, 0.5,
                  cv::Scalar(0, 0, 200), 1, cv::LINE_AA);
    }
  }

  void pedestrians(const snapshot* frame, const std::map<int, std::vector<vec2>>* trails) {
    if (frame == nullptr) return;
    for (const auto& p : frame->pedestrians()) {
      const cv::Scalar colour(p.look.shirt.b, p.look.shirt.g, p.look.shirt.r);
      if (trails != nullptr) {
        if (auto it = trails->find(p.id); it != trails->end() && it->second.size() > 1) {
          std::vector<cv::Point> line;
          for (const auto& q : it->second) line.push_back(px(q));
          cv::polylines(image_, line, false, colour, 1, cv::LINE_AA);
        }
      }
    }
    for (const auto& p : frame->pedestrians()) {
      const cv::Scalar colour(p.look.shirt.b, p.look.shirt.g, p.look.shirt.r);
      const int radius =
          std::max(3, static_cast<int>(std::lround(p.radius_m() * options_.pixels_per_m)));
      cv::circle(image_, px(p.position), radius, colour, cv::FILLED, cv::LINE_AA);
      cv::circle(image_, px(p.position), radius, cv::Scalar(30, 30, 30), 1, cv::LINE_AA);
    }
  }

  const cv::Mat& image() const { return image_; }

 private:
  const station& where_;
  const plan_view_options& options_;
  cv::Mat image_;
};

}  // namespace

std::array<int, 2> plan_pixel(const station& where, const plan_view_options& options,
                              const vec2& at) {
  const double height = where.plan().size_m.y();
  return {static_cast<int>(std::lround(margin_px + at.x() * options.pixels_per_m)),
          static_cast<int>(std::lround(margin_px + (height - at.y()) * options.pixels_per_m))};
}

cv::Mat paint_plan_view(const station& where, std::span<const config::camera_settings> cameras,
                        const snapshot* frame, const std::map<int, std::vector<vec2>>* trails,
                        const plan_view_options& options) {
  painter paint(where, options);
  paint.floor();
  paint.furniture();
  paint.cameras(cameras);
  paint.pedestrians(frame, trails);
  return paint.image();
}

std::vector<unsigned char> render_plan_view(const station& where,
                                            std::span<const config::camera_settings> cameras,
                                            const snapshot* frame,
                                            const std::map<int, std::vector<vec2>>* trails,
                                            const plan_view_options& options) {
  std::vector<unsigned char> png;
  cv::imencode(".png", paint_plan_view(where, cameras, frame, trails, options), png);
  return png;
}

void write_plan_view(const std::filesystem::path& png, const station& where,
                     std::span<const config::camera_settings> cameras, const snapshot* frame,
                     const std::map<int, std::vector<vec2>>* trails,
                     const plan_view_options& options) {
  const auto bytes = render_plan_view(where, cameras, frame, trails, options);
  std::FILE* file = std::fopen(png.string().c_str(), "wb");
  if (file == nullptr || std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) {
    if (file != nullptr) std::fclose(file);
    throw std::runtime_error("cannot write " + png.string());
  }
  std::fclose(file);
}

}  // namespace argus::world

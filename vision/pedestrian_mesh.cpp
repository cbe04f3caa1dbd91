#include "vision/pedestrian_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace argus::vision {
namespace {

using Eigen::Affine3d;
using Eigen::AngleAxisd;
using Eigen::Vector3d;
using Eigen::Vector3f;

Vector3f to_color(const world::rgb8& c) {
  return Vector3f{static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b)} /
         255.0f;
}

box_instance instance(const Affine3d& model, const Vector3f& color) {
  box_instance b;
  const Eigen::Matrix4f m = model.matrix().cast<float>();
  std::copy(m.data(), m.data() + 16, b.model);  // Eigen is column-major, like OpenGL
  b.color[0] = color.x();
  b.color[1] = color.y();
  b.color[2] = color.z();
  return b;
}

// A limb hanging from `pivot` (in body coordinates), swung by `angle` about the body's
// sideways axis (y), of size (thickness x, width y, length z).
Affine3d limb(const Affine3d& body, const Vector3d& pivot, double angle, const Vector3d& size) {
  Affine3d m = body;
  m.translate(pivot);
  m.rotate(AngleAxisd(angle, Vector3d::UnitY()));
  m.translate(Vector3d{0.0, 0.0, -size.z() / 2.0});
  m.scale(size);
  return m;
}

}  // namespace

const std::vector<float>& unit_cube_vertices() {
  static const std::vector<float> vertices = [] {
    std::vector<float> v;
    // Each face: normal axis and sign; corners counter-clockwise seen from outside.
    for (int axis = 0; axis < 3; ++axis) {
      for (int sign = -1; sign <= 1; sign += 2) {
        Vector3d n = Vector3d::Zero();
        n[axis] = sign;
        const Vector3d u = Vector3d::Unit((axis + 1) % 3) * sign;
        const Vector3d w = Vector3d::Unit((axis + 2) % 3);
        const Vector3d c = 0.5 * n;
        const Vector3d corners[4] = {c - 0.5 * u - 0.5 * w, c + 0.5 * u - 0.5 * w,
                                     c + 0.5 * u + 0.5 * w, c - 0.5 * u + 0.5 * w};
        for (int k : {0, 1, 2, 0, 2, 3}) {
          for (int i = 0; i < 3; ++i) v.push_back(static_cast<float>(corners[k][i]));
          for (int i = 0; i < 3; ++i) v.push_back(static_cast<float>(n[i]));
        }
      }
    }
    return v;
  }();
  return vertices;
}

box_instance make_box(const Vector3d& centre, const Vector3d& size, const Vector3f& color) {
  Affine3d m = Affine3d::Identity();
  m.translate(centre);
  m.scale(size);
  return instance(m, color);
}

void append_pedestrian(const world::pedestrian_state& p, double time_s,
                       std::vector<box_instance>& out) {
  const auto& look = p.look;
  const double h = look.height_m;
  const double girth = look.girth_m;
  const double speed = p.velocity.norm();
  const bool sitting = p.doing == world::activity::sitting;

  // Body frame: origin between the feet on the floor, x forward (heading), z up.
  Affine3d body = Affine3d::Identity();
  body.translate(Vector3d{p.position.x(), p.position.y(), 0.0});
  body.rotate(AngleAxisd(p.heading_rad(), Vector3d::UnitZ()));

  // Proportions of an adult figure, as fractions of the height.
  const double leg_length = 0.47 * h;
  const double torso_length = 0.33 * h;
  const double head_size = 0.13 * h;
  const double arm_length = 0.38 * h;
  const double depth = 0.55 * girth;  // chest front to back
  const double leg_width = 0.36 * girth;
  const double arm_width = 0.2 * girth;

  // Gait: one cycle per stride of ~1.4 m; the per-id offset keeps a crowd out of step.
  const double stride_m = 1.4;
  const double phase = 2.0 * M_PI * (time_s * speed / stride_m) + 0.7 * p.id;
  const double amplitude = 0.45 * std::min(1.0, speed / 1.3);
  const double swing = sitting ? 0.0 : amplitude * std::sin(phase);

  const double hip_z = sitting ? 0.45 : leg_length;
  const Vector3f trousers = to_color(look.trousers);
  const Vector3f shirt = to_color(look.shirt);
  const Vector3f skin = to_color(look.skin);
  const Vector3f hair = to_color(look.hair);

  // Legs: thighs forward when sitting (hip bent 90 degrees), shins down.
  for (int side : {-1, 1}) {
    const Vector3d hip{0.0, side * 0.25 * girth, hip_z};
    if (sitting) {
      const double thigh = 0.5 * leg_length;
      out.push_back(
          instance(limb(body, hip, -M_PI / 2.0, {leg_width, leg_width, thigh}), trousers));
      out.push_back(
          instance(limb(body, hip + Vector3d{thigh, 0.0, 0.0}, 0.0, {leg_width, leg_width, hip_z}),
                   trousers));
    } else {
      out.push_back(
          instance(limb(body, hip, side * swing, {leg_width, leg_width, leg_length}), trousers));
    }
  }
  // Torso.
  const double torso_bottom = hip_z;
  Affine3d torso = body;
  torso.translate(Vector3d{0.0, 0.0, torso_bottom + torso_length / 2.0});
  torso.scale(Vector3d{depth, girth * 0.85, torso_length});
  out.push_back(instance(torso, shirt));
  // Arms: sleeve (shirt) and forearm with hand (skin), counter-swinging the legs.
  const double shoulder_z = torso_bottom + torso_length * 0.95;
  for (int side : {-1, 1}) {
    const Vector3d shoulder{0.0, side * (girth * 0.425 + arm_width / 2.0), shoulder_z};
    const double a = -side * swing * 0.8;
    const double sleeve = 0.45 * arm_length;
    out.push_back(instance(limb(body, shoulder, a, {arm_width, arm_width, sleeve}), shirt));
    const Vector3d elbow = shoulder + Vector3d{-std::sin(a) * sleeve, 0.0, -std::cos(a) * sleeve};
    out.push_back(instance(
        limb(body, elbow, a, {arm_width * 0.85, arm_width * 0.85, arm_length - sleeve}), skin));
  }
  // Neck, head and hair (a cap on top and at the back).
  const double neck_z = torso_bottom + torso_length;
  const double head_z = neck_z + 0.02 * h + head_size / 2.0;
  out.push_back(instance(
      [&] {
        Affine3d m = body;
        m.translate(Vector3d{0.0, 0.0, head_z});
        m.scale(Vector3d{head_size * 0.95, head_size * 0.8, head_size});
        return m;
      }(),
      skin));
  Affine3d cap = body;
  cap.translate(Vector3d{-0.12 * head_size, 0.0, head_z + 0.4 * head_size});
  cap.scale(Vector3d{head_size * 0.9, head_size * 0.85, head_size * 0.3});
  out.push_back(instance(cap, hair));
  Affine3d back = body;
  back.translate(Vector3d{-0.45 * head_size, 0.0, head_z + 0.05 * head_size});
  back.scale(Vector3d{head_size * 0.2, head_size * 0.85, head_size * 0.8});
  out.push_back(instance(back, hair));
}

}  // namespace argus::vision

#include "vision/renderer.hpp"

#include <GLES3/gl3.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "fmt/format.h"
#include "vision/scene_mesh.hpp"
#include "world/snapshot.hpp"
#include "world/station.hpp"

namespace argus::vision {
namespace {

// Per-vertex Lambert lighting (faces are flat, so per-vertex is per-face): a key light from
// high up, a weak fill from the other side and ambient. Normals are turned toward the eye so
// that walls and thin slabs are lit from whichever side the camera sees.
constexpr const char* vertex_shader = R"(#version 300 es
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec4 a_model0;
layout(location = 4) in vec4 a_model1;
layout(location = 5) in vec4 a_model2;
layout(location = 6) in vec4 a_model3;
layout(location = 7) in vec3 a_instance_color;
uniform mat4 u_view_projection;
uniform vec3 u_eye;
uniform float u_lit;
out vec3 v_color;
out vec2 v_floor;
out float v_pattern;
void main() {
  mat4 model = mat4(a_model0, a_model1, a_model2, a_model3);
  vec4 world = model * vec4(a_position, 1.0);
  vec3 n = normalize(mat3(model) * a_normal);
  if (dot(n, u_eye - world.xyz) < 0.0) n = -n;
  vec3 key = normalize(vec3(0.35, 0.25, 0.9));
  vec3 fill = normalize(vec3(-0.5, -0.6, 0.4));
  float light = 0.36 + 0.52 * max(dot(n, key), 0.0) + 0.22 * max(dot(n, fill), 0.0);
  v_color = a_color.rgb * a_instance_color * mix(1.0, light, u_lit);
  v_floor = world.xy;
  v_pattern = a_color.a;
  gl_Position = u_view_projection * world;
}
)";

// Floor tiles: a 2 m checker of slightly different stone, for perspective.
constexpr const char* fragment_shader = R"(#version 300 es
precision highp float;
in vec3 v_color;
in vec2 v_floor;
in float v_pattern;
out vec4 frag_color;
void main() {
  vec3 c = v_color;
  if (v_pattern > 0.5) {
    vec2 tile = floor(v_floor / 2.0);
    c *= mix(1.0, 0.93, mod(tile.x + tile.y, 2.0));
  }
  frag_color = vec4(c, 1.0);
}
)";

GLuint compile(GLenum kind, const char* source) {
  GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(fmt::format("renderer: {} shader does not compile: {}",
                                         kind == GL_VERTEX_SHADER ? "vertex" : "fragment", log));
  }
  return shader;
}

void set_identity_instance() {
  // Attributes 3..7 with their arrays disabled take these constants: identity model, white.
  glDisableVertexAttribArray(3);
  glDisableVertexAttribArray(4);
  glDisableVertexAttribArray(5);
  glDisableVertexAttribArray(6);
  glDisableVertexAttribArray(7);
  glVertexAttrib4f(3, 1.0f, 0.0f, 0.0f, 0.0f);
  glVertexAttrib4f(4, 0.0f, 1.0f, 0.0f, 0.0f);
  glVertexAttrib4f(5, 0.0f, 0.0f, 1.0f, 0.0f);
  glVertexAttrib4f(6, 0.0f, 0.0f, 0.0f, 1.0f);
  glVertexAttrib4f(7, 1.0f, 1.0f, 1.0f, 1.0f);
}

// Whether a body of radius `reach_m` around `centre` can appear in `view` (cheap frustum
// test in camera coordinates; saves vertex work for the many pedestrians behind a camera).
bool maybe_visible(const camera_view& view, const Eigen::Matrix3d& axes,
                   const Eigen::Vector3d& centre, double reach_m) {
  const Eigen::Vector3d c = axes.transpose() * (centre - view.placement.position_m);
  if (c.z() < -reach_m) return false;
  const double f = view.focal_px();
  const double half_w = 0.5 * view.width_px / f;
  const double half_h = 0.5 * view.height_px / f;
  const double z = std::max(c.z(), 0.0);
  // reach * sqrt(1 + slope^2) bounds the distance from the frustum plane.
  return std::abs(c.x()) <= z * half_w + reach_m * std::sqrt(1.0 + half_w * half_w) &&
         std::abs(c.y()) <= z * half_h + reach_m * std::sqrt(1.0 + half_h * half_h);
}

// Rows come out top-down (flip_y), as OpenCV stores them: no flip after read-back.
Eigen::Matrix4f view_projection(const camera_view& view) {
  return view.gl_projection(renderer::near_m, renderer::far_m, true) * view.gl_view();
}

// Maps the frame's clip space to that of field `parity` (0: rows 0, 2, ...; 1: rows 1, 3, ...)
// of `rows` rows drawn into a viewport of its own: the centre of the field's row k lands
// where the centre of the frame's row 2k + parity was. In window coordinates of a frame of
// `height` rows, y' = (y - parity + 1/2) / 2; in normalised device coordinates that is
// y'_ndc = y_ndc * height / (2 rows) + (height / 2 - parity + 1/2) / rows - 1.
Eigen::Matrix4f field_projection(int height, int parity, int rows) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  const double scale = static_cast<double>(height) / (2.0 * rows);
  const double offset = (height / 2.0 - parity + 0.5) / rows - 1.0;
  m(1, 1) = static_cast<float>(scale);
  m(1, 3) = static_cast<float>(offset);
  return m;
}

}  // namespace

struct renderer::gl_objects {
  GLuint program = 0;
  GLint view_projection = -1;
  GLint eye = -1;
  GLint lit = -1;
  GLuint scene_vao = 0;
  GLuint scene_vbo = 0;
  GLsizei floor_vertices = 0;
  GLsizei solid_vertices = 0;
  GLuint cube_vao = 0;
  GLuint cube_vbo = 0;
  GLuint instance_vbo = 0;
  GLsizeiptr instance_capacity = 0;
  GLuint framebuffer = 0;
  GLuint color_buffer = 0;
  GLuint depth_buffer = 0;
  int width = 0;
  int height = 0;
  cv::Mat rgba;

  void resize(int w, int h) {
    if (w == width && h == height) return;
    if (framebuffer == 0) {
      glGenFramebuffers(1, &framebuffer);
      glGenRenderbuffers(1, &color_buffer);
      glGenRenderbuffers(1, &depth_buffer);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, color_buffer);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_buffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      throw std::runtime_error(
          fmt::format("renderer: framebuffer of {}x{} incomplete (status 0x{:x})", w, h, status));
    }
    width = w;
    height = h;
    rgba.create(h, w, CV_8UC4);
  }
};

renderer::renderer(std::shared_ptr<const world::station> where)
    : station_(std::move(where)), gl_(std::make_unique<gl_objects>()) {
  context_.make_current();
  try {
    auto& g = *gl_;
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex_shader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_shader);
    g.program = glCreateProgram();
    glAttachShader(g.program, vs);
    glAttachShader(g.program, fs);
    glLinkProgram(g.program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = 0;
    glGetProgramiv(g.program, GL_LINK_STATUS, &linked);
    if (!linked) throw std::runtime_error("renderer: shader program does not link");
    g.view_projection = glGetUniformLocation(g.program, "u_view_projection");
    g.eye = glGetUniformLocation(g.program, "u_eye");
    g.lit = glGetUniformLocation(g.program, "u_lit");

    // Static station geometry: floor layers first, then solids, in one buffer.
    glGenVertexArrays(1, &g.scene_vao);
    glGenBuffers(1, &g.scene_vbo);
    if (station_) {
      scene_mesh mesh = build_scene_mesh(station_->plan());
      g.floor_vertices = static_cast<GLsizei>(mesh.floor.size());
      g.solid_vertices = static_cast<GLsizei>(mesh.solids.size());
      mesh.floor.insert(mesh.floor.end(), mesh.solids.begin(), mesh.solids.end());
      glBindVertexArray(g.scene_vao);
      glBindBuffer(GL_ARRAY_BUFFER, g.scene_vbo);
      glBufferData(GL_ARRAY_BUFFER,
                   static_cast<GLsizeiptr>(mesh.floor.size() * sizeof(mesh_vertex)),
                   mesh.floor.data(), GL_STATIC_DRAW);
      const auto stride = static_cast<GLsizei>(sizeof(mesh_vertex));
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(offsetof(mesh_vertex, position)));
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(offsetof(mesh_vertex, normal)));
      glEnableVertexAttribArray(2);
      glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                            reinterpret_cast<void*>(offsetof(mesh_vertex, color)));
    }

    // The unit cube, drawn instanced for figures and markers.
    glGenVertexArrays(1, &g.cube_vao);
    glGenBuffers(1, &g.cube_vbo);
    glGenBuffers(1, &g.instance_vbo);
    glBindVertexArray(g.cube_vao);
    const auto& cube = unit_cube_vertices();
    glBindBuffer(GL_ARRAY_BUFFER, g.cube_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cube.size() * sizeof(float)), cube.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                          reinterpret_cast<void*>(3 * sizeof(float)));
    glBindBuffer(GL_ARRAY_BUFFER, g.instance_vbo);
    const auto stride = static_cast<GLsizei>(sizeof(box_instance));
    for (GLuint k = 0; k < 4; ++k) {
      glEnableVertexAttribArray(3 + k);
      glVertexAttribPointer(
          3 + k, 4, GL_FLOAT, GL_FALSE, stride,
          reinterpret_cast<void*>(offsetof(box_instance, model) + 4 * k * sizeof(float)));
      glVertexAttribDivisor(3 + k, 1);
    }
    glEnableVertexAttribArray(7);
    glVertexAttribPointer(7, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<void*>(offsetof(box_instance, color)));
    glVertexAttribDivisor(7, 1);
    glBindVertexArray(0);
    if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
      throw std::runtime_error(fmt::format("renderer: OpenGL error 0x{:x} during set-up", e));
    }
  } catch (...) {
    context_.release();
    throw;
  }
  context_.release();
}

renderer::~renderer() {
  try {
    context_.make_current();
  } catch (const std::exception&) {
    return;  // the context goes with its objects
  }
  auto& g = *gl_;
  glDeleteProgram(g.program);
  const GLuint buffers[] = {g.scene_vbo, g.cube_vbo, g.instance_vbo};
  glDeleteBuffers(3, buffers);
  const GLuint arrays[] = {g.scene_vao, g.cube_vao};
  glDeleteVertexArrays(2, arrays);
  if (g.framebuffer != 0) {
    glDeleteFramebuffers(1, &g.framebuffer);
    const GLuint renderbuffers[] = {g.color_buffer, g.depth_buffer};
    glDeleteRenderbuffers(2, renderbuffers);
  }
  context_.release();
}

cv::Mat renderer::render(const camera_view& view, const world::snapshot& frame, double time_s) {
  return render(view, frame.pedestrians(), time_s);
}

void renderer::collect_boxes(const camera_view& view,
                             std::span<const world::pedestrian_state> people, double time_s,
                             std::vector<box_instance>& out) const {
  out.clear();
  const Eigen::Matrix3d axes = view.orientation();
  for (const auto& p : people) {
    const double h = p.look.height_m;
    const Eigen::Vector3d centre{p.position.x(), p.position.y(), h / 2.0};
    if (!maybe_visible(view, axes, centre, 0.6 * h + 0.5)) continue;
    append_pedestrian(p, time_s, out);
  }
}

cv::Mat renderer::render(const camera_view& view, std::span<const world::pedestrian_state> people,
                         double time_s) {
  collect_boxes(view, people, time_s, boxes_);
  const pass whole{0, view.height_px, view_projection(view), &boxes_};
  return draw(view, station_ != nullptr, std::span{&whole, 1}, true, {64, 64, 70});
}

cv::Mat renderer::render_interlaced(const camera_view& view, const world::snapshot& frame,
                                    double first_time_s, double second_time_s) {
  return render_interlaced(view, frame.pedestrians(), first_time_s, frame.pedestrians(),
                           second_time_s);
}

cv::Mat renderer::render_interlaced(const camera_view& view,
                                    std::span<const world::pedestrian_state> first_people,
                                    double first_time_s,
                                    std::span<const world::pedestrian_state> second_people,
                                    double second_time_s) {
  if (view.height_px < 2) return render(view, first_people, first_time_s);
  collect_boxes(view, first_people, first_time_s, boxes_);
  collect_boxes(view, second_people, second_time_s, second_boxes_);
  // The even rows go to the framebuffer's top half, the odd rows below them.
  const int even_rows = (view.height_px + 1) / 2;
  const Eigen::Matrix4f whole = view_projection(view);
  const pass fields[] = {
      {0, even_rows, field_projection(view.height_px, 0, even_rows) * whole, &boxes_},
      {even_rows, view.height_px / 2,
       field_projection(view.height_px, 1, view.height_px / 2) * whole, &second_boxes_}};
  const cv::Mat stacked = draw(view, station_ != nullptr, fields, true, {64, 64, 70});
  cv::Mat woven(stacked.size(), stacked.type());
  for (int k = 0; k < even_rows; ++k) stacked.row(k).copyTo(woven.row(2 * k));
  for (int k = 0; k < view.height_px / 2; ++k)
    stacked.row(even_rows + k).copyTo(woven.row(2 * k + 1));
  return woven;
}

cv::Mat renderer::render_markers(const camera_view& view, std::span<const marker> markers,
                                 world::rgb8 background) {
  boxes_.clear();
  for (const auto& m : markers) {
    boxes_.push_back(
        make_box(m.position_m, Eigen::Vector3d::Constant(m.size_m),
                 Eigen::Vector3f{m.color.r / 255.0f, m.color.g / 255.0f, m.color.b / 255.0f}));
  }
  const pass whole{0, view.height_px, view_projection(view), &boxes_};
  return draw(view, false, std::span{&whole, 1}, false, background);
}

cv::Mat renderer::draw(const camera_view& view, bool with_station, std::span<const pass> passes,
                       bool lit, world::rgb8 background) {
  if (view.width_px <= 0 || view.height_px <= 0) {
    throw std::invalid_argument(
        fmt::format("renderer: image size {}x{} is not positive", view.width_px, view.height_px));
  }
  context_.make_current();
  auto& g = *gl_;
  cv::Mat bgr;
  try {
    g.resize(view.width_px, view.height_px);
    glBindFramebuffer(GL_FRAMEBUFFER, g.framebuffer);
    glViewport(0, 0, view.width_px, view.height_px);
    glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(g.program);
    const Eigen::Vector3f eye = view.placement.position_m.cast<float>();
    glUniform3f(g.eye, eye.x(), eye.y(), eye.z());
    glUniform1f(g.lit, lit ? 1.0f : 0.0f);
    glDisable(GL_CULL_FACE);
    for (const auto& p : passes) {
      glViewport(0, p.first_row, view.width_px, p.rows);
      glUniformMatrix4fv(g.view_projection, 1, GL_FALSE, p.view_projection.data());
      if (with_station && g.floor_vertices + g.solid_vertices > 0) {
        glBindVertexArray(g.scene_vao);
        set_identity_instance();
        // Floor layers are coplanar: painter's order, no depth test, no z-fighting.
        glDisable(GL_DEPTH_TEST);
        glDrawArrays(GL_TRIANGLES, 0, g.floor_vertices);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDrawArrays(GL_TRIANGLES, g.floor_vertices, g.solid_vertices);
      }
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      const auto& boxes = *p.boxes;
      if (!boxes.empty()) {
        glBindVertexArray(g.cube_vao);
        glVertexAttrib4f(2, 1.0f, 1.0f, 1.0f, 0.0f);  // per-vertex colour: white, no pattern
        glBindBuffer(GL_ARRAY_BUFFER, g.instance_vbo);
        const auto bytes = static_cast<GLsizeiptr>(boxes.size() * sizeof(box_instance));
        // New storage when it must grow, and for a second field: the first may still be
        // reading the old one (a frame's passes are drawn before its one read-back).
        const bool grows = bytes > g.instance_capacity;
        if (grows) g.instance_capacity = bytes * 2;
        if (grows || &p != &passes.front())
          glBufferData(GL_ARRAY_BUFFER, g.instance_capacity, nullptr, GL_STREAM_DRAW);
        glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, boxes.data());
        glDrawArraysInstanced(GL_TRIANGLES, 0, 36, static_cast<GLsizei>(boxes.size()));
      }
    }
    glBindVertexArray(0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, view.width_px, view.height_px, GL_RGBA, GL_UNSIGNED_BYTE, g.rgba.data);
    if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
      throw std::runtime_error(fmt::format("renderer: OpenGL error 0x{:x} while drawing", e));
    }
    cv::cvtColor(g.rgba, bgr, cv::COLOR_RGBA2BGR);
  } catch (...) {
    context_.release();
    throw;
  }
  context_.release();
  return bgr;
}

}  // namespace argus::vision

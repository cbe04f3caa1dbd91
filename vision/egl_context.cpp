#include "vision/egl_context.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "fmt/format.h"

namespace argus::vision {
namespace {

// Display creation and eglInitialize are process-wide; serialise them.
std::mutex& setup_mutex() {
  static std::mutex m;
  return m;
}

std::string error_name(EGLint e) {
  switch (e) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      return fmt::format("EGL error 0x{:x}", e);
  }
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + 1, name)) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

}  // namespace

egl_context::egl_context() {
  std::lock_guard guard(setup_mutex());
  // Mesa's llvmpipe hands each frame's tiles to rasterizer threads of its own (one per core by
  // default) and waits for them. Argus renders from as many threads as it has cores already,
  // one context each, so those threads only add two hand-overs per frame and compete for the
  // same cores: rasterizing on the calling thread renders the same pixels 13 % faster through
  // the render pool (bench/RESULTS.md, "Pixels at speed"). Read when the display is first
  // initialised; a user's own setting wins. GPUs ignore it.
  setenv("LP_NUM_THREADS", "0", 0);
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
      eglGetProcAddress("eglQueryDeviceStringEXT"));
  const char* forced = std::getenv("ARGUS_EGL_PLATFORM");
  const std::string only = forced != nullptr ? forced : "";
  std::vector<std::string> failures;
  if (get_platform_display == nullptr) {
    throw std::runtime_error(
        "EGL: eglGetPlatformDisplayEXT is missing (EGL_EXT_platform_base not supported); "
        "install an EGL 1.5 implementation (libegl-mesa0 or the NVIDIA driver)");
  }

  std::vector<EGLDeviceEXT> devices;
  const bool device_platform = has_extension(client, "EGL_EXT_platform_device") &&
                               query_devices != nullptr && query_device_string != nullptr;
  if (device_platform) {
    EGLint count = 0;
    if (query_devices(0, nullptr, &count) && count > 0) {
      devices.resize(static_cast<std::size_t>(count));
      query_devices(count, devices.data(), &count);
      devices.resize(static_cast<std::size_t>(count));
    }
  } else {
    failures.emplace_back("EGL device platform: EGL_EXT_platform_device not supported");
  }
  auto is_software = [&](EGLDeviceEXT d) {
    return has_extension(query_device_string(d, EGL_EXTENSIONS), "EGL_MESA_device_software");
  };
  auto try_devices = [&](bool software_allowed) {
    for (std::size_t i = 0; i < devices.size(); ++i) {
      if (!software_allowed && is_software(devices[i])) continue;
      if (software_allowed && !is_software(devices[i])) continue;  // tried in the first pass
      const std::string name =
          fmt::format("EGL device {}{}", i, is_software(devices[i]) ? " (software)" : "");
      EGLDisplay display = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
      std::string why;
      if (try_display(display, name, why)) return true;
      failures.push_back(name + ": " + why);
    }
    return false;
  };
  auto try_surfaceless = [&] {
    if (!has_extension(client, "EGL_MESA_platform_surfaceless")) {
      failures.emplace_back("surfaceless platform: EGL_MESA_platform_surfaceless not supported");
      return false;
    }
    EGLDisplay display =
        get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    std::string why;
    if (try_display(display, "surfaceless platform", why)) return true;
    failures.push_back("surfaceless platform: " + why);
    return false;
  };

  bool done = false;
  if (only.empty() || only == "device") done = try_devices(false);
  if (!done && (only.empty() || only == "surfaceless")) done = try_surfaceless();
  if (!done && (only.empty() || only == "device")) done = try_devices(true);
  if (done) return;
  std::string message = "EGL: no headless OpenGL ES 3 context could be created";
  if (!only.empty()) message += fmt::format(" (ARGUS_EGL_PLATFORM={})", only);
  if (only == "device" && devices.empty()) failures.emplace_back("no EGL devices found");
  for (const auto& f : failures) message += "; " + f;
  throw std::runtime_error(message);
}

bool egl_context::try_display(void* display_handle, const std::string& platform, std::string& why) {
  EGLDisplay display = display_handle;
  if (display == EGL_NO_DISPLAY) {
    why = "no display (" + error_name(eglGetError()) + ")";
    return false;
  }
  EGLint major = 0;
  EGLint minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    why = "eglInitialize failed (" + error_name(eglGetError()) + ")";
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_ES_API)) {
    why = "eglBindAPI(EGL_OPENGL_ES_API) failed (" + error_name(eglGetError()) + ")";
    return false;
  }
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
    why = "EGL_KHR_surfaceless_context not supported";
    return false;
  }
  // Rendering goes to a framebuffer object, so the config only has to support ES 3.
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs == 0) {
    if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
      why = "no OpenGL ES 3 config";
      return false;
    }
    config = EGL_NO_CONFIG_KHR;
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) {
    why = "eglCreateContext (OpenGL ES 3) failed (" + error_name(eglGetError()) + ")";
    return false;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    why = "eglMakeCurrent failed (" + error_name(eglGetError()) + ")";
    eglDestroyContext(display, context);
    return false;
  }
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  description_ =
      fmt::format("{} (EGL {}.{}) / {} / {}", platform, major, minor,
                  renderer != nullptr ? renderer : "?", version != nullptr ? version : "?");
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  display_ = display;
  context_ = context;
  return true;
}

egl_context::~egl_context() {
  if (context_ == nullptr) return;
  // The display is shared by every context of the process, so it is never terminated here.
  if (eglGetCurrentContext() == context_) release();
  eglDestroyContext(display_, context_);
}

void egl_context::make_current() {
  if (eglGetCurrentContext() == context_) return;
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    throw std::runtime_error(
        fmt::format("EGL: eglMakeCurrent failed ({}); is the context "
                    "still current in another thread?",
                    error_name(eglGetError())));
  }
}

void egl_context::release() noexcept {
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

}  // namespace argus::vision

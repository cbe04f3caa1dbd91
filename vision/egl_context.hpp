#pragma once

#include <string>

namespace argus::vision {

/// One headless OpenGL ES 3 context through EGL, with no window system: the NVIDIA driver
/// through the EGL device platform where a GPU exists, else Mesa (llvmpipe on a CPU-only
/// machine) through the surfaceless platform. The platform is chosen when the context is made:
///
///   1. EGL_EXT_platform_device, hardware devices (skipping Mesa's software device);
///   2. EGL_MESA_platform_surfaceless;
///   3. EGL_EXT_platform_device, any device (software included).
///
/// The environment variable ARGUS_EGL_PLATFORM = "device" or "surfaceless" forces one. A
/// context is current in at most one thread: make_current() before GL calls, release() after,
/// so that the owner may move between threads (an actor on a work-stealing scheduler).
class egl_context {
 public:
  /// Opens a display and creates the context; throws std::runtime_error naming every
  /// platform tried and why it failed when none works.
  egl_context();
  ~egl_context();
  egl_context(const egl_context&) = delete;
  egl_context& operator=(const egl_context&) = delete;

  /// Binds the context to the calling thread; throws std::runtime_error if EGL refuses (for
  /// instance because another thread still holds it).
  void make_current();
  /// Unbinds the context from the calling thread.
  void release() noexcept;

  /// "EGL device / NVIDIA ... / OpenGL ES 3.2 ..." or similar: what renders, for logs.
  const std::string& description() const noexcept { return description_; }

 private:
  bool try_display(void* display, const std::string& platform, std::string& why);

  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
};

}  // namespace argus::vision

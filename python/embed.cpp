#include "python/embed.hpp"

#include <filesystem>
#include <mutex>
#include <string>

#include "pybind11/embed.h"
#include "python/bindings.hpp"
#include "python/python_strategy.hpp"

// In the executable, `_argus` is a built-in module: argus/__init__.py imports it rather than
// loading the extension, a second copy of the simulator.
PYBIND11_EMBEDDED_MODULE(_argus, m) {
  argus::pybridge::bind_all(m);
}

namespace argus::pybridge {
namespace {

void start_interpreter() {
  static std::once_flag once;
  std::call_once(once, [] {
    py::initialize_interpreter();
    {
      // The package of an installed argus (PREFIX/bin/argus, PREFIX/lib/argus/python), else the
      // build tree's; after PYTHONPATH's.
      auto path = py::module_::import("sys").attr("path");
      std::error_code ec;
      const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
      const auto installed = exe.parent_path().parent_path() / ARGUS_PYTHON_INSTALL_DIR;
      const bool is_installed =
          !ec && std::filesystem::exists(installed / "argus" / "__init__.py", ec);
      path.attr("append")(is_installed ? installed.string() : std::string(ARGUS_PYTHON_DIR));
    }
    // Camera nodes step their strategies on the scheduler's threads: they take the GIL in
    // turn. The interpreter lives until the process ends.
    PyEval_SaveThread();
  });
}

}  // namespace

void enable_embedded_python() {
  serve_python_strategies(start_interpreter);
}

}  // namespace argus::pybridge

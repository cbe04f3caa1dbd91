#include "python/python_strategy.hpp"

#include <filesystem>
#include <mutex>
#include <stdexcept>

#include "fmt/format.h"

namespace argus::pybridge {
namespace {

// Camera nodes step their Python strategies from several scheduler threads. Handing the GIL
// itself from thread to thread forces a switch each time (the waiter signals, the holder waits
// until it has taken over): the run spent more time in the kernel than in Python. The nodes
// queue on this mutex instead and find the GIL free.
std::mutex& python_turn() {
  static std::mutex m;
  return m;
}

// A scheduler thread's Python thread state, made once and kept: taking the GIL on a thread
// without one makes a state and frees it again on release, a memory map and unmap per step.
bool keep_thread_state() {
  thread_local bool kept = false;
  if (kept) return true;
  kept = true;
  PyGILState_Ensure();  // this thread's state, with the GIL
  PyEval_SaveThread();  // the GIL released, the state kept for every later call
  return true;
}

// The GIL, taken after the turn, on the thread's own state.
struct python_call {
  std::lock_guard<std::mutex> turn{python_turn()};
  bool kept = keep_thread_state();
  py::gil_scoped_acquire gil;
};

// The Python exception as one line (and its traceback's last frame, where it has one).
std::string describe(py::error_already_set& e) {
  std::string where;
  if (e.trace()) {
    py::object tb = e.trace();
    while (!tb.attr("tb_next").is_none()) tb = tb.attr("tb_next");
    const auto code = tb.attr("tb_frame").attr("f_code");
    where = fmt::format(" (in {}, {} line {})", py::str(code.attr("co_name")).cast<std::string>(),
                        py::str(code.attr("co_filename")).cast<std::string>(),
                        tb.attr("tb_lineno").cast<int>());
  }
  std::string type = py::str(e.type().attr("__name__"));
  std::string message = py::str(e.value());
  return fmt::format("{}: {}{}", type, message, where);
}

// A strategy whose Python constructor raised: it fails at its first step, so that the run ends
// as for any raising strategy (the node names the camera and the tick).
class failed_strategy final : public controller::strategy {
 public:
  explicit failed_strategy(std::string why) : why_(std::move(why)) {}
  controller::frame_plan plan(std::int64_t, bool) override { throw std::runtime_error(why_); }
  controller::controller_output step(const controller::controller_input&) override {
    throw std::runtime_error(why_);
  }
  controller::strategy_status status() const override { return {}; }

 private:
  std::string why_;
};

class python_strategy final : public controller::strategy {
 public:
  // With the GIL held.
  explicit python_strategy(py::object object) : object_(std::move(object)) {
    step_ = object_.attr("step");
    status_fn_ = object_.attr("status");
    // plan() is called only where the class overrides argus.Strategy's: the default costs a call.
    const auto base = py::module_::import("argus").attr("Strategy").attr("plan");
    if (!py::type::of(object_).attr("plan").is(base)) plan_ = object_.attr("plan");
    takes_signatures_ = py::bool_(object_.attr("takes_operator_signatures"));
    status_ = status_fn_().cast<controller::strategy_status>();
  }

  ~python_strategy() override {
    python_call call;
    plan_ = py::object();
    step_ = py::object();
    status_fn_ = py::object();
    object_ = py::object();
  }

  controller::frame_plan plan(std::int64_t tick, bool looking) override {
    if (!plan_) return strategy::plan(tick, looking);
    python_call call;
    try {
      py::object r = plan_(tick, looking);
      controller::frame_plan p;
      if (py::isinstance<controller::frame_plan>(r))
        p = r.cast<controller::frame_plan>();
      else
        p.wants_frame = py::bool_(r);
      return p;
    } catch (py::error_already_set& e) {
      throw std::runtime_error(describe(e));
    }
  }

  controller::controller_output step(const controller::controller_input& in) override {
    python_call call;
    try {
      py::object r = step_(py::cast(in, py::return_value_policy::copy));
      controller::controller_output out;
      if (!r.is_none()) {
        if (!py::isinstance<controller::controller_output>(r))
          throw std::runtime_error(
              fmt::format("step() returned a {}, not an argus.Output (or None)",
                          py::str(py::type::of(r).attr("__name__")).cast<std::string>()));
        out = std::move(r.cast<controller::controller_output&>());
      }
      py::object s = status_fn_();
      if (!py::isinstance<controller::strategy_status>(s))
        throw std::runtime_error(
            fmt::format("status() returned a {}, not an argus.Status",
                        py::str(py::type::of(s).attr("__name__")).cast<std::string>()));
      status_ = s.cast<controller::strategy_status>();
      return out;
    } catch (py::error_already_set& e) {
      throw std::runtime_error(describe(e));
    }
  }

  controller::strategy_status status() const override { return status_; }
  bool takes_operator_signatures() const override { return takes_signatures_; }

 private:
  py::object object_;
  py::object step_;
  py::object status_fn_;
  py::object plan_;
  bool takes_signatures_ = true;
  // The status after the last step: the node asks for it without calling into Python.
  controller::strategy_status status_;
};

// `python:MODULE:CLASS`, split at its last colon.
std::pair<std::string, std::string> module_and_class(const std::string& value) {
  const auto rest = value.substr(std::string("python:").size());
  const auto colon = rest.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == rest.size())
    throw std::runtime_error(fmt::format(
        "'{}': expected python:MODULE:CLASS, e.g. python:my_strategies:Follower", value));
  return {rest.substr(0, colon), rest.substr(colon + 1)};
}

}  // namespace

std::shared_ptr<py::object> keep(py::object object) {
  return std::shared_ptr<py::object>(new py::object(std::move(object)), [](py::object* o) {
    if (Py_IsInitialized() == 0) return;  // the interpreter is gone: so is what o held
    py::gil_scoped_acquire gil;
    delete o;
  });
}

controller::strategy_entry python_entry(std::string name, py::object factory) {
  controller::strategy_entry entry;
  entry.name = name;
  entry.summary = "written in Python";
  const auto doc = py::getattr(factory, "__doc__", py::none());
  if (!doc.is_none()) {
    auto text = py::str(doc).cast<std::string>();
    text = text.substr(0, text.find('\n'));
    if (!text.empty()) entry.summary = text;
  }
  entry.source = "python";
  auto made_by = keep(std::move(factory));
  entry.make = [made_by, name](
                   const controller::strategy_context& c) -> std::unique_ptr<controller::strategy> {
    python_context context{c.me, c.scenario.run.tick.count(), c.scenario.run.seed, c.scenario.name,
                           name};
    py::gil_scoped_acquire gil;
    try {
      return std::make_unique<python_strategy>((*made_by)(context));
    } catch (py::error_already_set& e) {
      return std::make_unique<failed_strategy>(
          fmt::format("its constructor raised {}", describe(e)));
    } catch (const std::exception& e) {
      return std::make_unique<failed_strategy>(e.what());
    }
  };
  return entry;
}

void serve_python_strategies(std::function<void()> ready) {
  controller::register_strategy_source(
      "python:", [ready](const std::string& value) -> controller::strategy_entry {
        auto [module, cls] = module_and_class(value);
        if (ready) ready();
        py::gil_scoped_acquire gil;
        try {
          auto path = py::module_::import("sys").attr("path");
          const auto here = std::filesystem::current_path().string();
          if (!path.contains(here)) path.attr("append")(here);
          auto factory = py::module_::import(module.c_str()).attr(cls.c_str());
          const auto base = py::module_::import("argus").attr("Strategy");
          int subclass = 0;
          if (py::isinstance<py::type>(factory)) {
            subclass = PyObject_IsSubclass(factory.ptr(), base.ptr());
            if (subclass < 0) PyErr_Clear();
          }
          if (subclass != 1)
            throw std::runtime_error(
                fmt::format("'{}': {}.{} is not a subclass of argus.Strategy", value, module, cls));
          return python_entry(value, factory);
        } catch (py::error_already_set& e) {
          throw std::runtime_error(
              fmt::format("'{}': Python could not load it: {}", value, describe(e)));
        }
      });
}

}  // namespace argus::pybridge

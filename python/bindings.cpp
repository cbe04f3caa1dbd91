#include "python/bindings.hpp"

#include <cstring>

#include "config/scenario_error.hpp"
#include "controller/strategy_registry.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "pybind11/numpy.h"
#include "pybind11/operators.h"
#include "pybind11/stl.h"
#include "python/env_session.hpp"
#include "python/python_strategy.hpp"
#include "python/run_call.hpp"
#include "vision/fixate_zoom.hpp"

namespace argus::pybridge {
namespace {

using namespace controller;
using nlohmann::ordered_json;

// A Python value as JSON, for an event's fields (insertion order kept, as the dict's).
ordered_json to_json(py::handle v) {
  if (v.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::int_>(v)) return v.cast<long long>();
  if (py::isinstance<py::float_>(v)) return v.cast<double>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::dict>(v)) {
    ordered_json o = ordered_json::object();
    for (auto [key, value] : v.cast<py::dict>())
      o[py::str(key).cast<std::string>()] = to_json(value);
    return o;
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    ordered_json a = ordered_json::array();
    for (auto item : v) a.push_back(to_json(item));
    return a;
  }
  if (py::hasattr(v, "item")) return to_json(v.attr("item")());  // a NumPy scalar
  throw py::type_error(fmt::format("an event field cannot be a {}",
                                   py::str(py::type::of(v).attr("__name__")).cast<std::string>()));
}

// JSON members without braces, as controller_event wants them.
std::string fields_of(const py::dict& fields) {
  if (fields.empty()) return {};
  const auto text = to_json(fields).dump();
  return text.substr(1, text.size() - 2);
}

py::object image_of(const cv::Mat& image) {
  if (image.empty()) return py::none();
  py::array_t<std::uint8_t> a({image.rows, image.cols, image.channels()});
  for (int r = 0; r < image.rows; ++r)
    std::memcpy(a.mutable_data(r), image.ptr(r),
                static_cast<std::size_t>(image.cols) * static_cast<std::size_t>(image.channels()));
  return a;
}

protocol::group_message note_of(int sender, std::string topic, py::bytes body, task_id task) {
  return protocol::note{task, sender, std::move(topic), std::string(body)};
}

void bind_geometry(py::module_& m) {
  py::class_<vision::ptz_state>(m, "Pose", "A pan/tilt/zoom pose, in degrees")
      .def(py::init([](double pan, double tilt, double fov) {
             return vision::ptz_state{pan, tilt, fov};
           }),
           py::arg("pan_deg") = 0.0, py::arg("tilt_deg") = -20.0,
           py::arg("field_of_view_deg") = 45.0)
      .def_readwrite("pan_deg", &vision::ptz_state::pan_deg)
      .def_readwrite("tilt_deg", &vision::ptz_state::tilt_deg)
      .def_readwrite("field_of_view_deg", &vision::ptz_state::field_of_view_deg)
      .def(py::self == py::self)
      .def("__repr__", [](const vision::ptz_state& p) {
        return fmt::format("Pose(pan_deg={}, tilt_deg={}, field_of_view_deg={})", p.pan_deg,
                           p.tilt_deg, p.field_of_view_deg);
      });
  py::class_<config::degree_range>(m, "Range")
      .def_readonly("min_deg", &config::degree_range::min_deg)
      .def_readonly("max_deg", &config::degree_range::max_deg)
      .def("__repr__", [](const config::degree_range& r) {
        return fmt::format("Range({}, {})", r.min_deg, r.max_deg);
      });
  py::class_<vision::ptz_limits>(m, "Limits", "A head's ranges and slew rates")
      .def_readonly("pan", &vision::ptz_limits::pan)
      .def_readonly("tilt", &vision::ptz_limits::tilt)
      .def_readonly("field_of_view", &vision::ptz_limits::field_of_view)
      .def_readonly("pan_rate_deg_per_s", &vision::ptz_limits::pan_rate_deg_per_s)
      .def_readonly("tilt_rate_deg_per_s", &vision::ptz_limits::tilt_rate_deg_per_s)
      .def_readonly("zoom_rate_deg_per_s", &vision::ptz_limits::zoom_rate_deg_per_s)
      .def("clamp", &vision::ptz_limits::clamp, "The pose moved into the ranges");
  py::class_<vision::frame_size>(m, "FrameSize")
      .def_readonly("width_px", &vision::frame_size::width_px)
      .def_readonly("height_px", &vision::frame_size::height_px);
  py::class_<cv::Rect2d>(m, "Box", "A box in pixels: x, y its top-left corner")
      .def(py::init<double, double, double, double>(), py::arg("x"), py::arg("y"), py::arg("width"),
           py::arg("height"))
      .def_readwrite("x", &cv::Rect2d::x)
      .def_readwrite("y", &cv::Rect2d::y)
      .def_readwrite("width", &cv::Rect2d::width)
      .def_readwrite("height", &cv::Rect2d::height)
      .def("__repr__", [](const cv::Rect2d& b) {
        return fmt::format("Box(x={}, y={}, width={}, height={})", b.x, b.y, b.width, b.height);
      });
  py::class_<node_identity>(m, "NodeIdentity", "What a camera node knows of itself")
      .def_readonly("id", &node_identity::id)
      .def_readonly("limits", &node_identity::limits)
      .def_readonly("home", &node_identity::home)
      .def_readonly("frame", &node_identity::frame);
  m.def("centring_pose", &vision::centring_pose, py::arg("pose"), py::arg("box"), py::arg("frame"),
        py::arg("height_fraction") = 0.5,
        "The pose that centres `box` with its height `height_fraction` of the frame's");
}

void bind_inputs(py::module_& m) {
  py::class_<protocol::signature>(m, "Signature", "An appearance signature (HSV histogram)")
      .def(py::init<>())
      .def_readwrite("hue_bins", &protocol::signature::hue_bins)
      .def_readwrite("saturation_bins", &protocol::signature::saturation_bins)
      .def_readwrite("value_bins", &protocol::signature::value_bins)
      .def_readwrite("values", &protocol::signature::values)
      .def_readwrite("upper", &protocol::signature::upper)
      .def_readwrite("lower", &protocol::signature::lower)
      .def(py::self == py::self);
  py::class_<protocol::task_description>(m, "TaskDescription")
      .def_readonly("task", &protocol::task_description::task)
      .def_readonly("target", &protocol::task_description::target)
      .def_readonly("min_cameras", &protocol::task_description::min_cameras)
      .def_readonly("max_cameras", &protocol::task_description::max_cameras);
  py::class_<look_result>(m, "LookResult", "What the sensor saw of a target asked for")
      .def_readonly("task", &look_result::task)
      .def_readonly("found", &look_result::found)
      .def_readonly("box", &look_result::box)
      .def_readonly("score", &look_result::score)
      .def_readonly("model", &look_result::model);
  py::class_<operator_query>(m, "OperatorQuery")
      .def_readonly("task", &operator_query::task)
      .def_readonly("box", &operator_query::box);
  py::class_<acquired_signature>(m, "AcquiredSignature")
      .def_readonly("task", &acquired_signature::task)
      .def_readonly("signature", &acquired_signature::signature);
  py::class_<received_message>(m, "ReceivedMessage")
      .def_readonly("origin", &received_message::origin)
      .def_property_readonly(
          "kind",
          [](const received_message& r) { return std::string(protocol::kind_of(r.message)); })
      .def_property_readonly("task",
                             [](const received_message& r) { return protocol::task_of(r.message); })
      .def_property_readonly("topic",
                             [](const received_message& r) -> py::object {
                               if (auto* n = std::get_if<protocol::note>(&r.message))
                                 return py::str(n->topic);
                               return py::none();
                             })
      .def_property_readonly("body", [](const received_message& r) -> py::object {
        if (auto* n = std::get_if<protocol::note>(&r.message)) return py::bytes(n->body);
        return py::none();
      });
  py::class_<controller_input>(m, "Input", "One frame's inputs (controller/controller_io.hpp)")
      .def_readonly("tick", &controller_input::tick)
      .def_readonly("pose", &controller_input::pose)
      .def_readonly("sensed", &controller_input::sensed)
      .def_property_readonly("image", [](const controller_input& in) { return image_of(in.image); })
      .def_readonly("looks", &controller_input::looks)
      .def_readonly("acquired", &controller_input::acquired)
      .def_readonly("queries", &controller_input::queries)
      .def_readonly("messages", &controller_input::messages)
      .def_readonly("cancels", &controller_input::cancels);
}

void bind_outputs(py::module_& m) {
  m.attr("BROADCAST") = protocol::broadcast;
  py::class_<controller_output>(m, "Output", "One frame's outputs, built with its methods")
      .def(py::init<>())
      .def_property(
          "command", [](const controller_output& o) { return o.command; },
          [](controller_output& o, std::optional<vision::ptz_state> p) { o.command = p; },
          "The pose to slew towards (None: keep the last)")
      .def(
          "look",
          [](controller_output& o, task_id task, const protocol::signature& target) {
            o.looks.push_back({task, target});
          },
          py::arg("task"), py::arg("target"), "Look for task's target in the next frame")
      .def(
          "send",
          [](controller_output& o, int destination, std::string topic, py::bytes body,
             task_id task) {
            o.messages.push_back({destination, note_of(0, std::move(topic), body, task)});
          },
          py::arg("destination"), py::arg("topic"), py::arg("body") = py::bytes(),
          py::arg("task") = 0,
          "Send a note to one node (argus.BROADCAST: every node within the hop limit)")
      .def(
          "event",
          [](controller_output& o, std::string kind, std::optional<py::dict> fields,
             const py::kwargs& more) {
            py::dict all;
            if (fields)
              for (auto [k, v] : *fields) all[k] = v;
            for (auto [k, v] : more) all[k] = v;
            o.events.push_back({std::move(kind), fields_of(all)});
          },
          py::arg("kind"), py::arg("fields") = py::none(), "Log an event (kind and JSON fields)")
      .def(
          "acquire",
          [](controller_output& o, task_id task, const cv::Rect2d& box) {
            o.acquire.push_back({task, box});
          },
          py::arg("task"), py::arg("box"), "Take the signature of whoever is in box as task's")
      .def_property_readonly("looks",
                             [](const controller_output& o) {
                               std::vector<task_id> tasks;
                               for (const auto& l : o.looks) tasks.push_back(l.task);
                               return tasks;
                             })
      .def_property_readonly("events", [](const controller_output& o) {
        std::vector<std::pair<std::string, std::string>> events;
        for (const auto& e : o.events) events.emplace_back(e.kind, e.fields_json);
        return events;
      });
}

void bind_status(py::module_& m) {
  py::enum_<node_state>(m, "NodeState")
      .value("idle", node_state::idle)
      .value("computing_relevance", node_state::computing_relevance)
      .value("performing_task", node_state::performing_task);
  py::enum_<group_role>(m, "GroupRole")
      .value("member", group_role::member)
      .value("leader", group_role::leader);
  py::enum_<vision::tracking_state>(m, "TrackingState")
      .value("track", vision::tracking_state::track)
      .value("wait", vision::tracking_state::wait)
      .value("search", vision::tracking_state::search)
      .value("failed", vision::tracking_state::failed);
  py::class_<strategy_status>(m, "Status", "A strategy's state after its last step")
      .def(py::init([](node_state state, std::optional<task_id> task, group_role role,
                       vision::tracking_state tracking) {
             return strategy_status{state, task, role, tracking};
           }),
           py::arg("state") = node_state::idle, py::arg("task") = py::none(),
           py::arg("role") = group_role::member,
           py::arg("tracking") = vision::tracking_state::track)
      .def_readwrite("state", &strategy_status::state)
      .def_readwrite("task", &strategy_status::task)
      .def_readwrite("role", &strategy_status::role)
      .def_readwrite("tracking", &strategy_status::tracking);
  py::class_<frame_plan>(m, "Plan")
      .def(py::init([](bool wants_frame) {
             frame_plan p;
             p.wants_frame = wants_frame;
             return p;
           }),
           py::arg("wants_frame") = false)
      .def_readwrite("wants_frame", &frame_plan::wants_frame);
  py::class_<python_context>(m, "StrategyContext", "What a strategy is constructed with")
      .def_readonly("me", &python_context::me)
      .def_readonly("tick_s", &python_context::tick_s)
      .def_readonly("seed", &python_context::seed)
      .def_readonly("scenario", &python_context::scenario)
      .def_readonly("strategy", &python_context::strategy);
}

py::dict collected_dict(env_exchange::collected c) {
  py::dict d;
  d["tick"] = c.tick;
  py::dict inputs;
  for (auto& [id, in] : c.inputs) inputs[py::int_(id)] = py::cast(std::move(in));
  d["inputs"] = inputs;
  d["gone"] = c.gone;
  d["finished"] = c.finished;
  d["error"] = c.error;
  return d;
}

void bind_env(py::module_& m) {
  py::class_<env_action>(m, "EnvAction")
      .def(py::init<>())
      .def_readwrite("command", &env_action::command)
      .def_readwrite("looks", &env_action::looks)
      .def(
          "send",
          [](env_action& a, int destination, std::string topic, py::bytes body, task_id task) {
            a.messages.push_back({destination, note_of(0, std::move(topic), body, task)});
          },
          py::arg("destination"), py::arg("topic"), py::arg("body") = py::bytes(),
          py::arg("task") = 0);
  py::class_<env_session>(m, "EnvSession")
      .def(py::init<const std::string&, const std::vector<std::string>&>())
      .def("cameras", &env_session::cameras)
      .def_property_readonly("pixels", &env_session::pixels)
      .def_property_readonly("tick_s",
                             [](const env_session& s) { return s.scenario().run.tick.count(); })
      .def_property_readonly("name", [](const env_session& s) { return s.scenario().name; })
      .def("reset",
           [](env_session& s, std::optional<std::uint64_t> seed, const std::string& out) {
             env_exchange::collected c;
             {
               py::gil_scoped_release free;
               c = s.reset(seed, out);
             }
             return collected_dict(std::move(c));
           })
      .def("step",
           [](env_session& s, std::map<int, env_action> actions) {
             env_exchange::collected c;
             {
               py::gil_scoped_release free;
               c = s.step(std::move(actions));
             }
             return collected_dict(std::move(c));
           })
      .def("close", &env_session::close, py::call_guard<py::gil_scoped_release>());
}

}  // namespace

void bind_all(py::module_& m) {
  m.doc() = "Argus, smart camera networks in virtual reality: the simulator's C++ core";
  m.attr("__version__") = ARGUS_VERSION;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const config::scenario_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  bind_geometry(m);
  bind_inputs(m);
  bind_outputs(m);
  bind_status(m);
  bind_env(m);
  m.def("_run", &run_from_python, py::arg("scenario"), py::arg("set"), py::arg("strategy"),
        py::arg("progress"));
  m.def("_strategies", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& e : registered_strategies()) out.emplace_back(e.name, e.summary);
    return out;
  });
}

}  // namespace argus::pybridge

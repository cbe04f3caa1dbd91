#include "serve/console_server.hpp"

#include <httplib.h>

#include <random>
#include <stdexcept>
#include <string_view>

#include "fmt/format.h"
#include "nlohmann/json.hpp"
#include "protocol/topology.hpp"
#include "serve/console_page.hpp"
#include "serve/feed_renderer.hpp"
#include "world/plan_view.hpp"

namespace argus::serve {
namespace {

// Replies can echo what a client sent (a path, a field), which need not be UTF-8: such bytes are
// replaced, since a throwing dump() in a handler would end the whole run.
std::string json_text(const nlohmann::json& j) {
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void reply_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content(json_text({{"error", message}}), "application/json");
}

void reply_json(httplib::Response& res, const nlohmann::json& j, int status = 200) {
  res.status = status;
  res.set_content(json_text(j), "application/json");
  res.set_header("Cache-Control", "no-store");
}

// The plan as the page shows it: no labels (the page draws its own).
world::plan_view_options plan_options() {
  world::plan_view_options options;
  options.labels = false;
  return options;
}

// The plan's static part and how to draw on it: metres to the PNG's pixels.
std::string plan_description(const config::scenario& scenario, const world::station& where,
                             const world::plan_view_options& options) {
  const auto origin = world::plan_pixel(where, options, {0.0, 0.0});
  nlohmann::json j;
  j["pixels_per_m"] = options.pixels_per_m;
  j["origin_px"] = {origin[0], origin[1]};  // where (0, 0) m is; y grows up on the plan
  j["size_m"] = {where.plan().size_m.x(), where.plan().size_m.y()};
  j["tick_s"] = scenario.run.tick.count();
  auto& cameras = j["cameras"] = nlohmann::json::array();
  for (const auto& c : scenario.cameras)
    cameras.push_back({{"id", c.id},
                       {"x", c.position.x_m},
                       {"y", c.position.y_m},
                       {"width_px", c.imaging.width_px},
                       {"height_px", c.imaging.height_px}});
  j["links"] = protocol::topology(scenario).links();
  j["scenario"] = scenario.name;
  return json_text(j);
}

}  // namespace

console_server::console_server(const config::scenario& scenario,
                               std::shared_ptr<const world::station> where,
                               std::shared_ptr<live::session> session)
    : scenario_(scenario),
      station_(std::move(where)),
      session_(std::move(session)),
      feeds_(std::make_unique<feed_renderer>(scenario_, station_)),
      server_(std::make_unique<httplib::Server>()) {
  plan_json_ = plan_description(scenario_, *station_, plan_options());
}

console_server::~console_server() {
  stop();
}

std::string make_console_token() {
  std::random_device entropy;
  std::string out;
  for (int i = 0; i < 4; ++i) out += fmt::format("{:08x}", entropy());
  return out;
}

namespace {

// Compares in time independent of where the strings first differ.
bool same_secret(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

// The value of cookie `name` in a Cookie header, or empty.
std::string_view cookie(std::string_view header, std::string_view name) {
  while (!header.empty()) {
    auto end = header.find(';');
    auto item = header.substr(0, end);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    if (item.size() > name.size() && item.substr(0, name.size()) == name &&
        item[name.size()] == '=')
      return item.substr(name.size() + 1);
    if (end == std::string_view::npos) break;
    header.remove_prefix(end + 1);
  }
  return {};
}

}  // namespace

bool console_server::authorised(const httplib::Request& req, httplib::Response& res) const {
  const auto& token = settings_.token;
  if (token.empty()) return true;
  if (req.has_param("token") && same_secret(req.get_param_value("token"), token)) {
    // The page's own requests (the stream, the feeds, the commands) then carry the cookie.
    res.set_header("Set-Cookie", "argus_token=" + token + "; Path=/; HttpOnly; SameSite=Strict");
    return true;
  }
  const auto bearer = req.get_header_value("Authorization");
  if (bearer.rfind("Bearer ", 0) == 0 && same_secret(std::string_view(bearer).substr(7), token))
    return true;
  return same_secret(cookie(req.get_header_value("Cookie"), "argus_token"), token);
}

void console_server::routes() {
  auto& svr = *server_;
  svr.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (authorised(req, res)) return httplib::Server::HandlerResponse::Unhandled;
    res.status = 401;
    res.set_content(
        "This console listens beyond loopback and needs its secret: open the address argus serve "
        "printed (with ?token=...).\n",
        "text/plain; charset=utf-8");
    return httplib::Server::HandlerResponse::Handled;
  });
  svr.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(std::string(console_page), "text/html; charset=utf-8");
  });
  svr.Get("/plan.png", [this](const httplib::Request&, httplib::Response& res) {
    std::call_once(plan_drawn_, [this] {
      const auto png = world::render_plan_view(*station_, {}, nullptr, nullptr, plan_options());
      plan_png_.assign(png.begin(), png.end());
    });
    res.set_content(plan_png_, "image/png");
  });
  svr.Get("/plan.json", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(plan_json_, "application/json");
  });
  svr.Get("/state", [this](const httplib::Request&, httplib::Response& res) {
    auto j = session_->console.state_json();
    j["speed"] = session_->pace.speed();
    j["paused"] = session_->pace.paused();
    reply_json(res, j);
  });
  svr.Get("/events", [this](const httplib::Request&, httplib::Response& res) {
    if (streams_.fetch_add(1) >= settings_.max_streams) {
      streams_.fetch_sub(1);
      reply_error(res, 503,
                  fmt::format("too many live streams open (at most {})", settings_.max_streams));
      return;
    }
    res.set_header("Cache-Control", "no-store");
    // One message per interval, built when sent: a slow client gets fewer, never a backlog.
    res.set_chunked_content_provider(
        "text/event-stream",
        [this](std::size_t, httplib::DataSink& sink) {
          if (stopping_.load()) return false;
          auto j = session_->console.state_json();
          j["speed"] = session_->pace.speed();
          j["paused"] = session_->pace.paused();
          const auto message = "data: " + json_text(j) + "\n\n";
          if (!sink.is_writable() || !sink.write(message.data(), message.size())) return false;
          std::this_thread::sleep_for(settings_.stream_interval);
          return !stopping_.load();
        },
        [this](bool) { streams_.fetch_sub(1); });
  });
  svr.Get(R"(/feed/(-?\d{1,9})\.jpg)", [this](const httplib::Request& req, httplib::Response& res) {
    const int camera = std::stoi(req.matches[1].str());
    // On workers, a camera's own frames come to the console only while a page watches it.
    session_->console.watch(camera);
    std::optional<feed_image> image;
    try {
      image = feeds_->frame(camera, session_->console);
    } catch (const std::exception& e) {
      reply_error(res, 500, fmt::format("camera {}: cannot render its feed: {}", camera, e.what()));
      return;
    }
    if (!image) {
      reply_error(res, 404,
                  fmt::format("camera {} has no feed (unknown, crashed, or the run has "
                              "not started)",
                              camera));
      return;
    }
    res.set_header("Cache-Control", "no-store");
    res.set_header("X-Frame-Tick", std::to_string(image->tick));
    res.set_header("X-Frame-Source", image->source);
    res.set_content(std::string(image->jpeg.begin(), image->jpeg.end()), "image/jpeg");
  });
  svr.Get(R"(/feed/(-?\d{1,9})/people\.json)", [this](const httplib::Request& req,
                                                      httplib::Response& res) {
    const int camera = std::stoi(req.matches[1].str());
    const auto people = feeds_->people(camera, session_->console);
    if (!people) {
      reply_error(res, 404, fmt::format("camera {} has no view yet (unknown camera?)", camera));
      return;
    }
    reply_json(res, *people);
  });
  svr.Post("/command", [this](const httplib::Request& req, httplib::Response& res) {
    auto parsed = live::parse_command(req.body, scenario_);
    if (auto* error = std::get_if<std::string>(&parsed)) {
      reply_error(res, 400, *error);
      return;
    }
    const auto& c = std::get<live::command>(parsed);
    if (!session_->queue.push(c)) {
      reply_error(res, 429,
                  fmt::format("too many commands waiting (at most {}); try again",
                              live::command_queue::capacity));
      return;
    }
    reply_json(res, {{"queued", std::string(live::name_of(c.kind))}}, 202);
  });
  svr.Post("/pace", [this](const httplib::Request& req, httplib::Response& res) {
    const auto j = nlohmann::json::parse(req.body, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
      reply_error(res, 400, "expected a JSON object, e.g. {\"speed\": 2} or {\"paused\": true}");
      return;
    }
    const auto speed = j.find("speed");
    const auto paused = j.find("paused");
    if (speed == j.end() && paused == j.end()) {
      reply_error(res, 400, "expected 'speed' (>= 0; 0 = as fast as it goes) or 'paused'");
      return;
    }
    if (speed != j.end() &&
        (!speed->is_number() || !(speed->get<double>() >= 0.0) || speed->get<double>() > 1e6)) {
      reply_error(res, 400, "'speed' must be a number in [0, 1000000]");
      return;
    }
    if (paused != j.end() && !paused->is_boolean()) {
      reply_error(res, 400, "'paused' must be true or false");
      return;
    }
    if (speed != j.end()) session_->pace.speed(speed->get<double>());
    if (paused != j.end()) session_->pace.paused(paused->get<bool>());
    reply_json(res, {{"speed", session_->pace.speed()}, {"paused", session_->pace.paused()}});
  });
  svr.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;  // a route's own error
    const char* what = res.status == 404   ? "not found"
                       : res.status == 413 ? "request body too large (at most 16 KiB)"
                                           : "bad request";
    res.set_content(json_text({{"error", fmt::format("{} {}: {}", req.method, req.path, what)}}),
                    "application/json");
  });
}

void console_server::start(const server_settings& settings) {
  settings_ = settings;
  if (!settings_.tls_cert.empty() || !settings_.tls_key.empty() || !settings_.tls_ca.empty()) {
    // The client CA makes httplib require and verify a client certificate in every handshake.
    auto https = std::make_unique<httplib::SSLServer>(
        settings_.tls_cert.c_str(), settings_.tls_key.c_str(), settings_.tls_ca.c_str());
    if (!https->is_valid())
      throw std::runtime_error(fmt::format(
          "cannot serve HTTPS with --tls-cert {}, --tls-key {} and --tls-ca {}: expected "
          "readable PEM files, the key the certificate's",
          settings_.tls_cert, settings_.tls_key, settings_.tls_ca));
    server_ = std::move(https);
  }
  // The streams hold a thread each; the rest (feeds, commands) must still get one.
  const auto threads = static_cast<std::size_t>(settings_.max_streams) + 8;
  server_->new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
  server_->set_payload_max_length(16 * 1024);
  server_->set_read_timeout(std::chrono::seconds(5));
  server_->set_write_timeout(std::chrono::seconds(5));
  server_->set_keep_alive_max_count(100);
  routes();
  if (settings_.port == 0) {
    port_ = server_->bind_to_any_port(settings_.bind);
    if (port_ < 0)
      throw std::runtime_error(fmt::format("cannot listen on {} (any port)", settings_.bind));
  } else {
    if (!server_->bind_to_port(settings_.bind, settings_.port))
      throw std::runtime_error(
          fmt::format("cannot listen on {}:{} (in use?)", settings_.bind, settings_.port));
    port_ = settings_.port;
  }
  thread_ = std::thread([this] { server_->listen_after_bind(); });
}

void console_server::stop() {
  stopping_.store(true);
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
}

}  // namespace argus::serve

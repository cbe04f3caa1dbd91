#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "config/scenario.hpp"
#include "live/session.hpp"
#include "world/station.hpp"

namespace httplib {
class Server;
struct Request;
struct Response;
}  // namespace httplib

namespace argus::serve {

class feed_renderer;

/// Where and how the console listens.
struct server_settings {
  /// Address to bind: loopback unless the user asks for more.
  std::string bind = "127.0.0.1";
  /// TCP port; 0 = any free one (see console_server::port()).
  int port = 8080;
  /// How many live streams (/events) may be open at once; more get HTTP 503.
  int max_streams = 16;
  /// Interval between two live-stream messages.
  std::chrono::milliseconds stream_interval{200};
  /// The console's secret, required of every request when set (`argus serve` sets one beyond
  /// loopback, docs/serve.md): as `?token=` on the first page (which then keeps it in a
  /// same-site, HTTP-only cookie for the page's own requests), the cookie `argus_token`, or
  /// `Authorization: Bearer`. Anything else gets HTTP 401.
  std::string token;
  /// HTTPS with mutual authentication (docs/serve.md, "Beyond loopback"): this console's
  /// certificate and its key, and the CA that must have signed every client's certificate (a
  /// client without one is refused in the handshake). All three (PEM files), or none for HTTP.
  std::string tls_cert;
  std::string tls_key;
  std::string tls_ca;
};

/// A fresh console secret: 128 bits from the system's entropy, as 32 hex digits.
std::string make_console_token();

/// The live operator console's HTTP server (cpp-httplib): the embedded page, the live stream of
/// the run's state (Server-Sent Events), the feeds (JPEG) and the operator's commands. It only
/// reads what the run published (live::console_state) and queues commands (live::command_queue):
/// the run never waits for it or for any browser. Routes (docs/serve.md):
///   GET  /            the page            GET /plan.png, /plan.json   the station's plan
///   GET  /events      SSE: state JSON     GET /state                  one state JSON
///   GET  /feed/N.jpg  camera N's feed     POST /command, POST /pace   the operator's commands
/// Bad requests get HTTP 400 with {"error": "..."} and change nothing.
class console_server {
 public:
  /// Serves `session` for the run of `scenario` in `where`.
  console_server(const config::scenario& scenario, std::shared_ptr<const world::station> where,
                 std::shared_ptr<live::session> session);
  ~console_server();
  console_server(const console_server&) = delete;
  console_server& operator=(const console_server&) = delete;

  /// Binds and starts serving on a thread of its own. Throws std::runtime_error naming the
  /// address when it cannot bind, or the files when HTTPS cannot use them.
  void start(const server_settings& settings);

  /// The port it listens on (after start).
  int port() const noexcept { return port_; }

  /// Ends every stream and stops serving.
  void stop();

 private:
  void routes();
  /// Whether `req` carries the console's secret (or none is required); sets its cookie on `res`
  /// when it came as `?token=`.
  bool authorised(const httplib::Request& req, httplib::Response& res) const;

  config::scenario scenario_;
  std::shared_ptr<const world::station> station_;
  std::shared_ptr<live::session> session_;
  std::unique_ptr<feed_renderer> feeds_;
  std::unique_ptr<httplib::Server> server_;
  server_settings settings_;
  std::once_flag plan_drawn_;  // the plan is drawn when first asked for
  std::string plan_png_;
  std::string plan_json_;
  std::thread thread_;
  std::atomic<int> streams_{0};
  std::atomic<bool> stopping_{false};
  int port_ = 0;
};

}  // namespace argus::serve

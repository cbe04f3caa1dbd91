#include "distributed/worker_server.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "actors/worker_host.hpp"
#include "caf/io/all.hpp"
#include "caf/openssl/all.hpp"
#include "fmt/format.h"
#include "spdlog/spdlog.h"

namespace argus::distributed {

void serve_worker(const worker_options& options, const std::function<void(unsigned)>& listening,
                  const std::function<bool()>& stop) {
  if (!options.listen.loopback() && !options.tls.given())
    throw std::invalid_argument(fmt::format(
        "--listen {}: listening beyond loopback needs TLS with mutual authentication: give "
        "--tls-cert, --tls-key and --tls-ca (docs/distributed.md)",
        options.listen.to_string()));
  if (auto warning = check_tls_files(options.tls); !warning.empty())
    spdlog::warn("argus worker: {}", warning);
  const unsigned threads =
      options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  actors::system_config cfg(threads);
  load_network_layer(cfg, options.tls);
  caf::actor_system system{cfg};
  auto host = actors::spawn_worker_host(
      system, options.listen.to_string(),
      options.render_threads != 0 ? options.render_threads : threads, threads);
  const char* where = options.listen.host.c_str();
  auto port = options.tls.given()
                  ? caf::openssl::publish(host, options.listen.port, where, /*reuse=*/true)
                  : system.middleman().publish(host, options.listen.port, where, /*reuse=*/true);
  if (!port) {
    caf::anon_send_exit(host, caf::exit_reason::user_shutdown);
    throw std::runtime_error(fmt::format("cannot listen on {}: {}", options.listen.to_string(),
                                         system.render(port.error())));
  }
  // Published on port 0, it learns its name only now.
  caf::anon_send(host, actors::listening_atom_v,
                 endpoint{options.listen.host, static_cast<std::uint16_t>(*port)}.to_string());
  listening(*port);
  while (!stop()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  // What a run left here ends first: the actor system waits for every actor before it goes.
  caf::scoped_actor self{system};
  self->request(host, std::chrono::seconds(5), actors::release_atom_v)
      .receive([](actors::done_atom) {}, [](caf::error&) {});
  caf::anon_send_exit(host, caf::exit_reason::user_shutdown);
}

}  // namespace argus::distributed

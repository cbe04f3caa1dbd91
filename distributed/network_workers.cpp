#include "distributed/network_workers.hpp"

#include <set>
#include <stdexcept>
#include <string>

#include "actors/type_ids.hpp"
#include "caf/io/all.hpp"
#include "caf/openssl/all.hpp"
#include "fmt/format.h"
#include "spdlog/spdlog.h"

namespace argus::distributed {
namespace {

constexpr const char* nobody_there = "nothing accepts connections there";
constexpr const char* no_answer =
    "it accepted no connection or never answered the handshake in time";

// Whether a failed connect may be a refused TLS handshake (or TLS met without it), which
// tls_refusal_reason can explain: not a mute peer, and with TLS even "nobody there" (CAF's
// OpenSSL layer reports a handshake that a plain worker broke off that way).
bool may_be_handshake(const std::string& failure, bool tls) {
  return failure != no_answer && (tls || failure != nobody_there);
}

}  // namespace

network_workers::network_workers(std::vector<endpoint> workers, tls_files tls)
    : workers_(std::move(workers)), tls_(std::move(tls)) {
  if (!tls_.given())
    for (const auto& w : workers_)
      if (!w.loopback())
        throw std::invalid_argument(fmt::format(
            "--workers {}: a worker beyond loopback is reached only over TLS with mutual "
            "authentication: give --tls-cert, --tls-key and --tls-ca (docs/distributed.md)",
            w.to_string()));
  if (auto warning = check_tls_files(tls_); !warning.empty())
    spdlog::warn("argus run: {}", warning);
}

void network_workers::configure(caf::actor_system_config& cfg) const {
  load_network_layer(cfg, tls_);
}

std::vector<actors::worker_contact> network_workers::connect(caf::actor_system& system) const {
  std::vector<actors::worker_contact> out;
  caf::scoped_actor self{system};
  for (const auto& w : workers_) {
    caf::actor host;
    std::string failure;
    // The middleman's own connect, asked with a time-out: a worker that never answers is
    // reported by name instead of holding the run for as long as TCP tries.
    const auto& middleman =
        tls_.given() ? system.openssl_manager().actor_handle() : system.middleman().actor_handle();
    self->request(middleman, connect_timeout, caf::connect_atom_v, w.host, w.port)
        .receive(
            [&](const caf::node_id&, caf::strong_actor_ptr& ptr, const std::set<std::string>&) {
              host = caf::actor_cast<caf::actor>(std::move(ptr));
            },
            [&](caf::error& err) {
              if (err == caf::sec::cannot_connect_to_node)
                failure = nobody_there;
              else if (err == caf::sec::request_timeout || err == caf::sec::connection_timeout)
                failure = no_answer;
              else
                failure = system.render(err);
            });
    // CAF says only that the connection ended: ask OpenSSL why, with a handshake of our own.
    if (!host && may_be_handshake(failure, tls_.given()))
      if (auto why = tls_refusal_reason(tls_, w.host, w.port); !why.empty()) failure = why;
    if (!host && failure.empty()) failure = "it publishes no actor at that port";
    if (!failure.empty())
      throw std::runtime_error(fmt::format("cannot reach worker {}: {}", w.to_string(), failure));
    out.push_back({w.to_string(), std::move(host)});
  }
  return out;
}

}  // namespace argus::distributed

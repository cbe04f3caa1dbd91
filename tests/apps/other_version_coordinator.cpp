// A coordinator of another Argus version, in a process of its own: it reaches an `argus worker`
// over the middleman as `argus run --workers` does, greets it claiming version VERSION, and
// prints what the worker answered. tests/apps/distributed_loopback.sh checks the refusal names
// the worker and both versions, across processes (distributed_test checks it in one).
//   other_version_coordinator HOST:PORT VERSION
// Exit status: 0 refused (the message on stdout), 1 accepted, 2 bad use or no connection.

#include <chrono>
#include <iostream>
#include <string>

#include "actors/remote_network.hpp"
#include "actors/system_config.hpp"
#include "actors/type_ids.hpp"
#include "caf/all.hpp"
#include "distributed/endpoint.hpp"
#include "distributed/network_workers.hpp"

int main(int argc, char** argv) {
  using namespace argus;
  if (argc != 3) {
    std::cerr << "usage: other_version_coordinator HOST:PORT VERSION\n";
    return 2;
  }
  try {
    distributed::network_workers pool(distributed::parse_endpoints(argv[1], "HOST:PORT"), {});
    actors::system_config cfg(1);
    pool.configure(cfg);
    caf::actor_system system{cfg};
    const auto workers = pool.connect(system);
    caf::scoped_actor self{system};
    int status = 2;
    self->request(workers.front().host, std::chrono::seconds(10), actors::worker_hello_atom_v,
                  std::string(argv[2]))
        .receive(
            [&](std::string& version, std::string&) {
              std::cout << "accepted by a worker of Argus " << version << '\n';
              status = 1;
            },
            [&](caf::error& err) {
              std::cout << system.render(err) << '\n';
              status = 0;
            });
    return status;
  } catch (const std::exception& e) {
    std::cerr << "other_version_coordinator: " << e.what() << '\n';
    return 2;
  }
}

#include <csignal>
#include <iostream>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/tls_options.hpp"
#include "fmt/format.h"
#ifdef ARGUS_WITH_DISTRIBUTED
#include "distributed/worker_server.hpp"
#endif

namespace argus::apps {
namespace {

struct worker_arguments {
  std::string listen = "127.0.0.1:7001";
  unsigned threads = 0;
  std::size_t render_threads = 0;
  tls_arguments tls;
};

#ifdef ARGUS_WITH_DISTRIBUTED
volatile std::sig_atomic_t stop_requested = 0;
extern "C" void request_stop(int) {
  stop_requested = 1;
}
#endif

}  // namespace

void add_worker_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "worker",
      "Host camera nodes, links and crowd partitions for runs started elsewhere with argus run "
      "--workers");
  auto args = std::make_shared<worker_arguments>();
  cmd->add_option("--listen", args->listen,
                  "HOST:PORT to listen on (default 127.0.0.1:7001; port 0: any free one; beyond "
                  "loopback only with TLS)");
  cmd->add_option("--threads", args->threads,
                  "Scheduler threads, and those that compute the distance fields (default: one "
                  "per core)");
  cmd->add_option("--render-threads", args->render_threads,
                  "Renderers for pixel sensing, and for the video's tiles of its cameras (default: "
                  "as many as scheduler threads)");
  add_tls_options(cmd, args->tls, "worker", "coordinator");
  cmd->callback([args, &result] {
#ifdef ARGUS_WITH_DISTRIBUTED
    distributed::worker_options options;
    try {
      options.listen = distributed::parse_endpoint(args->listen, "--listen", /*any_port=*/true);
    } catch (const std::invalid_argument& e) {
      std::cerr << "argus worker: " << e.what() << '\n';
      result = bad_input;
      return;
    }
    options.threads = args->threads;
    options.render_threads = args->render_threads;
    options.tls = {args->tls.cert, args->tls.key, args->tls.ca};
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    try {
      distributed::serve_worker(
          options,
          [&](unsigned port) {
            std::cout << fmt::format("argus worker: listening on {}:{}", options.listen.host, port)
                      << std::endl;
          },
          [] { return stop_requested != 0; });
      result = ok;
    } catch (const std::invalid_argument& e) {
      std::cerr << "argus worker: " << e.what() << '\n';
      result = bad_input;
    } catch (const std::exception& e) {
      std::cerr << "argus worker: " << e.what() << '\n';
      result = run_failed;
    }
#else
    std::cerr << "argus worker: this build has no network layer (libcaf-io)\n";
    result = run_failed;
#endif
  });
}

}  // namespace argus::apps

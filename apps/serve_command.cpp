#include <csignal>
#include <iostream>
#include <memory>
#include <optional>

#include "actors/run_scenario.hpp"
#include "apps/commands.hpp"
#include "apps/option_checks.hpp"
#include "apps/run_overrides.hpp"
#include "apps/run_record.hpp"
#include "apps/set_option.hpp"
#include "apps/task_option.hpp"
#include "apps/tls_options.hpp"
#include "apps/workers_option.hpp"
#include "config/scenario_error.hpp"
#include "config/whole_file.hpp"
#include "distributed/loopback.hpp"
#ifdef ARGUS_WITH_DISTRIBUTED
#include "distributed/tls_files.hpp"
#endif
#include "fmt/format.h"
#include "live/command_log.hpp"
#include "live/session.hpp"
#include "serve/console_server.hpp"
#include "world/layout_loader.hpp"

namespace argus::apps {
namespace {

struct serve_arguments {
  std::string scenario;
  run_overrides overrides;
  std::vector<std::string> set;
  std::vector<std::string> tasks;
  std::string bind = "127.0.0.1";
  int port = 8080;
  bool hold = false;
  tls_arguments tls;
  workers_arguments workers;
};

// Blocks until SIGINT or SIGTERM (argus serve --hold, once the run is over).
void wait_for_interrupt() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  int received = 0;
  sigwait(&signals, &received);
}

int serve(const serve_arguments& args) {
  if (args.tls.given()) {
#ifdef ARGUS_WITH_DISTRIBUTED
    // The same check as argus worker's: all three, readable PEM, the key the certificate's.
    try {
      if (auto warning = distributed::check_tls_files({args.tls.cert, args.tls.key, args.tls.ca});
          !warning.empty())
        std::cerr << "argus serve: " << warning << '\n';
    } catch (const std::invalid_argument& e) {
      std::cerr << "argus serve: " << e.what() << '\n';
      return bad_input;
    }
#else
    if (args.tls.cert.empty() || args.tls.key.empty() || args.tls.ca.empty()) {
      std::cerr << "argus serve: HTTPS needs all of --tls-cert, --tls-key and --tls-ca\n";
      return bad_input;
    }
#endif
  }
  config::scenario scenario;
  try {
    scenario = load_with_tasks(args.scenario, overrides_from(args.set), args.tasks);
  } catch (const config::scenario_error& e) {
    std::cerr << e.what() << '\n';
    return bad_input;
  }
  apply_run_overrides(args.overrides, scenario);
  actors::run_options options;
  try {
    // One TLS identity for the process: the console's HTTPS and the workers' connections.
    apply_workers_options(args.workers, args.tls, /*tls_only_for_workers=*/false, options);
  } catch (const std::invalid_argument& e) {
    std::cerr << "argus serve: " << e.what() << '\n';
    return bad_input;
  }
  // A live run is paced to the wall clock unless asked otherwise: it is there to be watched.
  const double speed = args.overrides.speed.value_or(1.0);
  try {
    auto session = std::make_shared<live::session>(scenario, speed);
    // As argus run loads it: a large station's fields come from the field cache.
    auto station = actors::load_run_station(scenario);
    serve::console_server server(scenario, station, session);
    serve::server_settings settings;
    settings.bind = args.bind;
    settings.port = args.port;
    settings.tls_cert = args.tls.cert;
    settings.tls_key = args.tls.key;
    settings.tls_ca = args.tls.ca;
    // Beyond loopback anyone who reaches the console could crash cameras: it then needs a
    // client certificate from the CA of --tls-ca (HTTPS), or a secret, printed here once and
    // nowhere else (docs/serve.md, "Beyond loopback").
    if (!distributed::is_loopback_host(args.bind) && !args.tls.given())
      settings.token = serve::make_console_token();
    server.start(settings);
    std::cout << fmt::format("argus serve: {}://{}:{}/{}", args.tls.given() ? "https" : "http",
                             args.bind, server.port(),
                             settings.token.empty() ? "" : "?token=" + settings.token)
              << std::endl;
    options.live = session;
    options.station = station;
    auto outcome = actors::run_scenario(scenario, options);
    const auto commands = session->log.commands();
    config::write_whole_file(outcome.output_dir / "commands.yaml", [&](std::ostream& out) {
      out << live::commands_yaml(commands, scenario);
    });
    record_run(scenario, outcome.output_dir, /*feeds=*/true, outcome.station);
    const auto& r = outcome.result;
    std::cout << fmt::format(
        "{}: {} ticks, {:.1f} s simulated in {:.2f} s wall, {} events, {} operator commands\n",
        scenario.name, r.ticks, r.virtual_seconds, r.wall_seconds, r.events_total, commands.size());
    std::cout << "  events:   " << (outcome.output_dir / "events.jsonl").string() << '\n';
    std::cout << "  commands: " << (outcome.output_dir / "commands.yaml").string() << '\n';
    std::cout << "  replay:   argus run " << (outcome.output_dir / "scenario.yaml").string()
              << " --commands " << (outcome.output_dir / "commands.yaml").string() << " --out DIR"
              << std::endl;
    for (const auto& lost : r.lost_workers)
      std::cout << "  worker lost, its cameras crashed: " << lost << '\n';
    // A lost worker or a strategy that raised ended the run early: its files are whole up to
    // that tick, and the page says it is over.
    const int status = r.failure.empty() ? ok : run_failed;
    if (!r.failure.empty()) std::cerr << "argus serve: " << r.failure << '\n';
    if (args.hold) {
      std::cout << "argus serve: the run is over; serving its last state until interrupted"
                << std::endl;
      wait_for_interrupt();
    }
    server.stop();
    return status;
  } catch (const std::exception& e) {
    std::cerr << "argus serve: " << e.what() << '\n';
    return run_failed;
  }
}

}  // namespace

void add_serve_command(CLI::App& app, int& result) {
  auto* cmd = app.add_subcommand(
      "serve", "Run a scenario live and serve its operator console in the browser");
  auto args = std::make_shared<serve_arguments>();
  cmd->add_option("SCENARIO", args->scenario, "Scenario YAML file")->required();
  add_run_override_options(cmd, args->overrides);
  add_set_option(cmd, args->set);
  cmd->add_option("--task", args->tasks,
                  "Add an operator task, e.g. 'at=10s,camera=7,pixel=160x120' (repeatable)");
  cmd->add_option("--port", args->port, "TCP port to serve on (0 = any free port)")
      ->check(integer_in(0, 65535));
  cmd->add_option("--bind", args->bind,
                  "Address to listen on (default 127.0.0.1: this machine only; beyond loopback "
                  "the console requires a client certificate (--tls-*) or the secret it prints)");
  add_tls_options(cmd, args->tls, "console", "browser");
  add_workers_options(cmd, args->workers);
  // One identity for the process: with --workers it also secures the connections to them.
  cmd->get_option("--tls-cert")
      ->description(
          "This console's certificate (PEM); with --tls-key and --tls-ca the console is HTTPS "
          "and asks browsers for a client certificate, and with --workers every connection to a "
          "worker is TLS with mutual authentication too");
  cmd->get_option("--tls-ca")
      ->description(
          "The CA certificate (PEM) that must sign every browser's (and worker's) "
          "certificate");
  cmd->add_flag("--hold", args->hold,
                "Keep serving after the run has ended, until interrupted (Ctrl-C)");
  cmd->callback([args, &result] { result = serve(*args); });
}

}  // namespace argus::apps

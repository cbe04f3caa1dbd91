#pragma once

#include <string>

#include "CLI/CLI.hpp"

namespace argus::apps {

/// A process's TLS identity as given on the command line (docs/distributed.md, "Security").
struct tls_arguments {
  std::string cert;
  std::string key;
  std::string ca;

  bool given() const { return !cert.empty() || !key.empty() || !ca.empty(); }
};

/// Adds --tls-cert, --tls-key and --tls-ca to `cmd`; `self` names this side ("coordinator",
/// "worker"), `peer` the other.
inline void add_tls_options(CLI::App* cmd, tls_arguments& args, const std::string& self,
                            const std::string& peer) {
  cmd->add_option("--tls-cert", args.cert,
                  "This " + self +
                      "'s certificate (PEM); with --tls-key and --tls-ca every "
                      "connection is TLS with mutual authentication");
  cmd->add_option("--tls-key", args.key, "The private key of --tls-cert (PEM, unencrypted)");
  cmd->add_option("--tls-ca", args.ca,
                  "The CA certificate (PEM) that must sign every " + peer + "'s certificate");
}

}  // namespace argus::apps

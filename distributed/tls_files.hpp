#pragma once

#include <string>

#include "caf/fwd.hpp"

namespace argus::distributed {

/// A process's TLS identity (docs/distributed.md, "Security"): its certificate and private key
/// (PEM), and the CA that signs every certificate it accepts. Given, CAF's `caf_openssl` carries
/// every connection: each side presents its certificate and requires the other's, signed by the
/// CA and within its dates (mutual authentication), and the traffic is encrypted.
struct tls_files {
  std::string cert;
  std::string key;
  std::string ca;

  /// Whether any of the three is given.
  bool given() const { return !cert.empty() || !key.empty() || !ca.empty(); }
};

/// Checks the files before anything listens or connects, so a mistake is named here rather
/// than as a failed handshake on the other side: all three or none, each readable PEM, the key
/// the certificate's. Throws std::invalid_argument naming the option, the file and what is
/// wrong. A certificate the CA does not accept (expired, or another CA's) is the peer's to
/// refuse, and it says why; the returned text warns of it, empty when there is nothing to say.
std::string check_tls_files(const tls_files& files);

/// Loads CAF's middleman and, with `files` given, its OpenSSL manager with them.
void load_network_layer(caf::actor_system_config& cfg, const tls_files& files);

/// Why a TLS connection to HOST:PORT fails, found by a handshake of our own with OpenSSL after
/// CAF's failed (CAF's OpenSSL layer says only that the connection ended): the server's
/// certificate refused and why (another CA, expired), or ours refused by the server (the alert
/// it sent), or no TLS spoken there. Empty when the handshake succeeds after all.
std::string tls_refusal_reason(const tls_files& files, const std::string& host, unsigned port);

}  // namespace argus::distributed

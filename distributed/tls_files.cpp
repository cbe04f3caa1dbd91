#include "distributed/tls_files.hpp"

#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>
#include <openssl/x509_vfy.h>
#include <sys/socket.h>
#include <sys/time.h>

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "caf/io/middleman.hpp"
#include "caf/openssl/manager.hpp"
#include "fmt/format.h"

namespace argus::distributed {
namespace {

template <class T, void (*Free)(T*)>
struct freer {
  void operator()(T* p) const { Free(p); }
};
using x509_ptr = std::unique_ptr<X509, freer<X509, X509_free>>;
using key_ptr = std::unique_ptr<EVP_PKEY, freer<EVP_PKEY, EVP_PKEY_free>>;
using store_ptr = std::unique_ptr<X509_STORE, freer<X509_STORE, X509_STORE_free>>;
using store_ctx_ptr = std::unique_ptr<X509_STORE_CTX, freer<X509_STORE_CTX, X509_STORE_CTX_free>>;
using ctx_ptr = std::unique_ptr<SSL_CTX, freer<SSL_CTX, SSL_CTX_free>>;
using ssl_ptr = std::unique_ptr<SSL, freer<SSL, SSL_free>>;

std::string openssl_error() {
  std::string out;
  while (auto err = ERR_get_error()) {
    char buf[256];
    ERR_error_string_n(err, buf, sizeof(buf));
    if (!out.empty()) out += "; ";
    out += buf;
  }
  return out.empty() ? "no reason given" : out;
}

std::invalid_argument bad(const char* option, const std::string& file, const std::string& what) {
  return std::invalid_argument(fmt::format("{} {}: {}", option, file, what));
}

x509_ptr read_certificate(const char* option, const std::string& file) {
  std::unique_ptr<FILE, int (*)(FILE*)> in(std::fopen(file.c_str(), "r"), &std::fclose);
  if (!in) throw bad(option, file, "cannot be read");
  x509_ptr cert(PEM_read_X509(in.get(), nullptr, nullptr, nullptr));
  if (!cert) throw bad(option, file, "expected a PEM certificate (" + openssl_error() + ")");
  return cert;
}

}  // namespace

std::string check_tls_files(const tls_files& files) {
  if (!files.given()) return {};
  if (files.cert.empty() || files.key.empty() || files.ca.empty())
    throw std::invalid_argument(
        "--tls-cert, --tls-key and --tls-ca go together: a certificate, its private key and the "
        "CA that signs the peers'");
  auto cert = read_certificate("--tls-cert", files.cert);
  auto ca = read_certificate("--tls-ca", files.ca);
  {
    std::unique_ptr<FILE, int (*)(FILE*)> in(std::fopen(files.key.c_str(), "r"), &std::fclose);
    if (!in) throw bad("--tls-key", files.key, "cannot be read");
    key_ptr key(PEM_read_PrivateKey(in.get(), nullptr, nullptr, nullptr));
    if (!key)
      throw bad("--tls-key", files.key,
                "expected an unencrypted PEM private key (" + openssl_error() + ")");
    if (X509_check_private_key(cert.get(), key.get()) != 1)
      throw bad("--tls-key", files.key, "is not the key of --tls-cert " + files.cert);
  }
  store_ptr store(X509_STORE_new());
  X509_STORE_add_cert(store.get(), ca.get());
  store_ctx_ptr check(X509_STORE_CTX_new());
  X509_STORE_CTX_init(check.get(), store.get(), cert.get(), nullptr);
  if (X509_verify_cert(check.get()) == 1) return {};
  const int err = X509_STORE_CTX_get_error(check.get());
  const std::string why = X509_verify_cert_error_string(err);
  if (err == X509_V_ERR_CERT_HAS_EXPIRED || err == X509_V_ERR_CERT_NOT_YET_VALID)
    return fmt::format("--tls-cert {}: {}: every peer will refuse it", files.cert, why);
  return fmt::format(
      "--tls-cert {}: not signed by --tls-ca {} ({}): peers that trust only that "
      "CA will refuse it",
      files.cert, files.ca, why);
}

void load_network_layer(caf::actor_system_config& cfg, const tls_files& files) {
  cfg.load<caf::io::middleman>();
  // A heartbeat every second and a 3 s time-out: a silent peer is found within 5 s even when
  // no connection closes (a machine that went away, a cable pulled).
  cfg.set("middleman.heartbeat-interval", caf::timespan{std::chrono::seconds(1)});
  cfg.set("middleman.connection-timeout", caf::timespan{std::chrono::seconds(3)});
  if (!files.given()) return;
  cfg.load<caf::openssl::manager>();
  cfg.openssl_certificate = files.cert;
  cfg.openssl_key = files.key;
  cfg.openssl_cafile = files.ca;
}

std::string tls_refusal_reason(const tls_files& files, const std::string& host, unsigned port) {
  ERR_clear_error();
  ctx_ptr ctx(SSL_CTX_new(TLS_client_method()));
  if (!ctx) return "OpenSSL cannot make a context: " + openssl_error();
  if (!files.given()) {
    // A coordinator without TLS: does the worker speak TLS? A bare ClientHello tells.
    SSL_CTX_set_verify(ctx.get(), SSL_VERIFY_NONE, nullptr);
  } else {
    SSL_CTX_use_certificate_chain_file(ctx.get(), files.cert.c_str());
    SSL_CTX_use_PrivateKey_file(ctx.get(), files.key.c_str(), SSL_FILETYPE_PEM);
    SSL_CTX_load_verify_locations(ctx.get(), files.ca.c_str(), nullptr);
    SSL_CTX_set_verify(ctx.get(), SSL_VERIFY_PEER, nullptr);
  }
  auto* bio = BIO_new_connect(fmt::format("{}:{}", host, port).c_str());
  if (bio == nullptr || BIO_do_connect(bio) <= 0) {
    if (bio) BIO_free_all(bio);
    return "nothing accepts connections there";
  }
  // A worker that accepts and then says nothing must not hold this probe for ever.
  int fd = -1;
  BIO_get_fd(bio, &fd);
  if (fd >= 0) {
    timeval wait{2, 0};
    setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof(wait));
  }
  ssl_ptr ssl(SSL_new(ctx.get()));
  SSL_set_bio(ssl.get(), bio, bio);
  ERR_clear_error();
  const int done = SSL_connect(ssl.get());
  const long verified = SSL_get_verify_result(ssl.get());
  if (verified != X509_V_OK && files.given()) {
    const bool stranger = verified == X509_V_ERR_SELF_SIGNED_CERT_IN_CHAIN ||
                          verified == X509_V_ERR_UNABLE_TO_GET_ISSUER_CERT_LOCALLY ||
                          verified == X509_V_ERR_DEPTH_ZERO_SELF_SIGNED_CERT ||
                          verified == X509_V_ERR_UNABLE_TO_VERIFY_LEAF_SIGNATURE;
    return fmt::format("its certificate is refused: {} (OpenSSL: {})",
                       stranger ? "it is not signed by the CA of --tls-ca" : "it is not valid",
                       X509_verify_cert_error_string(verified));
  }
  std::string why;
  if (done == 1) {
    // TLS 1.3 reports a refused client certificate after the handshake, with the first read.
    char byte;
    if (SSL_read(ssl.get(), &byte, 1) > 0 || ERR_peek_error() == 0) {
      if (files.given()) return {};
    } else {
      why = openssl_error();
    }
  } else {
    why = openssl_error();
  }
  const bool spoke_tls = done == 1 || why.find("alert") != std::string::npos;
  if (!files.given())
    return spoke_tls ? "it speaks TLS and requires a certificate: give --tls-cert, --tls-key and "
                       "--tls-ca"
                     : fmt::format("the handshake failed ({})", why);
  if (!spoke_tls)
    return fmt::format("it does not speak TLS (a worker started without --tls-cert?): {}", why);
  return fmt::format("it refused this side's certificate ({})", why);
}

}  // namespace argus::distributed

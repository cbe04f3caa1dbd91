// Says, on the side that accepts, which TLS connection it refused and why (docs/distributed.md,
// "Security"). CAF's OpenSSL layer (caf_openssl 0.17) ends a connection whose handshake fails
// without a word, so a worker's operator never learnt that a coordinator with a stranger's or an
// expired certificate, or one without TLS, had knocked. It offers no hook, so `argus` defines
// `SSL_accept` itself: the dynamic linker binds CAF's calls (and cpp-httplib's, for the console)
// to this one, which calls OpenSSL's and, when the handshake has failed for good, logs the peer's
// address and OpenSSL's reason. The handshake itself is untouched: the same result goes back,
// and OpenSSL's error queue is only peeked at, so the caller reads what it would have read.
//
// Linked into the `argus` executable only (apps/CMakeLists.txt), never into a library that
// another program might load.

#include <arpa/inet.h>
#include <dlfcn.h>
#include <netinet/in.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>
#include <sys/socket.h>

#include <cstdio>
#include <string>

#include "spdlog/spdlog.h"

namespace {

using accept_function = int (*)(SSL*);

accept_function openssl_accept() {
  static const auto real = reinterpret_cast<accept_function>(dlsym(RTLD_NEXT, "SSL_accept"));
  return real;
}

// The peer's address, read before the handshake step: once the peer has refused and reset the
// connection, getpeername() fails (ENOTCONN), and the refusal could not say whom it refused.
struct peer_address {
  sockaddr_storage addr{};
  bool known = false;
};

peer_address address_of(const SSL* ssl) {
  peer_address out;
  const int fd = SSL_get_fd(ssl);
  socklen_t len = sizeof(out.addr);
  out.known = fd >= 0 && getpeername(fd, reinterpret_cast<sockaddr*>(&out.addr), &len) == 0;
  return out;
}

// The connection's address as first read, kept with the connection (freed with it): a handshake
// takes several calls, and by a later one the peer may already have refused and gone.
void free_peer(void*, void* kept, CRYPTO_EX_DATA*, int, long, void*) {
  delete static_cast<peer_address*>(kept);
}

int peer_index() {
  static const int index = SSL_get_ex_new_index(0, nullptr, nullptr, nullptr, free_peer);
  return index;
}

peer_address remembered_peer(SSL* ssl) {
  const auto fresh = address_of(ssl);
  auto* kept = static_cast<peer_address*>(SSL_get_ex_data(ssl, peer_index()));
  if (!fresh.known) return kept != nullptr ? *kept : fresh;
  if (kept == nullptr) {
    kept = new peer_address(fresh);
    if (SSL_set_ex_data(ssl, peer_index(), kept) != 1) delete kept;
  } else {
    *kept = fresh;
  }
  return fresh;
}

std::string to_string(const peer_address& peer) {
  if (!peer.known) return "an unknown peer";
  char host[INET6_ADDRSTRLEN] = {};
  if (peer.addr.ss_family == AF_INET) {
    const auto* in = reinterpret_cast<const sockaddr_in*>(&peer.addr);
    inet_ntop(AF_INET, &in->sin_addr, host, sizeof(host));
    return std::string(host) + ":" + std::to_string(ntohs(in->sin_port));
  }
  if (peer.addr.ss_family == AF_INET6) {
    const auto* in = reinterpret_cast<const sockaddr_in6*>(&peer.addr);
    inet_ntop(AF_INET6, &in->sin6_addr, host, sizeof(host));
    return "[" + std::string(host) + "]:" + std::to_string(ntohs(in->sin6_port));
  }
  return "a peer of another address family";
}

// OpenSSL's reason in words a worker's operator can act on.
std::string reason_of(const SSL* ssl, int error) {
  const long verified = SSL_get_verify_result(ssl);
  if (verified != X509_V_OK)
    return std::string("its certificate is refused: ") + X509_verify_cert_error_string(verified);
  const unsigned long queued = ERR_peek_last_error();
  if (queued != 0) {
    const int reason = ERR_GET_REASON(queued);
    const char* text = ERR_reason_error_string(queued);
    const std::string openssl = text != nullptr ? text : "error " + std::to_string(reason);
    if (ERR_GET_LIB(queued) == ERR_LIB_SSL &&
        (reason == SSL_R_WRONG_VERSION_NUMBER || reason == SSL_R_HTTP_REQUEST ||
         reason == SSL_R_PACKET_LENGTH_TOO_LONG || reason == SSL_R_UNKNOWN_PROTOCOL))
      return "it does not speak TLS (OpenSSL: " + openssl + ")";
    if (ERR_GET_LIB(queued) == ERR_LIB_SSL && reason == SSL_R_PEER_DID_NOT_RETURN_A_CERTIFICATE)
      return "it presented no certificate (OpenSSL: " + openssl + ")";
    // The peer's alert: most often it refused this side's certificate (another CA's, say).
    if (ERR_GET_LIB(queued) == ERR_LIB_SSL && reason >= SSL_AD_REASON_OFFSET)
      return "it refused the handshake (OpenSSL: " + openssl + ")";
    return "the handshake failed (OpenSSL: " + openssl + ")";
  }
  if (error == SSL_ERROR_ZERO_RETURN || error == SSL_ERROR_SYSCALL)
    return "it closed the connection during the handshake";
  return "the handshake failed (OpenSSL error " + std::to_string(error) + ")";
}

}  // namespace

extern "C" int SSL_accept(SSL* ssl) {
  const auto real = openssl_accept();
  if (real == nullptr) return -1;  // no OpenSSL loaded: nothing can have called here
  const auto peer = remembered_peer(ssl);
  const int result = real(ssl);
  if (result == 1) return result;
  const int error = SSL_get_error(ssl, result);
  if (error == SSL_ERROR_WANT_READ || error == SSL_ERROR_WANT_WRITE) return result;
  spdlog::warn("refused a TLS connection from {}: {}", to_string(peer), reason_of(ssl, error));
  return result;
}

#include "report/base64.hpp"

namespace argus::report {

std::string base64(std::span<const unsigned char> bytes) {
  static constexpr char alphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t k = 0;
  for (; k + 2 < bytes.size(); k += 3) {
    const unsigned triple = (bytes[k] << 16) | (bytes[k + 1] << 8) | bytes[k + 2];
    out += alphabet[(triple >> 18) & 63];
    out += alphabet[(triple >> 12) & 63];
    out += alphabet[(triple >> 6) & 63];
    out += alphabet[triple & 63];
  }
  if (k + 1 == bytes.size()) {
    const unsigned single = bytes[k] << 16;
    out += alphabet[(single >> 18) & 63];
    out += alphabet[(single >> 12) & 63];
    out += "==";
  } else if (k + 2 == bytes.size()) {
    const unsigned pair = (bytes[k] << 16) | (bytes[k + 1] << 8);
    out += alphabet[(pair >> 18) & 63];
    out += alphabet[(pair >> 12) & 63];
    out += alphabet[(pair >> 6) & 63];
    out += '=';
  }
  return out;
}

}  // namespace argus::report

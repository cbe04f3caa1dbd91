#pragma once

#include <span>
#include <string>

namespace argus::report {

/// RFC 4648 base64 (with padding) of `bytes`, for images inlined as `data:` URIs.
std::string base64(std::span<const unsigned char> bytes);

}  // namespace argus::report

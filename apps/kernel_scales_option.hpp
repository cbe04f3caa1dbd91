#pragma once

// `--scales` of `argus vision localize` and `argus vision calibrate`: which kernel sizes the
// multiscale localiser (vision/kernel_scales.hpp) tries.

#include <charconv>
#include <optional>
#include <string>
#include <vector>

#include "CLI/CLI.hpp"
#include "fmt/format.h"

namespace argus::apps {

/// The largest kernel size a user may name: a kernel 6L + 1 = 60,001 rows high, beyond any
/// image the commands accept.
inline constexpr int largest_kernel_size = 10000;

/// The sizes of a list such as "5,8,12" (each 1 to largest_kernel_size), or nullopt.
inline std::optional<std::vector<int>> kernel_size_list(const std::string& text) {
  std::vector<int> sizes;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  while (true) {
    int value = 0;
    const auto [next, error] = std::from_chars(at, end, value);
    if (error != std::errc{} || value < 1 || value > largest_kernel_size) return std::nullopt;
    sizes.push_back(value);
    if (next == end) return sizes;
    if (*next != ',') return std::nullopt;
    at = next + 1;
  }
}

/// `--scales`: "target", "paper" or a list of kernel sizes; `with_list` allows the list.
inline CLI::Validator kernel_scales_option(bool with_list = true) {
  return CLI::Validator(
      [with_list](const std::string& text) -> std::string {
        if (text == "target" || text == "paper" || (with_list && kernel_size_list(text))) return {};
        if (!with_list) return fmt::format("expected 'target' or 'paper', got '{}'", text);
        return fmt::format(
            "expected 'target', 'paper' or kernel sizes from 1 to {} separated by commas "
            "(e.g. 5,8,12), got '{}'",
            largest_kernel_size, text);
      },
      with_list ? "target|paper|L,L,..." : "target|paper");
}

}  // namespace argus::apps

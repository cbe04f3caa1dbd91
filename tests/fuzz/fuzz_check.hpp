#pragma once

// What the harnesses share: the input as text, and a check that stops the run (a crash the
// fuzzer keeps) when a property of the code under test does not hold.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace argus::fuzz {

/// The fuzzer's bytes as text (neither owned nor terminated).
inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Aborts, naming the property that failed and where: libFuzzer saves the input as a crash.
[[noreturn]] inline void check_failed(const char* what, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", file, line, what);
  std::abort();
}

}  // namespace argus::fuzz

#define ARGUS_FUZZ_CHECK(condition) \
  ((condition) ? void(0) : ::argus::fuzz::check_failed(#condition, __FILE__, __LINE__))

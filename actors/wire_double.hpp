#pragma once

// A double as it crosses to another process: as its bits. CAF 0.17 writes a double through a
// portable IEEE 754 packing that drops the sign of zero (-0.0 arrives as 0.0), and a run across
// processes must read what one process reads: a heading drawn from a facing of -0.0 is not the
// one drawn from 0.0, and a pan of -0.0 is written "-0". Inspectors name such a field
// `as_bits(x.field)`.

#include <bit>
#include <cstdint>

namespace argus::actors {

struct double_bits {
  double& value;
};

inline double_bits as_bits(double& x) {
  return {x};
}

template <class Inspector>
typename Inspector::result_type inspect(Inspector& f, double_bits& x) {
  if constexpr (Inspector::reads_state) {
    auto bits = std::bit_cast<std::uint64_t>(x.value);
    return f(bits);
  } else {
    std::uint64_t bits = 0;
    auto result = f(bits);
    x.value = std::bit_cast<double>(bits);
    return result;
  }
}

}  // namespace argus::actors

#include "sensing/signature.hpp"

#include <algorithm>

namespace argus::sensing {

namespace {

std::vector<float> normalised_values(const vision::color_histogram& histogram) {
  const auto normalised = histogram.normalized();
  return {normalised.counts().begin(), normalised.counts().end()};
}

vision::color_histogram histogram_of(const protocol::signature& signature,
                                     const std::vector<float>& values) {
  vision::color_histogram h(
      vision::histogram_bins{signature.hue_bins, signature.saturation_bins, signature.value_bins});
  auto counts = h.counts();
  std::copy_n(values.begin(), std::min(counts.size(), values.size()), counts.begin());
  return h;
}

}  // namespace

protocol::signature to_signature(const vision::color_histogram& histogram,
                                 const std::optional<vision::signature_halves>& halves) {
  protocol::signature s;
  s.hue_bins = static_cast<std::uint8_t>(histogram.bins().hue);
  s.saturation_bins = static_cast<std::uint8_t>(histogram.bins().saturation);
  s.value_bins = static_cast<std::uint8_t>(histogram.bins().value);
  s.values = normalised_values(histogram);
  if (halves) {
    s.upper = normalised_values(halves->upper);
    s.lower = normalised_values(halves->lower);
  }
  return s;
}

vision::color_histogram to_histogram(const protocol::signature& signature) {
  return histogram_of(signature, signature.values);
}

std::optional<vision::signature_halves> to_halves(const protocol::signature& signature) {
  if (signature.upper.empty() || signature.lower.empty()) return std::nullopt;
  return vision::signature_halves{histogram_of(signature, signature.upper),
                                  histogram_of(signature, signature.lower)};
}

}  // namespace argus::sensing

#include "sensing/signature.hpp"

#include <algorithm>

namespace argus::sensing {

protocol::signature to_signature(const vision::color_histogram& histogram) {
  const auto normalised = histogram.normalized();
  protocol::signature s;
  s.hue_bins = static_cast<std::uint8_t>(normalised.bins().hue);
  s.saturation_bins = static_cast<std::uint8_t>(normalised.bins().saturation);
  s.value_bins = static_cast<std::uint8_t>(normalised.bins().value);
  s.values.assign(normalised.counts().begin(), normalised.counts().end());
  return s;
}

vision::color_histogram to_histogram(const protocol::signature& signature) {
  vision::color_histogram h(
      vision::histogram_bins{signature.hue_bins, signature.saturation_bins, signature.value_bins});
  auto counts = h.counts();
  std::copy_n(signature.values.begin(), std::min(counts.size(), signature.values.size()),
              counts.begin());
  return h;
}

}  // namespace argus::sensing

#pragma once

#include <optional>

#include "protocol/group_messages.hpp"
#include "vision/color_histogram.hpp"
#include "vision/signature_halves.hpp"

namespace argus::sensing {

/// The signature a node sends for `histogram` (normalised to sum 1) and, when given, her
/// `halves` (each normalised to sum 1; with the histogram's bins).
protocol::signature to_signature(const vision::color_histogram& histogram,
                                 const std::optional<vision::signature_halves>& halves = {});

/// The halves `signature` carries, if it carries them.
std::optional<vision::signature_halves> to_halves(const protocol::signature& signature);

/// The histogram a node looks for when it receives `signature`.
vision::color_histogram to_histogram(const protocol::signature& signature);

}  // namespace argus::sensing

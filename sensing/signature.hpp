#pragma once

#include "protocol/group_messages.hpp"
#include "vision/color_histogram.hpp"

namespace argus::sensing {

/// The signature a node sends for `histogram` (normalised to sum 1).
protocol::signature to_signature(const vision::color_histogram& histogram);

/// The histogram a node looks for when it receives `signature`.
vision::color_histogram to_histogram(const protocol::signature& signature);

}  // namespace argus::sensing

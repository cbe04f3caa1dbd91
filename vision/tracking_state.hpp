#pragma once

namespace argus::vision {

/// The child states of PerformingTask (Fig. 10, inset), plus `failed` once Search times out.
enum class tracking_state { track, wait, search, failed };

}  // namespace argus::vision

#include "sensing/sensor.hpp"

namespace argus::sensing {

candidate_filter both(candidate_filter first, candidate_filter second) {
  if (!first) return second;
  if (!second) return first;
  return [first = std::move(first), second = std::move(second)](const candidate& c) {
    return first(c) && second(c);
  };
}

}  // namespace argus::sensing

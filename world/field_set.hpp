#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace argus::world {

/// A station's distance fields, one float per navigation cell each: computed in this process
/// and owned, or the field cache's file mapped into memory (field_cache::load). Mapped, the
/// processes of a distributed run and the runs of a sweep read the one copy in the page cache:
/// the large station's 523 MB were read, zeroed and copied again by every process that loaded
/// it (bench/RESULTS.md, "The fields mapped").
class field_set {
 public:
  field_set() = default;

  /// Fields computed here, kept by the set.
  explicit field_set(std::vector<std::vector<float>> owned) {
    auto kept = std::make_shared<std::vector<std::vector<float>>>(std::move(owned));
    views_.reserve(kept->size());
    for (const auto& f : *kept) views_.emplace_back(f);
    keeper_ = std::move(kept);
  }

  /// `views` into memory that `keeper` holds (a mapping) as long as the set or a copy lives.
  field_set(std::shared_ptr<const void> keeper, std::vector<std::span<const float>> views)
      : keeper_(std::move(keeper)), views_(std::move(views)) {}

  std::size_t size() const noexcept { return views_.size(); }
  bool empty() const noexcept { return views_.empty(); }
  std::span<const float> operator[](std::size_t field) const noexcept { return views_[field]; }

 private:
  std::shared_ptr<const void> keeper_;
  std::vector<std::span<const float>> views_;
};

}  // namespace argus::world

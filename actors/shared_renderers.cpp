#include "actors/shared_renderers.hpp"

#include <stdexcept>
#include <utility>

#include "vision/renderer.hpp"

namespace argus::actors {

shared_renderers::shared_renderers(std::shared_ptr<const world::station> station,
                                   std::size_t count) {
  if (count == 0) throw std::invalid_argument("shared renderers: needs at least one renderer");
  for (std::size_t i = 0; i < count; ++i) {
    all_.push_back(std::make_unique<vision::renderer>(station));
    free_.push_back(count - 1 - i);  // the lowest index is lent first
  }
}

shared_renderers::~shared_renderers() = default;

render_result shared_renderers::render(render_request request) {
  std::size_t index = 0;
  {
    std::unique_lock guard(mutex_);
    returned_.wait(guard, [this] { return !free_.empty(); });
    index = free_.back();
    free_.pop_back();
  }
  struct give_back {
    shared_renderers* self;
    std::size_t index;
    ~give_back() {
      {
        std::lock_guard guard(self->mutex_);
        self->free_.push_back(index);
      }
      self->returned_.notify_one();
    }
  } returning{this, index};
  auto result = render_frame(*all_[index], std::move(request));
  result.worker = index;
  return result;
}

}  // namespace argus::actors

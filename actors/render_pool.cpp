#include "actors/render_pool.hpp"

#include <stdexcept>
#include <utility>

#include "actors/type_ids.hpp"
#include "vision/capture.hpp"
#include "vision/renderer.hpp"

namespace argus::actors {
namespace {

struct render_worker_state {
  std::size_t index = 0;
  /// Shared only to pass it through spawn; no one else holds it.
  std::shared_ptr<vision::renderer> renderer;
};

// One detached actor per renderer: rendering blocks its thread for milliseconds, which would
// stall a scheduler worker shared with the lockstep participants.
caf::behavior render_worker(caf::stateful_actor<render_worker_state>* self, std::size_t index,
                            std::shared_ptr<vision::renderer> renderer) {
  self->state.index = index;
  self->state.renderer = std::move(renderer);
  return {
      [self](render_atom, render_request& request) -> render_result {
        auto result = render_frame(*self->state.renderer, std::move(request));
        result.worker = self->state.index;
        return result;
      },
  };
}

struct render_front_state {
  std::vector<caf::actor> workers;
  /// Requests in flight per worker.
  std::vector<std::size_t> load;
};

caf::behavior render_front(caf::stateful_actor<render_front_state>* self,
                           std::vector<caf::actor> workers) {
  for (auto& w : workers) self->link_to(w);
  self->state.load.assign(workers.size(), 0);
  self->state.workers = std::move(workers);
  return {
      [self](render_atom, render_request& request) {
        auto& st = self->state;
        std::size_t best = 0;
        for (std::size_t i = 1; i < st.load.size(); ++i)
          if (st.load[i] < st.load[best]) best = i;
        ++st.load[best];
        auto promise = self->make_response_promise<render_result>();
        self->request(st.workers[best], caf::infinite, render_atom_v, std::move(request))
            .then(
                [self, best, promise](render_result& result) mutable {
                  --self->state.load[best];
                  promise.deliver(std::move(result));
                },
                [self, best, promise](caf::error& err) mutable {
                  --self->state.load[best];
                  promise.deliver(std::move(err));
                });
        return promise;
      },
  };
}

}  // namespace

render_result render_frame(vision::renderer& renderer, render_request request) {
  render_result out;
  const auto& frame = *request.frame;
  if (!request.imaging) {
    out.image = renderer.render(request.view, frame, request.time_s);
    return out;
  }
  out.image = vision::capture(renderer, request.view, frame, request.time_s,
                              request.field_interval_s, *request.imaging);
  out.imaging = std::move(request.imaging);
  return out;
}

render_pool spawn_render_pool(caf::actor_system& system,
                              std::shared_ptr<const world::station> station, std::size_t workers) {
  if (workers == 0) throw std::invalid_argument("render pool: needs at least one worker");
  std::vector<caf::actor> handles;
  for (std::size_t i = 0; i < workers; ++i) {
    auto renderer = std::make_shared<vision::renderer>(station);
    handles.push_back(system.spawn<caf::detached>(render_worker, i, std::move(renderer)));
  }
  render_pool pool;
  pool.size = workers;
  pool.front = system.spawn(render_front, std::move(handles));
  return pool;
}

}  // namespace argus::actors

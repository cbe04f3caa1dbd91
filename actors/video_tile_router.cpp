#include "actors/video_tile_router.hpp"

#include <cstdint>
#include <exception>
#include <optional>
#include <set>
#include <utility>

#include "actors/render_pool.hpp"
#include "actors/type_ids.hpp"
#include "actors/video_tiles.hpp"
#include "spdlog/spdlog.h"

namespace argus::actors {
namespace {

// A tile out on a worker: kept whole, so it can be rendered here if the worker goes.
struct tile_in_flight {
  render_request request;
  caf::actor_addr host;
  caf::response_promise promise;
};

struct video_tile_router_state {
  video_tile_routes routes;
  std::set<caf::actor_addr> lost;
  std::map<std::uint64_t, tile_in_flight> in_flight;
  std::uint64_t next_id = 0;
  /// Made the first time a tile is rendered here.
  render_pool local;
};

using router_actor = caf::stateful_actor<video_tile_router_state>;

void render_here(router_actor* self, render_request request, caf::response_promise promise) {
  auto& st = self->state;
  if (!st.local.front) {
    try {
      st.local = spawn_render_pool(self->system(), st.routes.station, st.routes.local_renderers);
    } catch (const std::exception& e) {
      promise.deliver(caf::make_error(caf::sec::runtime_error,
                                      std::string("no renderer for the video here: ") + e.what()));
      return;
    }
    self->link_to(st.local.front);
  }
  self->request(st.local.front, caf::infinite, render_atom_v, std::move(request))
      .then([promise](render_result& result) mutable { promise.deliver(std::move(result)); },
            [promise](caf::error& err) mutable { promise.deliver(std::move(err)); });
}

// The worker's answer to tile `id`, unless the tile was rendered here meanwhile.
void on_tile(router_actor* self, std::uint64_t id, video_tile& tile) {
  auto it = self->state.in_flight.find(id);
  if (it == self->state.in_flight.end()) return;
  auto flight = std::move(it->second);
  self->state.in_flight.erase(it);
  try {
    flight.promise.deliver(from_tile(std::move(tile), std::move(flight.request.imaging)));
  } catch (const std::invalid_argument& e) {
    flight.promise.deliver(caf::make_error(caf::sec::runtime_error, e.what()));
  }
}

void on_tile_error(router_actor* self, std::uint64_t id, caf::error& err) {
  auto it = self->state.in_flight.find(id);
  if (it == self->state.in_flight.end()) return;
  auto flight = std::move(it->second);
  self->state.in_flight.erase(it);
  // The worker went before it answered: its down message may still be on its way.
  if (err == caf::sec::request_receiver_down) {
    self->state.lost.insert(flight.host);
    render_here(self, std::move(flight.request), std::move(flight.promise));
    return;
  }
  flight.promise.deliver(std::move(err));
}

caf::behavior video_tile_router(router_actor* self, video_tile_routes routes) {
  std::set<caf::actor> watched;
  for (const auto& [camera, host] : routes.hosts)
    if (host && watched.insert(host).second) self->monitor(host);
  self->state.routes = std::move(routes);
  self->set_down_handler([self](caf::down_msg& msg) {
    auto& st = self->state;
    if (!st.lost.insert(msg.source).second) return;
    spdlog::warn("video: a worker was lost; its cameras' tiles are rendered here from now on");
    std::vector<std::uint64_t> orphans;
    for (const auto& [id, flight] : st.in_flight)
      if (flight.host == msg.source) orphans.push_back(id);
    for (auto id : orphans) {
      auto flight = std::move(st.in_flight.at(id));
      st.in_flight.erase(id);
      render_here(self, std::move(flight.request), std::move(flight.promise));
    }
  });
  return {
      [self](render_atom, render_request& request) {
        auto& st = self->state;
        auto promise = self->make_response_promise<render_result>();
        auto it = st.routes.hosts.find(request.camera);
        if (it == st.routes.hosts.end() || !it->second || st.lost.count(it->second.address())) {
          render_here(self, std::move(request), promise);
          return promise;
        }
        const auto id = st.next_id++;
        auto tile = to_tile_request(request);
        st.in_flight.emplace(id, tile_in_flight{std::move(request), it->second.address(), promise});
        self->request(it->second, caf::infinite, video_tile_atom_v, std::move(tile))
            .then([self, id](video_tile& got) { on_tile(self, id, got); },
                  [self, id](caf::error& err) { on_tile_error(self, id, err); });
        return promise;
      },
  };
}

}  // namespace

caf::actor spawn_video_tile_router(caf::actor_system& system, video_tile_routes routes) {
  if (routes.local_renderers == 0) routes.local_renderers = 1;
  return system.spawn(video_tile_router, std::move(routes));
}

}  // namespace argus::actors

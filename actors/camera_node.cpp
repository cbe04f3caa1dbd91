#include "actors/camera_node.hpp"

#include "actors/participant_ids.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "fmt/format.h"

namespace argus::actors {
namespace {

struct camera_node_state {
  participant_info info;
  config::camera_settings camera;
  bool announced = false;
};

caf::behavior camera_node(caf::stateful_actor<camera_node_state>* self,
                          config::camera_settings camera) {
  auto& st = self->state;
  st.info = camera_participant(camera);
  st.camera = std::move(camera);
  return {
      [self](tick_atom, std::int64_t tick, std::uint8_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        if (!st.announced) {
          st.announced = true;
          ctx.emit("node_up",
                   fmt::format(R"("camera":{},"type":"{}")", st.camera.id,
                               st.camera.type == config::camera_type::ptz ? "ptz" : "static"));
        }
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
  };
}

}  // namespace

participant_info camera_participant(const config::camera_settings& camera) {
  return {participant_ids::camera(camera.id), fmt::format("camera/{}", camera.id), phase::cameras,
          wake_mode::every_tick};
}

caf::actor spawn_camera_node(caf::actor_system& system, const config::camera_settings& camera) {
  return system.spawn(camera_node, camera);
}

}  // namespace argus::actors

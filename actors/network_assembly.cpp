#include "actors/network_assembly.hpp"

#include <utility>
#include <vector>

#include "actors/camera_node.hpp"
#include "actors/link.hpp"
#include "actors/link_command.hpp"
#include "actors/type_ids.hpp"

namespace argus::actors {

network_directory spawn_network(caf::actor_system& system, const config::scenario& scenario,
                                const protocol::topology& topo, const caf::actor& clock,
                                std::shared_ptr<const camera_world> world) {
  network_directory net;
  net.world = std::move(world);
  std::vector<std::pair<caf::actor, participant_info>> links;
  auto model = make_link_model(scenario);
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    auto handle = spawn_link(system, scenario, model, i, a, b);
    net.links[a][b] = attached_link{info.id, handle};
    net.links[b][a] = attached_link{info.id, handle};
    links.emplace_back(handle, info);
  }
  for (const auto& cam : scenario.cameras) {
    auto node = spawn_camera_node(system, scenario, cam, net.links[cam.id], net.world);
    net.cameras.emplace(cam.id, node);
    caf::anon_send(clock, join_atom_v, node, camera_participant(cam));
  }
  attach_and_join_links(net, links, clock);
  return net;
}

void attach_and_join_links(const network_directory& net,
                           const std::vector<std::pair<caf::actor, participant_info>>& links,
                           const caf::actor& clock) {
  std::uint64_t seq = 0;
  for (const auto& [camera, neighbours] : net.links)
    for (const auto& [neighbour, link] : neighbours) {
      link_command attach;
      attach.op = link_op::attach;
      attach.node = camera;
      attach.handle = net.cameras.at(camera);
      // Stamped before tick 0, so each link reads it on its first tick.
      caf::anon_send(link.handle, link_cmd_atom_v, mail_stamp{-1, 0, 0, seq++}, attach);
    }
  for (const auto& [handle, info] : links) caf::anon_send(clock, join_atom_v, handle, info);
}

}  // namespace argus::actors

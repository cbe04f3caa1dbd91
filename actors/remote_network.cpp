#include "actors/remote_network.hpp"

#include <map>
#include <stdexcept>
#include <utility>

#include "actors/camera_node.hpp"
#include "actors/link.hpp"
#include "actors/network_assembly.hpp"
#include "actors/type_ids.hpp"
#include "actors/worker_host.hpp"
#include "fmt/format.h"
#include "spdlog/spdlog.h"

namespace argus::actors {

namespace {

// Asks `worker` and waits for its answer of type T, or throws naming it.
template <class T, class... Ts>
T ask(caf::scoped_actor& self, const worker_contact& worker, std::chrono::milliseconds timeout,
      const char* what, Ts&&... xs) {
  std::optional<T> out;
  std::string failure;
  self->request(worker.host, timeout, std::forward<Ts>(xs)...)
      .receive([&](T& answer) { out = std::move(answer); },
               [&](caf::error& err) {
                 failure = err == caf::sec::request_timeout
                               ? fmt::format("no answer within {} s", timeout.count() / 1000.0)
                               : self->system().render(err);
               });
  if (!out) throw std::runtime_error(fmt::format("worker {} ({}): {}", worker.name, what, failure));
  return std::move(*out);
}

}  // namespace

void greet_workers(caf::actor_system& system, const std::vector<worker_contact>& workers,
                   std::chrono::milliseconds timeout) {
  caf::scoped_actor self{system};
  for (const auto& w : workers) {
    std::string version;
    std::string failure;
    self->request(w.host, timeout, worker_hello_atom_v, std::string(argus_version()))
        .receive([&](std::string& v, std::string&) { version = std::move(v); },
                 [&](caf::error& err) {
                   failure = err == caf::sec::request_timeout
                                 ? fmt::format("no answer within {} s", timeout.count() / 1000.0)
                                 : system.render(err);
                 });
    if (!failure.empty())
      throw std::runtime_error(fmt::format("worker {} refused: {}", w.name, failure));
    if (version != argus_version())
      throw std::runtime_error(fmt::format("worker {} runs Argus {} and this coordinator Argus {}",
                                           w.name, version, argus_version()));
  }
}

network_directory spawn_remote_network(caf::actor_system& system, const config::scenario& scenario,
                                       const protocol::topology& topo, const caf::actor& clock,
                                       const std::vector<worker_contact>& workers,
                                       worker_setup setup) {
  const auto timeout = std::chrono::milliseconds(worker_setup_timeout);
  const auto where = place_cameras(scenario, workers.size());
  // Each worker's links, in topology order, and where their handles go.
  std::vector<std::vector<link_placement>> links_of(workers.size());
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    links_of[place_link(where, a, b)].push_back({i, a, b});
  }
  network_directory net;
  caf::scoped_actor self{system};
  std::vector<std::pair<caf::actor, participant_info>> links;
  std::vector<caf::actor> handles(topo.links().size());
  for (std::size_t w = 0; w < workers.size(); ++w) {
    auto mine = setup;
    mine.links = links_of[w];
    auto spawned = ask<std::vector<caf::actor>>(self, workers[w], timeout, "setting up",
                                                worker_setup_atom_v, std::move(mine));
    if (spawned.size() != links_of[w].size())
      throw std::runtime_error(fmt::format("worker {} spawned {} links of {}", workers[w].name,
                                           spawned.size(), links_of[w].size()));
    for (std::size_t k = 0; k < spawned.size(); ++k) handles[links_of[w][k].index] = spawned[k];
  }
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    info.host = workers[place_link(where, a, b)].name;
    net.links[a][b] = attached_link{info.id, handles[i]};
    net.links[b][a] = attached_link{info.id, handles[i]};
    links.emplace_back(handles[i], info);
  }
  // Cameras in scenario order, as spawn_network joins them; one request per worker.
  std::vector<std::vector<camera_placement>> cameras_of(workers.size());
  for (const auto& cam : scenario.cameras) {
    camera_placement p;
    p.camera = cam.id;
    for (const auto& [neighbour, link] : net.links[cam.id])
      p.links.push_back({neighbour, link.participant, link.handle});
    cameras_of[where.at(cam.id)].push_back(std::move(p));
  }
  std::map<int, caf::actor> nodes;
  for (std::size_t w = 0; w < workers.size(); ++w) {
    auto count = cameras_of[w].size();
    std::vector<int> ids;
    for (const auto& p : cameras_of[w]) ids.push_back(p.camera);
    auto spawned = ask<std::vector<caf::actor>>(self, workers[w], timeout, "spawning cameras",
                                                spawn_cameras_atom_v, std::move(cameras_of[w]));
    if (spawned.size() != count)
      throw std::runtime_error(fmt::format("worker {} spawned {} cameras of {}", workers[w].name,
                                           spawned.size(), count));
    for (std::size_t k = 0; k < count; ++k) nodes[ids[k]] = spawned[k];
  }
  for (const auto& cam : scenario.cameras) {
    const auto w = where.at(cam.id);
    net.cameras.emplace(cam.id, nodes.at(cam.id));
    net.hosts.emplace(cam.id, workers[w].host);
    net.host_names.emplace(cam.id, workers[w].name);
    auto info = camera_participant(cam);
    info.host = workers[w].name;
    caf::anon_send(clock, join_atom_v, nodes.at(cam.id), info);
  }
  attach_and_join_links(net, links, clock);
  return net;
}

void finish_workers(caf::actor_system& system, const std::vector<worker_contact>& workers,
                    eval::observation_log& log, std::chrono::milliseconds timeout) {
  caf::scoped_actor self{system};
  for (const auto& w : workers) {
    // A worker already lost (the run failed for it) is skipped at once rather than waited for:
    // monitoring a proxy whose node is gone reports it down immediately.
    self->monitor(w.host);
    bool lost = false;
    self->receive([&](caf::down_msg&) { lost = true; },
                  caf::after(std::chrono::seconds(0)) >> [] {});
    if (lost) {
      spdlog::warn("worker {} is gone: its cameras' frames are not in the evaluation", w.name);
      continue;
    }
    self->demonitor(w.host);
    try {
      log.add_worker_share(ask<eval::observation_log::contents>(
          self, w, timeout, "handing over its log", take_log_atom_v));
      ask<done_atom>(self, w, timeout, "releasing the run", release_atom_v);
    } catch (const std::exception& e) {
      spdlog::warn("{}", e.what());
    }
  }
}

}  // namespace argus::actors

#include "actors/remote_network.hpp"

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>
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

// Waits for `worker`'s answer of type T to the request behind `pending`, or throws naming it.
template <class T, class Pending>
T collect(caf::scoped_actor& self, const worker_contact& worker, std::chrono::milliseconds timeout,
          const char* what, Pending& pending) {
  std::optional<T> out;
  std::string failure;
  pending.receive([&](T& answer) { out = std::move(answer); },
                  [&](caf::error& err) {
                    failure = err == caf::sec::request_timeout
                                  ? fmt::format("no answer within {} s", timeout.count() / 1000.0)
                                  : self->system().render(err);
                  });
  if (!out) throw std::runtime_error(fmt::format("worker {} ({}): {}", worker.name, what, failure));
  return std::move(*out);
}

// Asks `worker` and waits for its answer of type T, or throws naming it.
template <class T, class... Ts>
T ask(caf::scoped_actor& self, const worker_contact& worker, std::chrono::milliseconds timeout,
      const char* what, Ts&&... xs) {
  auto pending = self->request(worker.host, timeout, std::forward<Ts>(xs)...);
  return collect<T>(self, worker, timeout, what, pending);
}

// Asks every worker at once, worker w with `message_of(w)`'s elements, and waits for all their
// answers of type T, in the workers' order: one after the other, a run waited for the sum of
// their set-ups (each parses the scenario and loads the station), side by side for the longest.
template <class T, class Message>
std::vector<T> ask_all(caf::scoped_actor& self, const std::vector<worker_contact>& workers,
                       std::chrono::milliseconds timeout, const char* what, Message message_of) {
  const auto request = [&](std::size_t w) {
    return std::apply(
        [&](auto&&... xs) {
          return self->request(workers[w].host, timeout, std::forward<decltype(xs)>(xs)...);
        },
        message_of(w));
  };
  std::vector<decltype(request(0))> pending;
  for (std::size_t w = 0; w < workers.size(); ++w) pending.push_back(request(w));
  std::vector<T> answers;
  for (std::size_t w = 0; w < workers.size(); ++w)
    answers.push_back(collect<T>(self, workers[w], timeout, what, pending[w]));
  return answers;
}

// Asks every worker in `live` at once, then hands each answer of type T to `use`, in their
// order; a worker that fails or does not answer is a warning, and the others are still asked.
template <class T, class Atom, class Use>
void ask_each(caf::scoped_actor& self, const std::vector<const worker_contact*>& live,
              std::chrono::milliseconds timeout, const char* what, Atom atom, Use use) {
  using request = decltype(self->request(caf::actor{}, timeout, atom));
  std::vector<request> pending;
  for (const auto* w : live) pending.push_back(self->request(w->host, timeout, atom));
  for (std::size_t i = 0; i < live.size(); ++i) {
    try {
      auto answer = collect<T>(self, *live[i], timeout, what, pending[i]);
      use(answer);
    } catch (const std::exception& e) {
      spdlog::warn("{}", e.what());
    }
  }
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

struct pending_set_up::requests {
  explicit requests(caf::actor_system& system) : self(system) {}
  caf::scoped_actor self;
  using handle = decltype(std::declval<caf::scoped_actor&>()->request(
      std::declval<caf::actor>(), std::chrono::milliseconds{}, worker_setup_atom_v,
      std::declval<worker_setup>()));
  std::vector<handle> pending;
  std::vector<std::vector<link_placement>> links_of;
  std::vector<std::optional<std::size_t>> host_of_link;
};

pending_set_up::pending_set_up() = default;
pending_set_up::pending_set_up(pending_set_up&&) noexcept = default;
pending_set_up& pending_set_up::operator=(pending_set_up&&) noexcept = default;
pending_set_up::~pending_set_up() = default;

pending_set_up ask_workers_to_set_up(caf::actor_system& system, const config::scenario& scenario,
                                     const protocol::topology& topo,
                                     const std::vector<worker_contact>& workers, worker_setup setup,
                                     worker_loss on_loss, const std::vector<bool>& steps_crowd) {
  pending_set_up out;
  out.asked = std::make_unique<pending_set_up::requests>(system);
  auto& asked = *out.asked;
  const auto where = place_cameras(scenario, workers.size());
  // Each worker's links, in topology order; the coordinator's (`--on-worker-loss crash-nodes`)
  // are spawned by spawn_remote_network.
  asked.links_of.resize(workers.size());
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    asked.host_of_link.push_back(place_link(where, a, b, on_loss));
    if (asked.host_of_link.back()) asked.links_of[*asked.host_of_link.back()].push_back({i, a, b});
  }
  for (std::size_t w = 0; w < workers.size(); ++w) {
    auto mine = setup;
    mine.links = asked.links_of[w];
    mine.steps_crowd = w < steps_crowd.size() && steps_crowd[w];
    asked.pending.push_back(asked.self->request(workers[w].host,
                                                std::chrono::milliseconds(worker_set_up_timeout),
                                                worker_setup_atom_v, std::move(mine)));
  }
  return out;
}

network_directory spawn_remote_network(caf::actor_system& system, const config::scenario& scenario,
                                       const protocol::topology& topo, const caf::actor& clock,
                                       const std::vector<worker_contact>& workers,
                                       pending_set_up asked_for) {
  const auto timeout = std::chrono::milliseconds(worker_setup_timeout);
  const auto where = place_cameras(scenario, workers.size());
  auto& asked = *asked_for.asked;
  auto& self = asked.self;
  std::vector<std::vector<caf::actor>> spawned_links;
  for (std::size_t w = 0; w < workers.size(); ++w)
    spawned_links.push_back(collect<std::vector<caf::actor>>(
        self, workers[w], std::chrono::milliseconds(worker_set_up_timeout), "setting up",
        asked.pending[w]));
  std::vector<caf::actor> handles(topo.links().size());
  std::shared_ptr<const protocol::link_model> model;
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    if (asked.host_of_link[i]) continue;
    auto [a, b] = topo.links()[i];
    if (!model) model = make_link_model(scenario);
    handles[i] = spawn_link(system, scenario, model, i, a, b);
  }
  network_directory net;
  std::vector<std::pair<caf::actor, participant_info>> links;
  const auto& links_of = asked.links_of;
  const auto& host_of_link = asked.host_of_link;
  for (std::size_t w = 0; w < workers.size(); ++w) {
    const auto& spawned = spawned_links[w];
    if (spawned.size() != links_of[w].size())
      throw std::runtime_error(fmt::format("worker {} spawned {} links of {}", workers[w].name,
                                           spawned.size(), links_of[w].size()));
    for (std::size_t k = 0; k < spawned.size(); ++k) handles[links_of[w][k].index] = spawned[k];
  }
  for (std::size_t i = 0; i < topo.links().size(); ++i) {
    auto [a, b] = topo.links()[i];
    auto info = link_participant(i, a, b);
    if (host_of_link[i]) info.host = workers[*host_of_link[i]].name;
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
  std::vector<std::vector<int>> ids_of(workers.size());
  for (std::size_t w = 0; w < workers.size(); ++w)
    for (const auto& p : cameras_of[w]) ids_of[w].push_back(p.camera);
  const auto spawned_cameras = ask_all<std::vector<caf::actor>>(
      self, workers, timeout, "spawning cameras", [&](std::size_t w) {
        return std::make_tuple(spawn_cameras_atom_v, std::move(cameras_of[w]));
      });
  for (std::size_t w = 0; w < workers.size(); ++w) {
    const auto& spawned = spawned_cameras[w];
    const auto count = ids_of[w].size();
    if (spawned.size() != count)
      throw std::runtime_error(fmt::format("worker {} spawned {} cameras of {}", workers[w].name,
                                           spawned.size(), count));
    for (std::size_t k = 0; k < count; ++k) nodes[ids_of[w][k]] = spawned[k];
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
                    eval::observation_log& log, std::chrono::milliseconds timeout, bool streamed,
                    const std::function<void(live_display)>& shown) {
  caf::scoped_actor self{system};
  std::vector<const worker_contact*> live;
  for (const auto& w : workers) {
    // A worker already lost (the run failed for it) is skipped at once rather than waited for:
    // monitoring a proxy whose node is gone reports it down immediately.
    self->monitor(w.host);
    bool lost = false;
    self->receive([&](caf::down_msg&) { lost = true; },
                  caf::after(std::chrono::seconds(0)) >> [] {});
    if (lost) {
      if (streamed)
        spdlog::warn("worker {} is gone: its cameras' frames up to its loss are in the evaluation",
                     w.name);
      else
        spdlog::warn("worker {} is gone: its cameras' frames are not in the evaluation", w.name);
      continue;
    }
    self->demonitor(w.host);
    live.push_back(&w);
  }
  // The last tick's turns: no gather follows them.
  if (shown)
    ask_each<live_display>(self, live, timeout, "showing its cameras' last turns",
                           take_display_atom_v,
                           [&](live_display& last) { shown(std::move(last)); });
  // Every worker is asked at once, so they write their logs side by side; they are added in
  // the workers' order, as one process records them.
  ask_each<eval::observation_log::contents>(
      self, live, timeout, "handing over its log", take_log_atom_v,
      [&](eval::observation_log::contents& share) { log.add_worker_share(std::move(share)); });
  ask_each<done_atom>(self, live, timeout, "releasing the run", release_atom_v, [](done_atom) {});
}

}  // namespace argus::actors

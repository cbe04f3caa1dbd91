#include "actors/camera_node.hpp"

#include <optional>
#include <vector>

#include "actors/camera_operator.hpp"
#include "actors/node_mail.hpp"
#include "actors/participant_ids.hpp"
#include "actors/render_pool.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "caf/sec.hpp"
#include "controller/strategy_registry.hpp"
#include "fmt/format.h"
#include "protocol/link_model.hpp"
#include "sensing/sensor_kinds.hpp"
#include "vision/imaging_model.hpp"

namespace argus::actors {
namespace {

struct camera_node_state {
  participant_info info;
  int camera_id = 0;
  bool ptz = true;
  bool up_logged = false;  // `node_up` emitted
  std::int64_t first_turn = -1;
  link_directory links;
  std::unique_ptr<protocol::node_network> network;
  net_arrivals arrivals;
  ordered_inbox<origination> to_originate;
  // What this node sends on a link is never due before the links' lookahead: it goes to the
  // link once per lookahead window (docs/network.md, "Outbox").
  link_outbox outbox{1};
  // The last turn taken: what a flush outside a turn (crash, end of run) is stamped with.
  mail_stamp last_turn{-1, static_cast<std::uint8_t>(phase::cameras), 0, 0};

  // The camera: its strategy (node knowledge only), its head, its sensor, its operator.
  std::unique_ptr<controller::strategy> strategy;
  std::string strategy_name;
  bool strategy_failed = false;  // it raised: the run ends after this tick
  std::optional<vision::ptz_camera> head;
  std::unique_ptr<sensing::sensor> sensor;  // null without a world
  std::optional<camera_operator> operator_desk;
  std::shared_ptr<const camera_world> world;
  vision::camera_placement placement;  // simulator knowledge: where the renderer puts it
  vision::frame_size frame;
  config::seconds tick_length{1.0 / 15.0};
  std::optional<vision::imaging_model> imaging;
  std::vector<controller::look_request> looks;           // to make in the next frame
  std::vector<controller::acquired_signature> acquired;  // for the next step

  // The turn in progress (it may wait for a rendered frame).
  std::optional<tick_context> ctx;
  caf::actor clock;
  controller::controller_input input;
  // The world as this turn senses it; null when it senses nothing.
  std::shared_ptr<const world::snapshot> snap;

  caf::behavior idle;
  caf::behavior computing_relevance;
  caf::behavior performing_task;
};

using node_actor = caf::stateful_actor<camera_node_state>;

// In a turn (`ctx` given) the hand-overs the links owe for it are announced to the clock;
// outside one (a crash, the end of the run) nobody waits for them.
void hand_to_links(node_actor* self, tick_context* ctx) {
  auto& st = self->state;
  st.outbox.flush(self, st.camera_id, st.last_turn, ctx != nullptr,
                  [&](std::uint64_t peer) { ctx->relayed_to(peer); });
}

std::vector<int> neighbours_of(const link_directory& links) {
  std::vector<int> out;
  for (const auto& [n, l] : links) out.push_back(n);
  return out;
}

void flush_network(node_actor* self, tick_context& ctx) {
  auto& st = self->state;
  const auto sent = batch_outgoing(*st.network, st.links, st.outbox, st.camera_id, ctx);
  if (sent > 0 && st.world && st.world->observer)
    st.world->observer->traffic(st.camera_id, sent, 0);
  if (st.outbox.window_ends(ctx.tick())) hand_to_links(self, &ctx);
}

vision::camera_view view_of(const camera_node_state& st) {
  vision::camera_view view;
  view.placement = st.placement;
  view.pose = st.head->state();
  view.width_px = st.frame.width_px;
  view.height_px = st.frame.height_px;
  return view;
}

caf::behavior& behaviour_for(camera_node_state& st) {
  switch (st.strategy->status().state) {
    case controller::node_state::idle:
      return st.idle;
    case controller::node_state::computing_relevance:
      return st.computing_relevance;
    case controller::node_state::performing_task:
      return st.performing_task;
  }
  return st.idle;
}

// A strategy that raises ends the run after this tick (outputs complete up to it): the node
// does nothing it asked, logs why and tells the clock, naming the strategy, camera and tick.
template <class Call>
auto guarded(camera_node_state& st, tick_context& ctx, Call call) -> decltype(call()) {
  if (st.strategy_failed) return {};
  try {
    return call();
  } catch (const std::exception& e) {
    st.strategy_failed = true;
    const auto why = fmt::format("strategy '{}' raised at camera {}, tick {}: {}", st.strategy_name,
                                 st.camera_id, ctx.tick(), e.what());
    ctx.emit(events::strategy_failed{.camera = st.camera_id, .error = {e.what()}});
    ctx.stop_run(why);
    return {};
  }
}

// The operator's picks due in this frame become the strategy's queries.
void take_picks(camera_node_state& st, const sensing::sensed_frame* frame) {
  auto& ctx = *st.ctx;
  std::function<void(const task_pick&)> picked;
  if (st.world && st.world->observer)
    picked = [&st](const task_pick& p) { st.world->observer->picked(p); };
  st.input.queries = st.operator_desk->resolve(
      frame, st.sensor.get(), st.strategy->takes_operator_signatures(),
      [&ctx](const events::event& e) { ctx.emit(e); }, picked);
}

// What the strategy asked the sensor to take from this frame: her signature, looked for from
// the next frame on and handed back to the strategy with it.
void take_signatures(camera_node_state& st, const std::vector<controller::acquire_request>& asked,
                     const sensing::sensed_frame* frame) {
  if (frame == nullptr || !st.sensor->can_acquire(*frame)) return;
  for (const auto& a : asked) {
    auto signature = st.sensor->acquire(a.task, *frame, a.box);
    st.looks.push_back({a.task, signature});
    st.acquired.push_back({a.task, std::move(signature)});
  }
}

// The second half of a turn, once the frame (if any) is there: sense, decide, act.
void finish_turn(node_actor* self, const cv::Mat& image) {
  auto& st = self->state;
  auto& ctx = *st.ctx;
  std::optional<sensing::sensed_frame> frame;
  if (st.snap)
    frame = sensing::sensed_frame{ctx.tick(), view_of(st), image, std::move(st.snap),
                                  st.world->station};
  if (frame && !st.looks.empty()) st.input.looks = st.sensor->look(*frame, st.looks);
  if (st.operator_desk->wants_frame()) take_picks(st, frame ? &*frame : nullptr);
  st.input.pose = st.head->state();
  st.input.sensed = frame.has_value();
  st.input.image = image;
  st.input.acquired = std::move(st.acquired);
  st.acquired.clear();
  auto out = guarded(st, ctx, [&] { return st.strategy->step(st.input); });
  for (auto& m : out.messages)
    st.network->send(m.destination, std::string(protocol::kind_of(m.message)),
                     protocol::encode(m.message));
  for (auto& e : out.events) ctx.emit(std::move(e.kind), std::move(e.fields_json));
  if (out.command) st.head->command(*out.command);
  st.looks = std::move(out.looks);
  take_signatures(st, out.acquire, frame ? &*frame : nullptr);
  st.head->step(st.tick_length);
  if (st.world && st.world->poses) st.world->poses->put(st.camera_id, ctx.tick(), st.head->state());
  if (st.world && st.world->observer)
    st.world->observer->turn_done(st.camera_id, ctx.tick(), st.head->state(), image,
                                  st.input.looks);
  st.input = {};
  st.network->tick(ctx.tick());
  flush_network(self, ctx);
  self->send(st.clock, std::move(*st.ctx).finish());
  st.ctx.reset();
  self->become(behaviour_for(st));
}

void take_turn(node_actor* self, std::int64_t tick, std::uint8_t p, const caf::actor& clock) {
  auto& st = self->state;
  st.last_turn = mail_stamp{tick, p, st.info.id, 0};
  st.ctx.emplace(st.info.id, st.info.name, tick, st.info.tick_phase);
  st.clock = clock;
  auto& ctx = *st.ctx;
  if (!st.up_logged) {
    st.up_logged = true;
    st.first_turn = tick;
    ctx.emit(events::node_up{.camera = st.camera_id, .type = st.ptz ? "ptz" : "static"});
  }
  st.input.tick = tick;
  const auto received = read_mail(*st.network, st.arrivals, st.to_originate, st.camera_id, tick, p,
                                  ctx, st.input.messages);
  if (received > 0 && st.world && st.world->observer)
    st.world->observer->traffic(st.camera_id, 0, received);
  if (st.world && st.world->operators) st.operator_desk->take_orders(*st.world->operators);
  st.input.cancels = st.operator_desk->take_due(tick, st.first_turn);
  auto plan = guarded(st, ctx, [&] { return st.strategy->plan(tick, !st.looks.empty()); });
  for (auto& e : plan.events) ctx.emit(std::move(e.kind), std::move(e.fields_json));
  // Only a node whose strategy or operator wants a frame takes one.
  const bool sense = st.world && (st.operator_desk->wants_frame() || plan.wants_frame);
  st.snap = sense ? st.world->board->latest() : nullptr;
  if (!st.snap || !st.sensor->needs_image()) {
    finish_turn(self, {});
    return;
  }
  render_request request;
  request.view = view_of(st);
  request.frame = st.snap;
  request.time_s = st.snap->time().count();
  request.field_interval_s = st.tick_length.count() / 2.0;
  request.imaging = std::move(st.imaging);
  render_result result;
  try {
    result = st.world->renderers->render(std::move(request));
  } catch (const std::exception&) {
    // As a render worker's failure came back through CAF: a handler's exception.
    st.ctx->emit(events::render_failed{.camera = st.camera_id,
                                       .error_code = static_cast<int>(caf::sec::runtime_error)});
    finish_turn(self, {});
    return;
  }
  st.imaging = std::move(result.imaging);
  finish_turn(self, result.image);
}

// A turn waits until every hand-over the clock announced for it has come (docs/network.md).
void take_turn_when_ready(node_actor* self) {
  if (auto t = self->state.arrivals.take_ready()) take_turn(self, t->tick, t->phase, t->clock);
}

// Fig. 10's top level: each state is a behaviour; they share the handlers of link mail and the
// end of the run.
caf::behavior state_behaviour(node_actor* self, controller::node_state state,
                              const caf::message_handler& shared) {
  return caf::message_handler{
      [self](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t relayed) {
        self->state.arrivals.hold({tick, p, caf::actor_cast<caf::actor>(self->current_sender())},
                                  relayed);
        take_turn_when_ready(self);
      },
      [state](node_state_atom) { return std::string(controller::name_of(state)); },
  }
      .or_else(shared);
}

// The camera's sensor and strategy: the scenario's, in the host's instruments.
void equip(camera_node_state& st, const config::scenario& scenario,
           const config::camera_settings& camera, const controller::node_identity& identity) {
  controller::oracle_source oracle;
  if (st.world) {
    st.sensor = sensing::make_sensor(scenario, camera, st.world->sensor_model);
    if (st.world->wrap_sensor) st.sensor = st.world->wrap_sensor(camera, std::move(st.sensor));
    if (st.world->oracle_for) oracle = st.world->oracle_for(camera);
    st.imaging = sensing::imaging_for(scenario, camera);
  }
  st.strategy_name = controller::strategy_name(scenario);
  st.strategy = controller::make_strategy(identity, scenario, oracle);
  if (st.world && st.world->wrap_strategy)
    st.strategy = st.world->wrap_strategy(camera, std::move(st.strategy));
}

caf::behavior camera_node(node_actor* self, const config::scenario& scenario,
                          config::camera_settings camera, link_directory links,
                          std::shared_ptr<const camera_world> world) {
  auto& st = self->state;
  st.info = camera_participant(camera);
  st.camera_id = camera.id;
  st.ptz = camera.type == config::camera_type::ptz;
  st.network = std::make_unique<protocol::node_network>(camera.id, neighbours_of(links), scenario);
  st.links = std::move(links);
  st.outbox = link_outbox{
      protocol::link_model::min_delay_ticks(scenario.network, scenario.run.tick.count())};
  const auto identity = controller::node_identity::from(camera);
  st.frame = identity.frame;
  st.head.emplace(vision::ptz_camera::from(camera));
  st.placement = vision::camera_placement::from(camera);
  st.tick_length = scenario.run.tick;
  st.world = std::move(world);
  st.operator_desk.emplace(scenario, camera.id);
  equip(st, scenario, camera, identity);
  // What the node sent before it went down was on the wire already: it still reaches the
  // links, and the fault injector waits for this node's end before the links run again.
  self->set_exit_handler([self](caf::exit_msg& msg) {
    hand_to_links(self, nullptr);
    self->quit(msg.reason);
  });
  caf::message_handler shared{
      // The run is over: the links count what is still queued as in flight.
      [self](flush_atom) {
        hand_to_links(self, nullptr);
        return done_atom_v;
      },
      [self](net_deliver_mail& mail) {
        self->state.arrivals.put(mail);
        take_turn_when_ready(self);
      },
      [self](net_retract_atom, std::uint64_t link, std::int64_t from_due) {
        self->state.arrivals.retract(link, from_due);
      },
      [self](net_originate_atom, const mail_stamp& stamp, int destination, std::string& kind,
             std::string& body, bool expects_reply) {
        self->state.to_originate.put(
            stamp, origination{destination, std::move(kind), std::move(body), expects_reply});
      },
  };
  st.idle = state_behaviour(self, controller::node_state::idle, shared);
  st.computing_relevance =
      state_behaviour(self, controller::node_state::computing_relevance, shared);
  st.performing_task = state_behaviour(self, controller::node_state::performing_task, shared);
  return st.idle;
}

}  // namespace

participant_info camera_participant(const config::camera_settings& camera) {
  participant_info info{participant_ids::camera(camera.id), fmt::format("camera/{}", camera.id),
                        phase::cameras, wake_mode::every_tick};
  info.flushes_at_end = true;
  return info;
}

caf::actor spawn_camera_node(caf::actor_system& system, const config::scenario& scenario,
                             const config::camera_settings& camera, link_directory links,
                             std::shared_ptr<const camera_world> world) {
  return system.spawn(camera_node, scenario, camera, std::move(links), std::move(world));
}

}  // namespace argus::actors

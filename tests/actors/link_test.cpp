#define CAF_SUITE actors.link

#include "actors/link.hpp"

#include <functional>
#include <map>
#include <set>

#include "actors/clock.hpp"
#include "actors/link_command.hpp"
#include "actors/link_outbox.hpp"
#include "actors/net_arrivals.hpp"
#include "actors/participant_ids.hpp"
#include "actors/system_config.hpp"
#include "caf/test/dsl.hpp"
#include "caf/test/unit_test_impl.hpp"
#include "tests/actors/recording_fixture.hpp"

using namespace argus;
using namespace argus::actors;
using namespace argus::actors::testing;

namespace {

struct delivery {
  std::int64_t tick;       // when the endpoint read it
  std::int64_t sent_tick;  // from the body
  std::uint64_t id;
};

struct endpoint_log {
  std::vector<delivery> got;
};

// A camera stand-in: sends `per_tick` messages to `peer` over the link on ticks in
// [from_tick, to_tick), and records what the link delivers to it.
struct endpoint_plan {
  int node = 0;
  int peer = 0;
  int per_tick = 0;
  std::int64_t from_tick = 0;
  std::int64_t to_tick = 0;
};

// Reads what the link hands over as a camera node does (actors/net_arrivals.hpp): each
// message in the endpoint's turn of its due tick, unless the link took it back first; a turn
// waits for the hand-overs the clock announces with it.
caf::behavior endpoint(caf::event_based_actor* self, endpoint_plan plan, caf::actor link,
                       std::uint64_t link_id, std::shared_ptr<endpoint_log> log) {
  auto seq = std::make_shared<std::uint32_t>(0);
  auto arrivals = std::make_shared<net_arrivals>();
  // 200 ms at 15 Hz: the links' lookahead. Sends go through an outbox as a camera node's do.
  auto outbox = std::make_shared<link_outbox>(3);
  auto turn = [=](const net_arrivals::turn& t) {
    tick_context ctx(participant_ids::camera(plan.node), "endpoint", t.tick, phase::cameras);
    arrivals->for_each_due(t.tick, t.phase,
                           [&](const mail_stamp& stamp, int, protocol::net_message& m) {
                             log->got.push_back({stamp.tick, std::stoll(m.body), m.id});
                           });
    mail_stamp now{t.tick, t.phase, participant_ids::camera(plan.node),
                   static_cast<std::uint64_t>(t.tick)};
    if (t.tick >= plan.from_tick && t.tick < plan.to_tick) {
      std::vector<protocol::net_message> batch;
      for (int i = 0; i < plan.per_tick; ++i) {
        protocol::net_message m;
        m.id = protocol::make_message_id(plan.node, (*seq)++);
        m.origin = plan.node;
        m.destination = plan.peer;
        m.kind = "test";
        m.body = std::to_string(t.tick);
        batch.push_back(std::move(m));
      }
      outbox->add(link_id, link, participant_ids::camera(plan.peer), t.tick, std::move(batch));
    }
    if (outbox->window_ends(t.tick))
      outbox->flush(self, plan.node, now, true, [&](std::uint64_t peer) { ctx.relayed_to(peer); });
    self->send(t.clock, std::move(ctx).finish());
  };
  return {
      [=](flush_atom) {
        outbox->flush(self, plan.node, mail_stamp{}, false, [](std::uint64_t) {});
        return done_atom_v;
      },
      [=](net_deliver_mail& mail) {
        arrivals->put(mail);
        if (auto t = arrivals->take_ready()) turn(*t);
      },
      [=](net_retract_atom, std::uint64_t from_link, std::int64_t from_due) {
        arrivals->retract(from_link, from_due);
      },
      [=](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t relayed) {
        arrivals->hold({tick, p, caf::actor_cast<caf::actor>(self->current_sender())}, relayed);
        if (auto t = arrivals->take_ready()) turn(*t);
      },
  };
}

// Ticked every tick as a camera; hands its outbox to the link when the run ends.
participant_info endpoint_participant(int node, std::string name) {
  participant_info info{participant_ids::camera(node), std::move(name), phase::cameras,
                        wake_mode::every_tick};
  info.flushes_at_end = true;
  return info;
}

// What the fault injector does to actors besides telling the link (kill, retire, join).
using side_effects = std::map<std::int64_t, std::function<void(caf::event_based_actor*)>>;

// Sends scheduled commands to the link in the faults phase, as the fault injector does: a
// request, and the turn's ack once the link has answered.
caf::behavior commander(caf::event_based_actor* self, caf::actor link,
                        std::map<std::int64_t, link_command> schedule, side_effects effects) {
  return {
      [=](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        tick_context ctx(participant_ids::fault_injector, "commander", tick, phase::faults);
        if (auto effect = effects.find(tick); effect != effects.end()) effect->second(self);
        auto clock = caf::actor_cast<caf::actor>(self->current_sender());
        auto ack = std::make_shared<tick_ack>(std::move(ctx).finish());
        auto it = schedule.find(tick);
        if (it == schedule.end()) {
          self->send(clock, std::move(*ack));
          return;
        }
        self->request(link, caf::infinite, link_cmd_atom_v,
                      mail_stamp{tick, 0, participant_ids::fault_injector, 0}, it->second)
            .then([=](done_atom) { self->send(clock, std::move(*ack)); });
      },
  };
}

struct fixture : recording_fixture {
  std::shared_ptr<endpoint_log> at1 = std::make_shared<endpoint_log>();
  std::shared_ptr<endpoint_log> at2 = std::make_shared<endpoint_log>();
  caf::actor clock;
  caf::actor link;
  std::uint64_t link_id = participant_ids::link(0);

  caf::actor e2;

  void build(config::network_settings net, std::int64_t ticks, endpoint_plan plan1,
             std::map<std::int64_t, link_command> schedule = {}, side_effects effects = {}) {
    clock_settings cs;
    cs.end_tick = ticks;
    clock = spawn_clock(sys, cs, recorder, caf::actor{});
    config::scenario s;
    s.run.seed = 5;
    s.network = net;
    link = spawn_link(sys, s, 0, 1, 2);
    auto e1 = sys.spawn(endpoint, plan1, link, link_id, at1);
    e2 = sys.spawn(endpoint, endpoint_plan{2, 1, 0, 0, 0}, link, link_id, at2);
    attach(1, e1);
    attach(2, e2);
    self->send(clock, join_atom_v, link, link_participant(0, 1, 2));
    self->send(clock, join_atom_v, e1, endpoint_participant(1, "e1"));
    self->send(clock, join_atom_v, e2, endpoint_participant(2, "e2"));
    auto cmd = sys.spawn(commander, link, std::move(schedule), std::move(effects));
    self->send(clock, join_atom_v, cmd,
               participant_info{participant_ids::fault_injector, "commander", phase::faults,
                                wake_mode::every_tick});
  }

  void attach(int node, caf::actor handle) {
    link_command c;
    c.op = link_op::attach;
    c.node = node;
    c.handle = std::move(handle);
    caf::anon_send(link, link_cmd_atom_v, mail_stamp{-1, 0, 0, static_cast<std::uint64_t>(node)},
                   c);
  }

  protocol::message_counts run_and_count() {
    self->send(clock, start_atom_v);
    run();
    run_result result;
    self->receive([&](run_result& r) { result = std::move(r); },
                  caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
    CAF_REQUIRE_EQUAL(result.links.count("link/1-2"), 1u);
    return result.links["link/1-2"]["test"];
  }
};

config::network_settings lossless() {
  config::network_settings n;
  n.loss_probability = 0.0;
  return n;
}

}  // namespace

CAF_TEST_FIXTURE_SCOPE(link_tests, fixture)

CAF_TEST(delays cover exactly the table 2 bounds when reordering is allowed) {
  auto net = lossless();
  net.reorder = true;
  build(net, 120, {1, 2, 20, 0, 100});
  auto c = run_and_count();
  CAF_CHECK_EQUAL(c.sent, 2000u);
  CAF_CHECK_EQUAL(c.delivered, 2000u);
  CAF_CHECK(c.balanced());
  CAF_REQUIRE_EQUAL(at2->got.size(), 2000u);
  std::int64_t lo = 100, hi = 0;
  bool reordered = false;
  for (std::size_t i = 0; i < at2->got.size(); ++i) {
    auto delay = at2->got[i].tick - at2->got[i].sent_tick;
    lo = std::min(lo, delay);
    hi = std::max(hi, delay);
    if (i > 0 && at2->got[i - 1].id > at2->got[i].id) reordered = true;
  }
  // 200-500 ms at 15 Hz: 3 to 7 ticks.
  CAF_CHECK_EQUAL(lo, 3);
  CAF_CHECK_EQUAL(hi, 7);
  CAF_CHECK(reordered);
}

CAF_TEST(by default each direction delivers in order within the bounds) {
  build(lossless(), 120, {1, 2, 20, 0, 100});
  auto c = run_and_count();
  CAF_CHECK_EQUAL(c.delivered, 2000u);
  CAF_REQUIRE_EQUAL(at2->got.size(), 2000u);
  for (std::size_t i = 0; i < at2->got.size(); ++i) {
    auto delay = at2->got[i].tick - at2->got[i].sent_tick;
    CAF_CHECK(delay >= 3 && delay <= 7);
    if (i > 0) CAF_CHECK_LESS(at2->got[i - 1].id, at2->got[i].id);
  }
}

CAF_TEST(loss rate within statistical tolerance and accounting balanced) {
  config::network_settings net;  // Table 2: loss 0.1
  build(net, 110, {1, 2, 40, 0, 100});
  auto c = run_and_count();
  CAF_CHECK_EQUAL(c.sent, 4000u);
  auto rate = static_cast<double>(c.lost) / static_cast<double>(c.sent);
  // 5 standard deviations of binomial(4000, 0.1): 0.024.
  CAF_CHECK_LESS(std::abs(rate - 0.1), 0.024);
  CAF_CHECK_EQUAL(c.delivered, at2->got.size());
  CAF_CHECK(c.balanced());
}

CAF_TEST(a cut loses everything until the link is healed) {
  link_command cut;
  cut.op = link_op::cut;
  link_command heal;
  heal.op = link_op::heal;
  build(lossless(), 80, {1, 2, 1, 0, 60}, {{20, cut}, {40, heal}});
  auto c = run_and_count();
  // Sent before 13 arrive before the cut at 20 (at most 7 ticks late); sent 13..19 may be
  // caught on the wire; sent 20..39 are lost; sent from 40 on arrive.
  for (const auto& d : at2->got) CAF_CHECK(d.sent_tick < 20 || d.sent_tick >= 40);
  std::size_t after_heal = 0;
  for (const auto& d : at2->got) after_heal += d.sent_tick >= 40 ? 1 : 0;
  CAF_CHECK_EQUAL(after_heal, 20u);
  CAF_CHECK_GREATER_OR_EQUAL(c.lost, 20u);
  CAF_CHECK(c.balanced());
}

CAF_TEST(a cut and a heal judge a message by when it was sent however late it is read) {
  // Windows of 3 ticks: what is sent at 18, 19 and 20 reaches the link at 21. The link runs
  // at 19 for the cut and at 20 for the heal before it reads the messages sent at 18 and 19.
  link_command cut;
  cut.op = link_op::cut;
  link_command heal;
  heal.op = link_op::heal;
  build(lossless(), 60, {1, 2, 1, 0, 40}, {{19, cut}, {20, heal}});
  auto c = run_and_count();
  std::set<std::int64_t> sent;
  for (const auto& d : at2->got) sent.insert(d.sent_tick);
  // On the wire at the cut (sent at 18, read after it) or sent while cut (19): lost.
  CAF_CHECK_EQUAL(sent.count(18), 0u);
  CAF_CHECK_EQUAL(sent.count(19), 0u);
  // Due before the cut whatever the delay (sent by 11): delivered. Sent after the heal: too.
  for (std::int64_t t = 0; t <= 11; ++t) CAF_CHECK_EQUAL(sent.count(t), 1u);
  for (std::int64_t t = 20; t < 40; ++t) CAF_CHECK_EQUAL(sent.count(t), 1u);
  CAF_CHECK_EQUAL(c.delivered, at2->got.size());
  CAF_CHECK(c.balanced());
}

CAF_TEST(a loss burst applies to what was sent while it lasted however late it is read) {
  link_command burst;
  burst.op = link_op::loss_burst;
  burst.loss_probability = 1.0;
  burst.until_tick = 21;
  build(lossless(), 60, {1, 2, 1, 0, 40}, {{19, burst}});
  auto c = run_and_count();
  std::set<std::int64_t> sent;
  for (const auto& d : at2->got) sent.insert(d.sent_tick);
  for (std::int64_t t = 0; t < 40; ++t)
    CAF_CHECK_EQUAL(sent.count(t), t == 19 || t == 20 ? 0u : 1u);
  CAF_CHECK_EQUAL(c.lost, 2u);
  CAF_CHECK(c.balanced());
}

CAF_TEST(messages sent in the last window are counted in flight at the end) {
  // Sent until the run ends at 50: the windows ending at 47 reach the link; 48 and 49 are
  // handed over when the run ends, and with everything else not yet due are in flight.
  build(lossless(), 50, {1, 2, 1, 0, 50});
  auto c = run_and_count();
  CAF_CHECK_EQUAL(c.sent, 50u);
  CAF_CHECK_EQUAL(c.delivered, at2->got.size());
  CAF_CHECK_GREATER_OR_EQUAL(c.in_flight, 2u);
  CAF_CHECK(c.balanced());
}

CAF_TEST(messages to a crashed node are dropped and counted and a recovered node is reachable) {
  link_command down;
  down.op = link_op::node_down;
  down.node = 2;
  // The node crashes at tick 20 (killed, retired from the clock, links told) and comes back
  // at tick 40 as a fresh actor that joins the clock and is attached to the link.
  auto fresh_log = std::make_shared<endpoint_log>();
  auto fresh = sys.spawn(endpoint, endpoint_plan{2, 1, 0, 0, 0}, caf::actor{}, link_id, fresh_log);
  link_command back;
  back.op = link_op::attach;
  back.node = 2;
  back.handle = fresh;
  side_effects effects;
  effects[20] = [this](caf::event_based_actor* cmd) {
    cmd->send(clock, retire_atom_v, participant_ids::camera(2));
    cmd->send_exit(e2, caf::exit_reason::kill);
  };
  effects[40] = [this, fresh](caf::event_based_actor* cmd) {
    cmd->send(clock, join_atom_v, fresh, endpoint_participant(2, "fresh"));
  };
  build(lossless(), 80, {1, 2, 1, 0, 60}, {{20, down}, {40, back}}, std::move(effects));
  auto c = run_and_count();
  for (const auto& d : at2->got) CAF_CHECK_LESS(d.tick, 20);
  CAF_CHECK(!fresh_log->got.empty());
  for (const auto& d : fresh_log->got) CAF_CHECK_GREATER_OR_EQUAL(d.tick, 40);
  CAF_CHECK_GREATER(c.dropped, 10u);  // due at ticks 20..39, while the node was down
  CAF_CHECK_EQUAL(c.delivered, at2->got.size() + fresh_log->got.size());
  CAF_CHECK_EQUAL(c.delivered + c.dropped, 60u);  // everything sent arrived or was dropped
  CAF_CHECK(c.balanced());
}

CAF_TEST_FIXTURE_SCOPE_END()

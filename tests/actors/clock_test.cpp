#define CAF_SUITE actors.clock

#include "actors/clock.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "actors/participant_ids.hpp"
#include "actors/system_config.hpp"
#include "actors/tick_context.hpp"
#include "actors/worker_loss.hpp"
#include "caf/test/dsl.hpp"
#include "caf/test/unit_test_impl.hpp"
#include "tests/actors/recording_fixture.hpp"

using namespace argus::actors;
using namespace argus::actors::testing;

namespace {

struct fixture : recording_fixture {
  std::shared_ptr<probe_log> log = std::make_shared<probe_log>();

  caf::actor make_clock(std::int64_t end_tick, double speed = 0.0) {
    clock_settings s;
    s.end_tick = end_tick;
    s.speed = speed;
    s.tick_seconds = 1.0 / 15.0;
    return spawn_clock(sys, s, recorder, caf::actor{});
  }

  caf::actor add_probe(const caf::actor& clock, participant_info info,
                       std::vector<std::uint64_t> wakes = {}, std::int64_t period = 0) {
    auto p = sys.spawn(probe, info, log, std::move(wakes), period);
    caf::anon_send(clock, join_atom_v, p, info);
    return p;
  }

  // Starts the clock and runs everything (timeouts included) until the run is over.
  run_result run_to_end(const caf::actor& clock) {
    self->send(clock, start_atom_v);
    run();
    run_result result;
    bool got = false;
    self->receive([&](run_result& r) { result = std::move(r), got = true; },
                  caf::after(std::chrono::seconds(0)) >> [] {});
    CAF_REQUIRE(got);
    return result;
  }

  std::size_t count(const std::string& entry) const {
    return static_cast<std::size_t>(std::count(log->ticks.begin(), log->ticks.end(), entry));
  }
};

participant_info info(std::uint64_t id, std::string name, phase p,
                      wake_mode m = wake_mode::every_tick) {
  return {id, std::move(name), p, m};
}

}  // namespace

CAF_TEST_FIXTURE_SCOPE(clock_tests, fixture)

CAF_TEST(every tick runs the phases in order and participants in id order) {
  auto clock = make_clock(2);
  // Joined out of order on purpose: the clock orders by phase, then id.
  add_probe(clock, info(30, "cam-b", phase::cameras));
  add_probe(clock, info(10, "crowd", phase::world));
  add_probe(clock, info(20, "cam-a", phase::cameras));
  add_probe(clock, info(5, "faults", phase::faults));
  add_probe(clock, info(15, "link", phase::network));
  auto result = run_to_end(clock);
  CAF_CHECK_EQUAL(result.ticks, 2);
  std::vector<std::string> expected{"0:0:faults", "0:1:crowd",  "0:2:link",  "0:3:cam-a",
                                    "0:3:cam-b",  "1:0:faults", "1:1:crowd", "1:2:link",
                                    "1:3:cam-a",  "1:3:cam-b"};
  // cam-a and cam-b share a phase: both are ticked before either answers, in id order.
  CAF_CHECK_EQUAL(log->ticks, expected);
  CAF_REQUIRE_EQUAL(rec->events.size(), 10u);
  CAF_CHECK_EQUAL(rec->events[3].source, "cam-a");
  CAF_CHECK_EQUAL(rec->events[4].source, "cam-b");
  CAF_CHECK(rec->done);
}

CAF_TEST(the next phase waits for every acknowledgement of the current one) {
  auto clock = make_clock(1);
  auto a = sys.spawn(silent, "x");
  auto b = sys.spawn(silent, "x");
  auto later = sys.spawn(silent, "x");
  self->send(clock, join_atom_v, a, info(1, "a", phase::world));
  self->send(clock, join_atom_v, b, info(2, "b", phase::world));
  self->send(clock, join_atom_v, later, info(3, "later", phase::cameras));
  self->send(clock, start_atom_v);
  sched.run();
  // a and b got tick 0; `later` must not, until both acknowledged.
  tick_ack ack_a;
  ack_a.participant = 1;
  inject((tick_ack), from(a).to(clock).with(ack_a));
  disallow((tick_atom, std::int64_t, std::uint8_t, std::uint32_t), from(clock).to(later));
  tick_ack ack_b;
  ack_b.participant = 2;
  inject((tick_ack), from(b).to(clock).with(ack_b));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(later).with(_, std::int64_t{0}, std::uint8_t{3}, std::uint32_t{0}));
  tick_ack ack_later;
  ack_later.participant = 3;
  inject((tick_ack), from(later).to(clock).with(ack_later));
  run();
  CAF_CHECK(rec->done);
}

CAF_TEST(a participant killed mid tick does not stall the run) {
  auto clock = make_clock(3);
  add_probe(clock, info(1, "crowd", phase::world));
  auto victim = sys.spawn(silent, "x");  // will never acknowledge tick 0
  self->send(clock, join_atom_v, victim, info(2, "victim", phase::cameras));
  self->send(clock, start_atom_v);
  sched.run();
  CAF_CHECK_EQUAL(count("1:1:crowd"), 0u);  // stuck waiting for the victim
  caf::anon_send_exit(victim, caf::exit_reason::kill);
  run();
  run_result result;
  self->receive([&](run_result& r) { result = std::move(r); },
                caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
  CAF_CHECK_EQUAL(result.ticks, 3);
  CAF_CHECK_EQUAL(count("2:1:crowd"), 1u);
  CAF_REQUIRE_EQUAL(result.unexpected_down.size(), 1u);
  CAF_CHECK_EQUAL(result.unexpected_down[0], "victim");
  auto down = std::find_if(rec->events.begin(), rec->events.end(),
                           [](const sim_event& e) { return e.kind == "participant_down"; });
  CAF_REQUIRE(down != rec->events.end());
  CAF_CHECK_EQUAL(down->tick, 0);
  CAF_CHECK_EQUAL(down->source, "victim");
}

CAF_TEST(a retired participant leaves at once and is not reported as unexpected) {
  auto clock = make_clock(3);
  add_probe(clock, info(1, "crowd", phase::world));
  auto victim = sys.spawn(silent, "x");
  self->send(clock, join_atom_v, victim, info(2, "victim", phase::cameras));
  self->send(clock, start_atom_v);
  sched.run();
  self->send(clock, retire_atom_v, std::uint64_t{2});
  caf::anon_send_exit(victim, caf::exit_reason::kill);
  auto result = [&] {
    run();
    run_result r;
    self->receive([&](run_result& x) { r = std::move(x); },
                  caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
    return r;
  }();
  CAF_CHECK_EQUAL(result.ticks, 3);
  CAF_CHECK(result.unexpected_down.empty());
}

CAF_TEST(idle on demand participants cost nothing until woken) {
  auto clock = make_clock(4);
  // The waker, in the network phase, wakes "late" (cameras, a later phase: same tick) and
  // "early" (world, an earlier phase: next tick), and only on ticks 0..3 as a probe does.
  add_probe(clock, info(1, "early", phase::world, wake_mode::on_demand));
  add_probe(clock, info(2, "late", phase::cameras, wake_mode::on_demand));
  add_probe(clock, info(3, "sleeper", phase::cameras, wake_mode::on_demand));
  add_probe(clock, info(9, "waker", phase::network, wake_mode::on_demand), {1, 2}, 2);
  run_to_end(clock);
  // Everyone on-demand is ticked once when it joins (tick 0).
  CAF_CHECK_EQUAL(count("0:1:early"), 1u);
  CAF_CHECK_EQUAL(count("0:3:sleeper"), 1u);
  // The sleeper asked for nothing and got no mail: never ticked again.
  CAF_CHECK_EQUAL(count("1:3:sleeper") + count("2:3:sleeper") + count("3:3:sleeper"), 0u);
  // The waker runs at 0 and 2 (period 2); its mail wakes "late" the same tick...
  CAF_CHECK_EQUAL(count("0:2:waker"), 1u);
  CAF_CHECK_EQUAL(count("1:2:waker"), 0u);
  CAF_CHECK_EQUAL(count("2:2:waker"), 1u);
  CAF_CHECK_EQUAL(count("2:3:late"), 1u);
  CAF_CHECK_EQUAL(count("1:3:late"), 0u);
  // ...and "early" the next tick.
  CAF_CHECK_EQUAL(count("1:1:early"), 1u);
  CAF_CHECK_EQUAL(count("3:1:early"), 1u);
  CAF_CHECK_EQUAL(count("2:1:early"), 0u);
}

CAF_TEST(relayed hand overs are announced with the receivers next tick) {
  auto clock = make_clock(3);
  auto sender = sys.spawn(silent, "x");
  auto receiver = sys.spawn(silent, "x");
  auto relay = sys.spawn(silent, "x");
  self->send(clock, join_atom_v, sender, info(1, "sender", phase::cameras));
  self->send(clock, join_atom_v, receiver, info(2, "receiver", phase::cameras));
  // A relay (a link) is never ticked: only the two cameras are.
  self->send(clock, join_atom_v, relay, info(9, "relay", phase::network, wake_mode::never));
  self->send(clock, start_atom_v);
  for (int i = 0; i < 3; ++i)
    expect((join_atom, caf::actor, participant_info), from(self).to(clock));
  expect((start_atom), from(self).to(clock));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(sender).with(_, std::int64_t{0}, std::uint8_t{3}, std::uint32_t{0}));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(receiver).with(_, std::int64_t{0}, std::uint8_t{3}, std::uint32_t{0}));
  // Tick 0: the sender flushed to two links towards the receiver, and one towards a camera
  // that is not a participant (crashed): announced, ignored.
  tick_ack from_sender;
  from_sender.participant = 1;
  from_sender.relayed = {2, 2, 77};
  inject((tick_ack), from(sender).to(clock).with(from_sender));
  tick_ack from_receiver;
  from_receiver.participant = 2;
  inject((tick_ack), from(receiver).to(clock).with(from_receiver));
  expect((advance_atom), from(clock).to(clock));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(sender).with(_, std::int64_t{1}, std::uint8_t{3}, std::uint32_t{0}));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(receiver).with(_, std::int64_t{1}, std::uint8_t{3}, std::uint32_t{2}));
  // Tick 1: nothing relayed; the count does not carry over.
  from_sender.tick = 1;
  from_sender.relayed.clear();
  from_receiver.tick = 1;
  inject((tick_ack), from(sender).to(clock).with(from_sender));
  inject((tick_ack), from(receiver).to(clock).with(from_receiver));
  expect((advance_atom), from(clock).to(clock));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(sender).with(_, std::int64_t{2}, std::uint8_t{3}, std::uint32_t{0}));
  expect((tick_atom, std::int64_t, std::uint8_t, std::uint32_t),
         from(clock).to(receiver).with(_, std::int64_t{2}, std::uint8_t{3}, std::uint32_t{0}));
  auto relay_ticked = received<tick_atom, std::int64_t, std::uint8_t, std::uint32_t>(relay);
  CAF_CHECK(!relay_ticked);
  // Tick 2, the last: the run ends and the clock lets everyone go.
  from_sender.tick = 2;
  from_receiver.tick = 2;
  inject((tick_ack), from(sender).to(clock).with(from_sender));
  inject((tick_ack), from(receiver).to(clock).with(from_receiver));
  run();
  CAF_CHECK(rec->done);
}

CAF_TEST(a relay that dies ends the run with an error that names it) {
  auto clock = make_clock(5);
  add_probe(clock, info(1, "crowd", phase::world));
  // A camera waiting for the relay's hand-over: it does not answer tick 0.
  auto waiting = sys.spawn(silent, "x");
  self->send(clock, join_atom_v, waiting, info(2, "camera", phase::cameras));
  auto relay = sys.spawn(silent, "x");
  self->send(clock, join_atom_v, relay, info(9, "link/3-4", phase::network, wake_mode::never));
  self->send(clock, start_atom_v);
  sched.run();
  CAF_CHECK_EQUAL(count("0:1:crowd"), 1u);
  caf::anon_send_exit(relay, caf::exit_reason::kill);
  run();
  std::string error;
  self->receive([&](run_result&) { CAF_FAIL("the run went on without its relay"); },
                [&](caf::error& err) { error = to_string(err); },
                caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
  CAF_CHECK_NOT_EQUAL(error.find("link/3-4"), std::string::npos);
  CAF_CHECK_EQUAL(count("1:1:crowd"), 0u);
}

CAF_TEST(the world that dies ends the run with an error that names it) {
  auto clock = make_clock(5);
  add_probe(clock, info(1, "crowd", phase::world));
  auto world = sys.spawn(silent, "x");
  self->send(
      clock, join_atom_v, world,
      info(participant_ids::world_coordinator, "world", phase::network, wake_mode::on_demand));
  self->send(clock, start_atom_v);
  sched.run();
  caf::anon_send_exit(world, caf::exit_reason::kill);
  run();
  std::string error;
  self->receive([&](run_result&) { CAF_FAIL("the run went on without its world"); },
                [&](caf::error& err) { error = to_string(err); },
                caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
  CAF_CHECK_NOT_EQUAL(error.find("the world stopped unexpectedly"), std::string::npos);
}

CAF_TEST(a lost worker ends the run with the last whole tick naming the worker) {
  auto clock = make_clock(5);
  add_probe(clock, info(1, "crowd", phase::world));
  auto remote = info(participant_ids::camera(7), "camera/7", phase::cameras);
  remote.host = "10.0.0.2:4242";
  auto camera = sys.spawn(silent, "x");  // stuck in tick 0 when its worker goes
  self->send(clock, join_atom_v, camera, remote);
  self->send(clock, start_atom_v);
  sched.run();
  caf::anon_send_exit(camera, caf::exit_reason::remote_link_unreachable);
  run();
  run_result result;
  self->receive([&](run_result& r) { result = std::move(r); },
                caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
  CAF_CHECK_EQUAL(result.ticks, 0);
  CAF_CHECK_NOT_EQUAL(result.failure.find("worker 10.0.0.2:4242 was lost during tick 0"),
                      std::string::npos);
  CAF_CHECK(result.lost_workers.empty());
}

CAF_TEST(a worker that is shut down mid run is a lost worker and says so) {
  // argus worker stopped with SIGTERM or Ctrl-C ends what it hosts with user_shutdown; one of
  // its links going that way must not read as a relay that broke the network.
  auto clock = make_clock(5);
  add_probe(clock, info(1, "crowd", phase::world));
  auto remote = info(participant_ids::link(3), "link/2-7", phase::network, wake_mode::never);
  remote.host = "10.0.0.2:4242";
  auto link = sys.spawn(silent, "x");
  self->send(clock, join_atom_v, link, remote);
  auto camera_there = info(participant_ids::camera(7), "camera/7", phase::cameras);
  camera_there.host = remote.host;
  self->send(clock, join_atom_v, sys.spawn(silent, "x"), camera_there);  // stuck in tick 0
  self->send(clock, start_atom_v);
  sched.run();
  caf::anon_send_exit(link, caf::exit_reason::user_shutdown);
  run();
  run_result result;
  self->receive([&](run_result& r) { result = std::move(r); },
                [&](caf::error& err) { CAF_FAIL("the run failed as a broken network: " << err); },
                caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
  CAF_CHECK_NOT_EQUAL(
      result.failure.find(
          "worker 10.0.0.2:4242 was lost during tick 0 (link/2-7 ended: the worker was shut down)"),
      std::string::npos);
}

// The fault injector's stand-in under --on-worker-loss crash-nodes: it records the losses it
// hears of, and the ticks it gets.
caf::behavior loss_listener(caf::event_based_actor* self, std::shared_ptr<probe_log> log,
                            std::shared_ptr<std::vector<lost_worker>> heard) {
  return {
      [=](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        log->ticks.push_back(std::to_string(tick) + ":0:faults");
        tick_context ctx(participant_ids::fault_injector, "faults", tick, phase::faults);
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
      [=](lost_worker& lost) { heard->push_back(std::move(lost)); },
  };
}

CAF_TEST(under crash nodes a lost worker leaves the barrier and the run goes on) {
  clock_settings s;
  s.end_tick = 4;
  s.on_worker_loss = worker_loss::crash_nodes;
  auto clock = spawn_clock(sys, s, recorder, caf::actor{});
  auto heard = std::make_shared<std::vector<lost_worker>>();
  auto faults = sys.spawn(loss_listener, log, heard);
  self->send(clock, join_atom_v, faults,
             info(participant_ids::fault_injector, "faults", phase::faults, wake_mode::on_demand));
  add_probe(clock, info(1, "crowd", phase::world));
  add_probe(clock, info(participant_ids::camera(1), "camera/1", phase::cameras));
  const std::string host = "10.0.0.2:4242";
  auto on_worker = [&](std::uint64_t id, std::string name, wake_mode m) {
    auto i = info(id, std::move(name), phase::cameras, m);
    i.host = host;
    auto a = sys.spawn(silent, "x");
    self->send(clock, join_atom_v, a, i);
    return a;
  };
  // Tick 0 waits for camera 7; the worker also hosts a link between two of its cameras.
  auto camera = on_worker(participant_ids::camera(7), "camera/7", wake_mode::every_tick);
  auto link = on_worker(participant_ids::link(3), "link/7-8", wake_mode::never);
  self->send(clock, start_atom_v);
  sched.run();
  CAF_CHECK_EQUAL(count("0:3:camera/1"), 1u);
  CAF_CHECK_EQUAL(count("1:1:crowd"), 0u);
  // The connection breaks: every proxy of the worker goes, the link first.
  caf::anon_send_exit(link, caf::exit_reason::remote_link_unreachable);
  caf::anon_send_exit(camera, caf::exit_reason::remote_link_unreachable);
  run();
  run_result result;
  self->receive([&](run_result& r) { result = std::move(r); },
                caf::after(std::chrono::seconds(0)) >> [] { CAF_FAIL("the run stalled"); });
  CAF_CHECK_EQUAL(result.ticks, 4);
  CAF_CHECK(result.failure.empty());
  CAF_CHECK(result.unexpected_down.empty());
  CAF_REQUIRE_EQUAL(result.lost_workers.size(), 1u);
  CAF_CHECK_EQUAL(result.lost_workers[0], host + " at tick 0");
  // The injector heard once, with both participants, and had a turn in the next tick.
  CAF_REQUIRE_EQUAL(heard->size(), 1u);
  CAF_CHECK_EQUAL(heard->front().host, host);
  CAF_CHECK_EQUAL(heard->front().tick, 0);
  const std::vector<std::uint64_t> both{participant_ids::camera(7), participant_ids::link(3)};
  CAF_CHECK_EQUAL(heard->front().participants, both);
  CAF_CHECK_EQUAL(count("1:0:faults"), 1u);
  CAF_CHECK_EQUAL(count("2:0:faults"), 0u);  // on demand: one turn, not every tick
  CAF_CHECK_EQUAL(count("3:3:camera/1"), 1u);
}

// A camera on a worker that acknowledges its ticks and never answers the end-of-run flush (as
// one whose worker is lost after the request went out).
caf::behavior flushes_never(caf::event_based_actor* self, participant_info info) {
  return {
      [=](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
        tick_context ctx(info.id, info.name, tick, info.tick_phase);
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
      [](flush_atom) -> caf::result<done_atom> { return caf::delegated<done_atom>(); },
  };
}

CAF_TEST(a worker lost while the run ends does not hold the end) {
  for (auto on_loss : {worker_loss::end_run, worker_loss::crash_nodes}) {
    clock_settings s;
    s.end_tick = 2;
    s.on_worker_loss = on_loss;
    // A recorder of its own: the stand-in ends with the run it recorded.
    auto clock =
        spawn_clock(sys, s, sys.spawn(fake_recorder, std::make_shared<recorded>()), caf::actor{});
    auto i = info(participant_ids::camera(7), "camera/7", phase::cameras);
    i.host = "10.0.0.2:4242";
    i.flushes_at_end = true;
    auto camera = sys.spawn(flushes_never, i);
    self->send(clock, join_atom_v, camera, i);
    self->send(clock, start_atom_v);
    run();
    bool ended = false;
    self->receive([&](run_result&) { ended = true; }, caf::after(std::chrono::seconds(0)) >> [] {});
    CAF_CHECK(!ended);  // waiting for the flush
    caf::anon_send_exit(camera, caf::exit_reason::remote_link_unreachable);
    run();
    run_result result;
    self->receive([&](run_result& r) { result = std::move(r), ended = true; },
                  caf::after(std::chrono::seconds(0)) >> [] {});
    CAF_REQUIRE(ended);
    CAF_CHECK_EQUAL(result.ticks, 2);
    if (on_loss == worker_loss::end_run) {
      CAF_CHECK_NOT_EQUAL(result.failure.find("worker 10.0.0.2:4242 was lost while the run ended"),
                          std::string::npos);
    } else {
      CAF_CHECK(result.failure.empty());
      CAF_REQUIRE_EQUAL(result.lost_workers.size(), 1u);
      CAF_CHECK_EQUAL(result.lost_workers[0], "10.0.0.2:4242 at the end of the run (tick 2)");
    }
  }
}

CAF_TEST(at speed 1 virtual time stays within one tick of wall time) {
  auto clock = make_clock(60, 1.0);
  add_probe(clock, info(1, "crowd", phase::world));
  self->send(clock, start_atom_v);
  const auto tick = std::chrono::duration<double>(1.0 / 15.0);
  const auto step = std::chrono::milliseconds(7);  // not a divisor of the tick on purpose
  auto elapsed = caf::timespan{0};
  std::int64_t ticks_done = 0;
  for (int i = 0; i < 1000 && !rec->done; ++i) {
    sched.run();
    ticks_done = static_cast<std::int64_t>(log->ticks.size());
    auto virtual_time = static_cast<double>(ticks_done) * tick.count();
    auto wall_time = std::chrono::duration<double>(elapsed).count();
    // Tick k starts at wall time k * tick: the clock is never ahead of wall time by more than
    // the tick in progress, nor behind it by more than one tick.
    CAF_CHECK_LESS_OR_EQUAL(virtual_time, wall_time + tick.count() + 1e-9);
    CAF_CHECK_GREATER_OR_EQUAL(virtual_time, wall_time - tick.count() - 1e-9);
    sched.advance_time(step);
    elapsed += step;
  }
  CAF_CHECK_EQUAL(ticks_done, 60);
}

// The clock asks at most a few hundred participants at a time at the end of a run (CAF 0.17
// searches outstanding requests linearly); more than that must still each be asked once.
CAF_TEST(every participant is asked once to flush and once to report however many there are) {
  constexpr int senders = 700;
  constexpr int reporters = 900;
  auto clock = make_clock(1);
  auto flushed = std::make_shared<std::vector<int>>(senders, 0);
  auto reported = std::make_shared<std::vector<int>>(reporters, 0);
  for (int i = 0; i < senders; ++i) {
    // The index is an argument, not a capture: CAF 0.17's spawn dereferences an empty
    // argument tuple, which UBSan reports (test_participants.hpp, `silent`).
    auto sender = sys.spawn(
        [=](caf::event_based_actor* self, int index) -> caf::behavior {
          return {
              [=](tick_atom, std::int64_t tick, std::uint8_t, std::uint32_t) {
                tick_context ctx(static_cast<std::uint64_t>(index + 1), "s", tick, phase::cameras);
                self->send(caf::actor_cast<caf::actor>(self->current_sender()),
                           std::move(ctx).finish());
              },
              [=](flush_atom) {
                // Every flush comes before the first report.
                CAF_CHECK(
                    std::all_of(reported->begin(), reported->end(), [](int n) { return n == 0; }));
                ++(*flushed)[static_cast<std::size_t>(index)];
                return done_atom_v;
              },
          };
        },
        i);
    auto in = info(static_cast<std::uint64_t>(i + 1), "s", phase::cameras);
    in.flushes_at_end = true;
    self->send(clock, join_atom_v, sender, in);
  }
  for (int i = 0; i < reporters; ++i) {
    auto reporter = sys.spawn(
        [=](caf::event_based_actor*, int index) -> caf::behavior {
          return {
              [=](report_atom, std::int64_t) {
                ++(*reported)[static_cast<std::size_t>(index)];
                return link_report{"link/" + std::to_string(index), {}};
              },
          };
        },
        i);
    auto in = info(static_cast<std::uint64_t>(10'000 + i), "r", phase::network, wake_mode::never);
    in.reports_at_end = true;
    self->send(clock, join_atom_v, reporter, in);
  }
  auto result = run_to_end(clock);
  CAF_CHECK(std::all_of(flushed->begin(), flushed->end(), [](int n) { return n == 1; }));
  CAF_CHECK(std::all_of(reported->begin(), reported->end(), [](int n) { return n == 1; }));
  CAF_CHECK_EQUAL(result.links.size(), static_cast<std::size_t>(reporters));
  CAF_CHECK(rec->done);
}

CAF_TEST_FIXTURE_SCOPE_END()

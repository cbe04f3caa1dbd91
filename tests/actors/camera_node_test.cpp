#define CAF_SUITE actors.camera_node

// Camera nodes with their controllers, link actors, the clock and the fault injector under
// CAF's deterministic test coordinator, sensing through the emulated sensor (with no misses or
// confusions) a still world: the auction of Fig. 13, a bidder whose links lose everything, a
// leader's crash and its member's self-promotion, the top-level FSM as actor behaviours, and
// an operator task on a pedestrian out of view.
//
//   camera 3 (100, 70) pan -135      pedestrian 1 at (85, 50): in view of all three
//              \                       pedestrian 2 at (100, 10): behind camera 2
//   camera 4 (68, 70) pan -45 --- camera 2 (100, 30) pan 135 (the operator's)

#include <map>
#include <set>
#include <string>

#include "actors/clock.hpp"
#include "actors/fault_injector.hpp"
#include "actors/network_assembly.hpp"
#include "actors/participant_ids.hpp"
#include "caf/test/dsl.hpp"
#include "caf/test/unit_test_impl.hpp"
#include "protocol/topology.hpp"
#include "tests/actors/recording_fixture.hpp"
#include "tests/actors/still_world.hpp"
#include "world/layout_loader.hpp"

using namespace argus;
using namespace argus::actors;
using namespace argus::actors::testing;

namespace {

config::scenario three_cameras() {
  config::scenario s;
  s.run.seed = 5;
  s.network.loss_probability = 0.0;
  s.network.node_failure_probability = 0.0;
  s.network.adjacency = {{2, 3}, {3, 4}, {2, 4}};
  s.sensing.mode = config::sensing_mode::emulated;
  s.controller.relevance_sigma_fov_deg = 30.0;
  s.controller.relevance_sigma_pan_deg = 60.0;
  s.controller.relevance_sigma_tilt_deg = 30.0;
  s.cameras = {mounted(2, 100, 30, 135), mounted(3, 100, 70, -135), mounted(4, 68, 70, -45)};
  return s;
}

struct fixture : recording_fixture {
  std::map<int, caf::actor> cameras;

  void run_cameras(const config::scenario& s, double seconds) {
    cameras = run_still(
        *this, s,
        still_world(s, {standing(1, 85, 50, {200, 30, 30}), standing(2, 100, 10, {30, 200, 30})}),
        seconds);
    CAF_REQUIRE(rec->done);
  }

  std::vector<sim_event> events(const std::string& kind, const std::string& fields = {}) const {
    std::vector<sim_event> out;
    for (const auto& ev : rec->events)
      if (ev.kind == kind && ev.fields_json.find(fields) != std::string::npos) out.push_back(ev);
    return out;
  }

  // Leader 2 and its member are cut off from each other for 7 s, then the links heal; returns
  // the cameras leading the task at the end.
  std::set<int> partition_then_heal(config::merge_rule rule) {
    auto s = three_cameras();
    s.controller.merge = rule;
    config::operator_task t;
    t.at = config::seconds{3.0};
    t.pedestrian = 1;
    t.camera = 2;
    t.cameras_wanted = 2;
    t.max_cameras = 3;
    s.tasks = {t};
    for (int peer : {3, 4}) {
      config::fault cut;
      cut.at = config::seconds{10.0};
      cut.kind = config::fault_kind::link_cut;
      cut.camera = 2;
      cut.peer = peer;
      s.faults.push_back(cut);
      cut.at = config::seconds{17.0};
      cut.kind = config::fault_kind::link_heal;
      s.faults.push_back(cut);
    }
    run_cameras(s, 30.0);
    std::map<int, int> follows;  // camera -> the leader it follows
    for (const auto& ev : rec->events) {
      if (ev.kind != "leader_changed" && ev.kind != "joined" && ev.kind != "task_created" &&
          ev.kind != "left_task")
        continue;
      const int camera = field(ev, "camera");
      if (ev.kind == "left_task") {
        follows.erase(camera);
      } else {
        follows[camera] = ev.kind == "task_created" ? camera : field(ev, "leader");
      }
    }
    std::set<int> leaders;
    for (const auto& [camera, leader] : follows)
      if (camera == leader) leaders.insert(camera);
    return leaders;
  }

  static int field(const sim_event& ev, const std::string& name) {
    const auto key = "\"" + name + "\":";
    return std::stoi(ev.fields_json.substr(ev.fields_json.find(key) + key.size()));
  }

  // The top-level state camera `id` was in at the end of the run (its last node_state event).
  std::string final_state(int id) const {
    std::string out = "idle";
    for (const auto& ev : events("node_state", fmt::format(R"("camera":{},)", id))) {
      const auto at = ev.fields_json.find(R"("to":")") + 6;
      out = ev.fields_json.substr(at, ev.fields_json.find('"', at) - at);
    }
    return out;
  }
};

config::operator_task task_at_camera_2(int pedestrian) {
  config::operator_task t;
  t.at = config::seconds{3.0};  // after neighbour discovery (first hellos by 1 s)
  t.pedestrian = pedestrian;
  t.camera = 2;
  t.cameras_wanted = 2;
  return t;
}

}  // namespace

CAF_TEST_FIXTURE_SCOPE(camera_node_tests, fixture)

CAF_TEST(an operator task forms a group by auction) {
  auto s = three_cameras();
  s.tasks = {task_at_camera_2(1)};
  run_cameras(s, 12.0);
  CAF_CHECK_EQUAL(events("task_created", R"("camera":2)").size(), 1u);
  CAF_CHECK_GREATER_OR_EQUAL(events("auction", R"("camera":2)").size(), 1u);
  // One slot (two cameras wanted, the leader is one): the better bidder is invited.
  const auto invited = events("invited", R"("camera":2)");
  CAF_REQUIRE_EQUAL(invited.size(), 1u);
  const int member = invited[0].fields_json.find(R"("member":3)") != std::string::npos ? 3 : 4;
  const int loser = member == 3 ? 4 : 3;
  CAF_CHECK_EQUAL(events("joined", fmt::format(R"("camera":{})", member)).size(), 1u);
  // The member bid once; the loser bids in every auction the leader holds while it waits
  // (the leader, below the auction threshold, keeps recruiting).
  const auto auctions = events("auction", R"("camera":2)").size();
  const auto loser_bids = events("bid", fmt::format(R"("camera":{})", loser)).size();
  CAF_CHECK_EQUAL(events("bid", fmt::format(R"("camera":{})", member)).size(), 1u);
  CAF_CHECK_GREATER_OR_EQUAL(loser_bids, 1u);
  CAF_CHECK_LESS_OR_EQUAL(loser_bids, auctions);
  CAF_CHECK_EQUAL(final_state(2), "performing_task");
  CAF_CHECK_EQUAL(final_state(member), "performing_task");
  // The other bidder waits for a join until the bidding timeout (2 min).
  CAF_CHECK_EQUAL(final_state(loser), "computing_relevance");
  CAF_CHECK(events("bad_message").empty());
}

CAF_TEST(a bidder whose links lose everything is not recruited) {
  auto s = three_cameras();
  s.tasks = {task_at_camera_2(1)};
  config::fault burst;
  burst.at = config::seconds{2.5};
  burst.kind = config::fault_kind::loss_burst;
  burst.camera = 3;
  burst.length = config::seconds{5.0};
  burst.loss_probability = 1.0;
  s.faults = {burst};
  run_cameras(s, 12.0);
  CAF_CHECK(events("bid", R"("camera":3)").empty() || events("invited", R"("member":3)").empty());
  CAF_CHECK_EQUAL(events("invited", R"("member":4)").size(), 1u);
  CAF_CHECK_EQUAL(events("joined", R"("camera":4)").size(), 1u);
}

CAF_TEST(a member takes over when its leader crashes) {
  auto s = three_cameras();
  s.tasks = {task_at_camera_2(1)};
  config::fault crash;
  crash.at = config::seconds{8.0};
  crash.kind = config::fault_kind::crash;
  crash.camera = 2;
  s.faults = {crash};
  run_cameras(s, 14.0);
  const auto taken = events("leader_changed", R"("reason":"leader_failed")");
  CAF_REQUIRE_EQUAL(taken.size(), 1u);
  // Within the leader failure timeout (3 s) and a heartbeat of the crash.
  CAF_CHECK_LESS_OR_EQUAL(taken[0].tick, 8 * 15 + 4 * 15 + 1);
  CAF_CHECK_GREATER_OR_EQUAL(taken[0].tick, 8 * 15 + 3 * 15 - 15);
}

// Leader 2 and its member are cut off from each other for 7 s: the leader drops the silent
// member, the member leads itself, and once the links heal the two leaders of the task merge
// (the lower id follows the higher).
// The partition: the leader drops the silent member, the member leads itself; once the links
// heal the two leaders of the task merge, by the highest id or by Fig. 15's negotiation.
CAF_TEST(a partition splits the group and healing merges it under the highest id) {
  const auto leaders = partition_then_heal(config::merge_rule::highest_id);
  // Leader 2 stops hearing its members: it drops them as silent, or sooner, as their relevance
  // decays without fresh statuses (footnote 2).
  CAF_CHECK_GREATER_OR_EQUAL(events("member_dropped", R"("camera":2,"task":0)").size(), 2u);
  CAF_CHECK_GREATER_OR_EQUAL(events("leader_changed", R"("reason":"leader_failed")").size(), 1u);
  CAF_CHECK_GREATER_OR_EQUAL(events("leader_changed", R"("reason":"demoted")").size(), 1u);
  CAF_CHECK_EQUAL(leaders.size(), 1u);
}

CAF_TEST(a partition splits the group and healing merges it by negotiation) {
  const auto leaders = partition_then_heal(config::merge_rule::negotiation);
  CAF_CHECK_GREATER_OR_EQUAL(events("leader_changed", R"("reason":"leader_failed")").size(), 1u);
  CAF_CHECK_GREATER_OR_EQUAL(events("demote").size(), 1u);
  CAF_CHECK_GREATER_OR_EQUAL(events("demoteack").size(), 1u);
  CAF_CHECK_EQUAL(leaders.size(), 1u);
}

CAF_TEST(a task on a pedestrian who is not there is refused as such) {
  auto s = three_cameras();
  s.tasks = {task_at_camera_2(99999)};  // an id the crowd has not produced
  run_cameras(s, 4.0);
  CAF_CHECK_EQUAL(
      events("task_refused", R"("pedestrian":99999,"reason":"no_such_pedestrian")").size(), 1u);
  CAF_CHECK(events("task_created").empty());
}

CAF_TEST(a task on a pedestrian out of view is refused) {
  auto s = three_cameras();
  s.tasks = {task_at_camera_2(2)};
  run_cameras(s, 4.0);
  CAF_CHECK_EQUAL(events("task_refused", R"("reason":"not_in_view")").size(), 1u);
  CAF_CHECK(events("task_created").empty());
  CAF_CHECK_EQUAL(final_state(2), "idle");
}

// The behaviour answers for the state: a node with nothing to do is idle.
CAF_TEST(a new node is in its idle behaviour) {
  auto s = three_cameras();
  auto node = spawn_camera_node(sys, s, s.cameras[0], {});
  auto answer = self->request(node, caf::infinite, node_state_atom_v);
  run();
  std::string state;
  answer.receive([&](std::string& name) { state = name; }, [](caf::error&) {});
  CAF_CHECK_EQUAL(state, "idle");
  anon_send_exit(node, caf::exit_reason::user_shutdown);
  run();
}

CAF_TEST_FIXTURE_SCOPE_END()

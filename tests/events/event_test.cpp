#include "events/event.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>
#include <vector>

#include "nlohmann/json.hpp"

namespace argus::events {
namespace {

// One line of every kind the vocabulary has, as runs wrote them before it existed (the first
// 25 taken from real runs of the shipped scenarios, the rest written from the old emit sites'
// formats).
const std::vector<std::string> lines{
    R"LINE({"t":10.000000,"tick":150,"source":"camera/7","kind":"auction","camera":7,"task":0,"auction":1,"group_size":1,"relevance":0.1879})LINE",
    R"LINE({"t":13.000000,"tick":195,"source":"camera/7","kind":"auction_closed","camera":7,"task":0,"auction":1,"bids":5,"chosen":[8]})LINE",
    R"LINE({"t":10.533333,"tick":158,"source":"camera/8","kind":"bid","camera":8,"task":0,"leader":7,"auction":1,"relevance":0.5250,"busy":false,"found_fraction":1.000,"mean_score":0.8000})LINE",
    R"LINE({"t":83.800000,"tick":1257,"source":"faults","kind":"fault","fault":"crash","camera":4,"random":true,"applied":true})LINE",
    R"LINE({"t":14.933333,"tick":224,"source":"world","kind":"goal_completed","pedestrian":64,"goal":"buy_ticket"})LINE",
    R"LINE({"t":64.933333,"tick":974,"source":"camera/7","kind":"handoff","camera":7,"task":0,"from":7,"to":6,"relevance":0.2643})LINE",
    R"LINE({"t":13.000000,"tick":195,"source":"camera/7","kind":"invited","camera":7,"task":0,"member":8,"reassign":false})LINE",
    R"LINE({"t":13.200000,"tick":198,"source":"camera/8","kind":"joined","camera":8,"task":0,"leader":7,"reassign":false,"term":2})LINE",
    R"LINE({"t":64.000000,"tick":960,"source":"camera/5","kind":"leader_changed","camera":5,"task":0,"leader":5,"previous":7,"reason":"leader_failed","term":3})LINE",
    R"LINE({"t":20.066667,"tick":301,"source":"camera/8","kind":"left_task","camera":8,"task":0,"reason":"relevance_low","role":"member"})LINE",
    R"LINE({"t":42.400000,"tick":636,"source":"camera/7","kind":"member_added","camera":7,"task":0,"member":13,"reason":"status"})LINE",
    R"LINE({"t":20.466667,"tick":307,"source":"camera/7","kind":"member_dropped","camera":7,"task":0,"member":8,"reason":"left"})LINE",
    R"LINE({"t":88.400000,"tick":1326,"source":"camera/3","kind":"neighbour_lost","camera":3,"neighbour":4})LINE",
    R"LINE({"t":0.200000,"tick":3,"source":"camera/1","kind":"neighbour_up","camera":1,"neighbour":15})LINE",
    R"LINE({"t":15.000000,"tick":225,"source":"faults","kind":"node_recovered","camera":3,"applied":true})LINE",
    R"LINE({"t":10.000000,"tick":150,"source":"camera/7","kind":"node_state","camera":7,"from":"idle","to":"performing_task"})LINE",
    R"LINE({"t":0.000000,"tick":0,"source":"camera/1","kind":"node_up","camera":1,"type":"ptz"})LINE",
    R"LINE({"t":18.466667,"tick":277,"source":"world","kind":"pedestrian_entered","pedestrian":101,"at":-3})LINE",
    R"LINE({"t":16.466667,"tick":247,"source":"world","kind":"pedestrian_left","pedestrian":98,"at":-4})LINE",
    R"LINE({"t":10.466667,"tick":157,"source":"camera/8","kind":"queried","camera":8,"task":0,"leader":7,"auction":1,"from":7})LINE",
    R"LINE({"t":11.333333,"tick":170,"source":"camera/12","kind":"query_dropped","camera":12,"task":0,"leader":7,"reason":"not_found"})LINE",
    R"LINE({"t":10.000000,"tick":150,"source":"camera/7","kind":"task_created","camera":7,"task":0,"min_cameras":2,"max_cameras":2,"relevance":0.1879,"term":1})LINE",
    R"LINE({"t":10.000000,"tick":150,"source":"script","kind":"task_issued","task":0,"by":"pedestrian","pedestrian":21,"camera":7,"cameras_wanted":2})LINE",
    R"LINE({"t":10.000000,"tick":150,"source":"camera/7","kind":"task_target","camera":7,"task":0,"pedestrian":21,"by":"pedestrian"})LINE",
    R"LINE({"t":10.133333,"tick":152,"source":"camera/7","kind":"tracking","camera":7,"task":0,"state":"wait"})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"signature_shared","camera":3,"task":0})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"join_refused","camera":3,"task":1,"leader":4,"busy_with":0})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"group_vanished","camera":3,"task":1})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"cancel_heard","camera":3,"task":1,"from":5})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"demote","camera":3,"task":1,"to":5})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"demoteack","camera":3,"task":1,"to":5})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"demotenack","camera":3,"task":1,"to":5})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"demoteretry","camera":3,"task":1,"to":5})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"conflict","camera":3,"task":1,"with_tasks":[0],"cameras":[2,4]})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/2","kind":"conflict_reported","camera":2,"task":0,"tasks":[0,1],"to":4})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"csp_yielded","camera":3,"task":1,"to_task":0})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"csp_abandoned","camera":3,"task":1,"missing":[0,2]})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"csp_solved","camera":3,"task":1,"solver":"best_solv","groups":2,"cameras":2,"weight":1.2345,"nodes_explored":12,"backtracks":30,"relaxed":false,"minima":{"1":2,"0":1},"optimal":true,"tasks":[0,1],"camera_ids":[2,5],"min_cameras":[1,0],"max_cameras":[2,1],"relevance":[[0.500000,-1.000000],[0.734500,0.250000]],"fixed":[[],[3]],"leaders":[4,3],"assigned":[[2],[5]]})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"csp_applied","camera":3,"task":1,"solver_camera":4,"cameras":[]})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"render_failed","camera":3,"error_code":7})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"strategy_failed","camera":3,"error":"ValueError: \"quoted\"\nline"})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"task_refused","camera":3,"task":0,"pedestrian":0,"reason":"not_in_view"})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"bad_message","camera":3,"origin":2,"message":"status","bytes":3})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"net_received","camera":3,"origin":2,"message":"ping","hops":1})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"net_sent","camera":3,"destination":-1,"message":"ping","id":9})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"peer_failed","camera":3,"peer":2,"request":"ping"})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"faults","kind":"fault","fault":"link_cut","camera":1,"peer":4,"random":false,"applied":true})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"script","kind":"task_issued","task":2,"by":"pixel","pixel":[160.5,120],"camera":2,"cameras_wanted":1})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"script","kind":"task_issued","task":3,"by":"first_to_enter","camera":2,"cameras_wanted":2})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"script","kind":"task_cancelled","task":0,"camera":2})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"world","kind":"world_partitions_missing","reported":1,"partitions":2})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"world/partition/1","kind":"world_out_of_step","partition":1,"snapshot_tick":-1})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"camera/3","kind":"participant_down","expected":false})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"video","kind":"video_render_failed","camera":3,"error_code":2})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"video","kind":"video_out_of_step","tick":15})LINE",
    R"LINE({"t":1.000000,"tick":15,"source":"world","kind":"world_partition_adopted","partition":2,"worker":"127.0.0.1:7002","replayed_ticks":6})LINE",
};

// The members of a line as the recorder wrote them: after its four common ones.
std::string members_text(const std::string& line) {
  const auto kind_at = line.find(R"("kind":")");
  const auto members_at = line.find(',', line.find('"', kind_at + 8)) + 1;
  return line.substr(members_at, line.size() - 1 - members_at);
}

TEST(events, every_kind_reads_back_and_writes_its_line_byte_for_byte) {
  std::set<std::string> kinds;
  for (const auto& line : lines) {
    const auto j = nlohmann::json::parse(line);
    const auto e = parse(j);
    ASSERT_TRUE(e) << line;
    EXPECT_FALSE(std::holds_alternative<custom>(*e)) << line;
    EXPECT_EQ(kind_of(*e), j["kind"].get<std::string>());
    // From the text, as written: members (and an object's members) in their order.
    const auto written = parse(kind_of(*e), members_text(line));
    ASSERT_TRUE(written) << line;
    EXPECT_EQ(fields_json(*written), members_text(line)) << line;
    kinds.insert(std::string(kind_of(*e)));
  }
  // Every struct of the vocabulary (and every kind a struct serves) was seen.
  EXPECT_EQ(kinds.size(), std::variant_size_v<event> - 1 + 6);
}

TEST(events, the_parsed_members_are_the_lines) {
  const auto e = parse(nlohmann::json::parse(
      R"({"t":1,"tick":15,"source":"faults","kind":"fault","fault":"crash_and_recover",)"
      R"("camera":4,"random":false,"applied":true})"));
  ASSERT_TRUE(e);
  const auto& f = std::get<fault_event>(*e);
  EXPECT_EQ(f.camera, 4);
  EXPECT_FALSE(f.peer);
  EXPECT_TRUE(f.takes_camera_down());
  const auto c = parse("conflict", R"("camera":3,"task":1,"with_tasks":[0,2],"cameras":[4])");
  ASSERT_TRUE(c);
  EXPECT_EQ(std::get<conflict>(*c).with_tasks, (std::vector<task_id>{0, 2}));
  const auto left = parse("neighbour_lost", R"("camera":3,"neighbour":4)");
  ASSERT_TRUE(left);
  EXPECT_FALSE(std::get<neighbour_change>(*left).up);
}

TEST(events, a_kind_of_its_own_is_kept_as_written) {
  const auto e = parse("lone_tracker_started", R"("task":0)");
  ASSERT_TRUE(e);
  EXPECT_EQ(kind_of(*e), "lone_tracker_started");
  EXPECT_EQ(fields_json(*e), R"("task":0)");
}

TEST(events, a_member_of_another_type_is_refused_and_a_missing_one_defaults) {
  EXPECT_FALSE(parse("joined", R"("camera":"three","task":0)"));
  const auto e = parse("joined", R"("camera":3)");
  ASSERT_TRUE(e);
  EXPECT_EQ(std::get<joined>(*e).camera, 3);
  EXPECT_FALSE(std::get<joined>(*e).reassign);
  EXPECT_FALSE(parse("joined", "not json"));
}

}  // namespace
}  // namespace argus::events

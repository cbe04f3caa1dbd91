#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

#include "config/scenario.hpp"
#include "controller/controller_io.hpp"
#include "controller/demotion_negotiator.hpp"
#include "controller/strategy.hpp"
#include "events/event.hpp"
#include "vision/frame_size.hpp"
#include "vision/tracker.hpp"

namespace argus::controller {

/// The camera controller of one node (Section III-C, Fig. 10) and its part in the grouping
/// protocol (Section IV, Figs. 13-15), in plain C++: each frame it takes what the node sensed,
/// its pose and the messages delivered to it, and returns messages, a PTZ command, what to look
/// for in the next frame, and events. docs/protocol.md describes every rule and timer.
///
///              queryrelevance                      join
///   idle ----------------------> computing ----------------> performing_task
///    ^  ^                        _relevance                    (track / wait / search)
///    |  +-- not found / bidding timeout --+                          |
///    +------------ left the group, task over (reset to home pose) ----+
///
/// An operator query makes the node a single-node group it leads (performing_task).
class camera_controller final : public strategy {
 public:
  /// `collaborate` false: the no_collaboration baseline, whose tasked camera never recruits.
  camera_controller(node_identity me, const config::scenario& scenario, bool collaborate = true);

  /// Wants a frame while looking and not idle (an idle node looks at nothing).
  frame_plan plan(std::int64_t tick, bool looking) override;
  /// One frame.
  controller_output step(const controller_input& in) override;
  strategy_status status() const override;

  /// The top-level state.
  node_state state() const noexcept;
  /// The task this node performs, if any.
  std::optional<task_id> task() const;
  /// Its role in its group (meaningful while performing a task).
  group_role role() const noexcept { return role_; }
  /// The leader it follows (itself when leading); 0 when in no group.
  int leader() const noexcept { return task_ ? leader_ : 0; }
  /// The epoch of the leadership it follows or holds (docs/protocol.md, "Terms"); 0 when in no
  /// group.
  protocol::term_epoch term() const noexcept { return task_ ? term_ : 0; }
  /// Whether it handed its group over and waits to hear the new leader lead (it then follows
  /// at the hand-over's epoch, which the new leader takes up only when the hand-over arrives).
  bool handing_over() const noexcept { return task_ && handed_over_at_.has_value(); }
  /// Its members, when it leads (ascending).
  std::vector<int> members() const;
  /// The child state of Fig. 10's inset, while performing a task.
  vision::tracking_state tracking() const noexcept { return fsm_.state(); }
  /// Its relevance to its task now (eq. (1) at the last sighting, decayed since).
  double relevance(std::int64_t now) const;

 private:
  // A query this node is bidding on (computing_relevance).
  struct pending_query {
    protocol::task_description task;
    int leader = 0;
    protocol::term_epoch term = 0;
    int querier = 0;
    std::uint32_t auction = 0;
    std::int64_t look_until = 0;
    std::int64_t give_up_at = 0;
    bool bid_sent = false;
    double relevance = 0.0;
    std::int64_t seen_tick = 0;
    // The evidence gathered since the first find (controller.bid_evidence_time).
    std::optional<std::int64_t> first_found;
    int frames = 0;
    int found = 0;
    double score_sum = 0.0;
    bool unconfirmed = false;
    std::int64_t bid_at = 0;
  };
  struct member_record {
    double relevance = 0.0;
    std::int64_t last_status = 0;
    std::int64_t joined = 0;
    // Placed here by a conflict's result: not given up to another conflict before then.
    std::int64_t pinned_until = 0;
  };
  struct auction_state {
    std::uint32_t id = 0;
    std::int64_t closes_at = 0;
    std::map<int, protocol::relevance_bid> bids;
    // Opened to gather relevances for a conflict (Section IV-B): it invites nobody.
    bool for_conflict = false;
  };
  // A conflict this leader centralises (Fig. 14).
  struct csp_round {
    std::uint32_t round = 0;
    std::int64_t deadline = 0;
    std::map<int, protocol::task_id> waiting;  // leader -> its task
    std::set<task_id> tasks;                   // its own and the others'
    std::vector<protocol::csp_data> data;
    // What the cameras that raised it said of their relevance to each task.
    std::map<task_id, std::vector<protocol::camera_relevance>> claims;
    // Its own gathering auction has closed.
    bool own_ready = false;
  };
  // A conflict another leader centralises, answered when this leader's gathering auction
  // closes.
  struct csp_reply {
    int solver = 0;
    task_id solver_task = 0;
    std::uint32_t round = 0;
  };
  // The last conflict this leader settled: the same one is not settled again within the
  // minimum task duration unless a task or camera joins it.
  struct settled_conflict {
    std::set<task_id> tasks;
    std::set<int> cameras;
    std::int64_t at = 0;
  };

  // One frame, in order.
  void take_looks(const controller_input& in, controller_output& out);
  void take_query(const operator_query& q, controller_output& out);
  void weigh_evidence(pending_query& p, const look_result& r, controller_output& out);
  void take_message(const received_message& m, controller_output& out);
  void on_query(int from, const protocol::query_relevance& q, controller_output& out);
  void on_bid(int from, const protocol::relevance_bid& b, controller_output& out);
  void on_join(int from, const protocol::join& j, controller_output& out);
  void on_status(int from, const protocol::status& s, controller_output& out);
  void on_handover(const protocol::handover& h, controller_output& out);
  void on_demotion(const protocol::demotion& d, controller_output& out);
  void on_csp_conflict(const protocol::csp_conflict& c, controller_output& out);
  void on_csp_query(int from, const protocol::csp_query& q, controller_output& out);
  void on_csp_data(const protocol::csp_data& d, controller_output& out);
  void on_csp_result(const protocol::csp_result& r, controller_output& out);
  void cancel(task_id task, int from, controller_output& out);
  void run_timers(controller_output& out);
  void lead(controller_output& out);
  void follow(controller_output& out);
  void plan_next(controller_output& out);
  // controller.track_while_bidding: the query whose find a free node follows with its head now,
  // if any, and the child FSM step that follows it.
  const pending_query* followed_query() const;
  bool follow_find(controller_output& out);

  // Transitions.
  void start_task(const protocol::task_description& task, group_role role, int leader,
                  double relevance, std::int64_t seen, protocol::term_epoch term,
                  controller_output& out);
  void leave_task(std::string_view reason, controller_output& out);
  // Leads at `term` (a new epoch past every one heard of this task when nullopt).
  void become_leader(std::string_view reason, controller_output& out,
                     std::optional<protocol::term_epoch> term = std::nullopt);
  void follow_leader(int leader, protocol::term_epoch term, std::string_view reason,
                     controller_output& out);
  // Another leader of this node's task, at `term`: a newer term is followed, an older one
  // answered with this node's status, an equal one merged by the scenario's merge rule.
  void met_other_leader(int other, protocol::term_epoch term, int sender, controller_output& out);
  // Records an epoch heard for `task`; returns the next epoch nobody here has heard of.
  void heard_term(task_id task, protocol::term_epoch term);
  protocol::term_epoch next_term(task_id task) const;
  // This node's status to `to`, who sent a term older than this node's (at most once per
  // heartbeat interval for each).
  void answer_stale(int to, controller_output& out);
  // Forgets the group this node led or followed: members, auction, conflict, negotiation.
  void forget_group();
  void emit_leader_changed(int leader, int previous, std::string_view reason,
                           controller_output& out) const;
  void absorb(int camera, controller_output& out);

  // Leader's work.
  // Gives the group to the best member (only one better than `mine` and above the threshold,
  // unless `to_anyone`); false when none qualifies.
  bool hand_over(double mine, controller_output& out, bool to_anyone = false);
  void open_auction(controller_output& out);
  void close_auction(controller_output& out);
  void invite(int camera, bool reassign, controller_output& out);
  // Conflicts (Section IV-B, docs/protocol.md "Conflicts"). A node claimed by two groups tells
  // the leader of the lower task, which centralises the CSP: it asks the other leaders for
  // their part, each leader (itself too) first auctions its task once more so that every
  // camera of the groups can say its relevance to every task, then it solves and sends the
  // whole result to every camera concerned, which takes its own place in it.
  void report_conflict(std::vector<protocol::conflict_claim> claims, controller_output& out);
  void start_csp(const std::map<int, protocol::task_id>& leaders,
                 const std::map<task_id, std::vector<protocol::camera_relevance>>& claims,
                 controller_output& out);
  void open_gathering(controller_output& out);
  void solve_csp(controller_output& out);
  // This node's place in a conflict's result.
  void take_place(const protocol::csp_result& r, controller_output& out);
  // A node the last result placed, heard out of its place as the result left it: it missed the
  // result, which it is sent again.
  void retell_place(const protocol::status& s, controller_output& out);
  void apply_demotions(const demotion_negotiator::actions& a, controller_output& out,
                       std::optional<protocol::term_epoch> peer_term = std::nullopt);
  // Its part of a conflict among `tasks`.
  protocol::csp_data own_csp_data(std::uint32_t round, const std::set<task_id>& tasks) const;
  protocol::status own_status() const;

  void send(int to, protocol::group_message m, controller_output& out) const;
  // Logs `e` as this camera's (its `camera` member set to this node).
  void emit(controller_output& out, events::event e) const;
  double relevance_of(const cv::Rect2d& box, bool busy) const;
  double decayed(double relevance, std::int64_t age) const;
  std::int64_t ticks(config::seconds d) const;
  bool locked() const;

  node_identity me_;
  bool collaborate_ = true;
  config::controller_settings settings_;
  config::seconds tick_;
  config::seconds message_timeout_;
  vision::tracking_fsm fsm_;
  demotion_negotiator negotiator_;

  std::int64_t now_ = 0;
  vision::ptz_state pose_;
  node_state reported_state_ = node_state::idle;

  std::vector<pending_query> pending_;
  // controller.track_while_bidding: the child FSM of ComputingRelevance (Fig. 10), the task
  // whose find it follows, and what the sensor saw of that task in this frame.
  vision::tracking_fsm bid_fsm_;
  std::optional<task_id> bid_followed_;
  std::optional<look_result> bid_seen_;
  // The task performed (performing_task), with the node's part in its group.
  std::optional<protocol::task_description> task_;
  group_role role_ = group_role::member;
  int leader_ = 0;
  std::int64_t joined_ = 0;
  std::int64_t last_leader_status_ = 0;
  double seen_relevance_ = 0.0;
  std::int64_t seen_tick_ = 0;
  std::optional<look_result> seen_now_;
  // Leader only.
  std::map<int, member_record> members_;
  std::optional<auction_state> auction_;
  std::uint32_t next_auction_id_ = 1;
  std::int64_t next_auction_at_ = 0;
  // Member: cameras it recruited through its neighbourhood (forwarded their join), whose
  // status it forwards to the leader and to which it forwards the leader's.
  std::set<int> relayed_for_;
  // A leader that handed its group over stays in the task, following the new leader, until a
  // status of the new leader's says it leads; when it handed over. None heard within the leader
  // failure timeout (the hand-over lost, the new leader gone or gone from the task): it takes
  // the group back rather than leave the task with nobody.
  std::optional<std::int64_t> handed_over_at_;
  // Member: the members its leader's last status listed (none heard yet: nullopt).
  std::optional<std::vector<int>> leader_members_;
  // The epoch of the leadership followed or held (docs/protocol.md, "Terms").
  protocol::term_epoch term_ = 0;
  // The newest epoch heard of each task (of any message), so that a new leadership is newer.
  std::map<task_id, protocol::term_epoch> epochs_;
  // When this node last answered a stale term from each node.
  std::map<int, std::int64_t> answered_stale_;
  // Which member relayed each bidder's bid (to forward the join through it).
  std::map<int, int> relayed_by_;
  // The bids of the last closed auction (candidates for conflict resolution).
  std::vector<protocol::relevance_bid> last_bids_;
  std::optional<csp_round> csp_;
  std::optional<csp_reply> csp_reply_;
  std::optional<settled_conflict> settled_;
  // The results taken (solver, round): a copy that arrives twice is taken once.
  std::set<std::pair<int, std::uint32_t>> results_taken_;
  // The last result taken, for a few seconds after (take_place says why), and how often it was
  // sent again to each node heard out of its place.
  std::optional<protocol::csp_result> last_result_;
  std::int64_t last_result_until_ = 0;
  std::map<int, int> results_retold_;
  // Placed in its group by a conflict's result: not given up to another before then.
  std::int64_t pinned_until_ = 0;
  // Tasks the operator ended: nothing about them is taken up again.
  std::set<task_id> cancelled_;
  std::uint32_t next_csp_round_ = 1;
};

}  // namespace argus::controller

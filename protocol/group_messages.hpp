#pragma once

// The messages of the grouping protocol (Sections IV-A to IV-C, Figs. 13-15), one struct per
// kind. A message travels in a `net_message` as its kind's name and a compact binary body;
// `encode` and `decode` are the only code that reads or writes those bytes.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace argus::protocol {

/// The name of a sensing task, given by the operator (unique in a run).
using task_id = std::uint32_t;

/// An appearance signature (Section III-B): a normalised HSV histogram, by its bin counts per
/// channel and its values. What a camera sends so that others can look for the pedestrian.
struct signature {
  std::uint8_t hue_bins = 8;
  std::uint8_t saturation_bins = 8;
  std::uint8_t value_bins = 4;
  std::vector<float> values;
  /// The same histogram of the upper and of the lower half of her box (a shirt above trousers,
  /// not below them), both empty unless the sender tests halves (sensing.halves_rho).
  std::vector<float> upper;
  std::vector<float> lower;
  friend bool operator==(const signature&, const signature&) = default;
};

/// A leadership's epoch within its task (docs/protocol.md, "Terms"). A term is the pair
/// (epoch, leader id), ordered by epoch and then by id: at most one leader per term by
/// construction. A node that hears a term of its task older than the one it follows ignores
/// it; hand-over, taking over from a failed leader and absorbing a demoted leader start a
/// newer epoch.
using term_epoch = std::uint32_t;

/// What a task asks for: whom to observe and with how many cameras.
struct task_description {
  task_id task = 0;
  signature target;
  std::uint16_t min_cameras = 1;
  std::uint16_t max_cameras = 1;
  friend bool operator==(const task_description&, const task_description&) = default;
};

/// The auction's announcement (Fig. 13): the sender asks its neighbourhood for bids on
/// `leader`'s task. With `relay` set it goes from a leader to one of its members, which then
/// announces the auction to its own neighbourhood and forwards the bids (Section IV-A).
struct query_relevance {
  task_description task;
  int leader = 0;
  term_epoch term = 0;  // the leader's
  std::uint32_t auction = 0;
  bool relay = false;
  friend bool operator==(const query_relevance&, const query_relevance&) = default;
};

/// A bid (Fig. 11's attributes, reduced to what eq. (1) needs, computed by the bidder): its
/// relevance as if it were free, and whether it is busy. `other_task`/`other_leader` name the
/// group that also claims the bidder (the one it belongs to, or another auction it bid in):
/// that is how a leader learns of a group-group conflict (Section IV-B). `locked`: the bidder
/// joined its group less than the minimum task duration ago and will not be reassigned.
struct relevance_bid {
  task_id task = 0;
  int leader = 0;
  term_epoch term = 0;  // of the auction's leader, as its query said
  std::uint32_t auction = 0;
  int bidder = 0;
  double relevance = 0.0;
  bool busy = false;
  bool locked = false;
  std::optional<task_id> other_task;
  int other_leader = 0;
  friend bool operator==(const relevance_bid&, const relevance_bid&) = default;
};

/// The selection (Fig. 13): `leader` invites camera `invitee` into its group. `reassign` is set
/// when conflict resolution moved the invitee from another group, which it then leaves. A
/// member that relayed the invitee's bid gets a copy and forwards it: the invitee may be beyond
/// the leader's hop limit.
struct join {
  task_description task;
  int leader = 0;
  term_epoch term = 0;  // the leader's
  int invitee = 0;
  bool reassign = false;
  friend bool operator==(const join&, const join&) = default;
};

/// The heartbeat of a group node, broadcast every heartbeat interval (Section IV-A). A
/// leader's (`leader == sender`) lists its members; a member's carries its relevance. A member
/// that leaves its group says so once with `leaving` set, so that its leader does not count it
/// (or hand the group to it) until its silence times out.
struct status {
  task_id task = 0;
  int sender = 0;
  int leader = 0;
  term_epoch term = 0;  // of `leader`'s leadership, as the sender knows it
  double relevance = 0.0;
  std::uint16_t min_cameras = 1;
  std::uint16_t max_cameras = 1;
  std::vector<int> members;
  bool leaving = false;
  friend bool operator==(const status&, const status&) = default;
};

/// A leader whose relevance fell below the threshold gives the group to `new_leader`
/// (Section IV-A), sent to every member.
struct handover {
  task_description task;
  int old_leader = 0;
  int new_leader = 0;
  term_epoch term = 0;  // the new leader's: one past the old leader's
  std::vector<int> members;
  friend bool operator==(const handover&, const handover&) = default;
};

/// Fig. 15's negotiation between two leaders of one task: demote, demoteack, demotenack,
/// demoteretry. A demoteack carries the demoted leader's members, who follow it.
enum class demotion_step : std::uint8_t { demote, ack, nack, retry };

/// One step of Fig. 15's negotiation.
struct demotion {
  demotion_step step = demotion_step::demote;
  task_id task = 0;
  int sender = 0;
  term_epoch term = 0;  // the sender's
  std::vector<int> members;
  friend bool operator==(const demotion&, const demotion&) = default;
};

/// Centralising a conflict (Section IV-B): the solving leader asks another leader for its
/// group's part of the CSP.
struct csp_query {
  task_id solver_task = 0;
  int solver = 0;
  term_epoch term = 0;  // the solver's
  std::uint32_t round = 0;
  friend bool operator==(const csp_query&, const csp_query&) = default;
};

/// A camera and its relevance to a group's task.
struct camera_relevance {
  int camera = 0;
  double relevance = 0.0;
  friend bool operator==(const camera_relevance&, const camera_relevance&) = default;
};

/// A leader's answer to csp_query, sent when the auction it opened on the query closes: its
/// task, and the cameras it could use with their relevance to it (itself, its members and
/// that auction's bidders). `members` are those in its group now (its leader first); `pinned`
/// those it will not give up: cameras that a conflict's result placed in the group less than
/// the minimum task duration ago.
struct csp_data {
  task_description task;
  int leader = 0;
  term_epoch term = 0;  // the leader's
  std::uint32_t round = 0;
  std::vector<camera_relevance> candidates;
  std::vector<int> members;
  std::vector<int> pinned;
  friend bool operator==(const csp_data&, const csp_data&) = default;
};

/// One group of a conflict's result: its task, its leader from now on (a new epoch when the
/// leader changes) and the leader it had, and its other cameras, each with its relevance to the
/// task as the solver knew it.
struct csp_assignment {
  task_description task;
  int leader = 0;
  term_epoch term = 0;
  int previous = 0;
  double relevance = 0.0;  // the leader's
  std::vector<camera_relevance> members;
  std::uint16_t minimum = 0;  // the minimum it was relaxed to
  friend bool operator==(const csp_assignment&, const csp_assignment&) = default;
};

/// The solver's decision, the whole of it, sent to every camera it names or takes from a
/// group: each applies its own part (docs/protocol.md, "Conflicts").
struct csp_result {
  task_id solver_task = 0;
  int solver = 0;
  term_epoch term = 0;  // the solver's
  std::uint32_t round = 0;
  std::vector<csp_assignment> groups;
  friend bool operator==(const csp_result&, const csp_result&) = default;
};

/// A group of `task` that claims a camera, as the camera knows it.
struct conflict_claim {
  task_id task = 0;
  int leader = 0;
  term_epoch term = 0;
  double relevance = 0.0;  // the camera's to that task
  friend bool operator==(const conflict_claim&, const conflict_claim&) = default;
};

/// Section IV-B: a node that intercepts queries of two groups for itself, or of another group
/// while it belongs to one, initiates conflict resolution: it tells the leader of the lowest
/// task among the claims, which centralises the CSP.
struct csp_conflict {
  int camera = 0;
  std::vector<conflict_claim> claims;
  friend bool operator==(const csp_conflict&, const csp_conflict&) = default;
};

/// The operator ended task `task` (not in the paper, which never ends a task): every node that
/// learns of it leaves the task and spreads the word to its neighbourhood once.
struct task_cancel {
  task_id task = 0;
  int sender = 0;
  friend bool operator==(const task_cancel&, const task_cancel&) = default;
};

/// A strategy's own message (not the paper's): a topic and opaque bytes, for strategies written
/// outside this protocol (docs/strategies.md) to talk to each other. The paper's controller
/// ignores it. At most 65,535 bytes of topic and of body each.
struct note {
  task_id task = 0;
  int sender = 0;
  std::string topic;
  std::string body;
  friend bool operator==(const note&, const note&) = default;
};

/// Any message of the protocol.
using group_message =
    std::variant<query_relevance, relevance_bid, join, status, handover, demotion, csp_conflict,
                 csp_query, csp_data, csp_result, task_cancel, note>;

/// The kind a message travels as: the paper's names ("queryrelevance", "relevance", "join",
/// "status", "demote", "demoteack", "demotenack", "demoteretry"), and ours for what it leaves
/// unnamed ("handover", "cspconflict", "cspquery", "cspdata", "cspresult", "cancel", "note").
std::string_view kind_of(const group_message& m);

/// The task a message is about (a conflict query: the solver's task).
task_id task_of(const group_message& m);

/// Whether `kind` names one of the protocol's messages.
bool is_group_kind(std::string_view kind);

/// The body bytes of `m`.
std::string encode(const group_message& m);

/// The message of kind `kind` with body `body`; nullopt when the kind is not the protocol's
/// or the bytes do not make a whole, valid message of it (bytes from a remote node are not
/// trusted).
std::optional<group_message> decode(std::string_view kind, std::string_view body);

}  // namespace argus::protocol

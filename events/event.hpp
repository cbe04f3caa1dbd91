#pragma once

// The vocabulary of the run's log: one struct per event kind, written by the strategies and the
// actors, read back by the evaluation, the report and the live console. events.jsonl is their
// serialisation (docs/events.md): `fields_json` writes an event's members, `parse` reads a line
// back into the struct of its kind.

#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "events/run_events.hpp"
#include "events/strategy_events.hpp"
#include "nlohmann/json_fwd.hpp"

namespace argus::events {

/// Any event of the log.
using event = std::variant<
    // strategies
    node_state, tracking, signature_shared, task_created, queried, bid, query_dropped, join_refused,
    joined, left_task, group_vanished, member_change, cancel_heard, auction_started, auction_closed,
    invited, handoff, leader_changed, demotion_sent, conflict, conflict_reported, csp_yielded,
    csp_abandoned, csp_solved, csp_applied,
    // the node, the network
    node_up, render_failed, strategy_failed, task_target, task_refused, neighbour_change,
    bad_message, net_received, net_sent, peer_failed,
    // faults, the script, the world, the runtime
    fault_event, node_recovered, task_issued, task_cancelled, pedestrian_moved, goal_completed,
    world_partitions_missing, world_out_of_step, participant_down, video_render_failed,
    video_out_of_step, world_partition_adopted,
    // anything else
    custom>;

/// Its kind, as the log names it.
std::string_view kind_of(const event& e);

/// Its members, as written after the common ones (JSON without braces).
std::string fields_json(const event& e);

/// The event a log line holds (its parsed JSON object, with its `kind`; an object member such as
/// csp_solved's `minima` comes in the parsed object's order): the struct of its kind,
/// or `custom` for a kind outside the vocabulary; nothing when a member of a known kind is of
/// another type (a missing one keeps its default).
std::optional<event> parse(const nlohmann::json& line);

/// The same from a kind and its members' JSON text (what the live console is handed), every
/// member in the order written.
std::optional<event> parse(std::string_view kind, std::string_view fields_json);

}  // namespace argus::events

#pragma once

// Every message type and atom of the actor layer, registered once. Include this
// header, not caf/all.hpp piecemeal, wherever argus messages are sent or matched.

#include <cstdint>
#include <vector>

#include "actors/link_command.hpp"
#include "actors/link_report.hpp"
#include "actors/net_handover.hpp"
#include "actors/net_send_window.hpp"
#include "actors/ordered_inbox.hpp"
#include "actors/participant_info.hpp"
#include "actors/render_pool.hpp"
#include "actors/run_result.hpp"
#include "actors/sim_event.hpp"
#include "actors/snapshot_delta.hpp"
#include "actors/tick_ack.hpp"
#include "actors/wire_log.hpp"
#include "actors/wire_partition.hpp"
#include "actors/wire_world.hpp"
#include "actors/worker_loss.hpp"
#include "actors/worker_protocol.hpp"
#include "actors/world_update.hpp"
#include "caf/all.hpp"
#include "protocol/net_message.hpp"

CAF_BEGIN_TYPE_ID_BLOCK(argus, caf::first_custom_type_id)

CAF_ADD_TYPE_ID(argus, (argus::actors::sim_event))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::actors::sim_event>))
CAF_ADD_TYPE_ID(argus, (argus::actors::participant_info))
CAF_ADD_TYPE_ID(argus, (argus::actors::tick_ack))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::actors::tick_ack>))
CAF_ADD_TYPE_ID(argus, (argus::actors::batched_tick))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::actors::batched_tick>))
CAF_ADD_TYPE_ID(argus, (argus::actors::run_result))
CAF_ADD_TYPE_ID(argus, (argus::actors::mail_stamp))
CAF_ADD_TYPE_ID(argus, (argus::actors::link_command))
CAF_ADD_TYPE_ID(argus, (argus::actors::link_report))
CAF_ADD_TYPE_ID(argus, (argus::protocol::net_message))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::protocol::net_message>))
CAF_ADD_TYPE_ID(argus, (argus::actors::net_handover))
CAF_ADD_TYPE_ID(argus, (argus::actors::net_send_window))
CAF_ADD_TYPE_ID(argus, (argus::actors::net_send_mail))
CAF_ADD_TYPE_ID(argus, (argus::actors::net_deliver_mail))
CAF_ADD_TYPE_ID(argus, (argus::actors::world_update))
CAF_ADD_TYPE_ID(argus, (argus::actors::partition_report))
CAF_ADD_TYPE_ID(argus, (argus::actors::render_request))
CAF_ADD_TYPE_ID(argus, (argus::actors::render_result))
CAF_ADD_TYPE_ID(argus, (std::shared_ptr<const argus::world::snapshot>))
CAF_ADD_TYPE_ID(argus, (argus::actors::serialized_delta))
CAF_ADD_TYPE_ID(argus, (argus::eval::task_origin))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::eval::task_origin>))
CAF_ADD_TYPE_ID(argus, (argus::eval::observation_log::contents))
CAF_ADD_TYPE_ID(argus, (argus::actors::worker_setup))
CAF_ADD_TYPE_ID(argus, (argus::actors::worker_gather))
CAF_ADD_TYPE_ID(argus, (argus::actors::lost_worker))
CAF_ADD_TYPE_ID(argus, (argus::actors::camera_placement))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::actors::camera_placement>))
CAF_ADD_TYPE_ID(argus, (argus::actors::partition_placement))
CAF_ADD_TYPE_ID(argus, (argus::actors::partition_arrivals))
CAF_ADD_TYPE_ID(argus, (argus::actors::partition_states))
CAF_ADD_TYPE_ID(argus, (argus::actors::video_tile_request))
CAF_ADD_TYPE_ID(argus, (argus::actors::video_tile))
CAF_ADD_TYPE_ID(argus, (std::vector<argus::actors::operator_order>))
CAF_ADD_TYPE_ID(argus, (argus::actors::display_watch))
CAF_ADD_TYPE_ID(argus, (argus::actors::live_display))

CAF_ADD_ATOM(argus, argus::actors, tick_atom, "tick")
CAF_ADD_ATOM(argus, argus::actors, join_atom, "join")
CAF_ADD_ATOM(argus, argus::actors, retire_atom, "retire")
CAF_ADD_ATOM(argus, argus::actors, start_atom, "start")
CAF_ADD_ATOM(argus, argus::actors, advance_atom, "advance")
CAF_ADD_ATOM(argus, argus::actors, record_atom, "record")
CAF_ADD_ATOM(argus, argus::actors, recorded_atom, "recorded")
CAF_ADD_ATOM(argus, argus::actors, done_atom, "done")
CAF_ADD_ATOM(argus, argus::actors, progress_atom, "progress")
CAF_ADD_ATOM(argus, argus::actors, report_atom, "report")
CAF_ADD_ATOM(argus, argus::actors, link_cmd_atom, "link_cmd")
CAF_ADD_ATOM(argus, argus::actors, net_retract_atom, "net_rtrct")
CAF_ADD_ATOM(argus, argus::actors, net_originate_atom, "net_orig")
CAF_ADD_ATOM(argus, argus::actors, world_report_atom, "w_report")
CAF_ADD_ATOM(argus, argus::actors, world_update_atom, "w_update")
CAF_ADD_ATOM(argus, argus::actors, world_attach_atom, "w_attach")
CAF_ADD_ATOM(argus, argus::actors, render_atom, "render")
CAF_ADD_ATOM(argus, argus::actors, world_snapshot_atom, "w_snap")
CAF_ADD_ATOM(argus, argus::actors, flush_atom, "flush")
CAF_ADD_ATOM(argus, argus::actors, node_state_atom, "node_st")
CAF_ADD_ATOM(argus, argus::actors, worker_hello_atom, "w_hello")
CAF_ADD_ATOM(argus, argus::actors, worker_setup_atom, "w_setup")
CAF_ADD_ATOM(argus, argus::actors, spawn_cameras_atom, "w_cams")
CAF_ADD_ATOM(argus, argus::actors, gather_atom, "w_gather")
CAF_ADD_ATOM(argus, argus::actors, board_atom, "w_board")
CAF_ADD_ATOM(argus, argus::actors, take_log_atom, "w_take")
CAF_ADD_ATOM(argus, argus::actors, release_atom, "w_release")
CAF_ADD_ATOM(argus, argus::actors, listening_atom, "w_listen")
CAF_ADD_ATOM(argus, argus::actors, spawn_partition_atom, "w_crowd")
CAF_ADD_ATOM(argus, argus::actors, video_tile_atom, "w_tile")
CAF_ADD_ATOM(argus, argus::actors, operator_orders_atom, "w_orders")
CAF_ADD_ATOM(argus, argus::actors, display_watch_atom, "w_watch")
CAF_ADD_ATOM(argus, argus::actors, take_display_atom, "w_display")
CAF_ADD_ATOM(argus, argus::actors, gather_sink_atom, "w_gsink")

CAF_END_TYPE_ID_BLOCK(argus)

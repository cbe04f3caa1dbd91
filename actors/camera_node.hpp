#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>

#include "actors/camera_pose_board.hpp"
#include "actors/node_observer.hpp"
#include "actors/operator_board.hpp"
#include "actors/participant_info.hpp"
#include "actors/shared_renderers.hpp"
#include "actors/snapshot_board.hpp"
#include "caf/actor.hpp"
#include "caf/fwd.hpp"
#include "config/scenario.hpp"
#include "controller/strategy_registry.hpp"
#include "sensing/sensor.hpp"
#include "vision/sensor_model.hpp"
#include "world/station.hpp"

namespace argus::actors {

/// The link actor to one neighbour, as a camera node knows it: nothing about where the
/// neighbour is, only which link leads to it.
struct attached_link {
  std::uint64_t participant = 0;
  caf::actor handle;
};

/// A camera node's links, by the neighbour's camera id.
using link_directory = std::map<int, attached_link>;

/// What the simulator lends every camera node of a run to sense with: the station and the
/// latest snapshot (for rendering and for the emulated sensor; never handed to the strategy),
/// the render pool (for sensors that need images) and the emulated sensor's error model; and
/// what the host equips nodes with (instruments, an oracle's ground truth, observers).
struct camera_world {
  std::shared_ptr<const world::station> station;
  std::shared_ptr<snapshot_board> board;
  /// The renderers nodes render their own frames on; null unless sensors need images.
  std::shared_ptr<shared_renderers> renderers;
  vision::sensor_model sensor_model;
  /// The host's instruments (eval/): each node's sensor and strategy go through these once made;
  /// unset: none.
  std::function<std::unique_ptr<sensing::sensor>(const config::camera_settings&,
                                                 std::unique_ptr<sensing::sensor>)>
      wrap_sensor;
  std::function<std::unique_ptr<controller::strategy>(const config::camera_settings&,
                                                      std::unique_ptr<controller::strategy>)>
      wrap_strategy;
  /// Ground truth for a strategy registered as an oracle; unset: none to lend.
  std::function<controller::oracle_source(const config::camera_settings&)> oracle_for;
  /// Who watches the nodes' turns (live console, evaluation); null for none.
  std::shared_ptr<node_observer> observer;
  /// The operator's live tasks and cancellations (argus serve); null for none.
  std::shared_ptr<operator_board> operators;
  /// Where nodes leave the pose of their next frame for the video recorder; null for none.
  std::shared_ptr<camera_pose_board> poses;
};

/// How camera `camera` takes part in the clock: phase cameras, every tick (it senses each frame).
participant_info camera_participant(const config::camera_settings& camera);

/// Spawns the actor of one camera node; the caller joins it to the clock with
/// `camera_participant(camera)`, before the clock starts or from inside a tick, so that joins
/// stay deterministic.
///
/// The node is glue: it hosts the camera's strategy (controller/strategy.hpp: the paper's
/// Fig. 10 controller and grouping protocol, or another by `controller.strategy`), its PTZ head
/// (vision::ptz_camera), its sensor (sensing/sensor.hpp) and the operator at its monitor
/// (camera_operator), and runs the network side (`protocol::node_network`: hello beacons, neighbour
/// discovery, multi-hop forwarding, `ping`, request time-outs). Fig. 10's top level is the actor's
/// behaviour: `idle`, `computing_relevance` and `performing_task` (the strategy's status), switched
/// with `become` after each turn; they share the link-mail handlers. A node senses only when the
/// strategy's plan or the operator wants a frame; its sensor then looks, at the head's pose, on a
/// frame it renders itself (shared_renderers) if it needs pixels. `(node_state_atom)` answers the
/// behaviour's name.
///
/// Each turn: the messages its links delivered (decoded; bytes that are not a protocol message
/// are logged `bad_message` and dropped), the operator's tasks for this camera due now (from
/// the scenario: the node takes the pedestrian's signature from its own pixels, or logs
/// `task_refused` when the pedestrian is not in its view), what it sensed; then the strategy's
/// messages go out through the node network, its events into the log, and the head slews one
/// tick toward the commanded pose. With `world` null the node has no sensor (network tests).
///
/// Mail: `(net_deliver_mail)` and `(net_retract_atom, ...)` from its links
/// (docs/network.md); a tick waits for the hand-overs the clock announces with it;
/// `(net_originate_atom, mail_stamp, int destination, std::string kind, std::string body, bool
/// expects_reply)` asks it to send a message (`protocol::broadcast` for all within the hop
/// limit), read in its turn in canonical order and logged as `net_sent`. What it sends goes
/// through its outbox (actors/link_outbox.hpp): one `net_send_mail` per link per lookahead
/// window, and whatever is queued when it crashes (its exit handler) or when the run ends
/// (`(flush_atom)`, answered with `done_atom`).
caf::actor spawn_camera_node(caf::actor_system& system, const config::scenario& scenario,
                             const config::camera_settings& camera, link_directory links,
                             std::shared_ptr<const camera_world> world = nullptr);

}  // namespace argus::actors

#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "config/clothing.hpp"

namespace argus::config {

/// Durations in scenarios are virtual time in (fractional) seconds; YAML writes them with a
/// unit ("1500 ms", "2 min", "1/15 s").
using seconds = std::chrono::duration<double>;

/// How the simulation runs: seed, length, tick (one video frame) and pacing.
struct run_settings {
  std::uint64_t seed = 1;
  seconds duration{60.0};
  /// One tick is one video frame.
  seconds tick{1.0 / 15.0};
  /// 1 = paced to wall clock, N = N times faster, 0 = free-running.
  double speed = 0.0;
  /// CAF scheduler worker threads; 0 = one per hardware thread.
  unsigned threads = 0;
  /// Where outputs go; empty = "out/<scenario name>".
  std::string output_dir;
  friend bool operator==(const run_settings&, const run_settings&) = default;
};

/// Pedestrians' preferred walking speeds: a normal distribution truncated to [min, max].
/// Defaults: Weidmann (1993), 1.34 m/s, sd 0.26 m/s (RiMEA test 7's reference).
struct speed_settings {
  double mean_mps = 1.34;
  double sd_mps = 0.26;
  double min_mps = 0.6;
  double max_mps = 2.0;
  friend bool operator==(const speed_settings&, const speed_settings&) = default;
};

/// An axis-aligned area of the floor plan, metres.
struct plan_box {
  double min_x_m = 0.0;
  double min_y_m = 0.0;
  double max_x_m = 0.0;
  double max_y_m = 0.0;
  friend bool operator==(const plan_box&, const plan_box&) = default;
};

/// A stream of pedestrians for a standard experiment: `count` appear in `spawn` (all at once
/// when rate_per_s is 0, else rate_per_s per second from start), each walks to the layout's
/// portal named `exit` and leaves there.
struct flow_settings {
  std::string name;
  plan_box spawn;
  unsigned count = 0;
  double rate_per_s = 0.0;
  seconds start{0.0};
  std::string exit;
  friend bool operator==(const flow_settings&, const flow_settings&) = default;
};

/// An area where density, speed and flow are measured (classic method: persons in the area
/// over its area, their mean speed, specific flow = density x speed; and the Voronoi method,
/// world/voronoi_measurement.hpp), written to measurements.csv.
struct measurement_area {
  std::string name;
  plan_box area;
  friend bool operator==(const measurement_area&, const measurement_area&) = default;
};

/// The station and its pedestrians.
struct world_settings {
  /// Station layout file, relative to the scenario file; empty = built-in Penn Station.
  std::string layout;
  /// Number of pedestrians the spawner keeps in the station.
  unsigned population = 100;
  /// New pedestrians entering per minute at the portals while below the target population.
  double spawn_rate_per_min = 60.0;
  /// Crowd partitions (actors) the station is split into.
  unsigned partitions = 1;
  /// Where preferred speeds come from.
  speed_settings speed;
  /// How their clothes are coloured.
  clothing clothes = clothing::palette;
  /// Streams of pedestrians walking to an exit (standard experiments).
  std::vector<flow_settings> flows;
  /// Areas where density, speed and flow are measured.
  std::vector<measurement_area> measurement_areas;
  friend bool operator==(const world_settings&, const world_settings&) = default;
};

/// A point on the station floor plan, in metres.
struct plan_point {
  double x_m = 0.0;
  double y_m = 0.0;
  friend bool operator==(const plan_point&, const plan_point&) = default;
};

/// Lower and upper bound of a camera degree of freedom, in degrees.
struct degree_range {
  double min_deg = 0.0;
  double max_deg = 0.0;
  friend bool operator==(const degree_range&, const degree_range&) = default;
};

/// Per-camera colour response in HSV (Section III-A): gains and offsets, plus tints (white),
/// tones (grey) and shades (black) mixed in, each a fraction in [0, 1].
struct color_response {
  double hue_offset_deg = 0.0;
  double saturation_gain = 1.0;
  double value_gain = 1.0;
  double value_offset = 0.0;
  double tint = 0.0;
  double tone = 0.0;
  double shade = 0.0;
  friend bool operator==(const color_response&, const color_response&) = default;
};

/// How data-dropout noise corrupts pixels.
enum class dropout_kind { snow, bit_flip, salt_and_pepper };

/// The imaging model of one camera (Section III-A); each effect can be off.
struct imaging_model {
  unsigned width_px = 640;
  unsigned height_px = 480;
  bool color_response_enabled = false;
  color_response response;
  /// Zero-mean Gaussian detector noise, in 8-bit intensity units; 0 = off.
  double noise_sigma = 0.0;
  /// Fraction of corrupted pixels in [0, 1]; 0 = off.
  double dropout_fraction = 0.0;
  dropout_kind dropout = dropout_kind::snow;
  /// JPEG round-trip quality in [1, 100]; 0 = off.
  unsigned jpeg_quality = 0;
  bool interlace = false;
  friend bool operator==(const imaging_model&, const imaging_model&) = default;
};

/// Static cameras are PTZ cameras that never move.
enum class camera_type { static_camera, ptz };

/// One camera node: where it stands (known to the simulator only, never to the node), its
/// default pose, limits and slew rates.
struct camera_settings {
  int id = 0;
  plan_point position;
  double height_m = 4.0;
  camera_type type = camera_type::ptz;
  double pan_deg = 0.0;
  double tilt_deg = -20.0;
  double field_of_view_deg = 45.0;
  degree_range pan_limits{-180.0, 180.0};
  degree_range tilt_limits{-80.0, 10.0};
  degree_range field_of_view_limits{5.0, 90.0};
  double pan_rate_deg_per_s = 60.0;
  double tilt_rate_deg_per_s = 30.0;
  double zoom_rate_deg_per_s = 20.0;
  imaging_model imaging;
  friend bool operator==(const camera_settings&, const camera_settings&) = default;
};

/// How a message for one node crosses more than one link (docs/network.md): flooded like a
/// broadcast, or along the reverse of the path by which the destination's own messages last
/// came (a route learned from its floods), flooding only when no live route is known.
enum class unicast_routing { flood, reverse_path };

/// The network model (Table 2, "Network communication parameters").
struct network_settings {
  double loss_probability = 0.1;
  seconds min_delay{0.200};
  seconds max_delay{0.500};
  /// Probability that a node fails, per second of virtual time (see docs/network.md).
  double node_failure_probability = 0.001;
  unsigned max_hops = 3;
  seconds message_timeout{1.500};
  /// Nodes within this distance are neighbours, unless `adjacency` lists the links.
  double communication_range_m = 40.0;
  /// Explicit neighbour pairs (camera ids); empty = by communication range.
  std::vector<std::array<int, 2>> adjacency;
  double duplicate_probability = 0.0;
  bool reorder = false;
  /// Every node sends a one-hop `hello` beacon to its neighbours this often.
  seconds hello_interval{1.0};
  /// A neighbour not heard for this long (beacons or any message) is given up; longer than
  /// `hello_interval`.
  seconds neighbour_timeout{5.0};
  unicast_routing unicast = unicast_routing::flood;
  friend bool operator==(const network_settings&, const network_settings&) = default;
};

/// Which CSP solver settles group-group conflicts (Section IV-B, Table 1): the paper's
/// BestSolv and AllSolv; optimistic_solv (default), BestSolv with a sound bound, which always
/// finds the optimum where the paper's rule can miss it; and bound_solv, a branch and bound
/// with a tighter bound and search ordering that returns the same answer (protocol/csp.hpp).
enum class conflict_solver { best_solv, all_solv, optimistic_solv, bound_solv };

/// How two leaders of one task merge their groups (Section IV-C): the one with the higher
/// unique id stays leader, or Fig. 15's negotiation (demote / demoteack / demotenack /
/// demoteretry with random back-off) for when unique ids are not guaranteed.
enum class merge_rule { highest_id, negotiation };

/// How camera nodes sense: rendered, degraded video through the low-level visual routines
/// (Section III), or the emulated sensor (ground truth through a calibrated error model).
enum class sensing_mode { pixels, emulated };

/// The kernel sizes of the pixel trackers' multiscale localiser (Fig. 9): around the target's
/// last box (vision::scale_rule::target), or the paper's (0.1 ... 1) x frame height / 7.
enum class tracker_scales { target, paper };

/// Who a camera's find is taken for: whoever its sensing settles on (the paper's cameras, which
/// know a target only by her signature), or, as a diagnostic bound, only the task's pedestrian
/// by ground truth: a find on anyone else counts as none, a perfect test of identity and of her
/// absence that no camera has. The cameras still find, localise and lose her with their own
/// sensing; only their mistakes of identity are taken away.
enum class identity_source { appearance, ground_truth };

/// What a node knows of how the other cameras' views map onto its own (sensing.group_geometry).
/// none, the paper's: nothing (no calibration, no world model; a query carries only her
/// signature). ground_truth: an instrument standing in for a perfectly learned map between
/// views (a ground-plane homography learned from co-observations would give it): a node that
/// looks for a task's target without holding her (bidding, or its tracker in Wait or Search)
/// is pointed, zoomed, at the pedestrian a group member's box was on in the last frame (the
/// leader's first), if it can reach him. Whom the boxes are on is the evaluation's label, so a
/// group that follows a stranger points its cameras at the stranger; identity stays each
/// camera's own. calibrated: each camera knows its own mounting and pose and puts the box it
/// holds on the floor; a node looking for her without holding her is pointed at the group's
/// latest estimate, and finds that cannot be her by that estimate are refused (the paper's
/// Section V suggestion; docs/protocol.md).
enum class group_geometry { none, ground_truth, calibrated };

/// Where a node expects the target to reappear once its whole group has lost her
/// (sensing.reappearance). none, the paper's: nowhere; the node searches its own view.
/// ground_truth: an instrument standing in for a perfect model of where people reappear
/// between views (the multi-camera tracking literature learns such models from transit times
/// and entry/exit zones): a node that looks for her without holding her, in a frame after one
/// in which no camera of her group held anyone, is pointed, zoomed, at her true position if it
/// can reach her. Whom it then finds there is its own tracker's.
enum class reappearance_model { none, ground_truth };

/// How camera nodes sense (Section III-A, B).
struct sensing_settings {
  sensing_mode mode = sensing_mode::pixels;
  /// The emulated sensor's error model file (relative to the scenario file); empty = the
  /// model's defaults.
  std::string sensor_model;
  /// Pixel sensing: the trackers' kernel sizes.
  tracker_scales scales = tracker_scales::target;
  /// Pixel sensing: trackers follow the camera's own pan, tilt and zoom between frames
  /// (vision::tracker_settings::ego_motion); false, the default, is the paper's tracker.
  bool ego_motion = false;
  /// Pixel sensing: a tracker re-takes its model from its own camera's pixels once it has held
  /// the target for a few frames and her box has changed size (vision/signature_update.hpp);
  /// false, the default, is the paper's tracker, which keeps the signature it was given.
  bool signature_update = false;
  /// Pixel sensing: a target looked for in the whole frame (a lost track, a bidder's first
  /// look) is taken only if it scores at least this much above the best other region there,
  /// a look-alike (vision::tracker_settings::reacquire_margin); 0, the default, is the paper's
  /// tracker, which takes the first region above rho.
  double reacquire_margin = 0.0;
  /// Pixel sensing: a lost track is looked for only around its last box, in a window that grows
  /// by a box size each frame, for this many frames before the whole frame
  /// (vision::tracker_settings::local_search_frames); 0, the default, is the paper's tracker,
  /// which looks in the whole frame at once.
  int local_search_frames = 0;
  /// Pixel sensing: a box whose colours match the ring around it more than this is taken for
  /// background and not accepted (vision::surround_match(),
  /// vision::tracker_settings::max_surround_match); 1, the default, is the paper's tracker,
  /// which has no such test.
  double max_surround_match = 1.0;
  /// Pixel sensing: the first this many frames of the track on the operator's pick, unbroken,
  /// are spared the figure-ground test (vision::tracker_settings::surround_grace_frames).
  int surround_grace_frames = 0;
  /// Pixel sensing: the same track is also spared it while its box is less than this many
  /// pixels tall (vision::tracker_settings::surround_grace_height_px); 0, the default: never.
  int surround_grace_height_px = 0;
  /// Pixel sensing: a live track's box in its search window is taken for background only once
  /// it has failed the figure-ground test in this many frames running
  /// (vision::tracker_settings::surround_patience_frames); 1, the default: at the first.
  int surround_patience_frames = 1;
  /// The figure-ground test against the ring's sides, K or more of them
  /// (vision::tracker_settings::surround_sides); 0, the default: against the whole ring.
  int surround_sides = 0;
  /// Pixel sensing: a live track is kept on a box in its search window scoring above this,
  /// while any other find must score above rho, 0.4 (vision::tracker_settings::track_rho); 0.4,
  /// the default, is the paper's one threshold.
  double track_rho = 0.4;
  /// Pixel sensing: the operator's pick also gives her signature in halves, the colours of the
  /// upper and of the lower half of her box (vision/signature_halves.hpp), carried in queries,
  /// and a find is taken only if its box's halves both match them above this
  /// (vision::tracker_settings::halves_rho); 0, the default, is the paper's: one histogram of
  /// the whole box, no halves sent or tested.
  double halves_rho = 0.0;
  /// Whom a find is taken for (identity_source); appearance, the default, is the paper's.
  identity_source identity = identity_source::appearance;
  /// What a node knows of the other cameras' views (group_geometry); none is the paper's.
  group_geometry geometry = group_geometry::none;
  /// Where a node looks for her once her group has lost her (reappearance_model); none is the
  /// paper's.
  reappearance_model reappearance = reappearance_model::none;
  friend bool operator==(const sensing_settings&, const sensing_settings&) = default;
};

/// Where the central oracle's cameras take her signature from: each from its own view of her
/// the first time it points at her (own_view, the default), or all from the operator's pick in
/// the tasked camera, the signature the paper's protocol passes in its queries (operator).
/// The second measures how much of the oracle's lead is a signature in each camera's own
/// colours at her full size, rather than where it points.
enum class oracle_signature { own_view, operator_pick };

/// The camera controller and protocol (Table 2, controller and at-node parameters; eq. 1).
struct controller_settings {
  seconds wait_timeout{120.0};
  seconds search_timeout{300.0};
  double min_relevance = 0.1;
  seconds heartbeat_interval{1.0};
  seconds leader_failure_timeout{3.0};
  seconds member_failure_timeout{5.0};
  double auction_relevance_threshold = 0.5;
  seconds min_task_duration{60.0};
  double membership_relevance_threshold = 0.1;
  seconds merge_timeout{300.0};
  seconds bidding_timeout{120.0};
  /// eq. (1) spreads for field of view, pan and tilt, in degrees.
  double relevance_sigma_fov_deg = 5.0;
  double relevance_sigma_pan_deg = 5.0;
  double relevance_sigma_tilt_deg = 5.0;
  conflict_solver solver = conflict_solver::optimistic_solv;
  merge_rule merge = merge_rule::highest_id;
  /// Who decides what each camera does (controller/strategy.hpp, docs/strategies.md): a
  /// registered strategy's name — `paper` (the paper's protocol: auctions, groups, handoffs,
  /// conflict resolution), `no_collaboration` (the tasked camera tracks alone, a baseline),
  /// `oracle` (a central oracle that assigns cameras from ground truth: an upper bound that no
  /// real network can reach), or one a plug-in registers; `plugin:PATH` (the strategy the
  /// shared library at PATH registers); or `python:MODULE:CLASS` (a Python class).
  std::string strategy = "paper";
  /// The central oracle only (strategy: oracle): its cameras' signature, and whether they zoom
  /// so that she is a third of the frame tall (true) or point at her with their default field
  /// of view (false). Instruments that take the oracle's lead apart; the defaults are the
  /// oracle as first built.
  oracle_signature oracle_signature_from = oracle_signature::own_view;
  bool oracle_zoom = true;
  /// In Track the camera zooms so that the target fills half the frame's height (Section
  /// III-B, "fixate and zoom"); false: it fixates only and keeps its field of view.
  bool zoom_in_track = true;
  // Beyond Table 2: what the paper leaves unstated (docs/protocol.md says why each).
  /// A leader collects bids for this long after announcing an auction, then selects.
  seconds auction_window{3.0};
  /// A leader announces its next auction no sooner than this after the last one closed.
  seconds auction_interval{3.0};
  /// A node asked for its relevance looks for the target in its view for this long.
  seconds relevance_look_time{0.5};
  /// A node that found the target keeps looking at it for this long before it bids, and bids
  /// only if she was found in at least `bid_min_found_fraction` of those frames with a mean
  /// acceptance score of at least `bid_min_mean_score`. 0: the paper's, a bid on the first
  /// find. The first find is the best of everyone in view, so its score is biased upwards
  /// against a stranger; the scores of the frames after it are not (bench/RESULTS.md, "a bid
  /// on evidence").
  seconds bid_evidence_time{0.0};
  double bid_min_found_fraction = 0.0;
  double bid_min_mean_score = 0.0;
  /// Fig. 10 embeds the child FSM (track / wait / search) in ComputingRelevance as well: a free
  /// node that found the target while bidding fixates and zooms on her, and keeps doing so after
  /// its bid until the join could have come (auction_window + the message timeout), so that it
  /// joins with her in view and large. false, the default: the node holds its pose while
  /// bidding and stops looking once it has bid, as this simulator did first.
  bool track_while_bidding = false;
  /// A leader whose tracker re-takes its model of her from its own pixels (a confirmed track,
  /// her box grown or shrunk by 1.4 since; sensing.signature_update) makes that model the task's
  /// signature, the one its later queries and handovers carry: her colours at the size its
  /// camera zoomed to, not the few pixels of the operator's wide view. false, the default: the
  /// paper's, the task keeps the signature of the operator's pick.
  bool share_model = false;
  /// Added, in a conflict's CSP, to each camera's relevance to the group it serves (its leader
  /// included): a reassignment must be worth more than the tracks it breaks. 0: the paper's,
  /// the sum of relevances alone (bench/RESULTS.md, "Conflicts as the paper says").
  double conflict_stay_bonus = 0.0;
  /// Fig. 15's "random interval": uniform in [0, this].
  seconds demotion_backoff_max{1.0};
  friend bool operator==(const controller_settings&, const controller_settings&) = default;
};

/// How an operator task names its target (Section IV: the operator selects a pedestrian in a
/// camera's feed; Fig. 19: a camera observes the first pedestrian who enters its view).
enum class task_target { pedestrian, pixel, first_to_enter };

/// A point in a camera's frame, in pixels from the top-left corner.
struct pixel_point {
  double x_px = 0.0;
  double y_px = 0.0;
  friend bool operator==(const pixel_point&, const pixel_point&) = default;
};

/// An operator request: at time `at`, observe a pedestrian starting from camera `camera`, with
/// at least `cameras_wanted` and at most `max_cameras` cameras (0 = as many as wanted). The
/// target is pedestrian `pedestrian` (by id: the operator's click stood in for by ground
/// truth), the pedestrian under `pixel` in the camera's frame (the click itself), or the first
/// pedestrian to enter the camera's view from `at` on. At `cancel_at` the operator ends it.
struct operator_task {
  seconds at{0.0};
  int pedestrian = 0;
  int camera = 0;
  unsigned cameras_wanted = 1;
  unsigned max_cameras = 0;
  task_target by = task_target::pedestrian;
  pixel_point pixel;
  std::optional<seconds> cancel_at;
  /// The number of cameras the group aims for.
  unsigned cameras_max() const noexcept { return std::max(cameras_wanted, max_cameras); }
  friend bool operator==(const operator_task&, const operator_task&) = default;
};

/// What a scheduled fault does.
/// `recover` brings a crashed camera back (a fresh actor), as a crash_and_recover's second half
/// does; the operator console's `recover` command is replayed as one.
/// `delay_spike` adds `delay` to every message `camera`'s links carry, both ways, for `length`.
enum class fault_kind {
  crash,
  crash_and_recover,
  link_cut,
  link_heal,
  loss_burst,
  recover,
  delay_spike
};

/// One scheduled fault. `peer` is the other end of a link fault; `length` is the recovery
/// delay (crash_and_recover) or the burst or spike length (loss_burst, delay_spike).
struct fault {
  seconds at{0.0};
  fault_kind kind = fault_kind::crash;
  int camera = 0;
  std::optional<int> peer;
  seconds length{0.0};
  double loss_probability = 1.0;
  /// The added delay of a delay_spike.
  seconds delay{0.0};
  friend bool operator==(const fault&, const fault&) = default;
};

/// A whole scenario file, validated, with every default filled in.
/// How a distributed run (argus run --workers) shares its cameras among the workers
/// (docs/distributed.md, "Placement"); a run in one process ignores it.
enum class placement_policy {
  /// Cameras in order along the station's longer side, one run of neighbours per worker: most
  /// links join two cameras of the same worker, so most mail stays inside a process.
  region,
  /// Cameras by id, one block of consecutive ids per worker.
  id,
};

/// Where a distributed run steps its crowd partitions (docs/distributed.md, "Placement").
enum class crowd_placement {
  /// Each worker steps a block of consecutive strips, beside its cameras.
  workers,
  /// The coordinator steps them all, as in one process.
  coordinator,
};

/// Where a distributed run renders the tiles of its `--video` (docs/distributed.md, "Video").
enum class video_placement {
  /// Each worker renders its own cameras' tiles from the snapshot on its board.
  workers,
  /// The coordinator renders every tile, as in one process (workers without a renderer).
  coordinator,
};

struct placement_settings {
  placement_policy policy = placement_policy::region;
  crowd_placement crowd = crowd_placement::workers;
  video_placement video = video_placement::workers;
  friend bool operator==(const placement_settings&, const placement_settings&) = default;
};

struct scenario {
  std::string name;
  /// The file it was read from (empty when built in code).
  std::string source_path;
  run_settings run;
  world_settings world;
  std::vector<camera_settings> cameras;
  network_settings network;
  controller_settings controller;
  sensing_settings sensing;
  std::vector<operator_task> tasks;
  std::vector<fault> faults;
  placement_settings placement;
  friend bool operator==(const scenario&, const scenario&) = default;
};

}  // namespace argus::config

#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "actors/pacing.hpp"
#include "actors/scheduling_order.hpp"
#include "actors/worker_loss.hpp"
#include "caf/actor.hpp"
#include "caf/fwd.hpp"

namespace argus::actors {

/// How a run's clock paces and ends the run.
struct clock_settings {
  /// The run ends after this many ticks.
  std::int64_t end_tick = 0;
  /// Virtual seconds per tick (one video frame).
  double tick_seconds = 1.0 / 15.0;
  /// 1 = paced to wall clock, N = N times faster, 0 = free-running.
  double speed = 0.0;
  /// How many ticks of events the recorder may have unwritten before the clock waits for it.
  std::size_t recorder_window = 16;
  /// How often (wall time) the progress observer hears from the clock.
  std::chrono::milliseconds progress_interval{250};
  /// The operator's pacing of a live run (argus serve), read between ticks instead of `speed`:
  /// its speed and pause. Null for none. Pacing only delays ticks; it never changes the run.
  std::shared_ptr<actors::pacing> pacing;
  /// Runs the clock on a thread of its own rather than on the scheduler's workers
  /// (clock_on_own_thread() says when that pays).
  bool own_thread = false;
  /// Sub-clocks by host (participant_info::host): a distributed run's worker hosts. The
  /// participants of a host are ticked through it, one `(tick_atom, int64 tick, uint8 phase,
  /// std::vector<batched_tick>)` a phase, and answer with one `std::vector<tick_ack>`: a tick
  /// costs two messages across the network per worker, not two per camera.
  std::map<std::string, caf::actor> sub_clocks;
  /// What a lost worker does to the run. Under `worker_loss::crash_nodes` its participants
  /// leave the barrier as retired, the run goes on, and the fault injector (the participant
  /// `participant_ids::fault_injector`) gets a `lost_worker` and a turn in the next tick.
  worker_loss on_worker_loss = worker_loss::end_run;
};

/// Whether a run with `threads` scheduler workers in `order` and `participants` participants
/// that the clock ticks (not `wake_mode::never` ones) should give the clock a thread of its
/// own.
///
/// Under CAF's order, a worker resumes the clock at once for every ack, so with thousands of
/// participants its state crosses cores thousands of times per tick: from 2,000 participants
/// on 2 threads a thread of its own paid (bench/RESULTS.md, "Clock thread"). Under the turn
/// order the clock waits behind the turn's other work and reads a phase's acks in a few
/// activations; on a worker it is then as fast or faster at every size measured (10,000
/// cameras on 2 threads: 1.14 against 0.96 M messages/s, bench/RESULTS.md, "Turn order"), and a
/// thread of its own only adds a third thread to two cores. Never with one worker, and never
/// under CAF's test coordinator, which runs only scheduled actors.
bool clock_on_own_thread(unsigned threads, std::size_t participants,
                         scheduling_order order = scheduling_order::turn_order);

/// Spawns the lockstep virtual-time clock (docs/runtime.md, "Time").
///
/// Messages it understands:
/// - `(join_atom, actor, participant_info)`: register a participant; takes effect at the next
///   tick boundary. Participants of a phase are ticked in id order.
/// - `(start_atom)` -> `run_result`: run every tick up to `end_tick`; the answer comes when the
///   recorder has written everything.
/// - `(retire_atom, uint64 id)`: a participant is about to be killed on purpose (a fault);
///   it leaves the barrier at once and its death is not reported as unexpected.
/// A participant with a `host` that dies because its connection broke takes its whole worker
/// with it: the run ends, or goes on without it (`clock_settings::on_worker_loss`).
/// - `tick_ack` from participants, `(recorded_atom, int64 tick)` from the recorder.
/// - From a sub-clock, `std::vector<tick_ack>`, or in phase world `(std::vector<tick_ack>,
///   worker_gather)`: what the worker's cameras did since it last answered, passed on as
///   `(gather_atom, actor_addr sub_clock, int64 tick, worker_gather)` to the actor named by
///   `(gather_sink_atom, actor)` (the world coordinator) before the acks are read, so it is
///   there before that actor's tick of phase network.
///
/// Each tick, for each phase in order, it sends `(tick_atom, int64 tick, uint8 phase, uint32
/// relayed)` to every participant due in that phase and waits for all their `tick_ack`s;
/// `relayed` is the number of hand-overs from relays (links) announced for that participant
/// since its last tick (`tick_ack::relayed`), which it waits for before it acts. Participants
/// that join with `wake_mode::never` (links) are never ticked. It monitors every participant:
/// one that dies is dropped from the barrier at once, logged, and the run goes on — unless it
/// is a relay (`wake_mode::never`), whose receivers would wait forever: then the run fails
/// with an error naming it. After the last phase it sends the tick's events, in canonical
/// order, as `(record_atom, int64 tick, std::vector<sim_event>)` to `recorder`. `progress`,
/// if valid, receives `(progress_atom, int64 tick, int64 end_tick, double wall_seconds)` every
/// `progress_interval`. When the run ends it asks each participant that `flushes_at_end` for
/// `(flush_atom)` and waits for all (they hand their links what they still hold), then each
/// that `reports_at_end` for `(report_atom, int64 end_tick)`, then closes the recorder. The
/// run's wall time runs from `start_atom` until the last report is in.
caf::actor spawn_clock(caf::actor_system& system, clock_settings settings, caf::actor recorder,
                       caf::actor progress);

}  // namespace argus::actors

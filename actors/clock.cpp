#include "actors/clock.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "actors/participant_ids.hpp"
#include "actors/phase.hpp"
#include "actors/type_ids.hpp"
#include "events/event.hpp"
#include "fmt/format.h"
#include "spdlog/spdlog.h"

namespace argus::actors {
namespace {

// One round of requests at the end of a run (flushes, then reports): whom to ask, the next to
// ask, and how many have not answered. CAF 0.17 keeps an actor's outstanding requests in a flat
// map that it searches linearly, so tens of thousands at once cost time quadratic in their
// number: asking 39,000 links for their reports all at once took 0.55 s of a 2.7 s run. A round
// keeps at most `in_flight` unanswered.
struct end_round {
  static constexpr std::size_t in_flight = 256;

  std::vector<caf::actor> targets;
  std::size_t next = 0;
  std::size_t pending = 0;
  // Asked and not answered: one whose worker is lost meanwhile never answers (a request
  // already on the wire gets no error back), so its end settles it instead.
  std::set<caf::actor_addr> outstanding;

  // Starts the round with `who`; false when there is nobody to ask.
  bool begin(std::vector<caf::actor> who) {
    targets = std::move(who);
    pending = targets.size();
    return pending > 0;
  }

  // The next to ask now, or nullptr when all are asked or `in_flight` have not answered.
  const caf::actor* next_to_ask() {
    auto answered = targets.size() - pending;
    if (next == targets.size() || next - answered >= in_flight) return nullptr;
    outstanding.insert(targets[next].address());
    return &targets[next++];
  }

  // Whether `who` was asked and had not answered (its answer, or its end, counts once).
  bool settle(const caf::actor_addr& who) { return outstanding.erase(who) != 0; }
};

// setup --start--> ticking --end_tick reached--> finishing --recorder done--> (quit)
//                    |  ^
//   phase: for each phase, tick the due participants, collect every ack (or their death)
//                    v  |
//   between ticks: hand events to the recorder, wait for it if it lags, pace to wall clock
class clock_actor : public caf::event_based_actor {
 public:
  clock_actor(caf::actor_config& cfg, clock_settings settings, caf::actor recorder,
              caf::actor progress)
      : caf::event_based_actor(cfg),
        settings_(settings),
        recorder_(std::move(recorder)),
        progress_(std::move(progress)) {}

  caf::behavior make_behavior() override {
    for (const auto& [host, sub] : settings_.sub_clocks) batches_[host];
    set_down_handler([this](caf::down_msg& msg) { on_down(msg); });
    monitor(recorder_);
    return {
        [this](join_atom, caf::actor& handle, participant_info& info) {
          pending_joins_.emplace_back(std::move(handle), std::move(info));
        },
        [this](retire_atom, std::uint64_t id) { drop(id, /*expected=*/true); },
        [this](start_atom) -> caf::result<run_result> {
          if (started_) return caf::make_error(caf::sec::runtime_error, "clock already started");
          started_ = true;
          promise_ = make_response_promise();
          wall_start_ = clock().now();
          last_progress_ = wall_start_;
          if (settings_.end_tick <= 0) {
            finish();
          } else {
            begin_tick();
          }
          return promise_;
        },
        [this](tick_ack& ack) { on_ack(ack); },
        [this](std::vector<tick_ack>& acks) {
          for (auto& ack : acks) on_ack(ack);
        },
        [this](std::vector<tick_ack>& acks, worker_gather& gathered) {
          if (gather_sink_)
            send(gather_sink_, gather_atom_v, caf::actor_cast<caf::actor_addr>(current_sender()),
                 tick_, std::move(gathered));
          for (auto& ack : acks) on_ack(ack);
        },
        [this](gather_sink_atom, caf::actor& sink) { gather_sink_ = std::move(sink); },
        [this](advance_atom) {
          if (settings_.pacing && !live_tick_due()) return;
          begin_tick();
        },
        [this](recorded_atom, std::int64_t) {
          --unwritten_batches_;
          if (waiting_for_recorder_ && unwritten_batches_ < settings_.recorder_window) {
            waiting_for_recorder_ = false;
            pace();
          }
        },
    };
  }

 private:
  struct entry {
    caf::actor handle;
    participant_info info;
    /// Calendar tick of an on-demand participant, or -1 when none is booked.
    std::int64_t booked = -1;
    /// Ticked in the current phase and not yet acknowledged.
    bool awaited = false;
    /// Hand-overs relays (links) owe it, announced since its last tick.
    std::uint32_t relayed = 0;
  };

  static std::size_t index(phase p) { return static_cast<std::size_t>(p); }

  void apply_joins() {
    if (pending_joins_.empty()) return;
    // Canonical order: by id, whatever order the joins arrived in.
    std::sort(pending_joins_.begin(), pending_joins_.end(),
              [](const auto& a, const auto& b) { return a.second.id < b.second.id; });
    for (auto& [handle, info] : pending_joins_) {
      if (participants_.count(info.id) != 0) {
        spdlog::warn("clock: participant id {} ({}) joined twice; second join ignored", info.id,
                     info.name);
        continue;
      }
      monitor(handle);
      ++joined_;
      by_address_[handle.address()] = info.id;
      auto id = info.id;
      auto& e = participants_[id];
      e.handle = std::move(handle);
      e.info = std::move(info);
      if (e.info.mode == wake_mode::every_tick) {
        auto& ids = every_tick_[index(e.info.tick_phase)];
        ids.insert(std::lower_bound(ids.begin(), ids.end(), id), id);
      } else if (e.info.mode == wake_mode::on_demand) {
        book(id, tick_);
      }
    }
    pending_joins_.clear();
  }

  // A calendar slot may list an id that was re-booked earlier or dropped since: collect_due
  // skips any id whose entry is gone or no longer booked for that slot. That keeps booking a
  // push_back, where erasing from the later slot would cost a search per re-booking.
  void book(std::uint64_t id, std::int64_t at) {
    if (auto it = participants_.find(id); it != participants_.end()) book(it->second, id, at);
  }

  void book(entry& e, std::uint64_t id, std::int64_t at) {
    if (e.info.mode != wake_mode::on_demand) return;
    if (e.booked >= 0 && e.booked <= at) return;
    calendar_[index(e.info.tick_phase)][at].push_back(id);
    e.booked = at;
  }

  void begin_tick() {
    if (finished_) return;  // a lost worker ended the run between ticks
    phase_ = 0;
    run_phases();
  }

  // Runs phases until one has participants to wait for, or the tick is over.
  void run_phases() {
    while (phase_ < phase_count) {
      apply_joins();  // joins sent from inside a tick precede their sender's ack
      collect_due();
      if (awaiting_ > 0) {
        const auto p = static_cast<std::uint8_t>(phase_);
        for (auto* e : due_) {
          if (!e->info.host.empty())
            if (auto sub = batches_.find(e->info.host); sub != batches_.end()) {
              sub->second.push_back({e->info.id, e->relayed, 0});
              e->relayed = 0;
              continue;
            }
          send(e->handle, tick_atom_v, tick_, p, e->relayed);
          e->relayed = 0;
        }
        for (auto& [host, batch] : batches_) {
          if (batch.empty()) continue;
          send(settings_.sub_clocks.at(host), tick_atom_v, tick_, p, std::move(batch));
          batch.clear();
        }
        return;
      }
      ++phase_;
    }
    finish_tick();
  }

  // Fills due_ with this phase's participants, in id order, and marks them awaited.
  void collect_due() {
    due_.clear();
    due_ids_.clear();
    auto& cal = calendar_[phase_];
    while (!cal.empty() && cal.begin()->first <= tick_) {
      auto slot = cal.begin()->first;
      for (auto id : cal.begin()->second) {
        auto it = participants_.find(id);
        if (it == participants_.end() || it->second.booked != slot) continue;
        it->second.booked = -1;
        due_ids_.push_back(id);
      }
      cal.erase(cal.begin());
    }
    if (!due_ids_.empty()) {
      const auto& every = every_tick_[phase_];
      auto calendar_end = due_ids_.size();
      due_ids_.insert(due_ids_.end(), every.begin(), every.end());
      std::sort(due_ids_.begin(), due_ids_.begin() + static_cast<std::ptrdiff_t>(calendar_end));
      std::inplace_merge(due_ids_.begin(),
                         due_ids_.begin() + static_cast<std::ptrdiff_t>(calendar_end),
                         due_ids_.end());
      for (auto id : due_ids_) due_.push_back(&participants_.find(id)->second);
    } else {
      for (auto id : every_tick_[phase_]) due_.push_back(&participants_.find(id)->second);
    }
    for (auto* e : due_) e->awaited = true;
    awaiting_ = due_.size();
  }

  void on_ack(tick_ack& ack) {
    if (finished_) return;  // a lost worker ended the run in the middle of a tick
    auto it = participants_.find(ack.participant);
    if (ack.tick != tick_ || it == participants_.end() || !it->second.awaited) {
      spdlog::warn("clock: stray ack from participant {} for tick {} (now tick {})",
                   ack.participant, ack.tick, tick_);
      return;
    }
    for (auto& ev : ack.events) batch_.push_back(std::move(ev));
    if (!ack.stop_run.empty() && stop_reason_.empty()) stop_reason_ = std::move(ack.stop_run);
    if (ack.next_wakeup != no_wakeup)
      book(it->second, ack.participant, std::max(ack.next_wakeup, tick_ + 1));
    for (auto id : ack.woken) wake_for_mail(id);
    // A receiver that is gone (crashed, retired) is owed nothing: its links know it is down.
    for (auto id : ack.relayed)
      if (auto* target = wake_for_mail(id)) ++target->relayed;
    it->second.awaited = false;
    if (--awaiting_ == 0) {
      ++phase_;
      run_phases();
    }
  }

  // Books participant `id` to read mail sent in this phase: this tick if its phase comes later,
  // else the next. Returns its entry, or nullptr if it is not (or no longer) a participant.
  entry* wake_for_mail(std::uint64_t id) {
    auto target = participants_.find(id);
    if (target == participants_.end()) return nullptr;
    auto& e = target->second;
    book(e, id, index(e.info.tick_phase) > phase_ ? tick_ : tick_ + 1);
    return &e;
  }

  void on_down(const caf::down_msg& msg) {
    if (msg.source == recorder_.address()) {
      // Without its recorder a run would lose its log: stop, and say why.
      spdlog::error("clock: the recorder stopped ({}); ending the run", to_string(msg.reason));
      if (promise_.pending())
        promise_.deliver(
            caf::make_error(caf::sec::runtime_error, "recorder stopped: " + to_string(msg.reason)));
      shut_down();
      return;
    }
    if (finished_) {
      // The end of the run asks for flushes and reports: one that can no longer come (its
      // worker is gone) is not waited for.
      if (msg.reason == caf::exit_reason::remote_link_unreachable) lost_at_end(msg.source);
      if (flushes_.settle(msg.source)) flush_received();
      if (reports_.settle(msg.source)) report_received();
    }
    auto it = by_address_.find(msg.source);
    if (it == by_address_.end()) return;
    auto id = it->second;
    by_address_.erase(it);
    if (retired_.erase(id) != 0) return;  // already dropped when it was retired
    auto entry_it = participants_.find(id);
    if (entry_it == participants_.end()) return;
    const auto& info = entry_it->second.info;
    auto name = info.name;
    // A worker's participants end with the worker: unreachable when it died or its connection
    // broke, shut down when it was stopped (SIGTERM, Ctrl-C). Nothing else ends them with
    // user_shutdown mid-run: a crash fault retires its node first.
    if (!info.host.empty() && (msg.reason == caf::exit_reason::remote_link_unreachable ||
                               msg.reason == caf::exit_reason::user_shutdown)) {
      lose_worker(info.host, fmt::format("{} {}", name,
                                         msg.reason == caf::exit_reason::user_shutdown
                                             ? "ended: the worker was shut down"
                                             : "unreachable"));
      return;
    }
    if (info.mode == wake_mode::never || id == participant_ids::world_coordinator) {
      // A relay that died owes hand-overs that will never come: the receivers would wait for
      // them forever, so the run ends here, saying why, rather than stall. Without the world
      // (a worker that could not rebuild its snapshot ends it) the cameras would go on looking
      // at a world that no longer moves.
      auto why = info.mode == wake_mode::never
                     ? fmt::format(
                           "{} stopped unexpectedly at tick {} ({}); the network cannot "
                           "deliver what it owes",
                           name, tick_, to_string(msg.reason))
                     : fmt::format("the {} stopped unexpectedly at tick {} ({})", name, tick_,
                                   to_string(msg.reason));
      spdlog::error("clock: {}", why);
      if (promise_.pending()) promise_.deliver(caf::make_error(caf::sec::runtime_error, why));
      shut_down();
      return;
    }
    spdlog::warn(
        "clock: participant {} died unexpectedly at tick {} ({}); dropped from the barrier", name,
        tick_, to_string(msg.reason));
    unexpected_down_.push_back(name);
    sim_event ev;
    ev.tick = tick_;
    ev.phase = static_cast<std::uint8_t>(std::min<std::size_t>(phase_, phase_count - 1));
    ev.source_id = id;
    ev.seq = 0xffffffffu;  // after anything the participant itself emitted this tick
    ev.source = name;
    const events::event down = events::participant_down{.expected = false};
    ev.kind = std::string(events::kind_of(down));
    ev.fields_json = events::fields_json(down);
    batch_.push_back(std::move(ev));
    drop(id, /*expected=*/false);
  }

  // A distributed run's worker is gone with everything it hosted (docs/distributed.md): the
  // tick in progress cannot complete, so the run ends with the last whole one, its outputs
  // complete up to it, and fails naming the worker.
  // `what`: the participant that told, and how it went ("camera/3 unreachable").
  void lose_worker(const std::string& host, const std::string& what) {
    if (finished_) return;
    if (settings_.on_worker_loss == worker_loss::crash_nodes) {
      crash_worker_nodes(host, what);
      return;
    }
    stop_reason_ = fmt::format(
        "worker {} was lost during tick {} ({}); the outputs are complete up to tick {}", host,
        tick_, what, tick_ - 1);
    spdlog::error("clock: {}", stop_reason_);
    batch_.clear();
    std::vector<std::uint64_t> gone;
    for (const auto& [id, e] : participants_)
      if (e.info.host == host) gone.push_back(id);
    finished_ = true;  // no phase runs on when the lost participants leave the barrier
    for (auto id : gone) drop(id, /*expected=*/true);
    finish();
  }

  // A worker lost while the run ends: what its participants still held (a camera's last
  // mail, a link's accounting) is missing from the outputs. Without crash-nodes that fails the
  // run, as a loss does before; with it, the worker is listed as lost.
  void lost_at_end(const caf::actor_addr& source) {
    auto it = by_address_.find(source);
    if (it == by_address_.end()) return;
    auto e = participants_.find(it->second);
    if (e == participants_.end() || e->second.info.host.empty()) return;
    const auto& host = e->second.info.host;
    const auto what = fmt::format("{} at the end of the run (tick {})", host, tick_);
    if (std::find(lost_at_end_.begin(), lost_at_end_.end(), host) != lost_at_end_.end()) return;
    lost_at_end_.push_back(host);
    spdlog::error(
        "clock: worker {} was lost while the run ended; what its participants still "
        "held (their last mail, their links' accounting) is missing",
        host);
    if (settings_.on_worker_loss == worker_loss::crash_nodes) {
      result_.lost_workers.push_back(what);
    } else if (result_.failure.empty()) {
      result_.failure = fmt::format(
          "worker {} was lost while the run ended; the outputs are complete up to tick {} but for "
          "what its participants still held",
          host, tick_ - 1);
    }
  }

  // `--on-worker-loss crash-nodes`: what the worker hosted leaves the barrier at once, as a
  // crashed camera does, and the fault injector takes its cameras down in the next tick's
  // faults phase (links, events). The tick in progress completes without them: what they
  // acknowledged before the loss stays in it, so from this tick on the run is not one process's.
  void crash_worker_nodes(const std::string& host, const std::string& what) {
    lost_worker lost{host, tick_, {}};
    for (const auto& [id, e] : participants_)
      if (e.info.host == host) lost.participants.push_back(id);
    std::sort(lost.participants.begin(), lost.participants.end());
    // A camera that recovered on the lost worker and has not joined yet never will.
    pending_joins_.erase(std::remove_if(pending_joins_.begin(), pending_joins_.end(),
                                        [&](const auto& j) { return j.second.host == host; }),
                         pending_joins_.end());
    spdlog::warn(
        "clock: worker {} was lost during tick {} ({}); its {} participants go on "
        "as crashed nodes (--on-worker-loss crash-nodes), so the run is the same as one "
        "process's only up to tick {}",
        host, tick_, what, lost.participants.size(), tick_ - 1);
    result_.lost_workers.push_back(fmt::format("{} at tick {}", host, tick_));
    batches_.erase(host);
    const bool in_phase = started_ && awaiting_ > 0;
    holding_ = true;  // one phase step for all of them, once they are all gone
    for (auto id : lost.participants) drop(id, /*expected=*/true);
    holding_ = false;
    if (auto injector = participants_.find(participant_ids::fault_injector);
        injector != participants_.end()) {
      send(injector->second.handle, std::move(lost));
      // Its next faults phase: this tick's is over once any phase runs, and between ticks
      // (phase_ past the last) the next tick has not begun.
      book(injector->second, participant_ids::fault_injector,
           phase_ < phase_count ? tick_ + 1 : tick_);
    }
    if (in_phase && awaiting_ == 0) {
      ++phase_;
      run_phases();
    }
  }

  void drop(std::uint64_t id, bool expected) {
    auto it = participants_.find(id);
    if (it == participants_.end()) return;
    auto& e = it->second;
    if (expected) retired_.insert(id);
    auto& every = every_tick_[index(e.info.tick_phase)];
    every.erase(std::remove(every.begin(), every.end(), id), every.end());
    bool was_awaited = e.awaited;
    due_.erase(std::remove(due_.begin(), due_.end(), &e), due_.end());
    participants_.erase(it);
    if (was_awaited && --awaiting_ == 0 && started_ && !finished_ && !holding_) {
      ++phase_;
      run_phases();
    }
  }

  void finish_tick() {
    if (!batch_.empty()) {
      std::stable_sort(batch_.begin(), batch_.end(), canonical_less);
      forward_group_changes();
      send(recorder_, record_atom_v, tick_, std::move(batch_));
      batch_.clear();
      ++unwritten_batches_;
    }
    ++tick_;
    report_progress(false);
    if (tick_ >= settings_.end_tick || !stop_reason_.empty()) {
      finish();
      return;
    }
    if (unwritten_batches_ >= settings_.recorder_window) {
      waiting_for_recorder_ = true;
      return;
    }
    pace();
  }

  // A live run's pace: the operator may change the speed or pause at any time, so the next
  // tick's due time is measured from the tick at which the setting last changed, and a long
  // wait is cut into short ones that look at the setting again.
  bool live_tick_due() {
    const auto& pacing = *settings_.pacing;
    const auto now = clock().now();
    const auto generation = pacing.generation();
    const bool paused = pacing.paused();
    if (generation != anchor_generation_ || paused) {
      anchor_generation_ = generation;
      anchor_wall_ = now;
      anchor_tick_ = tick_;
    }
    constexpr auto recheck = std::chrono::milliseconds(50);
    if (paused) {
      delayed_send(this, recheck, advance_atom_v);
      return false;
    }
    const double speed = pacing.speed();
    if (speed <= 0.0) return true;
    const auto due =
        anchor_wall_ +
        std::chrono::duration_cast<caf::timespan>(std::chrono::duration<double>(
            static_cast<double>(tick_ - anchor_tick_) * settings_.tick_seconds / speed));
    if (due <= now) return true;
    delayed_send(this, std::min<caf::timespan>(due - now, recheck), advance_atom_v);
    return false;
  }

  void pace() {
    if (settings_.pacing) {
      send(this, advance_atom_v);  // live_tick_due() waits
      return;
    }
    if (settings_.speed <= 0.0) {
      send(this, advance_atom_v);
      return;
    }
    auto due =
        wall_start_ + std::chrono::duration_cast<caf::timespan>(std::chrono::duration<double>(
                          static_cast<double>(tick_) * settings_.tick_seconds / settings_.speed));
    auto now = clock().now();
    if (due <= now)
      send(this, advance_atom_v);
    else
      delayed_send(this, due - now, advance_atom_v);
  }

  // The progress line shows who carries each task: it gets the events that change groups.
  void forward_group_changes() {
    if (!progress_) return;
    std::vector<sim_event> changes;
    for (const auto& ev : batch_)
      if (ev.kind == "task_created" || ev.kind == "joined" || ev.kind == "left_task" ||
          ev.kind == "leader_changed")
        changes.push_back(ev);
    if (!changes.empty()) send(progress_, record_atom_v, tick_, std::move(changes));
  }

  void report_progress(bool force) {
    if (!progress_) return;
    auto now = clock().now();
    if (!force && now - last_progress_ < settings_.progress_interval) return;
    last_progress_ = now;
    send(progress_, progress_atom_v, tick_, settings_.end_tick, wall_seconds(now));
  }

  double wall_seconds(caf::actor_clock::time_point now) const {
    return std::chrono::duration<double>(now - wall_start_).count();
  }

  void finish() {
    finished_ = true;
    report_progress(true);
    result_.ticks = tick_;
    result_.virtual_seconds = static_cast<double>(tick_) * settings_.tick_seconds;
    result_.participants = joined_;
    // Wall time is taken when the links have reported (close_recorder): the end-of-run flush
    // is work the run did.
    result_.unexpected_down = unexpected_down_;
    result_.failure = stop_reason_;
    // Senders hand over what they still hold before the links count what is in flight.
    if (flushes_.begin(participants_that(&participant_info::flushes_at_end)))
      ask_for_flushes();
    else
      request_reports();
  }

  std::vector<caf::actor> participants_that(bool participant_info::*flag) const {
    std::vector<caf::actor> out;
    for (const auto& [id, e] : participants_)
      if (e.info.*flag) out.push_back(e.handle);
    return out;
  }

  void ask_for_flushes() {
    while (auto* target = flushes_.next_to_ask())
      request(*target, caf::infinite, flush_atom_v)
          .then(
              [this, who = target->address()](done_atom) {
                if (flushes_.settle(who)) flush_received();
              },
              [this, who = target->address()](caf::error&) {
                if (flushes_.settle(who)) flush_received();
              });
  }

  void flush_received() {
    if (--flushes_.pending == 0)
      request_reports();
    else
      ask_for_flushes();
  }

  // Participants that account for something (links) report before the recorder closes.
  void request_reports() {
    if (reports_.begin(participants_that(&participant_info::reports_at_end)))
      ask_for_reports();
    else
      close_recorder();
  }

  void ask_for_reports() {
    while (auto* target = reports_.next_to_ask())
      request(*target, caf::infinite, report_atom_v, tick_)
          .then(
              [this, who = target->address()](link_report& r) {
                if (!reports_.settle(who)) return;
                result_.links[r.link] = std::move(r.counts);
                report_received();
              },
              [this, who = target->address()](caf::error&) {
                if (reports_.settle(who)) report_received();
              });
  }

  void report_received() {
    if (--reports_.pending == 0)
      close_recorder();
    else
      ask_for_reports();
  }

  void close_recorder() {
    result_.wall_seconds = wall_seconds(clock().now());
    request(recorder_, caf::infinite, done_atom_v, std::move(result_))
        .then(
            [this](run_result& final_result) {
              promise_.deliver(std::move(final_result));
              shut_down();
            },
            [this](caf::error& err) {
              promise_.deliver(std::move(err));
              shut_down();
            });
  }

  void shut_down() {
    for (auto& [id, e] : participants_) {
      demonitor(e.handle);
      send_exit(e.handle, caf::exit_reason::user_shutdown);
    }
    participants_.clear();
    quit();
  }

  clock_settings settings_;
  caf::actor recorder_;
  caf::actor progress_;
  caf::response_promise promise_;
  // A participant's reason to end the run early (tick_ack::stop_run).
  std::string stop_reason_;
  bool started_ = false;
  bool finished_ = false;
  // Participants leave in a group (a lost worker's): the phase moves on once all have left.
  bool holding_ = false;

  // Looked up on every ack and every wake-up: hashed, and node-based so due_ may point in.
  std::unordered_map<std::uint64_t, entry> participants_;
  std::unordered_map<caf::actor_addr, std::uint64_t> by_address_;
  std::vector<std::pair<caf::actor, participant_info>> pending_joins_;
  std::set<std::uint64_t> retired_;
  std::uint64_t joined_ = 0;
  run_result result_;
  end_round flushes_;
  end_round reports_;
  std::vector<std::string> unexpected_down_;
  std::vector<std::string> lost_at_end_;                            // hosts
  std::array<std::vector<std::uint64_t>, phase_count> every_tick_;  // sorted ids
  std::array<std::map<std::int64_t, std::vector<std::uint64_t>>, phase_count> calendar_;

  std::int64_t tick_ = 0;
  std::size_t phase_ = 0;
  std::vector<entry*> due_;
  // This phase's ticks for each sub-clock (clock_settings::sub_clocks), by host.
  std::map<std::string, std::vector<batched_tick>> batches_;
  // Where a sub-clock's gather goes (`gather_sink_atom`); none in one process.
  caf::actor gather_sink_;
  std::vector<std::uint64_t> due_ids_;
  std::size_t awaiting_ = 0;
  std::vector<sim_event> batch_;
  std::size_t unwritten_batches_ = 0;
  bool waiting_for_recorder_ = false;
  caf::actor_clock::time_point wall_start_;
  // Live pacing: the wall time and tick from which the current setting is measured.
  std::uint64_t anchor_generation_ = ~std::uint64_t{0};
  caf::actor_clock::time_point anchor_wall_;
  std::int64_t anchor_tick_ = 0;
  caf::actor_clock::time_point last_progress_;
};

}  // namespace

bool clock_on_own_thread(unsigned threads, std::size_t participants, scheduling_order order) {
  // Where the two lines crossed on this 2-core machine under CAF's order (bench/RESULTS.md,
  // "Clock thread"); under the turn order they do not cross.
  constexpr std::size_t crossover = 2'000;
  return order == scheduling_order::caf_default && threads > 1 && participants >= crossover;
}

caf::actor spawn_clock(caf::actor_system& system, clock_settings settings, caf::actor recorder,
                       caf::actor progress) {
  if (settings.own_thread)
    return system.spawn<clock_actor, caf::detached>(settings, std::move(recorder),
                                                    std::move(progress));
  return system.spawn<clock_actor>(settings, std::move(recorder), std::move(progress));
}

}  // namespace argus::actors

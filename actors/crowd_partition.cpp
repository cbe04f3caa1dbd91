#include "actors/crowd_partition.hpp"

#include "actors/ordered_inbox.hpp"
#include "actors/participant_ids.hpp"
#include "actors/partition_shadow.hpp"
#include "actors/tick_context.hpp"
#include "actors/type_ids.hpp"
#include "fmt/format.h"

namespace argus::actors {
namespace {

struct crowd_partition_state {
  participant_info info;
  crowd_partition_setup setup;
  caf::actor coordinator;
  /// The snapshot the next step reads.
  std::shared_ptr<const world::snapshot> previous;
  ordered_inbox<world_update> updates;
  /// On a worker: who was handed over to it, and its newcomers.
  ordered_inbox<partition_arrivals> arrivals;
  std::uint64_t sent = 0;
};

using partition_actor = caf::stateful_actor<crowd_partition_state>;

// The snapshot this tick's step reads, with the pedestrians it steps: on a worker its own
// kept ones, then the arrivals, in the order the coordinator would have sent them all.
std::shared_ptr<const world::snapshot> take_due(partition_actor* self, std::int64_t tick,
                                                std::uint8_t p) {
  auto& st = self->state;
  for (auto& [stamp, update] : st.updates.take_due(tick, p)) {
    st.previous = std::move(update.snapshot);
    st.setup.pedestrians = std::move(update.pedestrians);
  }
  if (!st.setup.board) return st.previous;
  auto& own = st.setup.pedestrians;
  for (auto& [stamp, arrived] : st.arrivals.take_due(tick, p))
    own.insert(own.end(), std::make_move_iterator(arrived.pedestrians.begin()),
               std::make_move_iterator(arrived.pedestrians.end()));
  return st.setup.board->latest();
}

// Steps and reports. Here the pedestrians travel with the report and come back updated; on a
// worker only their public states go, and those who stayed are kept.
void step_and_report(partition_actor* self, tick_context& ctx, const world::snapshot& previous,
                     const mail_stamp& stamp) {
  auto& st = self->state;
  auto result = world::partition_step(*st.setup.station, previous, st.setup.pedestrians,
                                      st.setup.bounds, st.setup.behaviour);
  if (st.setup.board) {
    partition_states report;
    report.index = st.setup.index;
    report.kept = subset_between(previous, result.pedestrians);
    report.handed_over = std::move(result.handed_over);
    report.events = std::move(result.events);
    if (st.setup.checkpoints && is_checkpoint_tick(stamp.tick, st.setup.index)) {
      report.checkpoint = true;
      report.whole = result.pedestrians;
    }
    st.setup.pedestrians = std::move(result.pedestrians);
    self->send(st.coordinator, world_report_atom_v, stamp, std::move(report));
  } else {
    st.setup.pedestrians.clear();
    self->send(st.coordinator, world_report_atom_v, stamp,
               partition_report{st.setup.index, std::move(result), std::nullopt, std::nullopt});
  }
  ctx.sent_mail_to(participant_ids::world_coordinator);
}

caf::behavior crowd_partition(partition_actor* self, crowd_partition_setup setup) {
  auto& st = self->state;
  st.info = crowd_partition_participant(setup.index);
  st.previous = std::move(setup.initial);
  st.setup = std::move(setup);
  return {
      [self](world_attach_atom, caf::actor coordinator) {
        self->state.coordinator = std::move(coordinator);
      },
      [self](world_update_atom, const mail_stamp& stamp, world_update& update) {
        self->state.updates.put(stamp, std::move(update));
      },
      [self](world_update_atom, const mail_stamp& stamp, partition_arrivals& arrived) {
        self->state.arrivals.put(stamp, std::move(arrived));
      },
      [self](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        const auto previous = take_due(self, tick, p);
        // The coordinator answers every report before this partition's next tick, and a
        // worker's board holds the tick's snapshot before its turn, so the snapshot is always
        // the one of this tick unless the coordinator is gone.
        if (!previous || previous->tick() != static_cast<std::uint64_t>(tick) || !st.coordinator) {
          ctx.emit(events::world_out_of_step{
              .partition = st.setup.index,
              .snapshot_tick = previous ? static_cast<std::int64_t>(previous->tick()) : -1});
        } else {
          step_and_report(self, ctx, *previous, mail_stamp{tick, p, st.info.id, st.sent++});
        }
        self->send(caf::actor_cast<caf::actor>(self->current_sender()), std::move(ctx).finish());
      },
  };
}

}  // namespace

participant_info crowd_partition_participant(std::size_t index) {
  participant_info info;
  info.id = participant_ids::crowd_partition(index);
  info.name = fmt::format("world/partition/{}", index);
  info.tick_phase = phase::world;
  info.mode = wake_mode::every_tick;
  return info;
}

caf::actor spawn_crowd_partition(caf::actor_system& system, crowd_partition_setup setup) {
  return system.spawn(crowd_partition, std::move(setup));
}

}  // namespace argus::actors

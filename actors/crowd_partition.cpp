#include "actors/crowd_partition.hpp"

#include "actors/ordered_inbox.hpp"
#include "actors/participant_ids.hpp"
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
  std::uint64_t sent = 0;
};

caf::behavior crowd_partition(caf::stateful_actor<crowd_partition_state>* self,
                              crowd_partition_setup setup) {
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
      [self](tick_atom, std::int64_t tick, std::uint8_t p, std::uint32_t) {
        auto& st = self->state;
        tick_context ctx(st.info.id, st.info.name, tick, st.info.tick_phase);
        for (auto& [stamp, update] : st.updates.take_due(tick, p)) {
          st.previous = std::move(update.snapshot);
          st.setup.pedestrians = std::move(update.pedestrians);
        }
        // The coordinator answers every report before this partition's next tick, so the
        // snapshot is always the one of this tick unless the coordinator is gone.
        if (!st.previous || st.previous->tick() != static_cast<std::uint64_t>(tick) ||
            !st.coordinator) {
          ctx.emit(events::world_out_of_step{
              .partition = st.setup.index,
              .snapshot_tick = st.previous ? static_cast<std::int64_t>(st.previous->tick()) : -1});
        } else {
          partition_report report;
          report.index = st.setup.index;
          report.result =
              world::partition_step(*st.setup.station, *st.previous, st.setup.pedestrians,
                                    st.setup.bounds, st.setup.behaviour);
          st.setup.pedestrians.clear();  // they travel with the report and come back updated
          self->send(st.coordinator, world_report_atom_v,
                     mail_stamp{tick, p, st.info.id, st.sent++}, std::move(report));
          ctx.sent_mail_to(participant_ids::world_coordinator);
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

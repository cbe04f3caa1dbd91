#include "actors/trajectory_recorder.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "actors/type_ids.hpp"
#include "caf/event_based_actor.hpp"
#include "caf/exit_reason.hpp"
#include "caf/local_actor.hpp"
#include "caf/stateful_actor.hpp"
#include "world/appearance_writer.hpp"
#include "world/snapshot.hpp"
#include "world/trajectory_writer.hpp"

namespace argus::actors {

struct trajectory_file {
  // Written as `<path>.partial`, renamed once complete.
  struct partial_file {
    std::filesystem::path final_path;
    std::filesystem::path partial_path;
    std::ofstream out;

    // Throws when it cannot be written.
    explicit partial_file(const std::filesystem::path& path)
        : final_path(path), partial_path(path) {
      partial_path += ".partial";
      out.open(partial_path, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error("cannot write " + partial_path.string());
    }
    void finish() {
      out.close();
      std::error_code ignored;
      std::filesystem::rename(partial_path, final_path, ignored);
    }
  };

  partial_file rows;
  partial_file looks;
  world::trajectory_writer row_writer{rows.out};
  world::appearance_writer look_writer{looks.out};

  explicit trajectory_file(const std::filesystem::path& path)
      : rows(path), looks(path.parent_path() / "pedestrians.csv") {}
};

std::shared_ptr<trajectory_file> open_trajectories(const std::filesystem::path& path) {
  if (path.empty()) return nullptr;
  std::error_code ignored;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ignored);
  return std::make_shared<trajectory_file>(path);
}

namespace {

// Gives both files their names with what they hold, and releases `file`.
void finish_trajectories(std::shared_ptr<trajectory_file>& file) {
  if (!file) return;
  file->rows.finish();
  file->looks.finish();
  file.reset();
}

}  // namespace

void write_trajectories(std::shared_ptr<trajectory_file>& file, const world::snapshot& frame,
                        std::int64_t end_tick) {
  if (!file) return;
  file->row_writer.write(frame);
  file->look_writer.write(frame);
  if (static_cast<std::int64_t>(frame.tick()) >= end_tick) finish_trajectories(file);
}

namespace {

struct trajectory_recorder_state {
  std::shared_ptr<trajectory_file> file;
  std::int64_t end_tick = 0;
  /// Once its owner ends nobody holds this actor, and CAF would end it as unreachable before
  /// it read the owner's exit: it holds itself until it has named the files.
  caf::actor keep_alive;
};

caf::behavior trajectory_recorder(caf::stateful_actor<trajectory_recorder_state>* self,
                                  std::shared_ptr<trajectory_file> file, std::int64_t end_tick) {
  self->state.file = std::move(file);
  self->state.end_tick = end_tick;
  self->state.keep_alive = caf::actor_cast<caf::actor>(self);
  // The owner's end: the mail to itself comes after every snapshot already queued, whatever the
  // exit's priority, so those are written before the files get their names.
  self->set_exit_handler([self](caf::exit_msg&) { self->send(self, done_atom_v); });
  return {
      [self](world_snapshot_atom, const std::shared_ptr<const world::snapshot>& frame)
          -> caf::result<recorded_atom, std::int64_t> {
        auto& st = self->state;
        write_trajectories(st.file, *frame, st.end_tick);
        return {recorded_atom_v, static_cast<std::int64_t>(frame->tick())};
      },
      [self](done_atom) {
        finish_trajectories(self->state.file);
        self->state.keep_alive = caf::actor{};
        self->quit();
      },
  };
}

}  // namespace

caf::actor spawn_trajectory_recorder(caf::local_actor* owner, std::shared_ptr<trajectory_file> file,
                                     std::int64_t end_tick) {
  return owner->spawn<caf::detached + caf::linked>(trajectory_recorder, std::move(file), end_tick);
}

}  // namespace argus::actors

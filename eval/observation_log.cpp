#include "eval/observation_log.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

#include "world/snapshot.hpp"

namespace argus::eval {

void observation_log::add_frame(camera_frame frame) {
  std::lock_guard<std::mutex> guard(mutex_);
  data_.frames[frame.camera].push_back(std::move(frame));
}

void observation_log::add_origin(const task_origin& origin) {
  std::lock_guard<std::mutex> guard(mutex_);
  data_.origins.push_back(origin);
}

void observation_log::add_cancel(std::uint32_t task, std::int64_t tick) {
  std::lock_guard<std::mutex> guard(mutex_);
  data_.cancels.emplace(task, tick);
}

void observation_log::add_origin_if_new(const task_origin& origin) {
  std::lock_guard<std::mutex> guard(mutex_);
  for (const auto& o : data_.origins)
    if (o.task == origin.task) return;
  data_.origins.push_back(origin);
}

std::optional<int> observation_log::target_of(std::uint32_t task) const {
  std::lock_guard<std::mutex> guard(mutex_);
  for (const auto& o : data_.origins)
    if (o.task == task) return o.pedestrian;
  return std::nullopt;
}

std::vector<task_origin> observation_log::origins() const {
  std::lock_guard<std::mutex> guard(mutex_);
  std::vector<task_origin> out;
  for (const auto& o : data_.origins) {
    auto c = data_.cancels.find(o.task);
    if (c == data_.cancels.end()) out.push_back(o);
  }
  return out;
}

std::set<int> observation_log::cameras_alive(std::int64_t tick) const {
  std::lock_guard<std::mutex> guard(mutex_);
  std::set<int> out;
  // A camera's newest frame may be of the tick in progress: look at the last two.
  for (const auto& [camera, frames] : data_.frames)
    for (auto it = frames.rbegin(); it != frames.rend() && it - frames.rbegin() < 2; ++it)
      if (it->tick == tick) out.insert(camera);
  return out;
}

void observation_log::add_samples(std::vector<target_sample> samples) {
  std::lock_guard<std::mutex> guard(mutex_);
  data_.samples.insert(data_.samples.end(), samples.begin(), samples.end());
}

void observation_log::add_sent(std::uint32_t task, std::string_view kind, std::int64_t tick) {
  std::lock_guard<std::mutex> guard(mutex_);
  ++data_.sent[{task, std::string(kind)}];
  ++data_.sent_by_tick[task][tick];
}

void observation_log::add_sent_after_cancel(std::uint32_t task, std::string_view kind) {
  std::lock_guard<std::mutex> guard(mutex_);
  ++data_.sent_after_cancel[{task, std::string(kind)}];
}

observation_log::contents observation_log::take() {
  std::lock_guard<std::mutex> guard(mutex_);
  auto out = std::move(data_);
  data_ = {};
  // Origins arrive from several cameras in one phase: put them in a thread-free order.
  std::sort(out.origins.begin(), out.origins.end(),
            [](const auto& a, const auto& b) { return a.task < b.task; });
  std::sort(out.samples.begin(), out.samples.end(), [](const auto& a, const auto& b) {
    return std::tie(a.tick, a.task) < std::tie(b.tick, b.task);
  });
  return out;
}

observation_log::contents observation_log::take_recorded() {
  std::lock_guard<std::mutex> guard(mutex_);
  contents out;
  out.frames = std::exchange(data_.frames, {});
  out.sent = std::exchange(data_.sent, {});
  out.sent_by_tick = std::exchange(data_.sent_by_tick, {});
  out.sent_after_cancel = std::exchange(data_.sent_after_cancel, {});
  out.origins = data_.origins;
  std::sort(out.origins.begin(), out.origins.end(),
            [](const auto& a, const auto& b) { return a.task < b.task; });
  return out;
}

void observation_log::add_worker_share(contents part) {
  for (const auto& o : part.origins) add_origin_if_new(o);
  std::lock_guard<std::mutex> guard(mutex_);
  for (auto& [camera, frames] : part.frames) {
    auto& mine = data_.frames[camera];
    const auto before = static_cast<std::ptrdiff_t>(mine.size());
    mine.insert(mine.end(), std::make_move_iterator(frames.begin()),
                std::make_move_iterator(frames.end()));
    // A camera crashed and recovered may have frames from two hosts: keep them in tick order.
    // Each share is in tick order already, and a worker that hands its share over every tick
    // only appends: merging costs nothing then.
    std::inplace_merge(mine.begin(), mine.begin() + before, mine.end(),
                       [](const auto& a, const auto& b) { return a.tick < b.tick; });
  }
  for (const auto& [key, count] : part.sent) data_.sent[key] += count;
  for (const auto& [task, by_tick] : part.sent_by_tick)
    for (const auto& [tick, count] : by_tick) data_.sent_by_tick[task][tick] += count;
  for (const auto& [key, count] : part.sent_after_cancel) data_.sent_after_cancel[key] += count;
}

void sample_targets(observation_log& log, const world::snapshot& frame) {
  std::vector<target_sample> samples;
  for (const auto& o : log.origins()) {
    target_sample s{static_cast<std::int64_t>(frame.tick()), o.task, o.pedestrian};
    if (const auto* who = frame.find(o.pedestrian)) {
      s.x_m = who->position.x();
      s.y_m = who->position.y();
      s.height_m = who->look.height_m;
      s.present = true;
    }
    samples.push_back(s);
  }
  if (!samples.empty()) log.add_samples(std::move(samples));
}

}  // namespace argus::eval

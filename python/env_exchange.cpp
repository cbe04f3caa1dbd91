#include "python/env_exchange.hpp"

namespace argus::pybridge {

void env_exchange::joined(int camera) {
  std::lock_guard<std::mutex> guard(mutex_);
  slots_[camera] = slot{};
  slots_[camera].live = true;
}

void env_exchange::left(int camera) {
  {
    std::lock_guard<std::mutex> guard(mutex_);
    auto it = slots_.find(camera);
    if (it == slots_.end() || !it->second.live) return;
    it->second = slot{};
    gone_.push_back(camera);
  }
  environment_.notify_all();
}

env_action env_exchange::exchange(int camera, controller::controller_input in) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (abandoned_) throw env_abandoned();
  auto& s = slots_[camera];
  s.live = true;
  s.posted = true;
  s.input = std::move(in);
  s.action.reset();
  environment_.notify_all();
  agents_.wait(lock, [&] { return abandoned_ || s.action.has_value(); });
  if (abandoned_) throw env_abandoned();
  s.posted = false;
  auto action = std::move(*s.action);
  s.action.reset();
  return action;
}

env_exchange::collected env_exchange::wait(bool until_finished) {
  std::unique_lock<std::mutex> lock(mutex_);
  // A camera that crashed is reported with the next tick's inputs (it never posts again); at the
  // run's end every node goes, which is no crash: the end is waited for.
  auto everyone_in = [&] {
    if (finished_) return true;
    if (until_finished) return false;
    bool any = false;
    for (const auto& [id, s] : slots_) {
      if (!s.live) continue;
      if (!s.posted || !s.input) return false;
      any = true;
    }
    return any;
  };
  environment_.wait(lock, everyone_in);
  collected c;
  c.finished = finished_;
  c.error = error_;
  if (!until_finished) c.gone = std::move(gone_);
  gone_.clear();
  for (auto& [id, s] : slots_) {
    if (!s.live || !s.posted || !s.input) continue;
    c.tick = s.input->tick;
    c.inputs.emplace(id, std::move(*s.input));
    s.input.reset();
  }
  return c;
}

void env_exchange::answer(std::map<int, env_action> actions) {
  {
    std::lock_guard<std::mutex> guard(mutex_);
    for (auto& [id, s] : slots_) {
      if (!s.posted || s.action) continue;
      auto it = actions.find(id);
      s.action = it != actions.end() ? std::move(it->second) : env_action{};
    }
  }
  agents_.notify_all();
}

void env_exchange::finish(std::string error) {
  {
    std::lock_guard<std::mutex> guard(mutex_);
    finished_ = true;
    error_ = std::move(error);
  }
  environment_.notify_all();
}

void env_exchange::abandon() {
  {
    std::lock_guard<std::mutex> guard(mutex_);
    abandoned_ = true;
  }
  agents_.notify_all();
}

}  // namespace argus::pybridge

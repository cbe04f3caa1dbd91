#include "actors/recorder.hpp"

#include <fstream>
#include <system_error>

#include "actors/type_ids.hpp"
#include "fmt/format.h"
#include "nlohmann/json.hpp"

namespace argus::actors {
namespace {

std::filesystem::path partial(const std::filesystem::path& p) {
  return std::filesystem::path(p.string() + ".partial");
}

caf::error io_error(const std::string& what) {
  return caf::make_error(caf::sec::runtime_error, what);
}

struct recorder_state {
  recorder_settings settings;
  std::ofstream events;
  std::filesystem::path events_path;
  std::uint64_t total = 0;
  std::map<std::string, std::uint64_t> by_kind;
  std::string line;
};

void write_event(recorder_state& st, const sim_event& ev) {
  auto& line = st.line;
  line.clear();
  fmt::format_to(std::back_inserter(line), R"({{"t":{:.6f},"tick":{},"source":{},"kind":{})",
                 static_cast<double>(ev.tick) * st.settings.tick_seconds, ev.tick,
                 nlohmann::json(ev.source).dump(), nlohmann::json(ev.kind).dump());
  if (!ev.fields_json.empty()) {
    line += ',';
    line += ev.fields_json;
  }
  line += "}\n";
  st.events.write(line.data(), static_cast<std::streamsize>(line.size()));
  ++st.total;
  ++st.by_kind[ev.kind];
}

nlohmann::json counts_json(const protocol::message_counts& c) {
  return {{"sent", c.sent},          {"duplicated", c.duplicated}, {"delivered", c.delivered},
          {"lost", c.lost},          {"dropped", c.dropped},       {"in_flight", c.in_flight},
          {"balanced", c.balanced()}};
}

// Message fates per link and kind, their totals, and whether the accounting invariant
// (sent + duplicated == delivered + lost + dropped + in flight) holds everywhere.
nlohmann::json network_json(const std::map<std::string, protocol::accounting_by_kind>& links) {
  protocol::accounting_by_kind by_kind;
  protocol::message_counts total;
  nlohmann::json per_link = nlohmann::json::object();
  bool balanced = true;
  for (const auto& [link, counts] : links) {
    protocol::merge(by_kind, counts);
    nlohmann::json kinds = nlohmann::json::object();
    for (const auto& [kind, c] : counts) {
      kinds[kind] = counts_json(c);
      total += c;
      balanced = balanced && c.balanced();
    }
    per_link[link] = std::move(kinds);
  }
  nlohmann::json kinds = nlohmann::json::object();
  for (const auto& [kind, c] : by_kind) kinds[kind] = counts_json(c);
  return {{"links", links.size()},
          {"totals", counts_json(total)},
          {"by_kind", std::move(kinds)},
          {"invariant_holds", balanced && total.balanced()},
          {"per_link", std::move(per_link)}};
}

nlohmann::json summary_json(const recorder_state& st, const run_result& r) {
  nlohmann::json j;
  j["scenario"] = st.settings.scenario;
  j["seed"] = st.settings.seed;
  j["threads"] = st.settings.threads;
  j["speed"] = st.settings.speed;
  j["tick_seconds"] = st.settings.tick_seconds;
  j["ticks"] = r.ticks;
  j["virtual_seconds"] = r.virtual_seconds;
  j["wall_seconds"] = r.wall_seconds;
  j["speed_ratio"] = r.wall_seconds > 0.0 ? r.virtual_seconds / r.wall_seconds : 0.0;
  j["participants"] = r.participants;
  j["unexpected_down"] = r.unexpected_down;
  if (!r.lost_workers.empty()) j["lost_workers"] = r.lost_workers;
  if (!r.failure.empty()) j["failure"] = r.failure;
  j["events_total"] = r.events_total;
  j["events_by_kind"] = r.events_by_kind;
  j["network"] = network_json(r.links);
  return j;
}

caf::behavior recorder(caf::stateful_actor<recorder_state>* self, recorder_settings s) {
  auto& st = self->state;
  st.settings = std::move(s);
  std::error_code ec;
  std::filesystem::create_directories(st.settings.output_dir, ec);
  st.events_path = st.settings.output_dir / "events.jsonl";
  st.events.open(partial(st.events_path), std::ios::binary | std::ios::trunc);
  if (!st.events) {
    self->quit(io_error(fmt::format("cannot write {}: {}", partial(st.events_path).string(),
                                    ec ? ec.message() : "open failed")));
    return {};
  }
  return {
      [self](record_atom, std::int64_t tick,
             const std::vector<sim_event>& batch) -> caf::result<recorded_atom, std::int64_t> {
        for (const auto& ev : batch) write_event(self->state, ev);
        if (self->state.settings.observer) self->state.settings.observer(batch);
        return {recorded_atom_v, tick};
      },
      [self](done_atom, run_result& result) -> caf::result<run_result> {
        auto& st = self->state;
        st.events.close();
        if (!st.events) return io_error("cannot finish writing " + st.events_path.string());
        result.events_total = st.total;
        result.events_by_kind = st.by_kind;
        auto summary_path = st.settings.output_dir / "summary.json";
        {
          std::ofstream out(partial(summary_path), std::ios::binary | std::ios::trunc);
          out << summary_json(st, result).dump(2) << '\n';
          if (!out) return io_error("cannot write " + summary_path.string());
        }
        std::error_code ec;
        std::filesystem::rename(partial(st.events_path), st.events_path, ec);
        if (!ec) std::filesystem::rename(partial(summary_path), summary_path, ec);
        if (ec)
          return io_error("cannot rename outputs in " + st.settings.output_dir.string() + ": " +
                          ec.message());
        self->quit();
        return result;
      },
  };
}

}  // namespace

caf::actor spawn_recorder(caf::actor_system& system, recorder_settings settings) {
  return system.spawn(recorder, std::move(settings));
}

}  // namespace argus::actors

#include "apps/resume_record.hpp"

#define XXH_INLINE_ALL
#include <xxhash.h>

#include <fstream>
#include <stdexcept>
#include <vector>

#include "fmt/format.h"
#include "report/binary_file.hpp"

namespace argus::apps {

std::string file_digest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot be read", file.string()));
  XXH3_state_t* state = XXH3_createState();
  if (state == nullptr || XXH3_128bits_reset(state) != XXH_OK) {
    XXH3_freeState(state);
    throw std::runtime_error("XXH3: no state");
  }
  std::vector<char> chunk(1 << 20);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    XXH3_128bits_update(state, chunk.data(), static_cast<std::size_t>(in.gcount()));
  }
  const bool failed = in.bad();
  const auto hash = XXH3_128bits_digest(state);
  XXH3_freeState(state);
  if (failed) throw std::runtime_error(fmt::format("{}: a read failed", file.string()));
  return fmt::format("{:016x}{:016x}", hash.high64, hash.low64);
}

nlohmann::json made_with(const std::filesystem::path& program, std::string_view scenario_yaml,
                         nlohmann::json settings) {
  const auto yaml_hash = XXH3_128bits(scenario_yaml.data(), scenario_yaml.size());
  return {{"argus", program.string()},
          {"argus_digest", file_digest(program)},
          {"scenario_digest", fmt::format("{:016x}{:016x}", yaml_hash.high64, yaml_hash.low64)},
          {"settings", std::move(settings)}};
}

std::optional<std::string> check_resume(const std::filesystem::path& dir,
                                        const nlohmann::json& made, bool has_runs,
                                        std::string_view command) {
  const auto file = dir / made_with_file;
  const auto recorded = report::read_json(file);
  const std::string advice =
      "resuming would mix runs of two programs or set-ups. Give another --out, or --fresh to "
      "remove the earlier runs first";
  if (!has_runs) {
    report::write_file(file, made.dump(1) + "\n");
    return std::nullopt;
  }
  if (!recorded.is_object())
    return fmt::format("{}: {} holds runs with no {}, made by an argus that kept no record; {}",
                       command, dir.string(), made_with_file, advice);
  std::vector<std::string> differ;
  if (recorded.value("argus_digest", "") != made["argus_digest"].get<std::string>())
    differ.push_back(fmt::format("a different argus executable ({} then, {} now)",
                                 recorded.value("argus", "?"), made["argus"].get<std::string>()));
  if (recorded.value("scenario_digest", "") != made["scenario_digest"].get<std::string>())
    differ.push_back("a different scenario (its fields as loaded)");
  if (recorded.value("settings", nlohmann::json()) != made["settings"])
    differ.push_back(fmt::format("different settings ({} then, {} now)",
                                 recorded.value("settings", nlohmann::json()).dump(),
                                 made["settings"].dump()));
  if (differ.empty()) return std::nullopt;
  std::string what = differ.front();
  for (std::size_t i = 1; i < differ.size(); ++i)
    what += (i + 1 == differ.size() ? " and " : ", ") + differ[i];
  return fmt::format("{}: {} holds runs made with {}; {}", command, dir.string(), what, advice);
}

}  // namespace argus::apps

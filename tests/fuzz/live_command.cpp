// Fuzzes the commands `argus serve` reads from the page (live::parse_command), against
// scenarios/minimal.yaml's four cameras. Any text gives a command or a message saying what is
// wrong with it, never an exception; a command it gives names a camera of the scenario (a link
// of it, for cut and heal) and, for a task, a pixel inside that camera's frame.

#include <algorithm>
#include <string>
#include <variant>

#include "config/scenario_loader.hpp"
#include "live/command.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace argus;
  static const auto scenario =
      config::load_scenario(std::string(ARGUS_SOURCE_DIR) + "/scenarios/minimal.yaml");
  const auto parsed = live::parse_command(fuzz::text_of(data, size), scenario);
  const auto* c = std::get_if<live::command>(&parsed);
  if (c == nullptr) {
    ARGUS_FUZZ_CHECK(!std::get<std::string>(parsed).empty());
    return 0;
  }
  ARGUS_FUZZ_CHECK(live::name_of(c->kind) != "?");
  if (c->kind == live::command_kind::cancel) {
    ARGUS_FUZZ_CHECK(c->task >= 0);
    return 0;
  }
  const auto camera = std::find_if(scenario.cameras.begin(), scenario.cameras.end(),
                                   [&](const auto& cam) { return cam.id == c->camera; });
  ARGUS_FUZZ_CHECK(camera != scenario.cameras.end());
  if (c->kind == live::command_kind::task) {
    ARGUS_FUZZ_CHECK(c->pixel.x_px >= 0 && c->pixel.x_px < camera->imaging.width_px);
    ARGUS_FUZZ_CHECK(c->pixel.y_px >= 0 && c->pixel.y_px < camera->imaging.height_px);
    ARGUS_FUZZ_CHECK(c->cameras_wanted >= 1 && c->cameras_wanted <= 64);
  }
  return 0;
}

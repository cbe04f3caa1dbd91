// Commands from the network: what the console's POST /command accepts, and the clear message
// for everything else (the server answers it with HTTP 400 and changes nothing).
#include "live/command.hpp"

#include <gtest/gtest.h>

namespace argus::live {
namespace {

//   camera 1 (0,0) ---- camera 2 (10,0)          camera 3 (500,0): out of range, no link
config::scenario three_cameras() {
  config::scenario s;
  for (int id : {1, 2, 3}) {
    config::camera_settings c;
    c.id = id;
    c.position = {id == 3 ? 500.0 : 10.0 * (id - 1), 0.0};
    c.imaging.width_px = 320;
    c.imaging.height_px = 240;
    s.cameras.push_back(c);
  }
  s.network.communication_range_m = 50.0;
  return s;
}

std::string error_of(std::string_view json) {
  auto parsed = parse_command(json, three_cameras());
  if (auto* error = std::get_if<std::string>(&parsed)) return *error;
  return "(accepted)";
}

TEST(command, reads_each_kind) {
  const auto s = three_cameras();
  auto task =
      std::get<command>(parse_command(R"({"command":"task","camera":2,"pixel":[160,120]})", s));
  EXPECT_EQ(task.kind, command_kind::task);
  EXPECT_EQ(task.camera, 2);
  EXPECT_DOUBLE_EQ(task.pixel.x_px, 160.0);
  EXPECT_DOUBLE_EQ(task.pixel.y_px, 120.0);
  EXPECT_EQ(task.cameras_wanted, 1u);
  auto cancel = std::get<command>(parse_command(R"({"command":"cancel","task":3})", s));
  EXPECT_EQ(cancel.kind, command_kind::cancel);
  EXPECT_EQ(cancel.task, 3);
  auto crash = std::get<command>(parse_command(R"({"command":"crash","camera":3})", s));
  EXPECT_EQ(crash.kind, command_kind::crash);
  EXPECT_EQ(crash.camera, 3);
  auto cut = std::get<command>(parse_command(R"({"command":"cut","camera":2,"peer":1})", s));
  EXPECT_EQ(cut.kind, command_kind::cut);
  EXPECT_EQ(cut.peer, 1);
  auto heal = std::get<command>(parse_command(R"({"command":"heal","camera":1,"peer":2})", s));
  EXPECT_EQ(heal.kind, command_kind::heal);
  auto recover = std::get<command>(parse_command(R"({"command":"recover","camera":1})", s));
  EXPECT_EQ(recover.kind, command_kind::recover);
}

TEST(command, says_what_is_wrong) {
  EXPECT_EQ(error_of("{\"command\":"), "malformed JSON");
  EXPECT_EQ(error_of("[1,2]"), "expected a JSON object");
  EXPECT_NE(error_of("{}").find("'command' is missing"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"explode","camera":1})").find("unknown command 'explode'"),
            std::string::npos);
  EXPECT_EQ(error_of(R"({"command":"crash","camera":9})"), "unknown camera 9");
  EXPECT_NE(error_of(R"({"command":"crash","camera":"1"})").find("whole number"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"command":"crash","camera":1e300})").find("whole number"),
            std::string::npos);
  EXPECT_EQ(error_of(R"({"command":"task","camera":1,"pixel":[320,10]})"),
            "pixel [320, 10] is outside camera 1's 320x240 frame");
  EXPECT_EQ(error_of(R"({"command":"task","camera":1,"pixel":[-1,10]})"),
            "pixel [-1, 10] is outside camera 1's 320x240 frame");
  EXPECT_NE(error_of(R"({"command":"task","camera":1,"pixel":[1]})").find("'pixel' must be"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"command":"task","camera":1})").find("'pixel' must be"),
            std::string::npos);
  EXPECT_EQ(error_of(R"({"command":"cut","camera":1,"peer":3})"),
            "no link between camera 1 and camera 3");
  EXPECT_NE(error_of(R"({"command":"cancel"})").find("'task' is missing"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"cancel","task":-2})").find("'task' must be in"),
            std::string::npos);
  EXPECT_NE(
      error_of(R"({"command":"task","camera":1,"pixel":[1,1],"cameras_wanted":0})").find("in [1"),
      std::string::npos);
}

}  // namespace
}  // namespace argus::live

#include "config/utf8_text.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/field_override.hpp"
#include "config/scenario_loader.hpp"

namespace argus::config {
namespace {

/// "line:column:0xBB" of the first break, or "none".
std::string break_in(const std::string& text) {
  const auto at = first_non_utf8(text);
  if (!at) return "none";
  return std::to_string(at->line) + ":" + std::to_string(at->column) + ":" +
         std::to_string(static_cast<int>(at->byte));
}

TEST(utf8_text, well_formed_text_of_every_length_passes) {
  EXPECT_EQ(break_in(""), "none");
  EXPECT_EQ(break_in("name: plain\n"), "none");
  EXPECT_EQ(break_in("name: caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9A\x86\n"), "none");  // é € 🚆
  EXPECT_EQ(break_in("\xEF\xBF\xBF \xF4\x8F\xBF\xBF"), "none");  // U+FFFF, U+10FFFF
}

TEST(utf8_text, the_first_bad_byte_is_located_by_line_and_column) {
  EXPECT_EQ(break_in("a: 1\nname: caf\xE9\n"), "2:10:233");  // Latin-1 é
  EXPECT_EQ(break_in("\xFF"), "1:1:255");
  EXPECT_EQ(break_in("x\n\ny \x80"), "3:3:128");  // a lone continuation byte
}

TEST(utf8_text, truncated_overlong_surrogate_and_out_of_range_forms_are_refused) {
  EXPECT_EQ(break_in("ab\xC3"), "1:3:195");            // cut off at the end
  EXPECT_EQ(break_in("\xE2\x82 x"), "1:1:226");        // cut off before a space
  EXPECT_EQ(break_in("\xC0\xAF"), "1:1:192");          // overlong '/'
  EXPECT_EQ(break_in("\xE0\x80\xAF"), "1:1:224");      // overlong, three bytes
  EXPECT_EQ(break_in("\xED\xA0\x80"), "1:1:237");      // a UTF-16 surrogate
  EXPECT_EQ(break_in("\xF4\x90\x80\x80"), "1:1:244");  // past U+10FFFF
  EXPECT_EQ(break_in("\xF5\x80\x80\x80"), "1:1:245");
}

/// The problems loading `yaml` from `file` with `set` reports, one per line; "loaded" if none.
std::string problems_of(const std::string& yaml, const std::string& file,
                        const std::vector<field_override>& set = {}) {
  try {
    parse_scenario(yaml, file, set);
  } catch (const scenario_error& e) {
    std::string out;
    for (const auto& p : e.problems()) out += to_string(p) + "\n";
    return out;
  }
  return "loaded";
}

TEST(utf8_text, a_scenario_that_is_not_utf8_is_refused_with_file_line_and_byte) {
  EXPECT_EQ(problems_of("run: {seed: 1}\nname: \"caf\xE9\"\n", "bad.yaml"),
            "bad.yaml:2:11: expected UTF-8 text (YAML is Unicode), got the byte 0xE9; save the "
            "file as UTF-8\n");
}

TEST(utf8_text, a_file_name_that_is_not_utf8_cannot_name_the_run) {
  EXPECT_EQ(problems_of("run: {seed: 1}\n", "dir/caf\xE9.yaml"),
            "dir/caf\xE9.yaml: name: the scenario has no name: and its file name is not UTF-8 "
            "text (byte 0xE9); give it a name:\n");
  EXPECT_EQ(parse_scenario("name: cafe\n", "dir/caf\xE9.yaml").name, "cafe");
}

TEST(utf8_text, a_set_value_that_is_not_utf8_is_refused) {
  EXPECT_EQ(problems_of("run: {seed: 1}\n", "ok.yaml", {{"name", "caf\xE9"}}),
            "ok.yaml: name: --set: expected UTF-8 text, got the byte 0xE9 at byte 4\n");
}

}  // namespace
}  // namespace argus::config

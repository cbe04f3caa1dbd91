#include "config/yaml_guards.hpp"

#include <fmt/format.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <sstream>

namespace argus::config {

std::optional<problem> nul_byte(const std::string& source, std::string_view text) {
  const auto at = text.find('\0');
  if (at == std::string_view::npos) return std::nullopt;
  const auto before = text.substr(0, at);
  const auto line_start = before.rfind('\n');
  const auto column = at - (line_start == std::string_view::npos ? 0 : line_start + 1) + 1;
  return problem{source,
                 static_cast<int>(std::count(before.begin(), before.end(), '\n') + 1),
                 static_cast<int>(column),
                 {},
                 "unexpected NUL byte (YAML allows none in a file)"};
}

void refuse_stuck_documents(const std::string& text) {
  struct document_starts : YAML::EventHandler {
    std::optional<YAML::Mark> last;
    bool stuck = false;
    void OnDocumentStart(const YAML::Mark& mark) override {
      stuck = last && last->pos == mark.pos;
      last = mark;
    }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
  };
  std::istringstream in(text);
  YAML::Parser parser(in);
  document_starts starts;
  while (parser.HandleNextDocument(starts)) {
    if (!starts.stuck) continue;
    const auto at = static_cast<std::size_t>(starts.last->pos);
    throw YAML::ParserException(*starts.last, at < text.size()
                                                  ? fmt::format("unexpected '{}'", text[at])
                                                  : "unexpected end");
  }
}

}  // namespace argus::config

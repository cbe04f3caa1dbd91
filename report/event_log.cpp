#include "report/event_log.hpp"

#include <fstream>
#include <sstream>

namespace argus::report {

std::optional<event_log> event_log::read(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str());
}

event_log event_log::parse(const std::string& text) {
  event_log out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    auto event = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (event.is_object()) out.events.push_back(std::move(event));
  }
  return out;
}

double event_log::last_time_s() const {
  double last = 0.0;
  for (const auto& e : events)
    if (auto t = e.find("t"); t != e.end() && t->is_number())
      last = std::max(last, t->get<double>());
  return last;
}

long long integer_field(const nlohmann::json& event, const char* field, long long fallback) {
  const auto it = event.find(field);
  if (it == event.end() || !it->is_number()) return fallback;
  return it->get<long long>();
}

std::string text_field(const nlohmann::json& event, const char* field) {
  const auto it = event.find(field);
  return it != event.end() && it->is_string() ? it->get<std::string>() : std::string{};
}

}  // namespace argus::report

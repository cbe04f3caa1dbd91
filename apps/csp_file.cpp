#include "apps/csp_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "fmt/format.h"
#include "nlohmann/json.hpp"

namespace argus::apps {
namespace {

using json = nlohmann::json;

/// A group as written, before cameras get their indices.
struct written_group {
  std::string id;
  unsigned min_cameras = 0;
  unsigned max_cameras = 0;
  std::map<std::string, double> relevance;
};

/// How a JSON value reads in a message: its text, shortened.
std::string shown(const json& value) {
  auto text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

class checker {
 public:
  explicit checker(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw csp_file_error(field.empty() ? fmt::format("{}: {}", path_, what)
                                       : fmt::format("{}: {}: {}", path_, field, what));
  }

  void only_keys(const json& object, const std::string& field,
                 std::initializer_list<const char*> keys) const {
    for (const auto& item : object.items()) {
      // A plain reference: clang before 16 cannot capture a structured binding.
      const auto& key = item.key();
      if (std::none_of(keys.begin(), keys.end(), [&](const char* k) { return key == k; }))
        fail(field.empty() ? key : field + "." + key,
             fmt::format("unknown key; expected one of: {}", fmt::join(keys, ", ")));
    }
  }

  const json& required(const json& object, const std::string& field, const char* key,
                       const char* expected) const {
    const auto found = object.find(key);
    if (found == object.end())
      fail(field + "." + key, fmt::format("missing; expected {}", expected));
    return *found;
  }

  unsigned count(const json& value, const std::string& field) const {
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        value.get<std::uint64_t>() > std::numeric_limits<unsigned>::max())
      fail(field, fmt::format("expected a non-negative integer, got {}", shown(value)));
    return value.get<unsigned>();
  }

  double unit_number(const json& value, const std::string& field) const {
    if (!value.is_number() || !(value.get<double>() >= 0.0 && value.get<double>() <= 1.0))
      fail(field, fmt::format("expected a number in [0, 1], got {}", shown(value)));
    return value.get<double>();
  }

  written_group group(const json& value, const std::string& field) const {
    if (!value.is_object()) fail(field, fmt::format("expected an object, got {}", shown(value)));
    only_keys(value, field, {"id", "min_cameras", "max_cameras", "relevance"});
    written_group group;
    const auto& id = required(value, field, "id", "a non-empty string");
    if (!id.is_string() || id.get<std::string>().empty())
      fail(field + ".id", fmt::format("expected a non-empty string, got {}", shown(id)));
    group.id = id.get<std::string>();
    group.min_cameras = count(required(value, field, "min_cameras", "a non-negative integer"),
                              field + ".min_cameras");
    group.max_cameras = count(required(value, field, "max_cameras", "a non-negative integer"),
                              field + ".max_cameras");
    if (group.max_cameras < group.min_cameras)
      fail(field + ".max_cameras", fmt::format("expected at least min_cameras ({}), got {}",
                                               group.min_cameras, group.max_cameras));
    const auto& relevance =
        required(value, field, "relevance", "an object of camera id: relevance in [0, 1]");
    if (!relevance.is_object())
      fail(field + ".relevance",
           fmt::format("expected an object of camera id: relevance in [0, 1], got {}",
                       shown(relevance)));
    for (const auto& [camera, r] : relevance.items())
      group.relevance[camera] = unit_number(r, field + ".relevance." + camera);
    return group;
  }

 private:
  std::string path_;
};

}  // namespace

named_csp parse_csp(const std::string& text, const std::string& path) {
  const checker check(path);
  json document;
  try {
    document = json::parse(text);
  } catch (const json::exception& e) {
    // parse_error, and out_of_range for a number beyond a double's range (`1e3000`).
    check.fail("", fmt::format("not valid JSON: {}", e.what()));
  }
  if (!document.is_object())
    check.fail("", fmt::format("expected a JSON object with \"groups\", got {}", shown(document)));
  check.only_keys(document, "", {"groups", "threshold"});
  named_csp named;
  if (const auto threshold = document.find("threshold"); threshold != document.end())
    named.problem.threshold = check.unit_number(*threshold, "threshold");
  const auto groups = document.find("groups");
  if (groups == document.end()) check.fail("groups", "missing; expected a list of groups");
  if (!groups->is_array())
    check.fail("groups", fmt::format("expected a list of groups, got {}", shown(*groups)));

  std::vector<written_group> written;
  std::map<std::string, std::size_t> first_index;
  std::set<std::string> cameras;
  for (std::size_t i = 0; i < groups->size(); ++i) {
    const auto field = fmt::format("groups[{}]", i);
    auto group = check.group((*groups)[i], field);
    if (const auto [at, fresh] = first_index.emplace(group.id, i); !fresh)
      check.fail(field + ".id",
                 fmt::format("duplicate group id '{}' (also groups[{}].id)", group.id, at->second));
    for (const auto& [camera, r] : group.relevance) cameras.insert(camera);
    written.push_back(std::move(group));
  }
  std::sort(written.begin(), written.end(),
            [](const written_group& a, const written_group& b) { return a.id < b.id; });

  named.camera_ids.assign(cameras.begin(), cameras.end());
  named.problem.camera_count = named.camera_ids.size();
  for (const auto& group : written) {
    protocol::csp_group g;
    g.min_cameras = group.min_cameras;
    g.max_cameras = group.max_cameras;
    // A camera the group does not list is not relevant to it (NaN never is).
    g.relevance.assign(named.camera_ids.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t c = 0; c < named.camera_ids.size(); ++c)
      if (const auto r = group.relevance.find(named.camera_ids[c]); r != group.relevance.end())
        g.relevance[c] = r->second;
    named.group_ids.push_back(group.id);
    named.problem.groups.push_back(std::move(g));
  }
  return named;
}

named_csp read_csp_file(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw csp_file_error(fmt::format("{}: cannot open file: it is a directory", path));
  std::ifstream in(path);
  if (!in)
    throw csp_file_error(fmt::format("{}: cannot open file: {}", path, std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw csp_file_error(fmt::format("{}: cannot read file", path));
  return parse_csp(text.str(), path);
}

}  // namespace argus::apps

#pragma once

// The JSON file `argus csp solve` reads: a conflict between groups, by id.
//
//   {"groups": [{"id": "g1", "min_cameras": 2, "max_cameras": 3,
//                "relevance": {"c1": 0.9, "c2": 0.4}}, ...],
//    "threshold": 0.1}                                   # optional, default 0.1
//
// Groups are ordered by id (string order); the cameras are the union of every relevance key,
// ordered by id; a camera absent from a group's relevance is not relevant to it.

#include <stdexcept>
#include <string>
#include <vector>

#include "protocol/csp.hpp"

namespace argus::apps {

/// A conflict read from a file: the problem, and the ids of its groups and cameras by index.
struct named_csp {
  protocol::csp_problem problem;
  std::vector<std::string> group_ids;
  std::vector<std::string> camera_ids;
};

/// A malformed file; what() names the file, the field (e.g. `groups[1].max_cameras`) and
/// what was expected.
class csp_file_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads and checks the file at `path`; throws csp_file_error.
named_csp read_csp_file(const std::string& path);

/// Parses and checks `text`, naming `path` in errors; throws csp_file_error.
named_csp parse_csp(const std::string& text, const std::string& path);

}  // namespace argus::apps

#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace argus::config {

/// One thing wrong with a scenario file, located like a compiler diagnostic.
struct problem {
  /// The file (or source name) the scenario came from.
  std::string file;
  /// 1-based line of the offending value; 0 when unknown.
  int line = 0;
  /// 1-based column of the offending value; 0 when unknown.
  int column = 0;
  /// Full path of the field, e.g. `cameras[2].imaging.jpeg_quality`; empty for the whole file.
  std::string field;
  /// What is wrong and what was expected.
  std::string message;

  friend bool operator==(const problem&, const problem&) = default;
};

/// Formats `FILE:LINE:COL: FIELD: MESSAGE`; LINE and COL are left out when unknown (0) and
/// FIELD when empty, so a missing file reads `x.yaml: cannot open file: ...`.
std::string to_string(const problem& what);

/// Thrown when a scenario cannot be loaded. Carries every problem found in one pass, so a
/// user fixes a file in one round instead of one error at a time.
class scenario_error : public std::runtime_error {
 public:
  /// Takes the problems found; `what()` lists them one per line.
  explicit scenario_error(std::vector<problem> problems);

  /// All problems, in file order.
  const std::vector<problem>& problems() const noexcept { return problems_; }

 private:
  std::vector<problem> problems_;
};

}  // namespace argus::config

#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace argus::report {

/// A CSV file of a run's output (tracks.csv, targets.csv, poses.csv): a header naming the
/// columns, then rows of plain fields (no quoting: the run writes numbers and bare words).
/// Columns are found by name, so a file with more or reordered columns still reads.
class csv_table {
 public:
  /// Reads `file`; nothing when it does not exist or has no header. A row with fewer fields
  /// than the header (a run killed while writing) is dropped.
  static std::optional<csv_table> read(const std::filesystem::path& file);

  /// Parses CSV text (header line first).
  static csv_table parse(std::string_view text);

  /// The index of column `name`, if the header has it.
  std::optional<std::size_t> column(std::string_view name) const;

  /// The rows, each as many fields as the header.
  const std::vector<std::vector<std::string>>& rows() const noexcept { return rows_; }

  /// Field `column` of `row` as a number; `fallback` when it is not one.
  static double number(const std::vector<std::string>& row, std::size_t column,
                       double fallback = 0.0);

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace argus::report

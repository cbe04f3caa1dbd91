#include "report/camera_logs.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include "fmt/format.h"

namespace argus::report {

namespace {

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t from = 0;
  while (true) {
    const auto comma = line.find(',', from);
    out.push_back(line.substr(from, comma == std::string_view::npos ? comma : comma - from));
    if (comma == std::string_view::npos) return out;
    from = comma + 1;
  }
}

// Reads a run's CSV strictly: unlike csv_table (which skips what it cannot use, for pictures
// that tolerate a gap), a frame drawn from a wrong row would show a wrong camera pose, so every
// row must be whole and every number a number; the first that is not ends the reading with
// its file and line.
class strict_csv {
 public:
  strict_csv(std::string_view text, std::string name, std::vector<std::string_view> wanted)
      : text_(text), name_(std::move(name)) {
    const auto header = next_line();
    if (!header) throw camera_log_error(fmt::format("{}: empty, expected a header line", name_));
    header_ = fields_of(*header);
    for (auto column : wanted) {
      const auto it = std::find(header_.begin(), header_.end(), column);
      if (it == header_.end())
        throw camera_log_error(
            fmt::format("{}:1: no column '{}' in the header '{}'", name_, column, *header));
      columns_.push_back(static_cast<std::size_t>(it - header_.begin()));
    }
  }

  // Calls `row` for every data row; inside it, number(k) and text(k) read wanted column k.
  void for_each_row(const std::function<void()>& row) {
    while (auto line = next_line()) {
      fields_ = fields_of(*line);
      if (fields_.size() != header_.size())
        throw camera_log_error(fmt::format("{}:{}: expected {} fields, got {}", name_, line_,
                                           header_.size(), fields_.size()));
      row();
    }
  }

  double number(std::size_t k) const {
    const auto field = fields_[columns_[k]];
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (field.empty() || error != std::errc{} || end != field.data() + field.size())
      throw camera_log_error(fmt::format("{}:{}: column {}: expected a number, got '{}'", name_,
                                         line_, header_[columns_[k]], field));
    return value;
  }

  std::int64_t integer(std::size_t k) const {
    const double value = number(k);
    // Within the doubles that hold whole numbers exactly, so that the cast is defined.
    if (!(std::abs(value) < 9.0e15) || value != std::trunc(value))
      throw camera_log_error(fmt::format("{}:{}: column {}: expected a whole number, got '{}'",
                                         name_, line_, header_[columns_[k]], fields_[columns_[k]]));
    return static_cast<std::int64_t>(value);
  }

  std::string_view text(std::size_t k) const { return fields_[columns_[k]]; }

  std::size_t line() const { return line_; }
  const std::string& name() const { return name_; }

 private:
  // The next non-empty line, without its line ending.
  std::optional<std::string_view> next_line() {
    while (from_ < text_.size()) {
      auto end = text_.find('\n', from_);
      if (end == std::string_view::npos) end = text_.size();
      auto line = text_.substr(from_, end - from_);
      from_ = end + 1;
      ++line_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (!line.empty()) return line;
    }
    return std::nullopt;
  }

  std::string_view text_;
  std::string name_;
  std::size_t from_ = 0;
  std::size_t line_ = 0;
  std::vector<std::string_view> header_;
  std::vector<std::size_t> columns_;
  std::vector<std::string_view> fields_;
};

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw camera_log_error(fmt::format("{}: cannot be read", file.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

pose_history pose_history::read(const std::filesystem::path& file) {
  return parse(text_of(file), file.string());
}

pose_history pose_history::parse(std::string_view text, const std::string& name) {
  strict_csv csv(text, name, {"tick", "camera", "pan", "tilt", "fov", "state"});
  pose_history out;
  csv.for_each_row([&] {
    camera_pose pose;
    pose.world_tick = csv.integer(0);
    pose.pan_deg = csv.number(2);
    pose.tilt_deg = csv.number(3);
    pose.field_of_view_deg = csv.number(4);
    pose.state = std::string(csv.text(5));
    if (pose.field_of_view_deg <= 0.0 || pose.field_of_view_deg >= 180.0)
      throw camera_log_error(fmt::format("{}:{}: column fov: {} is not a field of view in degrees",
                                         csv.name(), csv.line(), pose.field_of_view_deg));
    auto& rows = out.by_camera_[static_cast<int>(csv.integer(1))];
    if (!rows.empty() && rows.back().world_tick > pose.world_tick)
      throw camera_log_error(fmt::format("{}:{}: tick {} comes after tick {} of the same camera",
                                         csv.name(), csv.line(), pose.world_tick,
                                         rows.back().world_tick));
    rows.push_back(std::move(pose));
  });
  return out;
}

const camera_pose* pose_history::at(int camera, std::int64_t world_tick) const {
  const auto it = by_camera_.find(camera);
  if (it == by_camera_.end()) return nullptr;
  const auto& rows = it->second;
  // The first row after the tick; the one before it holds.
  const auto after = std::upper_bound(
      rows.begin(), rows.end(), world_tick,
      [](std::int64_t tick, const camera_pose& pose) { return tick < pose.world_tick; });
  return after == rows.begin() ? nullptr : &*std::prev(after);
}

const std::vector<camera_pose>& pose_history::rows_of(int camera) const {
  static const std::vector<camera_pose> none;
  const auto it = by_camera_.find(camera);
  return it == by_camera_.end() ? none : it->second;
}

std::vector<int> pose_history::cameras() const {
  std::vector<int> out;
  for (const auto& [camera, rows] : by_camera_) out.push_back(camera);
  return out;
}

track_history track_history::read(const std::filesystem::path& file) {
  return parse(text_of(file), file.string());
}

track_history track_history::parse(std::string_view text, const std::string& name) {
  strict_csv csv(text, name, {"tick", "camera", "task", "found", "x", "y", "w", "h", "observed"});
  track_history out;
  csv.for_each_row([&] {
    track_box box;
    box.task = static_cast<int>(csv.integer(2));
    box.found = csv.integer(3) != 0;
    box.x = csv.number(4);
    box.y = csv.number(5);
    box.width = csv.number(6);
    box.height = csv.number(7);
    box.observed = csv.integer(8) != 0;
    if (box.found && (box.width < 0.0 || box.height < 0.0))
      throw camera_log_error(
          fmt::format("{}:{}: a found box with a negative size", csv.name(), csv.line()));
    out.by_camera_tick_[{static_cast<int>(csv.integer(1)), csv.integer(0)}].push_back(box);
  });
  return out;
}

std::vector<track_box> track_history::at(int camera, std::int64_t world_tick) const {
  const auto it = by_camera_tick_.find({camera, world_tick});
  return it == by_camera_tick_.end() ? std::vector<track_box>{} : it->second;
}

std::int64_t track_history::first_report(int camera, int task, std::int64_t from,
                                         std::int64_t to) const {
  for (auto it = by_camera_tick_.lower_bound({camera, from});
       it != by_camera_tick_.end() && it->first.first == camera && it->first.second <= to; ++it)
    for (const auto& box : it->second)
      if (box.task == task) return it->first.second;
  return -1;
}

}  // namespace argus::report

// The distance fields kept on disk between processes (world/field_cache.hpp): read back bit for
// bit, never read when damaged, of another version or of another station, kept to their size,
// and a cache that cannot be written costs a station nothing but the time.

#include "world/field_cache.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <latch>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "world/station.hpp"

namespace argus::world {
namespace {

namespace fs = std::filesystem;

// A folder of its own for each test, removed after it.
class scratch {
 public:
  explicit scratch(const std::string& name)
      : path_(fs::path(::testing::TempDir()) /
              ("field_cache_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~scratch() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// A hall with a wall piece and a pillar, so that the fields bend and keep off walls.
layout hall() {
  layout plan;
  plan.source_path = "hall.yaml";
  plan.size_m = {20.0, 10.0};
  plan.regions.push_back({"hall", region_kind::waiting_room, {{0, 0}, {20, 10}}});
  plan.portals.push_back({"door", portal_kind::street, {{0, 4}, {1, 6}}});
  plan.stairways.push_back({"platform", {{17, 4}, {19, 6}}});
  plan.walls.push_back({{{10, 0}, {10, 6}}});
  plan.obstacles.push_back({"pillar", {{5, 6}, {6, 6}, {6, 7}, {5, 7}}});
  return plan;
}

navigation_settings cached_in(const fs::path& dir) {
  navigation_settings settings;
  settings.field_cache = dir;
  return settings;
}

// Every value of every field (the door's and the platform's), hashed.
std::string digest_of(const station& s) {
  field_key key;
  for (const auto kind : {target_kind::portal, target_kind::stairs}) {
    const int field = s.target(kind, 0);
    for (int y = 0; y < s.grid_height(); ++y)
      for (int x = 0; x < s.grid_width(); ++x) key.add_value(s.field_at(field, x, y));
  }
  return key.hex();
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
  return out;
}

TEST(field_cache, a_station_reads_back_the_fields_it_stored_bit_for_bit) {
  scratch dir("round_trip");
  const station computed{hall()};
  const station first{hall(), cached_in(dir.path())};
  EXPECT_FALSE(first.fields_from_cache());
  EXPECT_EQ(first.field_cache_problem(), "");
  ASSERT_EQ(files_in(dir.path()).size(), 1u);
  const station second{hall(), cached_in(dir.path())};
  EXPECT_TRUE(second.fields_from_cache());
  EXPECT_EQ(digest_of(second), digest_of(computed));
  EXPECT_EQ(digest_of(first), digest_of(computed));
  // Another station is another file, never the first one's fields.
  auto moved = hall();
  moved.walls.front().points.back() = {10, 7};
  const station other{moved, cached_in(dir.path())};
  EXPECT_FALSE(other.fields_from_cache());
  EXPECT_NE(digest_of(other), digest_of(computed));
  EXPECT_EQ(files_in(dir.path()).size(), 2u);
}

TEST(field_cache, a_damaged_short_or_other_version_file_is_not_read_and_is_replaced) {
  scratch dir("damaged");
  const station computed{hall()};
  const station first{hall(), cached_in(dir.path())};
  const auto file = files_in(dir.path()).at(0);
  const auto size = fs::file_size(file);
  auto spoil = [&](std::uintmax_t offset, char value) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(offset));
    f.put(value);
  };
  // One value of the last field changed; then the version; then the file cut short.
  const std::vector<std::function<void()>> damages{[&] { spoil(size - 3, 0x55); },
                                                   [&] { spoil(8, 7); },
                                                   [&] { fs::resize_file(file, size - 4); }};
  for (std::size_t d = 0; d < damages.size(); ++d) {
    damages[d]();
    const station again{hall(), cached_in(dir.path())};
    EXPECT_FALSE(again.fields_from_cache()) << "damage " << d;
    EXPECT_EQ(digest_of(again), digest_of(computed)) << "damage " << d;
    // Computed again and stored again, whole.
    EXPECT_EQ(fs::file_size(file), size) << "damage " << d;
    EXPECT_TRUE(station(hall(), cached_in(dir.path())).fields_from_cache()) << "damage " << d;
  }
}

// A station reads its kept fields where the file is mapped. The cache never changes a file in
// place: it writes a new one aside and renames it over the old, and trim() unlinks. Either
// leaves a station that mapped the old file with the fields it read.
TEST(field_cache, a_station_keeps_the_fields_it_read_when_the_file_is_replaced_or_removed) {
  scratch dir("replaced");
  const station computed{hall()};
  { const station first{hall(), cached_in(dir.path())}; }
  const station reading{hall(), cached_in(dir.path())};
  ASSERT_TRUE(reading.fields_from_cache());
  const auto file = files_in(dir.path()).at(0);
  const auto size = fs::file_size(file);
  // Another file of the same size, written aside and renamed over it, as store() does.
  const auto aside = dir.path() / "aside";
  {
    std::ofstream out(aside, std::ios::binary);
    const std::string zeros(size, '\0');
    out.write(zeros.data(), static_cast<std::streamsize>(zeros.size()));
  }
  fs::rename(aside, file);
  EXPECT_EQ(digest_of(reading), digest_of(computed));
  fs::remove(file);
  EXPECT_EQ(digest_of(reading), digest_of(computed));
}

TEST(field_cache, the_cache_keeps_to_its_size_and_drops_the_least_recently_used_first) {
  scratch dir("trim");
  const std::vector<std::vector<float>> fields(2, std::vector<float>(1000, 1.5f));
  auto key = [](char c) { return std::string(64, c); };
  // Room for two files (a header and the values each).
  ASSERT_EQ(field_cache(dir.path()).store(key('a'), fields), "");
  const auto bytes = fs::file_size(field_cache(dir.path()).file_of(key('a')));
  EXPECT_GT(bytes, 2 * 1000 * sizeof(float));
  const field_cache cache(dir.path(), 2 * bytes + 10);
  const auto now = fs::file_time_type::clock::now();
  ASSERT_EQ(cache.store(key('b'), fields), "");
  fs::last_write_time(cache.file_of(key('a')), now - std::chrono::hours(2));
  fs::last_write_time(cache.file_of(key('b')), now - std::chrono::hours(1));
  // Reading a marks it used: b is now the least recently used.
  ASSERT_TRUE(cache.load(key('a'), 2, 1000).has_value());
  ASSERT_EQ(cache.store(key('c'), fields), "");
  EXPECT_TRUE(fs::exists(cache.file_of(key('a'))));
  EXPECT_FALSE(fs::exists(cache.file_of(key('b'))));
  EXPECT_TRUE(fs::exists(cache.file_of(key('c'))));
  // A load asks for the shape it expects: another shape is a miss.
  EXPECT_FALSE(cache.load(key('a'), 3, 1000).has_value());
  EXPECT_FALSE(cache.load(key('a'), 2, 999).has_value());
  EXPECT_FALSE(cache.load("../a", 2, 1000).has_value());
}

TEST(field_cache, a_cache_that_cannot_be_written_costs_a_station_only_time) {
  scratch dir("unwritable");
  // The cache's folder would have to be made inside a plain file.
  const auto blocker = dir.path() / "a-file";
  std::ofstream(blocker) << "not a folder";
  const station computed{hall()};
  const station s{hall(), cached_in(blocker / "fields")};
  EXPECT_FALSE(s.fields_from_cache());
  EXPECT_NE(s.field_cache_problem().find("cannot make " + (blocker / "fields").string()),
            std::string::npos)
      << s.field_cache_problem();
  EXPECT_EQ(digest_of(s), digest_of(computed));
}

// Sets an environment variable for one scope, then puts back what was there.
class environment_variable {
 public:
  environment_variable(const char* name, const char* value) : name_(name) {
    if (const char* was = std::getenv(name)) was_ = was;
    if (value != nullptr)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  }
  ~environment_variable() {
    if (was_)
      ::setenv(name_, was_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> was_;
};

TEST(field_cache, runs_keep_it_where_the_environment_says) {
  {
    environment_variable chosen("ARGUS_FIELD_CACHE", "/somewhere/fields");
    EXPECT_EQ(field_cache::default_dir(), fs::path("/somewhere/fields"));
  }
  {
    environment_variable off("ARGUS_FIELD_CACHE", "off");
    EXPECT_EQ(field_cache::default_dir(), std::nullopt);
  }
  environment_variable unset("ARGUS_FIELD_CACHE", nullptr);
  {
    environment_variable xdg("XDG_CACHE_HOME", "/cache");
    EXPECT_EQ(field_cache::default_dir(), fs::path("/cache/argus/fields"));
  }
  environment_variable no_xdg("XDG_CACHE_HOME", nullptr);
  {
    environment_variable home("HOME", "/home/me");
    EXPECT_EQ(field_cache::default_dir(), fs::path("/home/me/.cache/argus/fields"));
  }
  environment_variable no_home("HOME", nullptr);
  EXPECT_EQ(field_cache::default_dir(), std::nullopt);
}

TEST(field_cache, the_fields_of_a_fixed_layout_are_pinned) {
  // Files of the cache are read by later builds. When this digest changes, the fields
  // computed from the same grid have changed: bump field_cache::version with it, or a later
  // run reads the fields of an earlier build.
  EXPECT_EQ(digest_of(station{hall()}),
            "5da406428442907d31edcc624e6c3238bba59f9e926afa8c32dc3fb7b7011841");
}

}  // namespace
// A distributed run's processes load the station at once: while one computes the fields, the
// others wait for it, then read what it stored.
TEST(field_cache, a_station_waits_for_the_one_computing_then_reads_what_it_stored) {
  scratch dir("waits");
  scratch elsewhere("waits_elsewhere");
  const station computed{hall(), cached_in(elsewhere.path())};
  const auto stored = files_in(elsewhere.path()).at(0);
  std::atomic<bool> loaded{false};
  std::unique_ptr<station> waiting;
  {
    auto computing = field_cache(dir.path()).lock_to_compute();
    ASSERT_TRUE(computing.held());
    std::jthread loader([&] {
      waiting = std::make_unique<station>(hall(), cached_in(dir.path()));
      loaded = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_FALSE(loaded) << "a station computed its fields while another held the right to";
    // What the one computing stores before it lets go.
    fs::copy_file(stored, dir.path() / stored.filename(), fs::copy_options::overwrite_existing);
    computing = {};
    loader.join();
  }
  ASSERT_TRUE(waiting);
  EXPECT_TRUE(waiting->fields_from_cache());
  EXPECT_EQ(digest_of(*waiting), digest_of(computed));
}

TEST(field_cache, of_stations_loaded_at_once_one_computes_and_the_others_read) {
  scratch dir("at_once");
  constexpr std::size_t at_once = 4;
  std::vector<std::unique_ptr<station>> loaded(at_once);
  {
    std::latch go(at_once);
    std::vector<std::jthread> loaders;
    for (std::size_t i = 0; i < at_once; ++i)
      loaders.emplace_back([&, i] {
        go.arrive_and_wait();
        loaded[i] = std::make_unique<station>(hall(), cached_in(dir.path()));
      });
  }
  std::size_t computed = 0;
  for (const auto& s : loaded) {
    ASSERT_TRUE(s);
    if (!s->fields_from_cache()) ++computed;
    EXPECT_EQ(digest_of(*s), digest_of(*loaded.front()));
  }
  EXPECT_EQ(computed, 1u);
}

}  // namespace argus::world

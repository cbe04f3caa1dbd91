#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "world/field_set.hpp"

namespace argus::world {

/// A station's distance fields kept on disk, so that a machine computes them once for every
/// run of the station and every process of a run, instead of once per process: 10 s on two
/// cores for the large station, paid again by each worker of a distributed run and each run of
/// a sweep (docs/world.md, "Navigation").
///
/// A file holds one station's fields under a key that hashes everything they are computed from
/// (the grid, the targets' cells, `version`), and a checksum of its contents. A file that is
/// not whole, not this version or altered is never read: the fields are computed instead. A
/// file appears whole or not at all (written aside, then renamed), so processes that compute
/// the same fields at once each write the same bytes and any reader sees one whole copy.
class field_cache {
 public:
  /// Bump when the fields computed from the same grid and sources change (the step costs of
  /// station::dijkstra, say): files of another version are never read.
  /// `station_test.the_fields_of_a_fixed_layout_are_pinned` fails when they change.
  /// 2: the contents' checksum is XXH3's 128 bits instead of SHA-256.
  static constexpr std::uint32_t version = 2;
  /// The most the cache keeps; the least recently used files go first.
  static constexpr std::uint64_t default_max_bytes = std::uint64_t{4} << 30;

  explicit field_cache(std::filesystem::path dir, std::uint64_t max_bytes = default_max_bytes);

  /// Where runs keep it: `$ARGUS_FIELD_CACHE`, else `$XDG_CACHE_HOME/argus/fields`, else
  /// `$HOME/.cache/argus/fields`; none when `ARGUS_FIELD_CACHE` is `off` or there is no home.
  static std::optional<std::filesystem::path> default_dir();
  /// The same as `navigation_settings::field_cache` takes it: empty for none.
  static std::filesystem::path default_dir_or_none() {
    return default_dir().value_or(std::filesystem::path{});
  }

  /// The `fields` fields of `cells` values each stored under `key`, if a whole file of this
  /// version with a matching checksum is there (and it is marked as just used). The file is
  /// mapped, not copied: the set reads the page cache's copy, shared with every other process
  /// that loaded it. A file is never changed in place (store writes aside, then renames, and
  /// trim unlinks), so a mapped one stays whole while it is read.
  std::optional<field_set> load(const std::string& key, std::size_t fields,
                                std::size_t cells) const;

  /// Stores `fields` under `key` and trims the cache to its size. Returns what went wrong
  /// (the folder cannot be made, the disk is full), empty when it was stored: a cache that
  /// cannot be written costs time, never a run.
  std::string store(const std::string& key, const std::vector<std::vector<float>>& fields) const;

  /// The file `key` is kept in.
  std::filesystem::path file_of(const std::string& key) const;

  /// The right to compute fields for this cache, held by one process (or thread) at a time: an
  /// exclusive `flock` on the cache's folder, released when it goes. A distributed run's
  /// coordinator and its workers load the station at once; when the fields are not yet kept,
  /// the first to take this computes them and the others wait, then read them, instead of each
  /// computing them on the same cores. Where the folder cannot be made or locked, it holds
  /// nothing and waits for nothing: a cache that cannot be locked costs time, never a run.
  class compute_lock {
   public:
    compute_lock() = default;
    explicit compute_lock(const std::filesystem::path& dir);
    compute_lock(compute_lock&& other) noexcept;
    compute_lock& operator=(compute_lock&& other) noexcept;
    compute_lock(const compute_lock&) = delete;
    compute_lock& operator=(const compute_lock&) = delete;
    ~compute_lock();
    /// Whether the folder is locked by this (false where it could not be).
    bool held() const noexcept { return fd_ >= 0; }

   private:
    int fd_ = -1;
  };

  /// Waits until no other process or thread computes fields for this cache, and holds that
  /// right until the lock goes. Load again after taking it: the one waited for may have stored
  /// the very fields wanted.
  compute_lock lock_to_compute() const;

 private:
  void trim(const std::filesystem::path& keep) const;

  std::filesystem::path dir_;
  std::uint64_t max_bytes_;
};

/// Builds a field_cache key: the SHA-256 of everything added, in hex.
class field_key {
 public:
  field_key();
  ~field_key();
  field_key(const field_key&) = delete;
  field_key& operator=(const field_key&) = delete;

  void add(std::span<const std::byte> bytes);
  template <class T>
  void add_values(std::span<const T> values) {
    add(std::as_bytes(values));
  }
  template <class T>
  void add_value(const T& value) {
    add_values(std::span<const T>(&value, 1));
  }
  /// The key; adds nothing after.
  std::string hex();

 private:
  void* context_;
};

}  // namespace argus::world

#include "world/field_cache.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
// Debian's libxxhash-dev, inlined: the checksum of the fields' bytes, not of the key.
#define XXH_INLINE_ALL
#include <xxhash.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <tuple>
#include <utility>

#include "fmt/format.h"

namespace argus::world {
namespace {

namespace fs = std::filesystem;

constexpr std::array<char, 8> magic{'A', 'R', 'G', 'U', 'S', 'F', 'L', 'D'};
constexpr std::size_t key_chars = 64;
constexpr const char* extension = ".fields";

// What a file starts with; the fields follow, one after another, as the machine's floats.
struct file_header {
  std::array<char, 8> magic{};
  std::uint32_t version = 0;
  std::uint32_t reserved = 0;
  std::uint64_t fields = 0;
  std::uint64_t cells = 0;
  std::array<char, key_chars> key{};
  std::array<unsigned char, 32> checksum{};
};
static_assert(sizeof(file_header) == 8 + 4 + 4 + 8 + 8 + key_chars + 32);

EVP_MD_CTX* new_sha256() {
  EVP_MD_CTX* context = EVP_MD_CTX_new();
  if (context == nullptr || EVP_DigestInit_ex(context, EVP_sha256(), nullptr) != 1) {
    EVP_MD_CTX_free(context);
    throw std::runtime_error("OpenSSL cannot make a SHA-256 context");
  }
  return context;
}

std::array<unsigned char, 32> finish(EVP_MD_CTX* context) {
  std::array<unsigned char, 32> digest{};
  unsigned length = 0;
  EVP_DigestFinal_ex(context, digest.data(), &length);
  EVP_MD_CTX_free(context);
  return digest;
}

// The checksum of a file's fields: XXH3's 128 bits, at memory speed. SHA-256 over the large
// station's 523 MB took 0.3 s of every process's loading (bench/RESULTS.md, "The field cache's
// checksum"); a checksum here finds a damaged file, which needs no cryptographic strength (the
// key, which names the file, stays SHA-256).
class fields_checksum {
 public:
  fields_checksum() : state_(XXH3_createState()) {
    if (state_ == nullptr || XXH3_128bits_reset(state_) != XXH_OK)
      throw std::runtime_error("cannot make an XXH3 state");
  }
  fields_checksum(const fields_checksum&) = delete;
  fields_checksum& operator=(const fields_checksum&) = delete;
  ~fields_checksum() { XXH3_freeState(state_); }
  void add(const void* bytes, std::size_t size) { XXH3_128bits_update(state_, bytes, size); }
  /// In the header's 32 bytes: the canonical (big-endian) 16, then zeros.
  std::array<unsigned char, 32> digest() const {
    XXH128_canonical_t canonical;
    XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state_));
    std::array<unsigned char, 32> out{};
    std::memcpy(out.data(), canonical.digest, sizeof canonical.digest);
    return out;
  }

 private:
  XXH3_state_t* state_;
};

bool key_fits(const std::string& key) {
  return key.size() == key_chars &&
         std::all_of(key.begin(), key.end(), [](char c) { return std::isxdigit(c) != 0; });
}

}  // namespace

field_cache::field_cache(std::filesystem::path dir, std::uint64_t max_bytes)
    : dir_(std::move(dir)), max_bytes_(max_bytes) {}

std::optional<std::filesystem::path> field_cache::default_dir() {
  if (const char* chosen = std::getenv("ARGUS_FIELD_CACHE"); chosen != nullptr && *chosen != 0) {
    if (std::string(chosen) == "off") return std::nullopt;
    return fs::path(chosen);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg == '/')
    return fs::path(xdg) / "argus" / "fields";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != 0)
    return fs::path(home) / ".cache" / "argus" / "fields";
  return std::nullopt;
}

std::filesystem::path field_cache::file_of(const std::string& key) const {
  return dir_ / (key + extension);
}

std::optional<field_set> field_cache::load(const std::string& key, std::size_t fields,
                                           std::size_t cells) const {
  if (!key_fits(key)) return std::nullopt;
  const auto file = file_of(key);
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  const std::size_t value_bytes = cells * sizeof(float);
  const std::size_t size = sizeof(file_header) + fields * value_bytes;
  struct stat status {};
  // A file of another size is not whole (or holds another shape): it is not mapped, so no read
  // runs past its end.
  if (::fstat(fd, &status) != 0 || static_cast<std::uint64_t>(status.st_size) != size) {
    ::close(fd);
    return std::nullopt;
  }
  // Populated at once: one call maps the pages the page cache holds, instead of a fault each.
  void* at = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  ::close(fd);
  if (at == MAP_FAILED) return std::nullopt;
  const std::shared_ptr<const void> mapping(
      at, [size](const void* p) { ::munmap(const_cast<void*>(p), size); });
  const auto* bytes = static_cast<const unsigned char*>(at);
  file_header header;
  std::memcpy(&header, bytes, sizeof header);
  if (header.magic != magic || header.version != version || header.fields != fields ||
      header.cells != cells || std::memcmp(header.key.data(), key.data(), key_chars) != 0)
    return std::nullopt;
  fields_checksum checksum;
  checksum.add(bytes + sizeof header, fields * value_bytes);
  if (checksum.digest() != header.checksum) return std::nullopt;
  // The header is 128 bytes into a page-aligned mapping: the floats are aligned.
  std::vector<std::span<const float>> views;
  views.reserve(fields);
  for (std::size_t f = 0; f < fields; ++f)
    views.emplace_back(reinterpret_cast<const float*>(bytes + sizeof header + f * value_bytes),
                       cells);
  // Marked as used, for trim(); a cache on a read-only disk still serves.
  std::error_code ignored;
  fs::last_write_time(file, fs::file_time_type::clock::now(), ignored);
  return field_set(mapping, std::move(views));
}

std::string field_cache::store(const std::string& key,
                               const std::vector<std::vector<float>>& fields) const {
  if (!key_fits(key)) return fmt::format("'{}' is not a field cache key", key);
  std::error_code error;
  fs::create_directories(dir_, error);
  if (error) return fmt::format("cannot make {}: {}", dir_.string(), error.message());
  file_header header;
  header.magic = magic;
  header.version = version;
  header.fields = fields.size();
  header.cells = fields.empty() ? 0 : fields.front().size();
  for (const auto& f : fields)
    if (f.size() != header.cells) return "fields of different sizes cannot be stored";
  std::copy(key.begin(), key.end(), header.key.begin());
  // Aside first, under a name no other process or thread uses, then renamed into place.
  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const auto aside =
      dir_ / fmt::format("{}.tmp.{}.{}.{}", key, ::getpid(),
                         std::hash<std::thread::id>{}(std::this_thread::get_id()), stamp);
  {
    // One pass over the fields: each is hashed as it is written, and the header, written first
    // without its checksum, is written again with it.
    fields_checksum checksum;  // before the file: when it throws, none is left
    std::ofstream out(aside, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    for (const auto& f : fields) {
      const auto bytes = f.size() * sizeof(float);
      out.write(reinterpret_cast<const char*>(f.data()), static_cast<std::streamsize>(bytes));
      checksum.add(f.data(), bytes);
    }
    header.checksum = checksum.digest();
    out.seekp(0);
    out.write(reinterpret_cast<const char*>(&header), sizeof header);
    out.flush();
    if (!out) {
      fs::remove(aside, error);
      return fmt::format("cannot write {} (is the disk full?)", aside.string());
    }
  }
  const auto file = file_of(key);
  fs::rename(aside, file, error);
  if (error) {
    const auto message =
        fmt::format("cannot rename {} to {}: {}", aside.string(), file.string(), error.message());
    fs::remove(aside, error);
    return message;
  }
  trim(file);
  return {};
}

field_cache::compute_lock::compute_lock(const std::filesystem::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) return;
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) return;
  int locked;
  do {
    locked = ::flock(fd_, LOCK_EX);
  } while (locked != 0 && errno == EINTR);
  if (locked != 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

field_cache::compute_lock::compute_lock(compute_lock&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)) {}

field_cache::compute_lock& field_cache::compute_lock::operator=(compute_lock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

// Closing the descriptor releases the flock.
field_cache::compute_lock::~compute_lock() {
  if (fd_ >= 0) ::close(fd_);
}

field_cache::compute_lock field_cache::lock_to_compute() const {
  return compute_lock(dir_);
}

void field_cache::trim(const std::filesystem::path& keep) const {
  struct entry {
    fs::file_time_type used;
    std::uint64_t bytes;
    fs::path path;
  };
  std::vector<entry> files;
  std::uint64_t total = 0;
  const auto now = fs::file_time_type::clock::now();
  std::error_code error;
  for (const auto& item : fs::directory_iterator(dir_, error)) {
    std::error_code e;
    const auto used = item.last_write_time(e);
    if (e) continue;
    const auto name = item.path().filename().string();
    // A file left aside by a process that died while writing it.
    if (name.find(".tmp.") != std::string::npos) {
      if (now - used > std::chrono::hours(1)) fs::remove(item.path(), e);
      continue;
    }
    if (item.path().extension() != extension) continue;
    const auto bytes = item.file_size(e);
    if (e) continue;
    files.push_back({used, bytes, item.path()});
    total += bytes;
  }
  std::sort(files.begin(), files.end(), [](const entry& a, const entry& b) {
    return std::tie(a.used, a.path) < std::tie(b.used, b.path);
  });
  for (const auto& f : files) {
    if (total <= max_bytes_) break;
    if (f.path == keep) continue;
    std::error_code e;
    if (fs::remove(f.path, e)) total -= f.bytes;
  }
}

field_key::field_key() : context_(new_sha256()) {}

field_key::~field_key() {
  if (context_ != nullptr) EVP_MD_CTX_free(static_cast<EVP_MD_CTX*>(context_));
}

void field_key::add(std::span<const std::byte> bytes) {
  if (context_ == nullptr) throw std::logic_error("field_key: add after hex()");
  EVP_DigestUpdate(static_cast<EVP_MD_CTX*>(context_), bytes.data(), bytes.size());
}

std::string field_key::hex() {
  if (context_ == nullptr) throw std::logic_error("field_key: hex() twice");
  const auto digest = finish(static_cast<EVP_MD_CTX*>(context_));
  context_ = nullptr;
  std::string out;
  for (const auto b : digest) out += fmt::format("{:02x}", b);
  return out;
}

}  // namespace argus::world

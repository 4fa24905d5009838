#include "io/DrapeCache.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <system_error>

#include "io/AtomicFile.h"
#include "io/ByteReader.h"
#include "io/ByteWriter.h"
#include "io/Fnv1a.h"
#include "io/SharedCacheStore.h"

namespace figment {

namespace {
constexpr std::array<char, 16> kMagic = {'f', 'i', 'g', 'm', 'e', 'n', 't', '-',
                                         'd', 'r', 'a', 'p', 'e', ' ', '2', '\n'};  // 2: one record
// Three digests of a key, each FNV-1a from its own basis.
constexpr std::uint64_t kBases[3] = {14695981039346656037ull, 0x84222325cbf29ce4ull, 0x9e3779b97f4a7c15ull};

std::uint64_t digest(const std::string& text, int which) {
  Fnv1a hash(kBases[which]);
  hash.addText(text);
  return hash.value();
}

std::uint64_t checksum(const std::vector<unsigned char>& bytes) {
  Fnv1a hash;
  hash.addBytes(bytes.data(), bytes.size());
  return hash.value();
}

// An entry's name: two digests of its key, so the folder and a shared store name it alike.
std::string stemOf(const std::string& key) {
  char name[40];
  std::snprintf(name, sizeof name, "%016" PRIx64 "%016" PRIx64, digest(key, 0), digest(key, 1));
  return name;
}

// An entry's bytes: the magic, a third digest of the key, the payload's size and checksum,
// the payload (the record).
std::vector<unsigned char> encode(const std::string& key, const std::vector<unsigned char>& payload) {
  ByteWriter entry;
  entry.put(kMagic);
  entry.put(digest(key, 2));
  entry.put(static_cast<std::uint64_t>(payload.size()));
  entry.put(checksum(payload));
  std::vector<unsigned char> bytes = entry.take();
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  return bytes;
}

// The record an entry's bytes hold, if they are sound and made for `key`.
std::optional<std::vector<unsigned char>> decode(const std::vector<unsigned char>& bytes, const std::string& key) {
  ByteReader header(bytes);
  std::array<char, 16> magic{};
  std::uint64_t keyDigest = 0, size = 0, sum = 0;
  const bool sound = header.get(magic) && magic == kMagic && header.get(keyDigest) && keyDigest == digest(key, 2) &&
                     header.get(size) && header.get(sum);
  const std::size_t headerSize = kMagic.size() + 3 * sizeof(std::uint64_t);
  if (!sound || bytes.size() != headerSize + size) return std::nullopt;
  std::vector<unsigned char> payload(bytes.begin() + headerSize, bytes.end());
  if (checksum(payload) != sum) return std::nullopt;
  return payload;
}

std::string writeEntry(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  return writeAtomically(path.string(), [&](const std::string& temporary) -> std::string {
    std::ofstream out(temporary, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.close();
    return out ? "" : "cannot write";
  });
}
}  // namespace

DrapeCache::DrapeCache(std::filesystem::path folder, std::uintmax_t maxBytes,
                       std::shared_ptr<const SharedCacheStore> shared)
    : folder_(std::move(folder)), maxBytes_(maxBytes), shared_(std::move(shared)) {}

std::filesystem::path DrapeCache::userFolder() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "figment";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "figment";
  return {};
}

std::filesystem::path DrapeCache::entryPath(const std::string& key) const {
  return folder_ / (stemOf(key) + ".drape");
}

std::string DrapeCache::sharedName(const std::string& key) const {
  return "drape:" + stemOf(key);
}

std::optional<std::vector<unsigned char>> DrapeCache::find(const std::string& key, std::string& problem) const {
  problem.clear();
  const std::filesystem::path path = entryPath(key);
  std::ifstream in(path, std::ios::binary);
  if (!in) return shared_ ? findShared(key, problem) : std::nullopt;
  const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::optional<std::vector<unsigned char>> drape = decode(bytes, key);
  std::error_code ec;
  if (!drape) {
    std::filesystem::remove(path, ec);
    problem = path.string() + ": a damaged entry, removed; draped again";
    return std::nullopt;
  }
  std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now(), ec);  // recently used
  return drape;
}

std::optional<std::vector<unsigned char>> DrapeCache::findShared(const std::string& key, std::string& problem) const {
  const std::string name = sharedName(key);
  const std::optional<std::string> kept = shared_->get(name);
  if (!kept) return std::nullopt;
  const std::vector<unsigned char> bytes(kept->begin(), kept->end());
  std::optional<std::vector<unsigned char>> drape = decode(bytes, key);
  if (!drape) {
    shared_->remove(name);
    problem = "shared entry " + name + ": damaged or foreign, removed; draped again";
    return std::nullopt;
  }
  // The folder is the first level: the next read of this entry is local. A folder that
  // cannot be written costs only that.
  if (writeEntry(entryPath(key), bytes).empty()) trim();
  return drape;
}

std::string DrapeCache::store(const std::string& key, const std::vector<unsigned char>& record) const {
  const std::vector<unsigned char> bytes = encode(key, record);
  if (shared_) shared_->put(sharedName(key), std::string(bytes.begin(), bytes.end()));
  std::error_code ec;
  std::filesystem::create_directories(folder_, ec);
  if (ec) return folder_.string() + ": cannot make the cache folder: " + ec.message();
  const std::filesystem::path path = entryPath(key);
  if (std::string error = writeEntry(path, bytes); !error.empty()) return path.string() + ": " + error;
  trim();
  return "";
}

void DrapeCache::remove(const std::string& key) const {
  std::error_code ignored;  // an entry that is not there is removed already
  std::filesystem::remove(entryPath(key), ignored);
  if (shared_) shared_->remove(sharedName(key));
}

void DrapeCache::trim() const {
  struct Entry {
    std::filesystem::path path;
    std::filesystem::file_time_type used;
    std::uintmax_t size;
  };
  std::vector<Entry> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const auto& file : std::filesystem::directory_iterator(folder_, ec)) {
    if (file.path().extension() != ".drape") continue;
    const std::uintmax_t size = file.file_size(ec);
    if (ec) continue;
    entries.push_back({file.path(), file.last_write_time(ec), size});
    total += size;
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
  for (const Entry& e : entries) {
    if (total <= maxBytes_) break;
    if (std::filesystem::remove(e.path, ec)) total -= e.size;
  }
}

}  // namespace figment

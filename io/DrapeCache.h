#pragma once
// Finished drapes kept on disk, so rendering another view of a scene, or running it
// again, does not simulate again. An entry holds a drape's record (io/DrapeRecord.h: its
// report, positions and sections) as bytes the cache does not read; it is keyed by a text that holds everything
// that shaped the drape (nodes/cloth/DrapeKey.h writes it: every engine input, the
// body, the files they read, the node library's own build); its file is named by two 64-bit
// digests of the key and carries a third, and a checksum of its contents, so a damaged
// or foreign entry is found out and dropped, never used. Entries are written through a
// temporary name; past `maxBytes` the least recently used go first.
//
// With a shared store below it (io/SharedCacheStore.h: figment-serve's Redis), the folder
// is the first level: an entry missing here is looked for there, checked as a file is
// (a damaged or foreign one is dropped from the store too) and copied into the folder;
// a stored entry goes to both.

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace figment {

class SharedCacheStore;

class DrapeCache {
 public:
  DrapeCache(std::filesystem::path folder, std::uintmax_t maxBytes,
             std::shared_ptr<const SharedCacheStore> shared = nullptr);

  // $XDG_CACHE_HOME/figment, else $HOME/.cache/figment; empty when neither is set.
  static std::filesystem::path userFolder();

  const std::filesystem::path& folder() const { return folder_; }
  // The record kept for `key`, if there is a sound entry. A damaged one is removed and
  // `problem` says so (naming the file); otherwise `problem` is left empty.
  std::optional<std::vector<unsigned char>> find(const std::string& key, std::string& problem) const;
  // Keeps `record` under `key`; "" or the error, naming the file or folder.
  std::string store(const std::string& key, const std::vector<unsigned char>& record) const;
  // Removes the entry for `key`, if any: one whose record the engine cannot read (of
  // another version) goes, to be made again.
  void remove(const std::string& key) const;
  // The file an entry for `key` lives in.
  std::filesystem::path entryPath(const std::string& key) const;
  // The name an entry for `key` has in the shared store: "drape:" and its file's stem.
  std::string sharedName(const std::string& key) const;

 private:
  // The entry the shared store holds for `key`, checked and copied into the folder.
  std::optional<std::vector<unsigned char>> findShared(const std::string& key, std::string& problem) const;
  void trim() const;

  std::filesystem::path folder_;
  std::uintmax_t maxBytes_;
  std::shared_ptr<const SharedCacheStore> shared_;  // null: the folder alone
};

}  // namespace figment

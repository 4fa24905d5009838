#include "io/AtomicFile.h"

#include <filesystem>
#include <system_error>
#include <unistd.h>

namespace figment {

std::string writeAtomically(const std::string& path,
                            const std::function<std::string(const std::string& temporaryPath)>& write) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  // The folder is made as needed, so an output may name one that does not exist yet.
  std::error_code made;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), made);
  if (made) return "cannot make the folder " + target.parent_path().string() + ": " + made.message();
  // Same folder, so the rename cannot cross file systems; same extension, so writers
  // that choose the format by extension still see it.
  fs::path temporary = target.parent_path() / ".";
  temporary += target.stem();
  temporary += ".tmp" + std::to_string(::getpid());
  temporary += target.extension();
  std::string error = write(temporary.string());
  std::error_code ec;
  if (error.empty() && !fs::is_regular_file(temporary, ec)) error = "nothing was written";
  if (error.empty()) {
    fs::rename(temporary, target, ec);
    if (ec) error = ec.message();
  }
  if (!error.empty()) fs::remove(temporary, ec);
  return error;
}

}  // namespace figment

#include "io/AtomicFile.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

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

namespace {

// The temporary name beside `target`: hidden, with the process id, so two programs
// writing the same output never share it.
std::filesystem::path temporaryBeside(const std::filesystem::path& target, const std::string& suffix) {
  std::filesystem::path temporary = target.parent_path() / ".";
  temporary += target.stem();
  temporary += ".tmp" + std::to_string(::getpid()) + suffix;
  return temporary;
}

// Moves the files in `folder` beside `target` (named as they are), `target`'s own last;
// "" or the error, with `moved` listing what now lies beside `target`.
std::string moveOut(const std::filesystem::path& folder, const std::filesystem::path& target,
                    std::vector<std::string>& moved) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec))
    if (entry.path().filename() != target.filename()) files.push_back(entry.path());
  if (ec) return ec.message();
  if (!fs::is_regular_file(folder / target.filename(), ec)) return "nothing was written";
  files.push_back(folder / target.filename());
  for (const fs::path& file : files) {
    const fs::path destination = target.parent_path() / file.filename();
    fs::rename(file, destination, ec);
    if (ec) return "cannot move " + file.filename().string() + " into place: " + ec.message();
    moved.push_back(destination.string());
  }
  return "";
}

}  // namespace

std::string writeFilesAtomically(const std::string& path,
                                 const std::function<std::string(const std::string& temporaryPath)>& write,
                                 std::vector<std::string>* written) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
  if (ec) return "cannot make the folder " + target.parent_path().string() + ": " + ec.message();
  const fs::path folder = temporaryBeside(target, ".d");
  fs::remove_all(folder, ec);  // a folder a killed run of this process id left
  if (!fs::create_directory(folder, ec) || ec)
    return "cannot make the temporary folder " + folder.string() + ": " + (ec ? ec.message() : "it exists");
  std::vector<std::string> moved;
  std::string error = write((folder / target.filename()).string());
  if (error.empty()) error = moveOut(folder, target, moved);
  if (!error.empty())
    for (const std::string& file : moved) fs::remove(file, ec);
  fs::remove_all(folder, ec);
  if (error.empty() && written) *written = moved;
  if (error.empty() && written) std::rotate(written->begin(), written->end() - 1, written->end());  // path first
  return error;
}

}  // namespace figment

#pragma once
// Output files that exist only when complete.

#include <functional>
#include <string>
#include <vector>

namespace figment {

// Makes the folder of `path` where it is missing, calls `write` with a temporary path in
// it and renames the result to `path` when `write` returns "" (success). On failure the temporary file is removed,
// `path` is left as it was, and the error is returned.
std::string writeAtomically(const std::string& path,
                            const std::function<std::string(const std::string& temporaryPath)>& write);

// The same for a writer that puts companion files beside its file (an OBJ's .mtl, a
// .gltf's .bin) and names them after it: `write` gets `path`'s file name inside a fresh
// temporary folder next to `path`, so the names it writes into its file are already the
// final ones. When it returns "", every file it made there is moved beside `path`, the
// companions first and `path` last, and `written` (when given) lists them all, `path`
// first. On failure nothing it made is left (a companion it had moved already replaced
// any older file of that name), the folder is removed and the error is returned.
std::string writeFilesAtomically(const std::string& path,
                                 const std::function<std::string(const std::string& temporaryPath)>& write,
                                 std::vector<std::string>* written = nullptr);

}  // namespace figment

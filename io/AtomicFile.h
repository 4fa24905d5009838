#pragma once
// Output files that exist only when complete.

#include <functional>
#include <string>

namespace figment {

// Makes the folder of `path` where it is missing, calls `write` with a temporary path in
// it and renames the result to `path` when `write` returns "" (success). On failure the temporary file is removed,
// `path` is left as it was, and the error is returned.
std::string writeAtomically(const std::string& path,
                            const std::function<std::string(const std::string& temporaryPath)>& write);

}  // namespace figment

#!/usr/bin/env bash
# Fails, naming each file, when a C++ source differs from what clang-format makes of it
# under .clang-format (ctest lint.Formatting; fix with `clang-format -i FILE`).
#   scripts/check-format.sh [ROOT]   (default: the repository root)
set -euo pipefail
cd "${1:-$(dirname "$0")/..}"
command -v clang-format >/dev/null || { echo "check-format: clang-format is not installed (scripts/setup.sh installs it)"; exit 1; }
unformatted=()
while IFS= read -r -d '' file; do
  clang-format --dry-run --Werror "$file" >/dev/null 2>&1 || unformatted+=("$file")
done < <(git ls-files -z '*.cpp' '*.h')
for file in "${unformatted[@]}"; do echo "$file: not as clang-format makes it (clang-format -i $file)"; done
((${#unformatted[@]} == 0))

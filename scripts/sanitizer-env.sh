# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: how the sanitizers report. Absolute
# paths, since the fuzz targets change their working directory.
# shellcheck shell=bash
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# Leaks are checked (LeakSanitizer), with the system libraries' own leaks suppressed one by one.
# Not strict_string_checks: assimp's OBJ parser hands strtol a line buffer with no NUL after it,
# which strict mode reports although strtol stops inside the buffer (ASan's default check, of
# the bytes strtol did read, finds nothing; fuzz_mesh's obj-face-line-unterminated-strtol.seed).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:detect_stack_use_after_return=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$here/tests/sanitize/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=$here/tests/sanitize/ubsan.supp}
unset here

#!/usr/bin/env bash
# Builds one libFuzzer target (tests/fuzz) in build-fuzz and runs it for MINUTES minutes on one
# core, starting from its seed corpus (tests/fuzz/corpus/TARGET), then prints how many inputs
# ran, at what rate, and what it found.
#   scripts/fuzz.sh fuzz_scene 10
#   scripts/fuzz.sh fuzz_mesh 10
#   scripts/fuzz.sh fuzz_render_request 1   (figment-serve's query parser)
#   scripts/fuzz.sh fuzz_pattern 10         (the sewing-pattern reader)
#   scripts/fuzz.sh fuzz_http_exchange 20   (figment-serve's whole HTTP exchange, no workers)
# New interesting inputs go to build-fuzz/corpus/TARGET (kept between runs); a crash, leak,
# timeout or out-of-memory input to build-fuzz/findings/TARGET/. Rerun one input with
#   build-fuzz/bin/TARGET FILE
# Needs scripts/setup.sh's packages, and clang (installed here when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
[ $# -eq 2 ] || { echo "usage: scripts/fuzz.sh fuzz_scene|fuzz_mesh|fuzz_render_request|fuzz_pattern|fuzz_http_exchange MINUTES" >&2; exit 2; }
target=$1 minutes=$2
case "$target" in fuzz_scene | fuzz_mesh | fuzz_render_request | fuzz_pattern | fuzz_http_exchange) ;; *) echo "fuzz.sh: no fuzz target '$target'" >&2; exit 2 ;; esac
[[ "$minutes" =~ ^[0-9]+$ ]] && ((minutes > 0)) || { echo "fuzz.sh: MINUTES must be a whole number > 0" >&2; exit 2; }

source scripts/need-packages.sh
need_packages clang libomp-dev  # libomp: clang's OpenMP, for sim/cloth's implicit solver
source scripts/sanitizer-env.sh

build=build-fuzz
if [ ! -f "$build/CMakeCache.txt" ]; then
  # -O1: the usual trade for fuzzing (fast enough, and sanitizer reports name real lines).
  CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DFIGMENT_SANITIZE=ON -DFIGMENT_BUILD_FUZZERS=ON -DFIGMENT_BUILD_TESTS=OFF -DFIGMENT_BUILD_BENCH=OFF >/dev/null
fi
nice -n 19 cmake --build "$build" -j 2 --target "$target" | { grep -vE '^\[[0-9]+/[0-9]+\] ' || true; }

corpus=$root/$build/corpus/$target findings=$root/$build/findings/$target
mkdir -p "$corpus" "$findings"
log=$root/$build/$target.log
# fuzz_scene's inputs are scenes: 16 KB holds every seed; meshes stay smaller still. -timeout:
# an input past 10 s is a hang (the slowest seed takes well under 1 s). One thread per drape.
# -close_fd_mask=3: the target's own stdout and stderr (Coin's warnings) are dropped; libFuzzer's
# lines and sanitizer reports still reach the log.
max_len=16384
[ "$target" = fuzz_mesh ] && max_len=4096
[ "$target" = fuzz_render_request ] && max_len=1024
# Pattern seeds are small literal patterns and one shipped skirt (6 KB).
[ "$target" = fuzz_pattern ] && max_len=8192
# An exchange's seeds are a few requests; 16 KB also passes the service's 8 KB limits on a URL,
# a header line and a body (414, 400, 413).
# A target's dictionary of tokens, where it has one (tests/fuzz/TARGET.dict).
dict=()
[ -f "tests/fuzz/$target.dict" ] && dict=(-dict="$root/tests/fuzz/$target.dict")
echo "fuzz.sh: running $target for $minutes min (log: $build/$target.log)" >&2
set +e
start=$SECONDS
# softpipe: Mesa's plain software rasterizer draws a 48x48 image in half llvmpipe's time (no
# shader compiling); the GL calls our nodes make are the same.
GALLIUM_DRIVER=softpipe OMP_NUM_THREADS=1 nice -n 19 "$build/bin/$target" "$corpus" "$root/tests/fuzz/corpus/$target" \
  -max_total_time=$((minutes * 60)) -max_len=$max_len -timeout=10 -rss_limit_mb=4096 \
  -artifact_prefix="$findings/" -print_final_stats=1 -close_fd_mask=3 "${dict[@]}" >"$log" 2>&1
status=$?
set -e
executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
# A slow unit (libFuzzer's slow-unit-*, over 10 s) is not a crash: on a shared machine a niced
# fuzzer left without a core writes them (one of 22 s ran in 0.6 s alone, 2026-12-03). Rerun
# each alone before calling it a hang; the others (crash-, leak-, timeout-, oom-) are findings.
found=$(find "$findings" -type f ! -name 'slow-unit-*' | wc -l)
slow=$(find "$findings" -type f -name 'slow-unit-*' | wc -l)
echo "fuzz.sh: $target: ${executions:-?} executions in $((SECONDS - start)) s (${rate:-?}/s), exit $status," \
  "$found finding(s) and $slow slow unit(s) in $build/findings/$target"
grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | head -5 || true
[ "$status" -eq 0 ] && [ "$found" -eq 0 ]

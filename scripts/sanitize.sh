#!/usr/bin/env bash
# The sanitizer job, run by `.ci/run sanitize` on a machine of its own (needs scripts/setup.sh's packages):
#   asan  every test module and program built with AddressSanitizer + UndefinedBehaviorSanitizer
#         (FIGMENT_SANITIZE, cmake/FigmentSanitize.cmake) in build-asan, and every test ctest
#         registers there run, the service's Python scenarios included: they start that tree's
#         sanitized figment-serve. Left out: tests/sanitize/left-out.txt, each with why.
#   tsan  the service's library and test_serve built with ThreadSanitizer
#         (FIGMENT_SANITIZE_THREAD) in build-tsan, and test_serve's threaded units run: the
#         worker pool, the job queue and its workers, the HTTP service, the shared caches.
#   scripts/sanitize.sh [asan|tsan]...   (none: both)
# For a part of it: FIGMENT_SANITIZE_TARGETS='figment-serve figment-precompute test_serve' (what
# the asan job builds; all by default) and FIGMENT_SANITIZE_LABELS=serve (a ctest -L expression);
# FIGMENT_SANITIZE_EXCLUDE='' runs the left-out tests too.
# A sanitizer report fails the test it comes from (halt_on_error, -fno-sanitize-recover).
#
# Why -O1 -g1 (not the Release flags): the sanitized trees are built for their reports, not for
# their pictures; -O1 compiles in two thirds of -O2's time and keeps the reports' lines (one
# batch, sim/collision's first: 35 CPU-s at -O1, 52 at -O2, 12 in Release; the sanitizers'
# instrumentation of Eigen's inlined code is most of it). NDEBUG as in Release, so the same
# code is checked.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=("$@")
((${#jobs[@]})) || jobs=(asan tsan)
source scripts/sanitizer-env.sh  # also during the build: test discovery runs the tests
flags="-O1 -g1 -DNDEBUG"

configure() {  # BUILD_DIR OPTION...
  local build=$1
  shift
  [ -f "$build/CMakeCache.txt" ] && return
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="$flags" -DFIGMENT_BUILD_TESTS=ON -DFIGMENT_BUILD_SERVICE=ON "$@" >/dev/null
}
quiet() { grep -vE '^\[[0-9]+/[0-9]+\] ' || true; }

for job in "${jobs[@]}"; do
  case "$job" in
  asan)
    build=${FIGMENT_ASAN_BUILD_DIR:-build-asan}
    configure "$build" -DFIGMENT_SANITIZE=ON -DFIGMENT_BUILD_BENCH=ON
    # MakeHuman's body model where this build looks for it; Schemathesis's venv is the normal
    # build's (scripts/setup.sh), which serve.Contract looks for in its own tree.
    python3 scripts/fetch-makehuman.py "$build/data/makehuman"
    [ -e "$build/contract-venv" ] || ln -s "$PWD/${FIGMENT_BUILD_DIR:-build}/contract-venv" "$build/contract-venv"
    read -ra targets <<<"${FIGMENT_SANITIZE_TARGETS:-}"
    cmake --build "$build" -j "$(scripts/cores.sh)" ${targets[@]:+--target "${targets[@]}"} | quiet
    exclude=${FIGMENT_SANITIZE_EXCLUDE-$(grep -v '^#' tests/sanitize/left-out.txt | cut -f1 | paste -sd'|')}
    labels=${FIGMENT_SANITIZE_LABELS:-}
    # One implicit-solver thread per test (every test's environment): tests run side by side.
    # The service's scenarios start their servers with a render limit of 10 minutes instead of
    # 60 s (ServeSupport.time_limited): under the sanitizers a drape of theirs took past 60 s
    # and was answered 504 (serve.Service, the job's first run).
    FIGMENT_SERVE_TIME_LIMIT=${FIGMENT_SERVE_TIME_LIMIT:-600} ctest --test-dir "$build" ${labels:+-L "$labels"} ${exclude:+-E "$exclude"} -j "$(scripts/cores.sh)" \
      --output-on-failure --timeout 900
    ;;
  tsan)
    build=${FIGMENT_TSAN_BUILD_DIR:-build-tsan}
    configure "$build" -DFIGMENT_SANITIZE_THREAD=ON -DFIGMENT_BUILD_BENCH=OFF
    python3 scripts/fetch-makehuman.py "$build/data/makehuman"  # FitWorkerTest's bodies
    cmake --build "$build" -j "$(scripts/cores.sh)" --target test_serve | quiet
    # The units whose code runs on more than one thread (serve/workers, serve/http); the
    # service's other units are single-threaded parsing, checked under ASan above. 1800 s:
    # a FitWorker unit draping an advice's sizes side by side took 767 s alone under TSan and
    # ran past 900 s beside another (2026-12-03).
    TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1} \
      ctest --test-dir "$build" -L '^serve$' -R '^(WorkerPool|JobQueue|HttpService|ClientRateLimit|ImageCache|SharedImages|RedisConnection|FitWorker)' \
      -j "$(scripts/cores.sh)" --output-on-failure --timeout 1800
    ;;
  *)
    echo "sanitize.sh: $job: not asan or tsan" >&2
    exit 2
    ;;
  esac
done

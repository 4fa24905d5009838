#!/usr/bin/env bash
# The sanitizer job: test_nodes built with AddressSanitizer and UndefinedBehaviorSanitizer
# (FIGMENT_SANITIZE, cmake/FigmentSanitize.cmake) in build-asan, and its tests run; a sanitizer
# report fails the test it comes from. Run by .ci/run after the normal suite; needs
# scripts/setup.sh's packages (run it first).
#
# Why test_nodes: it drives the node kit (reading, read errors, bad fields, draping, collision
# bodies, the hybrid renderer's nodes) and through it most of sim/ and io/, and it fits CI's
# 20 minutes on 2 cores beside the normal suite (building it with the sanitizers takes about
# 600 CPU-seconds). test_sim as well roughly doubles the build (its ~40 test files and
# sim/volumes), past the limit; run both where time allows:
#   FIGMENT_SANITIZE_LABELS='^(sim|nodes)$' scripts/sanitize.sh
# (a ctest -L regular expression over the test modules: sim, io, nodes, viewer, headless, scenes).
set -euo pipefail
cd "$(dirname "$0")/.."
labels=${FIGMENT_SANITIZE_LABELS:-'^nodes$'}
source scripts/sanitizer-env.sh  # also during the build: test discovery runs the tests

build=${FIGMENT_ASAN_BUILD_DIR:-build-asan}
if [ ! -f "$build/CMakeCache.txt" ]; then
  # -O2 with line tables: the suite runs at about a third of its Release speed and reports
  # name lines. NDEBUG as in Release, so the same code is tested.
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
    -DFIGMENT_SANITIZE=ON -DFIGMENT_BUILD_BENCH=OFF >/dev/null
fi
# MakeHuman's body model where this build looks for it (the scenes with a HumanBody need it).
python3 scripts/fetch-makehuman.py "$build/data/makehuman"
targets=()
[[ "sim" =~ $labels ]] && targets+=(test_sim)
[[ "nodes" =~ $labels ]] && targets+=(test_nodes)
[[ "io" =~ $labels ]] && targets+=(test_io)
[[ "viewer" =~ $labels ]] && targets+=(test_viewer)
[[ "headless" =~ $labels ]] && targets+=(test_headless)
[[ "scenes" =~ $labels ]] && targets+=(test_scenes)
((${#targets[@]})) || { echo "sanitize.sh: no test module matches '$labels'" >&2; exit 2; }
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}" | { grep -vE '^\[[0-9]+/[0-9]+\] ' || true; }
# Whole-garment drapes that take minutes under the sanitizers (1-7 s in Release): their code runs
# in the job's shorter drapes. FIGMENT_SANITIZE_EXCLUDE='' runs them too.
exclude=${FIGMENT_SANITIZE_EXCLUDE-'SkirtUnderLimiters|ProgressiveClothEngine.TheDressSplitAllAtOnce|ToleranceEngine.DrapesByTheFastest|ToleranceEngineCommittedTable|LayeredGarments.TheSkirtOverTheTShirtsHem'}
# One implicit-solver thread per test: the tests run side by side instead.
OMP_NUM_THREADS=1 ctest --test-dir "$build" -L "$labels" ${exclude:+-E "$exclude"} -j "$(nproc)" \
  --output-on-failure --timeout 600

#!/usr/bin/env bash
# A compiler or linker launcher that measures each step's CPU time (user + system seconds, not
# wall time: the machine may be shared) and appends "output user sys" to $FIGMENT_CPU_LOG
# (docs/results.md, "CI in 20 minutes"). For a measurement build:
#   FIGMENT_CPU_LOG=$PWD/cpu.log cmake -S . -B build-cold -G Ninja ... \
#     -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/scripts/cpu-time-launcher.sh \
#     -DCMAKE_CXX_LINKER_LAUNCHER=$PWD/scripts/cpu-time-launcher.sh
#   FIGMENT_CPU_LOG=$PWD/cpu.log cmake --build build-cold
#   python3 scripts/build-cpu-report.py cpu.log
set -uo pipefail
out=?
args=("$@")
for ((i = 0; i < ${#args[@]} - 1; i++)); do
  [ "${args[i]}" = -o ] && out=${args[i + 1]}
done
log=${FIGMENT_CPU_LOG:-/dev/null}
stats=$(mktemp)
/usr/bin/time -f '%U %S' -o "$stats" "$@"
status=$?
echo "$out $(tail -n 1 "$stats")" >>"$log"
rm -f "$stats"
exit $status

#!/usr/bin/env bash
# figment-serve under load on loopback (docs/service.md, "Figures"): cold requests (a new
# body each, one garment, 800x600) one after another on one worker, their median and 95th
# percentile, on the Mannequin and on bodies made to measurements; another view of a draped outfit; then a cached image's requests/s and
# latency with wrk (Debian's). Medians, not a test: the figures go into docs/service.md.
# Last, an overload: wrk asks for a new body on every request (bench/serve-overload.lua),
# far past what the workers drape, for OVERLOAD_SECONDS; the answers by status, and the
# server's and workers' resident memory before and after.
#   bench/serve-load.sh [BUILD_DIR] [COLD_REQUESTS] [WRK_SECONDS] [OVERLOAD_SECONDS]
set -euo pipefail
build=${1:-build}
cold=${2:-10}
seconds=${3:-10}
overload=${4:-60}
work=$(mktemp -d)
trap 'kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$work"' EXIT

"$build/bin/figment-serve" --port 0 --workers 1 --rate 0 --cache "$work/cache" >"$work/out" 2>"$work/err" &
server=$!
until grep -q http:// "$work/out"; do sleep 0.1; done
url=$(grep -o 'http://[^ ]*' "$work/out")
curl -s -o /dev/null "${url}healthz"

median() { sort -n | awk '{v[NR]=$1} END {p=int((NR+1)/2); q=int(NR*0.95+0.999); print "p50 " v[p] " s, p95 " v[q] " s (" NR " requests)"}'; }

echo "cold (new body, dress, 800x600, one worker):"
for i in $(seq 1 "$cold"); do
  curl -s -o /dev/null -w '%{time_total}\n' "${url}api/render?stature=$(printf '1.%03d' $((600 + i)))&outfit=dress:M"
done | median
echo "cold, a body made to measurements (sex=female, new stature each, dress M, 800x600):"
for i in $(seq 1 "$cold"); do
  curl -s -o /dev/null -w '%{time_total}\n' \
    "${url}api/render?sex=female&stature=$(printf '1.%03d' $((640 + i)))&bust=0.88&waist=0.72&hips=0.97&outfit=dress:M"
done | median
echo "another view of the outfit just draped (the worker keeps its scene):"
for i in $(seq 1 "$cold"); do
  curl -s -o /dev/null -w '%{time_total}\n' "${url}api/render?stature=$(printf '1.%03d' $((600 + cold)))&outfit=dress:M&view=$((10 * i)),10"
done | median
echo "another view of an outfit draped before (its drape from the drape cache):"
for i in $(seq 1 "$cold"); do
  curl -s -o /dev/null -w '%{time_total}\n' "${url}api/render?stature=$(printf '1.%03d' $((600 + i)))&outfit=dress:M&view=$((10 * i)),10"
done | median
echo "a cached image (wrk, 2 threads, 32 connections, ${seconds} s):"
curl -s -o /dev/null "${url}api/render?stature=1.601&outfit=dress:M"
wrk -t2 -c32 -d"${seconds}s" --latency "${url}api/render?stature=1.601&outfit=dress:M" | grep -E 'Requests/sec|50%|99%|Non-2xx'
memory() {
  echo "server resident memory: $(awk '/VmRSS/ {print $2 " kB"}' /proc/$server/status)"
  for child in $(cat /proc/$server/task/*/children); do
    echo "worker $child resident memory: $(awk '/VmRSS/ {print $2 " kB"}' /proc/$child/status)"
  done
}
memory
echo "overload (a new body on every request, 2 threads, 64 connections, ${overload} s):"
wrk -t2 -c64 -d"${overload}s" --timeout 120s -s "$(dirname "$0")/serve-overload.lua" "$url" |
  grep -E 'Requests/sec|status|Socket errors'
kill -0 "$server" && echo "the server still runs; healthz: $(curl -s "${url}healthz")"
memory

#!/usr/bin/env bash
# Cold-request throughput of figment-serve with one render worker against two (docs/service.md,
# "Figures"; the issue's aim: two at least 1.7 times one). Each run starts its own server on a
# free loopback port with an empty drape cache and sends REQUESTS cold requests (a new
# Mannequin body each: one garment, 800x600) four at a time, so every worker always has
# one waiting; prints requests/s for each and the ratio. Wants idle cores: one per worker.
#   bench/serve-workers.sh [BUILD_DIR] [REQUESTS]
set -euo pipefail
build=${1:-build}
requests=${2:-24}
work=$(mktemp -d)
server=
trap '[ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"' EXIT

# Requests/s of `requests` cold requests on a fresh server with $1 workers, its own empty
# drape cache, and the same statures for every run (taller bodies drape longer).
throughput() {
  "$build/bin/figment-serve" --port 0 --workers "$1" --rate 0 --cache "$work/cache-$1" >"$work/out-$1" 2>"$work/err-$1" &
  server=$!
  until grep -q http:// "$work/out-$1"; do sleep 0.1; done
  local url
  url=$(grep -o 'http://[^ ]*' "$work/out-$1")
  curl -s -o /dev/null "${url}healthz"
  sleep 2  # the workers start after the server answers: time the drapes, not the start
  local start end
  start=$(date +%s.%N)
  seq 1 "$requests" | xargs -P 4 -I{} sh -c \
    "curl -s -o /dev/null -w '%{http_code}\n' '${url}api/render?stature='\$(printf '1.%03d' \$(( 600 + {} )))'&outfit=dress:M'" \
    >"$work/codes-$1"
  end=$(date +%s.%N)
  kill "$server"
  wait "$server" 2>/dev/null || true
  server=
  if grep -qv '^200$' "$work/codes-$1"; then
    echo "serve-workers: $(grep -cv '^200$' "$work/codes-$1") of $requests requests did not answer 200" >&2
    exit 1
  fi
  echo "$requests $start $end" | awk '{printf "%.2f", $1 / ($3 - $2)}'
}

one=$(throughput 1)
two=$(throughput 2)
echo "cold requests, one worker: $one requests/s; two workers: $two requests/s; ratio $(echo "$one $two" | awk '{printf "%.2f", $2 / $1}')"

#!/usr/bin/env bash
# A shopper's journey through figment-serve on loopback (docs/service.md, "The shopper's
# journey"): for each of SHOPPERS new bodies (made to measurements, women's), the first
# picture (one garment, cold caches), an outfit of two layers, the size advice for one
# style (three sizes draped), the advice for another style on the same body, the picture
# of each advised size, and another view; then a cached picture's requests/s with wrk
# (Debian's). The server runs WORKERS workers (2: one core each on this machine), with
# OMP_NUM_THREADS=1. Medians and 95th percentiles, not a test: the figures go into
# docs/service.md.
# ADVICE_THREADS: each worker's --advice-threads (default: the server's, one per core).
#   bench/serve-journey.sh [BUILD_DIR] [SHOPPERS] [WORKERS] [WRK_SECONDS] [ADVICE_THREADS]
set -euo pipefail
build=${1:-build}
shoppers=${2:-6}
workers=${3:-2}
seconds=${4:-10}
threads=(${5:+--advice-threads "$5"})
work=$(mktemp -d)
trap 'kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$work"' EXIT

OMP_NUM_THREADS=1 "$build/bin/figment-serve" --port 0 --workers "$workers" --rate 0 --cache "$work/cache" "${threads[@]}" \
  >"$work/out" 2>"$work/err" &
server=$!
until grep -q http:// "$work/out"; do sleep 0.1; done
url=$(grep -o 'http://[^ ]*' "$work/out")
curl -s -o /dev/null "${url}healthz"

# The seconds one request took, and its cache header, appended to FILE.
timed() {
  local file=$1 path=$2
  curl -s -o /dev/null -D "$work/headers" -w '%{time_total}' "${url}${path}" >>"$file"
  echo " $(tr -d '\r' <"$work/headers" | awk -F': ' 'tolower($1) == "x-figment-cache" {print $2}')" >>"$file"
}
summary() {
  sort -n "$1" | awk -v what="$2" '{v[NR]=$1; if ($2 == "hit") h++}
    END {p=int((NR+1)/2); q=int(NR*0.95+0.999); printf "%-58s p50 %.3f s, p95 %.3f s (%d requests, %d cache hits)\n", what, v[p], v[q], NR, h}'
}

for i in $(seq 1 "$shoppers"); do
  # A body between the chart's sizes, another each time: nothing of it is cached.
  body="sex=female&stature=$(printf '1.%03d' $((640 + 7 * i)))&bust=0.$((86 + i))&waist=0.$((70 + i))&hips=$(printf '%d.%02d' $(((94 + 2 * i) / 100)) $(((94 + 2 * i) % 100)))"
  timed "$work/first" "api/render?${body}&outfit=dress:M&size=480x640"
  timed "$work/layers" "api/render?${body}&outfit=tshirt:M,skirt:M&size=480x640"
  advice=$(curl -s -o "$work/advice.json" -w '%{time_total} %{http_code}' "${url}api/fit?${body}&style=dress")
  [ "${advice#* }" = 200 ] || { echo "advice for ${body}: ${advice#* } $(cat "$work/advice.json")" >&2; exit 1; }
  echo "${advice% *}" >>"$work/fit"
  timed "$work/fit-other" "api/fit?${body}&style=pencil"
  for size in $(python3 -c "import json; print(' '.join(json.load(open('$work/advice.json'))['sizes']))"); do
    timed "$work/advised" "api/render?${body}&outfit=dress:${size}&size=480x640"
  done
  timed "$work/view" "api/render?${body}&outfit=dress:M&size=480x640&view=90,5"
done

summary "$work/first" "first picture (new body, dress M, 480x640):"
summary "$work/layers" "two layers (tshirt M under skirt M), same body:"
summary "$work/fit" "size advice, dress, 3 sizes (the first: a new worker):"
summary "$work/fit-other" "size advice, another style (pencil), same body:"
summary "$work/advised" "picture of an advised size, after the advice:"
summary "$work/view" "another view of a picture made:"
echo "a cached picture (wrk, 2 threads, 32 connections, ${seconds} s):"
curl -s -o /dev/null "${url}api/render?stature=1.700&outfit=dress:M&size=480x640"
wrk -t2 -c32 -d"${seconds}s" --latency "${url}api/render?stature=1.700&outfit=dress:M&size=480x640" |
  grep -E 'Requests/sec|50%|99%|Non-2xx'

#!/usr/bin/env bash
# figment-serve past one machine (docs/deploy.md, "Capacity"): a Redis of its own on a Unix
# socket and everything else on 127.0.0.1, in a temporary folder, stopped at the end.
#   1. precompute throughput: JOBS cold jobs (a new body each, the dress, 400x300) rendered
#      by one job worker, then (Redis emptied, fresh drape caches) by two;
#   2. Redis's memory per cached image and per drape (MEMORY USAGE, mean over the keys);
#   3. requests/s of one instance with one render worker (one core renders) for cold (a new
#      body each), warm (another view of a draped outfit) and cached (one image) requests;
#   4. through nginx (Debian's): a cached image and cold requests on one instance, then two.
# Medians are wrk's; figures, not a test. Each wrk run lasts WRK_SECONDS.
#   bench/redis-load.sh [BUILD_DIR] [JOBS] [WRK_SECONDS]
set -euo pipefail
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg); cores: $(getconf _NPROCESSORS_ONLN)"
build=$(realpath "${1:-build}")
jobs=${2:-24}
seconds=${3:-10}
here=$(dirname "$(realpath "$0")")
work=$(mktemp -d /tmp/figment-bench-XXXXXX)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
serve=$build/bin/figment-serve
precompute=$build/bin/figment-precompute

redis-server --port 0 --unixsocket "$work/redis.sock" --dir "$work" --save "" --appendonly no \
  --maxmemory 2gb --maxmemory-policy volatile-lru --logfile "$work/redis.log" &
pids+=($!)
until redis-cli -s "$work/redis.sock" ping >/dev/null 2>&1; do sleep 0.1; done
redis="$work/redis.sock"
rcli() { redis-cli -s "$redis" "$@"; }

for i in $(seq 1 "$jobs"); do
  printf 'stature=%.3f&outfit=dress:M&size=400x300\n' "$(echo "1.500 + 0.007 * $i" | bc)"
done >"$work/jobs.txt"

# CPU seconds (user + system) the render workers of the given processes have used: what a
# job or request costs a core, whatever else the machine runs.
render_cpu() {
  local total=0 pid child
  for pid in "$@"; do
    for child in $(cat /proc/"$pid"/task/*/children 2>/dev/null); do
      total=$((total + $(awk '{print $14 + $15}' /proc/"$child"/stat)))
    done
  done
  echo "scale=2; $total / $(getconf CLK_TCK)" | bc
}

# Runs the jobs on N job workers (one render worker each, fresh drape caches); jobs/s,
# timed from when the workers have done a first job each (started, the wardrobe read).
precompute_rate() {
  local n=$1 started workers=()
  rcli flushall >/dev/null
  for w in $(seq 1 "$n"); do
    "$serve" --job-worker --redis "$redis" --workers 1 --consumer "bench-$n-$w" --cache "$work/cache-$n-$w" \
      >/dev/null 2>>"$work/workers.log" &
    workers+=($!)
    pids+=($!)
  done
  for w in $(seq 1 "$n"); do printf 'stature=1.%03d&outfit=skirt:S&size=64x80\n' $((500 + w)); done >"$work/warm.txt"
  "$precompute" --redis "$redis" --requests "$work/warm.txt" >/dev/null
  "$precompute" --redis "$redis" --status --wait 3600 >/dev/null
  started=$(date +%s.%N)
  local cpu elapsed
  cpu=$(render_cpu "${workers[@]}")
  "$precompute" --redis "$redis" --requests "$work/jobs.txt" >/dev/null
  "$precompute" --redis "$redis" --status --wait 3600 >"$work/status"
  elapsed=$(echo "$(date +%s.%N) - $started" | bc)
  cpu=$(echo "$(render_cpu "${workers[@]}") - $cpu" | bc)
  kill "${workers[@]}"
  wait "${workers[@]}" 2>/dev/null || true
  echo "$n job worker(s): $jobs jobs in ${elapsed} s: $(echo "scale=2; $jobs / $elapsed" | bc) jobs/s;" \
    "render CPU $(echo "scale=3; $cpu / $jobs" | bc) s a job; $(head -1 "$work/status")"
}
echo "== precompute throughput (cold jobs: a new body each)"
precompute_rate 1
precompute_rate 2

echo "== Redis memory per entry"
mean_usage() {
  rcli --scan --pattern "$1" | while read -r key; do rcli memory usage "$key" samples 0; done |
    awk -v what="$2" '{s += $1; n++} END {if (n) printf "%s: %d keys, mean %.0f bytes\n", what, n, s / n}'
}
mean_usage 'figment:image:*' "image (400x300 PNG)"
mean_usage 'figment:drape:*' "drape (the dress)"
echo "used_memory after $jobs jobs: $(rcli info memory | awk -F: '/^used_memory:/ {print $2}' | tr -d '\r') bytes"

# An instance on a free port; its URL in the variable named $1.
start_instance() {
  local log=$work/instance-$1.out
  "$serve" --port 0 --workers 1 --rate 0 --redis "$redis" --cache "$work/icache-$1" >"$log" 2>>"$work/instances.log" &
  pids+=($!)
  until grep -q http:// "$log"; do sleep 0.1; done
  printf -v "$1" '%s' "$(grep -o 'http://[^ ]*' "$log")"
}
rps() { grep -E 'Requests/sec|Non-2xx' | tr -s ' ' | tr '\n' ' '; echo; }

echo "== one instance, one render worker (wrk, 2 threads, 4 connections; cached: 32 connections)"
start_instance a
url=$a
# wrk on one instance, with the render CPU a request cost (its worker's CPU over the requests).
measured() {
  local name=$1 cpu out
  shift
  cpu=$(render_cpu "$instance")
  out=$(wrk "$@" | grep -E 'requests in|Requests/sec|Non-2xx')
  cpu=$(echo "$(render_cpu "$instance") - $cpu" | bc)
  local n
  n=$(echo "$out" | awk '/requests in/ {print $1}')
  echo "$name $(echo "$out" | grep -v 'requests in' | tr -s ' ' | tr '\n' ' ') render CPU $(echo "scale=4; $cpu / $n" | bc) s a request"
}
instance=${pids[-1]}
measured "cold:  " -t2 -c4 -d"${seconds}s" --timeout 60s -s "$here/serve-overload.lua" "$url"
curl -s -o /dev/null "${url}api/render?stature=1.650&outfit=dress:M&size=400x300"
measured "warm:  " -t2 -c4 -d"${seconds}s" --timeout 60s -s "$here/serve-views.lua" "$url"
server_cpu() { echo "scale=2; $(awk '{print $14 + $15}' /proc/"$1"/stat) / $(getconf CLK_TCK)" | bc; }
cpu=$(server_cpu "$instance")
out=$(wrk -t2 -c32 -d"${seconds}s" --latency "${url}api/render?stature=1.650&outfit=dress:M&size=400x300")
cpu=$(echo "$(server_cpu "$instance") - $cpu" | bc)
echo "cached: $(echo "$out" | grep -E 'Requests/sec|Non-2xx| 50%| 99%' | tr -s ' ' | tr '\n' ' ')" \
  "server CPU $(echo "scale=6; $cpu / $(echo "$out" | awk '/requests in/ {print $1}')" | bc) s a request"
tag=$(curl -s -D - -o /dev/null "${url}api/render?stature=1.650&outfit=dress:M" | tr -d '\r"' | awk -F': ' 'tolower($1) == "etag" {print $2}')
echo "an 800x600 image in Redis: $(rcli memory usage "figment:image:$tag" samples 0) bytes"

# nginx on a free loopback port before the given instances (deploy/nginx.conf, rate limit
# off); its URL in the variable named $1.
start_nginx() {
  local name=$1 folder=$work/nginx-$1 port
  shift
  mkdir -p "$folder"
  port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
  sed -e '/limit_req/d' -e '/server 10\.0\.0\./d' -e "s|listen 80;|listen 127.0.0.1:$port;|" \
    -e "s|least_conn;|least_conn;$(for a in "$@"; do printf '\\n    server %s;' "$a"; done)|" \
    "$here/../deploy/nginx.conf" >"$folder/site.conf"
  cat >"$folder/nginx.conf" <<CONF
daemon off; worker_processes 2; pid $folder/nginx.pid; error_log $folder/error.log;
events { worker_connections 1024; }
http { access_log off; proxy_max_temp_file_size 0; client_body_temp_path $folder/b; proxy_temp_path $folder/p; fastcgi_temp_path $folder/f;
       uwsgi_temp_path $folder/u; scgi_temp_path $folder/s; include $folder/site.conf; }
CONF
  nginx -e "$folder/error.log" -p "$folder" -c "$folder/nginx.conf" >/dev/null 2>&1 &
  pids+=($!)
  until curl -s -o /dev/null "http://127.0.0.1:$port/healthz"; do sleep 0.1; done
  printf -v "$name" '%s' "http://127.0.0.1:$port/"
}
echo "== through nginx"
start_instance b
strip() { echo "$1" | sed -e 's|http://||' -e 's|/$||'; }
start_nginx one "$(strip "$a")"
start_nginx two "$(strip "$a")" "$(strip "$b")"
for lb in one two; do
  target=${!lb}
  curl -s -o /dev/null "${target}api/render?stature=1.650&outfit=dress:M&size=400x300"
  echo "$lb instance(s), cached: $(wrk -t2 -c32 -d"${seconds}s" "${target}api/render?stature=1.650&outfit=dress:M&size=400x300" | rps)"
  echo "$lb instance(s), cold:   $(wrk -t2 -c4 -d"${seconds}s" --timeout 60s -s "$here/serve-overload.lua" "$target" | rps)"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); cores: $(getconf _NPROCESSORS_ONLN)"

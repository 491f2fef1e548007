#!/usr/bin/env bash
# Soak test of locatord, bounded in time. Starts locatord on a generated
# dataset, re-tuning every few seconds (--retune-interval-s), and drives it
# with three locator-load processes at once: unary calls (1-cluster), 2000-
# point LocateBatch calls (uniform) and LocateStream streams (drift, so the
# tuner keeps re-learning). Every SAMPLE_S seconds it prints the server's
# resident memory (VmRSS); at the end it prints the RSS after warm-up and at
# the end, throughput and errors of each load and the queries the server
# counted.
#
# Exits 1 if any call failed, a load or the server died, the server did not
# exit 0 on SIGTERM, or RSS grew by 5% or more after warm-up; 2 on usage
# errors. Needs a built tree (cmake --build build).
#
# Usage: deploy/soak.sh [--duration SECONDS] [--warmup SECONDS]
# Environment: BUILD_DIR (build), SOAK_DURATION (600), SOAK_WARMUP
# (duration / 6, at least 10), SOAK_DATASET (uniform:200000:7), SAMPLE_S (5).
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR="${BUILD_DIR:-build}"
DURATION="${SOAK_DURATION:-600}"
WARMUP="${SOAK_WARMUP:-}"
DATASET="${SOAK_DATASET:-uniform:200000:7}"
SAMPLE_S="${SAMPLE_S:-5}"
MAX_GROWTH_PERCENT=5

usage() { echo "usage: deploy/soak.sh [--duration SECONDS] [--warmup SECONDS]"; }
while [ $# -gt 0 ]; do
  case "$1" in
    --duration) DURATION="${2:-}"; shift 2 ;;
    --warmup) WARMUP="${2:-}"; shift 2 ;;
    -h | --help) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
done
WARMUP="${WARMUP:-$((DURATION / 6 > 10 ? DURATION / 6 : 10))}"
if ! [[ "$DURATION" =~ ^[0-9]+$ && "$WARMUP" =~ ^[0-9]+$ ]] ||
  [ "$WARMUP" -ge "$DURATION" ]; then
  echo "soak: --duration and --warmup must be whole seconds," \
    "warm-up shorter than the duration" >&2
  exit 2
fi

LOCATORD="$BUILD_DIR/server/locatord"
LOCATOR="$BUILD_DIR/client/locator"
LOAD="$BUILD_DIR/client/locator-load"
for bin in "$LOCATORD" "$LOCATOR" "$LOAD"; do
  [ -x "$bin" ] || { echo "soak: $bin not built" >&2; exit 2; }
done

tmp=$(mktemp -d)
server=""
loads=()
cleanup() {
  kill -TERM ${server:+"$server"} "${loads[@]}" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

"$LOCATORD" --dataset "$DATASET" --listen 127.0.0.1:0 --retune-interval-s 3 \
  > "$tmp/locatord.log" 2>&1 &
server=$!
port=""
until [ -n "$port" ]; do
  kill -0 "$server" 2>/dev/null || { cat "$tmp/locatord.log" >&2; exit 1; }
  sleep 0.1
  port=$(sed -n 's/^locatord listening on .*:\([0-9]*\)$/\1/p' \
    "$tmp/locatord.log")
done
target="127.0.0.1:$port"
until "$LOCATOR" --target "$target" health > /dev/null 2>&1; do
  kill -0 "$server" 2>/dev/null || { cat "$tmp/locatord.log" >&2; exit 1; }
  sleep 0.5
done
echo "soak: locatord (pid $server) on $target serving $DATASET;" \
  "${DURATION}s of load, the first ${WARMUP}s warm-up"

# load NAME FLAGS...: one locator-load process for the whole run.
load() {
  "$LOAD" --target "$target" --warmup "$WARMUP" \
    --duration $((DURATION - WARMUP)) --cost-window 1000000 --format json \
    "${@:2}" > "$tmp/$1.json" 2> "$tmp/$1.err" &
  loads+=($!)
}
load unary --mode unary --workload 1-cluster --concurrency 16
load batch --mode batch --workload uniform --batch-size 2000 --concurrency 2
load stream --mode stream --workload drift --concurrency 2 --window 16

# "QUERIES_SERVED RETUNE_COUNT" from the server's GetStats.
server_counts() {
  "$LOCATOR" --target "$target" --json stats | python3 -c 'import json, sys
d = json.load(sys.stdin)
print(d["queries_served"], d["tuning"]["retune_count"])'
}
rss_kib() { awk '/^VmRSS:/ {print $2}' "/proc/$server/status"; }

start=$SECONDS
baseline="" counts_at_baseline="" rss="" t=0
while kill -0 "${loads[@]}" 2>/dev/null; do
  kill -0 "$server" 2>/dev/null || { echo "soak: locatord died" >&2; exit 1; }
  t=$((SECONDS - start))
  rss=$(rss_kib)
  echo "soak: t=${t}s rss=$((rss / 1024)) MiB"
  if [ -z "$baseline" ] && [ "$t" -ge "$WARMUP" ]; then
    baseline=$rss
    counts_at_baseline=$(server_counts)
  fi
  sleep "$SAMPLE_S"
done
[ -n "$baseline" ] || { echo "soak: the loads ended during warm-up" >&2; exit 1; }
status=0
for pid in "${loads[@]}"; do wait "$pid" || status=1; done
loads=()
counts_at_end=$(server_counts)
end_rss=$(rss_kib)
measured=$((SECONDS - start - WARMUP))
kill -TERM "$server"
server_exit=0
wait "$server" || server_exit=$?
server=""

python3 - "$tmp" "$baseline" "$end_rss" "$counts_at_baseline" \
  "$counts_at_end" "$measured" "$server_exit" "$status" \
  "$MAX_GROWTH_PERCENT" <<'PY'
import json, sys
(tmp, base, end, counts0, counts1, seconds, server_exit, load_status,
 max_growth) = sys.argv[1:]
(served0, retunes0), (served1, retunes1) = counts0.split(), counts1.split()
failed = 0
for name in ["unary", "batch", "stream"]:
    try:
        r = json.load(open(f"{tmp}/{name}.json"))
    except ValueError:
        print(f"soak: {name}: no report;", open(f"{tmp}/{name}.err").read())
        failed += 1
        continue
    failed += r["failed_calls"]
    print(f"soak: {name:6} {r['calls_per_second']:10.1f} calls/s "
          f"{r['points_per_second']:12.1f} points/s  p99 "
          f"{r['latency_us']['p99'] / 1000:.2f} ms  failed "
          f"{r['failed_calls']} {r['errors'] or ''}")
growth = 100.0 * (int(end) - int(base)) / int(base)
served = int(served1) - int(served0)
print(f"soak: server  {served} queries in {seconds} s after warm-up "
      f"({served / max(int(seconds), 1):.0f} queries/s), "
      f"{int(retunes1) - int(retunes0)} re-tunes")
print(f"soak: rss     after warm-up {int(base) / 1024:.1f} MiB, end "
      f"{int(end) / 1024:.1f} MiB, growth {growth:+.2f}% "
      f"(limit {max_growth}%)")
print(f"soak: errors  {failed}; locatord exit on SIGTERM {server_exit}")
ok = (failed == 0 and load_status == "0" and server_exit == "0"
      and growth < float(max_growth))
print("soak: PASS" if ok else "soak: FAIL")
sys.exit(0 if ok else 1)
PY

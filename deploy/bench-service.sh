#!/usr/bin/env bash
# Measures the service end to end on this machine, in one run: locatord on
# 1M uniform points against locator-noop-server (same message shapes, no
# geometry), with locator-load on the same machine. Writes each run's JSON
# report to $OUT_DIR (default $BUILD_DIR/bench-service) and prints a summary
# table of the ratios the service is held to:
#   unary closed loop (64 in flight)      >= 12k calls/s, >= 0.8x no-op
#   LocateBatch, 10^4-point batches       >= 1.5M points/s, >= 2x nested batch
#   open loop at 5000 calls/s             p99 <= 2 ms
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
DURATION="${DURATION:-10}"
WORKLOAD="${WORKLOAD:-1-cluster}"
OUT_DIR="${OUT_DIR:-$BUILD_DIR/bench-service}"
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" \
  --target locatord locator-noop-server locator locator-load > /dev/null

tmp=$(mktemp -d)
pids=()
trap 'kill -TERM "${pids[@]}" 2>/dev/null; wait 2>/dev/null; rm -rf "$tmp"' EXIT

# Starts the server binary at BUILD_DIR/PATH with args, waits for its
# "listening on" line, and prints the port.
start() {
  local log="$tmp/$(basename "$1").log" port=""
  "$BUILD_DIR/$1" "${@:2}" --listen 127.0.0.1:0 > "$log" 2>&1 &
  pids+=($!)
  for _ in $(seq 1 600); do
    port=$(sed -n 's/.* listening on .*:\([0-9]*\)$/\1/p' "$log")
    [ -n "$port" ] && break
    sleep 0.1
  done
  [ -n "$port" ] || { cat "$log" >&2; exit 1; }
  echo "$port"
}

real=127.0.0.1:$(start server/locatord --dataset uniform:1000000:1)
noop=127.0.0.1:$(start server/bench/locator-noop-server)
until "$BUILD_DIR"/client/locator --target "$real" health > /dev/null 2>&1; do
  sleep 0.5
done

mkdir -p "$OUT_DIR"
load() {  # name target flags...
  echo "bench-service: $1 (${DURATION} s) -> $OUT_DIR/$1.json"
  "$BUILD_DIR"/client/locator-load --target "$2" --workload "$WORKLOAD" \
    --duration "$DURATION" --warmup 2 --format json "${@:3}" \
    > "$OUT_DIR/$1.json"
}
load unary "$real" --mode unary --concurrency 64
load unary-noop "$noop" --mode unary --concurrency 64
load batch "$real" --mode batch --batch-size 10000 --concurrency 4
load nested-batch-noop "$noop" --mode nested-batch --batch-size 10000 --concurrency 4
load open-loop "$real" --mode unary --rate 5000

python3 - "$OUT_DIR" <<'PY'
import json, sys
d = {k: json.load(open(f"{sys.argv[1]}/{k}.json")) for k in
     ["unary", "unary-noop", "batch", "nested-batch-noop", "open-loop"]}
def calls(k): return d[k]["calls_per_second"]
def points(k): return d[k]["points_per_second"]
p99 = d["open-loop"]["latency_us"]["p99"]
print("\n== summary")
print(f"unary      {calls('unary'):10.0f} calls/s  no-op {calls('unary-noop'):10.0f}  ratio {calls('unary')/calls('unary-noop'):.2f}")
print(f"batch      {points('batch'):10.0f} points/s nested no-op {points('nested-batch-noop'):10.0f}  ratio {points('batch')/points('nested-batch-noop'):.2f}")
print(f"open loop  5000 calls/s: p99 {p99/1000:.2f} ms")
failed = {k: v["failed_calls"] for k, v in d.items() if v["failed_calls"]}
print(f"failed calls: {failed or 'none'}")
PY

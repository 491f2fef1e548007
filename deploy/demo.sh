#!/usr/bin/env bash
# README command 1: installs what is missing, builds, starts locatord on a
# generated 1M-point dataset and drives it with locator-load on a clustered
# workload, so you can watch the mean cost per window drop once the server
# has learned where the queries land.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
BUILD_DIR="${BUILD_DIR:-build}"
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$BUILD_DIR" -j"$(nproc)" --target locatord locator locator-load

DATASET="${DATASET:-uniform:1000000:1}"
WORKLOAD="${WORKLOAD:-1-cluster}"
log=$(mktemp)
"$BUILD_DIR"/server/locatord --dataset "$DATASET" --listen 127.0.0.1:0 \
  --stats-interval-s 5 > "$log" 2>&1 &
server=$!
trap 'kill -TERM $server 2>/dev/null; wait $server 2>/dev/null; rm -f "$log"' EXIT

port=""
for _ in $(seq 1 300); do
  port=$(sed -n 's/^locatord listening on .*:\([0-9]*\)$/\1/p' "$log")
  [ -n "$port" ] && break
  kill -0 $server 2>/dev/null || { cat "$log"; exit 1; }
  sleep 0.1
done
target="127.0.0.1:$port"
echo "== locatord on $target, building the triangulation of $DATASET"
until "$BUILD_DIR"/client/locator --target "$target" health > /dev/null 2>&1; do
  kill -0 $server 2>/dev/null || { cat "$log"; exit 1; }
  sleep 0.5
done
grep -E 'serving|built' "$log" || true

echo "== locator-load: $WORKLOAD, unary, 16 in flight; server cost per 1000 queries"
"$BUILD_DIR"/client/locator-load --target "$target" --workload "$WORKLOAD" \
  --mode unary --concurrency 16 --queries 12000 --cost-window 1000

echo "== locator-load: $WORKLOAD, LocateBatch of 10000 points"
"$BUILD_DIR"/client/locator-load --target "$target" --workload "$WORKLOAD" \
  --mode batch --batch-size 10000 --concurrency 2 --duration 5

echo "== locator stats"
"$BUILD_DIR"/client/locator --target "$target" stats

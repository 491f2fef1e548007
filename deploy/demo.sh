#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and shows what locator
# does on an embedded default dataset (1M generated points, no download):
#   1. the same clustered load against three servers, one per strategy:
#      Jump&Walk (no tuning), the paper's adaptive Jump&Walk and self-tuning.
#      The server's mean cost (faces visited + start comparisons) per 2000
#      queries shows the paper's method adapt once it has seen ~2000 queries
#      (its Section IV), and self-tuning answer in a few faces throughout;
#   2. a summary, and the status page of the self-tuning server to open;
#   3. terrain as it comes: a DEM made here (a GeoTIFF of 800 x 600 pixels
#      of 30 m in UTM zone 33N, a hill with a lake of nodata, written as an
#      ASCII grid and converted by gdal_translate) served as dem.tif?
#      max_error=0.5: its certificate, a query in lon/lat, and the TIN
#      rendered back with `locator grid` at the DEM's pixel centres and
#      compared with the DEM pixel by pixel.
# Knobs: DATASET (default uniform:1000000:1), QUERIES (per strategy, 20000),
# BUILD_DIR (build). With a terminal on stdin the self-tuning server keeps
# running after the summary until Ctrl-C, for the status page.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
BUILD_DIR="${BUILD_DIR:-build}"
DATASET="${DATASET:-uniform:1000000:1}"
QUERIES="${QUERIES:-16000}"
echo "demo: building locatord, locator and locator-load in $BUILD_DIR" \
  "(log: $BUILD_DIR/demo-build.log)"
mkdir -p "$BUILD_DIR"
{ cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release &&
  cmake --build "$BUILD_DIR" -j"$(nproc)" --target locatord locator \
    locator-load; } > "$BUILD_DIR/demo-build.log" 2>&1 ||
  { tail -n 40 "$BUILD_DIR/demo-build.log"; exit 1; }

tmp=$(mktemp -d)
pids=()
trap 'kill -TERM "${pids[@]}" 2>/dev/null; wait 2>/dev/null; rm -rf "$tmp"' EXIT

# serve NAME ARGS...: starts locatord on an OS-chosen port; its log is
# $tmp/NAME.log.
serve() {
  "$BUILD_DIR"/server/locatord --dataset "$DATASET" --listen 127.0.0.1:0 \
    "${@:2}" > "$tmp/$1.log" 2>&1 &
  pids+=($!)
}
# port_of NAME [http]: waits for NAME's "listening on" line; prints the port.
port_of() {
  local pattern='^locatord listening on .*:\([0-9]*\)$'
  [ "${2:-}" = http ] && pattern='^locatord http listening on .*:\([0-9]*\)$'
  for _ in $(seq 1 600); do
    port=$(sed -n "s/$pattern/\1/p" "$tmp/$1.log")
    [ -n "$port" ] && { echo "$port"; return; }
    sleep 0.1
  done
  cat "$tmp/$1.log" >&2
  exit 1
}
# load NAME TARGET WORKLOAD WINDOW: LOAD's JSON summary into $tmp/NAME.json.
load() {
  "$BUILD_DIR"/client/locator-load --target "$2" --workload "$3" \
    --mode unary --concurrency 8 --queries "$QUERIES" --cost-window "$4" \
    --format json > "$tmp/$1.json"
}

echo "demo: starting three servers on $DATASET (triangulating takes a few s)"
strategies=(jump-and-walk adaptive-paper self-tuning)
for s in "${strategies[@]}"; do
  extra=()
  [ "$s" = self-tuning ] && extra=(--http-listen 127.0.0.1:0)
  serve "$s" --strategy "$s" "${extra[@]}"
done

# The DEM: an ASCII grid written here, made a GeoTIFF by gdal_translate.
python3 - "$tmp/dem.asc" <<'PY'
import math, sys
width, height, cell = 800, 600, 30.0
x0, y0 = 500000 - width * cell / 2, 5500000 - height * cell / 2
with open(sys.argv[1], "w") as out:
    out.write(f"ncols {width}\nnrows {height}\nxllcorner {x0}\n"
              f"yllcorner {y0}\ncellsize {cell}\nNODATA_value -9999\n")
    for row in range(height):
        y = y0 + (height - row - 0.5) * cell - 5500000
        values = []
        for col in range(width):
            x = x0 + (col + 0.5) * cell - 500000
            if (x - 3000) ** 2 + (y + 2000) ** 2 < 1200 ** 2:
                values.append("-9999")  # the lake
                continue
            z = (400 + 600 * math.exp(-(x * x + y * y) / (2 * 4000 ** 2))
                 + 40 * math.sin(x / 900) * math.cos(y / 700)
                 + 8 * math.sin((x + 2 * y) / 250))
            values.append(f"{z:.2f}")
        out.write(" ".join(values) + "\n")
PY
gdal_translate -q -of GTiff -a_srs EPSG:32633 "$tmp/dem.asc" "$tmp/dem.tif"
"$BUILD_DIR"/server/locatord --dataset "$tmp/dem.tif?max_error=0.5" \
  --listen 127.0.0.1:0 > "$tmp/dem.log" 2>&1 &
pids+=($!)
for s in "${strategies[@]}"; do
  target="127.0.0.1:$(port_of "$s")"
  echo "$target" > "$tmp/$s.target"
  until "$BUILD_DIR"/client/locator --target "$target" health \
    > /dev/null 2>&1; do sleep 0.2; done
done

echo "demo: $QUERIES queries of the 3-cluster workload against each strategy"
for s in "${strategies[@]}"; do
  load "$s" "$(cat "$tmp/$s.target")" 3-cluster 2000
done
http_port=$(port_of self-tuning http)

python3 - "$tmp" "$QUERIES" <<'PY'
import json, sys
tmp, queries = sys.argv[1], int(sys.argv[2])
def means(name):
    return json.load(open(f"{tmp}/{name}.json"))["cost_window_means"]
print("\n== mean cost per 2000 queries, 3-cluster workload (lower is better)")
rows = {}
for name in ["jump-and-walk", "adaptive-paper", "self-tuning"]:
    m = means(name)
    rows[name] = m
    print(f"{name:15s} " + " ".join(f"{v:6.1f}" for v in m))
jw, st = rows["jump-and-walk"][-1], rows["self-tuning"][-1]
ap0, ap = rows["adaptive-paper"][0], rows["adaptive-paper"][-1]
print(f"\n== summary: Jump&Walk pays {jw:.1f} per query on this load. The"
      f" paper's adaptive Jump&Walk learns the clusters from its first 2000"
      f" queries and drops from {ap0:.1f} to {ap:.1f}. Self-tuning, which"
      f" re-tunes from a decayed histogram as traffic moves, pays {st:.1f}:"
      f" {jw / st:.0f}x less than Jump&Walk.")
PY
dem="$BUILD_DIR/client/locator --target 127.0.0.1:$(port_of dem)"
until $dem health > /dev/null 2>&1; do sleep 0.2; done
echo
echo "== a DEM served within max_error 0.5 m: $tmp/dem.tif (800 x 600" \
  "pixels), locatord --dataset 'dem.tif?max_error=0.5'"
$dem stats | grep -E '^(points|crs|simplified) '
echo "-- the summit, asked in lon/lat:" \
  "locator --crs EPSG:4326 locate 15.0 49.6525"
$dem --crs EPSG:4326 locate 15.0 49.6525 | grep -E '^(type|value) '
echo "-- rendered back: locator grid --te 488000 5491000 512000 5509000" \
  "--outsize 800 600 (the DEM's own pixel centres)"
$dem grid --te 488000 5491000 512000 5509000 --outsize 800 600 \
  --a_nodata -9999 --of GTiff --out "$tmp/rendered.tif" > /dev/null
gdal_translate -q -of AAIGrid "$tmp/rendered.tif" "$tmp/rendered.asc"
python3 - "$tmp/dem.asc" "$tmp/rendered.asc" <<'PY'
import sys
def cells(path):
    with open(path) as f:
        rows = [line.split() for line in f]
    return [float(v) for row in rows if not row[0][0].isalpha() for v in row]
dem, tin = cells(sys.argv[1]), cells(sys.argv[2])
valid = [(d, t) for d, t in zip(dem, tin) if d != -9999]
worst = max(abs(d - t) for d, t in valid if t != -9999)
holes = all((t == -9999) == (d == -9999) for d, t in zip(dem, tin))
print(f"   max |TIN - DEM| over the {len(valid)} pixels with a value:"
      f" {worst:.3f} m; nodata exactly where the DEM has none:"
      f" {'yes' if holes else 'NO'}")
PY
echo
echo "== status page of the self-tuning server: http://127.0.0.1:$http_port/"
if [ -t 0 ]; then
  echo "   (serving until Ctrl-C)"
  wait "${pids[2]}"
fi

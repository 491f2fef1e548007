#!/usr/bin/env bash
# A locator cluster on this machine, with no container engine, behind
# Debian's nginx, under load, losing a replica mid-run.
#
# Without flags: three locatord replicas of one dataset on loopback, each
# with its own state directory, behind nginx configured from
# deploy/nginx/locator.conf. It drives locator-load (unary calls, with the
# client's gRPC retry policy) through nginx, SIGKILLs one replica mid-run,
# restarts it a few seconds later on the same port and state directory, and
# prints the totals, p50/p99 before, during and after the failure, and what
# the restarted replica came back with.
#
# With --shards N [--replicas R]: the same run against a sharded tile set.
# It builds a tile set of DATASET with locator-build (about 5 tiles per
# shard), first drives the same load against ONE locatord serving the whole
# tile set (the one-box throughput), then starts N x R shard replicas
# (locatord --tiles K/N), one nginx upstream per shard over its R replicas
# (each on its own port), 2 routers (locatord --route) over the shards'
# nginx ports, and nginx's front over the routers, which locator-load
# drives. Every shard replica and router also serves HTTP (--http-listen),
# behind nginx's HTTP front: the routed JSON calls to the routers, the rest
# (tiles, the elevation APIs, the web map) to the shard replicas. Before the
# load it checks that front with curl: a :locate and a :locateBatch through
# a router, and a terrain tile from a shard. Replica 0 of shard 1 is
# SIGKILLed and restarted. It also prints both throughputs and their ratio,
# and the calls that failed during the kill. The nginx config comes from
# deploy/nginx/locator-shards.conf.
#
#   bash deploy/local-cluster.sh                 # 20 s of load
#   DURATION=60 PLOT=cluster.svg bash deploy/local-cluster.sh
#   bash deploy/local-cluster.sh --shards 4 --replicas 2
#
# Environment (all optional):
#   BUILD_DIR      build tree with the binaries                  (build)
#   NGINX          the nginx binary                              (/usr/sbin/nginx)
#   DURATION       seconds of load (of each run with --shards)   (20)
#   KILL_AT        seconds into the load when the victim dies, at the
#                  earliest once it has saved its tuning        (35% of it)
#   RESTART_AFTER  seconds between the kill and the restart      (3)
#   DATASET        locatord --dataset; with --shards, locator-build's
#                  SOURCE                                        (uniform:200000:1)
#   TILE_POINTS    with --shards: locator-build --tile-points    (DATASET's
#                  points / (5 x N); needed when DATASET is not a generator)
#   WORKLOAD       locator-load --workload                       (1-cluster;
#                  uniform with --shards, so that every shard is queried)
#   CONCURRENCY    calls in flight                               (16)
#   MODE           locator-load --mode: unary or batch           (unary)
#   BATCH_SIZE     with MODE=batch: points per call              (1000)
#   RETUNE_EVERY   locatord --retune-every                       (its default)
#   PLOT           also write locator-load's SVG chart here (the cluster's run)
#   SUMMARY_JSON   also write the summary as JSON here (the ctests read it)
#   KEEP_DIR=1     keep the working directory (logs, nginx.conf) and say where
#
# Exit code: 0 when every call succeeded, 1 when any failed or the cluster
# could not be set up, 2 for a usage error. Every process it starts is
# stopped on exit.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

usage() {
  echo "usage: local-cluster.sh [--shards N [--replicas R]]   (N >= 2, R >= 2; see the header)" >&2
  exit 2
}
SHARDS=0     # 0: the three replicas of one dataset
REPLICAS=""  # replicas per shard (2)
while [ $# -gt 0 ]; do
  case $1 in
    --shards) [ $# -ge 2 ] || usage; SHARDS=$2; shift 2 ;;
    --replicas) [ $# -ge 2 ] || usage; REPLICAS=$2; shift 2 ;;
    *) usage ;;
  esac
done
if [ "$SHARDS" = 0 ] && [ -n "$REPLICAS" ]; then usage; fi
REPLICAS=${REPLICAS:-2}
[[ $SHARDS =~ ^[0-9]+$ && $REPLICAS =~ ^[0-9]+$ ]] || usage
# The victim is a replica of shard 1, and its shard must keep a replica.
if [ "$SHARDS" != 0 ] && { [ "$SHARDS" -lt 2 ] || [ "$REPLICAS" -lt 2 ]; }; then usage; fi
sharded() { [ "$SHARDS" -gt 0 ]; }

BUILD_DIR="${BUILD_DIR:-$repo/build}"
LOCATORD="$BUILD_DIR/server/locatord"
LOCATOR="$BUILD_DIR/client/locator"
LOCATOR_LOAD="$BUILD_DIR/client/locator-load"
LOCATOR_BUILD="$BUILD_DIR/server/locator-build"
NGINX="${NGINX:-/usr/sbin/nginx}"
DURATION="${DURATION:-20}"
KILL_AT="${KILL_AT:-$(python3 -c "print(round($DURATION * 0.35, 1))")}"
RESTART_AFTER="${RESTART_AFTER:-3}"
DATASET="${DATASET:-uniform:200000:1}"
# 1-cluster's hot spot lies in a tile or two: sharded, it would load one
# shard and leave the victim's idle.
if sharded; then WORKLOAD="${WORKLOAD:-uniform}"; else WORKLOAD="${WORKLOAD:-1-cluster}"; fi
CONCURRENCY="${CONCURRENCY:-16}"
MODE="${MODE:-unary}"
BATCH_SIZE="${BATCH_SIZE:-1000}"
case "$MODE" in
  unary) mode_flags=(--mode unary) ;;
  batch) mode_flags=(--mode batch --batch-size "$BATCH_SIZE") ;;
  *) echo "local-cluster: MODE must be unary or batch" >&2; exit 2 ;;
esac
retune_flags=()
if [ -n "${RETUNE_EVERY:-}" ]; then retune_flags=(--retune-every "$RETUNE_EVERY"); fi
ROUTERS=2

binaries=("$LOCATORD" "$LOCATOR" "$LOCATOR_LOAD" "$NGINX")
if sharded; then binaries+=("$LOCATOR_BUILD"); fi
for binary in "${binaries[@]}"; do
  [ -x "$binary" ] || { echo "local-cluster: $binary not found (build first)" >&2; exit 1; }
done
if sharded && [ -z "${TILE_POINTS:-}" ]; then
  # uniform:N[:SEED] and clusters:N:K[:SEED] say their N; ~5 tiles per shard.
  points=$(sed -nE 's/^(uniform|clusters):([0-9]+)(:.*)?$/\2/p' <<< "$DATASET")
  [ -n "$points" ] || { echo "local-cluster: set TILE_POINTS for DATASET=$DATASET" >&2; exit 2; }
  TILE_POINTS=$(((points + 5 * SHARDS - 1) / (5 * SHARDS)))
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/locator-cluster.XXXXXX")
declare -A pids=()  # name -> pid of every process still running

cleanup() {
  local status=$?
  trap - EXIT INT TERM
  for name in "${!pids[@]}"; do kill -TERM "${pids[$name]}" 2>/dev/null || true; done
  for name in "${!pids[@]}"; do wait "${pids[$name]}" 2>/dev/null || true; done
  if [ "${KEEP_DIR:-0}" = 1 ]; then
    echo "local-cluster: logs kept in $work" >&2
  else
    rm -rf "$work"
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

log() { echo "== [$(date +%T)] $*"; }
fail() { echo "local-cluster: $*" >&2; exit 1; }

# Prints `count` distinct TCP ports that are free on 127.0.0.1, chosen below
# the kernel's ephemeral range: a restarted replica must get its port back,
# and a port there cannot meanwhile become the local end of some outgoing
# connection.
free_ports() {
  python3 - "$1" <<'PY'
import pathlib, random, socket, sys
low = int(pathlib.Path("/proc/sys/net/ipv4/ip_local_port_range").read_text().split()[0])
chosen = set()
while len(chosen) < int(sys.argv[1]):
    if low > 11000:
        port = random.randrange(10000, low)
    else:  # no room below the ephemeral range: let the kernel choose
        port = 0
    with socket.socket() as s:
        try:
            s.bind(("127.0.0.1", port))
        except OSError:
            continue
        chosen.add(s.getsockname()[1])
print(" ".join(map(str, chosen)))
PY
}

# Whether process `pid` runs (an exited child stays a zombie until reaped,
# and kill -0 succeeds on a zombie). Its status file may vanish while read.
alive() {
  local state
  state=$(grep '^State:' "/proc/$1/status" 2>/dev/null) || return 1
  [[ ! $state =~ ^State:[[:space:]]*[ZX] ]]
}

# wait_for SECONDS PID LOG COMMAND...: polls COMMAND every 0.1 s until it
# succeeds; fails after SECONDS, or at once when PID has died (LOG is shown).
wait_for() {
  local seconds=$1 pid=$2 logfile=$3; shift 3
  local deadline=$((SECONDS + seconds))
  until "$@" > /dev/null 2>&1; do
    alive "$pid" || { cat "$logfile" >&2; fail "process $pid died"; }
    [ $SECONDS -lt $deadline ] || { cat "$logfile" >&2; fail "timed out: $*"; }
    sleep 0.1
  done
}

health() { "$LOCATOR" --target "$1" --deadline-ms 1000 health; }

# Ports: nginx's front first, then one for every process that listens
# (sharded: then nginx's HTTP front and every shard replica's and router's
# HTTP port).
if sharded; then
  read -r -a ports <<< "$(free_ports $((1 + SHARDS + SHARDS * REPLICAS + ROUTERS + 1 \
    + 1 + SHARDS * REPLICAS + ROUTERS)))"
else
  read -r -a ports <<< "$(free_ports 4)"
fi
nginx_port=${ports[0]}
declare -A port=()      # name -> its port
declare -A tiles_of=()  # replica name -> its --tiles selector (sharded)
shard_flags=()          # the locatord flags every shard replica adds
next_port=1
assign_port() { port[$1]=${ports[$next_port]}; next_port=$((next_port + 1)); }
replicas=()
if sharded; then
  for ((k = 0; k < SHARDS; k++)); do
    assign_port "nginx-shard$k"
    for ((j = 0; j < REPLICAS; j++)); do
      replicas+=("shard$k-$j")
      assign_port "shard$k-$j"
      tiles_of[shard$k-$j]="$k/$SHARDS"
    done
  done
  for ((r = 0; r < ROUTERS; r++)); do assign_port "router$r"; done
  assign_port one-box
  assign_port http-front
  for name in "${replicas[@]}"; do assign_port "$name-http"; done
  for ((r = 0; r < ROUTERS; r++)); do assign_port "router$r-http"; done
  # The victim: replica 0 of shard 1.
  victim_shard=1 victim_replica=0
  victim_name=shard$victim_shard-$victim_replica
  victim_label="shard $victim_shard replica $victim_replica"
else
  for i in 1 2 3; do replicas+=("replica$i"); assign_port "replica$i"; done
  victim_replica=2
  victim_name=replica$victim_replica victim_label="replica $victim_replica"
fi

if sharded; then
  log "tile set: locator-build $DATASET --tile-points $TILE_POINTS"
  "$LOCATOR_BUILD" "$DATASET" --out "$work/tileset" --tile-points "$TILE_POINTS" --quiet \
    > "$work/tileset.log" 2>&1 || { cat "$work/tileset.log" >&2; fail "locator-build failed"; }
  tile_count=$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["tiles"]))' \
    "$work/tileset/manifest.json")
  [ "$tile_count" -ge "$SHARDS" ] || fail "$tile_count tiles for $SHARDS shards: lower TILE_POINTS"
  dataset_flags=(--dataset "big=$work/tileset/manifest.json")
  # The HTTP front's tile check needs a tile set that can be drawn on a web
  # map: one with a CRS and values (server/tiles/terrain_tile.h). The
  # generators' points have neither, so then the shards also serve
  # "terrain", a small tile set of 1000 points per shard with both (UTM
  # zone 32N, in 200-point tiles: 5 per shard), split by the same --tiles.
  # The load and the one box use big alone.
  if python3 -c 'import json, sys
manifest = json.load(open(sys.argv[1]))
sys.exit(0 if manifest["crs"] and manifest["has_values"] else 1)' "$work/tileset/manifest.json"; then
    tile_dataset=big
  else
    tile_dataset=terrain
    python3 - "$work/terrain.geojson" $((1000 * SHARDS)) <<'PY'
import json, math, random, sys
path, count = sys.argv[1], int(sys.argv[2])
rng = random.Random(1)
features = []
for _ in range(count):
    x, y = 500000 + 10000 * rng.random(), 5000000 + 10000 * rng.random()
    z = 100 + 50 * math.sin(x / 900) * math.cos(y / 700)
    features.append({"type": "Feature", "properties": {},
                     "geometry": {"type": "Point", "coordinates": [x, y, z]}})
json.dump({"type": "FeatureCollection", "features": features}, open(path, "w"))
PY
    "$LOCATOR_BUILD" "$work/terrain.geojson?a_srs=EPSG:32632" --out "$work/terrain" \
      --tile-points 200 --quiet > "$work/terrain.log" 2>&1 ||
      { cat "$work/terrain.log" >&2; fail "locator-build failed (terrain)"; }
    shard_flags+=(--dataset "terrain=$work/terrain/manifest.json")
  fi
else
  dataset_flags=(--dataset "$DATASET")
fi

# start_replica NAME: starts replica NAME on its port (again, after a kill)
# and waits until it listens; SERVING comes later, once the dataset is built
# (or the tile set mapped). A shard replica also serves HTTP on a port of
# its own.
start_replica() {
  local name=$1 tiles=()
  if [ -n "${tiles_of[$name]:-}" ]; then
    tiles=(--tiles "${tiles_of[$name]}" "${shard_flags[@]}"
           --http-listen "127.0.0.1:${port[$name-http]}")
  fi
  mkdir -p "$work/$name/state"
  "$LOCATORD" "${dataset_flags[@]}" "${tiles[@]}" --listen "127.0.0.1:${port[$name]}" \
    --state-dir "$work/$name/state" "${retune_flags[@]}" \
    >> "$work/$name/locatord.log" 2>&1 &
  pids[$name]=$!
  wait_for 60 $! "$work/$name/locatord.log" \
    grep -q "listening on 127.0.0.1:${port[$name]}\$" "$work/$name/locatord.log"
}

# The one-box baseline: the cluster's load against one locatord serving the
# whole tile set, run before the cluster starts (they would share the CPUs).
one_box_status=0
if sharded; then
  one_box="127.0.0.1:${port[one-box]}"
  "$LOCATORD" "${dataset_flags[@]}" --listen "$one_box" "${retune_flags[@]}" \
    > "$work/one-box.log" 2>&1 &
  pids[one-box]=$!
  wait_for 300 "${pids[one-box]}" "$work/one-box.log" health "$one_box"
  log "one box: locator-load against one locatord serving all $tile_count tiles: $WORKLOAD, ${mode_flags[*]}, $CONCURRENCY in flight, ${DURATION} s, --retry"
  "$LOCATOR_LOAD" --target "$one_box" --workload "$WORKLOAD" "${mode_flags[@]}" \
    --concurrency "$CONCURRENCY" --duration "$DURATION" --retry \
    --format json > "$work/one-box.json" 2> "$work/one-box.err" || one_box_status=$?
  kill -TERM "${pids[one-box]}"
  wait "${pids[one-box]}" 2>/dev/null || true
  unset "pids[one-box]"
fi

if sharded; then
  log "$SHARDS shards x $REPLICAS replicas of the tile set ($tile_count tiles, --tiles K/$SHARDS), each with a state dir"
else
  log "3 replicas of $DATASET on ports ${port[replica1]} ${port[replica2]} ${port[replica3]}, each with a state dir"
fi
for name in "${replicas[@]}"; do start_replica "$name"; done
for name in "${replicas[@]}"; do
  wait_for 300 "${pids[$name]}" "$work/$name/locatord.log" health "127.0.0.1:${port[$name]}"
done

# nginx: deploy/nginx/locator.conf (sharded: locator-shards.conf, its shard
# block repeated per shard) with its upstreams and listen addresses
# rewritten, inside a main config that keeps every file in $work.
mkdir -p "$work/nginx"
if sharded; then
  # One argument per shard: its nginx port, then its replicas' ports.
  shard_args=()
  for ((k = 0; k < SHARDS; k++)); do
    ports_of_shard=${port[nginx-shard$k]}
    for ((j = 0; j < REPLICAS; j++)); do ports_of_shard+=",${port[shard$k-$j]}"; done
    shard_args+=("$ports_of_shard")
  done
  routers_arg=${port[router0]} routers_http_arg=${port[router0-http]}
  for ((r = 1; r < ROUTERS; r++)); do
    routers_arg+=",${port[router$r]}" routers_http_arg+=",${port[router$r-http]}"
  done
  # The HTTP ports of every replica of every shard, for the HTTP front.
  shards_http_arg=${port[${replicas[0]}-http]}
  for name in "${replicas[@]:1}"; do shards_http_arg+=",${port[$name-http]}"; done
  python3 - "$repo/deploy/nginx/locator-shards.conf" "$work/nginx/locator.conf" "$nginx_port" \
    "$routers_arg" "${port[http-front]}" "$routers_http_arg" "$shards_http_arg" \
    "${shard_args[@]}" <<'PY'
import pathlib, re, sys
template, out, listen, routers, http_listen, routers_http, shards_http, *shards = sys.argv[1:]
text = pathlib.Path(template).read_text()
block = re.search(r"^# BEGIN SHARD 0\n.*?^# END SHARD 0\n", text, re.S | re.M)
replica_line = r"^( *)server shard0-\d+:50051( .*)\n"
if not block or len(re.findall(replica_line, block[0], re.M)) != 2:
    sys.exit(f"{template}: expected a BEGIN/END SHARD 0 block with 2 replica servers")


def shard_block(k, listen_port, *replica_ports):
    """The shard block of shard k: on listen_port, over replica_ports."""
    indent, options = re.search(replica_line, block[0], re.M).groups()
    servers = "".join(f"{indent}server 127.0.0.1:{p}{options}\n" for p in replica_ports)
    # The template's replica lines, adjacent, become these.
    text, n = re.subn(f"(?:{replica_line})+", lambda m: servers, block[0], flags=re.M)
    if n != 1:
        sys.exit(f"{template}: the shard block's replica servers must be adjacent lines")
    text = re.sub(r"\b(SHARD |shard |locator_shard)0\b", rf"\g<1>{k}", text)
    text, n = re.subn(r"listen 50060 http2;", f"listen 127.0.0.1:{listen_port} http2;", text)
    if n != 1:
        sys.exit(f"{template}: expected 1 listen line in the shard block, found {n}")
    return text


text = text.replace(block[0], "\n".join(
    shard_block(k, *s.split(",")) for k, s in enumerate(shards)))
router_ports = routers.split(",")
servers = iter(router_ports)
text, n = re.subn(r"server router\d+:50051", lambda m: f"server 127.0.0.1:{next(servers)}", text)
text, m = re.subn(r"listen 8080 http2;", f"listen 127.0.0.1:{listen} http2;", text)
if (n, m) != (len(router_ports), 1):
    sys.exit(f"{template}: expected {len(router_ports)} router servers and 1 front"
             f" listen line, found {n} and {m}")
# The HTTP front: the routers' HTTP ports, every shard replica's (the
# template's adjacent shard HTTP lines become one line per replica), and
# its listen line.
router_http_ports = routers_http.split(",")
servers = iter(router_http_ports)
text, n = re.subn(r"server router\d+:9090", lambda m: f"server 127.0.0.1:{next(servers)}", text)
shard_http_line = r"^( *)server shard\d+-\d+:9090( .*)\n"
template_lines = re.findall(shard_http_line, text, re.M)
if not template_lines:
    sys.exit(f"{template}: expected shard HTTP servers (server shardK-J:9090), found none")
indent, options = template_lines[0]
servers = "".join(f"{indent}server 127.0.0.1:{p}{options}\n" for p in shards_http.split(","))
text, s = re.subn(f"(?:{shard_http_line})+", lambda m: servers, text, flags=re.M)
text, m = re.subn(r"listen 8088;", f"listen 127.0.0.1:{http_listen};", text)
if (n, s, m) != (len(router_http_ports), 1, 1):
    sys.exit(f"{template}: expected {len(router_http_ports)} router HTTP servers, 1 run of"
             f" adjacent shard HTTP servers and 1 HTTP front listen line, found {n}, {s}"
             f" and {m}")
pathlib.Path(out).write_text(text)
PY
else
  python3 - "$repo/deploy/nginx/locator.conf" "$work/nginx/locator.conf" "$nginx_port" \
    "${port[replica1]}" "${port[replica2]}" "${port[replica3]}" <<'PY'
import pathlib, re, sys
template, out, listen, *replicas = sys.argv[1:]
text = pathlib.Path(template).read_text()
servers = iter(replicas)
text, n = re.subn(r"server locator\d+:50051", lambda m: f"server 127.0.0.1:{next(servers)}", text)
text, m = re.subn(r"listen 8080 http2;", f"listen 127.0.0.1:{listen} http2;", text)
if (n, m) != (3, 1):
    sys.exit(f"{template}: expected 3 upstream servers and 1 listen line, found {n} and {m}")
pathlib.Path(out).write_text(text)
PY
fi
# Each access log line starts with the port that took the call, which tells
# the front's 502s from a shard's.
cat > "$work/nginx/nginx.conf" <<NGINX_CONF
daemon off;
worker_processes 1;
pid $work/nginx/nginx.pid;
error_log $work/nginx/error.log warn;
events { worker_connections 1024; }
http {
  log_format by_port '\$server_port \$remote_addr [\$time_local] "\$request" \$status \$body_bytes_sent \$request_time';
  access_log $work/nginx/access.log by_port;
  client_body_temp_path $work/nginx/body;
  proxy_temp_path $work/nginx/proxy;
  fastcgi_temp_path $work/nginx/fastcgi;
  uwsgi_temp_path $work/nginx/uwsgi;
  scgi_temp_path $work/nginx/scgi;
  include $work/nginx/locator.conf;
}
NGINX_CONF
nginx_cmd=("$NGINX" -p "$work/nginx" -c "$work/nginx/nginx.conf" -e "$work/nginx/error.log")
"${nginx_cmd[@]}" -t -q || fail "nginx -t rejected $work/nginx/nginx.conf"
"${nginx_cmd[@]}" &
pids[nginx]=$!
target="127.0.0.1:$nginx_port"

# The routers: stateless; each asks every shard (through its nginx port)
# for its topology, and forwards each call to its point's shard: the gRPC
# calls and, on its HTTP port, the routed JSON calls.
if sharded; then
  shard_targets=127.0.0.1:${port[nginx-shard0]}
  for ((k = 1; k < SHARDS; k++)); do shard_targets+=",127.0.0.1:${port[nginx-shard$k]}"; done
  for ((r = 0; r < ROUTERS; r++)); do
    mkdir -p "$work/router$r"
    "$LOCATORD" --route --shards "$shard_targets" --listen "127.0.0.1:${port[router$r]}" \
      --http-listen "127.0.0.1:${port[router$r-http]}" >> "$work/router$r/locatord.log" 2>&1 &
    pids[router$r]=$!
  done
  for ((r = 0; r < ROUTERS; r++)); do
    wait_for 60 "${pids[router$r]}" "$work/router$r/locatord.log" health "127.0.0.1:${port[router$r]}"
  done
  log "$ROUTERS routers over the shards' nginx ports ($shard_targets)"
fi
wait_for 30 "${pids[nginx]}" "$work/nginx/error.log" health "$target"
log "nginx on $target"

# nginx's HTTP front (sharded), checked with curl before the load: the
# routed calls must reach a router and the rest a shard. A :locate of the
# centre of big's box must name a triangle; a :locateBatch of 16 points all
# over the box must answer them all, which only a router does (a shard
# refuses the points of the other shards' tiles with 400); a terrain tile
# at the centre of the tile set's TileJSON must come back as a PNG, which
# only a shard sends (a router 404s tiles).
if sharded; then
  http_front="127.0.0.1:${port[http-front]}"
  log "nginx's HTTP front on $http_front: :locate, :locateBatch, :profile, :grid and :topology to the routers, the rest to the shard replicas"
  mkdir -p "$work/http"
  # front_call NAME METHOD PATH [JSON]: calls PATH on the HTTP front (with
  # the JSON body, if given), writes the answer's body to $work/http/NAME
  # and prints its status and content type (status 000: no answer).
  front_call() {
    local args=(-sS --max-time 60 -o "$work/http/$1" -w '%{http_code} %{content_type}' -X "$2")
    if [ $# -ge 4 ]; then args+=(-H 'Content-Type: application/json' --data-binary "$4"); fi
    : > "$work/http/$1"
    curl "${args[@]}" "http://$http_front$3" 2> "$work/http/$1.err" || true
  }
  # front_fail NAME WHAT REPLY: fails, showing the answer's body (or curl's
  # error).
  front_fail() {
    fail "$2 through the HTTP front answered ${3:-nothing}:
$(head -c 2000 "$work/http/$1")$(cat "$work/http/$1.err")"
  }
  read -r locate_body batch_body <<< "$(python3 - "$work/tileset/manifest.json" <<'PY'
import json, sys
x0, y0, x1, y1 = json.load(open(sys.argv[1]))["bounds"]
grid = [(i + 0.5) / 4 for i in range(4)]
locate = {"point": {"x": (x0 + x1) / 2, "y": (y0 + y1) / 2}}
batch = {"xs": [x0 + (x1 - x0) * u for u in grid for v in grid],
         "ys": [y0 + (y1 - y0) * v for u in grid for v in grid]}
print(json.dumps(locate, separators=(",", ":")), json.dumps(batch, separators=(",", ":")))
PY
)"
  what="POST /v1/datasets/big:locate $locate_body"
  reply=$(front_call locate.json POST /v1/datasets/big:locate "$locate_body")
  [[ $reply == "200 application/json"* ]] || front_fail locate.json "$what" "$reply"
  if ! triangle=$(python3 -c 'import json, sys
print(int(json.load(open(sys.argv[1]))["triangle_id"]))' "$work/http/locate.json" 2>/dev/null) ||
    [ "$triangle" -lt 0 ]; then
    front_fail locate.json "$what" "$reply, no triangle"
  fi
  log "HTTP front: $what: $reply, triangle $triangle"
  what="POST /v1/datasets/big:locateBatch (16 points all over the box)"
  reply=$(front_call batch.json POST /v1/datasets/big:locateBatch "$batch_body")
  [[ $reply == "200 application/json"* ]] || front_fail batch.json "$what" "$reply"
  python3 -c 'import json, sys
sys.exit(len(json.load(open(sys.argv[1]))["triangle_ids"]) != 16)' "$work/http/batch.json" 2>/dev/null ||
    front_fail batch.json "$what" "$reply, not 16 answers"
  log "HTTP front: $what: $reply, 16 answers (a router's: no shard holds all their tiles)"
  what="GET /v1/datasets/$tile_dataset/tiles.json"
  reply=$(front_call tiles.json GET "/v1/datasets/$tile_dataset/tiles.json")
  [[ $reply == "200 application/json"* ]] || front_fail tiles.json "$what" "$reply"
  # The XYZ tile holding the TileJSON's centre [lon, lat, zoom].
  tile=$(python3 -c 'import json, math, sys
lon, lat, z = json.load(open(sys.argv[1]))["center"]
n = 2 ** int(z)
x = int((lon + 180) / 360 * n)
y = int((1 - math.asinh(math.tan(math.radians(lat))) / math.pi) / 2 * n)
print(f"{int(z)}/{x}/{y}")' "$work/http/tiles.json" 2>/dev/null) || front_fail tiles.json "$what" "$reply, no centre"
  what="GET /v1/datasets/$tile_dataset/tiles/$tile.png"
  reply=$(front_call tile.png GET "/v1/datasets/$tile_dataset/tiles/$tile.png")
  if [ "$reply" != "200 image/png" ] || [ "$(head -c 4 "$work/http/tile.png" | tail -c 3)" != PNG ]; then
    front_fail tile.png "$what" "$reply"
  fi
  log "HTTP front: $what: $reply, $(wc -c < "$work/http/tile.png") bytes (a shard's: a router has no tiles)"
fi

plot_args=()
if [ -n "${PLOT:-}" ]; then plot_args=(--plot "$PLOT"); fi
log "locator-load: $WORKLOAD, ${mode_flags[*]}, $CONCURRENCY in flight, ${DURATION} s, --retry; $victim_label dies at ${KILL_AT} s"
"$LOCATOR_LOAD" --target "$target" --workload "$WORKLOAD" "${mode_flags[@]}" \
  --concurrency "$CONCURRENCY" --duration "$DURATION" --retry --phase-signal \
  --format json "${plot_args[@]}" > "$work/load.json" 2> "$work/load.err" &
pids[load]=$!

# Starts the next phase of locator-load's report.
mark_phase() {
  alive "${pids[load]}" || fail "the load ended before the failover did: raise DURATION"
  kill -USR1 "${pids[load]}"
}

victim="127.0.0.1:${port[$victim_name]}"
# saved_tuning: whether the victim has written its tuning state at least
# once, so that its restart has something to restore.
saved_tuning() {
  "$LOCATOR" --target "$victim" --deadline-ms 1000 --json stats 2>/dev/null |
    python3 -c 'import json, sys
stats = json.load(sys.stdin)
saves = stats.get("tuning", {}).get("persistence", {}).get("saves", "0")
sys.exit(0 if int(saves) > 0 else 1)'
}
sleep "$KILL_AT"
# Killed at KILL_AT, or later once it has saved its tuning: a slow machine
# (or a sanitizer build) may not have re-tuned by KILL_AT. Only the load
# makes it re-tune, so this waits while the load runs, and at most 60 s.
save_deadline=$((SECONDS + 60))
until saved_tuning; do
  alive "${pids[load]}" ||
    fail "$victim_label saved no tuning state before the load ended: raise DURATION or lower RETUNE_EVERY"
  [ $SECONDS -lt $save_deadline ] || fail "$victim_label saved no tuning state in 60 s"
  sleep 0.1
done
mark_phase  # phase 2: during the failure (calls it breaks count there)
# Out of the job table first: bash would otherwise now and then report the
# kill on stderr ("line N: PID Killed ..."). It is gone once not alive().
disown "${pids[$victim_name]}"
kill -KILL "${pids[$victim_name]}"
while alive "${pids[$victim_name]}"; do sleep 0.05; done
unset "pids[$victim_name]"
log "SIGKILL $victim_label ($victim)"

sleep "$RESTART_AFTER"
start_replica "$victim_name"
# Its first GetStats, as early as it answers: before nginx, which marked it
# failed for fail_timeout (5 s), sends it traffic, it shows what the replica
# came back with rather than what it has learned since.
wait_for 300 "${pids[$victim_name]}" "$work/$victim_name/locatord.log" \
  sh -c "'$LOCATOR' --target $victim --deadline-ms 1000 --json stats > '$work/restart-stats.json'"
mark_phase  # phase 3: after the recovery
log "$victim_label is back"
# Its cost on its first queries, asked directly rather than through nginx (a
# shard would refuse the points of the other shards' tiles).
if ! sharded; then
  "$LOCATOR_LOAD" --target "$victim" --workload "$WORKLOAD" --mode unary \
    --concurrency 4 --queries 500 --cost-window 500 --format json \
    > "$work/probe.json" 2>> "$work/load.err" || true
fi

load_status=0
wait "${pids[load]}" || load_status=$?
unset "pids[load]"
"$LOCATOR" --target "$victim" --json stats > "$work/end-stats.json" || true

# What the summary needs to know of the setup, as JSON.
if sharded; then
  listeners="\"$nginx_port\": \"front\", \"${port[http-front]}\": \"http front\""
  for ((k = 0; k < SHARDS; k++)); do listeners+=", \"${port[nginx-shard$k]}\": \"shard $k\""; done
  setup="{\"shard\": $victim_shard, \"replica\": $victim_replica, \"shards\": $SHARDS, \"replicas\": $REPLICAS,
    \"routers\": $ROUTERS, \"tiles\": $tile_count, \"tile_points\": $TILE_POINTS,
    \"one_box_exit_code\": $one_box_status, \"nginx_listeners\": {$listeners},
    \"http_front\": \"$http_front\"}"
else
  setup="{\"replica\": $victim_replica}"
fi

python3 - "$work" "$setup" "$load_status" "${SUMMARY_JSON:-}" <<'PY'
import json, os, pathlib, sys

work, setup, load_status, summary_path = sys.argv[1:]
setup = json.loads(setup)
sharded = "shards" in setup
# A fresh self-tuning replica cannot re-tune before retune_every / 4 = 500
# queries (server/core/strategies/self_tuning_locator.cc); a tuning seen earlier was
# restored from its state directory.
EARLIEST_OWN_RETUNE = 500


def load(name):
    text = read(name) if os.path.exists(os.path.join(work, name)) else ""
    return json.loads(text) if text else {}


def read(name):
    return pathlib.Path(work, name).read_text()


def tuned_at_restart(stats):
    """Whether the restarted replica's first GetStats shows learned tuning.

    True when it says it restored its state file and already has hot regions
    (a fresh replica has none), before it could have learned anything
    itself; None when the capture came too late to tell.
    """
    tuning = stats.get("tuning", {})
    restored = bool(tuning.get("persistence", {}).get("restored_from_state"))
    learned = restored and bool(tuning.get("hot_regions"))
    if int(stats.get("queries_served", 0)) >= EARLIEST_OWN_RETUNE:
        return None
    return learned


run, probe = load("load.json"), load("probe.json")
first, end = load("restart-stats.json"), load("end-stats.json")
if not run:
    sys.exit("local-cluster: locator-load printed no report:\n" +
             read("load.err"))
one_box = load("one-box.json") if sharded else {}
if sharded and not one_box:
    sys.exit("local-cluster: the one-box locator-load printed no report:\n" +
             read("one-box.err"))
names = ["before", "during", "after"]
phases = [dict(name=names[i] if i < 3 else f"phase {i + 1}",
               start_seconds=p["start_seconds"], calls=int(p["calls"]),
               failed_calls=int(p["failed_calls"]),
               p50_us=int(p["latency_us"]["p50"]),
               p99_us=int(p["latency_us"]["p99"]))
          for i, p in enumerate(run["phases"])]
# 502s by the nginx listener that answered them (the access log's first
# field is its port).
nginx_502 = {}
for line in read("nginx/access.log").splitlines():
    if " 502 " in line:
        listener = setup.get("nginx_listeners", {}).get(line.split(" ", 1)[0], "front")
        nginx_502[listener] = nginx_502.get(listener, 0) + 1
cold, steady = run["cost_window_means"][:1], run["cost_window_means"][-1:]
restarted = dict(replica=setup["replica"])
if sharded:
    restarted["shard"] = setup["shard"]
restarted.update(
    first_stats_queries_served=int(first.get("queries_served", 0)),
    first_stats_snapshot_version=int(
        first.get("tuning", {}).get("snapshot_version", 0)),
    first_stats_retune_count=int(
        first.get("tuning", {}).get("retune_count", 0)),
    first_stats_hot_regions=len(first.get("tuning", {}).get("hot_regions", [])),
    tuned_at_restart=tuned_at_restart(first) if first else None,
    first_queries_mean_cost=(probe.get("cost_window_means") or [None])[0],
    end_queries_served=int(end.get("queries_served", 0)),
    end_mean_cost_lifetime=end.get("mean_cost_lifetime"))
summary = dict(
    calls=int(run["calls"]), failed_calls=int(run["failed_calls"]),
    errors=run["errors"], load_exit_code=int(load_status),
    p99_us=int(run["latency_us"]["p99"]), phases=phases,
    nginx_502_answers=sum(nginx_502.values()),
    restarted=restarted,
    cluster_cold_mean_cost=cold[0] if cold else None,
    cluster_end_mean_cost=steady[0] if steady else None)
if sharded:
    cluster_rate = float(run["calls_per_second"])
    one_box_rate = float(one_box["calls_per_second"])
    one_box_costs = one_box["cost_window_means"]
    summary.update(
        sharded=dict(shards=setup["shards"], replicas_per_shard=setup["replicas"],
                     routers=setup["routers"], tiles=setup["tiles"],
                     tile_points=setup["tile_points"], http_front=setup["http_front"]),
        nginx_502_by_listener=nginx_502,
        failed_calls_during_kill=phases[1]["failed_calls"] if len(phases) > 1 else None,
        throughput=dict(
            one_box_calls_per_second=one_box_rate,
            cluster_calls_per_second=cluster_rate,
            cluster_to_one_box=cluster_rate / one_box_rate if one_box_rate else None,
            one_box_calls=int(one_box["calls"]),
            one_box_failed_calls=int(one_box["failed_calls"]),
            one_box_errors=one_box["errors"],
            one_box_exit_code=setup["one_box_exit_code"],
            one_box_p99_us=int(one_box["latency_us"]["p99"]),
            one_box_cold_mean_cost=one_box_costs[0] if one_box_costs else None,
            one_box_end_mean_cost=one_box_costs[-1] if one_box_costs else None))

ms = lambda us: f"{us / 1000:.2f} ms"
errors = "".join(f" {code} {int(n)}" for code, n in run["errors"].items())
if sharded:
    # A shard's nginx answers the router, whose channel retries the call;
    # the front answers the client, whose --retry does.
    by_listener = "".join(f", {name}: {n}" for name, n in sorted(nginx_502.items()))
    answered = (f" nginx answered {summary['nginx_502_answers']} calls with 502"
                f" (retried{by_listener})")
else:
    answered = (f" nginx answered {summary['nginx_502_answers']} calls with 502"
                " (retried by the client)")
print(f"totals      {summary['calls']} calls, {summary['failed_calls']} failed"
      f"{errors}; p99 {ms(summary['p99_us'])};{answered}")
for p in phases:
    print(f"{p['name']:<11} from {p['start_seconds']:6.2f} s: {p['calls']:7d} calls,"
          f" {p['failed_calls']} failed, p50 {ms(p['p50_us'])}, p99 {ms(p['p99_us'])}")
r = summary["restarted"]
verdict = {True: "yes", False: "no", None: "unknown (captured too late)"}
label = f"shard {r['shard']} replica {r['replica']}" if sharded else f"replica {r['replica']}"
print(f"restarted   {label}: first GetStats:"
      f" {r['first_stats_queries_served']} queries served, snapshot"
      f" {r['first_stats_snapshot_version']}, {r['first_stats_retune_count']} re-tunes,"
      f" {r['first_stats_hot_regions']} hot regions -> tuned at restart:"
      f" {verdict[r['tuned_at_restart']]}")
fmt = lambda cost: "n/a" if cost is None else f"{cost:.1f}"
if sharded:
    t, s = summary["throughput"], summary["sharded"]
    ratio = "n/a" if t["cluster_to_one_box"] is None else f"{t['cluster_to_one_box']:.2f}"
    print(f"cost        per query, first 500 / last 500: cluster"
          f" {fmt(summary['cluster_cold_mean_cost'])} / {fmt(summary['cluster_end_mean_cost'])},"
          f" one box {fmt(t['one_box_cold_mean_cost'])} / {fmt(t['one_box_end_mean_cost'])}")
    one_box_errors = "".join(f" {code} {int(n)}" for code, n in t["one_box_errors"].items())
    print(f"one box     {t['one_box_calls']} calls, {t['one_box_failed_calls']} failed"
          f"{one_box_errors}; p99 {ms(t['one_box_p99_us'])}")
    print(f"throughput  one box {t['one_box_calls_per_second']:.0f} calls/s,"
          f" cluster ({s['shards']} shards x {s['replicas_per_shard']} replicas,"
          f" {s['routers']} routers) {t['cluster_calls_per_second']:.0f} calls/s:"
          f" ratio {ratio}; {summary['failed_calls_during_kill']} calls failed during the kill")
else:
    print(f"cost        restarted replica's first 500 queries {fmt(r['first_queries_mean_cost'])}"
          f" per query (cluster: first 500 {fmt(summary['cluster_cold_mean_cost'])},"
          f" last 500 {fmt(summary['cluster_end_mean_cost'])})")
if summary_path:
    pathlib.Path(summary_path).write_text(json.dumps(summary, indent=2))
PY

[ "$one_box_status" = 0 ] || fail "the one-box locator-load exited $one_box_status: some calls failed"
[ "$load_status" = 0 ] || fail "locator-load exited $load_status: some calls failed"

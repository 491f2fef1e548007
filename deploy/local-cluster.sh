#!/usr/bin/env bash
# A 3-replica locator cluster on this machine, with no container engine:
# three locatord on loopback, each with its own state directory, behind
# Debian's nginx configured from
# deploy/nginx/locator.conf. It drives locator-load (unary calls, with the
# client's gRPC retry policy) through nginx, SIGKILLs one replica mid-run,
# restarts it a few seconds later on the same port and state directory, and
# prints the totals, p50/p99 before, during and after the failure, and what
# the restarted replica came back with.
#
#   bash deploy/local-cluster.sh                 # 20 s of load
#   DURATION=60 PLOT=cluster.svg bash deploy/local-cluster.sh
#
# Environment (all optional):
#   BUILD_DIR      build tree with the binaries                  (build)
#   NGINX          the nginx binary                              (/usr/sbin/nginx)
#   DURATION       seconds of load                               (20)
#   KILL_AT        seconds into the load when replica 2 dies, at the
#                  earliest once it has saved its tuning        (35% of it)
#   RESTART_AFTER  seconds between the kill and the restart      (3)
#   DATASET        locatord --dataset                            (uniform:200000:1)
#   WORKLOAD       locator-load --workload                       (1-cluster)
#   CONCURRENCY    calls in flight                               (16)
#   RETUNE_EVERY   locatord --retune-every                       (its default)
#   PLOT           also write locator-load's SVG chart here
#   SUMMARY_JSON   also write the summary as JSON here (the ctest reads it)
#   KEEP_DIR=1     keep the working directory (logs, nginx.conf) and say where
#
# Exit code: 0 when every call succeeded, 1 when any failed or the cluster
# could not be set up. Every process it starts is stopped on exit.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

BUILD_DIR="${BUILD_DIR:-$repo/build}"
LOCATORD="$BUILD_DIR/server/locatord"
LOCATOR="$BUILD_DIR/client/locator"
LOCATOR_LOAD="$BUILD_DIR/client/locator-load"
NGINX="${NGINX:-/usr/sbin/nginx}"
DURATION="${DURATION:-20}"
KILL_AT="${KILL_AT:-$(python3 -c "print(round($DURATION * 0.35, 1))")}"
RESTART_AFTER="${RESTART_AFTER:-3}"
DATASET="${DATASET:-uniform:200000:1}"
WORKLOAD="${WORKLOAD:-1-cluster}"
CONCURRENCY="${CONCURRENCY:-16}"
retune_flags=()
if [ -n "${RETUNE_EVERY:-}" ]; then retune_flags=(--retune-every "$RETUNE_EVERY"); fi
VICTIM=2  # the replica that is killed and restarted

for binary in "$LOCATORD" "$LOCATOR" "$LOCATOR_LOAD" "$NGINX"; do
  [ -x "$binary" ] || { echo "local-cluster: $binary not found (build first)" >&2; exit 1; }
done

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
# and kill -0 succeeds on a zombie).
alive() { [ -r "/proc/$1/status" ] && ! grep -q '^State:[[:space:]]*Z' "/proc/$1/status"; }

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

read -r -a ports <<< "$(free_ports 4)"
nginx_port=${ports[0]}

# start_replica I: starts replica I on its port (again, after a kill) and
# waits until it listens; SERVING comes later, once the dataset is built.
start_replica() {
  local i=$1
  mkdir -p "$work/replica$i/state"
  "$LOCATORD" --dataset "$DATASET" --listen "127.0.0.1:${ports[$i]}" \
    --state-dir "$work/replica$i/state" "${retune_flags[@]}" \
    >> "$work/replica$i/locatord.log" 2>&1 &
  pids[replica$i]=$!
  wait_for 60 $! "$work/replica$i/locatord.log" \
    grep -q "listening on 127.0.0.1:${ports[$i]}\$" "$work/replica$i/locatord.log"
}

health() { "$LOCATOR" --target "$1" --deadline-ms 1000 health; }

log "3 replicas of $DATASET on ports ${ports[*]:1}, each with a state dir"
for i in 1 2 3; do start_replica $i; done
for i in 1 2 3; do
  wait_for 300 "${pids[replica$i]}" "$work/replica$i/locatord.log" health "127.0.0.1:${ports[$i]}"
done

# nginx: deploy/nginx/locator.conf with its upstream and listen address
# rewritten, inside a main config that keeps every file in $work.
mkdir -p "$work/nginx"
python3 - "$repo/deploy/nginx/locator.conf" "$work/nginx/locator.conf" "$nginx_port" "${ports[@]:1}" <<'PY'
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
cat > "$work/nginx/nginx.conf" <<EOF
daemon off;
worker_processes 1;
pid $work/nginx/nginx.pid;
error_log $work/nginx/error.log warn;
events { worker_connections 1024; }
http {
  access_log $work/nginx/access.log;
  client_body_temp_path $work/nginx/body;
  proxy_temp_path $work/nginx/proxy;
  fastcgi_temp_path $work/nginx/fastcgi;
  uwsgi_temp_path $work/nginx/uwsgi;
  scgi_temp_path $work/nginx/scgi;
  include $work/nginx/locator.conf;
}
EOF
nginx_cmd=("$NGINX" -p "$work/nginx" -c "$work/nginx/nginx.conf" -e "$work/nginx/error.log")
"${nginx_cmd[@]}" -t -q || fail "nginx -t rejected $work/nginx/nginx.conf"
"${nginx_cmd[@]}" &
pids[nginx]=$!
target="127.0.0.1:$nginx_port"
wait_for 30 "${pids[nginx]}" "$work/nginx/error.log" health "$target"
log "nginx on $target"

plot_args=()
if [ -n "${PLOT:-}" ]; then plot_args=(--plot "$PLOT"); fi
log "locator-load: $WORKLOAD, unary, $CONCURRENCY in flight, ${DURATION} s, --retry; replica $VICTIM dies at ${KILL_AT} s"
"$LOCATOR_LOAD" --target "$target" --workload "$WORKLOAD" --mode unary \
  --concurrency "$CONCURRENCY" --duration "$DURATION" --retry --phase-signal \
  --format json "${plot_args[@]}" > "$work/load.json" 2> "$work/load.err" &
pids[load]=$!

# Starts the next phase of locator-load's report.
mark_phase() {
  alive "${pids[load]}" || fail "the load ended before the failover did: raise DURATION"
  kill -USR1 "${pids[load]}"
}

victim="127.0.0.1:${ports[$VICTIM]}"
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
    fail "replica $VICTIM saved no tuning state before the load ended: raise DURATION or lower RETUNE_EVERY"
  [ $SECONDS -lt $save_deadline ] || fail "replica $VICTIM saved no tuning state in 60 s"
  sleep 0.1
done
mark_phase  # phase 2: during the failure (calls it breaks count there)
kill -KILL "${pids[replica$VICTIM]}"
wait "${pids[replica$VICTIM]}" 2>/dev/null || true
unset "pids[replica$VICTIM]"
log "SIGKILL replica $VICTIM ($victim)"

sleep "$RESTART_AFTER"
start_replica $VICTIM
# Its first GetStats, as early as it answers: before nginx, which marked it
# failed for fail_timeout (5 s), sends it traffic, it shows what the replica
# came back with rather than what it has learned since.
wait_for 300 "${pids[replica$VICTIM]}" "$work/replica$VICTIM/locatord.log" \
  sh -c "'$LOCATOR' --target $victim --deadline-ms 1000 --json stats > '$work/restart-stats.json'"
mark_phase  # phase 3: after the recovery
log "replica $VICTIM is back"
# Its cost on its first queries, asked directly rather than through nginx.
"$LOCATOR_LOAD" --target "$victim" --workload "$WORKLOAD" --mode unary \
  --concurrency 4 --queries 500 --cost-window 500 --format json \
  > "$work/probe.json" 2>> "$work/load.err" || true

load_status=0
wait "${pids[load]}" || load_status=$?
unset "pids[load]"
"$LOCATOR" --target "$victim" --json stats > "$work/end-stats.json" || true

python3 - "$work" "$VICTIM" "$load_status" "${SUMMARY_JSON:-}" <<'PY'
import json, os, pathlib, sys

work, victim, load_status, summary_path = sys.argv[1:]
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
names = ["before", "during", "after"]
phases = [dict(name=names[i] if i < 3 else f"phase {i + 1}",
               start_seconds=p["start_seconds"], calls=int(p["calls"]),
               failed_calls=int(p["failed_calls"]),
               p50_us=int(p["latency_us"]["p50"]),
               p99_us=int(p["latency_us"]["p99"]))
          for i, p in enumerate(run["phases"])]
nginx_502 = sum(" 502 " in line for line in read("nginx/access.log").splitlines())
cold, steady = run["cost_window_means"][:1], run["cost_window_means"][-1:]
summary = dict(
    calls=int(run["calls"]), failed_calls=int(run["failed_calls"]),
    errors=run["errors"], load_exit_code=int(load_status),
    p99_us=int(run["latency_us"]["p99"]), phases=phases,
    nginx_502_answers=nginx_502,
    restarted=dict(
        replica=int(victim),
        first_stats_queries_served=int(first.get("queries_served", 0)),
        first_stats_snapshot_version=int(
            first.get("tuning", {}).get("snapshot_version", 0)),
        first_stats_retune_count=int(
            first.get("tuning", {}).get("retune_count", 0)),
        first_stats_hot_regions=len(first.get("tuning", {}).get("hot_regions", [])),
        tuned_at_restart=tuned_at_restart(first) if first else None,
        first_queries_mean_cost=(probe.get("cost_window_means") or [None])[0],
        end_queries_served=int(end.get("queries_served", 0)),
        end_mean_cost_lifetime=end.get("mean_cost_lifetime")),
    cluster_cold_mean_cost=cold[0] if cold else None,
    cluster_end_mean_cost=steady[0] if steady else None)

ms = lambda us: f"{us / 1000:.2f} ms"
errors = "".join(f" {code} {int(n)}" for code, n in run["errors"].items())
print(f"totals      {summary['calls']} calls, {summary['failed_calls']} failed"
      f"{errors}; p99 {ms(summary['p99_us'])};"
      f" nginx answered {nginx_502} calls with 502 (retried by the client)")
for p in phases:
    print(f"{p['name']:<11} from {p['start_seconds']:6.2f} s: {p['calls']:7d} calls,"
          f" {p['failed_calls']} failed, p50 {ms(p['p50_us'])}, p99 {ms(p['p99_us'])}")
r = summary["restarted"]
verdict = {True: "yes", False: "no", None: "unknown (captured too late)"}
print(f"restarted   replica {victim}: first GetStats:"
      f" {r['first_stats_queries_served']} queries served, snapshot"
      f" {r['first_stats_snapshot_version']}, {r['first_stats_retune_count']} re-tunes,"
      f" {r['first_stats_hot_regions']} hot regions -> tuned at restart:"
      f" {verdict[r['tuned_at_restart']]}")
fmt = lambda cost: "n/a" if cost is None else f"{cost:.1f}"
print(f"cost        restarted replica's first 500 queries {fmt(r['first_queries_mean_cost'])}"
      f" per query (cluster: first 500 {fmt(summary['cluster_cold_mean_cost'])},"
      f" last 500 {fmt(summary['cluster_end_mean_cost'])})")
if summary_path:
    pathlib.Path(summary_path).write_text(json.dumps(summary, indent=2))
PY

[ "$load_status" = 0 ] || fail "locator-load exited $load_status: some calls failed"

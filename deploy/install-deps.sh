#!/usr/bin/env bash
# Installs every Debian package that locator's build, tests and benchmarks
# need, then the npm packages pinned by the lockfiles in NPM_DIRS (with
# Debian's npm). Idempotent: when all packages are present it changes
# nothing and does not touch the network. Prints one line per step; apt's own output goes to
# a log file ($LOCATOR_DEPS_LOG, default /tmp/locator-install-deps.log) that
# is shown if a step fails.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libcgal-dev libgmp-dev libmpfr-dev libxxhash-dev
  libboost-dev
  libprotobuf-dev protobuf-compiler
  libgrpc++-dev libgrpc-dev protobuf-compiler-grpc
  libgtest-dev libgmock-dev
  prometheus-cpp-dev
  libgdal-dev gdal-bin libproj-dev proj-bin libgeotiff-dev
  libpng-dev libdeflate-dev
  python3 python3-grpcio python3-protobuf python3-numpy python3-pyproj
  libssl-dev
  chromium nginx openssl curl
  clang libclang-rt-14-dev lld
)

LOG="${LOCATOR_DEPS_LOG:-/tmp/locator-install-deps.log}"
REPO="$(cd "$(dirname "$0")/.." && pwd)"
# The JavaScript locator embeds or runs, each directory's package-lock.json
# installed into its node_modules by `npm ci`: MapLibre GL JS for the web map,
# @here/quantized-mesh-decoder for the quantized-mesh tests' independent decoder.
NPM_DIRS=(client/web tests/server/tiles/quantized_mesh_decoder)

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done
# Debian's npm, unless an npm is installed already (a nodejs package from
# elsewhere, such as NodeSource's, bundles one and conflicts with Debian's).
if ! command -v npm > /dev/null; then missing+=(npm); fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
: > "$LOG"

# step DESCRIPTION COMMAND...: runs COMMAND with its output in the log, and
# prints one line; on failure, the log's tail and the log's path.
step() {
  local what=$1 start=$SECONDS
  shift
  printf 'install-deps: %s ... ' "$what"
  if "$@" >> "$LOG" 2>&1; then
    echo "ok ($((SECONDS - start)) s)"
  else
    echo "FAILED"
    echo "---- last lines of $LOG ----"
    tail -n 40 "$LOG"
    exit 1
  fi
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
else
  step "updating the package lists" $SUDO apt-get update
  step "installing ${#missing[@]} packages (${missing[*]})" \
    env DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y \
    --no-install-recommends "${missing[@]}"
fi

# npm_ci DIR: installs DIR's lockfile; a copy of the lockfile in
# node_modules marks an install that is up to date.
npm_ci() {
  local dir=$REPO/$1
  if cmp -s "$dir/package-lock.json" "$dir/node_modules/.locator-lock.json"; then
    echo "install-deps: $1/node_modules is up to date"
    return
  fi
  step "npm ci in $1" npm ci --prefix "$dir" --no-audit --no-fund \
    --ignore-scripts
  cp "$dir/package-lock.json" "$dir/node_modules/.locator-lock.json"
}
for dir in "${NPM_DIRS[@]}"; do npm_ci "$dir"; done
echo "install-deps: done; the installers' output is in $LOG"

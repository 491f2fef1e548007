#!/usr/bin/env bash
# Installs every Debian package that locator's build, tests and benchmarks
# need, and (with Debian's npm) the pinned npm packages of the tests
# (tests/server/tiles/quantized_mesh_decoder: the independent quantized-mesh
# decoder). Idempotent: when all are present it changes nothing and does
# not touch the network. Prints one line per step; apt's own output goes to
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
  libpng-dev
  python3 python3-grpcio python3-protobuf python3-numpy
  libssl-dev
  chromium nginx openssl curl
  clang libclang-rt-14-dev lld
)

LOG="${LOCATOR_DEPS_LOG:-/tmp/locator-install-deps.log}"

missing=()
for pkg in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

# node and npm: Debian's, unless a node of another origin (which conflicts
# with Debian's npm) already brings its own npm.
if ! command -v node > /dev/null || ! command -v npm > /dev/null; then
  missing+=(nodejs npm)
fi

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

# The npm packages, exactly as package-lock.json pins them, into the
# folder's node_modules (git-ignored), where the tests look.
DECODER_DIR="$(cd "$(dirname "$0")/.." && pwd)/tests/server/tiles/quantized_mesh_decoder"
DECODER_VERSION=$(sed -n 's/.*"@here\/quantized-mesh-decoder": "\(.*\)".*/\1/p' \
  "$DECODER_DIR/package.json")
INSTALLED="$DECODER_DIR/node_modules/@here/quantized-mesh-decoder/package.json"
if [ -f "$INSTALLED" ] && grep -q "\"version\": \"$DECODER_VERSION\"" "$INSTALLED"; then
  echo "install-deps: npm packages present"
else
  step "installing the tests' npm packages (npm ci)" \
    npm ci --prefix "$DECODER_DIR" --no-audit --no-fund
fi
echo "install-deps: done; apt's output is in $LOG"

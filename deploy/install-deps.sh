#!/usr/bin/env bash
# Installs every Debian package that locator's build, tests and benchmarks
# need. Idempotent: when all packages are present it changes nothing and does
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

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
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

step "updating the package lists" $SUDO apt-get update
step "installing ${#missing[@]} packages (${missing[*]})" \
  env DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y \
  --no-install-recommends "${missing[@]}"
echo "install-deps: done; apt's output is in $LOG"

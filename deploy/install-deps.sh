#!/usr/bin/env bash
# Installs every Debian package that locator's build, tests and benchmarks need.
# Idempotent: when all packages are present it changes nothing and does not touch
# the network.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libcgal-dev libgmp-dev libmpfr-dev
  libboost-dev libboost-program-options-dev
  libprotobuf-dev protobuf-compiler
  libgrpc++-dev libgrpc-dev protobuf-compiler-grpc
  libgtest-dev libgmock-dev
  prometheus-cpp-dev
  python3 python3-grpcio python3-protobuf
  libssl-dev
  libgdal-dev gdal-bin libproj-dev proj-bin
  chromium nginx openssl curl
  clang libclang-rt-14-dev
)

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
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"

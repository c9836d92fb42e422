#!/usr/bin/env bash
# Installs the Debian packages collide2d needs to build, test and benchmark, when any is missing.
set -euo pipefail
packages=(build-essential cmake pkg-config python3 clang-format libeigen3-dev libhwy-dev libbox2d-dev googletest libgtest-dev libbenchmark-dev libboost-dev nlohmann-json3-dev clang libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y "${missing[@]}"
fi

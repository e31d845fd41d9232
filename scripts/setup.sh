#!/usr/bin/env bash
# Installs what roughgas needs from Debian's packages (only what is missing) and builds Release into build/.
# Idempotent and quiet when everything is already there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

packages=(g++ cmake make pkg-config libeigen3-dev libfftw3-dev libboost-dev libboost-math-dev
          libgtest-dev libbenchmark-dev libtomlplusplus-dev libcli11-dev libfmt-dev
          python3-numpy python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

build="${ROUGHGAS_BUILD_DIR:-$root/build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
log="$build/build.log"
if ! cmake --build "$build" --parallel "$(nproc)" >"$log" 2>&1; then
  grep -E -A5 "error|Error" "$log" | head -80 >&2
  echo "setup: build failed (full log: $log)" >&2
  exit 1
fi

#!/usr/bin/env bash
# Installs what roughgas needs from Debian's packages (only what is missing) and builds Release into build/.
# Idempotent and quiet when everything is already there.
# Usage: scripts/setup.sh
set -euo pipefail
for a in "$@"; do
  case "$a" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
done
root=$(cd "$(dirname "$0")/.." && pwd)

"$root/scripts/apt_install.sh" --base

build="${ROUGHGAS_BUILD_DIR:-$root/build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  # Ninja: the objects of a target compile while the libraries it links are still being built
  # (with Makefiles one core idled while src/dsmc/run.cpp, the longest object, compiled).
  # ROUGHGAS_CMAKE_ARGS: extra configure arguments (.ci/run leaves the benchmarks out).
  cmake -G Ninja -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release ${ROUGHGAS_CMAKE_ARGS:-} >/dev/null
fi
"$root/scripts/cmake_build.sh" setup "$build/build.log" "$build" --parallel "$(nproc)"

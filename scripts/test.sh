#!/usr/bin/env bash
# Sets up (installs missing Debian packages, builds Release) and runs every test with ctest.
# Usage: scripts/test.sh [CTEST_ARGS]   (extra arguments go to ctest, e.g. scripts/test.sh -L unit)
set -euo pipefail
case "${1:-}" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
build="${ROUGHGAS_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure --parallel "$(nproc)" "$@"

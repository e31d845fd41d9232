#!/usr/bin/env bash
# cmake_build.sh NAME LOG ARGS...: runs `cmake --build ARGS...` quietly into LOG; on failure prints
# the errors and "NAME: build failed (full log: LOG)" on stderr and exits 1. Used by setup.sh,
# sanitize.sh and fuzz.sh.
set -euo pipefail
case "${1:-}" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
name="$1" log="$2"
shift 2
mkdir -p "$(dirname "$log")"
if ! cmake --build "$@" >"$log" 2>&1; then
  grep -E -A5 "error|Error" "$log" | head -80 >&2
  echo "$name: build failed (full log: $log)" >&2
  exit 1
fi

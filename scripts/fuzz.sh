#!/usr/bin/env bash
# Fuzzes the case-file parser and validator (tests/fuzz/case_file_fuzz.cpp) for SECONDS (default
# 60) with libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer (clang; CMakePresets.json
# "fuzz", build dir build-fuzz/). The seed corpus is cases/*.toml, copied to a scratch directory
# (the inputs libFuzzer adds go there, never into cases/). Exit 0: no crash, no sanitizer report.
# Prints the corpus size and the number of runs (docs/reliability.md quotes them).
# Usage: scripts/fuzz.sh [SECONDS]
set -euo pipefail
for a in "$@"; do
  case "$a" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
seconds="${1:-60}"
"$root/scripts/apt_install.sh" --base clang libclang-rt-14-dev libomp-14-dev
cd "$root"
[ -f build-fuzz/CMakeCache.txt ] || cmake --preset fuzz >/dev/null
"$root/scripts/cmake_build.sh" fuzz "$root/build-fuzz/build.log" --preset fuzz
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp cases/*.toml "$corpus/"
seeds=$(ls "$corpus" | wc -l)
out="$root/build-fuzz/fuzz.log"
if ! build-fuzz/case_file_fuzz -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$root/build-fuzz/" \
     "$corpus" >"$out" 2>&1; then
  tail -60 "$out" >&2
  echo "fuzz: FAILED (crash input in build-fuzz/crash-*; log $out)" >&2
  exit 1
fi
runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out" | grep -o '[0-9]*$')
echo "fuzz: ${seconds} s, ${runs} inputs, seed corpus ${seeds} case files, corpus grew to $(ls "$corpus" | wc -l): no failure"

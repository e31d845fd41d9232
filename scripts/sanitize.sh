#!/usr/bin/env bash
# Builds roughgas with AddressSanitizer and UndefinedBehaviorSanitizer (gcc; CMakePresets.json
# "sanitize", build dir build-sanitize/) and runs the unit tests there (ctest -L unit: every test
# area but the stress, validation and e2e suites, which run in scripts/test.sh). Only the binaries those
# tests need are built, with -O1 and -g1 (line tables: enough for the sanitizers' stack traces, and
# a third less compile time than -g). Any sanitizer report fails the test it occurs in
# (-fno-sanitize-recover, halt_on_error). Ten unit tests are left out (GTEST_FILTER in the preset):
# statistical checks that repeat code the other tests already run thousands of times over (the
# eps^T table against 12 000 direct integrations, collision-rate and step-length statistics, theta
# against theory, a threads comparison, the shipped cooling cases' scaled states); under the sanitizers they took 5 of the job's 11 CPU
# minutes. They run in scripts/test.sh. UndefinedBehaviorSanitizer makes the engine's
# instantiations slow to compile (in one file, .ci/run took 21 min on a Zen 1 VM, that file alone
# 165-196 s); they are spread over five files that compile on both cores (src/dsmc/drive_*.cpp).
# ROUGHGAS_SANITIZE_PRESET=sanitize-address builds AddressSanitizer only (build-sanitize-address/):
# .ci/run chooses it on a machine too slow for both sanitizers within its 20 minutes.
# Usage: scripts/sanitize.sh [CTEST_ARGS]   (extra arguments go to ctest)
set -euo pipefail
case "${1:-}" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/apt_install.sh" --base
cd "$root"
preset="${ROUGHGAS_SANITIZE_PRESET:-sanitize}"
case "$preset" in sanitize | sanitize-address) ;; *) echo "sanitize.sh: ROUGHGAS_SANITIZE_PRESET must be sanitize or sanitize-address" >&2; exit 2 ;; esac
dir="build-$preset"
[ -f "$dir/CMakeCache.txt" ] || cmake --preset "$preset" >/dev/null
"$root/scripts/cmake_build.sh" "$preset" "$root/$dir/build.log" --preset "$preset"
ctest --preset "$preset" "$@"

#!/usr/bin/env bash
# Builds roughgas with AddressSanitizer (gcc; CMakePresets.json "sanitize", build dir
# build-sanitize/) and runs the unit tests there (ctest -L unit: every test
# area but the stress, validation and e2e suites, which run in scripts/test.sh). Only the binaries those
# tests need are built, with -O1 and -g1 (line tables: enough for the sanitizers' stack traces, and
# a third less compile time than -g). Any sanitizer report fails the test it occurs in
# (-fno-sanitize-recover, halt_on_error). Nine unit tests are left out (GTEST_FILTER in the preset):
# statistical checks that repeat code the other tests already run thousands of times over (the
# eps^T table against 12 000 direct integrations, collision-rate and step-length statistics, theta
# against theory, a threads comparison); under the sanitizers they took 5 of the job's 11 CPU
# minutes. They run in scripts/test.sh. UndefinedBehaviorSanitizer was part of this build until
# session 11: on that session's Zen 1 VM it made the build a quarter longer and .ci/run 21 min; it
# stays in the fuzz build (scripts/fuzz.sh, clang), and -fsanitize=undefined may be added back here
# on a faster machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/apt_install.sh" --base
cd "$root"
[ -f build-sanitize/CMakeCache.txt ] || cmake --preset sanitize >/dev/null
"$root/scripts/cmake_build.sh" sanitize "$root/build-sanitize/build.log" --preset sanitize
ctest --preset sanitize "$@"

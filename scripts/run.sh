#!/usr/bin/env bash
# Sets up and runs the main job on a case (default: cases/ice.toml).
# Until the DSMC lands, the main job is the restitution tabulation of the contact model:
# it writes out/<case>/normal.csv and tangential.csv and draws them to PNG.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
case_file="${1:-$root/cases/ice.toml}"
name=$(basename "$case_file" .toml)
out="${ROUGHGAS_OUT:-$root/out/$name}"
"${ROUGHGAS_BUILD_DIR:-$root/build}/roughgas" restitution "$case_file" --out "$out" --force
# The ice cases also draw the measured ice law their dissipation A was fitted to (paper Fig. 1).
plot_args=()
case "$name" in ice*) plot_args+=(--bridges) ;; esac
"$root/scripts/python3" "$root/scripts/plot_restitution.py" "$out" "${plot_args[@]}"
echo "run: results in $out"

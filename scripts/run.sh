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
"$root/scripts/python3" "$root/scripts/plot_restitution.py" "$out"
echo "run: results in $out"

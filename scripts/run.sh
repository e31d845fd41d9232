#!/usr/bin/env bash
# Sets up (Debian packages, Release build) and runs the main job on a case (default: cases/ice.toml):
#  - cases with a contact model ([material]): `roughgas restitution` tabulates it and
#    scripts/plot_restitution.py draws it (the paper's Figs. 1 and 2; the ice cases add the measured
#    ice law their dissipation was fitted to);
#  - every case: `roughgas run` (the DSMC) writes moments.csv and the files of its kind of run, and
#    scripts/plot_run.py draws what the run is: the cooling panels (plot.py), uniform shear flow
#    (plot_shear.py), and for a box its profiles, spectra and fields.
# Results go to out/<case>/ (or $ROUGHGAS_OUT); earlier results there are replaced.
# Usage: scripts/run.sh [CASE]
set -euo pipefail
for a in "$@"; do
  case "$a" in -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;; esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
case_file="${1:-$root/cases/ice.toml}"
name=$(basename "$case_file" .toml)
out="${ROUGHGAS_OUT:-$root/out/$name}"
roughgas="${ROUGHGAS_BUILD_DIR:-$root/build}/roughgas"
mkdir -p "$out"
# Both commands share the contact tables through one cache file (built once).
cache=(--set "contact.cache_file=\"$out/tables.cache\"")
if grep -q '^\[material\]' "$case_file"; then
  "$roughgas" restitution "$case_file" --out "$out" --force "${cache[@]}"
  plot_args=()
  case "$name" in ice*) plot_args+=(--bridges) ;; esac
  "$root/scripts/python3" "$root/scripts/plot_restitution.py" "$out" "${plot_args[@]}"
else
  cache=()
fi
"$roughgas" run "$case_file" --out "$out" --force "${cache[@]}"
"$root/scripts/python3" "$root/scripts/plot_run.py" "$out"
echo "run: results in $out"

#!/usr/bin/env bash
# Redraws the pictures in docs/ from the shipped cases, each with the command named in the doc
# that shows it (about five minutes on two cores, most of it the ice cases' eps^T tables and the driven cases):
#   docs/ice_normal.png        roughgas restitution cases/ice.toml, plot_restitution.py --bridges
#   docs/fig2c_tangential.png  roughgas restitution cases/ice_fig2c.toml, plot_restitution.py
#   docs/hcs_mixture.png       roughgas run cases/hcs_mixture.toml, plot.py
#   docs/mpemba.png            roughgas run cases/mpemba_{prepare_hot,prepare_cold,hot,cold}.toml, mpemba.py
#   docs/kovacs.png            roughgas run cases/kovacs_rough.toml, kovacs.py
#   docs/usf_rough.png         roughgas run cases/usf_rough.toml, plot_shear.py
#   docs/usf_sweep_alpha.png   roughgas sweep of cases/usf_rough.toml over alpha, plot_shear.py --sweep
#   docs/box_*.png             roughgas run cases/box_{couette,fourier,thermal_walls,heated_bed,usf,shear_mode}.toml,
#                              plot_profiles.py (the shear mode's last block: --from 60)
#   docs/box_shear_mode_spectra.png  the same run of box_shear_mode.toml, plot_spectra.py
#   docs/box_cooling_slab_spectra.png  roughgas run cases/box_cooling_slab.toml, plot_spectra.py --times 5
#   docs/box_cooling_slab_fields.png   the same run of box_cooling_slab.toml, plot_fields.py --from 140 --times 4
#   docs/box_cooling_slab_{medium,strong}_roughness_fields.png  roughgas run of those cases, plot_fields.py
#                              --from 20 and --from 300, --times 4
#   docs/box_cooling_3d_{spectra,fields}.png  roughgas run cases/box_cooling_3d.toml, plot_spectra.py, plot_fields.py
#   docs/box_cooling_3d_{medium,strong}_roughness_fields.png  the rough cubes, plot_fields.py --from 60 and 300
#   docs/box_heated_white_noise_spectra.png  roughgas run cases/box_heated_white_noise.toml, plot_spectra.py --times 4
# Not redrawn here (minutes of CPU each): docs/accuracy.png, the work-precision study of
# docs/accuracy.md (scripts/bench_accuracy.py); docs/transport_errors.png, the study of
# docs/validation.md (scripts/transport_errors.py --collisions 3000 --plot docs/transport_errors.png,
# ten minutes on two cores) and docs/conductivity_errors.png (transport_errors.py --flow fourier
# --collisions 8000 --plot docs/conductivity_errors.png, forty minutes); docs/instability_map.png, its instability map
# (scripts/instability_map.py --seeds 8 --plot docs/instability_map.png, eight minutes on two cores).
# Usage: scripts/docs_figures.sh [WORK_DIR]   (default out/docs_figures; the build must exist)
set -euo pipefail
case "${1:-}" in
  -h | --help) sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; exit 0 ;;
  -*) echo "docs_figures.sh: unknown option $1 (usage: scripts/docs_figures.sh [WORK_DIR])" >&2; exit 2 ;;
esac
root=$(cd "$(dirname "$0")/.." && pwd)
work="${1:-$root/out/docs_figures}"
roughgas="${ROUGHGAS_BUILD_DIR:-$root/build}/roughgas"
py="$root/scripts/python3"
mkdir -p "$work"

"$roughgas" restitution "$root/cases/ice.toml" --out "$work/ice" --force
"$py" "$root/scripts/plot_restitution.py" "$work/ice" --bridges
cp "$work/ice/normal.png" "$root/docs/ice_normal.png"

"$roughgas" restitution "$root/cases/ice_fig2c.toml" --out "$work/ice_fig2c" --force
"$py" "$root/scripts/plot_restitution.py" "$work/ice_fig2c"
cp "$work/ice_fig2c/tangential.png" "$root/docs/fig2c_tangential.png"

"$roughgas" run "$root/cases/hcs_mixture.toml" --out "$work/hcs_mixture" --force --quiet
"$py" "$root/scripts/plot.py" "$work/hcs_mixture"
cp "$work/hcs_mixture/moments.png" "$root/docs/hcs_mixture.png"

for s in hot cold; do
  "$roughgas" run "$root/cases/mpemba_prepare_$s.toml" --out "$work/mpemba_prepare_$s" --force --quiet
  "$roughgas" run "$root/cases/mpemba_$s.toml" --out "$work/mpemba_$s" --force --quiet \
      --set initial.from="$work/mpemba_prepare_$s"
done
"$py" "$root/scripts/mpemba.py" "$work/mpemba_hot" "$work/mpemba_cold" --out "$root/docs/mpemba.png"

"$roughgas" run "$root/cases/kovacs_rough.toml" --out "$work/kovacs_rough" --force --quiet
"$py" "$root/scripts/kovacs.py" "$work/kovacs_rough" --out "$root/docs/kovacs.png"

"$roughgas" run "$root/cases/usf_rough.toml" --out "$work/usf_rough" --force --quiet
"$py" "$root/scripts/plot_shear.py" "$work/usf_rough"
cp "$work/usf_rough/moments_shear.png" "$root/docs/usf_rough.png"

"$roughgas" sweep "$root/cases/usf_rough.toml" --param collision.alpha=0.5:0.95:10 --out "$work/usf_alpha" \
    --force --quiet --set run.particles=20000 --set run.end=200 --set run.replicas=1 \
    --set species.0.temperature=0.03 --set species.0.rotational_temperature=0.007
"$py" "$root/scripts/plot_shear.py" --sweep "$work/usf_alpha"
cp "$work/usf_alpha/sweep.png" "$root/docs/usf_sweep_alpha.png"

for c in couette fourier thermal_walls heated_bed usf shear_mode; do
  "$roughgas" run "$root/cases/box_$c.toml" --out "$work/box_$c" --force --quiet
  if [ "$c" = shear_mode ]; then
    "$py" "$root/scripts/plot_profiles.py" "$work/box_$c" --from 60
    "$py" "$root/scripts/plot_spectra.py" "$work/box_$c" --out "$root/docs/box_shear_mode_spectra.png"
  else
    "$py" "$root/scripts/plot_profiles.py" "$work/box_$c"
  fi
  cp "$work/box_$c/profiles.png" "$root/docs/box_$c.png"
done
"$roughgas" run "$root/cases/box_cooling_slab.toml" --out "$work/box_cooling_slab" --force --quiet
"$py" "$root/scripts/plot_spectra.py" "$work/box_cooling_slab" --times 5 --out "$root/docs/box_cooling_slab_spectra.png"
"$py" "$root/scripts/plot_fields.py" "$work/box_cooling_slab" --from 140 --times 4 \
    --out "$root/docs/box_cooling_slab_fields.png"
"$roughgas" run "$root/cases/box_cooling_3d.toml" --out "$work/box_cooling_3d" --force --quiet
"$py" "$root/scripts/plot_spectra.py" "$work/box_cooling_3d" --times 5 --out "$root/docs/box_cooling_3d_spectra.png"
"$py" "$root/scripts/plot_fields.py" "$work/box_cooling_3d" --from 150 --times 4 --out "$root/docs/box_cooling_3d_fields.png"
for c in medium:60 strong:300; do
  r="box_cooling_3d_${c%%:*}_roughness"
  "$roughgas" run "$root/cases/$r.toml" --out "$work/$r" --force --quiet
  "$py" "$root/scripts/plot_fields.py" "$work/$r" --from "${c##*:}" --times 4 --out "$root/docs/${r}_fields.png"
done
for c in medium:20 strong:300; do
  r="box_cooling_slab_${c%%:*}_roughness"
  "$roughgas" run "$root/cases/$r.toml" --out "$work/$r" --force --quiet
  "$py" "$root/scripts/plot_fields.py" "$work/$r" --from "${c##*:}" --times 4 --out "$root/docs/${r}_fields.png"
done
"$roughgas" run "$root/cases/box_heated_white_noise.toml" --out "$work/box_heated_white_noise" --force --quiet
"$py" "$root/scripts/plot_spectra.py" "$work/box_heated_white_noise" --times 4 \
    --out "$root/docs/box_heated_white_noise_spectra.png"

echo "docs_figures: redrew docs/ice_normal.png, fig2c_tangential.png, hcs_mixture.png, usf_rough.png, usf_sweep_alpha.png, box_*.png (with the spectra of box_shear_mode, box_cooling_slab, box_cooling_3d and box_heated_white_noise, and the fields of the three cooling slabs and the three cubes)"

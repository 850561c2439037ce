#!/usr/bin/env bash
# Full-size identity tests of `colza calibrate` (issue 6): synthetic "measured" data made by
# colza at known parameters other than the paper's, then recovered by the paper's procedure
# and by the sequential mode.
#   density:     truth rho_p = 1280 kg/m^3 (Table 1 otherwise)  -> its bulk density
#   compression: truth kn_p = 470e3 N/m, mu_pp = 0.33, rho_p = 1230 -> its compression curve
#                (seed 1), with the scatter of five seeds as its uncertainties and correlation
#   shear:       truth Cn = 1.8 N, Cs = 3.3 N (Table 2 otherwise) -> its shear curves at 25.75
#                and 78.75 kPa (the paper's box, 30 mm of shear); the design runs are the same
#                runs as data/calibration/shear.toml's: a runs-shear directory copied from
#                such a calibration's runs/ is reused
#   shear_peak:  the same truth and design, targets from the curves' peaks (strength =
#                "peak", 1 mm), 8 mm of shear per design run (about 5 min per point)
# density + compression: about 45 min on 2 cores (the compression truth is five runs). shear: hours (each design point is two
# 30 mm loads of 11342 spheres, 10-15 min each on 2 cores; the settling of the sample ~11 min;
# 12 loads for the paper mode, 6-14 for the sequential mode, plus the truth).
# Calibrations reuse finished design runs, so an interrupted run continues where it stopped.
# Usage: scripts/calibration-identity-full.sh [WORKDIR [STAGE ...]]
#        (default /tmp/colza-identity-full, stages density compression; add shear and
#        shear_peak explicitly)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
colza="$root/build/src/colza"
work="${1:-/tmp/colza-identity-full}"
shift || true
stages=("$@")
[ ${#stages[@]} -eq 0 ] && stages=(density compression)
wants() { local x; for x in "${stages[@]}"; do [ "$x" = "$1" ] && return 0; done; return 1; }
mkdir -p "$work"
cd "$work"
oed="$root/data/oedometer.toml"
density_stop=(--set oedometer.stop_force=200.0 --set oedometer.fit_force_max=190.0 --set oedometer.fit_force_min=10.0)

if wants density; then
  "$colza" run oedometer --config "$oed" --set particle.density=1280 "${density_stop[@]}" --out truth-density --force --quiet
  bulk=$(python3 -c "import json; print(repr(json.load(open('truth-density/summary.json'))['bulk_density']))")
  sed -e "s|@OEDOMETER_CONFIG@|$oed|" -e "s|@BULK_DENSITY@|$bulk|" "$root/data/calibration/identity/density_full.toml" > density_full.toml
fi
if wants compression; then
  # The "measured" curve is the truth's at seed 1 (truth-compression); its uncertainties and
  # the correlation of c1 and c2 are the scatter of five realisations (seeds 1-5), each
  # settling its own sample as every design run does: a lab's repeat tests.
  truth=(--config "$oed" --set particle.density=1230 --set particle.normal_stiffness=470e3 --set particle.friction=0.33)
  for seed in 1 2 3 4 5; do
    dir=truth-compression; [ "$seed" = 1 ] || dir="truth-compression-seed$seed"
    [ -f "$dir/summary.json" ] || "$colza" run oedometer "${truth[@]}" --seed "$seed" --out "$dir" --force --quiet
  done
  read -r u1 u2 r < <(python3 - <<'PY'
import json, statistics
dirs = ["truth-compression"] + [f"truth-compression-seed{s}" for s in range(2, 6)]
fits = [json.load(open(f"{d}/summary.json"))["fit"] for d in dirs]
c1, c2 = [f["c1"] for f in fits], [f["c2"] for f in fits]
s1, s2 = statistics.stdev(c1), statistics.stdev(c2)
m1, m2 = statistics.mean(c1), statistics.mean(c2)
r = sum((a - m1) * (b - m2) for a, b in zip(c1, c2)) / ((len(c1) - 1) * s1 * s2)
print(repr(s1), repr(s2), repr(r))
PY
)
  echo "compression truth scatter (5 seeds): c1 +/- $u1 N/m, c2 +/- $u2 N/m^2, correlation $r"
  sed -e "s|@OEDOMETER_CONFIG@|$oed|" -e "s|@TRUTH_CURVE@|$work/truth-compression/curve.csv|" \
    -e "s|@C1_UNCERTAINTY@|$u1|" -e "s|@C2_UNCERTAINTY@|$u2|" -e "s|@CORRELATION@|$r|" \
    "$root/data/calibration/identity/compression_full.toml" > compression_full.toml
fi
if wants shear || wants shear_peak; then
  # The truth settles its sample from data/shear.toml at seed 1, as every design run does.
  shear="$root/data/shear.toml"
  [ -f truth-shear/summary.json ] || "$colza" run shear-series --config "$shear" \
    --set 'shear_box.normal_stresses=[25750.0, 78750.0]' --set contact.contact_bond.normal_strength=1.8 \
    --set contact.contact_bond.shear_strength=3.3 --jobs 2 --threads 1 --out truth-shear --quiet
  for spec in shear_full shear_peak_full; do
    sed -e "s|@SHEAR_CONFIG@|$shear|" -e "s|@TRUTH_DIR@|$work/truth-shear|" \
      "$root/data/calibration/identity/$spec.toml" > "$spec.toml"
  done
fi

for stage in "${stages[@]}"; do
  for mode in paper sequential; do
    echo "== $stage, $mode"
    # One runs directory per stage: the two modes share the runs they have in common.
    "$colza" calibrate "${stage%_peak}" --spec "${stage}_full.toml" --mode "$mode" --out "out-$stage-$mode" \
      --runs "runs-$stage" --force --quiet || true
  done
done

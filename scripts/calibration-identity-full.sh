#!/usr/bin/env bash
# Full-size identity tests of `colza calibrate` (issue 6): synthetic "measured" data made by
# colza at known parameters other than the paper's, then recovered by the paper's procedure
# and by the sequential mode. About 40 min on 2 cores.
#   density:     truth rho_p = 1280 kg/m^3 (Table 1 otherwise)  -> its bulk density
#   compression: truth kn_p = 470e3 N/m, mu_pp = 0.33, rho_p = 1230 -> its compression curve
# Usage: scripts/calibration-identity-full.sh [WORKDIR]   (default /tmp/colza-identity-full)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
colza="$root/build/src/colza"
work="${1:-/tmp/colza-identity-full}"
mkdir -p "$work"
cd "$work"
oed="$root/data/oedometer.toml"
density_stop=(--set oedometer.stop_force=200.0 --set oedometer.fit_force_max=190.0 --set oedometer.fit_force_min=10.0)

"$colza" run oedometer --config "$oed" --set particle.density=1280 "${density_stop[@]}" --out truth-density --force --quiet
"$colza" run oedometer --config "$oed" --set particle.density=1230 --set particle.normal_stiffness=470e3 \
  --set particle.friction=0.33 --out truth-compression --force --quiet

bulk=$(python3 -c "import json; print(repr(json.load(open('truth-density/summary.json'))['bulk_density']))")
sed -e "s|@OEDOMETER_CONFIG@|$oed|" -e "s|@BULK_DENSITY@|$bulk|" "$root/data/calibration/identity/density_full.toml" > density_full.toml
sed -e "s|@OEDOMETER_CONFIG@|$oed|" -e "s|@TRUTH_CURVE@|$work/truth-compression/curve.csv|" \
  "$root/data/calibration/identity/compression_full.toml" > compression_full.toml

for stage in density compression; do
  for mode in paper sequential; do
    echo "== $stage, $mode"
    "$colza" calibrate "$stage" --spec "${stage}_full.toml" --mode "$mode" --jobs 2 --out "out-$stage-$mode" --force --quiet || true
  done
done

#!/usr/bin/env bash
# Mesh-objective stress extremes (results/singular_points.h): on the Koyna
# section (first 3 s of the record, P2 at 2 m and 1 m), the largest tension
# at the re-entrant neck corner grows with refinement (the elastic stress is
# unbounded there: r^(lambda - 1) with lambda ~ 0.6 for its ~200 degree
# corner, so more than 10% per halving; measured 13.97 -> 16.70 MPa, +19.5%),
# while the extremes farther than 5% of the height (5.15 m) from the
# singular points converge: they change by less than 2% between the two
# meshes (measured 0.1% in tension, 0.6% in compression; the field there is
# smooth, and what is left is the position of the nearest stress points to
# the excluded disc, O(h) times its gradient).
# Usage: singular_extremes.sh KOYNA PYTHON
set -eu
exe=$1 python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for h in 2 1; do
  "$exe" --out "$work/h$h" --set mesh.size=$h --set time.duration=3 \
    --set output.every=1000 --set output.plots=false >/dev/null
done
"$python" - "$work/h2" "$work/h1" <<'PY'
import json, sys
a, b = (json.load(open(f"{d}/summary.json")) for d in sys.argv[1:3])
raw = b["max_principal_tension_mpa"]["value"] / a["max_principal_tension_mpa"]["value"]
print(f"raw max tension 2 m -> 1 m: {a['max_principal_tension_mpa']['value']:.3f} -> "
      f"{b['max_principal_tension_mpa']['value']:.3f} MPa (x{raw:.3f})")
assert raw > 1.10, "the singular corner should grow with refinement"
for key in ("max_principal_tension_mpa", "max_principal_compression_mpa"):
    va = a["away_from_singular_points"][key]["value"]
    vb = b["away_from_singular_points"][key]["value"]
    rel = abs(vb - va) / abs(va)
    print(f"away from the singular points, {key}: {va:.4f} -> {vb:.4f} MPa "
          f"({100 * rel:.2f}%)")
    assert rel < 0.02
PY

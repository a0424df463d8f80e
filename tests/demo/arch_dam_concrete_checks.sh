#!/usr/bin/env bash
# HTC concrete in the arch_dam demo (issue 21's first step), on the small
# case of arch_dam_mpi_matches_serial.sh (P2, 16 m, 3 bonded joints, 0.3 s):
#  1. material.model = "elastic" (the Newton engine, stresses at the
#     quadrature points) equals the linear engine (LinearNewmark): the
#     crest history to 1e-7 of its peak (measured 2e-10, the digits
#     written);
#  2. viscoplastic concrete with a low tensile strength (1 MPa, Gf 2000
#     N/m) at 0.8 g for 1 s, points cracking in the static stage and in
#     the time history (up to 133 in a step, 196 Newton iterations): 2
#     ranks equal serial, the crest history to 1e-5 of its peak (the Newton
#     tolerance), the same Newton iterations.
#  3. on rock with mass and a viscous-spring boundary (wave input), the
#     elastic material equals the linear engine too: crest history to 1e-7
#     of its peak (measured 1e-11 by hand in the session that built it);
#  4. study.table1 at two reservoir levels, perfectly plastic in tension
#     (concrete.tension_softening = "none", ft 1 MPa, +30% for the
#     rate-independent models, 0.8 g, 0.3 s): the six runs and table1.csv;
#     the plastic model's largest principal stress at the quadrature points
#     is the dynamic tensile strength 1.3 MPa (the Rankine plane sigma_1 <=
#     ft, no softening) to 1e-6, where the elastic model's exceeds it;
#     the same study stopped in its first run (a checkpoint two folders
#     down, level_100m/elastic) and restarted with run.restart = true
#     gives the same table1.csv to the digits written.
# Usage: arch_dam_concrete_checks.sh ARCH_DAM MPIEXEC PYTHON
set -eu
exe=$1 mpiexec=$2 python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set mesh.size=16 --set mesh.size_far=60 --set joints.count=3
        --set time.duration=0.3 --set output.every=100
        --set output.plots=false --set modal.count=4)
"$exe" --out "$work/linear" "${common[@]}" --set material.model=linear >/dev/null
"$exe" --out "$work/elastic" "${common[@]}" --set material.model=elastic >/dev/null
vp=(--set material.model=viscoplastic --set concrete.ft=1.0e6
    --set concrete.Gf=2000 --set motion.stream.peak_g=0.8
    --set time.duration=1.0)
"$exe" --out "$work/vp1" "${common[@]}" "${vp[@]}" >/dev/null
"$mpiexec" -n 2 "$exe" --out "$work/vp2" "${common[@]}" "${vp[@]}" >/dev/null
vs=(--set foundation.boundary=viscous_spring --set rock.E=20e9)
"$exe" --out "$work/vs_linear" "${common[@]}" "${vs[@]}" \
  --set material.model=linear >/dev/null
"$exe" --out "$work/vs_elastic" "${common[@]}" "${vs[@]}" \
  --set material.model=elastic >/dev/null
t1=(--set study.table1=true --set 'study.reservoir_levels=[100, 70]'
    --set concrete.ft=1.0e6 --set concrete.tension_softening=none
    --set concrete.dynamic_factor_E=1.3 --set concrete.dynamic_factor_strength=1.3
    --set motion.stream.peak_g=0.8)
"$exe" --out "$work/table1" "${common[@]}" "${t1[@]}" >/dev/null
set +e
"$exe" --out "$work/table1_split" "${common[@]}" "${t1[@]}" \
  --set run.checkpoint_every=10 --set run.stop_at_step=15 >/dev/null 2>&1
rc=$?
set -e
[ "$rc" -eq 3 ] || { echo "stopped study exited $rc, expected 3"; exit 1; }
"$exe" --out "$work/table1_split" "${common[@]}" "${t1[@]}" \
  --set run.checkpoint_every=10 --set run.restart=true >/dev/null
"$python" - "$work" <<'PY'
import csv, json, os, sys
import numpy as np
w = sys.argv[1]
def crest(d):
    return np.genfromtxt(f"{w}/{d}/crest.csv", delimiter=",", names=True)
def diff(a, b):
    ca, cb = crest(a), crest(b)
    keys = ca.dtype.names[1:]
    peak = max(np.abs(ca[k]).max() for k in keys)
    return max(np.abs(ca[k] - cb[k]).max() for k in keys) / peak
d1 = diff("linear", "elastic")
print(f"elastic vs linear engine: crest history {d1:.2e} of its peak")
assert d1 < 1e-7, d1
d3 = diff("vs_linear", "vs_elastic")
print(f"viscous-spring foundation, elastic vs linear engine: crest history "
      f"{d3:.2e} of its peak")
assert d3 < 1e-7, d3
s1 = json.load(open(f"{w}/vp1/summary.json"))
s2 = json.load(open(f"{w}/vp2/summary.json"))
d2 = diff("vp1", "vp2")
n1, n2 = s1["newton"], s2["newton"]
print(f"viscoplastic, 2 ranks vs serial: crest history {d2:.2e}; Newton "
      f"iterations {n1['iterations']} vs {n2['iterations']}, max "
      f"inelastic points in a step {n1['max_inelastic_points']}")
assert s2["mpi_ranks"] == 2
assert d2 < 1e-5, d2
assert n1["iterations"] == n2["iterations"]
assert n1["max_inelastic_points"] > 0, "no point cracked in the time history"
assert s1["analysis"].startswith("arch dam, HTC concrete (viscoplastic)")
t1 = list(csv.DictReader(open(f"{w}/table1/table1.csv")))
assert [(r["reservoir_level_m"], r["model"]) for r in t1] == [
    (l, m) for l in ("100", "70")
    for m in ("elastic", "plastic", "viscoplastic")], t1
for l in ("100", "70"):
    for m in ("elastic", "plastic", "viscoplastic"):
        assert os.path.exists(f"{w}/table1/level_{l}m/{m}/summary.json")
    assert os.path.exists(f"{w}/table1/level_{l}m/plastic/"
                          "face_upstream_concrete.csv")
top = {r["model"]: float(r["max_tension_mpa"]) for r in t1
       if r["reservoir_level_m"] == "100"}
print(f"table1, level 100 m: largest principal stress elastic "
      f"{top['elastic']:.4f}, plastic {top['plastic']:.6f}, viscoplastic "
      f"{top['viscoplastic']:.4f} MPa (plastic strength 1.3 MPa)")
assert top["elastic"] > 1.3, "the elastic run does not reach the strength"
assert abs(top["plastic"] - 1.3) < 1.3e-6, top["plastic"]
split = list(csv.DictReader(open(f"{w}/table1_split/table1.csv")))
for a, b in zip(t1, split):
    for k in a:
        if k != "seconds_per_step":
            assert a[k] == b[k], (k, a[k], b[k])
assert json.load(open(f"{w}/table1_split/level_100m/elastic/summary.json"))[
    "restarted_from_step"] == 15
print("table1 study stopped at step 15 of its first run and restarted: "
      "the same table")
PY

#!/usr/bin/env bash
# arch_dam on rock with mass and a viscous-spring boundary, with contact
# joints (issue 20 with issue 19's joints), a coarse P2 mesh, 3 joints:
# 1. Contact joints whose bonds cannot fail (tensile strength and cohesion
#    100 MPa, dead weight with the joints active) are the bonded (tied)
#    joints: crest history and stress extremes within 1e-8 of their peaks,
#    the pair problem's tolerance (the contact pairs then act as ties; the
#    P2 midside pairs follow the vertex pairs through a constraint, which
#    the free-field load's restriction must respect; measured 2e-10 and
#    7e-13).
# 2. Contact joints without bonds, HHT alpha = -0.1: the run completes,
#    every output is finite, the joints open (by more than 1 mm; measured
#    1.5 cm at 0.5 g after 2 s) and the energy balance shows no energy
#    created (error <= 0 within 1e-6 of the load work: HHT removes energy,
#    never adds it), and HHT removes little of it (error >= -1e-3 of the
#    load work; measured -3e-5).
# 3. A P1 mesh (12 m, no joints) on the 2H block, HHT alpha = 0, 0.6 s:
#    the energy balance holds to round-off (|error| <= 1e-9 of the load
#    work: with average acceleration the trapezoidal work terms make it an
#    identity of the scheme; measured 7e-15). Before linalg::
#    duplicate_matrix was used for the dashpots' copy, PETSc's generic BAIJ
#    product left the copy's empty rows unset (the interior nodes kept M u)
#    and this run grew exponentially: 2.4e-3 at 0.6 s.
# Usage: arch_foundation_checks.sh ARCH_DAM PYTHON
set -eu
exe=$1 python=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set mesh.size=16 --set mesh.size_far=60 --set joints.count=3
        --set time.duration=2.0 --set output.every=100 --set output.plots=false
        --set modal.count=4 --set foundation.boundary=viscous_spring
        --set time.hht_alpha=-0.1 --set motion.stream.peak_g=0.5)
"$exe" --out "$work/bonded" "${common[@]}" >/dev/null
"$exe" --out "$work/strong" "${common[@]}" --set joints.model=contact \
  --set joints.dead_load=joints_active \
  --set 'joints.tensile_strength=[1e8, 1e8, 1e8]' \
  --set 'joints.cohesion=[1e8, 1e8, 1e8]' >/dev/null
"$exe" --out "$work/contact" "${common[@]}" --set joints.model=contact >/dev/null
"$exe" --out "$work/p1" --set joints.count=0 --set mesh.order=1 \
  --set mesh.size=12 --set foundation.boundary=viscous_spring \
  --set foundation.extent_beyond=2 --set foundation.extent_upstream=2 \
  --set foundation.extent_downstream=2 --set foundation.extent_below=2 \
  --set time.dt=0.0015 --set time.duration=0.6 \
  --set 'damping.frequencies_hz=[3.891, 6.906]' --set output.every=100000 \
  --set output.plots=false --set modal.count=4 >/dev/null
"$python" - "$work" <<'PY'
import json, math, sys
import numpy as np
w = sys.argv[1]
a = np.genfromtxt(f"{w}/bonded/crest.csv", delimiter=",", names=True)
b = np.genfromtxt(f"{w}/strong/crest.csv", delimiter=",", names=True)
keys = [k for k in a.dtype.names if k != "t_s"]
peak = max(np.abs(a[k]).max() for k in keys)
diff = max(np.abs(a[k] - b[k]).max() for k in keys) / peak
sa = json.load(open(f"{w}/bonded/summary.json"))
sb = json.load(open(f"{w}/strong/summary.json"))
sdiff = max(abs(sa[k]["value"] - sb[k]["value"]) / abs(sa[k]["value"])
            for k in ("max_principal_tension_mpa", "max_principal_compression_mpa"))
print(f"unbreakable bonds vs tied joints: crest {diff:.1e}, stresses {sdiff:.1e}")
assert "viscous-spring" in sb["analysis"], sb["analysis"]
assert sb["joints"]["static_stage"]["bonds_broken"] == 0
assert diff < 1e-8 and sdiff < 1e-8
c = json.load(open(f"{w}/contact/summary.json"))
e = c["energy"]
opening = c["joints"]["max_opening_cm"]
print(f"contact joints: largest opening {opening:.2f} cm, energy balance "
      f"error {e['balance_error_j']:.3e} J of {e['load_work_j']:.3e} J load "
      f"work, joint work {e['joint_work_j']:.3e} J")
assert opening > 0.1, opening
assert -1e-3 * abs(e["load_work_j"]) <= e["balance_error_j"] <= 1e-6 * abs(e["load_work_j"])
for k, v in e.items():
    if k != "note":
        assert math.isfinite(v), (k, v)
e = json.load(open(f"{w}/p1/summary.json"))["energy"]
ratio = e["balance_error_j"] / e["load_work_j"]
print(f"P1 on the 2H block: energy balance error {ratio:.1e} of the load work")
assert abs(ratio) <= 1e-9, ratio
PY

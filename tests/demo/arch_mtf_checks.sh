#!/usr/bin/env bash
# arch_dam on rock with mass and Liao's multi-transmitting boundary (issue
# 20 in 3D): a coarse P1 mesh (16 m) with 3 bonded joints, the structured
# band (4 layers of 20 m along the block's bottom, sides, upstream and
# downstream faces: transfinite hexahedral pieces, those beside the
# canyon's walls trapezoids), 0.45 s of the record (the incident wave
# reaches the dam and the scattered waves the band):
# 1. The band is conforming: every mesh node on the block's five faces is
#    a boundary node of the formula.
# 2. 2 ranks give the serial crest history to 1e-8 of its peak (the
#    stencils and the band's pieces cross the partition; before the band
#    was conforming its mesh hung in DOLFINx's distribution on 2 ranks).
# 3. HTC concrete, elastic, equals the linear engine: the partition in the
#    Newton integrator (on the tied unknowns, the formula on the motion
#    from the static state) against PartitionedNewmark (the state relative
#    to the static one): the crest's seismic history within 1e-4 of its
#    peak (the Newton tolerance is 1e-6 of the load, static included).
# 4. Contact joints on it (the nonlinear engine's constrained Newton with
#    the partition), their bonds too strong to break: the joints stay
#    closed and stuck, so the crest's seismic history is the bonded
#    joints' (check 3's HTC elastic run) to 1e-4 of its peak (as check 3:
#    the Newton tolerance is 1e-6 of the load, static included); 2 ranks
#    in the U canyon (6).
# 5. The band implicit (foundation.band_integration), the step 5 ms (s =
#    0.9; the explicit band's stable step is 1.8 ms): 2 ranks give the
#    serial crest history to 1e-8 (the prescribed rows' coupling moved to
#    the right-hand side on each rank's rows); HTC elastic (the Newton
#    integrator's partition without explicit elements) gives the linear
#    engine's to 1e-4 of its peak (as check 3).
# 6. A U canyon (12 fillet segments a side): the band, unstructured
#    beside the walls, is conforming (check 1's count), and contact
#    joints with unbreakable bonds on it under HHT alpha = -0.1 (the band
#    implicit, the nonlinear engine) equal the bonded joints to 1e-4 of
#    the crest's seismic peak (as check 4), 2 ranks serial to 1e-8.
# 7. Bad input exits 2 with one line before any work: order 2 on P2, a
#    band reaching the rims, contact joints in the linear engine, HHT
#    alpha with the band explicit or in the linear engine, study.foundation
#    whose stiffest rock breaks s <= 1, a vertical wall segment.
# Usage: arch_mtf_checks.sh ARCH_DAM PYTHON MPIEXEC
set -u
exe=$1 python=$2 mpiexec=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

mtf=(--set foundation.boundary=mtf --set mesh.order=1
     --set foundation.band_size=20 --set time.dt=0.0015)
common=("${mtf[@]}" --set mesh.size=16 --set joints.count=3
        --set foundation.extent_beyond=1.5 --set foundation.extent_upstream=1.5
        --set foundation.extent_downstream=1.5
        --set foundation.extent_below=1.5 --set reservoir.level=0
        --set time.duration=0.45 --set output.every=100000
        --set output.plots=false --set modal.count=4)
set -e
"$exe" --out "$work/serial" "${common[@]}" >/dev/null
"$exe" --out "$work/elastic" "${common[@]}" --set material.model=elastic \
  >/dev/null
"$mpiexec" -n 2 "$exe" --out "$work/mpi" "${common[@]}" >/dev/null
contact=("${common[@]}" --set material.model=elastic --set joints.model=contact
         --set "joints.tensile_strength=[1e8, 1e8, 1e8]"
         --set "joints.cohesion=[1e8, 1e8, 1e8]")
implicit=("${common[@]}" --set foundation.band_integration=implicit
          --set time.dt=0.005)
"$exe" --out "$work/implicit" "${implicit[@]}" >/dev/null
"$mpiexec" -n 2 "$exe" --out "$work/implicit_mpi" "${implicit[@]}" >/dev/null
"$exe" --out "$work/implicit_htc" "${implicit[@]}" --set material.model=elastic \
  >/dev/null
ucanyon=("${implicit[@]}" --set canyon.shape=u --set time.hht_alpha=-0.1
         --set material.model=elastic)
"$exe" --out "$work/u_bonded" "${ucanyon[@]}" >/dev/null
ucontact=("${ucanyon[@]}" --set joints.model=contact
          --set "joints.tensile_strength=[1e8, 1e8, 1e8]"
          --set "joints.cohesion=[1e8, 1e8, 1e8]")
"$exe" --out "$work/u_contact" "${ucontact[@]}" >/dev/null 2>&1
"$mpiexec" -n 2 "$exe" --out "$work/u_contact_mpi" "${ucontact[@]}" \
  >/dev/null 2>&1
"$exe" --out "$work/contact" "${contact[@]}" >/dev/null 2>&1
"$python" - "$work" <<'PY'
import json, sys
import numpy as np
w = sys.argv[1]
def crest(name, cols):
    a = np.genfromtxt(f"{w}/{name}/crest.csv", delimiter=",", names=True)
    return np.column_stack([a[c] for c in cols])
seismic = ["ux_m", "uy_m", "uz_m"]
s = json.load(open(f"{w}/serial/summary.json"))
assert "multi-transmitting" in s["analysis"], s["analysis"]
assert s["joints"]["count"] == 3, s["joints"]
m = s["foundation"]["mtf"]
print(f"band: {m['boundary_nodes']} boundary nodes ({m['bottom_nodes']} on "
      f"the bottom), stable step {m['stable_dt_s']:.3e} s, s = {m['courant_s']:.3f}")
# The band is conforming: every node on the block's bottom, sides,
# upstream and downstream faces is a boundary node of the formula (on the
# non-conforming band of gmsh's default corners the facets of a third of
# the faces' quadrangles were not the tetrahedra's, and 1109 of 1340 nodes
# were found).
import h5py
def conforming(name):
    m = json.load(open(f"{w}/{name}/summary.json"))["foundation"]["mtf"]
    x = h5py.File(f"{w}/{name}/fields.h5", "r")["/mesh/geometry"][:]
    lo, hi = x.min(axis=0), x.max(axis=0)
    tol = 1e-6 * (hi - lo).max()
    bottom = np.abs(x[:, 2] - lo[2]) < tol
    faces = bottom.copy()
    for k in (0, 1):
        faces |= (np.abs(x[:, k] - lo[k]) < tol) | (np.abs(x[:, k] - hi[k]) < tol)
    print(f"{name}: mesh nodes on the block's five faces {faces.sum()} "
          f"({bottom.sum()} on the bottom), boundary nodes {m['boundary_nodes']}")
    assert m["boundary_nodes"] == faces.sum(), (m["boundary_nodes"], faces.sum())
    assert m["bottom_nodes"] == bottom.sum(), (m["bottom_nodes"], bottom.sum())
conforming("serial")
conforming("u_bonded")
a, c = crest("serial", seismic), crest("elastic", seismic)
peak = np.abs(a).max()
d_mpi = np.abs(a - crest("mpi", seismic)).max() / peak
print(f"2 ranks against serial {d_mpi:.1e}")
assert d_mpi < 1e-8, d_mpi
d_engine = np.abs(a - c).max() / peak
print(f"crest's seismic peak {peak:.3e} m; HTC elastic against the linear "
      f"engine {d_engine:.1e}")
assert peak > 1e-5, peak  # the waves reached the dam
k = crest("contact", seismic)
s = json.load(open(f"{w}/contact/summary.json"))
assert "contact joints" in s["analysis"], s["analysis"]
d_contact = np.abs(k - c).max() / peak
print(f"contact joints with unbreakable bonds against bonded joints "
      f"{d_contact:.1e}")
assert d_contact < 1e-4, d_contact
u = crest("u_bonded", seismic)
d_u = np.abs(crest("u_contact", seismic) - u).max() / np.abs(u).max()
d_u_mpi = np.abs(crest("u_contact", seismic) -
                 crest("u_contact_mpi", seismic)).max() / np.abs(u).max()
print(f"U canyon, HHT -0.1, band implicit: crest's seismic peak "
      f"{np.abs(u).max():.3e} m; contact with unbreakable bonds against "
      f"bonded {d_u:.1e}; 2 ranks against serial {d_u_mpi:.1e}")
assert np.abs(u).max() > 1e-5
assert d_u < 1e-4, d_u
assert d_u_mpi < 1e-8, d_u_mpi
i = crest("implicit", seismic)
d_implicit = np.abs(i - crest("implicit_mpi", seismic)).max() / np.abs(i).max()
print(f"implicit band, dt 5 ms: crest's seismic peak {np.abs(i).max():.3e} m "
      f"(explicit, 1.5 ms: {peak:.3e}); 2 ranks against serial "
      f"{d_implicit:.1e}")
assert d_implicit < 1e-8, d_implicit
d_implicit_htc = np.abs(i - crest("implicit_htc", seismic)).max() / np.abs(i).max()
print(f"implicit band, HTC elastic against the linear engine {d_implicit_htc:.1e}")
assert d_implicit_htc < 1e-4, d_implicit_htc
assert np.abs(i).max() > 1e-5
assert d_engine < 1e-4, d_engine
PY
set +e

expect mtf_order_two_on_p2 'foundation\.mtf_order.*mesh\.order = 1' "${mtf[@]}" \
  --set mesh.order=2
expect mtf_band_too_thick 'foundation\.band_size.*reach' "${mtf[@]}" \
  --set foundation.band_layers=6
expect mtf_contact_linear 'foundation\.boundary.*contact joints in the nonlinear engine.*material\.model = "elastic"' \
  "${mtf[@]}" --set joints.model=contact
expect mtf_hht 'time\.hht_alpha.*must be 0.*explicit band' "${mtf[@]}" \
  --set time.hht_alpha=-0.1
expect mtf_hht_linear 'time\.hht_alpha.*linear engine.*material\.model = "elastic"' \
  "${mtf[@]}" --set time.hht_alpha=-0.1 --set foundation.band_integration=implicit
expect mtf_study_courant 'time\.dt.*s = c_p dt / dx = 1\.[0-9]*.*must be at most 1' \
  "${mtf[@]}" --set study.foundation=true --set 'study.foundation_ratios=[0.5, 20.0]'
expect mtf_vertical_wall 'canyon\.x_left.*vertical or overhanging' "${mtf[@]}" \
  --set canyon.shape=points --set 'canyon.z=[0.0, 50.0, 102.0]' \
  --set 'canyon.x_left=[-12.0, -12.0, -130.0]' \
  --set 'canyon.x_right=[12.0, 60.0, 130.0]'
expect mtf_band_too_thin 'foundation\.band_layers.*at least 4 layers' \
  "${mtf[@]}" --set foundation.band_layers=3
[ "$failures" -eq 0 ]

#!/usr/bin/env bash
# Lamb's problem in 2D, the scattering check of issue 20: a half-space
# (E 20 GPa, nu 0.25, rho 2600) pressed by a vertical half-sine traction
# pulse (1 MPa, 0.1 s) on the strip |x| <= 4 m of its surface, the surface
# displacement 20, 40, 60 and 80 m away. Its P, S and Rayleigh waves reach
# the truncated block's sides and bottom at every angle of incidence, and
# in 2D the half-space keeps a slowly decaying quasi-static displacement
# behind them (the static line load's displacement grows like log(1/r)).
# The reference is Lamb's (1904) Fourier integral, evaluated by
# tests/demo/lamb_reference.py (no finite elements; its kernels derived
# there and checked against Flamant's static solution and the Rayleigh
# speed).
#  1. The finite elements agree with it and converge to it: P2 cells of
#     16 and 8 m in rock reaching 1600 m (a viscous-spring boundary so far
#     away that no reflection returns within the 0.6 s: a P wave's round
#     trip takes 2 x 1600 / 3038 = 1.05 s). Asserted: the error (largest
#     displacement difference over the 0.6 s and the four points / the
#     point's peak) falls at least twofold from 16 to 8 m and is below 2%
#     at 8 m (measured 3.4% and 1.4%; 0.6% with 4 m cells, 0.3% with 4 m
#     and dt 0.5 ms, by hand).
#  2. The multi-transmitting (P2, order 1, band implicit) and the viscous-
#     spring boundary on blocks 120 and 240 m wide either side and deep:
#     - until a wave reflected at the 240 m block's boundary can reach a
#       receiver (a P wave from the strip to the side and back to x = 80:
#       (240 + 160) / 3038 = 0.132 s) the 240 m blocks are as accurate as
#       the 1600 m one (the boundary has not been reached: below the 2%
#       of check 1);
#     - the truncated models converge to the half-space as the boundary
#       moves out: the error over the 0.6 s falls from 120 to 240 m, for
#       both boundaries;
#     - the waves of the pulse (t <= 0.15 s, when the Rayleigh wave has
#       passed x = 80 m; on the 120 m block their reflections return
#       within it): the multi-transmitting boundary reflects less than the
#       viscous-spring one, whose dashpots are exact at normal incidence
#       only (Lysmer & Kuhlemeyer 1969) where the formula transmits any
#       angle of incidence to first order (Liao & Wong 1984).
#     Measured, not asserted: the error over the 0.6 s is 64% and 27% on
#     the multi-transmitting blocks (120, 240 m), 24% and 12% on the
#     viscous-spring ones. After the pulse the multi-transmitting block
#     comes to rest displaced as a whole (the formula passes a rigid
#     translation and has no stiffness at zero frequency), where the half-
#     space's displacement decays and the viscous-spring boundary's
#     springs pull the block back: the quasi-static tail of a load with a
#     net impulse (drift control 0.01 in place of 1e-4: 23% on the 120 m
#     block; order 2 on P1 drifts away with 1e-4).
# Usage: lamb_checks.sh BIN_DIR PYTHON SOURCE_DIR
set -eu
bin=$1 python=$2 src=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
geo=$src/tests/data/meshes/lamb_half_space_2d.geo
case=(--case "$src/tests/data/case/lamb_2d.toml")
vs=(--set 'supports.transmitting=[]' --set 'supports.viscous_spring=[boundary]')
far=("${vs[@]}" --set 'regions.groups=[source, rock, band, far]'
     --set 'regions.E=[20e9, 20e9, 20e9, 20e9]'
     --set 'regions.nu=[0.25, 0.25, 0.25, 0.25]'
     --set 'regions.rho=[2600, 2600, 2600, 2600]')
for h in 16 8; do
  gmsh -2 -setnumber far 1 -setnumber h $h "$geo" -o "$work/far_$h.msh" \
    -format msh41 >/dev/null
  "$bin/dam_model" "${case[@]}" --out "$work/far_$h" "${far[@]}" \
    --set mesh.file="$work/far_$h.msh" >/dev/null
done
for L in 120 240; do
  gmsh -2 -setnumber L $L "$geo" -o "$work/block_$L.msh" -format msh41 >/dev/null
  "$bin/dam_model" "${case[@]}" --out "$work/mtf_$L" \
    --set mesh.file="$work/block_$L.msh" >/dev/null
  "$bin/dam_model" "${case[@]}" --out "$work/vs_$L" "${vs[@]}" \
    --set mesh.file="$work/block_$L.msh" >/dev/null
done

"$python" - "$work" "$src/tests/demo" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from bounds import check, finish
from lamb_reference import HalfSpace, surface_response, self_check

hs = HalfSpace(20e9, 0.25, 2600.0)
cR = self_check(hs)
xs = [20, 40, 60, 80]
runs = ["far_16", "far_8", "mtf_120", "vs_120", "mtf_240", "vs_240"]
data = {r: np.genfromtxt(f"{w}/{r}/histories.csv", delimiter=",", names=True)
        for r in runs}
t = data["far_8"]["t_s"]
for r in runs:
    assert np.array_equal(data[r]["t_s"], t), r
    for k in data[r].dtype.names:
        assert np.all(np.isfinite(data[r][k])), (r, k)
ux, uy = surface_response(hs, xs, t, 1e6, 4.0, 0.1)

def error(run, t_end=1e9):
    """Largest displacement difference from Lamb's over t <= t_end and the
    four points, each / its peak."""
    m = t <= t_end + 1e-9
    e = 0.0
    for i, x in enumerate(xs):
        peak = max(np.abs(ux[i]).max(), np.abs(uy[i]).max())
        for ref, c in ((ux[i], "ux_m"), (uy[i], "uy_m")):
            e = max(e, np.abs(data[run][f"x{x}_{c}"][m] - ref[m]).max() / peak)
    return e


print(f"Rayleigh speed {cR:.1f} m/s (c_s {hs.cs:.1f}, c_p {hs.cp:.1f})")
# 1.
e16, e8 = error("far_16"), error("far_8")
check("rock to 1600 m, 8 m cells: error", e8, 0.02)
check("error with 8 m cells / with 16 m cells", e8 / e16, 0.5)
# 2.
check("240 m block, multi-transmitting, t <= 0.132 s: error",
      error("mtf_240", 0.132), 0.02)
check("240 m block, viscous-spring, t <= 0.132 s: error",
      error("vs_240", 0.132), 0.02)
for b in ("mtf", "vs"):
    e120, e240 = error(f"{b}_120"), error(f"{b}_240")
    print(f"{b}: error over 0.6 s {e120:.1%} (120 m), {e240:.1%} (240 m)")
    check(f"{b}: error at 240 m / at 120 m", e240 / e120, 1.0)
mtf, vs = error("mtf_120", 0.15), error("vs_120", 0.15)
print(f"120 m block, t <= 0.15 s: multi-transmitting {mtf:.1%}, "
      f"viscous-spring {vs:.1%}")
check("120 m block, t <= 0.15 s: multi-transmitting / viscous-spring",
      mtf / vs, 1.0)
finish()
PY

#!/usr/bin/env bash
# The koyna demo gives the same answer on 2 MPI ranks as serial: crest
# history to 1e-8 relative (of its peak), and the same frequencies and stress
# extremes (the direct solvers differ: PETSc Cholesky serial, MUMPS in
# parallel, both exact to ~1e-12 here, so 1e-8 leaves room for round-off).
# With a nonlinear concrete (extra --set arguments) the two runs agree to
# the Newton tolerance instead (TOL argument, e.g. 1e-5: residual 1e-6 of the
# load).
# Every output is finite and the XDMF envelopes match too (check_outputs.py).
# Usage: mpi_matches_serial.sh KOYNA MPIEXEC PYTHON [TOL [--set k=v ...]]
set -eu
exe=$1 mpiexec=$2 python=$3
tol=${4:-1e-8}
shift 3
if [ $# -gt 0 ]; then shift; fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set mesh.size=4 --set time.duration=3 --set output.every=50
        --set output.plots=false --set foundation.enabled=true "$@")
"$exe" --out "$work/serial" "${common[@]}" >/dev/null
"$mpiexec" -n 2 "$exe" --out "$work/mpi" "${common[@]}" >/dev/null
"$python" - "$work/serial" "$work/mpi" "$tol" <<'PY'
import json, sys
import numpy as np
a, b, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
ca = np.genfromtxt(f"{a}/crest.csv", delimiter=",", names=True)
cb = np.genfromtxt(f"{b}/crest.csv", delimiter=",", names=True)
peak = np.abs(ca["ux_m"]).max()
diff = max(np.abs(ca[k] - cb[k]).max() for k in ca.dtype.names) / peak
sa = json.load(open(f"{a}/summary.json"))
sb = json.load(open(f"{b}/summary.json"))
fa, fb = np.array(sa["frequencies_hz"]), np.array(sb["frequencies_hz"])
fdiff = np.abs(fa - fb).max() / fa.max()
sdiff = max(abs(sa[k]["value"] - sb[k]["value"]) / abs(sa[k]["value"])
            for k in ("max_principal_tension_mpa", "max_principal_compression_mpa"))
print(f"crest history max rel. diff {diff:.2e}, frequencies {fdiff:.2e}, "
      f"stress extremes {sdiff:.2e} (ranks {sa['mpi_ranks']} vs {sb['mpi_ranks']})")
assert sb["mpi_ranks"] == 2
if "newton" in sb:
    print(f"Newton iterations {sa['newton']['iterations']} vs "
          f"{sb['newton']['iterations']}, cuts {sa['newton']['step_cuts']} vs "
          f"{sb['newton']['step_cuts']}, max inelastic points "
          f"{sa['newton']['max_inelastic_points']}")
# Displacement envelope along the upstream face: same on 2 ranks, and at the
# crest node it equals the extremes of the crest history.
ea = np.genfromtxt(f"{a}/displacement_envelope.csv", delimiter=",", names=True)
eb = np.genfromtxt(f"{b}/displacement_envelope.csv", delimiter=",", names=True)
ediff = max(np.abs(ea["max_m"] - eb["max_m"]).max(),
            np.abs(ea["min_m"] - eb["min_m"]).max()) / peak
top = np.argmax(ea["y_m"])
cdiff = max(abs(ea["max_m"][top] - ca["ux_m"].max()),
            abs(ea["min_m"][top] - ca["ux_m"].min())) / peak
print(f"displacement envelope 2 ranks vs serial {ediff:.2e}, "
      f"crest node vs crest history {cdiff:.2e}")
# Face tables: the same header and rows as serial (every rank's rows in
# rank 0's columns: a rank without points on a face once wrote one column
# fewer), the envelope values equal point by point.
import glob, os
for fa_path in sorted(glob.glob(f"{a}/face_*.csv")):
    fb_path = f"{b}/{os.path.basename(fa_path)}"
    ha, hb = open(fa_path).readline(), open(fb_path).readline()
    assert ha == hb, (fb_path, ha, hb)
    ta = np.genfromtxt(fa_path, delimiter=",", names=True)
    tb = np.genfromtxt(fb_path, delimiter=",", names=True)
    assert ta.shape == tb.shape, (fb_path, ta.shape, tb.shape)
    # A vertex of a P2 face is a row per adjacent face cell (the stress
    # points are DG1: one value per cell), in the ranks' own order: the
    # rows at one point are ordered by their values.
    oa, ob = (np.lexsort((t["min_principal_mpa"], t["max_principal_mpa"],
                          t["z_m"], t["y_m"], t["x_m"])) for t in (ta, tb))
    for k in ("x_m", "y_m", "max_principal_mpa", "min_principal_mpa"):
        scale = max(np.abs(ta[k]).max(), 1e-30)
        d = np.abs(ta[k][oa] - tb[k][ob]).max() / scale
        assert d < max(tol, 1e-7), (fb_path, k, d)  # 8 digits written
    print(f"{os.path.basename(fa_path)}: {len(ta)} rows as serial")
# Vertical-stress envelope (nonlinear runs): sigma_yy lies between the
# principal stresses at every point, so its envelope does too.
try:
    pa = np.genfromtxt(f"{a}/dam_points.csv", delimiter=",", names=True)
    slack = 1e-9 * np.abs(pa["min_principal_mpa"]).max()
    assert np.all(pa["max_syy_mpa"] <= pa["max_principal_mpa"] + slack)
    assert np.all(pa["min_syy_mpa"] >= pa["min_principal_mpa"] - slack)
    print(f"vertical stress envelope within the principal one at {len(pa)} points")
except FileNotFoundError:
    pass
assert diff < tol and fdiff < 1e-8 and sdiff < tol
assert ediff < tol and cdiff < 1e-8  # CSV files carry 10 digits
# IMPL-EX: its equilibrium error (assembled across the ranks) as well.
if "implex_equilibrium_error" in sa:
    ia, ib = sa["implex_equilibrium_error"], sb["implex_equilibrium_error"]
    idiff = max(abs(ia[k] - ib[k]) / ia[k] for k in ("rms", "max"))
    print(f"IMPL-EX equilibrium error rms {ia['rms']:.4e} / {ib['rms']:.4e}, "
          f"max {ia['max']:.4e} / {ib['max']:.4e}")
    assert ia["max"] > 0 and idiff < tol
PY
# No NaN or infinity in any output (the foundation block is on: the dam
# envelopes must not leak into it), XDMF files of one grid per step, and the
# envelope fields of 2 ranks equal serial point by point.
"$python" "$(dirname "$0")/check_outputs.py" "$work/serial" "$work/mpi" "$tol"
"$python" "$(dirname "$0")/check_outputs.py" "$work/mpi"

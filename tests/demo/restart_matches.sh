#!/usr/bin/env bash
# A run stopped at a checkpoint and restarted gives the same results as an
# uninterrupted run (crest history and stress extremes to round-off: the
# restart recomputes the M and K images of the state from u, v, a), and the
# same envelopes: the displacement envelope along the upstream face and, for
# a nonlinear concrete (extra --set arguments), every column of
# dam_points.csv (state, strain-rate and vertical-stress envelopes), all to
# the digits written.
# Usage: restart_matches.sh DEMO PYTHON [--set k=v ...] (koyna defaults:
# a 4 m mesh, 3 s; the --set arguments come last and override them)
set -eu
exe=$1 python=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set mesh.size=4 --set time.duration=3 --set output.every=50
        --set output.plots=false --set run.checkpoint_every=100 "$@")
"$exe" --out "$work/full" "${common[@]}" >/dev/null
set +e
"$exe" --out "$work/split" "${common[@]}" --set run.stop_at_step=170 >/dev/null 2>"$work/err"
rc=$?
set -e
grep -q "stopped at step 170" "$work/err" || { cat "$work/err"; exit 1; }
[ "$rc" -eq 3 ] || { echo "stopped run exited $rc, expected 3"; exit 1; }
"$exe" --out "$work/split" "${common[@]}" --set run.restart=true >/dev/null
"$python" - "$work/full" "$work/split" <<'PY'
import json, sys
import numpy as np
a, b = sys.argv[1], sys.argv[2]
ca = np.genfromtxt(f"{a}/crest.csv", delimiter=",", names=True)
cb = np.genfromtxt(f"{b}/crest.csv", delimiter=",", names=True)
peak = np.abs(ca["ux_m"]).max()
diff = max(np.abs(ca[k] - cb[k]).max() for k in ca.dtype.names) / peak
sa = json.load(open(f"{a}/summary.json"))
sb = json.load(open(f"{b}/summary.json"))
sdiff = max(abs(sa[k]["value"] - sb[k]["value"]) / abs(sa[k]["value"])
            for k in ("max_principal_tension_mpa", "max_principal_compression_mpa",
                      "crest_displacement_max_m"))
print(f"restart from step {sb['restarted_from_step']}: crest history rel. diff "
      f"{diff:.2e}, extremes {sdiff:.2e}")
assert sb["restarted_from_step"] == 170
assert diff < 1e-9 and sdiff < 1e-9
# Run statistics cover all steps, also after a restart.
if "newton" in sa:
    na, nb = sa["newton"], sb["newton"]
    print(f"Newton iterations per step {na['iterations_per_step']:.4f} / "
          f"{nb['iterations_per_step']:.4f}")
    assert abs(na["iterations_per_step"] - nb["iterations_per_step"]) < 1e-12
if "implex_equilibrium_error" in sa:
    ia, ib = sa["implex_equilibrium_error"], sb["implex_equilibrium_error"]
    print(f"IMPL-EX equilibrium error rms {ia['rms']:.4e} / {ib['rms']:.4e}")
    assert abs(ia["rms"] - ib["rms"]) <= 1e-9 * ia["rms"]
    assert abs(ia["max"] - ib["max"]) <= 1e-9 * ia["max"]
for name in ("displacement_envelope.csv", "dam_points.csv"):
    try:
        ea = np.genfromtxt(f"{a}/{name}", delimiter=",", names=True)
    except FileNotFoundError:
        assert name == "dam_points.csv", name
        continue
    eb = np.genfromtxt(f"{b}/{name}", delimiter=",", names=True)
    ediff = max(np.abs(ea[k] - eb[k]).max() for k in ea.dtype.names)
    print(f"{name}: {len(ea)} rows, largest difference {ediff:.2e}")
    assert ediff < 1e-9, name
PY

#!/usr/bin/env bash
# Regression: each case of regression_cases.sh gives the results stored in
# tests/data/regression/<name>, written by the code before the one-engine
# refactor (issue 18, commit ac28040). Compared: every number and word of
# summary.json except timings and paths, crest.csv, face_<name>.csv,
# displacement_envelope.csv and table1.csv; not the Newton iteration's
# statistics (iterations, GMRES iterations, return maps: how the solution
# was found, not what it is). Tolerances: linear runs 1e-9 relative to the
# largest value of a file (round-off; measured 0, the arithmetic is the
# same), runs with nonlinear concrete 1e-5: the Newton tolerance (1e-6 of
# the load per step) carried along the inelastic path. A converged iterate
# moves by that much when the iteration takes another path to it: starting
# from Newmark's predictor in place of the last displacement moved these
# results by up to 3.3e-6.
# Usage: regression.sh BIN_DIR PYTHON SOURCE_DIR [NAME]
set -eu
bin=$1 python=$2 src=$3 only=${4:-}
ref=$src/tests/data/regression
source "$src/tests/demo/regression_cases.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
while read -r name exe args; do
  [ -n "$only" ] && [ "$only" != "$name" ] && continue
  args=${args//@SRC@/$src}
  # shellcheck disable=SC2086
  "$bin/$exe" --out "$work/$name" $args --set output.plots=false \
    --set output.every=1000000 >/dev/null
  "$python" - "$ref/$name" "$work/$name" "$name" <<'PY' || status=1
import json, os, sys
import numpy as np
ref, run, name = sys.argv[1:4]
worst, failures = 0.0, []
def tolerance(summary):
    return 1e-5 if "newton" in summary else 1e-9
def walk(x, y, path, tol):
    global worst
    if isinstance(x, dict):
        for k, v in x.items():
            # timings, and paths (the record file: where the tree is)
            if "second" in k or k in ("warnings", "solver", "record", "newton"):
                continue
            if k not in y:
                failures.append(f"{path}/{k} missing")
                continue
            walk(v, y[k], f"{path}/{k}", tol)
    elif isinstance(x, list):
        if len(x) != len(y):
            failures.append(f"{path}: {len(x)} vs {len(y)} values")
            return
        for i, (p, q) in enumerate(zip(x, y)):
            walk(p, q, f"{path}[{i}]", tol)
    elif isinstance(x, (int, float)) and not isinstance(x, bool):
        d = abs(x - y) / max(abs(x), 1e-12)
        worst = max(worst, d)
        if d > tol:
            failures.append(f"{path}: {x} now {y} (rel. {d:.1e})")
    elif x != y:
        failures.append(f"{path}: {x!r} now {y!r}")
for root, _, files in os.walk(ref):
    sub = os.path.relpath(root, ref)
    s = json.load(open(os.path.join(root, "summary.json"))) if "summary.json" in files else {}
    tol = tolerance(s) if s else 1e-6
    for f in sorted(files):
        a, b = os.path.join(root, f), os.path.join(run, sub, f)
        if f == "summary.json":
            walk(s, json.load(open(b)), f"{sub}/{f}", tol)
            continue
        if f == "table1.csv":
            # columns of the numbers of the summaries (timings excluded)
            A = np.genfromtxt(a, delimiter=",", names=True, dtype=None, encoding=None)
            B = np.genfromtxt(b, delimiter=",", names=True, dtype=None, encoding=None)
            cols = [c for c in A.dtype.names if A[c].dtype.kind == "f"
                    and "second" not in c and "newton" not in c]
        else:
            A = np.genfromtxt(a, delimiter=",", names=True)
            B = np.genfromtxt(b, delimiter=",", names=True)
            cols = list(A.dtype.names)
        scale = max(np.nanmax(np.abs(A[c])) for c in cols) or 1.0
        d = max(np.nanmax(np.abs(A[c] - B[c])) for c in cols) / scale
        worst = max(worst, d)
        if d > tol:
            failures.append(f"{sub}/{f}: max difference {d:.1e} of the largest value")
print(f"{name}: largest relative difference {worst:.1e}")
for f in failures[:20]:
    print("  " + f)
sys.exit(1 if failures else 0)
PY
done < <(regression_cases)
exit $status

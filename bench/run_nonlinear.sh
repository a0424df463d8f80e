#!/usr/bin/env bash
# Cost of the nonlinear concrete runs against the elastic one on the same
# mesh and engine (issue: a viscoplastic step should cost at most 3 elastic
# steps): runs a Table 1 case (default demos/koyna/koyna_table1.toml) and
# writes bench/results/<name>-nonlinear-<date>.md from the three summaries.
#   bench/run_nonlinear.sh [BUILD_DIR] [EXECUTABLE] [CASE] [--set ...]
# Run by hand on an otherwise idle machine (it takes minutes).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
exe=${2:-koyna}
case=${3:-$root/demos/koyna/koyna_table1.toml}
shift $(( $# < 3 ? $# : 3 ))
out=$root/bench/results
mkdir -p "$out"
report=$out/$exe-nonlinear-$(date +%Y-%m-%d).md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/$exe" --case "$case" --out "$work" --set output.plots=false \
  --set output.every=100000 "$@" >"$work.log" 2>&1
/usr/bin/python3 - "$work" "$case" "$report" <<'PY'
import json, sys, subprocess
work, case, report = sys.argv[1:4]
rows = []
for m in ("elastic", "plastic", "viscoplastic"):
    s = json.load(open(f"{work}/{m}/summary.json"))
    rows.append((m, s))
el = rows[0][1]["seconds_per_step"]
cpu = subprocess.run(["bash", "-c", "grep -m1 'model name' /proc/cpuinfo | cut -d: -f2"],
                     capture_output=True, text=True).stdout.strip()
with open(report, "w") as f:
    f.write(f"# Nonlinear concrete cost, {case}\n\n")
    f.write(f"Machine: {cpu}; one rank; one run each (the runs take minutes).\n\n")
    f.write("| model | cells | dofs | Newton it./step | max it. in a step | tangent factorisations | step cuts | s/step | / elastic | max tension [MPa] | max compression [MPa] | crest [cm] |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for m, s in rows:
        n = s["newton"]
        f.write(f"| {m} | {s['n_cells']} | {s['n_dofs']} | {n['iterations_per_step']:.2f} | "
                f"{int(n['max_iterations_in_a_step'])} | {int(n['tangent_factorizations'])} | "
                f"{int(n['step_cuts'])} | {s['seconds_per_step']:.4f} | "
                f"{s['seconds_per_step'] / el:.1f} | "
                f"{s['max_principal_tension_mpa']['value']:.2f} | "
                f"{s['max_principal_compression_mpa']['value']:.2f} | "
                f"{100 * s['crest_displacement_max_m']['value']:.2f} |\n")
print(open(report).read())
PY

#!/usr/bin/env bash
# Cost of the nonlinear concrete runs against the elastic one on the same
# mesh and engine (issue: a viscoplastic step should cost at most 3 elastic
# steps): runs a Table 1 case (default demos/koyna/koyna_table1.toml) and
# writes bench/results/<name>-nonlinear-<date>.md from the three summaries.
#   bench/run_nonlinear.sh [BUILD_DIR] [EXECUTABLE] [CASE] [--set ...]
# BENCH_TAG=x appends -x to the report's name (e.g. a run with
# --set solver.material_integration=implex); an existing report is kept and
# the new one gets -2, -3, ... after the date.
# Run by hand on an otherwise idle machine (it takes minutes).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
exe=${2:-koyna}
case=${3:-$root/demos/koyna/koyna_table1.toml}
shift $(( $# < 3 ? $# : 3 ))
out=$root/bench/results
mkdir -p "$out"
report=$out/$exe-nonlinear${BENCH_TAG:+-$BENCH_TAG}-$(date +%Y-%m-%d).md
# Never overwrite a report (it may carry notes by hand): -2, -3, ...
k=2
while [ -e "$report" ]; do
  report=$out/$exe-nonlinear${BENCH_TAG:+-$BENCH_TAG}-$(date +%Y-%m-%d)-$k.md
  k=$((k + 1))
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bin/$exe" --case "$case" --out "$work" --set output.plots=false \
  --set output.every=100000 "$@" >"$work.log" 2>&1
# The linear engine on the same mesh (one solve per step, no material
# points): the floor any nonlinear step is compared with as well.
"$build/bin/$exe" --case "$case" --out "$work/linear" --set output.plots=false \
  --set output.every=100000 --set study.table1=false \
  --set material.model=linear "$@" >>"$work.log" 2>&1
/usr/bin/python3 - "$work" "${case#"$root"/}" "$report" <<'PY'
import json, os, sys, subprocess
work, case, report = sys.argv[1:4]
rows = []
for m in ("elastic", "plastic", "viscoplastic"):
    s = json.load(open(f"{work}/{m}/summary.json"))
    rows.append((m, s))
lin = json.load(open(f"{work}/linear/summary.json"))["seconds_per_step"]
el = rows[0][1]["seconds_per_step"]
cpu = subprocess.run(["bash", "-c", "grep -m1 'model name' /proc/cpuinfo | cut -d: -f2"],
                     capture_output=True, text=True).stdout.strip()
with open(report, "w") as f:
    integ = rows[1][1]["concrete"].get("material_integration", "implicit")
    f.write(f"# Nonlinear concrete cost, {case}\n\n")
    f.write(f"Material integration: {integ}.\n")
    f.write(f"Machine: {cpu}; one rank; one run each (the runs take minutes).\n")
    f.write(f"Linear engine on the same mesh: {1000 * lin:.2f} ms/step.\n\n")
    f.write("| model | cells | dofs | Newton it./step | max it. in a step | GMRES it. | tangent factorisations | step cuts | ms/step | / elastic | / linear | max tension [MPa] | max compression [MPa] | crest [cm] |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    for m, s in rows:
        n = s["newton"]
        f.write(f"| {m} | {s['n_cells']} | {s['n_dofs']} | {n['iterations_per_step']:.2f} | "
                f"{int(n['max_iterations_in_a_step'])} | {int(n.get('krylov_iterations', 0))} | "
                f"{int(n['tangent_factorizations'])} | "
                f"{int(n['step_cuts'])} | {1000 * s['seconds_per_step']:.1f} | "
                f"{s['seconds_per_step'] / el:.1f} | {s['seconds_per_step'] / lin:.0f} | "
                f"{s['max_principal_tension_mpa']['value']:.2f} | "
                f"{s['max_principal_compression_mpa']['value']:.2f} | "
                f"{100 * s['crest_displacement_max_m']['value']:.2f} |\n")
    f.write("\nTime of the time-history loop by part [s]:\n\n")
    f.write("| model | material update + residual | of which return maps | tangent assembly | factorisations | direction solves | loop |\n")
    f.write("|---|---|---|---|---|---|---|\n")
    for m, s in rows:
        t = s["newton"].get("seconds", {})
        loop = s["time_loop_seconds"]
        f.write(f"| {m} | {t.get('residual', 0):.1f} | {t.get('return_maps_core_seconds', 0):.1f} | "
                f"{t.get('tangent_assembly', 0):.1f} | "
                f"{t.get('factorization', 0):.1f} | {t.get('direction_solves', 0):.1f} | {loop:.1f} |\n")
    f.write("\nReturn maps in the run (points that left the elastic fast path; plane "
            "stress: all return maps of a point's sigma_zz iteration):\n\n")
    f.write("| model | points | return maps | return maps per point | points per core-second |\n")
    f.write("|---|---|---|---|---|\n")
    for m, s in rows[1:]:
        n = s["newton"]
        pts = n.get("returned_points", 0)
        f.write(f"| {m} | {int(pts)} | {int(n['return_maps'])} | "
                f"{n['return_maps'] / pts if pts else 0:.2f} | "
                f"{n.get('returned_points_per_core_second', 0):.3g} |\n")
    if os.path.exists(f"{work}/table1.md"):
        f.write("\n## Table 1 as written by the demo\n\n" + open(f"{work}/table1.md").read())
print(open(report).read())
PY

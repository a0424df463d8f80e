#!/usr/bin/env bash
# The paper-scale 102 m arch dam on rock with mass and a viscous-spring
# or multi-transmitting boundary (wave input) against the massless
# foundation, side by side on RANKS ranks, the 1000-step record, mesh and
# modes included (issue 20's speed target: at most 1.5x the massless
# run's whole wall time; run by hand on an otherwise idle machine). Writes
# bench/results/foundation-<date>.md: whole-run and per-step ratios, the
# stages, and the step split into the solve and the free-field load.
#   bench/run_foundation.sh [BUILD_DIR] [RANKS] [STEPS] [BOUNDARY]
#                           [EXTRA --set ARGS... (both runs)]
# BOUNDARY: viscous_spring (default) or mtf; with mtf the band implicit,
# one layer of 80 m P2 cells (s = c_p dt / dx = 0.9 at the record's 0.01
# s), order 1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
ranks=${2:-2}
steps=${3:-1000}
boundary=${4:-viscous_spring}
shift $(( $# < 4 ? $# : 4 ))
extra=("$@")
boundary_args=(--set foundation.boundary="$boundary")
if [ "$boundary" = mtf ]; then
  boundary_args+=(--set foundation.band_integration=implicit
                  --set foundation.band_size=80 --set foundation.band_layers=1
                  --set foundation.mtf_order=1)
fi
report=$root/bench/results/foundation-$(date +%Y-%m-%d).md
for suffix in b c d e f; do # keep the earlier reports of the day
  [ -e "$report" ] || break
  report=$root/bench/results/foundation-$(date +%Y-%m-%d)$suffix.md
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
case=$root/demos/arch_dam/presets/paper_102m_v.toml
duration=$(python3 -c "print($steps * 0.01)")

run() { # name args...
  local name=$1
  shift
  /usr/bin/time -f "%e %M" -o "$work/$name.time" mpirun -n "$ranks" \
    "$build/bin/arch_dam" --case "$case" --out "$work/$name" \
    --set output.plots=false --set output.every=100000 \
    --set reservoir.level=100 --set motion.stream.peak_g=0.2 \
    --set time.duration="$duration" "${extra[@]}" "$@" >"$work/$name.log" 2>&1
}
run massless
run "$boundary" "${boundary_args[@]}"

python3 - "$work" "$ranks" "$(git -C "$root" rev-parse --short HEAD)" \
  "$boundary" >"$report" <<'PY'
import json, sys, datetime
work, ranks, commit, boundary = sys.argv[1:]
def load(name):
    s = json.load(open(f"{work}/{name}/summary.json"))
    wall, mem = open(f"{work}/{name}.time").read().split()
    return s, float(wall), int(mem) / 1024
a, aw, am = load("massless")
b, bw, bm = load(boundary)
n = a["steps"]
kind = {"mtf": "a multi-transmitting boundary (band implicit)",
        "viscous_spring": "a viscous-spring boundary"}[boundary]
print(f"# Rock with mass and {kind} against the massless "
      f"foundation, paper-scale arch dam, "
      f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}\n")
print(f"102 m arch dam (demos/arch_dam/presets/paper_102m_v.toml), 13 bonded "
      f"joints, reservoir 100 m, El Centro NS scaled to 0.2 g along the "
      f"stream, {n} steps of 0.01 s, {ranks} MPI ranks; wall: the whole "
      f"mpirun (GNU time); memory: the largest process.\n")
print("| foundation | cells | dofs | modal [s] | factor [s] | setup and "
      "static [s] | per step [ms] | of which free-field load [ms] | time "
      "loop [s] | wall [s] | peak memory [MB] |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for name, s, w, m in (("massless", a, aw, am), (boundary, b, bw, bm)):
    ff = s.get("foundation", {}).get("free_field_load_seconds", 0.0)
    print(f"| {name} | {s['n_cells']} | {s['n_dofs']} | {s['modal_seconds']:.1f} | "
          f"{s['factorization_seconds']:.1f} | {s['setup_and_static_seconds']:.1f} | "
          f"{1000 * s['seconds_per_step']:.1f} | {1000 * ff / n:.2f} | "
          f"{s['time_loop_seconds']:.1f} | {w:.1f} | {m:.0f} |")
rest = {"viscous_spring": "the solve with the dashpots' damping (one more "
                          "product)",
        "mtf": "the solve, the formula at the boundary's nodes (a scatter "
               "and the stencils) and the prescribed rows' lifting (one "
               "product)"}[boundary]
ff = b.get("foundation", {}).get("free_field_load_seconds", 0.0)
print(f"\nWhole run: {bw / aw:.2f}x the massless run (target: at most 1.5x). "
      f"Per step: {b['seconds_per_step'] / a['seconds_per_step']:.2f}x; the "
      f"free-field load (the free field at every node, sparse products) "
      f"{1000 * ff / n:.2f} ms of {1000 * b['seconds_per_step']:.1f} ms; the "
      f"rest of the step is {rest}.")
for s, name in ((a, "massless"), (b, boundary)):
    print(f"\n{name}: frequencies {', '.join(f'{f:.3f}' for f in s['frequencies_hz'][:4])} Hz, "
          f"crest {100 * abs(s['crest_displacement_max_m']['value']):.2f} cm, "
          f"max tension {s['max_principal_tension_mpa']['value']:.2f} MPa")
PY
echo "wrote $report"

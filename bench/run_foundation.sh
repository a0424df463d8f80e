#!/usr/bin/env bash
# The paper-scale 102 m arch dam on rock with mass and a viscous-spring
# or multi-transmitting boundary (wave input) against the massless
# foundation, side by side on RANKS ranks, the 1000-step record, mesh and
# modes included (issue 20's speed target: at most 1.5x the massless
# run's whole wall time; run by hand on an otherwise idle machine). Writes
# bench/results/foundation-<date>.md: whole-run and per-step ratios, the
# stages, and the step split into the solve, the explicit band, the
# boundary update and the free-field load.
#   bench/run_foundation.sh [BUILD_DIR] [RANKS] [STEPS] [BOUNDARY]
#                           [EXTRA --set ARGS... (both runs)]
# BOUNDARY: viscous_spring (default), mtf or mtf_explicit. With mtf the
# band implicit, one layer of 80 m P2 cells (s = c_p dt / dx = 0.9 at the
# record's 0.01 s), order 1. With mtf_explicit the same band explicit:
# a first run finds its stable step (it stops with exit 2 at 0.01 s and
# states it), then STEPS steps at 0.95 of it; the report gives the cost
# of the whole record at that step from the measured per-step time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
ranks=${2:-2}
steps=${3:-1000}
boundary=${4:-viscous_spring}
shift $(( $# < 4 ? $# : 4 ))
extra=("$@")
boundary_args=(--set foundation.boundary="${boundary%_explicit}")
case $boundary in
  mtf | mtf_explicit)
    integration=implicit
    [ "$boundary" = mtf_explicit ] && integration=explicit
    boundary_args+=(--set foundation.band_integration=$integration
                    --set foundation.band_size=80 --set foundation.band_layers=1
                    --set foundation.mtf_order=1) ;;
esac
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
if [ "$boundary" = mtf_explicit ]; then
  # The band's stable step, stated before the run refuses the record's.
  run probe "${boundary_args[@]}" || true
  stable=$(sed -n 's/.*explicit band: stable time step \([0-9.e+-]*\) s.*/\1/p' \
           "$work/probe.log")
  [ -n "$stable" ] || { echo "no stable step in the probe's log" >&2; exit 1; }
  dt=$(python3 -c "print(0.95 * $stable)")
  run "$boundary" "${boundary_args[@]}" --set time.dt="$dt" \
    --set time.duration="$(python3 -c "print($steps * $dt)")"
else
  run "$boundary" "${boundary_args[@]}"
fi

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
        "mtf_explicit": "a multi-transmitting boundary (band explicit)",
        "viscous_spring": "a viscous-spring boundary"}[boundary]
print(f"# Rock with mass and {kind} against the massless "
      f"foundation, paper-scale arch dam, "
      f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}\n")
print(f"102 m arch dam (demos/arch_dam/presets/paper_102m_v.toml), 13 bonded "
      f"joints, reservoir 100 m, El Centro NS scaled to 0.2 g along the "
      f"stream, {n} steps of 0.01 s, {ranks} MPI ranks; wall: the whole "
      f"mpirun (GNU time); memory: the largest process.\n")
print("| foundation | cells | dofs | time step [s] | steps | modal [s] | factor [s] | setup and "
      "static [s] | per step [ms] | time loop [s] | wall [s] | peak memory [MB] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for name, s, w, m in (("massless", a, aw, am), (boundary, b, bw, bm)):
    print(f"| {name} | {s['n_cells']} | {s['n_dofs']} | {s['dt_s']:.4g} | {s['steps']} | "
          f"{s['modal_seconds']:.1f} | "
          f"{s['factorization_seconds']:.1f} | {s['setup_and_static_seconds']:.1f} | "
          f"{1000 * s['seconds_per_step']:.1f} | "
          f"{s['time_loop_seconds']:.1f} | {w:.1f} | {m:.0f} |")
f = b.get("foundation", {})
nb = b["steps"]
ff = 1000 * f.get("free_field_load_seconds", 0.0) / nb
split = f.get("step_seconds")
print(f"\nThe {boundary} run's step, ms (rank 0's clock):\n")
if split:
    ms = {k: 1000 * split[k] / split["steps"] for k in ("solve", "band", "boundary", "rest")}
    print("| implicit solve | explicit band | boundary update | free-field load | rest (predictors, products, energy) | step |")
    print("|---|---|---|---|---|---|")
    print(f"| {ms['solve']:.1f} | {ms['band']:.1f} | {ms['boundary']:.1f} | {ff:.1f} | "
          f"{ms['rest']:.1f} | {1000 * b['seconds_per_step']:.1f} |")
    print("\n(explicit band: its stiffness damping's products; its elastic "
          "forces ride in the product of all elements' K, under rest. "
          "Boundary update: the formula at the boundary's nodes and the "
          "prescribed rows' predictors and lifting.)")
else:
    print(f"free-field load {ff:.2f} ms of {1000 * b['seconds_per_step']:.1f} ms; "
          f"the rest is the solve with the dashpots' damping (one more product).")
if boundary == "mtf_explicit":
    record_steps = round(n * a["dt_s"] / b["dt_s"])
    loop = record_steps * b["seconds_per_step"]
    whole = bw - b["time_loop_seconds"] + loop
    stable = f["mtf"]["stable_dt_s"]
    print(f"\nThe band's stable step {stable:.4g} s: the record's {n * a['dt_s']:.0f} s "
          f"take {record_steps} steps at {b['dt_s']:.4g} s. At the measured "
          f"{1000 * b['seconds_per_step']:.1f} ms per step the time loop would take "
          f"{loop:.0f} s and the whole run about {whole:.0f} s, "
          f"{whole / aw:.2f}x the massless run (target: at most 1.5x, "
          f"at the record's step).")
else:
    print(f"\nWhole run: {bw / aw:.2f}x the massless run (target: at most 1.5x). "
          f"Per step: {b['seconds_per_step'] / a['seconds_per_step']:.2f}x.")
for s, name in ((a, "massless"), (b, boundary)):
    print(f"\n{name}: frequencies {', '.join(f'{f:.3f}' for f in s['frequencies_hz'][:4])} Hz, "
          f"crest {100 * abs(s['crest_displacement_max_m']['value']):.2f} cm, "
          f"max tension {s['max_principal_tension_mpa']['value']:.2f} MPa")
PY
echo "wrote $report"

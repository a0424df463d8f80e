#!/usr/bin/env bash
# Contact joints against bonded joints on the paper-scale arch dam (the 102
# m dam of Lin et al., 13 joints, 2.3 m mesh), side by side on RANKS ranks,
# the 1000-step record (run by hand on an otherwise idle machine; takes
# about half an hour). Writes bench/results/contact-<date>.md: whole-run
# and per-step ratios, the stages, and the contact step split into bulk
# solve, contact solve and impact correction.
#   bench/run_contact.sh [BUILD_DIR] [RANKS] [STEPS] [EXTRA --set ARGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
ranks=${2:-2}
steps=${3:-1000}
shift $(( $# < 3 ? $# : 3 ))
extra=("$@")
report=$root/bench/results/contact-$(date +%Y-%m-%d).md
for suffix in b c d e f; do # keep the earlier reports of the day
  [ -e "$report" ] || break
  report=$root/bench/results/contact-$(date +%Y-%m-%d)$suffix.md
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
run bonded
run contact --set joints.model=contact

python3 - "$work" "$ranks" "$(git -C "$root" rev-parse --short HEAD)" \
  >"$report" <<'PY'
import json, sys, datetime
work, ranks, commit = sys.argv[1:]
def load(name):
    s = json.load(open(f"{work}/{name}/summary.json"))
    wall, mem = open(f"{work}/{name}.time").read().split()
    return s, float(wall), int(mem) / 1024
b, bw, bm = load("bonded")
c, cw, cm = load("contact")
j = c["joints"]
n = c["steps"]
print(f"# Contact joints against bonded joints, paper-scale arch dam, "
      f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}\n")
print(f"102 m arch dam (demos/arch_dam/presets/paper_102m_v.toml), 13 joints, "
      f"reservoir 100 m, El Centro NS scaled to 0.2 g along the stream, "
      f"{n} steps of 0.01 s, {ranks} MPI ranks; wall: the whole mpirun (GNU "
      f"time); memory: the largest process.\n")
print("| joints | cells | dofs | pairs | mesh [s] | modal [s] | factor [s] | "
      "setup and static [s] | per step [ms] | time loop [s] | wall [s] | peak memory [MB] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for name, s, w, m in (("bonded", b, bw, bm), ("contact", c, cw, cm)):
    pairs = s["joints"].get("pairs", "-")
    print(f"| {name} | {s['n_cells']} | {s['n_dofs']} | {pairs} | "
          f"{s['mesh_seconds']:.1f} | {s['modal_seconds']:.1f} | "
          f"{s['factorization_seconds']:.1f} | {s['setup_and_static_seconds']:.1f} | "
          f"{1e3 * s['seconds_per_step']:.0f} | {s['time_loop_seconds']:.0f} | "
          f"{w:.0f} | {m:.0f} |")
sec = j["seconds"]
print(f"\nRatios contact / bonded: whole run {cw / bw:.2f} (target at most 1.4), "
      f"per step {c['seconds_per_step'] / b['seconds_per_step']:.2f} "
      f"(target at most 1.5).\n")
print("Contact step, mean per step [ms]: bulk solve (condense + expand) "
      f"{1e3 * sec['bulk_solve'] / n:.0f}, contact solve (rank 0) "
      f"{1e3 * sec['contact_solve'] / n:.1f}, impact correction "
      f"{1e3 * sec['impact_correction'] / n:.2f}; flexibility set-up "
      f"{sec['flexibility_setup']:.1f} s (static and dynamic factorisations; "
      f"{j.get('pairs_condensed_on_relative_displacement', 0)} of "
      f"{j['pairs']} pairs condensed on their relative displacement). "
      f"NCP iterations {j['ncp_iterations']} ({j['ncp_iterations'] / n:.2f} per "
      f"step), line-search steps {j['line_search_steps']}, state changes "
      f"{j['state_changes']}, impacts {j['impacts']}; largest opening "
      f"{j['max_opening_cm']:.3f} cm, largest sliding {j['max_sliding_cm']:.3f} cm.")
print("\nJoint table (largest opening and sliding, cm):\n")
print(open(f"{work}/contact/joint_table.md").read())
PY
echo "wrote $report"
cat "$report"

#!/usr/bin/env bash
# Benchmark of the arch_dam demo at the paper's scale (run by hand on an
# otherwise idle machine; takes tens of minutes and several GB of memory).
# Writes bench/results/arch[-TAG]-<date>.md.
#   [BENCH_TAG=name] bench/run_arch.sh [BUILD_DIR] [RANKS] [STEPS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
ranks=${2:-2}
steps=${3:-1000}
out=$root/bench/results
mkdir -p "$out"
report=$out/arch${BENCH_TAG:+-$BENCH_TAG}-$(date +%Y-%m-%d).md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
dt=0.01
duration=$(python3 -c "print($steps * $dt)")

run() { # name case args...
  local name=$1 case=$2
  shift 2
  /usr/bin/time -f "%M" -o "$work/mem" mpirun -n "$ranks" "$build/bin/arch_dam" \
    --case "$case" --out "$work/o" --set output.plots=false \
    --set output.every=100000 --set time.duration="$duration" "$@" \
    >"$work/log" 2>&1
  python3 - "$name" "$work/o/summary.json" "$(cat "$work/mem")" "$ranks" >>"$report" <<'PY'
import json, sys
name, summ, mem, ranks = sys.argv[1:]
s = json.load(open(summ))
print(f"| {name} | {ranks} | {s['n_cells']} | {s['n_dofs']} | {s['joints']['count']} | "
      f"{s['mesh_seconds']:.1f} | {s['modal_seconds']:.1f} | {s['factorization_seconds']:.1f} | "
      f"{s['steps']} | {1e3 * s['seconds_per_step']:.0f} | {s['time_loop_seconds']:.0f} | "
      f"{s['wall_seconds']:.0f} | {int(mem) / 1024:.0f} |")
PY
}

{
  echo "# arch_dam benchmarks, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)."
  echo "P2 tetrahedra, massless foundation, bonded joints, Westergaard added mass,"
  echo "MUMPS Cholesky, $steps steps of $dt s (El Centro, river direction),"
  echo "envelopes at every stress point every step, XDMF fields off."
  echo "Peak memory: largest process (GNU time), per rank."
  echo
  echo "| case | ranks | cells | dofs | joints | mesh [s] | modal [s] | factor [s] | steps | per step [ms] | time loop [s] | wall [s] | peak memory per rank [MB] |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} >"$report"

run "paper 102 m dam, paper-scale mesh (2.3 m)" \
  "$root/demos/arch_dam/presets/paper_102m_v.toml" \
  --set reservoir.level=100 --set motion.stream.peak_g=0.2
run "Xiluodu-like, paper-scale mesh" \
  "$root/demos/arch_dam/presets/xiluodu_like.toml" \
  --set reservoir.level=215 --set motion.stream.peak_g=0.321
echo "wrote $report"
cat "$report"

#!/usr/bin/env bash
# Benchmarks of the koyna demo and of the factorisations (run by hand, on an
# otherwise idle machine). Writes bench/results/koyna-<date>.md.
#   bench/run.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out=$root/bench/results
mkdir -p "$out"
report=$out/koyna-$(date +%Y-%m-%d).md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
runs=3

{
  echo "# koyna benchmarks, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo),"\
       "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)."
  echo "1000 steps of 0.01 s (El Centro scaled to 0.38 g), Newmark average acceleration,"
  echo "envelopes at every stress point every step, XDMF fields off (output.every"
  echo "= 100000) unless stated. Median of $runs runs; peak memory is the largest"
  echo "process's maximum resident set (GNU time)."
  echo
  echo "| case | ranks | cells | dofs | factorisation | factor [s] | time loop [s] | per step [ms] | wall [s] | peak memory [MB] |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
} >"$report"

run_case() { # name ranks args...
  local name=$1 ranks=$2
  shift 2
  local loops=() walls=() mems=()
  for i in $(seq $runs); do
    local launcher=()
    [ "$ranks" -gt 1 ] && launcher=(mpirun -n "$ranks")
    /usr/bin/time -f "%M" -o "$work/mem" "${launcher[@]}" "$build/bin/koyna" \
      --out "$work/o" --set output.plots=false "$@" >/dev/null
    loops+=("$(python3 -c "import json;print(json.load(open('$work/o/summary.json'))['time_loop_seconds'])")")
    walls+=("$(python3 -c "import json;print(json.load(open('$work/o/summary.json'))['wall_seconds'])")")
    mems+=("$(cat "$work/mem")")
  done
  python3 - "$name" "$ranks" "$work/o/summary.json" "${loops[*]}" "${walls[*]}" "${mems[*]}" >>"$report" <<'PY'
import json, statistics, sys
name, ranks, summ, loops, walls, mems = sys.argv[1:]
s = json.load(open(summ))
med = lambda v: statistics.median(float(x) for x in v.split())
loop = med(loops)
print(f"| {name} | {ranks} | {s['n_cells']} | {s['n_dofs']} | {s['solver']} | "
      f"{s['factorization_seconds']:.3f} | {loop:.3f} | {1e3 * loop / s['steps']:.3f} | "
      f"{med(walls):.2f} | {med(mems) / 1024:.0f} |")
PY
}

quiet=(--set output.every=100000)
run_case "default case (2 m, P2)" 1 "${quiet[@]}"
run_case "default case with XDMF every 10 steps" 1
run_case "1 m, P2" 1 --set mesh.size=1 "${quiet[@]}"
run_case "0.65 m, P2 (about 20,000 cells)" 1 --set mesh.size=0.65 "${quiet[@]}"
run_case "2 m, P2" 2 "${quiet[@]}"
run_case "1 m, P2" 2 --set mesh.size=1 "${quiet[@]}"

{
  echo
  echo "## Factorisations of the effective matrix (bench_factorizations)"
  echo
  "$build/bin/bench_factorizations" 2 2 500
  echo
  "$build/bin/bench_factorizations" 1 2 300
  echo
  mpirun -n 2 "$build/bin/bench_factorizations" 1 2 100
} >>"$report"
echo "wrote $report"
cat "$report"

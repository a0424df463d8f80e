#!/usr/bin/env bash
# The size estimate printed before meshing (geometry::estimate_size) against
# the measured run: cells, dofs, peak memory (all ranks), time per linear
# step. Run by hand on an idle machine; writes
# bench/results/size-estimate-<date>.md.
#   bench/run_size_estimate.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
report=$root/bench/results/size-estimate-$(date +%Y-%m-%d).md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

{
  echo "# Size estimate before meshing against the run, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)."
  echo "Linear analyses, XDMF fields off, one run each. Estimated / measured;"
  echo "memory is the sum over ranks of the peak resident set (GNU time, per"
  echo "rank); time per step from summary.json (seconds_per_step). The 2D time"
  echo "fit (geometry/mesh_estimate.cpp) was made on these runs except the one"
  echo "marked; memory and 3D on earlier benchmarks (koyna-, arch-2026-11-22.md)."
  echo
  echo "| case | ranks | cells est. / run | dofs est. / run | memory est. / run [GB] | per step est. / run [ms] |"
  echo "|---|---|---|---|---|---|"
} >"$report"

run_case() { # name demo ranks args...
  local name=$1 demo=$2 ranks=$3
  shift 3
  local launcher=()
  [ "$ranks" -gt 1 ] && launcher=(mpirun -n "$ranks")
  rm -rf "$work/o"
  "${launcher[@]}" /usr/bin/time -f "%M" -a -o "$work/mem" "$build/bin/$demo" \
    --out "$work/o" --set output.plots=false --set output.every=100000 "$@" \
    >"$work/log"
  local est
  est=$(grep -m1 "size estimate before meshing" "$work/log")
  python3 - "$name" "$ranks" "$work/o/summary.json" "$work/mem" "$est" >>"$report" <<'PY'
import json, re, sys
name, ranks, summary, mem, est = sys.argv[1:]
s = json.load(open(summary))
kb = sum(int(l) for l in open(mem) if l.strip())
n = [float(x.replace(',', '')) for x in re.findall(r'([\d.,]+) (?:cells|dofs|GB|ms)', est)]
cells = s['n_cells']
dofs = s['n_dofs']
print(f"| {name} | {ranks} | {n[0]:.0f} / {cells} | {n[1]:.0f} / {dofs} | "
      f"{n[2]:.2f} / {kb/1e6:.2f} | {n[3]:.3g} / {1e3*s['seconds_per_step']:.3g} |")
PY
  rm -f "$work/mem"
}

run_case "koyna, 2 m, P2" koyna 1
run_case "koyna, 1 m, P2" koyna 1 --set mesh.size=1
run_case "koyna, 0.7 m, P1" koyna 1 --set mesh.size=0.7 --set mesh.order=1
run_case "koyna, 0.65 m, P2 (not in the fit)" koyna 1 --set mesh.size=0.65
run_case "koyna, 2 m, P2, foundation" koyna 1 --set foundation.enabled=true
run_case "rcc_gravity (linear), its P1 mesh" rcc_gravity 1 --set study.table1=false --set material.model=linear
run_case "arch_dam demo (6 m, P2), 1 s" arch_dam 2 --set time.duration=1.0
echo "report: $report"

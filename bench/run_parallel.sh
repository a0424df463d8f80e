#!/usr/bin/env bash
# Serial against 2 ranks on the 2D koyna section (2 m and 1 m meshes, 1000
# steps) and on the paper-scale 3D arch dam (100 steps), run by hand on an
# otherwise idle machine. Writes bench/results/parallel-<date>.md.
#   bench/run_parallel.sh [BUILD_DIR] [ARCH_STEPS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
arch_steps=${2:-100}
report=$root/bench/results/parallel-$(date +%Y-%m-%d).md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

run() { # name ranks demo case args...
  local name=$1 ranks=$2 demo=$3 case=$4
  shift 4
  /usr/bin/time -f "%e %M" -o "$work/time" mpirun -n "$ranks" \
    "$build/bin/$demo" --case "$case" --out "$work/o" \
    --set output.plots=false "$@" >"$work/log" 2>&1
  python3 - "$name" "$ranks" "$work/o/summary.json" "$(cat "$work/time")" \
    >>"$report" <<'PY'
import json, sys
name, ranks, summ, tm = sys.argv[1:]
wall, mem = tm.split()
s = json.load(open(summ))
mesh = f"{s['mesh_seconds']:.1f}" if 'mesh_seconds' in s else "-"  # 3D only
print(f"| {name} | {ranks} | {s['n_dofs']} | {s['solver']} | "
      f"{mesh} | {s['modal_seconds']:.2f} | "
      f"{s['factorization_seconds']:.2f} | {s['steps']} | "
      f"{1e3 * s['seconds_per_step']:.2f} | {s['time_loop_seconds']:.2f} | "
      f"{float(wall):.2f} | {int(mem) / 1024:.0f} |")
PY
}

{
  echo "# Serial against 2 ranks, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD)"
  echo
  echo "Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)."
  echo "Factorisation auto (2D: PETSc LU serially, redundant PETSc LU on 2"
  echo "ranks; 3D: MUMPS). Wall: the whole mpirun, GNU time; peak memory:"
  echo "the largest process. Koyna rows alternate serial / 2 ranks, 3 pairs."
  echo
  echo "| case | ranks | dofs | factorisation | mesh [s] (3D only) | modal [s] | factor [s] | steps | per step [ms] | time loop [s] | wall [s] | peak memory [MB] |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} >"$report"

koyna=$root/demos/koyna/koyna.toml
for size in 2.0 1.0; do
  for pair in 1 2 3; do
    for ranks in 1 2; do
      run "koyna, mesh $size m" "$ranks" koyna "$koyna" --set mesh.size=$size
    done
  done
done
arch=$root/demos/arch_dam/presets/paper_102m_v.toml
duration=$(python3 -c "print($arch_steps * 0.01)")
for ranks in 1 2; do
  run "paper 102 m arch, 2.3 m mesh, 13 joints" "$ranks" arch_dam "$arch" \
    --set reservoir.level=100 --set motion.stream.peak_g=0.2 \
    --set output.every=100000 --set time.duration="$duration"
done
echo "wrote $report"
cat "$report"

#!/usr/bin/env bash
# Issue 21's run with everything on (demos/arch_dam/everything_on.toml: 13
# contact joints, viscoplastic HTC concrete, rock with mass on Liao's
# multi-transmitting boundary, the whole 20 s three-component record)
# beside the runs that switch one feature off: bonded joints, linear
# elastic concrete (material.model = "elastic": the nonlinear engine, which
# takes HHT alpha on the boundary), massless rock. Each run on RANKS ranks, one after the other (by hand, on
# an otherwise idle machine). Writes bench/results/everything-on-<date>.md
# (bench/everything_on_report.py) and keeps the runs' folders in OUT.
#   bench/run_everything_on.sh [BUILD_DIR] [RANKS] [OUT] [EXTRA --set ARGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
ranks=${2:-2}
out=${3:-/tmp/everything_on}
shift $(( $# < 3 ? $# : 3 ))
report=$root/bench/results/everything-on-$(date +%Y-%m-%d).md
for suffix in b c d e f; do # keep the earlier reports of the day
  [ -e "$report" ] || break
  report=$root/bench/results/everything-on-$(date +%Y-%m-%d)$suffix.md
done
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() { # name args...
  local name=$1
  shift
  /usr/bin/time -f "%e %M" -o "$out/$name.time" mpirun -n "$ranks" \
    "$build/bin/arch_dam" --case "$root/demos/arch_dam/everything_on.toml" \
    --out "$out/$name" "$@" >"$out/$name.log" 2>&1
}
run everything "$@"
run bonded_joints --set joints.model=bonded "$@"
run linear_concrete --set material.model=elastic "$@"
run massless_rock --set foundation.boundary=fixed "$@"
/usr/bin/python3 "$root/bench/everything_on_report.py" "$out" "$ranks" \
  "$(git -C "$root" rev-parse --short HEAD)" >"$report"
echo "$report"

#!/usr/bin/env bash
# The paper's section I study (Table 1) on RANKS ranks: the 278 m
# Xiluodu-like arch dam, elastic, plastic and viscoplastic HTC concrete at
# two reservoir levels, the whole 20 s records (issue 21's speed targets: a
# viscoplastic run at most 3x the elastic run on the same mesh and time
# step, whole runs; the whole study about half an hour on 2 cores; run by
# hand on an otherwise idle machine). Writes
# bench/results/section1-<date>.md (bench/section1_report.py).
#   bench/run_section1.sh [BUILD_DIR] [RANKS] [EXTRA --set ARGS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
ranks=${2:-2}
shift $(( $# < 2 ? $# : 2 ))
report=$root/bench/results/section1-$(date +%Y-%m-%d).md
for suffix in b c d e f; do # keep the earlier reports of the day
  [ -e "$report" ] || break
  report=$root/bench/results/section1-$(date +%Y-%m-%d)$suffix.md
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
/usr/bin/time -f "%e %M" -o "$work/study.time" mpirun -n "$ranks" \
  "$build/bin/arch_dam" --case "$root/demos/arch_dam/section1_table1.toml" \
  --out "$work/study" "$@" >"$work/study.log" 2>&1
read -r wall mem <"$work/study.time"
python3 "$root/bench/section1_report.py" "$work/study" "$wall" "$mem" \
  "$ranks" "$(git -C "$root" rev-parse --short HEAD)" >"$report"
echo "$report"

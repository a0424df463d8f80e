#!/usr/bin/env bash
# The full fuzz run (the commands of `ctest -L fuzz`: 10^5 inputs per
# target, seed 2) with its report in bench/results/fuzz-<date>.md.
#   bench/run_fuzz.sh [BUILD_DIR] [RUNS] [SEED]
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
runs=${2:-100000}
seed=${3:-2}
report=$root/bench/results/fuzz-$(date +%Y-%m-%d).md
failures=$(mktemp -d)
{
  echo "# Fuzz run, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD)"
  echo
  echo "\`damseis_fuzz --target T --runs $runs --seed $seed\` per target (one process"
  echo "each, single-threaded, 2-core machine). A finding is a crash, a hang"
  echo "(over 20 s), an exception other than the one-line input error, a message"
  echo "of several lines, with control characters or over 2,000 characters, or"
  echo "a non-finite value accepted."
  echo
  echo '```'
} >"$report"
status=0
for t in case_gravity case_arch case_material_point case_ground_motion record_at2 record_columns \
         checkpoint_meta checkpoint_rank; do
  "$build/bin/damseis_fuzz" --target "$t" --runs "$runs" --seed "$seed" \
    --failures "$failures" 2>>"$report" || status=1
done
echo '```' >>"$report"
echo >>"$report"
echo "Inputs that failed: $(ls "$failures" | wc -l) (kept in $failures)" >>"$report"
echo "report: $report"
exit $status

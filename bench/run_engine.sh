#!/usr/bin/env bash
# "No slowdown" pairs for the one-engine refactor (issue 18): the koyna
# linear time loop (1000 steps) and the arch_dam time per step, run
# alternately with the binaries before (BASE_BIN) and after (NEW_BIN) the
# change, on an otherwise idle machine. Writes
# bench/results/engine-<date>.md with each pair's ratio new/base.
#   [ARCH_PAIRS=3] bench/run_engine.sh BASE_BIN NEW_BIN [KOYNA_PAIRS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
base=$1 new=$2 pairs=${3:-5}
out=$root/bench/results
mkdir -p "$out"
report=$out/engine-$(date +%Y-%m-%d).md
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

loop_seconds() { # exe args...: prints time_loop_seconds and seconds_per_step
  "$@" --out "$work/o" --set output.plots=false >/dev/null
  python3 -c "import json;s=json.load(open('$work/o/summary.json'));print(s['time_loop_seconds'], s['seconds_per_step'])"
}

pair_case() { # name exe args...
  local name=$1 exe=$2
  shift 2
  local ratios=() b_all=() n_all=()
  for i in $(seq "$pairs"); do
    read -r b bs < <(loop_seconds "$base/$exe" "$@")
    read -r n ns < <(loop_seconds "$new/$exe" "$@")
    b_all+=("$bs") n_all+=("$ns")
    ratios+=("$(python3 -c "print($ns/$bs)")")
  done
  python3 - "$name" "${b_all[*]}" "${n_all[*]}" "${ratios[*]}" <<'PY' >>"$report"
import statistics as st, sys
name, b, n, r = sys.argv[1], *[list(map(float, a.split())) for a in sys.argv[2:]]
print(f"| {name} | {len(r)} | {1e3*st.median(b):.3f} | {1e3*st.median(n):.3f} | "
      f"{st.median(r):.3f} | {min(r):.3f} .. {max(r):.3f} |")
PY
}

{
  echo "# One-engine refactor: time loop before and after, $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo
  echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)."
  echo "Pairs run alternately (before, after); the time per step is the summary's"
  echo "seconds_per_step (the time loop without set-up, modes and factorisation);"
  echo "ratio = after / before per pair, median and range. Serial runs."
  echo
  echo "| case | pairs | before [ms/step] | after [ms/step] | ratio (median) | ratio range |"
  echo "|---|---|---|---|---|---|"
} >"$report"
pair_case "koyna, P2 2 m, 1000 steps" koyna --set output.every=100000
pairs=${ARCH_PAIRS:-3}
pair_case "arch_dam default (6 m), 50 steps" arch_dam \
  --set time.duration=0.5 --set output.every=100000
echo "written $report"
cat "$report"

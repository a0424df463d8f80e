#!/usr/bin/env bash
# Speed and acceptance of response spectra and artificial records (run by
# hand on an idle machine); writes bench/results/ground-motion-<date>.md.
#   bench/run_ground_motion.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
report=$root/bench/results/ground-motion-$(date +%Y-%m-%d).md
{
  echo "# Ground motions, $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git -C "$root" rev-parse --short HEAD)"
  echo
  echo "Machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo), serial."
  echo "Spectrum: Nigam-Jennings, 64 samples per period at least. Generation:"
  echo "three components (h, h, v 2/3), 20 s at 0.01 s, 100 control periods"
  echo "0.04-4 s, tolerance +-10%, |corr| <= 0.16, up to 10 attempts each."
  echo
  "$build/bin/bench_ground_motion"
} >"$report"
echo "report: $report"
cat "$report"

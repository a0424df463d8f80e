#!/usr/bin/env bash
# The two formulations of the joint contact problem (issue 19) on the same
# problems: every pair problem of an arch-dam contact run (7 joints, coarse
# mesh, 3 s of the default record at 0.5 g, reservoir at 60 m; the static
# stage's and the time history's, dumped by DAMSEIS_DUMP_NCP) solved again
# by bench_ncp_replay in the Alart-Curnier form (the default) and in the
# paper's polar form (--paper). Writes bench/results/ncp-formulations-
# <date>.md: problems converged, Newton iterations, line-search and
# gradient steps, the largest Cartesian residual of the forces found, time.
# Run by hand (about a minute; the dumps take about 0.6 GB in a temporary
# folder).
#   bench/compare_ncp_formulations.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
report=$root/bench/results/ncp-formulations-$(date +%Y-%m-%d).md
args=(--set mesh.size=12 --set mesh.size_far=60 --set joints.count=7
      --set time.duration=3.0 --set output.every=100 --set modal.count=4
      --set joints.model=contact --set motion.cross_stream.peak_g=0.5
      --set reservoir.level=60 --set output.plots=false)
(cd "$root/demos/arch_dam" && DAMSEIS_DUMP_NCP="$work/p" \
  "$build/bin/arch_dam" --out "$work/run" "${args[@]}" >"$work/run.log")
mapfile -t files < <(ls "$work"/p_*.bin | sort -t_ -k2 -n)
"$build/bin/bench_ncp_replay" "${files[@]}" >"$work/ac.md"
"$build/bin/bench_ncp_replay" --paper "${files[@]}" >"$work/paper.md"
python3 - "$work" "$(git -C "$root" rev-parse --short HEAD)" "${args[*]}" \
  >"$report" <<'PY'
import datetime, statistics, sys
work, commit, args = sys.argv[1:]
def rows(name):
    return [l.split("|")[1:-1] for l in open(f"{work}/{name}.md")
            if l.startswith("| /")]
print(f"# Joint contact: Alart-Curnier against the paper's formulation, "
      f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}\n")
print(f"The pair problems of one arch_dam run ({args}; "
      "static stage and time history), each solved from the run's own "
      "starting forces by bench_ncp_replay (tolerance 1e-10 on the "
      "formulation's residual over the force scale, 50 Newton iterations, "
      "two starts). Cartesian residual: the Alart-Curnier residual of the "
      "forces found, the same yardstick for both.\n")
print("| formulation | problems | pairs | converged | Newton iterations: mean, "
      "median, max | line-search steps | gradient steps | largest "
      "Cartesian residual | time: total [s], median per problem [ms] |")
print("|---|---|---|---|---|---|---|---|---|")
for name, label in (("ac", "Alart-Curnier (B)"), ("paper", "paper, polar (A)")):
    r = rows(name)
    its = [int(x[3]) for x in r]
    sec = [float(x[8]) for x in r]
    print(f"| {label} | {len(r)} | {r[0][1].strip()} | "
          f"{sum(x[2].strip() == 'yes' for x in r)} | {statistics.mean(its):.1f}, "
          f"{statistics.median(its):.0f}, {max(its)} | "
          f"{sum(int(x[4]) for x in r)} | {sum(int(x[5]) for x in r)} | "
          f"{max(float(x[7]) for x in r):.1e} | {sum(sec):.2f}, "
          f"{1e3 * statistics.median(sec):.1f} |")
failed = [x[0].strip().split("/")[-1] for x in rows("paper")
          if x[2].strip() != "yes"]
print(f"\nNot converged in the paper's form: {', '.join(failed) or 'none'}.")
PY
echo "wrote $report"
cat "$report"

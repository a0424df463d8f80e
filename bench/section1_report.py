#!/usr/bin/python3
"""Report of a section I study (bench/run_section1.sh): per run the wall
time, the time loop, the Newton work and the parts of the step, and the
ratios of the HTC runs to the elastic one at each level.
Usage: section1_report.py STUDY_DIR WALL_S MAX_RSS_KB RANKS COMMIT"""
import datetime
import json
import sys
from pathlib import Path

study, wall, mem, ranks, commit = sys.argv[1:]
study = Path(study)
levels = sorted((p for p in study.iterdir() if p.name.startswith("level_")),
                key=lambda p: -float(p.name[6:-1]))
print(f"# Section I study (Table 1), "
      f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}\n")
print(f"demos/arch_dam/section1_table1.toml, {ranks} MPI ranks. Whole study "
      f"(3 models x {len(levels)} levels, meshing, modes and static stages "
      f"included): **{float(wall) / 60:.1f} min** wall (GNU time), largest "
      f"process {int(mem) / 1024:.0f} MB.\n")
print("| level | model | cells | dofs | steps | wall [s] | time loop [s] | "
      "x elastic (wall) | Newton it./step | GMRES it. | direction solves [s] "
      "| residuals [s] | tangents [s] | return maps [core s] | cuts |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for lv in levels:
    base = None
    for model in ("elastic", "plastic", "viscoplastic"):
        s = json.load(open(lv / model / "summary.json"))
        n = s["newton"]
        sec = n["seconds"]
        base = base or s["wall_seconds"]
        print(f"| {lv.name[6:-1]} | {model} | {s['n_cells']} | {s['n_dofs']} "
              f"| {s['steps']} | {s['wall_seconds']:.1f} | "
              f"{s['time_loop_seconds']:.1f} | "
              f"{s['wall_seconds'] / base:.2f} | "
              f"{n['iterations_per_step']:.2f} | {n['krylov_iterations']:.0f} "
              f"| {sec['direction_solves']:.1f} | {sec['residual']:.1f} | "
              f"{sec['tangent_assembly']:.1f} | "
              f"{sec['return_maps_core_seconds']:.1f} | {n['step_cuts']:.0f} |")

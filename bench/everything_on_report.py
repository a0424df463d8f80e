#!/usr/bin/python3
"""Report of bench/run_everything_on.sh: per run the cost and the results
engineers read (face peaks away from the rock, crest, joints, concrete
state), then the joint tables of the three runs with contact joints.
Usage: everything_on_report.py OUT_DIR RANKS COMMIT"""
import csv
import datetime
import json
import sys
from pathlib import Path

out, ranks, commit = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
runs = [("everything", "everything on"),
        ("bonded_joints", "bonded joints"),
        ("linear_concrete", "linear concrete"),
        ("massless_rock", "massless rock")]


def load(name):
    s = json.load(open(out / name / "summary.json"))
    wall, mem = open(out / f"{name}.time").read().split()
    return s, float(wall), int(mem)


print(f"# One run with everything on (issue 21), "
      f"{datetime.datetime.utcnow():%Y-%m-%d %H:%M} UTC, commit {commit}\n")
try:
    analysis = json.load(open(out / "everything" / "summary.json"))["analysis"]
except (OSError, ValueError, KeyError):
    analysis = "(the everything-on run failed)"
print("demos/arch_dam/everything_on.toml: the Xiluodu-like arch dam, 13 "
      "contact joints, viscoplastic HTC concrete, rock with mass, the 20 s "
      "three-component record at 0.321 g, reservoir 215 m; beside it the "
      f"runs with one feature off. {ranks} MPI ranks per run; wall: the "
      "whole mpirun (GNU time); memory: the largest process.\n")
print(f"The everything-on run: {analysis}.\n")
print("| run | cells | dofs | steps | wall [s] | time loop [s] | memory [MB] "
      "| Newton it./step | cuts | NCP it. | U tension | U compression | "
      "D tension | D compression [MPa] | crest [cm] | max opening [cm] | "
      "max sliding [cm] | max strain rate [1/s] | max kappa_t |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
      "---|---|")
for name, label in runs:
    try:
        s, wall, mem = load(name)
    except (OSError, ValueError) as e:
        print(f"| {label} | failed: {e} |")
        continue
    f = s["faces"]
    a = {k: f[k]["away_from_singular_points"] for k in ("upstream", "downstream")}
    n = s.get("newton", {})
    j = s.get("joints", {})
    contact = "max_opening_cm" in j
    rate = s.get("max_strain_rate_per_s", {}).get("value")
    kappa = s.get("max_kappa_t", {}).get("value")
    print(f"| {label} | {s['n_cells']} | {s['n_dofs']} | {s['steps']} | "
          f"{wall:.0f} | {s['time_loop_seconds']:.0f} | {mem / 1024:.0f} | "
          + (f"{n['iterations_per_step']:.2f} | {n['step_cuts']:.0f} | "
             if n else "- | - | ")
          + (f"{j['ncp_iterations']} | " if contact else "- | ")
          + f"{a['upstream']['max_principal_tension_mpa']['value']:.2f} | "
          f"{a['upstream']['max_principal_compression_mpa']['value']:.2f} | "
          f"{a['downstream']['max_principal_tension_mpa']['value']:.2f} | "
          f"{a['downstream']['max_principal_compression_mpa']['value']:.2f} | "
          f"{100 * s['crest_displacement_max_m']['value']:.2f} | "
          + (f"{j['max_opening_cm']:.3f} | {j['max_sliding_cm']:.3f} | "
             if contact else "- | - | ")
          + (f"{rate:.2e} | " if rate is not None else "- | ")
          + (f"{kappa:.2e} |" if kappa is not None else "- |"))

print("\nJoint tables, largest opening / sliding over the record [cm], "
      "upstream (U) and downstream (D) faces:\n")
tables = {}
for name, label in runs:
    try:
        with open(out / name / "joint_table.csv") as fh:
            tables[label] = {r["joint"]: r for r in csv.DictReader(fh)}
    except OSError:
        pass
labels = list(tables)
print("| joint | " + " | ".join(f"{l}: opening U / D | sliding U / D"
                                for l in labels) + " |")
print("|---|" + "---|---|" * len(labels))
for joint in next(iter(tables.values())):
    cells = []
    for l in labels:
        r = tables[l][joint]
        keys = list(r)
        cells.append(f"{float(r[keys[2]]):.3f} / {float(r[keys[3]]):.3f} | "
                     f"{float(r[keys[5]]):.3f} / {float(r[keys[6]]):.3f}")
    print(f"| {joint} | " + " | ".join(cells) + " |")

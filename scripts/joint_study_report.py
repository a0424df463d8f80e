#!/usr/bin/python3
"""The paper's section II joint-opening findings checked on joint studies
(arch_dam study.joints) and extra runs, as Markdown on stdout.

Usage: joint_study_report.py NAME CANDIDATES STUDY_DIR [EXTRA=DIR ...]

CANDIDATES is the number of candidate joints (13: A ... M); STUDY_DIR
holds the study's subfolders (joints_0, joints_3_DGJ, ...) with
their summary.json; each EXTRA_DIR is a study folder of one more case
(e.g. the 7 joints excited in the river direction only). For every case:
the largest opening and sliding, where they occur (joint label and its
place along the crest: crown, quarter, abutment), the face stresses away
from the singular points (principal, arch, cantilever), the crest
displacement and the energy terms; then the paper's findings (1)-(3)
against them.
"""
import csv
import json
import sys
from pathlib import Path


def runs_of(study: Path):
    for d in sorted(study.glob("joints_*"), key=lambda p: (len(p.name), p.name)):
        f = d / "summary.json"
        if f.exists():
            s = json.loads(f.read_text())
            s["_dir"] = str(d)
            yield d.name, s


def place(label: str, labels: str) -> str:
    """Crown, quarter or abutment, by the joint's place among the
    candidates (0 at the left abutment, 1 at the right)."""
    i = labels.index(label)
    x = (i + 1) / (len(labels) + 1)
    d = abs(x - 0.5)
    return "crown" if d < 0.1 else ("quarter" if d < 0.32 else "abutment")


def largest(summary, what):
    rows = summary["joints"]["table"]
    best = max(rows, key=lambda r: r[what]["cm"])
    return best["joint"], best[what]["cm"]


def face(summary, f, kind, key="away_from_singular_points"):
    v = summary["faces"][f].get(key, {}).get(kind)
    return None if v is None else v["value"]


def off_joints(folder: Path, f: str, radius: float):
    """Largest tension and compression [MPa] of a face's envelope over the
    points away from the singular points and off the joints (node-to-node
    impacts load single points of the joint faces' edges)."""
    path = folder / f"face_{f}.csv"
    if not path.exists():
        return None, None
    rows = [r for r in csv.DictReader(open(path))
            if float(r["distance_to_singular_m"]) >= radius
            and r.get("joint_side", "0") in ("0", "0.0")]
    if not rows:
        return None, None
    return (max(float(r["max_principal_mpa"]) for r in rows),
            min(float(r["min_principal_mpa"]) for r in rows))


def fmt(v, d=2):
    return "-" if v is None else f"{v:.{d}f}"


def main() -> None:
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    name, study = sys.argv[1], Path(sys.argv[3])
    candidates = "".join(chr(ord("A") + i) for i in range(int(sys.argv[2])))
    cases = [(n, s) for n, s in runs_of(study)]
    for extra in sys.argv[4:]:
        label, d = extra.split("=", 1)
        for n, s in runs_of(Path(d)):
            cases.append((f"{n} ({label})", s))
    if not cases:
        sys.exit(f"no runs in {study}")
    print(f"## {name}\n")
    m = cases[0][1]
    print(f"Model: {m['n_cells']} cells, {m['n_dofs']} dofs, first frequency "
          f"{m['frequencies_hz'][0]:.3f} Hz; input: "
          + "; ".join(f"{k}: {v.get('record', '')} at {v.get('peak_g', 0):.3f} g"
                      for k, v in m.get("ground_motion", {}).items()
                      if isinstance(v, dict)) + "\n")
    print("| case | pairs | largest opening [cm] (joint, place) | largest "
          "sliding [cm] (joint, place) | tension U / D [MPa] | compression "
          "U / D [MPa] | off the joints: tension, compression U / D | arch "
          "tension U / D | cantilever tension U / D | "
          "crest [cm] | load work [MJ] | joint work [MJ] | impacts [MJ] | removed "
          "by HHT [MJ] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n, s in cases:
        j = s.get("joints", {})
        contact = "table" in j and j.get("model") == "contact"
        if contact:
            jo, o = largest(s, "opening")
            js, sl = largest(s, "sliding")
            open_s = f"{o:.4f} ({jo}, {place(jo, candidates)})"
            slide_s = f"{sl:.4f} ({js}, {place(js, candidates)})"
        else:
            open_s = slide_s = "-"
        e = s.get("energy", {})
        ac = "arch_cantilever_away_from_singular_points"
        r = s.get("away_from_singular_points", {}).get("radius_m", 0.0)
        tu, cu = off_joints(Path(s["_dir"]), "upstream", r)
        td, cd = off_joints(Path(s["_dir"]), "downstream", r)
        print(f"| {n} | {j.get('pairs', 0)} | {open_s} | {slide_s} | "
              f"{fmt(face(s, 'upstream', 'max_principal_tension_mpa'))} / "
              f"{fmt(face(s, 'downstream', 'max_principal_tension_mpa'))} | "
              f"{fmt(face(s, 'upstream', 'max_principal_compression_mpa'))} / "
              f"{fmt(face(s, 'downstream', 'max_principal_compression_mpa'))} | "
              f"{fmt(tu)}, {fmt(cu)} / {fmt(td)}, {fmt(cd)} | "
              f"{fmt(face(s, 'upstream', 'arch_tension_mpa', ac))} / "
              f"{fmt(face(s, 'downstream', 'arch_tension_mpa', ac))} | "
              f"{fmt(face(s, 'upstream', 'cantilever_tension_mpa', ac))} / "
              f"{fmt(face(s, 'downstream', 'cantilever_tension_mpa', ac))} | "
              f"{100 * s['crest_displacement_max_m']['value']:.2f} | "
              f"{1e-6 * e.get('load_work_j', 0):.3f} | "
              f"{1e-6 * e.get('joint_work_j', 0):.3f} | "
              f"{1e-6 * e.get('impact_corrections_j', 0):.3f} | "
              f"{-1e-6 * e.get('balance_error_j', 0):.3f} |")
    print()
    # Finding (3): arch tension released, cantilever tension little changed.
    base = next((s for n, s in cases if n == "joints_0"), None)
    most = max((s for n, s in cases if s.get("joints", {}).get("model") == "contact"),
               key=lambda s: s["joints"].get("count", 0), default=None)
    if base and most:
        ac = "arch_cantilever_away_from_singular_points"
        print("Finding (3), no joints against the most joints "
              f"({most['joints'].get('count')}):")
        for f in ("upstream", "downstream"):
            a0, a1 = face(base, f, "arch_tension_mpa", ac), face(most, f, "arch_tension_mpa", ac)
            c0, c1 = (face(base, f, "cantilever_tension_mpa", ac),
                      face(most, f, "cantilever_tension_mpa", ac))
            r = base.get("away_from_singular_points", {}).get("radius_m", 0.0)
            k0 = off_joints(Path(base["_dir"]), f, r)[1]
            k1 = off_joints(Path(most["_dir"]), f, r)[1]
            if None in (a0, a1, c0, c1, k0, k1):
                continue
            print(f"- {f} face: arch tension {a0:.2f} -> {a1:.2f} MPa "
                  f"({a1 / a0 - 1:+.0%}), cantilever tension {c0:.2f} -> "
                  f"{c1:.2f} MPa ({c1 / c0 - 1:+.0%}), compression off the "
                  f"joints {k0:.2f} "
                  f"-> {k1:.2f} MPa ({k1 / k0 - 1:+.0%})")
        print()


if __name__ == "__main__":
    main()

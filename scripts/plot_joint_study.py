#!/usr/bin/python3
"""Plot of a joint study (arch_dam's study.joints): the largest opening and
sliding of each joint along the dam axis, one line per case, on the
upstream (solid) and downstream (dashed) faces (the paper's Figs. 12-13
for several joint counts), from the subfolders' joint_table.csv and
joint_pairs.csv.

Usage: plot_joint_study.py STUDY_DIR   (writes joint_study.png)
"""
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plot_joints import column, load_joint_table  # noqa: E402


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    cases = sorted((d for d in out.glob("joints_*")
                    if (d / "joint_table.csv").exists()),
                   key=lambda d: int(d.name.split("_")[1]))
    if not cases:
        return
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    for k, case in enumerate(cases):
        table = load_joint_table(case)
        if table is None:
            continue
        rows, s, order = table
        parts = case.name.split("_")  # joints_<count>[_<labels>]
        name = f"{parts[1]} joints" + (f" ({parts[2]})" if len(parts) > 2
                                       else "")
        colour = f"C{k}"
        for ax, what in zip(axes, ("opening", "sliding")):
            for face, style in (("upstream", "-"), ("downstream", "--")):
                key = f"{what}_{face}_cm"
                if key not in rows[0]:
                    continue
                v = column(rows, key)
                ax.plot(s[order], v[order], style, color=colour, marker="o",
                        ms=3, lw=1.1,
                        label=name if face == "upstream" else None)
    for ax, what in zip(axes, ("opening", "sliding")):
        ax.set_ylabel(f"largest {what} [cm]")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize="small")
    axes[0].set_title("Joint opening and sliding along the dam axis per case "
                      "(solid: upstream face, dashed: downstream)")
    axes[1].set_xlabel("position along the axis at the crest [m]")
    fig.tight_layout()
    fig.savefig(out / "joint_study.png", dpi=130)
    plt.close(fig)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Plots of contraction-joint results (joints.model = "contact"): the
largest opening and sliding of each joint along the dam axis, per face, as
the paper's Figs. 12-13, from joint_table.csv and joint_pairs.csv.

Each joint is placed at the horizontal position of its top pair (at the
crest), projected on the direction along which the joints spread (the dam
axis), oriented so that the first joint of the table is on the left.

And the histories of opening and sliding at the pairs of
joint_histories.csv (joints.history_points; by default each joint's top
pair).

Usage: plot_joints.py OUT_DIR
(writes joints_along_axis.png and joint_histories.png)
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def joint_positions(out: Path, labels: list) -> np.ndarray:
    """Position of each joint along the axis [m]: its top pair's horizontal
    coordinates projected on the joints' main horizontal direction."""
    tops = {}
    with open(out / "joint_pairs.csv") as f:
        for row in csv.DictReader(f):
            x = np.array([float(row["x"]), float(row["y"]), float(row["z"])])
            j = row["joint"]
            if j not in tops or x[2] > tops[j][2]:
                tops[j] = x
    xy = np.array([tops[j][:2] for j in labels])
    if len(labels) < 2:
        return np.zeros(len(labels))
    centred = xy - xy.mean(axis=0)
    direction = np.linalg.svd(centred, full_matrices=False)[2][0]
    s = centred @ direction
    return s if s[0] <= s[-1] else -s


def load_joint_table(out: Path):
    """The rows of joint_table.csv, the joints' positions along the axis and
    their order along it (None if the table is empty)."""
    with open(out / "joint_table.csv") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return None
    s = joint_positions(out, [r["joint"] for r in rows])
    return rows, s, np.argsort(s)


def column(rows, key: str) -> np.ndarray:
    """A column of joint_table.csv as numbers (NaN where a joint has none)."""
    return np.array([float(r[key]) if r[key] not in ("", "-") else np.nan
                     for r in rows])


def plot_joints(out: Path) -> None:
    table = load_joint_table(out)
    if table is None:
        return
    rows, s, order = table
    labels = [r["joint"] for r in rows]
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    for ax, what in zip(axes, ("opening", "sliding")):
        faces = [c for c in rows[0] if c.startswith(what + "_")
                 and c != what + "_cm"]
        columns = faces if faces else [what + "_cm"]
        for c in columns:
            v = column(rows, c)
            name = c[len(what) + 1:-3] if faces else "all pairs"
            ax.plot(s[order], v[order], marker="o", lw=1.2,
                    label={"U": "upstream face", "D": "downstream face"}.get(
                        name, name))
        ax.set_ylabel(f"largest {what} [cm]")
        ax.set_ylim(bottom=0)
        ax.grid(alpha=0.3)
        ax.legend()
    axes[0].set_title("Joint opening (normal) and sliding (tangential) "
                      "along the dam axis")
    axes[1].set_xticks(s[order])
    axes[1].set_xticklabels([f"{labels[i]}\n{s[i]:.0f}" for i in order])
    axes[1].set_xlabel("joint, and its position along the axis at the "
                       "crest [m]")
    fig.tight_layout()
    fig.savefig(out / "joints_along_axis.png", dpi=130)
    plt.close(fig)


def plot_joint_histories(out: Path) -> None:
    data = np.genfromtxt(out / "joint_histories.csv", delimiter=",",
                         names=True)
    names = [n[:-len("_opening_cm")] for n in data.dtype.names
             if n.endswith("_opening_cm")]
    if not names or data.size < 2:
        return
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    for ax, what in zip(axes, ("opening", "sliding")):
        for n in names:
            ax.plot(data["t_s"], data[f"{n}_{what}_cm"], lw=0.9,
                    label=n.replace("_top", " (top)"))
        ax.set_ylabel(f"{what} [cm]")
        ax.grid(alpha=0.3)
    axes[0].legend(ncol=min(len(names), 7), fontsize="small")
    axes[0].set_title("Joint opening and sliding (from the static state) "
                      "at the recorded pairs")
    axes[1].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(out / "joint_histories.png", dpi=130)
    plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    plot_joints(Path(sys.argv[1]))
    plot_joint_histories(Path(sys.argv[1]))

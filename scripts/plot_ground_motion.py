#!/usr/bin/python3
"""Plots the outputs of demos/ground_motion in OUT: time_histories.png
(acceleration, velocity, displacement of each generated component) and
spectra.png (pseudo-acceleration spectra against the target with its
+-10% band, log period axis).  Usage: plot_ground_motion.py OUT"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

G = 9.80665


def read_csv(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def read_record(path):
    t, a = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            x, y = line.split()
            t.append(float(x))
            a.append(float(y))
    return t, a


def integrate(t, a):
    """Velocity and displacement from rest (exact for linear a)."""
    v, d = [0.0], [0.0]
    for k in range(len(a) - 1):
        dt = t[k + 1] - t[k]
        v.append(v[-1] + 0.5 * dt * (a[k] + a[k + 1]))
        d.append(d[-1] + dt * v[-2] + dt * dt * (a[k] / 3 + a[k + 1] / 6))
    return v, d


def time_histories(out, summary):
    comps = summary["components"]
    fig, ax = plt.subplots(3, len(comps), figsize=(4.6 * len(comps), 7.5),
                           sharex=True, squeeze=False)
    for j, c in enumerate(comps):
        t, a = read_record(os.path.join(out, c["name"] + ".txt"))
        v, d = integrate(t, a)
        for i, (y, label) in enumerate(
                [([x / G for x in a], "acceleration [g]"),
                 ([x * 100 for x in v], "velocity [cm/s]"),
                 ([x * 100 for x in d], "displacement [cm]")]):
            ax[i][j].plot(t, y, lw=0.6)
            ax[i][j].grid(True, alpha=0.4)
            if j == 0:
                ax[i][j].set_ylabel(label)
        ax[0][j].set_title("%s: PGA %.3f g" % (c["name"], c["pga_g"]))
        ax[2][j].set_xlabel("time [s]")
    fig.suptitle("Artificial records, seed %d (%s)" %
                 (summary["seed"], comps[0]["target"]), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "time_histories.png"), dpi=120)
    plt.close(fig)


def spectra(out, summary):
    s = read_csv(os.path.join(out, "spectra.csv"))
    target_file = os.path.join(out, "target_spectrum.csv")
    target = read_csv(target_file) if os.path.exists(target_file) else None
    fig, ax = plt.subplots(figsize=(8, 5))
    t = s["period_s"]
    for name, values in s.items():
        if name == "period_s":
            continue
        ax.plot(t, [x / G for x in values], lw=1.0, label=name)
    if target:
        for key, style in [("horizontal_m_s2", "k"), ("vertical_m_s2", "k--")]:
            y = [x / G for x in target[key]]
            label = "target, " + key.split("_")[0]
            ax.plot(target["period_s"], y, style, lw=1.6, label=label)
            ax.fill_between(target["period_s"], [0.9 * x for x in y],
                            [1.1 * x for x in y], color="0.5", alpha=0.15,
                            lw=0)
    ax.set_xscale("log")
    ax.set_xlabel("period [s]")
    ax.set_ylabel("pseudo-acceleration [g]")
    ax.grid(True, which="both", alpha=0.4)
    ax.legend(fontsize=8)
    title = "Response spectra"
    if target:
        title += " against the target (band: +-10%)"
    ax.set_title(title)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "spectra.png"), dpi=120)
    plt.close(fig)


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    out = sys.argv[1]
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    if summary["task"] == "generate":
        time_histories(out, summary)
    spectra(out, summary)
    return 0


if __name__ == "__main__":
    sys.exit(main())

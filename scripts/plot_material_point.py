#!/usr/bin/python3
"""Plots the CSV of demos/material_point: sigma11-eps11 curve and the
internal variables.  Usage: plot_material_point.py CSV [PNG]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else path.rsplit(".", 1)[0] + ".png"
    with open(path) as f:
        rows = list(csv.DictReader(f))
    col = lambda k: [float(r[k]) for r in rows]  # noqa: E731
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    ax[0].plot([e * 1e3 for e in col("eps11")],
               [s / 1e6 for s in col("sig11")], "-")
    ax[0].set_xlabel("eps11 [1e-3]")
    ax[0].set_ylabel("sigma11 [MPa]")
    ax[0].grid(True)
    ax[1].plot(col("time"), col("kappa_t"), label="kappa_t")
    ax[1].plot(col("time"), col("kappa_c"), label="kappa_c")
    ax[1].set_xlabel("time [s]")
    ax[1].set_ylabel("equivalent viscoplastic strain")
    ax[1].legend()
    ax[1].grid(True)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

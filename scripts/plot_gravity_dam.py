#!/usr/bin/python3
"""Plots of a gravity-dam analysis (koyna demo): crest displacement history
and contour maps of the principal-stress envelopes on the section.

Usage: plot_gravity_dam.py OUT_DIR
Reads OUT_DIR/crest.csv, OUT_DIR/envelopes.h5 and OUT_DIR/summary.json;
writes OUT_DIR/crest_history.png and OUT_DIR/envelopes.png. For nonlinear
concrete runs (OUT_DIR/dam_points.csv) also OUT_DIR/strain_rates.png: the
maximum strain rate and the final equivalent tensile viscoplastic strain at
the quadrature points (the paper's Fig. 9); and, from
OUT_DIR/displacement_envelope.csv, displacement_envelope.png (the envelope of
the horizontal displacement along the upstream face, the paper's Fig. 7),
and vertical_stress.png (envelopes of sigma_yy, the paper's Fig. 8).
"""
import json
import sys
from pathlib import Path

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402


def plot_crest(out: Path, summary: dict) -> None:
    data = np.genfromtxt(out / "crest.csv", delimiter=",", names=True)
    fig, ax = plt.subplots(figsize=(9, 4))
    ax.plot(data["t_s"], 100 * data["ux_m"], lw=0.9, label="horizontal")
    ax.plot(data["t_s"], 100 * data["uy_m"], lw=0.9, label="vertical")
    peak = summary["crest_displacement_max_m"]
    ax.plot([peak["t"]], [100 * peak["value"]], "ro", ms=4)
    ax.annotate(f"{100 * peak['value']:.2f} cm", (peak["t"], 100 * peak["value"]),
                textcoords="offset points", xytext=(6, 6))
    ax.set_xlabel("time [s]")
    ax.set_ylabel("crest displacement relative to base [cm]")
    ax.set_title("Crest displacement (seismic part)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "crest_history.png", dpi=130)
    plt.close(fig)


def plot_envelopes(out: Path, summary: dict) -> None:
    # envelopes.h5 holds the dam only (results/xdmf_writer.h layout).
    with h5py.File(out / "envelopes.h5", "r") as f:
        x = f["mesh/geometry"][:]
        cells = f["mesh/topology"][:]
        vmax = f["fields/max_principal_vertex_MPa"][:].ravel()
        vmin = f["fields/min_principal_vertex_MPa"][:].ravel()
    tri = mtri.Triangulation(x[:, 0], x[:, 1], cells)
    fig, axes = plt.subplots(1, 2, figsize=(11, 6.5))
    kind = summary.get("stress", "total")
    # Colour ranges without the singular corners (summary.json
    # away_from_singular_points): their values grow with refinement and
    # would wash out the section; beyond the range the colour saturates.
    away = summary.get("away_from_singular_points")
    for ax, values, title, key, side in (
        (axes[0], vmax, "max principal stress (tension +)",
         "max_principal_tension_mpa", "max"),
        (axes[1], vmin, "min principal stress (compression -)",
         "max_principal_compression_mpa", "min"),
    ):
        lo, hi = values.min(), values.max()
        extend = "neither"
        if away is not None:
            a = away[key]["value"]
            if side == "max" and a < hi:
                hi, extend = a, "max"
            if side == "min" and a > lo:
                lo, extend = a, "min"
        levels = np.linspace(lo, hi, 21) if hi > lo else 20
        cs = ax.tricontourf(tri, np.clip(values, lo, hi), levels=levels,
                            cmap="RdYlBu_r", extend=extend)
        fig.colorbar(cs, ax=ax, shrink=0.8, label="MPa")
        e = summary[key]
        ax.plot([e["x"]], [e["y"]], "k*", ms=9)
        text = f"peak {e['value']:.2f} MPa at t = {e['t']:.2f} s"
        if away is not None:
            r = away["radius_m"]
            for p in away.get("singular_points", []):
                ax.add_patch(plt.Circle((p[0], p[1]), r, fill=False, ls="--",
                                        lw=0.8, color="k"))
            text += (f"\n{away[key]['value']:.2f} MPa farther than "
                     f"{r:.3g} m from the dashed corners")
        ax.set_title(f"Envelope of {title}\n({kind} stress)", fontsize=10)
        ax.text(0.02, -0.16, text, transform=ax.transAxes, fontsize=8,
                va="top")
        pad = 0.05 * np.ptp(x[:, 1])
        ax.set_xlim(x[:, 0].min() - pad, x[:, 0].max() + pad)
        ax.set_ylim(x[:, 1].min() - pad, x[:, 1].max() + pad)
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    fig.tight_layout()
    fig.savefig(out / "envelopes.png", dpi=130)
    plt.close(fig)


def save_section_maps(fig, axes, summary: dict, title: str, file: Path) -> None:
    """Common finish of the maps over the dam section: equal axes in m, the
    concrete model in the title, written to `file`."""
    for ax in axes:
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    model = summary.get("concrete", {}).get("model", "")
    fig.suptitle(f"{title}: {model}")
    fig.tight_layout()
    fig.savefig(file, dpi=130)
    plt.close(fig)


def plot_strain_rates(out: Path, summary: dict) -> None:
    d = np.genfromtxt(out / "dam_points.csv", delimiter=",", names=True)
    fig, axes = plt.subplots(1, 2, figsize=(11, 6.5))
    rate = np.maximum(d["max_strain_rate_per_s"], 1e-8)
    sc = axes[0].scatter(d["x_m"], d["y_m"], c=np.log10(rate), s=4,
                         cmap="viridis")
    fig.colorbar(sc, ax=axes[0], shrink=0.8,
                 label="log10(max principal strain rate [1/s])")
    e = summary["max_strain_rate_per_s"]
    axes[0].plot([e["x"]], [e["y"]], "r*", ms=9)
    axes[0].set_title(f"Maximum strain rate (peak {e['value']:.3g} /s "
                      f"at t = {e['t']:.2f} s)", fontsize=10)
    kt = d["kappa_t"]
    sc = axes[1].scatter(d["x_m"], d["y_m"], c=kt, s=4, cmap="magma_r",
                         vmin=0, vmax=max(kt.max(), 1e-12))
    fig.colorbar(sc, ax=axes[1], shrink=0.8, label="kappa_t [-]")
    axes[1].set_title("Equivalent tensile viscoplastic strain (end)",
                      fontsize=10)
    save_section_maps(fig, axes, summary, "Concrete model",
                      out / "strain_rates.png")


def plot_vertical_stress(out: Path, summary: dict) -> None:
    """Envelopes of the vertical stress sigma_yy at the quadrature points
    (the paper's Fig. 8): largest (tension) and smallest (compression)."""
    d = np.genfromtxt(out / "dam_points.csv", delimiter=",", names=True)
    if "max_syy_mpa" not in d.dtype.names:
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 6.5))
    panels = (("max_syy_mpa", "max_vertical_stress_mpa", "Largest"),
              ("min_syy_mpa", "min_vertical_stress_mpa", "Smallest"))
    for ax, (col, key, word) in zip(axes, panels):
        v = d[col]
        lim = max(abs(v).max(), 1e-9)
        sc = ax.scatter(d["x_m"], d["y_m"], c=v, s=4, cmap="RdBu_r",
                        vmin=-lim, vmax=lim)
        fig.colorbar(sc, ax=ax, shrink=0.8,
                     label="vertical stress [MPa] (tension +)")
        e = summary.get(key)
        title = f"{word} vertical stress"
        if e:
            ax.plot([e["x"]], [e["y"]], "k*", ms=9)
            title += f" ({e['value']:.2f} MPa at t = {e['t']:.2f} s)"
        ax.set_title(title, fontsize=10)
    save_section_maps(fig, axes, summary,
                      "Envelope of the vertical stress, concrete model",
                      out / "vertical_stress.png")


def plot_displacement_envelope(out: Path, summary: dict) -> None:
    d = np.genfromtxt(out / "displacement_envelope.csv", delimiter=",",
                      names=True)
    fig, ax = plt.subplots(figsize=(5, 7))
    ax.plot(100 * d["max_m"], d["y_m"], "r-", lw=1.2, label="max (downstream)")
    ax.plot(100 * d["min_m"], d["y_m"], "b-", lw=1.2, label="min (upstream)")
    ax.axvline(0.0, color="k", lw=0.5)
    ax.set_xlabel("horizontal displacement relative to the base [cm]")
    ax.set_ylabel("elevation [m]")
    model = summary.get("concrete", {}).get("model", "linear")
    ax.set_title(f"Envelope along the upstream face ({model})", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "displacement_envelope.png", dpi=130)
    plt.close(fig)


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    summary = json.loads((out / "summary.json").read_text())
    plot_crest(out, summary)
    plot_envelopes(out, summary)
    if (out / "displacement_envelope.csv").exists():
        plot_displacement_envelope(out, summary)
    if (out / "dam_points.csv").exists():
        plot_strain_rates(out, summary)
        plot_vertical_stress(out, summary)


if __name__ == "__main__":
    main()

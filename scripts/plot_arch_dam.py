#!/usr/bin/python3
"""Plots of an arch-dam analysis (arch_dam demo): crest displacement
histories and maps of the principal-stress envelopes on the upstream and
downstream faces, each face drawn in elevation as seen by an observer in
front of it (upstream face from upstream, downstream face from downstream).

Usage: plot_arch_dam.py OUT_DIR
Reads crest.csv, face_upstream.csv, face_downstream.csv and summary.json;
writes crest_history.png, face_envelopes.png, face_arch_cantilever.png
(the arch and cantilever stress envelopes), face_strain_rate.png (HTC
concrete: face_<face>_concrete.csv) (and, with contact joints,
joints_along_axis.png and joint_histories.png: plot_joints.py).
"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from plot_joints import plot_joint_histories, plot_joints  # noqa: E402


def plot_crest(out: Path, summary: dict) -> None:
    data = np.genfromtxt(out / "crest.csv", delimiter=",", names=True)
    fig, ax = plt.subplots(figsize=(9, 4))
    names = {"ux_m": "cross-stream (x)", "uy_m": "stream (y)",
             "uz_m": "vertical (z)"}
    for key, label in names.items():
        ax.plot(data["t_s"], 100 * data[key], lw=0.9, label=label)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("crest displacement relative to base [cm]")
    ax.set_title("Crown crest displacement (seismic part)")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "crest_history.png", dpi=130)
    plt.close(fig)


def face_triangulation(x, z):
    """Delaunay triangulation of the face points in elevation, without the
    long triangles that would bridge across the outline."""
    tri = mtri.Triangulation(x, z)
    pts = np.column_stack([x, z])[tri.triangles]
    edges = np.linalg.norm(pts - np.roll(pts, 1, axis=1), axis=2).max(axis=1)
    tri.set_mask(edges > 4.0 * np.median(edges))
    return tri


def joint_planes(out: Path):
    """Planes (centre, unit normal towards +x) of the contact joints, fitted
    to each joint's pairs (joint_pairs.csv; arch_dam cuts its joints along
    planes); none if there are no contact joints or a joint is not plane."""
    f = out / "joint_pairs.csv"
    if not f.exists():
        return []
    d = np.genfromtxt(f, delimiter=",", names=True, dtype=None,
                      encoding=None)
    pts = np.column_stack([d["x"], d["y"], d["z"]]).astype(float)
    planes = []
    for label in dict.fromkeys(np.atleast_1d(d["joint"])):
        p = pts[np.atleast_1d(d["joint"]) == label]
        c = p.mean(axis=0)
        _, sv, vt = np.linalg.svd(p - c)
        if len(p) < 3 or sv[2] > 1e-4 * sv[0]:  # the CSV's six digits
            return []
        n = vt[2] if vt[2][0] > 0 else -vt[2]
        planes.append((c, n))
    return planes


def face_blocks(d, planes):
    """The block (monolith) of each face point: the number of joint planes
    it lies beyond (towards +x); a point on a plane (the joint's edge on
    the face, where each side has its own point) belongs to the block of
    its side (column joint_side: 1 on side 2, the block beyond). The
    quadrature points of a nonlinear run (no joint_side) lie inside their
    cells, off the planes."""
    q = np.column_stack([d["x_m"], d["y_m"], d["z_m"]])
    block = np.zeros(len(q), dtype=int)
    if not planes:
        return block
    side = d["joint_side"] if "joint_side" in d else np.zeros(len(q))
    # The planes come from six-digit coordinates; the points off a plane
    # lie an element or so away from it.
    tol = 1e-4 * np.ptp(q, axis=0).max()
    for c, n in planes:
        s = (q - c) @ n
        on = np.abs(s) <= tol
        block += (s > tol) | (on & (side > 0))
    return block


def read_face(path: Path) -> dict:
    """A face CSV as a dict of columns. With a column `cell` (quadrature
    points of a nonlinear run: the points of a cell lie at several depths
    behind the face) each cell's points become one point, at their mean
    position with their mean values."""
    d = np.genfromtxt(path, delimiter=",", names=True)
    cols = {k: np.atleast_1d(d[k]) for k in d.dtype.names}
    if "cell" not in cols:
        return cols
    cells, inverse = np.unique(cols.pop("cell"), return_inverse=True)
    count = np.bincount(inverse, minlength=len(cells))
    return {k: np.bincount(inverse, weights=v, minlength=len(cells)) / count
            for k, v in cols.items()}


def face_x(d: dict, face: str):
    """x in the picture of a face seen by an observer in front of it: the
    downstream face is seen looking upstream, so the left bank (x < 0) is
    on the right."""
    return -d["x_m"] if face == "downstream" else d["x_m"]


def label_face_axes(ax, face: str) -> None:
    ax.set_aspect("equal")
    ax.set_xlabel("x along the dam axis [m]"
                  + (" (mirrored: seen from downstream)"
                     if face == "downstream" else ""))
    ax.set_ylabel("z [m]")


def plot_face_maps(out: Path, summary: dict, suffix: str, panels, title: str,
                   png: str) -> None:
    """Maps of face envelopes, a row per face (face_<face><suffix>.csv),
    a column per panel (CSV column, title, summary extreme of the face)."""
    fig, axes = plt.subplots(2, 2, figsize=(13, 8))
    r = summary.get("away_from_singular_points", {}).get("radius_m")
    planes = joint_planes(out)
    for row, face in enumerate(("upstream", "downstream")):
        d = read_face(out / f"face_{face}{suffix}.csv")
        x = face_x(d, face)
        # With contact joints each block is drawn apart: the contours break
        # across the joints (open or sliding, they carry no continuity).
        block = face_blocks(d, planes)
        tris = [(b, face_triangulation(x[b], d["z_m"][b]))
                for b in (block == k for k in np.unique(block))
                if b.sum() >= 3]
        for col, (key, what, extreme) in enumerate(panels):
            ax = axes[row, col]
            # Colour range without the points near the dam-rock contact
            # lines (singular: growing with refinement) and on the joints;
            # beyond it the colour saturates.
            v = d[key]
            lo, hi = v.min(), v.max()
            if r is not None and "distance_to_singular_m" in d:
                away = d["distance_to_singular_m"] >= r
                # Nor the joints' edges, where node-to-node impacts load
                # single points.
                if "joint_side" in d:
                    away &= d["joint_side"] == 0
                if away.any():
                    lo, hi = v[away].min(), v[away].max()
            extend = ("both" if v.min() < lo and v.max() > hi else
                      "min" if v.min() < lo else
                      "max" if v.max() > hi else "neither")
            levels = np.linspace(lo, hi, 21) if hi > lo else 20
            for b, tri in tris:
                cs = ax.tricontourf(tri, np.clip(v[b], lo, hi), levels=levels,
                                    cmap="RdYlBu_r", extend=extend)
            if len(tris) > 1 and "joint_side" in d:  # the joints' edges
                for k in range(1, block.max() + 1):
                    e = (block == k) & (d["joint_side"] > 0)
                    order = np.argsort(d["z_m"][e])
                    ax.plot(x[e][order], d["z_m"][e][order], "k-", lw=0.6)
            fig.colorbar(cs, ax=ax, shrink=0.85, label="MPa")
            e, note = extreme(summary["faces"][face])
            if e is not None:
                ex = -e["x"] if face == "downstream" else e["x"]
                ax.plot([ex], [e["z"]], "k*", ms=9)
                ax.set_title(f"{face} face: envelope of {what}\n"
                             f"extreme {e['value']:.2f} MPa at t = "
                             f"{e['t']:.2f} s{note}", fontsize=9)
            label_face_axes(ax, face)
    fig.suptitle(f"{title} ({summary.get('stress', 'total')} stress)")
    fig.tight_layout()
    fig.savefig(out / png, dpi=120)
    plt.close(fig)


def plot_faces(out: Path, summary: dict) -> None:
    r = summary.get("away_from_singular_points", {}).get("radius_m")

    def principal(kind):
        def extreme(f):
            away = f.get("away_from_singular_points", {}).get(kind)
            note = ("" if away is None else
                    f"; {away['value']:.2f} MPa farther than {r:.3g} m "
                    "from the rock")
            return f[kind], note
        return extreme

    plot_face_maps(out, summary, "", (
        ("max_principal_mpa", "max principal stress (tension +)",
         principal("max_principal_tension_mpa")),
        ("min_principal_mpa", "min principal stress (compression -)",
         principal("max_principal_compression_mpa"))),
        "Principal-stress envelopes", "face_envelopes.png")
    if not (out / "face_upstream_arch_cantilever.csv").exists():
        return

    def directional(kind):
        def extreme(f):
            e = f.get("arch_cantilever_away_from_singular_points", {}).get(kind)
            return e, ("" if r is None else
                       f", farther than {r:.3g} m from the rock")
        return extreme

    plot_face_maps(out, summary, "_arch_cantilever", (
        ("arch_max_mpa", "largest arch stress (horizontal in the face)",
         directional("arch_tension_mpa")),
        ("cantilever_max_mpa", "largest cantilever stress (across it)",
         directional("cantilever_tension_mpa"))),
        "Arch and cantilever stress envelopes (tension +)",
        "face_arch_cantilever.png")


def plot_concrete_faces(out: Path, summary: dict) -> None:
    """HTC concrete runs: maps of the envelope of the strain rate (log
    scale) and of the final kappa_t (cracking) on both faces
    (face_<face>_concrete.csv), as the paper's strain-rate maps."""
    if not (out / "face_upstream_concrete.csv").exists():
        return
    fig, axes = plt.subplots(2, 2, figsize=(13, 8))
    planes = joint_planes(out)
    for row, face in enumerate(("upstream", "downstream")):
        d = read_face(out / f"face_{face}_concrete.csv")
        x = face_x(d, face)
        # Contact joints: each block drawn apart (as in plot_face_maps).
        block = face_blocks(d, planes)
        tris = [(b, face_triangulation(x[b], d["z_m"][b]))
                for b in (block == k for k in np.unique(block))
                if b.sum() >= 3]
        rate = np.log10(np.maximum(d["max_strain_rate_per_s"], 1e-8))
        panels = ((rate, "log10 of the largest strain rate [1/s]",
                   f"max {d['max_strain_rate_per_s'].max():.3g} /s"),
                  (d["kappa_t"], "kappa_t at the end (tensile damage)",
                   f"max {d['kappa_t'].max():.3g}"))
        for col, (v, what, note) in enumerate(panels):
            ax = axes[row, col]
            hi = v.max()
            lo = min(v.min(), hi - 1e-12)
            for b, tri in tris:
                cs = ax.tricontourf(tri, v[b], levels=np.linspace(lo, hi, 21),
                                    cmap="viridis" if col == 0 else "magma_r")
            fig.colorbar(cs, ax=ax, shrink=0.85)
            ax.set_title(f"{face} face: {what}\n{note} (cell means)",
                         fontsize=9)
            label_face_axes(ax, face)
    rate = summary.get("max_strain_rate_per_s", {})
    fig.suptitle("HTC concrete: strain rate and cracking on the faces"
                 + (f" (largest strain rate in the dam {rate['value']:.3g} /s"
                    f" at t = {rate['t']:.2f} s)" if "value" in rate else ""))
    fig.tight_layout()
    fig.savefig(out / "face_strain_rate.png", dpi=120)
    plt.close(fig)


def main() -> None:
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = Path(sys.argv[1])
    summary = json.loads((out / "summary.json").read_text())
    plot_crest(out, summary)
    plot_faces(out, summary)
    plot_concrete_faces(out, summary)
    if (out / "joint_table.csv").exists():
        plot_joints(out)
        plot_joint_histories(out)


if __name__ == "__main__":
    main()

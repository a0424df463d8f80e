#!/usr/bin/python3
"""Pictures of a 3D arch-dam mesh written by damseis::geometry::write_model.

Reads the XDMF/HDF5 pair (mesh, "cell_tags", "facet_tags"; tag values of
cpp/damseis/geometry/tags.h) and draws

  <out>_model.png   the dam-foundation model in perspective (paper Figs. 10, 16)
  <out>_joints.png  the dam seen from downstream, its mesh and the contraction
                    joints labelled A, B, ... (paper Figs. 11, 17)

Usage: plot_arch_mesh.py MESH.xdmf [--out PREFIX] [--from-upstream]

The downstream view looks upstream (towards -y): the left bank (smallest x,
joint A) is on the right of the picture, as an observer downstream sees it.
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

UPSTREAM, DOWNSTREAM, CREST, INTERFACE = 1, 2, 3, 4
UPSTREAM_WETTED = 12  # wetted part of the upstream face (water-line meshes)
ROCK = (5, 6, 7, 8, 9, 10, 11)
JOINT_BASE = 100


def read(path):
    """Returns x (n,3), cells (m,4), cell tags, facets (k,3), facet tags."""
    h5 = os.path.splitext(path)[0] + ".h5"
    with h5py.File(h5, "r") as f:
        mesh = f["Mesh"]
        name = list(mesh.keys())[0]
        x = mesh[name]["geometry"][...]
        cells = mesh[name]["topology"][...]
        tags = f["MeshTags"]
        ct = tags["cell_tags"]
        ft = tags["facet_tags"]
        return (x, cells, ct["Values"][...].ravel(), ct["topology"][...],
                ft["topology"][...], ft["Values"][...].ravel())


def joint_label(tag):
    return chr(ord("A") + (tag - JOINT_BASE) // 2)


def plot_model(x, ncells, facets, ftags, out):
    fig = plt.figure(figsize=(10, 7))
    ax = fig.add_subplot(projection="3d")
    # Rock surface of the valley and the plateau (the far boundaries of the
    # block would hide the dam)
    rock = np.isin(ftags, (7, 8, 9))
    dam = np.isin(ftags, (UPSTREAM, UPSTREAM_WETTED, DOWNSTREAM, CREST))
    ax.add_collection3d(Poly3DCollection(
        x[facets[rock]], facecolor=(0.80, 0.72, 0.60, 0.35),
        edgecolor=(0.35, 0.30, 0.25, 0.35), linewidth=0.2))
    ax.add_collection3d(Poly3DCollection(
        x[facets[dam]], facecolor=(0.75, 0.78, 0.85, 1.0),
        edgecolor=(0.2, 0.2, 0.3, 0.8), linewidth=0.3))
    joints = (ftags >= JOINT_BASE) & ((ftags - JOINT_BASE) % 2 == 0)
    if joints.any():
        ax.add_collection3d(Poly3DCollection(
            x[facets[joints]], facecolor=(0.85, 0.15, 0.1, 0.9),
            edgecolor="none"))
    lo, hi = x.min(axis=0), x.max(axis=0)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(hi - lo)
    ax.view_init(elev=28, azim=-60 + 180)  # from downstream, above
    ax.set_xlabel("x (dam axis) [m]")
    ax.set_ylabel("y (downstream) [m]")
    ax.set_zlabel("z [m]")
    ax.set_title("Dam-foundation model: %d tetrahedra (rock: valley and "
                 "plateau surface shown)" % ncells)
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def plot_joints(x, facets, ftags, out, from_upstream):
    face = (UPSTREAM, UPSTREAM_WETTED) if from_upstream else (DOWNSTREAM,)
    fig, ax = plt.subplots(figsize=(12, 5.5))
    # Face mesh: the edges of its triangles projected on the x-z plane
    tri = facets[np.isin(ftags, face)]
    edges = np.sort(np.concatenate(
        [tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
    edges = np.unique(edges, axis=0)
    seg = x[edges][:, :, [0, 2]]
    from matplotlib.collections import LineCollection, PolyCollection
    ax.add_collection(LineCollection(seg, colors="0.55", linewidths=0.4))
    # Dam-foundation interface (outline of the canyon under the dam)
    itf = facets[ftags == INTERFACE]
    ax.add_collection(PolyCollection(x[itf][:, :, [0, 2]],
                                     facecolors=(0.8, 0.72, 0.6, 0.5),
                                     edgecolors="none"))
    # Joints: side-1 facets projected, labelled at the crest
    zmax = x[facets[ftags == CREST]][:, :, 2].max() if (
        ftags == CREST).any() else x[:, 2].max()
    for t in sorted(set(int(v) for v in ftags if v >= JOINT_BASE)):
        if (t - JOINT_BASE) % 2:
            continue
        jf = x[facets[ftags == t]]
        ax.add_collection(PolyCollection(jf[:, :, [0, 2]],
                                         facecolors=(0.85, 0.1, 0.1, 0.9),
                                         edgecolors=(0.85, 0.1, 0.1, 1.0),
                                         linewidths=0.6))
        top = jf.reshape(-1, 3)
        xt = top[np.argmax(top[:, 2]), 0]
        ax.annotate(joint_label(t), (xt, zmax), xytext=(0, 6),
                    textcoords="offset points", ha="center",
                    fontsize=11, fontweight="bold", color="darkred")
    pts = x[tri].reshape(-1, 3)
    ax.set_xlim(pts[:, 0].min() - 5, pts[:, 0].max() + 5)
    ax.set_ylim(min(pts[:, 2].min(), 0) - 5, zmax * 1.12)
    if not from_upstream:
        ax.invert_xaxis()  # seen from downstream: +x to the left
    ax.set_aspect("equal")
    ax.set_xlabel("x (dam axis) [m]" +
                  ("" if from_upstream else ", increasing to the left"))
    ax.set_ylabel("z [m]")
    nj = len([t for t in set(ftags.tolist()) if t >= JOINT_BASE]) // 2
    ax.set_title("Contraction joints (%d), %s view" %
                 (nj, "upstream" if from_upstream else "downstream"))
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    plt.close(fig)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("mesh", help="XDMF file written by write_model")
    p.add_argument("--out", help="output prefix (default: next to the mesh)")
    p.add_argument("--from-upstream", action="store_true",
                   help="view the joints from upstream instead")
    a = p.parse_args(argv)
    x, cells, ctags, _, facets, ftags = read(a.mesh)
    prefix = a.out or os.path.splitext(a.mesh)[0]
    plot_model(x, len(cells), facets, ftags, prefix + "_model.png")
    plot_joints(x, facets, ftags, prefix + "_joints.png", a.from_upstream)
    print("%s_model.png, %s_joints.png: %d nodes, %d cells" %
          (prefix, prefix, len(x), len(cells)))


if __name__ == "__main__":
    main(sys.argv[1:])

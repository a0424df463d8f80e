"""Checks the outputs of damseis runs.

    check_outputs.py DIR [DIR2 TOL]

DIR: every number in every HDF5 dataset, CSV file and summary.json under DIR
is finite (no NaN, no infinity, no null); every XDMF file is one grid
(envelopes, modes) or a temporal collection of grids, each carrying all its
fields on one mesh (results/xdmf_writer.h).
DIR2 TOL: DIR2 is the same run on other ranks: the envelope fields at the
same points (matched by coordinates, which the ranks number differently)
agree to TOL relative to their largest value.
"""
import json
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np


def finite_h5(path):
    bad = []

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
            if not np.all(np.isfinite(obj[()])):
                bad.append(name)

    with h5py.File(path, "r") as f:
        f.visititems(visit)
    return bad


def finite_json(value):
    if value is None:
        return False
    if isinstance(value, float):
        return np.isfinite(value)
    if isinstance(value, dict):
        return all(finite_json(v) for v in value.values())
    if isinstance(value, list):
        return all(finite_json(v) for v in value)
    return True


def check_xdmf(path):
    domain = ET.parse(path).getroot().find("Domain")
    grids = domain.findall("Grid")
    assert len(grids) == 1, f"{path}: {len(grids)} top-level grids"
    g = grids[0]
    steps = g.findall("Grid") if g.get("GridType") == "Collection" else [g]
    for s in steps:
        assert s.find("Topology") is not None and s.find("Geometry") is not None
        names = [a.get("Name") for a in s.findall("Attribute")]
        assert names, f"{path}: a grid without fields"
    return len(steps)


def envelope_by_point(d):
    """Vertex envelope fields sorted by point (and, at coincident points
    such as the two sides of a joint, by value), with the sorted points."""
    with h5py.File(d / "envelopes.h5", "r") as f:
        x = f["mesh/geometry"][:]
        values = {k: f["fields/" + k][:].ravel() for k in f["fields"]
                  if "vertex" in k}
    keys = list(np.round(x, 6).T[::-1])
    out = {}
    for k, v in values.items():
        out[k] = v[np.lexsort([v] + keys)]
    return x[np.lexsort(keys)], out


def main():
    d = Path(sys.argv[1])
    problems = []
    counted = 0
    for p in sorted(d.rglob("*.h5")):
        counted += 1
        problems += [f"{p}:{name} is not finite" for name in finite_h5(p)]
    for p in sorted(d.rglob("*.csv")):
        counted += 1
        a = np.genfromtxt(p, delimiter=",", skip_header=1)
        if a.size and not np.all(np.isfinite(a)):
            problems.append(f"{p} has a non-finite value")
    for p in sorted(d.rglob("summary.json")):
        counted += 1
        if not finite_json(json.load(open(p))):
            problems.append(f"{p} has a null or non-finite value")
    grids = {p.name: check_xdmf(p) for p in sorted(d.rglob("*.xdmf"))
             if p.name != "model.xdmf"}
    print(f"{d}: {counted} files checked, all finite" if not problems
          else "\n".join(problems))
    print(f"xdmf grids: {grids}")
    if len(sys.argv) > 3:
        tol = float(sys.argv[3])
        xa, va = envelope_by_point(d)
        xb, vb = envelope_by_point(Path(sys.argv[2]))
        assert xa.shape == xb.shape and np.abs(xa - xb).max() < 1e-9
        diff = max(np.abs(va[k] - vb[k]).max() / np.abs(va[k]).max()
                   for k in va)
        print(f"envelopes (vertex fields) other ranks vs these: {diff:.2e}")
        if diff > tol:
            problems.append(f"envelopes differ by {diff:.2e} > {tol}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

"""Read the results of a savageHutterFoam case for the tutorials' plots.

Fields are OpenFOAM files in ASCII or binary format (the case's
writeFormat), uncompressed.  The mesh is one structured block, cell k being
(i, j) = (k mod nx, k div nx); cell centres come from the C field that
`postProcess -func writeCellCentres -time 0` writes.
"""

import os
import re

import numpy as np


def _internal_field(data, n_comp):
    """(values, None) for a nonuniform field, (None, text) for a uniform
    one; data are the file's bytes, ASCII or binary format"""
    m = re.search(rb"internalField\s+uniform\s+([^;]+);", data)
    if m:
        return None, m.group(1).decode()
    m = re.search(rb"internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(", data)
    if not m:
        raise ValueError("no internalField found")
    n = int(m.group(1))
    if re.search(rb"format\s+binary\s*;", data[:2000]):
        values = np.frombuffer(data, dtype="<f8", count=n * n_comp, offset=m.end())
    else:
        body = data[m.end():]
        body = body[:body.index(b"\n)")].replace(b"(", b" ").replace(b")", b" ")
        values = np.array(body.split(), dtype=float)
    if values.size != n * n_comp:
        raise ValueError("expected %d values, found %d" % (n * n_comp, values.size))
    return values.reshape(n, n_comp) if n_comp > 1 else values, None


def read_field(case, time, name, n_cells=None):
    """The internal field `name` at time directory `time` as a numpy array
    (n,) for scalars or (n, 3) for vectors."""
    path = os.path.join(case, time, name)
    with open(path, "rb") as f:
        data = f.read()
    n_comp = 3 if b"volVectorField" in data[:2000] else 1
    values, uniform = _internal_field(data, n_comp)
    if values is not None:
        return values
    if n_cells is None:
        raise ValueError("%s is uniform; pass n_cells" % path)
    parts = uniform.replace("(", " ").replace(")", " ").split()
    v = np.array(parts, dtype=float)
    return np.tile(v, (n_cells, 1)) if n_comp > 1 else np.full(n_cells, v[0])


class Grid:
    """The structured grid of a case: nx, ny, cell centres x (nx), y (ny)."""

    def __init__(self, case):
        C = read_field(case, "0", "C")
        xs = C[:, 0]
        ys = C[:, 1]
        # cells run i fastest: the first row has the distinct x values
        self.nx = int(np.argmax(ys > ys[0] + 1e-12 * (1 + abs(ys[0])))) or len(xs)
        self.ny = len(xs) // self.nx
        self.x = xs[: self.nx]
        self.y = ys[:: self.nx]
        self.n = len(xs)

    def as2d(self, values):
        """(ny, nx) view of a cell field"""
        return np.asarray(values).reshape(self.ny, self.nx)


def times(case):
    """Time directories of a case, sorted, as strings"""
    out = []
    for d in os.listdir(case):
        try:
            t = float(d)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(case, d, "h")):
            out.append((t, d))
    return [d for _, d in sorted(out)]


def closest_time(case, t):
    """The time directory closest to t"""
    return min(times(case), key=lambda d: abs(float(d) - t))

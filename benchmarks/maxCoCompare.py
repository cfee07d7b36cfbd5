#!/usr/bin/python3
"""The spatial error a time step is judged against (issue 27 item 3).

    maxCoCompare.py COARSE FINE [RUN ...]

COARSE and FINE: the same tutorial on a mesh and on the mesh refined twice
in each direction (the same block); FINE's fields are averaged over 2x2
blocks onto COARSE's cells.  Prints, at each case's last time, the
relative L1 differences sum |a - b| / sum b of the deposit h and of the
peak map hMax, and the differences of hazardMaps' runoutX and
comTravelAngle (postProcessing/hazardMaps/<t>/report.dat), for COARSE
against FINE: the mesh's (spatial) difference; and for each RUN (a mesh
at another maxCo) against FINE or COARSE, whichever has its mesh: the
time step's difference.
"""
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "SAVAGEHUTTER_DIR",
    os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")),
    "tutorials", "tools"))
import foamCase  # noqa: E402


def nxny(case):
    txt = open(os.path.join(case, "system", "blockMeshDict")).read()
    nx = int(re.search(r"^\s*nx\s+(\d+)\s*;", txt, re.M).group(1))
    ny = int(re.search(r"^\s*ny\s+(\d+)\s*;", txt, re.M).group(1))
    return nx, ny


def fields(case):
    t = foamCase.times(case)[-1]
    nx, ny = nxny(case)
    h = foamCase.read_field(case, t, "h", nx * ny).reshape(ny, nx)
    hm = foamCase.read_field(case, t, "hMax", nx * ny).reshape(ny, nx)
    rep = {}
    for f in glob.glob(os.path.join(case, "postProcessing", "hazardMaps", "*", "report.dat")):
        for line in open(f):
            p = line.split()
            if len(p) == 2 and not line.startswith("#"):
                rep[p[0]] = float(p[1])
    return h, hm, rep


def coarsen(a, shape):
    ny, nx = shape
    if a.shape == shape:
        return a
    assert a.shape == (2 * ny, 2 * nx), (a.shape, shape)
    return 0.25 * (a[0::2, 0::2] + a[1::2, 0::2] + a[0::2, 1::2] + a[1::2, 1::2])


def compare(label, a, b):
    ha, hma, ra = a
    hb, hmb, rb = b
    hb, hmb = coarsen(hb, ha.shape), coarsen(hmb, ha.shape)
    d = lambda x, y: np.abs(x - y).sum() / y.sum()
    dr = lambda k: ("%9.3g" % abs(ra[k] - rb[k])) if k in ra and k in rb else "%9s" % "-"
    print("%-34s %9.3e %9.3e %s %s" % (label, d(ha, hb), d(hma, hmb),
                                       dr("runoutX"), dr("comTravelAngle")))


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 1
    coarse, fine = sys.argv[1], sys.argv[2]
    c, f = fields(coarse), fields(fine)
    print("%-34s %9s %9s %9s %9s" % ("", "dh", "dhMax", "d runout", "d comTA"))
    compare("mesh: %s vs %s" % (os.path.basename(coarse), os.path.basename(fine)), c, f)
    for run in sys.argv[3:]:
        r = fields(run)
        ref, name = (f, fine) if r[0].shape == f[0].shape else (c, coarse)
        compare("step: %s vs %s" % (os.path.basename(run), os.path.basename(name)), r, ref)
    return 0


if __name__ == "__main__":
    sys.exit(main())

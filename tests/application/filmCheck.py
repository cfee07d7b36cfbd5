#!/usr/bin/python3
"""No runaway films at the end of a run: every savageHutterFoam case under a
directory, at its last time.

Usage: filmCheck.py <directory>

A case is a directory whose time directories hold h and hU (an ensemble
member too); its g is that of the nearest constant/transportProperties.

A thin layer is fed by the flow around it; it can be no faster than that
flow allows.  The fastest a front fed by a layer of speed |u| and thickness
h can move is the Riemann invariant |u| + 2 sqrt(g h) (Ritter's front of a
dam break, eq. 28's front speed), so with the flow's body the cells whose h
is at least 5 % of the largest:
  1. the last time: every cell with h > 1e-4 m no faster than 1.05 times
     the largest |u| + 2 sqrt(g h) of the body;
  2. the peak maps at the last time (hMax, UMax; pMax = rho |u|^2): UMax of
     every cell that was wet (hMax > 1e-4 m) at most 1.05 times the largest
     UMax + 2 sqrt(g hMax) of the body (hMax at least 5 % of its peak), and
     pMax at most rho (the case's, transportProperties) times that
     speed squared.
g is the case's (constant/transportProperties), an upper bound of the
normal gravity g cos(zeta).  Prints one line per case and check; exit
status 1 when a check fails or no case was found.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tutorials", "tools"))
import foamCase  # noqa: E402

import numpy as np  # noqa: E402

THIN = 1e-4
BODY = 0.05
MARGIN = 1.05


def results(case):
    """The time directories of a directory that hold h and hU, sorted"""
    return [t for t in foamCase.times(case)
            if os.path.isfile(os.path.join(case, t, "hU"))]


def cases(top):
    """Directories under top whose time directories hold h and hU (cases,
    ensemble members), processor directories left out"""
    out = []
    for root, dirs, _ in os.walk(top):
        dirs[:] = sorted(d for d in dirs if not d.startswith("processor"))
        if results(root):
            out.append(root)
    return out


def transport(case, top):
    """The text of the case's constant/transportProperties: the directory's
    own or the nearest one above it (an ensemble member's case)"""
    d = os.path.abspath(case)
    top = os.path.abspath(top)
    while True:
        path = os.path.join(d, "constant", "transportProperties")
        if os.path.isfile(path):
            return path, open(path).read()
        if d == top or d == os.path.dirname(d):
            raise ValueError("%s: no constant/transportProperties" % case)
        d = os.path.dirname(d)


def density(case, top):
    """rho of transportProperties (the density of pMax), None without"""
    _, text = transport(case, top)
    m = re.search(r"^\s*rho\s+([0-9.eE+-]+)\s*;", text, re.M)
    return float(m.group(1)) if m else None


def gravity(case, top):
    """g of the case's transportProperties"""
    path, text = transport(case, top)
    m = re.search(r"^\s*g\s+([0-9.eE+-]+)\s*;", text, re.M)
    if not m:
        raise ValueError("%s: no keyword g" % path)
    return float(m.group(1))


def check(case, g, top):
    """Lines to print and the number of failed checks"""
    t = results(case)[-1]
    h = foamCase.read_field(case, t, "h")
    n = h.size
    hU = foamCase.read_field(case, t, "hU", n)
    speed = np.where(h > THIN, np.hypot(hU[:, 0], hU[:, 1]) / np.maximum(h, THIN), 0)
    lines, failed = [], 0
    if h.max() > THIN:
        body = h >= BODY * h.max()
        bound = np.max(speed[body] + 2 * np.sqrt(g * h[body]))
        worst = speed.max()
        ok = worst <= MARGIN * bound
        failed += not ok
        lines.append("%s  %s t = %s: largest speed where h > 1e-4 m %.4g m/s, "
                     "bound %.4g m/s (1.05 x max |u| + 2 sqrt(g h) of the body)"
                     % ("PASS" if ok else "FAIL", case, t, worst, MARGIN * bound))
    names = os.listdir(os.path.join(case, t))
    if "hMax" in names and "UMax" in names:
        hMax = foamCase.read_field(case, t, "hMax", n)
        UMax = foamCase.read_field(case, t, "UMax", n)
        wet = hMax > THIN
        if wet.any():
            body = hMax >= BODY * hMax.max()
            bound = MARGIN * np.max(UMax[body] + 2 * np.sqrt(g * hMax[body]))
            worst = UMax[wet].max()
            ok = worst <= bound
            failed += not ok
            lines.append("%s  %s t = %s: UMax where hMax > 1e-4 m %.4g m/s, bound %.4g m/s"
                         % ("PASS" if ok else "FAIL", case, t, worst, bound))
            rho = density(case, top)
            if "pMax" in names and rho is not None:
                pMax = foamCase.read_field(case, t, "pMax", n)
                worst = pMax[wet].max()
                ok = worst <= rho * bound ** 2
                failed += not ok
                lines.append("%s  %s t = %s: pMax where hMax > 1e-4 m %.4g Pa, "
                             "bound rho (bound)^2 = %.4g Pa"
                             % ("PASS" if ok else "FAIL", case, t, worst,
                                rho * bound ** 2))
    return lines, failed


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    found = cases(sys.argv[1])
    if not found:
        print("FAIL  no savageHutterFoam case with results under %s" % sys.argv[1])
        return 1
    failed = 0
    for case in found:
        lines, f = check(case, gravity(case, sys.argv[1]), sys.argv[1])
        failed += f
        for line in lines:
            print(line)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

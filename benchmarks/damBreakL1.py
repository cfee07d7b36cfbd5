#!/usr/bin/env python3
"""
savageHutterFoam: the L1 error of h of the peers' dam break (docs/design.md
section 4) against its exact solution (Stoker's: a rarefaction into the
deep side, a bore into the shallow one; flat frictionless bed, shallow
water as the Savage-Hutter equations give it with eps = 1, K = 1).

Usage: damBreakL1.py <time dir>/h nx ny x0 hLeft hRight t [g]
Reads the OpenFOAM field h (ascii or binary, uniform or nonuniform) of a
nx x ny mesh of 1 m cells (cell index i + nx j, as blockMesh numbers a
single block), x0 the dam's position.  Prints:
  L1 = sum |h - h_exact| dx dy / Ly   [m^2], the error over a line
       along the flow (the norm maxCoStudy's dam breaks use), and
  mean |h - h_exact| over the cells [m],
against the exact cell averages (16-point midpoint rule per cell).
Pure Python: no numpy needed on the GPU machine.
"""
import math
import re
import struct
import sys


def read_field(path, n):
    data = open(path, 'rb').read()
    m = re.search(rb'internalField\s+(uniform|nonuniform)', data)
    if not m:
        sys.exit(f'damBreakL1: no internalField in {path}')
    if m.group(1) == b'uniform':
        v = float(re.match(rb'\s*([-+0-9.eE]+)', data[m.end():]).group(1))
        return [v]*n
    m2 = re.compile(rb'\s*List<scalar>\s*(\d+)\s*\(').match(data, m.end())
    if not m2:
        sys.exit(f'damBreakL1: cannot parse the list in {path}')
    count = int(m2.group(1))
    if count != n:
        sys.exit(f'damBreakL1: {path} holds {count} values, the mesh {n}')
    start = m2.end()
    binary = re.search(rb'format\s+binary', data[:m.start()]) is not None
    if binary:
        size = 8
        arch = re.search(rb'scalar\s*=\s*(\d+)', data[:m.start()])
        if arch:
            size = int(arch.group(1))//8
        fmt = '<%d%s' % (n, 'd' if size == 8 else 'f')
        return list(struct.unpack_from(fmt, data, start))
    end = data.index(b')', start)
    return [float(x) for x in data[start:end].split()]


def stoker(hl, hr, g):
    """The middle state (h_m, u_m) and the bore's speed"""
    cl = math.sqrt(g*hl)

    def f(hm):
        um_raref = 2*(cl - math.sqrt(g*hm))
        um_bore = (hm - hr)*math.sqrt(g*(hm + hr)/(2*hm*hr))
        return um_raref - um_bore
    lo, hi = hr, hl
    for _ in range(200):
        mid = 0.5*(lo + hi)
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    hm = 0.5*(lo + hi)
    um = 2*(cl - math.sqrt(g*hm))
    return hm, um, hm*um/(hm - hr)


def exact_h(x, x0, hl, hr, t, g, hm, um, s):
    cl = math.sqrt(g*hl)
    cm = math.sqrt(g*hm)
    xi = (x - x0)/t
    if xi <= -cl:
        return hl
    if xi <= um - cm:
        return (2*cl - xi)**2/(9*g)
    if xi <= s:
        return hm
    return hr


def main():
    if len(sys.argv) < 8:
        sys.exit(__doc__)
    path = sys.argv[1]
    nx, ny = int(sys.argv[2]), int(sys.argv[3])
    x0, hl, hr, t = map(float, sys.argv[4:8])
    g = float(sys.argv[8]) if len(sys.argv) > 8 else 9.81
    h = read_field(path, nx*ny)
    hm, um, s = stoker(hl, hr, g)
    sub = 16
    exact = []
    for i in range(nx):
        exact.append(sum(exact_h(i + (k + 0.5)/sub, x0, hl, hr, t, g, hm, um, s)
                         for k in range(sub))/sub)
    total = 0.0
    for j in range(ny):
        row = h[j*nx:(j + 1)*nx]
        total += sum(abs(a - b) for a, b in zip(row, exact))
    l1 = total/ny            # dx = dy = 1 m: sum |e| dx dy / Ly
    mean = total/(nx*ny)
    print(f'L1 {l1:.6g} m2 (sum |h - h_exact| dx dy / Ly), mean |e| {mean:.4g} m,'
          f' h_m {hm:.6f}, bore at x = {x0 + s*t:.3f}')


main()

#!/usr/bin/env python3
"""Compare a decomposed run with the serial run of the same case, bit for bit.

Usage: compareDecomposed.py <what> <serial case> <decomposed case> <times> <fields>
(times and fields: space-separated lists)

Fields are written with 17 significant digits, so two doubles print alike
only when they are the same double (signs of zero included).  Checks, each a
PASS or FAIL line:
  - every processor's internalField of every field and time against the
    serial run's cells (constant/polyMesh/cellProcAddressing): identical;
  - the fields reconstructPar wrote against the serial run's: identical but
    for the sign of zero, which reconstructPar does not keep (a serial -0 is
    its 0; counted and printed).
"""
import glob
import os
import re
import sys


def internal(path):
    """The internalField of a field file as a list of value strings"""
    with open(path) as f:
        text = f.read()
    m = re.search(r'internalField\s+nonuniform\s+List<\w+>\s*(\d+)\s*\(', text)
    if m:
        n = int(m.group(1))
        body = text[m.end():]
        values = re.findall(r'\([^()]*\)|[^\s()]+', body)
        return values[:n]
    m = re.search(r'internalField\s+uniform\s+(\([^()]*\)|[^\s;]+)\s*;', text)
    if m:
        return ('uniform', m.group(1))
    raise ValueError('no internalField in ' + path)


def expand(values, n):
    if isinstance(values, tuple):
        return [values[1]]*n
    return values


def addressing(proc):
    path = os.path.join(proc, 'constant', 'polyMesh', 'cellProcAddressing')
    with open(path) as f:
        text = f.read()
    m = re.search(r'\n(\d+)\s*\(', text)
    n = int(m.group(1))
    return [int(x) for x in text[m.end():].split(')')[0].split()][:n]


def zeroless(v):
    return re.sub(r'(?<![\d.eE+-])-0(?![\d.eE])', '0', v)


def main():
    what, serial, case, times, fields = sys.argv[1:6]
    times = times.split()
    fields = fields.split()
    procs = sorted(glob.glob(os.path.join(case, 'processor*')),
                   key=lambda p: int(p.rsplit('processor', 1)[1]))
    if not procs:
        print('FAIL  %s: no processor directories in %s' % (what, case))
        return 1
    maps = [addressing(p) for p in procs]
    differ, recDiffer, zeros, compared = [], [], 0, 0
    for t in times:
        for name in fields:
            ser = internal(os.path.join(serial, t, name))
            nCells = sum(len(a) for a in maps)
            ser = expand(ser, nCells)
            for p, a in zip(procs, maps):
                vals = expand(internal(os.path.join(p, t, name)), len(a))
                compared += len(a)
                bad = [k for k, c in enumerate(a) if vals[k] != ser[c]]
                if bad:
                    k = bad[0]
                    differ.append('%s/%s/%s (%d cells, e.g. cell %d: %s, serial %s)'
                                  % (os.path.basename(p), t, name, len(bad),
                                     a[k], vals[k], ser[a[k]]))
            rec = expand(internal(os.path.join(case, t, name)), nCells)
            for c in range(nCells):
                if rec[c] != ser[c]:
                    if zeroless(rec[c]) == zeroless(ser[c]):
                        zeros += 1
                    else:
                        recDiffer.append('%s/%s cell %d: %s, serial %s'
                                         % (t, name, c, rec[c], ser[c]))
    if differ:
        print('FAIL  %s: the processors\' fields differ from the serial run\'s: %s'
              % (what, '; '.join(differ[:4])))
    else:
        print('PASS  %s: %d processors x %d fields x %d times, %d cell values'
              ' identical to the serial run\'s' % (what, len(procs), len(fields),
                                                   len(times), compared))
    if recDiffer:
        print('FAIL  %s: reconstructPar\'s fields differ: %s'
              % (what, '; '.join(recDiffer[:4])))
    else:
        print('PASS  %s: reconstructPar\'s fields the serial run\'s (%d signs'
              ' of zero it does not keep)' % (what, zeros))
    return 1 if differ or recDiffer else 0


if __name__ == '__main__':
    sys.exit(main())

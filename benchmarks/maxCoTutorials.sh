#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The largest stable time step, the tutorials' half (issue 27 item 3;
#     the verification cases with exact solutions: benchmarks/maxCoStudy.C).
#     Runs every tutorial shortened (SH_SHORT=1, as ./Alltest runs them) at
#     each Courant number maxCo of system/controlDict, in copies under the
#     work directory, and prints per tutorial and maxCo:
#       ok        Allrun passed, every savageHutterFoam log ends in "End",
#                 no FOAM FATAL, no NaN in a log
#       check     the tutorial's own ./plot --check (its paper table or its
#                 volume/rest checks), and tests/application/filmCheck.py
#       steps     time steps of all its solver runs together
#       clips     thin cells whose speed was bounded (speedBounds), summed
#       min h     the smallest h at the last time of every run
#       dV        the volume at the last time against the maxCo 0.4 run's
#                 (relative: tutorials with inflow or outflow do not keep
#                 their initial volume, so the reference is the 0.4 run)
#       dh        sum |h - h_0.4| / sum h_0.4 at the last time (deposit),
#       dhMax     the same of the peak map hMax, over all runs of the case
#       runout    hazardMaps' runout (terrain tutorials) or the largest x
#                 reached by hMax > 1e-3 of max hMax, against 0.4's
#     then the tutorial's own accuracy line (log.plot) for the cases that
#     print an error against the paper.
#
# Usage
#     benchmarks/maxCoTutorials.sh [-work DIR] [-co "0.4 0.5 ..."] [-full] [tutorial ...]
#     (-full: the tutorials' own meshes and times, not SH_SHORT=1)
#     (default: every tutorial, maxCo 0.4 0.5 0.6 0.7 0.8 0.9 1.0,
#     work directory /tmp/maxCoTutorials; CPU backend: SH_FOAM_ARGS)
#------------------------------------------------------------------------------
set -u
project="$(cd "$(dirname "$0")/.." && pwd)"
work=/tmp/maxCoTutorials
cos="0.4 0.5 0.6 0.7 0.8 0.9 1.0"
short=1
while [ $# -gt 0 ]
do
    case "$1" in
        -work) work="$2"; shift 2 ;;
        -co) cos="$2"; shift 2 ;;
        -full) short=0; shift ;;
        *) break ;;
    esac
done
. "$project/etc/bashrc"
export SH_FOAM_ARGS="${SH_FOAM_ARGS:--backend cpu}"

tutorials=("$@")
if [ ${#tutorials[@]} -eq 0 ]
then
    for d in "$project"/tutorials/*/Allrun
    do
        tutorials+=("$(basename "$(dirname "$d")")")
    done
fi
mkdir -p "$work"

#- The fields of one run tree: per case directory (one with a log of the
#  solver or an ensemble member), at its last time: min h, volume, and the
#  fields for the comparison with the reference tree
summary()
{
    /usr/bin/python3 - "$1" "${2:-}" <<'EOF'
import os, re, sys
sys.path.insert(0, os.path.join(os.environ["SAVAGEHUTTER_DIR"], "tutorials", "tools"))
import numpy as np
import foamCase

run, ref = sys.argv[1], sys.argv[2]

def cases(root):
    out = []
    for d, subdirs, files in os.walk(root):
        if "processor" in d:
            continue
        ts = [t for t in foamCase.times(d) if float(t) > 0] if os.path.isdir(d) else []
        if ts and os.path.isfile(os.path.join(d, ts[-1], "h")):
            out.append(os.path.relpath(d, root))
    return sorted(out)

def fields(root, c):
    d = os.path.join(root, c)
    t = foamCase.times(d)[-1]
    h = foamCase.read_field(d, t, "h")
    hm = None
    if os.path.isfile(os.path.join(d, t, "hMax")):
        hm = foamCase.read_field(d, t, "hMax", len(h))
    x = None
    for t0 in ("0", foamCase.times(d)[0]):
        if os.path.isfile(os.path.join(d, t0, "C")):
            x = foamCase.read_field(d, t0, "C")[:, 0]
            break
    return t, h, hm, x

def runout(root):
    # hazardMaps' report (terrain tutorials), else the peak map's reach
    for dp, _, files in os.walk(root):
        if "report.dat" in files and "hazardMaps" in dp:
            for line in open(os.path.join(dp, "report.dat")):
                m = re.match(r"\s*runout\w*\s+([-0-9.eE+]+)", line)
                if m:
                    return float(m.group(1))
    return None

mins, dv, dh, dhm, ro = [], [], [], [], []
for c in cases(run):
    t, h, hm, x = fields(run, c)
    mins.append(h.min())
    if not ref or not os.path.isdir(os.path.join(ref, c)):
        continue
    try:
        t0, h0, hm0, x0 = fields(ref, c)
    except Exception:
        continue
    if h0.shape != h.shape:
        continue
    dv.append(abs(h.sum() - h0.sum())/max(h0.sum(), 1e-300))
    dh.append(np.abs(h - h0).sum()/max(h0.sum(), 1e-300))
    if hm is not None and hm0 is not None:
        dhm.append(np.abs(hm - hm0).sum()/max(hm0.sum(), 1e-300))
        if x is not None:
            reach = lambda m: x[m > 1e-3*m.max()].max()
            ro.append(abs(reach(hm) - reach(hm0)))
r, r0 = runout(run), (runout(ref) if ref else None)
if r is not None and r0 is not None:
    ro = [abs(r - r0)]
fmt = lambda v: ("%.2e" % max(v)) if v else "-"
print("%d %.3e %s %s %s %s" % (len(mins), min(mins) if mins else float("nan"),
      fmt(dv), fmt(dh), fmt(dhm), ("%.3g" % max(ro)) if ro else "-"))
EOF
}

printf "%-14s %5s %4s %6s %7s %6s %10s %9s %9s %9s %8s\n" \
    tutorial maxCo ok check steps clips "min h" dV dh dhMax "d runout"
for t in "${tutorials[@]}"
do
    for co in $cos
    do
        dir="$work/$t-$co"
        rm -rf "$dir"
        cp -r "$project/tutorials/$t" "$dir"
        (cd "$dir" && ./Allclean > /dev/null 2>&1)
        sed -i "s/^maxCo .*/maxCo           $co;/" "$dir/system/controlDict"
        ok=yes
        (cd "$dir" && SH_SHORT=$short ./Allrun > "$dir.Allrun.log" 2>&1) || ok=no
        grep -rlq "FOAM FATAL" --include='log.*' "$dir" && ok=no
        grep -rliqw "nan" --include='log.savageHutterFoam*' "$dir" && ok=no
        steps=0
        clips=0
        while IFS= read -r log
        do
            grep -q "^End" "$log" || ok=no
            s="$(grep -o "steps = [0-9]*" "$log" | tail -n1 | grep -o "[0-9]*$")"
            # an ensemble: the steps of all its members together
            [ -n "$s" ] || s="$(sed -n 's/^Ensemble: .*, \([0-9]*\) member steps.*/\1/p' "$log" | tail -n1)"
            c="$(sed -n 's/^Thin cells whose speed was bounded.*: \([0-9]*\)$/\1/p' "$log" | tail -n1)"
            steps=$((steps + ${s:-0}))
            clips=$((clips + ${c:-0}))
        done < <(find "$dir" -name 'log.savageHutterFoam*')
        check=pass
        (cd "$dir" && ./plot --check > "$dir.check.log" 2>&1) || check=FAIL
        "$project/tests/application/filmCheck.py" "$dir" > "$dir.films.log" 2>&1 \
            || check="${check}/film"
        ref=""
        [ "$co" != 0.4 ] && ref="$work/$t-0.4"
        read -r n minh dv dh dhm ro < <(summary "$dir" "$ref" 2> "$dir.summary.log" \
            || echo "0 nan - - - -")
        printf "%-14s %5s %4s %6s %7s %6s %10s %9s %9s %9s %8s\n" \
            "$t" "$co" "$ok" "$check" "$steps" "$clips" "$minh" "$dv" "$dh" "$dhm" "$ro"
        # The tutorial's own error against the paper, where it prints one
        case "$t" in
            damBreak) grep -E "^[0-9]+x[0-9]+ " "$dir/log.plot" | sed 's/^/    Table II: /' ;;
            staticPile) grep -A1 "^ *L2 " "$dir/log.plot" | tail -n1 | sed 's/^/    Table III (L2 Linf max|hU|): /' ;;
            granularJet) grep "max relative difference" "$dir/log.plot" | sed 's/^ */    /' ;;
        esac
    done
done

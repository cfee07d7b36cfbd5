#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Soak test of the application: the damBreak tutorial on 64 x 8 cells in
#     a closed box (walls on all four sides), fixed deltaT, run for STEPS
#     time steps on one CPU core, writing a time directory every STEPS/200
#     steps.
#       - mass: the volume sum(h) dx dy of the last written h equals that of
#         the initial h to 1e-12 relative (fields are written with 17
#         digits; the scheme conserves mass exactly in a closed box);
#       - memory: the resident set size (VmRSS, sampled from /proc every
#         0.2 s) after the first write and at the end of the run differ by
#         less than 256 kB, while 200 writes would leak 800 kB if each kept
#         one field.  "The end" is the last sample before the log's final
#         "End" (every write done, the writer thread joined): after it the
#         process exits, and a sample landing in its exit path read
#         0.3-1.8 MB more in 3 of 46 runs (2026-12-04; what the exit
#         touches, static destructors or code pages run for the first
#         time, was not pinned down): no leak of the writes.
#     Prints the figures and "N passed, M failed, K skipped".
#
# Usage
#     soakTest.sh <project dir> <work dir> [STEPS]
#     STEPS: default $SH_SOAK_STEPS, else 20000 (what ./Alltest runs);
#            the full soak: SH_SOAK_STEPS=100000 ./Alltest, or
#            tests/application/soakTest.sh . /tmp/soak 100000
#------------------------------------------------------------------------------
project="$1"
work="$2"
steps="${3:-${SH_SOAK_STEPS:-20000}}"
. "$project/tests/application/testFunctions.sh"

d="$work/closedBox"
mkdir "$d"
cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$d"/
every=$((steps / 200))
[ "$every" -ge 1 ] || every=1
(
    cd "$d" || exit 1
    setBlockCells 64 8
    # deltaT 0.01 keeps the Courant number below 1 here (the solver would
    # shorten a step that does not): steps = endTime/deltaT
    setEntry system/controlDict adjustTimeStep no
    setEntry system/controlDict deltaT 0.01
    setEntry system/controlDict endTime "$(python3 -c "print($steps*0.01)")"
    setEntry system/controlDict writeControl runTime
    setEntry system/controlDict writeInterval "$(python3 -c "print($every*0.01)")"
    runApplication blockMesh
    restore0Dir
    runApplication setAvalancheFields
    closeSlope
) > "$work/setup.log" 2>&1 || { cat "$work/setup.log"; fail "setting up the case (its log above)"; finish; exit 1; }

log="$d/log.savageHutterFoam"
# One thread: OpenMP on 512 cells costs more than it gains, the more so
# on a shared machine
(cd "$d" && OMP_NUM_THREADS=1 exec savageHutterFoam -backend cpu -logInterval 30 \
    > log.savageHutterFoam 2>&1) &
pid=$!
rssFirst=""
rssLast=""
rssMax=0
while kill -0 "$pid" 2>/dev/null
do
    rss=$(sed -n 's/^VmRSS:[ \t]*\([0-9]*\) kB/\1/p' "/proc/$pid/status" 2>/dev/null)
    if [ -n "$rss" ]
    then
        # From the first write on: set-up and the first write allocate
        if [ -z "$rssFirst" ] \
        && [ -n "$(cd "$d" && ls -d [0-9]* | grep -v '^0$' | grep -v orig)" ]
        then
            rssFirst=$rss
        fi
        # Up to the log's final "End": the exit path is not the writes'
        grep -qx End "$log" 2>/dev/null && break
        [ -n "$rssFirst" ] && rssLast=$rss && [ "$rss" -gt "$rssMax" ] && rssMax=$rss
    fi
    sleep 0.2
done
wait "$pid"
rc=$?

ran=$(sed -n 's/^Time loop: \([0-9]*\) steps.*/\1/p' "$log")
if [ $rc -eq 0 ] && [ "${ran:-0}" -ge "$steps" ]
then
    pass "closed box: $ran time steps ($(sed -n 's/^Time loop: .* in \([^ ]*\) s wall.*/\1/p' "$log") s), exit 0"
else
    fail "closed box: rc $rc, ${ran:-no} steps of $steps (see $log)"
fi

last=$(cd "$d" && ls -d [0-9]* | grep -v '^0$' | sort -g | tail -n1)
if python3 - "$d" "$last" <<'PY'
import re, sys
case, last = sys.argv[1], sys.argv[2]
def volume(t):
    s = open("%s/%s/h" % (case, t)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", s)
    h = [float(x) for x in m.group(2).split()]
    return sum(h) * 0.4 * 0.4, len(h)
v0, n = volume("0")
v1, _ = volume(last)
rel = abs(v1 - v0) / v0
print("      volume at t = 0: %.17g, at t = %s: %.17g (%d cells), relative change %.3g" % (v0, last, v1, n, rel))
sys.exit(0 if rel <= 1e-12 else 1)
PY
then
    pass "closed box: volume at t = $last within 1e-12 of the initial volume"
else
    fail "closed box: volume not conserved to 1e-12 (see $d)"
fi

if [ -n "$rssFirst" ] && [ -n "$rssLast" ] && [ $((rssLast - rssFirst)) -lt 256 ]
then
    pass "memory flat: VmRSS $rssFirst kB after the first write, $rssLast kB at the end (max $rssMax kB) over $(ls -d "$d"/[0-9]* | wc -l) writes"
else
    fail "memory: VmRSS ${rssFirst:-?} kB after the first write, ${rssLast:-?} kB at the end (max $rssMax kB)"
fi

finish

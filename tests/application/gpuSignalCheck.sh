#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Signals on the GPU backend (called by tests/gpuCheck with the bundle
#     of bin/bundleOpenFOAM, like gpuAppCheck.sh): a dam break on
#     4096 x 512 cells runs with -backend cuda towards an end time it would
#     take minutes to reach; SIGUSR1 must write the current state and let
#     the run go on, SIGTERM must write it and end the run cleanly (exit 0,
#     "End") within 5 s, although the backend advances in CUDA graphs of
#     many steps; a restart from the directory SIGTERM wrote must run;
#     SIGINT must write the state of the stop time with its peak maps and
#     end the |dh/dt| report (postProcessing/steadyState) at it, exit 0,
#     within 5 s.  The restart after SIGTERM runs to 0.05 s past the stop,
#     as does a run from 0 without a stop, and the fields there (h, U, hU,
#     regime, hMax, UMax) must be the same byte for byte (as
#     tests/application/caseTests.sh checks on the CPU: no write time
#     before the end in either run, so that both take the same steps).
#     A SIGTERM 3 s after the start (the mesh being read) and a SIGINT as
#     the GPU is set up end the run before its first step with a message,
#     exit 0, writing nothing.
#     Prints how long each signal took to be acted on, and the comparison.
#
# Usage
#     gpuSignalCheck.sh <project dir> <work dir>
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
. "$project/tests/application/bundleEnv.sh" || exit 1
status=0
pass() { echo "PASS  $*"; }
fail() { echo "FAIL  $*"; status=1; }

d="$work/signals"
mkdir -p "$d"
cp -r "$project/tutorials/damBreak"/{0.orig,constant,system} "$d"/
cd "$d" || exit 1
rm -rf constant/polyMesh
setBlockCells 4096 512
setEntry system/controlDict endTime 1000
setEntry system/controlDict writeInterval 1000
setEntry system/controlDict writeFormat binary
setEntry constant/transportProperties rho 1500   # pMax written and restarted
runApplication blockMesh
restore0Dir
[ -f system/setAvalancheFieldsDict ] && runApplication setAvalancheFields

timeDirs() { ls -d [0-9]* 2>/dev/null | grep -E '^[0-9.e+-]+$' | grep -v '^0$' | sort -g; }
now() { date +%s.%N; }
#- startRun: savageHutterFoam -backend cuda in the background (pid in $pid),
#  3 s into its time loop
startRun()
{
    savageHutterFoam -backend cuda > log.savageHutterFoam 2>&1 &
    pid=$!
    for _ in $(seq 1 600); do
        grep -q "Starting time loop" log.savageHutterFoam 2>/dev/null && break
        sleep 0.1
    done
    sleep 3
}

startRun

# SIGUSR1: write and go on
kill -USR1 "$pid"
t0=$(now)
for _ in $(seq 1 100); do
    [ -n "$(timeDirs)" ] && break
    sleep 0.1
done
t1=$(now)
first="$(timeDirs | tail -n1)"
if [ -n "$first" ] && [ -f "$first/h" ] && kill -0 "$pid" 2>/dev/null; then
    pass "SIGUSR1: wrote $first in $(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b - a}') s, run goes on"
else
    fail "SIGUSR1: no time directory within 10 s, or the run stopped"
fi

sleep 2
kill -TERM "$pid"
t0=$(now)
wait "$pid"
rc=$?
t1=$(now)
took="$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b - a}')"
last="$(timeDirs | tail -n1)"
if [ "$rc" -eq 0 ] && grep -q "^End" log.savageHutterFoam \
   && [ "$last" != "$first" ] && [ -f "$last/h" ] && [ -f "$last/hMax" ] \
   && awk -v t="$took" 'BEGIN{exit !(t < 5)}'; then
    pass "SIGTERM: wrote $last and ended (exit 0, End) in $took s"
else
    fail "SIGTERM: exit $rc after $took s, last time directory '$last'"
    tail -n 20 log.savageHutterFoam
fi
grep -E "Cell updates per second|Time loop" log.savageHutterFoam | sed 's/^/      /'

# A restart from what SIGTERM wrote continues exactly: it runs to an end
# 0.05 s later, as does a run from 0 without a stop (the same write times
# before it: none, writeInterval 1000; the SIGUSR1 write changes no step),
# and the fields at that end are the same byte for byte
end="$(awk -v t="$last" 'BEGIN{print t + 0.05}')"
rm -rf "$d.ref"
mkdir "$d.ref"
cp -r 0 constant system "$d.ref"/
setEntry system/controlDict startFrom latestTime
setEntry system/controlDict endTime "$end"
if savageHutterFoam -backend cuda > log.restart 2>&1 && grep -q "^End" log.restart; then
    pass "restart from $last: runs to $(timeDirs | tail -n1)"
else
    fail "restart from $last failed"
    tail -n 20 log.restart
fi
setEntry "$d.ref/system/controlDict" endTime "$end"
(cd "$d.ref" && savageHutterFoam -backend cuda > log.savageHutterFoam 2>&1)
rc=$?
final="$(timeDirs | tail -n1)"
differ=""
compared=0
for f in h U hU regime hMax UMax pMax tArrival; do
    if cmp -s "$final/$f" "$d.ref/$final/$f"; then
        compared=$((compared + $(stat -c %s "$final/$f")))
    else
        differ="$differ $f"
    fi
done
if [ "$rc" -eq 0 ] && [ -n "$final" ] && [ -z "$differ" ]; then
    pass "SIGTERM at $last, restart to $final: h U hU regime hMax UMax pMax tArrival identical byte for byte to a run 0 -> $final without a stop ($compared bytes)"
else
    fail "SIGTERM at $last, restart to '$final': differs from a run without a stop in:${differ:- (reference run exit $rc)}"
    tail -n 20 "$d.ref/log.savageHutterFoam"
fi

# SIGINT (^C): write the state with its peak maps and the |dh/dt| report
# at the stop time, and end the run, within 5 s (the log prints the stop
# time to 8 digits, the report to more)
rm -rf "$d.int"
cp -r "$d" "$d.int"
cd "$d.int" || exit 1
rm -rf $(timeDirs) postProcessing
setEntry system/controlDict startFrom startTime
setEntry system/controlDict endTime 1000
setEntry system/controlDict writeInterval 1000
startRun
kill -INT "$pid"
t0=$(now)
wait "$pid"
rc=$?
t1=$(now)
took="$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b - a}')"
stop="$(sed -n 's/^SIGINT at t = \([^:]*\): writing and stopping$/\1/p' log.savageHutterFoam)"
last="$(timeDirs | tail -n1)"
report=postProcessing/steadyState/0/dhdt.dat
lastRow="$(grep -v '^#' "$report" 2>/dev/null | tail -n1 | awk '{print $1}')"
if [ "$rc" -eq 0 ] && grep -q "^Stopped by SIGINT" log.savageHutterFoam \
   && [ -n "$last" ] && [ -f "$last/h" ] && [ -f "$last/hMax" ] \
   && [ -f "$last/UMax" ] && [ -n "$stop" ] \
   && awk -v a="$lastRow" -v b="$stop" 'BEGIN{d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= 1e-6*(b > 1 ? b : 1))}' \
   && awk -v t="$took" 'BEGIN{exit !(t < 5)}'; then
    pass "SIGINT: stopped at t = $stop, wrote $last with hMax and UMax, dh/dt report ends at $lastRow, exit 0 in $took s"
else
    fail "SIGINT: exit $rc after $took s, stop '$stop', last directory '$last', report's last row '$lastRow'"
    tail -n 20 log.savageHutterFoam
fi

# A signal during start-up (reading 2M cells, the GPU's initialisation):
# SIGTERM 3 s after the start, SIGINT as the GPU line appears (the backend
# then being set up); each ends the run before its first step with a
# message, exit 0, nothing written
setEntry system/controlDict startFrom startTime
for how in "TERM:" "INT:^GPU: "
do
    sig="${how%%:*}"
    at="${how#*:}"
    had="$(timeDirs | tr '\n' ' ')"
    savageHutterFoam -backend cuda > log.startUp.$sig 2>&1 &
    pid=$!
    if [ -z "$at" ]
    then
        sleep 3
    else
        for _ in $(seq 1 600); do
            grep -q "$at" log.startUp.$sig 2>/dev/null && break
            sleep 0.01
        done
    fi
    kill -"$sig" "$pid"
    wait "$pid"
    rc=$?
    stage="$(sed -n "s/^SIG$sig during start-up (\(.*\)): the run ends before its first step; nothing written$/\1/p" log.startUp.$sig)"
    if [ $rc -eq 0 ] && [ -n "$stage" ] && [ "$(timeDirs | tr '\n' ' ')" = "$had" ] \
    && ! grep -q "^Starting time loop" log.startUp.$sig
    then
        pass "SIG$sig during start-up ($stage): ended with the message, exit 0, nothing written"
    else
        fail "SIG$sig during start-up: exit $rc, stage '$stage', time directories '$had' -> '$(timeDirs | tr '\n' ' ')'"
        tail -n 20 log.startUp.$sig
    fi
done

[ $status -eq 0 ] && echo "gpuSignalCheck: OK" || echo "gpuSignalCheck: FAILED"
exit $status

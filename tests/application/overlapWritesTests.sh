#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Writes overlapped with the steps (issue 27 item 1): a writer thread
#     writes, flushes and renames each time directory while the solver
#     steps on.  On the dam break (256 x 32 cells, binary, writes every
#     0.05 s to 0.5 s), each write held 0.03 s in flight
#     (SH_TEST_WRITE_DELAY, a test hook; the steps between two writes take
#     longer, 0.07 s on the development machine, so that a write waited
#     for shows as a wait):
#     same: every file of every time directory equals, byte for byte, a
#       run whose writes are on the solver's thread (SH_OVERLAP_WRITES=0);
#     overlapped: the summary line says the writes ran on the writer
#       thread and the solver waited for them less than half their time
#       (it stepped while they were in flight); the run with them
#       switched off says so;
#     fill: with the fill of the fields from the host snapshot held
#       0.2 s per write (SH_TEST_FILL_DELAY, a test hook), the solver's
#       thread spends less than 0.1 s per write in write() besides waiting
#       for the write before (the fill is the writer thread's), while with
#       SH_OVERLAP_WRITES=0 it spends at least the 0.2 s; both runs' time
#       directories byte for byte those of "same";
#     fails: a write that fails on the writer thread (a file size limit,
#       ulimit -f, standing in for a full disk) is reported on the
#       solver's thread naming the staging path, non-zero exit, no time
#       directory of it nor any incomplete one;
#     sigterm: SIGTERM while a write is in flight (each held 1 s, with
#       about 0.2 s of steps between writes: one is in flight nearly all
#       the time, the log being buffered gives no exact moment): exit 0,
#       that write and the signal's complete, and the restart from the
#       signal's time ends at 0.5 with h, U, hU, hMax equal to the
#       uninterrupted run's byte for byte.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     overlapWritesTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
export OMP_NUM_THREADS=1

#- makeCase <dir>: the damBreak tutorial on 256 x 32 cells, binary
makeCase()
{
    rm -rf "$1"
    mkdir -p "$1"
    cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$1"/
    (
        cd "$1" || exit 1
        rm -rf constant/polyMesh
        setBlockCells 256 32
        blockMesh > log.blockMesh 2>&1 || exit 1
        restore0Dir > /dev/null
        setAvalancheFields > log.setAvalancheFields 2>&1 || exit 1
        setEntry system/controlDict writeInterval 0.05
        setEntry system/controlDict writeFormat binary
    )
}

#- secondsOf <log> <n>: the n-th number of seconds in the "Writes:" line
secondsOf()
{
    grep '^Writes: ' "$1" | tail -n1 | grep -oE '[0-9.]+ s' | sed -n "$2p" \
        | cut -d' ' -f1
}

#- ownPerWrite <log>: seconds per write in write() on the solver's thread
#  besides waiting for the write before ("S s in write on the solver's
#  thread (W s of it waiting ...)": (S - W)/N)
ownPerWrite()
{
    grep '^Writes: ' "$1" | tail -n1 | python3 -c "
import re, sys
l = sys.stdin.read()
n = int(re.match(r'Writes: ([0-9]+) ', l).group(1))
m = re.search(r'([0-9.]+) s in write on the solver.s thread \(([0-9.]+) s of it waiting', l)
print('%.3f' % ((float(m.group(1)) - float(m.group(2)))/n))"
}

#- runPair <dir> <sync dir> <env> <sync env>: copies of the base case run
#  with writes overlapped and with SH_OVERLAP_WRITES=0, each with its
#  environment settings (NAME=value ...); their exit status in rcOver,
#  rcSync
runPair()
{
    cp -r "$base" "$1"
    cp -r "$base" "$2"
    (cd "$1" && env $3 savageHutterFoam -backend cpu > log 2>&1)
    rcOver=$?
    (cd "$2" && env $4 SH_OVERLAP_WRITES=0 savageHutterFoam -backend cpu > log 2>&1)
    rcSync=$?
}

base="$work/base"
makeCase "$base" || { fail "case set-up (see $base)"; finish; exit; }

# -- same, overlapped
over="$work/overlap"
sync="$work/sync"
runPair "$over" "$sync" SH_TEST_WRITE_DELAY=0.03 ""
nOver=$(timeDirs "$over" | wc -l)
if [ $rcOver -eq 0 ] && [ $rcSync -eq 0 ] && [ "$nOver" -eq 10 ] \
&& diff -r -x 'log*' "$over" "$sync" > "$work/same.diff" 2>&1
then
    pass "same: 10 time directories (postProcessing too) byte for byte those of SH_OVERLAP_WRITES=0"
else
    fail "same: rc $rcOver/$rcSync, $nOver time directories, or they differ (see $work/same.diff)"
fi

writing=$(secondsOf "$over/log" 1)
waited=$(secondsOf "$over/log" 2)
if grep -q '^Writes: 10 in .* on the writer thread (.* waited for by the solver)' "$over/log" \
&& python3 -c "import sys; w, q = float('$writing'), float('$waited'); sys.exit(not (w >= 0.3 and q < 0.5*w))" 2>/dev/null \
&& grep -q "^Writes: 10 in .* on the solver's thread" "$sync/log" \
&& grep -q "Writes on the solver's thread, not overlapped with the steps: SH_OVERLAP_WRITES=0" "$sync/log"
then
    pass "overlapped: 10 writes, $writing s on the writer thread, $waited s waited for; SH_OVERLAP_WRITES=0 writes on the solver's thread and says so"
else
    fail "overlapped: writing '$writing' s, waited '$waited' s (see $over/log, $sync/log)"
fi

# -- fill: on the writer thread, held 0.2 s per write
fillOver="$work/fillOverlap"
fillSync="$work/fillSync"
runPair "$fillOver" "$fillSync" SH_TEST_FILL_DELAY=0.2 SH_TEST_FILL_DELAY=0.2
ownOver=$(ownPerWrite "$fillOver/log" 2>/dev/null)
ownSync=$(ownPerWrite "$fillSync/log" 2>/dev/null)
if [ $rcOver -eq 0 ] && [ $rcSync -eq 0 ] \
&& grep -q '^Writes: 10 in .* on the writer thread (.* MB ([0-9.]* s of it fsync, [0-9.]* s filling the fields); ' "$fillOver/log" \
&& python3 -c "import sys; o, s = float('$ownOver'), float('$ownSync'); sys.exit(not (o < 0.1 and s >= 0.2))" 2>/dev/null \
&& diff -r -x 'log*' "$fillOver" "$sync" > "$work/fill.diff" 2>&1 \
&& diff -r -x 'log*' "$fillSync" "$sync" >> "$work/fill.diff" 2>&1
then
    pass "fill: held 0.2 s per write, the solver's thread spends $ownOver s per write in write besides waiting (SH_OVERLAP_WRITES=0: $ownSync s); directories those of \"same\""
else
    fail "fill: rc $rcOver/$rcSync, solver's thread '$ownOver' s per write (SH_OVERLAP_WRITES=0: '$ownSync' s), or the directories differ (see $fillOver/log, $fillSync/log, $work/fill.diff)"
fi

# -- fails: the first write of the run fails on the writer thread
d="$work/fails"
cp -r "$base" "$d"
# The log through a pipe: the limit is on every file the solver writes
(cd "$d" && ulimit -f 8 && trap '' XFSZ \
    && SH_TEST_WRITE_DELAY=0.1 exec savageHutterFoam -backend cpu 2>&1) \
    | cat > "$d/log"
rc=${PIPESTATUS[0]}
if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$d/log" \
&& grep -q "Cannot write .*fails/.savageHutterFoam-writing/0.05" "$d/log" \
&& grep -q "disk full" "$d/log" && ! grep -qE "printStack|^#[0-9]+ " "$d/log" \
&& [ -z "$(timeDirs "$d")" ] && ! grep -q "^End$" "$d/log"
then
    pass "fails: a write failing on the writer thread (ulimit -f 8) stops the run naming .savageHutterFoam-writing/0.05, rc $rc, no time directory"
else
    fail "fails: rc $rc, message, or directories $(timeDirs "$d" | tr '\n' ' ') (see $d/log)"
fi

# -- sigterm while a write is in flight
d="$work/sigterm"
cp -r "$base" "$d"
(cd "$d" && SH_TEST_WRITE_DELAY=1 exec savageHutterFoam -backend cpu > log 2>&1) &
pid=$!
# Once the run writes (a write is then in flight nearly all the time)
if waitFor "$d/log" "Steady-state check" 60
then
    sleep 1.5
    kill -TERM $pid
fi
wait $pid
rc=$?
last=$(timeDirs "$d" | tail -n1)
allComplete=true
for t in $(timeDirs "$d")
do
    complete "$d" "$t" || allComplete=false
done
if [ $rc -eq 0 ] && grep -q "^SIGTERM at t = " "$d/log" && [ -n "$last" ] \
&& [ "$(timeDirs "$d" | wc -l)" -ge 2 ] && $allComplete \
&& [ ! -d "$d/.savageHutterFoam-writing" ]
then
    setEntry "$d/system/controlDict" startFrom latestTime
    (cd "$d" && savageHutterFoam -backend cpu > log.restart 2>&1)
    same=true
    for f in h U hU hMax
    do
        cmp -s "$d/0.5/$f" "$sync/0.5/$f" || same=false
    done
    if $same
    then
        pass "sigterm: during a write in flight, rc 0, $(timeDirs "$d" | wc -l) complete directories to $last; the restart's 0.5 equals the uninterrupted run's"
    else
        fail "sigterm: the restart from $last differs at 0.5 (see $d/log.restart)"
    fi
else
    fail "sigterm: rc $rc, complete $allComplete, directories $(timeDirs "$d" | tr '\n' ' ') (see $d/log)"
fi

finish

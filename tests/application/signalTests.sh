#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Stopping a run, and time directories replaced (caseTests.sh has
#     SIGTERM, SIGUSR1 and the restart from a stop; this is the rest):
#       - SIGINT (^C) during the time loop: the run finishes the step under
#         way, writes the current state (off the write times) as a complete
#         time directory with the peak maps hMax, UMax (hMax >= h,
#         UMax >= |U|, neither below the previous write's), adds the stop
#         time to the |dh/dt| report postProcessing/steadyState/0/dhdt.dat,
#         and ends normally (exit 0, End) within seconds;
#       - a second SIGINT while that state is being written (on 256 x 128
#         cells, sent as soon as the staging directory appears): the
#         process ends at once, as OpenFOAM's does on a second signal
#         (exit status 130 = 128 + SIGINT), no time directory of the stop
#         time appears (or, had the write finished first, a complete one),
#         every other time directory stays complete; the next start removes
#         what was being written, with a warning, and runs;
#       - a restart that writes again the time directories of an earlier
#         run (writeControl timeStep, every step, from 0 again): each is
#         replaced (a new directory, inode changed), complete, none ever
#         missing or incomplete while a watcher reads them all the time;
#         no staging directory is left; the same with the fallback that
#         moves the old one aside (SH_NO_RENAME_EXCHANGE=1), where the
#         watcher may see a name missing for an instant (counted, not a
#         failure) but the end state is the same;
#       - SIGKILL while such a restart writes its 2nd, 9th, ... directory
#         in place of an earlier one: afterwards every directory of the
#         earlier run is there and complete;
#       - a directory left aside by the fallback when killed between its
#         two renames (<case>/.savageHutterFoam-writing/<time>.replaced,
#         <time> missing) is moved back, with a warning, before the start
#         time is chosen: startFrom latestTime starts from it.
#       - SIGTERM while the mesh is read, SIGINT while the fields are
#         (1024 x 512 cells, start-up takes seconds): the run ends after
#         that stage with a message and exit status 0, writing nothing.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     signalTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
export OMP_NUM_THREADS=1

#- makeCase <dir> <nx> <ny>: the damBreak tutorial on nx x ny cells, h set
makeCase()
{
    mkdir -p "$1"
    cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$1"/
    (
        cd "$1" || exit 1
        setBlockCells "$2" "$3"
        runApplication blockMesh
        restore0Dir
        runApplication setAvalancheFields
    ) > "$1.setup.log" 2>&1
}

#- incomplete <case>: the time directories that are not complete
incomplete()
{
    local t out=""
    for t in $(timeDirs "$1")
    do
        complete "$1" "$t" || out="$out $t"
    done
    echo "$out"
}

#- startRun <case> <log>: savageHutterFoam in <case> in the background, its
#  output in <case>/<log>; its process id in $pid (the solver's own: exec)
startRun()
{
    (cd "$1" && exec savageHutterFoam -backend cpu > "$2" 2>&1) &
    pid=$!
}

#- startPastWrite <case> <time> <seconds> <polls> <delay>: startRun with
#  log.savageHutterFoam, then waits for its time loop (<seconds> at most)
#  and for its directory <time> (<polls> tenths of a second at most), then
#  <delay> seconds more
startPastWrite()
{
    startRun "$1" log.savageHutterFoam
    waitFor "$1/log.savageHutterFoam" "^Starting time loop" "$3"
    local i
    for i in $(seq "$4")
    do
        [ -d "$1/$2" ] && break
        sleep 0.1
    done
    sleep "$5"
}

# -- SIGINT: write the state and end the run -----------------------------------
d="$work/sigint"
makeCase "$d" 256 32 || { cat "$d.setup.log"; fail "sigint: set-up failed"; }
setEntry "$d/system/controlDict" endTime 100
setEntry "$d/system/controlDict" writeInterval 0.05
cp -r "$d" "$work/sigintSetUp"
log="$d/log.savageHutterFoam"
# A signal that arrives during the last step before a write time stops the
# run on that write time, rightly; the check of a state off the write
# times needs one that arrives elsewhere, so the run is made again (a new
# copy of the case) when the stop lies on the write grid, up to 4 times
attempts=0
while :
do
    attempts=$((attempts + 1))
    # Past the first write time, so that the stop has one before it
    startPastWrite "$d" 0.05 60 300 0.3
    t0=$(date +%s.%N)
    kill -INT "$pid"
    wait "$pid"
    rc=$?
    took=$(python3 -c "print('%.2f' % ($(date +%s.%N) - $t0))")
    tStop=$(sed -n 's/^SIGINT at t = \([^:]*\): writing and stopping$/\1/p' "$log")
    onGrid=$(python3 -c "k = float('${tStop:-0.5}')/0.05; print(int(abs(k - round(k)) < 1e-6))")
    [ "$onGrid" = 1 ] && [ $attempts -lt 4 ] || break
    echo "      attempt $attempts: the signal stopped the run on the write time $tStop; again"
    rm -rf "$d"
    cp -r "$work/sigintSetUp" "$d"
done
stopDir=$(sed -n 's/^Stopped by SIGINT at t = .*, written to \([^ ]*\) .*/\1/p' "$log")
last=$(timeDirs "$d" | tail -n1)
if [ $rc -eq 0 ] && grep -q "^End" "$log" && [ -n "$tStop" ] && [ -n "$stopDir" ] \
&& [ "$stopDir" = "$last" ] && complete "$d" "$stopDir" \
&& python3 -c "import sys; sys.exit(not $took < 10)"
then
    pass "SIGINT at t = $tStop: wrote $stopDir (complete, the last time directory) and ended the run (exit 0, End) in $took s"
else
    fail "SIGINT: rc $rc, t '$tStop', directory '$stopDir' (last '$last'), $took s (see $log)"
fi
# The state written is that of the stop time, after a whole step: the time
# of uniform/time is the one logged, off the write times; the |dh/dt|
# report has the stop time as its last line; the peak maps hold
if [ -n "$stopDir" ] && python3 - "$d" "$stopDir" "$tStop" <<'PY'
import os, re, sys
case, stop, tStop = sys.argv[1], sys.argv[2], float(sys.argv[3])
def field(t, name):
    text = open(os.path.join(case, t, name)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text)
    if not m:
        v = re.search(r"internalField\s+uniform\s+\(?([^;)]*)", text).group(1).split()
        return [float(x) for x in v]
    body = text[m.end():text.index("\n)", m.end())]
    return [float(x) for x in body.replace("(", " ").replace(")", " ").split()]
problems = []
value = float(re.search(r"\bvalue\s+([^;]+);", open(os.path.join(case, stop, "uniform", "time")).read()).group(1))
if abs(value - tStop) > 1e-6 * max(abs(tStop), 1e-30):
    problems.append("uniform/time value %r, logged %r" % (value, tStop))
k = value / 0.05
if abs(k - round(k)) < 1e-6:
    problems.append("the stop time %r lies on the write grid (no state off the write times)" % value)
report = os.path.join(case, "postProcessing", "steadyState", "0", "dhdt.dat")
rows = [l.split() for l in open(report) if l.strip() and not l.startswith("#")]
if not rows or abs(float(rows[-1][0]) - value) > 1e-9 * max(abs(value), 1):
    problems.append("dhdt.dat's last time %s, not the stop %r" % (rows[-1][0] if rows else None, tStop))
h, U, hMax, UMax = (field(stop, f) for f in ("h", "U", "hMax", "UMax"))
times = sorted((t for t in os.listdir(case) if re.fullmatch(r"[0-9.e+-]+", t) and t != "0"), key=float)
prev = times[times.index(stop) - 1]
hMax0, UMax0 = field(prev, "hMax"), field(prev, "UMax")
bad = 0
for c in range(len(h)):
    speed = (U[3*c]**2 + U[3*c+1]**2) ** 0.5
    if hMax[c] < h[c] or (h[c] > 1e-6 and UMax[c] < speed * (1 - 1e-12)):
        bad += 1
    if hMax[c] < hMax0[c] or UMax[c] < UMax0[c]:
        bad += 1
if bad:
    problems.append("%d peak-map violations" % bad)
if max(hMax) <= max(h) and max(UMax) <= 0:
    problems.append("peak maps empty")
print("      t = %r (write grid 0.05); dhdt.dat %d rows, last at %s: RMS %s; hMax up to %.6g, UMax up to %.6g; previous write %s"
      % (value, len(rows), rows[-1][0], rows[-1][1], max(hMax), max(UMax), prev))
for p in problems:
    print("      " + p)
sys.exit(1 if problems else 0)
PY
then
    pass "SIGINT: $stopDir holds the state of the stop time (off the write grid), the peak maps (hMax >= h, UMax >= |U|, not below $(timeDirs "$d" | tail -n2 | head -n1)'s) and the |dh/dt| report ends at it"
else
    fail "SIGINT: the stop directory, its peak maps or the |dh/dt| report are wrong (see $d)"
fi

# -- A signal during start-up -------------------------------------------------
# On 1024 x 512 cells start-up takes seconds (reading the mesh, the fields,
# the backend); a SIGTERM while the mesh is read, a SIGINT while the fields
# are: the run ends after that stage with a message, exit status 0, and
# writes nothing (no time directory, no staging directory, no report).
# The signal is sent when the log shows the stage has begun; on a loaded
# machine the stage can be over before it arrives, and the run then ends
# after a later start-up stage (still with nothing written).  Such an
# attempt is repeated, three attempts at most: the check fails when none
# ends after the stage it aimed at, or when any writes something, goes on
# into the time loop or exits non-zero.
d="$work/startUp"
makeCase "$d" 1024 512 || { cat "$d.setup.log"; fail "start-up: set-up failed"; }
setEntry "$d/system/controlDict" endTime 1
before="$(cd "$d" && find . | sort)"
later="(checking the case's time directories|reading the controls|reading the mesh|reading the fields|setting up the backend)"
for how in "TERM:^Create mesh for time:reading the mesh" \
           "INT:^Reading field h:reading the fields"
do
    sig="${how%%:*}"
    rest="${how#*:}"
    at="${rest%%:*}"
    stage="${rest#*:}"
    result=""
    for attempt in 1 2 3
    do
        log="$d/log.startUp.$sig.$attempt"
        startRun "$d" "log.startUp.$sig.$attempt"
        waitFor "$log" "$at" 120
        kill -"$sig" "$pid"
        wait "$pid"
        rc=$?
        after="$(cd "$d" && find . ! -name 'log.*' | sort)"
        if [ $rc -ne 0 ] || grep -q "^Starting time loop" "$log" \
        || [ "$after" != "$(echo "$before" | grep -v '/log\.')" ]
        then
            result="bad"
            break
        elif grep -q "^SIG$sig during start-up ($stage): the run ends before its first step; nothing written" "$log"
        then
            result="ok"
            break
        elif grep -qE "^SIG$sig during start-up \($later\): the run ends before its first step; nothing written" "$log"
        then
            echo "      attempt $attempt: the signal arrived after $stage had ended ($(grep -oE "during start-up \([^)]*\)" "$log")); again"
            result="late"
        else
            result="bad"
            break
        fi
    done
    if [ "$result" = ok ]
    then
        pass "SIG$sig during start-up ($stage, on 1024 x 512 cells, attempt $attempt): the run ended with a message, exit 0, nothing written"
    elif [ "$result" = late ]
    then
        fail "SIG$sig during start-up: in 3 attempts the run never ended after $stage (see $d/log.startUp.$sig.*)"
    else
        fail "SIG$sig during start-up: rc $rc, message or files wrong (see $log; files now: $(echo "$after" | tr '\n' ' ' | cut -c1-300))"
    fi
done

# -- A second SIGINT while the state is being written --------------------------
d="$work/secondSignal"
makeCase "$d" 256 128 || { cat "$d.setup.log"; fail "second signal: set-up failed"; }
setEntry "$d/system/controlDict" endTime 100
setEntry "$d/system/controlDict" writeInterval 0.005
log="$d/log.savageHutterFoam"
staging="$d/.savageHutterFoam-writing"
startPastWrite "$d" 0.005 120 600 0.2
kill -INT "$pid"
# The second as soon as the stop's directory is being written: after the
# log says so (a write time's directory may be under way before), when the
# staging directory appears (builtins only: no time lost to forks)
sent=false
end=$((SECONDS + 60))
text=""
while [ $SECONDS -lt $end ] && kill -0 "$pid" 2>/dev/null
do
    IFS= read -r -d '' text < "$log"
    [[ $text == *"SIGINT at t = "* ]] && break
done
# What was there when the stop's write began
before="$(timeDirs "$d" | tr '\n' ' ')"
while [ $SECONDS -lt $end ] && kill -0 "$pid" 2>/dev/null
do
    if [ -d "$staging" ]
    then
        kill -INT "$pid" && sent=true
        break
    fi
done
wait "$pid"
rc=$?
tStop=$(sed -n 's/^SIGINT at t = \([^:]*\): writing and stopping$/\1/p' "$log")
after="$(timeDirs "$d" | tr '\n' ' ')"
bad="$(incomplete "$d")"
leftover=false
[ -d "$staging" ] && leftover=true
how=""
if [ $rc -eq 130 ] && ! grep -q "^End" "$log" && [ "$after" = "$before" ] && $leftover
then
    how="ended by the second SIGINT (exit 130) while writing t = $tStop: no directory of it, the directory being written left in .savageHutterFoam-writing"
elif [ $rc -eq 0 ] && grep -q "^Stopped by SIGINT" "$log"
then
    how="the write of t = $tStop finished before the second SIGINT took effect (exit 0): directories $after"
fi
if $sent && [ -n "$how" ] && [ -z "$bad" ]
then
    pass "second SIGINT while writing: $how; every time directory complete ($after)"
else
    fail "second SIGINT: sent $sent, rc $rc, before '$before', after '$after', incomplete '$bad', staging left $leftover (see $log)"
fi
# The next start clears what was being written and runs on
last=$(timeDirs "$d" | tail -n1)
restartFromLast "$d" 0.005 $leftover
rc=$restartRc
warned=$restartWarned
if [ $rc -eq 0 ] && $warned && [ ! -d "$staging" ] && [ -z "$(incomplete "$d")" ] \
&& grep -q "^Create mesh for time = $last\$" "$d/log.restart"
then
    pass "second SIGINT: the next start (latestTime $last) $($leftover && echo "removed the staging directory with a warning" || echo "found no staging directory") and ran to $(timeDirs "$d" | tail -n1)"
else
    fail "second SIGINT: the restart rc $rc, warned $warned, staging still there or incomplete directories (see $d/log.restart)"
fi

# -- A restart that writes the directories of an earlier run again -------------
#- watch <case> <stop file> <out>: looks up every time directory present
#  at its start, and reads its files, again and again until <stop file>
#  appears; writes "polls missing incomplete" to <out>: missing, a name
#  not found; incomplete, a file missing or cut short in a directory that
#  stayed in place (the same inode before and after its files were read:
#  a directory replaced meanwhile, its files removed under the reader,
#  makes the read inconclusive and it is read again; one gone meanwhile,
#  as between the fallback's two renames, counts as missing)
watch()
{
    python3 - "$1" "$2" "$3" <<'PY' &
import os, re, sys
case, stop, out = sys.argv[1:4]
names = [t for t in os.listdir(case) if re.fullmatch(r"[0-9.e+-]+", t) and t != "0"]
files = ["h", "U", "hU", "zb", "regime", "hMax", "UMax", os.path.join("uniform", "time")]
def inode(t):
    try:
        return os.stat(os.path.join(case, t)).st_ino
    except FileNotFoundError:
        return None
def whole(t):
    """True or False for a directory in place all along; "gone" when its
    name was missing at the end; None when it was replaced meanwhile"""
    before = inode(t)
    if before is None:
        return "gone"
    ok = True
    for f in files:
        try:
            with open(os.path.join(case, t, f), "rb") as fh:
                fh.seek(0, 2)
                fh.seek(max(0, fh.tell() - 200))
                if b"// ****" not in fh.read():
                    ok = False
        except FileNotFoundError:
            ok = False
    after = inode(t)
    if after is None:
        return "gone"
    return ok if after == before else None
polls = missing = incomplete = 0
while not os.path.exists(stop):
    for t in names:
        polls += 1
        r = whole(t)
        while r is None:
            r = whole(t)
        if r == "gone":
            missing += 1
        elif not r:
            incomplete += 1
open(out, "w").write("%d %d %d\n" % (polls, missing, incomplete))
PY
}

#- inodes <case>: "time inode" lines
inodes()
{
    (cd "$1" && for t in $(timeDirs .); do echo "$t $(stat -c %i "$t")"; done)
}

d="$work/replace"
makeCase "$d" 128 16 || { cat "$d.setup.log"; fail "replace: set-up failed"; }
setEntry "$d/system/controlDict" endTime 0.25
setEntry "$d/system/controlDict" writeControl timeStep
setEntry "$d/system/controlDict" writeInterval 1
(cd "$d" && savageHutterFoam -backend cpu > log.first 2>&1) || fail "replace: the first run failed (see $d/log.first)"
first="$(timeDirs "$d")"
nFirst=$(echo "$first" | wc -l)
cp -r "$d" "$work/replaceFirst"

#- rewrite <label> [env...]: the run from 0 again, watched; checks
rewrite()
{
    local label="$1"
    shift
    local old new stopFile="$work/$label.stop" out="$work/$label.watch"
    old="$(inodes "$d")"
    rm -f "$stopFile" "$out"
    watch "$d" "$stopFile" "$out"
    local wpid=$!
    sleep 0.2
    (cd "$d" && env "$@" savageHutterFoam -backend cpu > "log.$label" 2>&1)
    local rc=$?
    touch "$stopFile"
    wait "$wpid"
    new="$(inodes "$d")"
    local kept=0 t
    while read -r t ino
    do
        grep -qx "$t $ino" <<< "$old" && kept=$((kept + 1))
    done <<< "$new"
    read -r polls missing incompleteSeen < "$out"
    local bad
    bad="$(incomplete "$d")"
    local now
    now="$(timeDirs "$d")"
    problems=""
    [ $rc -eq 0 ] || problems="$problems exit $rc;"
    [ "$now" = "$first" ] || problems="$problems the time directories are not those of the first run;"
    [ "$kept" -eq 0 ] || problems="$problems $kept directories not replaced;"
    [ -z "$bad" ] || problems="$problems incomplete:$bad;"
    [ ! -d "$d/.savageHutterFoam-writing" ] || problems="$problems staging directory left;"
    watched="$polls reads of the $nFirst directories while they were replaced: $missing missing, $incompleteSeen incomplete"
}

rewrite swap
if [ -z "$problems" ] && [ "$missing" -eq 0 ] && [ "$incompleteSeen" -eq 0 ] && [ "$polls" -gt 0 ]
then
    pass "replace: a run from 0 again replaced all $nFirst time directories of the first run (new inodes, complete, no staging left); $watched"
else
    fail "replace:$problems $watched (see $d/log.swap)"
fi
rewrite fallback SH_NO_RENAME_EXCHANGE=1
if [ -z "$problems" ] && [ "$incompleteSeen" -eq 0 ]
then
    pass "replace (fallback, moved aside first): all $nFirst replaced, complete, no staging left; $watched (a name may be missing for an instant here)"
else
    fail "replace (fallback):$problems $watched (see $d/log.fallback)"
fi

# SIGKILL while a run from 0 replaces them: none lost, all complete
lost=""
bad=""
kills=0
staging="$d/.savageHutterFoam-writing"
for at in 2 9 17 28 40
do
    # Under load the watching loop may miss short-lived staging
    # directories and the run end before its at-th: that run is checked
    # too, and made again (up to 3 times) for a kill that lands
    for attempt in 1 2 3
    do
        # Killed while writing its at-th directory (the staging directory
        # there, watched with builtins only)
        rm -rf "$staging"
        startRun "$d" "log.kill$at"
        seen=0
        inside=false
        end=$((SECONDS + 60))
        while [ $SECONDS -lt $end ] && kill -0 "$pid" 2>/dev/null
        do
            if [ -d "$staging" ]
            then
                if ! $inside
                then
                    inside=true
                    seen=$((seen + 1))
                    [ $seen -ge $at ] && break
                fi
            else
                inside=false
            fi
        done
        kill -KILL "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        rcKill=$?
        # Killed (128 + 9), not ended on its own
        landed=false
        [ $rcKill -eq 137 ] && landed=true
        for t in $first
        do
            [ -d "$d/$t" ] || lost="$lost $t"
        done
        bad="$bad$(incomplete "$d")"
        if $landed
        then
            kills=$((kills + 1))
            break
        fi
        echo "      the run ended before its ${at}th directory was seen (attempt $attempt); again"
    done
done
rm -rf "$d/.savageHutterFoam-writing"
if [ "$kills" -eq 5 ] && [ -z "$lost" ] && [ -z "$bad" ]
then
    pass "replace: 5 SIGKILLs while a run from 0 was writing its 2nd, 9th, 17th, 28th, 40th directory in place of the first run's: all $nFirst still there and complete after each"
else
    fail "replace: kills $kills, lost:${lost:- none}, incomplete:${bad:- none} (see $d)"
fi

# A directory the fallback had moved aside when killed is moved back
d="$work/restore"
cp -r "$work/replaceFirst" "$d"
rm -f "$d"/log.*
last=$(timeDirs "$d" | tail -n1)
mkdir -p "$d/.savageHutterFoam-writing"
mv "$d/$last" "$d/.savageHutterFoam-writing/$last.replaced"
cp -r "$d/.savageHutterFoam-writing/$last.replaced" "$d/.savageHutterFoam-writing/$last"
truncate -s 100 "$d/.savageHutterFoam-writing/$last/h"
setEntry "$d/system/controlDict" startFrom latestTime
setEntry "$d/system/controlDict" endTime 0.26
setEntry "$d/system/controlDict" writeControl adjustableRunTime
setEntry "$d/system/controlDict" writeInterval 0.01
(cd "$d" && savageHutterFoam -backend cpu > log.restore 2>&1)
rc=$?
if [ $rc -eq 0 ] && grep -q "Restoring .*/$last\" from .*$last.replaced" "$d/log.restore" \
&& grep -q "^Create mesh for time = $last\$" "$d/log.restore" && complete "$d" "$last" \
&& [ ! -d "$d/.savageHutterFoam-writing" ] && complete "$d" 0.26
then
    pass "restore: $last, left aside in .savageHutterFoam-writing by a kill between the fallback's two renames, is moved back with a warning and the run starts from it"
else
    fail "restore: rc $rc (see $d/log.restore)"
fi

finish

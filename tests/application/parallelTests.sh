#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Decomposed runs the OpenFOAM way, on CPU ranks, against the serial
#     run of the same case: a copy of the damBreak tutorial on 48 x 12
#     cells with an inflow side (xMin), a transmissive side (xMax),
#     walls (y), a dam break and a cap off the centre line (so that cuts in
#     x and y both carry flow), rho for pMax, the arrival map, written with
#     writePrecision 17 (decomposePar and reconstructPar write fields with
#     it).  Checks (bin/tools/compareDecomposed compares):
#       - decompositions (2 1 1), (1 2 1) simple, (2 2 1) hierarchical and
#         an uneven (3 1 1) by method manual (20/14/14 columns): decomposePar,
#         mpirun -np N savageHutterFoam -parallel, reconstructPar; every
#         field of every written time (h, U, hU, zb, regime, hMax, UMax,
#         pMax, tArrival) on every processor identical to the serial run's
#         cells, bit for bit, and as reconstructed (reconstructPar writes a
#         -0 as 0: the sign of zero aside); the steady-state report written
#         with as many lines;
#       - decompositions that are not a tensor product of rectangles
#         refused naming the methods that work, non-zero exit, nothing
#         written, no hang: simple (5 1 1) (a staircase), a manual
#         T-junction, a manual part one column wide; a side of the block
#         with two conditions on two processors' parts refused;
#       - a restart with pMax missing on one processor: all do without it;
#       - a parallel restart (startFrom latestTime, (2 2 1)) continues to
#         the serial run's files; so does one whose last time is missing on
#         one processor (the processors agree on the earlier time);
#       - SIGTERM to mpirun: both processors write the same time whole and
#         stop; a parallel restart from it reaches, at the next write time
#         but one, the state of the serial run uninterrupted to it;
#       - foamToVTK -parallel reads the decomposed output.
#     SH_PARALLEL_BACKEND=cuda runs the decomposed runs on the GPU (a GPU
#     per processor by its rank on the node, the GPUs shared when fewer),
#     still against the serial CPU run (tests/application/
#     gpuParallelCheck.sh on the GPU machine).
#     mpirun runs as root with OMPI_ALLOW_RUN_AS_ROOT and oversubscribes
#     the cores (--oversubscribe: Open MPI).  Without MPI (mpirun absent,
#     or savageHutterFoam built without it) every check is skipped, saying
#     why.
#
# Usage
#     parallelTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"

# The decomposed runs' backend (the serial reference runs on the CPU):
# SH_PARALLEL_BACKEND=cuda on the GPU machine (gpuParallelCheck.sh)
backend="${SH_PARALLEL_BACKEND:-cpu}"
echo "Decomposed runs with -backend $backend, the serial run with -backend cpu"

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMP_NUM_THREADS=1

if ! command -v mpirun > /dev/null
then
    skip "decomposed runs: no mpirun (bin/installDependencies installs openmpi-bin)"
    finish
    exit 77
fi

fields="h U hU zb regime hMax UMax pMax tArrival"

base="$work/base"
mkdir "$base"
cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$base"/
(
    cd "$base" || exit 1
    setBlockCells 48 12
    setEntry system/controlDict endTime 0.4
    setEntry system/controlDict writeInterval 0.2
    setEntry system/controlDict writePrecision 17
    setEntry system/controlDict startFrom latestTime
    setEntry constant/transportProperties rho 1500
    setEntry 0.orig/h boundaryField/upslope "{ type fixedValue; value uniform 0.3; }"
    setEntry 0.orig/U boundaryField/upslope "{ type fixedValue; value uniform (2 0 0); }"
    cat > system/setAvalancheFieldsDict <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }
h
(
    damBreak   { position -6; upstream 1; downstream 0; }
    hemisphere { centre (1 0.7); radius 1.3; }
);
U
(
    box { min (-3 -1.6); max (3 0); value (1 0.5 0); }
);
EOF
    runApplication blockMesh
    restore0Dir
    runApplication setAvalancheFields
) > "$work/base.log" 2>&1 || { cat "$work/base.log"; fail "setting up the base case (its log above)"; finish; exit 1; }

# The serial run
serial="$work/serial"
cp -r "$base" "$serial"
(cd "$serial" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
    || { fail "the serial run (see $serial/log.savageHutterFoam)"; finish; exit 1; }
serialTimes="$(timeDirs "$serial" | tr '\n' ' ')"
[ "$serialTimes" = "0.2 0.4 " ] || fail "the serial run wrote '$serialTimes', not 0.2 0.4"

#- runDecomposed <n> <log> [args]: mpirun -np <n> savageHutterFoam -parallel
#  in the current directory, its output in <log>; status 124 when it has
#  not ended within 300 s (a hang)
runDecomposed()
{
    local n="$1" log="$2"
    shift 2
    timeout 300 mpirun --oversubscribe -np "$n" savageHutterFoam -parallel \
        -backend "$backend" "$@" > "$log" 2>&1
}

#- decomposeDict <case> <n> <method> [<nx> <ny>]: system/decomposeParDict
decomposeDict()
{
    local dir="$1" n="$2" method="$3"
    {
        echo 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }'
        echo "numberOfSubdomains $n;"
        echo "method $method;"
        echo "simpleCoeffs { n ($4 $5 1); delta 0.001; }"
        echo "hierarchicalCoeffs { n ($4 $5 1); delta 0.001; order xyz; }"
        echo 'manualCoeffs { dataFile "cellDecomposition"; }'
    } > "$dir/system/decomposeParDict"
}

#- sameAsSerial <case> <what>: every field of every serial time, on every
#  processor (bit for bit) and as reconstructed (but for signs of zero)
sameAsSerial()
{
    local out rc
    out="$(python3 "$project/bin/tools/compareDecomposed" "$2" \
        "$serial" "$1" "$serialTimes" "$fields" 2>&1)"
    rc=$?
    tally "$rc" "$out" "$2"
}

#- runParallel <case> <n> [args]: decomposePar, mpirun, reconstructPar
runParallel()
{
    local dir="$1" n="$2"
    shift 2
    (
        cd "$dir" || exit 1
        decomposePar -force > log.decomposePar 2>&1 || exit 2
        runDecomposed "$n" log.savageHutterFoam "$@" || exit 3
        reconstructPar > log.reconstructPar 2>&1 || exit 4
    )
}

newCase()
{
    rm -rf "$work/$1"
    cp -r "$base" "$work/$1"
    echo "$work/$1"
}

for split in "2 simple 2 1" "2 simple 1 2" "4 hierarchical 2 2" "3 manual 3 1"
do
    set -- $split
    name="split$3x$4-$2"
    dir="$(newCase "$name")"
    decomposeDict "$dir" "$1" "$2" "$3" "$4"
    if [ "$2" = manual ]
    then
        # Columns 0-19, 20-33, 34-47: parts of 20, 14 and 14 columns
        {
            echo 'FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }'
            echo 576
            echo '('
            for j in $(seq 0 11); do for i in $(seq 0 47); do
                if [ "$i" -lt 20 ]; then echo 0; elif [ "$i" -lt 34 ]; then echo 1; else echo 2; fi
            done; done
            echo ')'
        } > "$dir/constant/cellDecomposition"
    fi
    runParallel "$dir" "$1"
    rc=$?
    if grep -q "built without MPI" "$dir/log.savageHutterFoam" 2>/dev/null
    then
        skip "decomposed runs: savageHutterFoam was built without MPI"
        finish
        exit 77
    fi
    if [ $rc -ne 0 ]
    then
        fail "$name: step $rc of decomposePar, mpirun, reconstructPar failed (see $dir/log.*)"
        continue
    fi
    sameAsSerial "$dir" "$name, mpirun -np $1"
    if [ "$(wc -l < "$dir/postProcessing/steadyState/0/dhdt.dat")" \
        = "$(wc -l < "$serial/postProcessing/steadyState/0/dhdt.dat")" ]
    then
        pass "$name: the steady-state report written (by the master)"
    else
        fail "$name: postProcessing/steadyState/0/dhdt.dat missing or short"
    fi
done

# A staircase: refused, naming the methods; nothing written
dir="$(newCase staircase)"
decomposeDict "$dir" 5 simple 5 1
(cd "$dir" && decomposePar -force > log.decomposePar 2>&1)
(cd "$dir" && runDecomposed 5 log.savageHutterFoam)
rc=$?
written="$(cd "$dir" && ls -d processor*/[1-9]* processor*/0.[0-9]* 2>/dev/null)"
if [ $rc -ne 0 ] && grep -q "not a rectangle" "$dir/log.savageHutterFoam" \
    && grep -q "method simple or hierarchical" "$dir/log.savageHutterFoam" \
    && [ -z "$written" ]
then
    pass "simple (5 1 1), a staircase: refused ($(grep -m1 'not a rectangle' "$dir/log.savageHutterFoam" | cut -c1-100)...)"
else
    fail "simple (5 1 1), a staircase: exit $rc, written '$written' (see $dir/log.savageHutterFoam)"
fi

#- refusedSplit <name> <n> <log pattern> <what>: a manual decomposition
#  (constant/cellDecomposition written by the caller into $dir) refused
#  within 120 s, naming the methods that work, nothing written
refusedSplit()
{
    local name="$1" n="$2" pattern="$3" what="$4" rc written
    (cd "$dir" && decomposePar -force > log.decomposePar 2>&1)
    (cd "$dir" && runDecomposed "$n" log.savageHutterFoam)
    rc=$?
    written="$(cd "$dir" && ls -d processor*/[1-9]* processor*/0.[0-9]* 2>/dev/null)"
    if [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q "$pattern" "$dir/log.savageHutterFoam" \
        && grep -q "method simple or hierarchical" "$dir/log.savageHutterFoam" \
        && [ -z "$written" ]
    then
        pass "$what: refused ($(grep -m1 "$pattern" "$dir/log.savageHutterFoam" | cut -c1-110)...)"
    else
        fail "$what: exit $rc (124: hung), written '$written' (see $dir/log.savageHutterFoam)"
    fi
}

#- manualSplit <dir> <awk expression of i, j giving the part>
manualSplit()
{
    {
        echo 'FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }'
        echo 576
        echo '('
        awk "BEGIN { for (j = 0; j < 12; j++) for (i = 0; i < 48; i++) print $2 }"
        echo ')'
    } > "$1/constant/cellDecomposition"
}

# A T-junction: part 0 the left half, parts 1 and 2 the right half's
# bottom and top: part 0's side meets two neighbours
dir="$(newCase tJunction)"
decomposeDict "$dir" 3 manual 1 1
manualSplit "$dir" '(i < 24 ? 0 : (j < 6 ? 1 : 2))'
refusedSplit tJunction 3 "neighbours do not share whole sides" "manual T-junction"

# A part one column wide (narrower than the two ghost layers)
dir="$(newCase narrowPart)"
decomposeDict "$dir" 2 manual 1 1
manualSplit "$dir" '(i < 47 ? 0 : 1)'
refusedSplit narrowPart 2 "narrower than the" "manual split with a part one column wide"

# The inflow side cut in two (1 2 1), one half made transmissive in the
# decomposed fields: a side with two conditions, refused as in serial
dir="$(newCase mixedSide)"
decomposeDict "$dir" 2 simple 1 2
(cd "$dir" && decomposePar -force > log.decomposePar 2>&1)
setEntry "$dir/processor1/0/h" boundaryField/upslope "{ type zeroGradient; }"
setEntry "$dir/processor1/0/U" boundaryField/upslope "{ type zeroGradient; }"
(cd "$dir" && runDecomposed 2 log.savageHutterFoam)
rc=$?
if [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q "different conditions on different processors" "$dir/log.savageHutterFoam"
then
    pass "xMin inflow on processor 0, transmissive on processor 1: refused"
else
    fail "xMin with two conditions across processors: exit $rc (124: hung; see $dir/log.savageHutterFoam)"
fi

#- firstPart <case> <n>: decomposePar, the decomposed run to 0.2
#  (log.first), endTime back to 0.4 for the restart; the run's status
firstPart()
{
    local rc
    setEntry "$1/system/controlDict" endTime 0.2
    (cd "$1" && decomposePar -force > log.decomposePar 2>&1 \
        && runDecomposed "$2" log.first)
    rc=$?
    setEntry "$1/system/controlDict" endTime 0.4
    return $rc
}

# A parallel restart: to 0.2, then on to 0.4 from latestTime
dir="$(newCase restart)"
decomposeDict "$dir" 4 hierarchical 2 2
firstPart "$dir" 4
rc1=$?
(cd "$dir" && runDecomposed 4 log.restart \
    && reconstructPar > log.reconstructPar 2>&1)
rc2=$?
if [ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] && grep -q "Create mesh for time = 0.2" "$dir/log.restart"
then
    sameAsSerial "$dir" "restart from 0.2 on 2 x 2"
else
    fail "restart on 2 x 2: exit $rc1, $rc2, or not from 0.2 (see $dir/log.*)"
fi

# The last time missing on one processor: all start from the one before
rm -rf "$dir"/processor1/0.4 "$dir"/0.2 "$dir"/0.4
(cd "$dir" && runDecomposed 4 log.agree \
    && reconstructPar > log.reconstructPar2 2>&1)
rc=$?
if [ $rc -eq 0 ] && grep -q "all start from 0.2" "$dir/log.agree"
then
    sameAsSerial "$dir" "restart with 0.4 missing on processor 1 (all from 0.2)"
else
    fail "restart with 0.4 missing on processor 1: exit $rc (see $dir/log.agree)"
fi

# A restart file missing on one processor (as the hint for an unreadable
# one suggests): every processor does without it, and the run goes on
dir="$(newCase missingPMax)"
decomposeDict "$dir" 2 simple 2 1
firstPart "$dir" 2
rm -f "$dir/processor1/0.2/pMax"
(cd "$dir" && runDecomposed 2 log.restart)
rc=$?
if [ $rc -eq 0 ] && grep -q "pMax is missing on other processors" "$dir/log.restart" \
    && [ -f "$dir/processor0/0.4/pMax" ] && [ -f "$dir/processor1/0.4/pMax" ]
then
    pass "restart with pMax missing on processor 1: both do without it and run to 0.4"
else
    fail "restart with pMax missing on processor 1: exit $rc (124: hung; see $dir/log.restart)"
fi

# SIGTERM to mpirun: every processor writes the same time and stops; a
# parallel restart from there reaches the serial run's state
dir="$(newCase sigterm)"
decomposeDict "$dir" 2 simple 2 1
setEntry "$dir/system/controlDict" endTime 1000
# Open MPI's mpirun, given SIGTERM, sends the processes SIGCONT at once,
# SIGTERM 1 s later (odls_base_sigkill_timeout) and SIGKILL 1 s after
# that, and meanwhile no longer drains their standard output.  Written
# every 0.2 s (every 13 steps, 4.5 ms of wall time, a steady-state line
# each), the solver filled that pipe within the first second, blocked on
# its log before the SIGTERM came and was killed without stopping (both
# CI runs of 2026-12-06; measured with a probe process: SIGCONT, +1.000 s
# SIGTERM, +2.000 s SIGKILL).  Written every 2 s, its log stays far below
# the pipe's 64 kB and the stop itself is what is tested.
sigInterval=2
setEntry "$dir/system/controlDict" writeInterval $sigInterval
(cd "$dir" && decomposePar -force > log.decomposePar 2>&1)
(cd "$dir" && exec mpirun --oversubscribe -np 2 savageHutterFoam -parallel -backend $backend -logInterval 0.1 > log.savageHutterFoam 2>&1) &
pid=$!
waitFor "$dir/log.savageHutterFoam" "^Time = " 60
sleep 0.5
kill -TERM $pid
wait $pid
rc=$?
t0="$(timeDirs "$dir/processor0" | tail -n 1)"
t1="$(timeDirs "$dir/processor1" | tail -n 1)"
if grep -q "Stopped by SIGTERM" "$dir/log.savageHutterFoam" && [ -n "$t0" ] \
    && [ "$t0" = "$t1" ] && complete "$dir/processor0" "$t0" && complete "$dir/processor1" "$t0"
then
    pass "SIGTERM to mpirun (exit $rc): both processors wrote $t0 whole and stopped"
    # On to the next write time but one, from latestTime, against the
    # serial run uninterrupted to it
    end="$(python3 -c "import math; print('%.9g' % ((math.floor($t0/$sigInterval + 1e-9) + 2)*$sigInterval))")"
    setEntry "$dir/system/controlDict" endTime "$end"
    (cd "$dir" && runDecomposed 2 log.restart \
        && reconstructPar -latestTime > log.reconstructPar 2>&1)
    rc=$?
    ser2="$work/serialTo$end"
    cp -r "$base" "$ser2"
    setEntry "$ser2/system/controlDict" endTime "$end"
    setEntry "$ser2/system/controlDict" writeInterval $sigInterval
    (cd "$ser2" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    if [ $rc -eq 0 ] && [ -d "$ser2/$end" ] && grep -q "Create mesh for time = $t0" "$dir/log.restart"
    then
        out="$(python3 "$project/bin/tools/compareDecomposed" \
            "restart from $t0 (SIGTERM) to $end" "$ser2" "$dir" "$end" "$fields" 2>&1)"
        tally $? "$out" "restart from $t0"
    else
        fail "restart from $t0 to $end after SIGTERM: exit $rc (see $dir/log.restart, $ser2)"
    fi
else
    fail "SIGTERM to mpirun: exit $rc, latest times '$t0' and '$t1' (see $dir/log.savageHutterFoam)"
fi

# foamToVTK on the decomposed case
dir="$work/restart"
if ! command -v foamToVTK > /dev/null
then
    skip "foamToVTK -parallel: no foamToVTK here (the GPU machine's bundle has none)"
elif (cd "$dir" && mpirun --oversubscribe -np 4 foamToVTK -parallel -latestTime > log.foamToVTK 2>&1) \
    && ls "$dir"/VTK/* > /dev/null 2>&1
then
    pass "foamToVTK -parallel -latestTime wrote $(ls "$dir"/VTK | head -3 | tr '\n' ' ')"
else
    fail "foamToVTK -parallel (see $dir/log.foamToVTK)"
fi

finish

#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The application's speed on the peers' common case (docs/design.md
#     section 4): a dam break 1.0 | 0.5 m at x = Lx/2 on a flat bed, 1 m cells,
#     walls on all sides, fully wet, t = 0...30 s, on 2048 x 2048 and
#     4096 x 2048 cells, run with -backend cuda in double and single
#     precision (called by tests/gpuCheck with the bundle of
#     bin/bundleOpenFOAM).  Shallow water as the Savage-Hutter equations
#     give it: eps = 1, K = 1 (isotropic), no friction (delta = 0), g =
#     9.81.  Written: the 0 and 30 s time directories, binary.
#     Prints, per run, the application's own figures (log): cell updates
#     per second over the time loop as a whole (set-up of the backend
#     excluded, the final write included) and over the stepping alone
#     (the line "Stepping:"), and the wall time of the run.
#
# Usage
#     gpuDamBreakRate.sh <project dir> <work dir> [sizes, e.g. 2048x2048]
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
sizes="${3:-2048x2048 4096x2048}"
. "$project/tests/application/bundleEnv.sh" || exit 1
status=0

for size in $sizes
do
    nx="${size%x*}"
    ny="${size#*x}"
    d="$work/dam$size/base"
    mkdir -p "$d"
    cp -r "$project/tutorials/damBreak"/{0.orig,constant,system} "$d"/
    (
        cd "$d" || exit 1
        rm -rf constant/polyMesh
        cat > system/blockMeshDict <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices
(
    (0 0 0) ($nx 0 0) ($nx $ny 0) (0 $ny 0)
    (0 0 1) ($nx 0 1) ($nx $ny 1) (0 $ny 1)
);
blocks ( hex (0 1 2 3 4 5 6 7) ($nx $ny 1) simpleGrading (1 1 1) );
boundary
(
    upslope   { type wall; faces ((0 4 7 3)); }
    downslope { type wall; faces ((1 2 6 5)); }
    sides     { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOD
        cat > system/setAvalancheFieldsDict <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }
h ( damBreak { position $((nx/2)); upstream 1.0; downstream 0.5; } );
EOD
        sed -i -e '/upslope\|downslope\|sides/s/zeroGradient; }/slip; }/' 0.orig/U
        setEntry constant/transportProperties inclination "constant 0"
        setEntry constant/transportProperties CoulombCoeffs/delta 0
        setEntry system/controlDict endTime 30
        setEntry system/controlDict writeInterval 30
        setEntry system/controlDict writeFormat binary
        runApplication blockMesh
        restore0Dir
        runApplication setAvalancheFields
    ) || { echo "FAIL  dam $size: case set-up failed"; status=1; continue; }
    for precision in double single
    do
        r="$work/dam$size/cuda-$precision"
        cp -r "$d" "$r"
        start=$(date +%s.%N)
        (cd "$r" && savageHutterFoam -backend cuda -precision "$precision" \
            > log.savageHutterFoam 2>&1) \
            || { echo "FAIL  dam $size $precision: solver failed"; \
                 tail -n 20 "$r/log.savageHutterFoam"; status=1; continue; }
        end=$(date +%s.%N)
        echo "      dam $size $precision: $(grep -E '^(Cell updates|Stepping|Time loop)' "$r/log.savageHutterFoam" | tr '\n' ' ')| run $(awk "BEGIN { print $end - $start }") s wall"
    done
done
[ $status = 0 ] && echo "gpuDamBreakRate: OK" || echo "gpuDamBreakRate: FAILED"
exit $status
#------------------------------------------------------------------------------

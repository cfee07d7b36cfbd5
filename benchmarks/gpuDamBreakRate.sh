#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The application's speed on the peers' common case (docs/design.md
#     section 4): a dam break 1.0 | 0.5 m at x = Lx/2 on a flat bed, 1 m cells,
#     walls on all sides, fully wet, t = 0...30 s, on 2048 x 2048 and
#     4096 x 2048 cells (benchmarks/damBreakCase.sh), run with -backend
#     cuda in double and single precision (called by tests/gpuCheck with
#     the bundle of bin/bundleOpenFOAM).  Written: the 0 and 30 s time
#     directories, binary.
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
. "$project/benchmarks/damBreakCase.sh"
status=0

for size in $sizes
do
    nx="${size%x*}"
    ny="${size#*x}"
    d="$work/dam$size/base"
    damBreakCase "$d" "$nx" "$ny" \
        || { echo "FAIL  dam $size: case set-up failed"; status=1; continue; }
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

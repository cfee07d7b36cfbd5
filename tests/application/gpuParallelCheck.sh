#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     On the GPU machine (tests/gpuCheck stage 6b), with the bundle of
#     bin/bundleOpenFOAM (the MPI build of libPstream, decomposePar,
#     reconstructPar) and that machine's Open MPI: the decomposed runs of
#     parallelTests.sh with -backend cuda (four decompositions, the
#     staircase refused, parallel restarts, SIGTERM to mpirun) against the
#     serial CPU run, bit for bit.  First says which Open MPI the bundle's
#     executables load (ldd) and the machine's version.
#
# Usage
#     gpuParallelCheck.sh <project dir> <work dir>
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
. "$project/tests/application/bundleEnv.sh" || exit 1

echo "Open MPI here: $(mpirun --version 2>&1 | head -n 1)"
echo "savageHutterFoam loads: $(ldd "$work/bundle/bin/savageHutterFoam" | grep -E 'libmpi|libPstream' | awk '{print $1, $3}' | tr '\n' ' ')"
echo "libPstream loads: $(ldd "$work/bundle/lib/libPstream.so" | grep -E 'libmpi' | awk '{print $1, $3}' | tr '\n' ' ')"
if ldd "$work/bundle/bin/savageHutterFoam" "$work/bundle/bin/decomposePar" | grep -q "not found"
then
    echo "FAIL  libraries not found:"
    ldd "$work/bundle/bin/savageHutterFoam" "$work/bundle/bin/decomposePar" | grep "not found"
    exit 1
fi
echo "GPUs: $(nvidia-smi -L 2>/dev/null | wc -l)"
SH_PARALLEL_BACKEND=cuda bash "$project/tests/application/parallelTests.sh" \
    "$project" "$work/parallel"
status=$?
[ $status = 0 ] && echo "gpuParallelCheck: OK" || echo "gpuParallelCheck: FAILED"
exit $status
#------------------------------------------------------------------------------

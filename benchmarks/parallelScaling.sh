#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The scaling tables of decomposed runs (docs/performance.md), run by
#     tests/gpuCheck stage 3b on the GPU machine: benchmarks/
#     parallelBenchmark on the wet dam break of docs/design.md section 4,
#       - GPU, double and float: strong scaling of 4320 x 2016 cells (the
#         8.7M of the single-GPU tables) on 1 and 2 ranks (2x1); weak
#         scaling, 4320 x 2016 cells per rank, 2 ranks split 2x1 and 1x2.
#         A GPU per rank; with one GPU the 2 ranks share it, which measures
#         what the exchange costs, not scaling;
#       - CPU ranks, double, 2048 x 1024 cells: 1 rank of all cores'
#         threads, then 2, 4, ..., all cores' ranks of one thread.
#     Prints one markdown table; rank 0 of each run prints its row.
#
# Usage
#     benchmarks/parallelScaling.sh <build dir> [steps]
#------------------------------------------------------------------------------
set -u
build="$1"
steps="${2:-200}"
pb="$build/benchmarks/parallelBenchmark"
[ -x "$pb" ] || { echo "parallelScaling: $pb missing (a build with MPI)" >&2; exit 1; }
mpiRun=(mpirun --allow-run-as-root --oversubscribe --bind-to none)
cores=$(nproc)
gpus=$(nvidia-smi -L 2>/dev/null | wc -l)
status=0
echo "GPUs: $gpus, cores: $cores"
echo
first=-header
for p in double float
do
    for n in 1 2
    do
        "${mpiRun[@]}" -np $n "$pb" -backend cuda -precision $p \
            -nx 4320 -ny 2016 -steps "$steps" $first || status=1
        first=""
    done
    "${mpiRun[@]}" -np 2 "$pb" -backend cuda -precision $p \
        -weak 4320 2016 -steps "$steps" || status=1
    "${mpiRun[@]}" -np 2 "$pb" -backend cuda -precision $p \
        -weak 4320 2016 -split 1 2 -steps "$steps" || status=1
done
for n in 1 2 4 8 $cores
do
    [ "$n" -le "$cores" ] || continue
    OMP_NUM_THREADS=$((cores/n)) "${mpiRun[@]}" -np $n -x OMP_NUM_THREADS \
        "$pb" -backend cpu -nx 2048 -ny 1024 -steps 20 || status=1
done
exit $status
#------------------------------------------------------------------------------

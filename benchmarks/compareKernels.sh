#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Whether a change kept the kernels' speed: builds shBenchmark from this
#     tree and from another (an earlier commit's source, e.g. from
#     git archive), both with the same compilers and flags, then runs the
#     two alternately, rounds times, so that a drift of the machine shows
#     in both.  Prints each run's table, labelled.  Meant for the GPU
#     machine (docs/performance.md says what was compared).
#
# Usage
#     benchmarks/compareKernels.sh <other tree> <work dir> [rounds]
#         [-- shBenchmark options]   (default: -meshes 4,8 -large 48
#                                     -largeTime 1 -noCpu)
#------------------------------------------------------------------------------
set -uo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
other="$(cd "$1" && pwd)" || exit 2
work="$2"
rounds="${3:-2}"
shift 3 2>/dev/null || shift $#
[ "${1:-}" = "--" ] && shift
args=("$@")
[ ${#args[@]} -eq 0 ] && args=(-meshes 4,8 -large 48 -largeTime 1 -noCpu)
mkdir -p "$work"
nvcc=/usr/local/cuda/bin/nvcc
command -v "$nvcc" > /dev/null || nvcc="$(command -v nvcc)"

build()
{
    cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_CUDA_COMPILER="$nvcc" -DSH_OPENFOAM=OFF -DSH_MPI=OFF \
        > "$2.log" 2>&1 \
    && cmake --build "$2" -j "$(( $(nproc) / 2 ))" --target shBenchmark \
        >> "$2.log" 2>&1
}
build "$here" "$work/this" & pThis=$!
build "$other" "$work/other" & pOther=$!
ok=true
wait $pThis || { echo "compareKernels: build of this tree failed ($work/this.log)"; ok=false; }
wait $pOther || { echo "compareKernels: build of $other failed ($work/other.log)"; ok=false; }
$ok || exit 1

for r in $(seq "$rounds")
do
    for which in other this
    do
        echo "== round $r: $which ($([ $which = this ] && echo "$here" || echo "$other"))"
        "$work/$which/benchmarks/shBenchmark" "${args[@]}" \
            -out "$work/$which.$r.md" > "$work/$which.$r.log" 2>&1 \
            || echo "compareKernels: shBenchmark failed ($work/$which.$r.log)"
        grep -E '^\| (double|float) ' "$work/$which.$r.md"
    done
done

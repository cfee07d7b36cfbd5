#!/bin/bash
#------------------------------------------------------------------------------
# Where the plan grid's step spends its time against the slope step's
# (issue 24 item 7): ncu on three steps of shBenchmark's wet plane
# (-profileCase wet, slope coordinates) and of its plan counterpart
# (-profileCase plan: the same plane as a DEM with bumps, benchmarks/
# shBenchmark.C "plan wet"), both precisions, the step kernels only.
# For the GPU machine (device tool), one call:
#   benchmarks/planProfile.sh [k]        (k: shBenchmark -profile, default 96)
# Results under $OUT (or build-plan/out): planProfile.md (per kernel:
# duration, warp instructions, SM and DRAM throughput, DRAM bytes,
# occupancy, registers,
# cache hit rates, cycles per issued instruction), and the whole reports
# ncu-<case>-<precision>.txt (with the warp state statistics).
#------------------------------------------------------------------------------
set -uo pipefail
cd "$(dirname "$0")/.."
out="${OUT:-build-plan/out}"
mkdir -p "$out"
k="${1:-96}"
ncuBin=$(command -v ncu || ls /usr/local/cuda/bin/ncu 2>/dev/null)
[ -n "$ncuBin" ] || { echo "planProfile: no ncu"; exit 1; }
if ! {
    cmake -S . -B build-plan -DCMAKE_BUILD_TYPE=Release -DSH_OPENFOAM=OFF \
        -DSH_MPI=OFF -DCMAKE_CUDA_ARCHITECTURES=90 \
        -DCMAKE_CUDA_COMPILER=/usr/local/cuda/bin/nvcc &&
    cmake --build build-plan -j "$(nproc)" --target shBenchmark
} > "$out/build.log" 2>&1; then
    tail -n 20 "$out/build.log"; echo "planProfile: build FAILED"; exit 1
fi
for c in wet plan; do
    for p in double float; do
        "$ncuBin" --section SpeedOfLight --section Occupancy \
            --section LaunchStats --section WarpStateStats \
            --section MemoryWorkloadAnalysis \
            --metrics dram__bytes.sum,smsp__inst_executed.sum \
            -k 'regex:(predictor|flux|corrector|finish)Kernel' -c 8 \
            build-plan/benchmarks/shBenchmark -profile "$k" \
            -profileCase "$c" -precision "$p" \
            > "$out/ncu-$c-$p.txt" 2>&1 || echo "ncu ($c, $p) failed"
    done
done
# The lines of each kernel's report that the tables of docs/performance.md
# are made from
for f in "$out"/ncu-*.txt; do
    echo "## ${f##*/}"
    grep -E "Kernel<|Kernel\(|smsp__inst_executed.sum|Duration|Compute \(SM\) Throughput|DRAM Throughput|dram__bytes.sum|Achieved Occupancy|Registers Per Thread|Warp Cycles Per Issued Instruction|Theoretical Occupancy|Block Limit Registers|L1/TEX Hit Rate|L2 Hit Rate|Mem Busy|Max Bandwidth|Issue Slots Busy|Executed Ipc Active" "$f" \
        | sed -E 's/\(Model.*//'
done > "$out/planProfile.md"
cat "$out/planProfile.md" | head -n 400

#!/bin/bash
#------------------------------------------------------------------------------
# The plan grid's kernels under several register caps (stepKernels.H
# SH_PLAN_*_BLOCKS: resident blocks per SM the predictor, flux and
# corrector kernels are compiled for), each against the slope mode on the
# same mesh: shBenchmark's "plan wet" table (cost per wet cell-step of the
# plan mode relative to the slope mode), and ptxas's registers and spills.
# For the GPU machine (device tool), one call:
#   benchmarks/planLaunchBounds.sh [variant ...]
# a variant is "P/F/C" (predictor/flux/corrector blocks), default
# "4/3/4 3/2/3 2/2/2 2/2/3".  Results under $OUT (or build-plan/out):
# planLaunchBounds.md (the tables), build.log.
#------------------------------------------------------------------------------
set -uo pipefail
cd "$(dirname "$0")/.."
out="${OUT:-build-plan/out}"
mkdir -p "$out"
variants=("$@")
[ ${#variants[@]} -eq 0 ] && variants=(4/3/4 3/2/3 2/2/2 2/2/3)
bench=(-meshes 0 -large 96 -largeTime 0.02 -noCpu)
{
    nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
    echo "commit: ${SH_COMMIT:-unknown}; shBenchmark ${bench[*]}"
} | tee "$out/planLaunchBounds.md"
for v in "${variants[@]}"; do
    IFS=/ read -r P F C <<< "$v"
    flags="-DSH_PLAN_PREDICTOR_BLOCKS=$P -DSH_PLAN_FLUX_BLOCKS=$F -DSH_PLAN_CORRECTOR_BLOCKS=$C -Xptxas -v"
    if ! {
        cmake -S . -B build-plan -DCMAKE_BUILD_TYPE=Release -DSH_OPENFOAM=OFF \
            -DSH_MPI=OFF -DCMAKE_CUDA_ARCHITECTURES=90 \
            -DCMAKE_CUDA_COMPILER=/usr/local/cuda/bin/nvcc \
            "-DCMAKE_CUDA_FLAGS=$flags" &&
        cmake --build build-plan -j "$(nproc)" --target shBenchmark
    } > "$out/build-$P$F$C.log" 2>&1; then
        tail -n 20 "$out/build-$P$F$C.log"; echo "build of $v FAILED"; continue
    fi
    {
        echo; echo "## plan blocks predictor/flux/corrector = $v"
        # registers and spills of the stepping kernels (ptxas -v)
        python3 - "$out/build-$P$F$C.log" <<'PY'
import re, sys
cur = None
for l in open(sys.argv[1]):
    m = re.search(r"Compiling entry function '\S*?(predictor|flux|corrector)KernelI([df])Lb0ENS_\d+(Plan|Slope)Stages", l)
    if m:
        cur = m.groups(); continue
    if cur is None:
        continue
    s = re.search(r"(\d+) bytes spill stores, (\d+) bytes spill loads", l)
    if s:
        spill = s.groups()
    r = re.search(r"Used (\d+) registers", l)
    if r:
        print("    %-10s %s %-5s %4s registers, spill stores %5s B, loads %5s B"
              % (cur[0], "double" if cur[1] == "d" else "float ", cur[2], r.group(1), *spill))
        cur = None
PY
        build-plan/benchmarks/shBenchmark "${bench[@]}" \
            > "$out/bench-$P$F$C.log" 2>&1
        grep -i -E "plan|slope|wet|precision|mesh" "$out/bench-$P$F$C.log" |
            head -n 40
    } | tee -a "$out/planLaunchBounds.md"
done

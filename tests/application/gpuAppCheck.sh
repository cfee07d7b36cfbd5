#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The OpenFOAM application on the GPU machine (called by tests/gpuCheck
#     when external/bundle.tar.xz, made by bin/bundleOpenFOAM, is there;
#     it is unpacked into the work directory and put on the paths):
#     each case below runs with -backend cpu and -backend cuda from the same
#     prepared mesh and fields, and every field written at every time must
#     be byte-identical, in double and in single precision (both backends
#     run the same operations in the same order; the CUDA build disables
#     FMA contraction).  On a difference it prints the relative RMS
#     difference of h at the last time.  Prints the cell-update rates.
#
# Usage
#     gpuAppCheck.sh <project dir> <work dir>
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
cd "$project" || exit 1
rm -rf "$work"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
tar -xJf external/bundle.tar.xz -C "$work" || exit 1
export PATH="$work/bundle/bin:$PATH"
export LD_LIBRARY_PATH="$work/bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export WM_PROJECT_DIR="$work/bundle/OpenFOAM"
. bin/tools/RunFunctions
status=0

#- prepare <name> <tutorial> <nx> <ny> <endTime> <writeInterval> [entry value]...
prepare()
{
    local name="$1" tut="$2" nx="$3" ny="$4" end="$5" wi="$6"
    shift 6
    local d="$work/$name/base"
    mkdir -p "$d"
    cp -r "$project/tutorials/$tut"/{0.orig,constant,system} "$d"/
    (
        cd "$d" || exit 1
        rm -rf constant/polyMesh
        setBlockCells "$nx" "$ny"
        setEntry system/controlDict endTime "$end"
        setEntry system/controlDict writeInterval "$wi"
        setEntry system/controlDict writeFormat binary
        while [ $# -gt 0 ]
        do
            setEntry "$1" "$2" "$3"
            shift 3
        done
        runApplication blockMesh
        restore0Dir
        runApplication setAvalancheFields
    )
}

#- compare <name> <precision>: run cpu and cuda copies, compare the files
compare()
{
    local name="$1" precision="$2"
    local b
    for b in cpu cuda
    do
        rm -rf "$work/$name/$b-$precision"
        cp -r "$work/$name/base" "$work/$name/$b-$precision"
        (cd "$work/$name/$b-$precision" \
         && savageHutterFoam -backend "$b" -precision "$precision" \
            > log.savageHutterFoam 2>&1) \
            || { echo "FAIL  $name $b $precision: solver failed"; \
                 tail -n 20 "$work/$name/$b-$precision/log.savageHutterFoam"; \
                 status=1; return; }
        echo "      $name $b $precision: $(grep -m1 'Backend:' \
            "$work/$name/$b-$precision/log.savageHutterFoam") |" \
            "$(grep 'Cell updates' "$work/$name/$b-$precision/log.savageHutterFoam")" \
            "| $(grep 'Time loop:' "$work/$name/$b-$precision/log.savageHutterFoam" | cut -d'(' -f1)"
    done
    local cpu="$work/$name/cpu-$precision" gpu="$work/$name/cuda-$precision"
    local times
    times="$(cd "$cpu" && ls -d [0-9]* | grep -E '^[0-9.e+-]+$' | grep -v '^0$' | sort -g)"
    local nFiles=0 nDiff=0 t f
    for t in $times
    do
        for f in h U hU regime
        do
            nFiles=$((nFiles + 1))
            if [ ! -f "$cpu/$t/$f" ] || ! cmp -s "$cpu/$t/$f" "$gpu/$t/$f"
            then
                nDiff=$((nDiff + 1))
                echo "      differs or missing: $t/$f"
            fi
        done
    done
    if [ "$nDiff" -eq 0 ] && [ "$nFiles" -gt 0 ]
    then
        echo "PASS  $name $precision: cuda = cpu, $nFiles field files identical ($(echo $times | wc -w) times)"
        return
    fi
    echo "FAIL  $name $precision: $nDiff of $nFiles field files differ"
    status=1
    local last
    last="$(echo "$times" | tail -n1)"
    python3 - "$cpu/$last/h" "$gpu/$last/h" <<'PY'
import math, re, struct, sys
def read(p):
    d = open(p, "rb").read()
    m = re.search(rb"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", d)
    n = int(m.group(1))
    return struct.unpack("<%dd" % n, d[m.end():m.end() + 8 * n])
a, b = read(sys.argv[1]), read(sys.argv[2])
num = math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))
den = math.sqrt(sum(x * x for x in a))
print("      relative RMS difference of h at the last time: %.3e" % (num / den))
PY
}

fv=system/fvSolution
prepare damBreak damBreak 128 16 0.5 0.1
compare damBreak double
compare damBreak single

prepare collapsingPile staticPile 128 128 1 0.25 \
    constant/transportProperties phi 20 \
    constant/transportProperties CoulombCoeffs/delta 20
compare collapsingPile double
compare collapsingPile single

prepare inclinedPlane inclinedPlane 480 224 24 6
compare inclinedPlane double
compare inclinedPlane single

echo
[ $status -eq 0 ] && echo "gpuAppCheck: OK" || echo "gpuAppCheck: FAILED"
exit $status

#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Issue 27's targets on the peers' common case (docs/design.md section
#     4, benchmarks/damBreakCase.sh): the dam break 1.0 | 0.5 m, 1 m cells,
#     walls, fully wet, to t = 30 s, with the application, in double and
#     single precision, against the first-order GPU flood code's figures
#     measured on one H200 (issue 27): 0.217 s (double) and 0.144 s
#     (single) for the 30 s on 2048^2.
#     Per precision:
#       1. maxCo 0.4 (the tutorial's) and the larger values of -co: the
#          steps, the stepping time (the log's "Stepping:" line), the time
#          loop with the one final write, and the L1 error of h at 30 s
#          against the exact solution (benchmarks/damBreakL1.py); the
#          accuracy of a larger maxCo is the tutorial's when its L1 is not
#          above the one at 0.4 (docs/performance.md, "Largest stable time
#          step": at a bore the error falls with maxCo; the default list
#          stops at 0.8, where smooth flow's error is still within a few
#          per cent of 0.4's);
#       2. at the largest such maxCo: the stepping against the other
#          code's wall time; the time loop against 1.5 x (stepping + the
#          disk's time for the bytes of the 30 s directory, dd with fsync
#          of the same size in the same call);
#       3. the same with writeInterval 1 (30 writes): the time loop against
#          1.2 x max(stepping, writing alone), writing alone the writes'
#          time on the writer thread as the log's "Writes:" line gives it
#          (and, beside it, dd's time for the same bytes).
#     Prints a markdown table (stdout) and keeps the logs under <work>.
#
# Usage
#     timeToSolution.sh <project dir> <work dir> [-size 2048x2048]
#         [-backend cuda] [-co "0.4 0.6 0.8"]
#     The application from external/bundle.tar.xz when it is there and no
#     savageHutterFoam is on the path (the GPU machine), else the one on
#     the path (the development machine, for a small -size with -backend cpu).
#------------------------------------------------------------------------------
set -u
project="$(cd "$1" && pwd)"
work="$2"
shift 2
size=2048x2048
backend=cuda
coList="0.4 0.6 0.8"
while [ $# -gt 0 ]; do
    case "$1" in
        -size) size="$2"; shift ;;
        -backend) backend="$2"; shift ;;
        -co) coList="$2"; shift ;;
        *) echo "timeToSolution: unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
if ! command -v savageHutterFoam > /dev/null && [ -f "$project/external/bundle.tar.xz" ]
then
    . "$project/tests/application/bundleEnv.sh" || exit 1
else
    rm -rf "$work"; mkdir -p "$work"; work="$(cd "$work" && pwd)"
    . "$project/bin/tools/RunFunctions"
fi
. "$project/benchmarks/damBreakCase.sh"
nx="${size%x*}"
ny="${size#*x}"
status=0

base="$work/base"
damBreakCase "$base" "$nx" "$ny" > "$work/setup.log" 2>&1 \
    || { echo "timeToSolution: case set-up failed ($work/setup.log)"; exit 1; }

# The log's figures: steps, stepping [s], time loop [s], writer's time [s]
figures()
{
    local log="$1"
    local steps stepping loop writes
    steps=$(sed -n 's/^Time loop: \([0-9]*\) steps.*/\1/p' "$log")
    loop=$(sed -n 's/^Time loop: .* in \([0-9.e+-]*\) s wall.*/\1/p' "$log")
    stepping=$(sed -n 's/^Stepping: .*(\([0-9.e+-]*\) s wall stepping.*/\1/p' "$log")
    writes=$(sed -n 's/^Writes: [0-9]* in \([0-9][0-9.e+-]*\) s .*/\1/p' "$log" | head -n 1)
    echo "${steps:-?} ${stepping:-?} ${loop:-?} ${writes:--}"
}

# dd with fsync of N bytes in the work directory: seconds
ddSeconds()
{
    local bytes="$1" mb s e
    mb=$(( (bytes + 1048575)/1048576 ))
    s=$(date +%s.%N)
    dd if=/dev/zero of="$work/dd.bin" bs=1M count="$mb" conv=fsync 2> /dev/null
    e=$(date +%s.%N)
    rm -f "$work/dd.bin"
    awk "BEGIN { print $e - $s }"
}

# One run: precision, maxCo, writeInterval; prints its directory
runCase()
{
    local p="$1" co="$2" wi="$3"
    local r="$work/$p-co$co-w$wi"
    rm -rf "$r"
    cp -r "$base" "$r"
    (
        cd "$r" || exit 1
        setEntry system/controlDict maxCo "$co"
        setEntry system/controlDict writeInterval "$wi"
        savageHutterFoam -backend "$backend" -precision "$p" \
            > log.savageHutterFoam 2>&1
    ) || { echo "timeToSolution: $p maxCo $co writeInterval $wi failed ($r/log.savageHutterFoam)" >&2; return 1; }
    echo "$r"
}

declare -A peer=([double]=0.217 [single]=0.144)
echo "## Time to solution, the peers' dam break ${nx}x${ny}, -backend $backend"
echo
echo "| precision | maxCo | steps | stepping [s] | time loop, 1 write [s] | L1 of h at 30 s [m²] |"
echo "|---|---:|---:|---:|---:|---:|"
declare -A chosen l1At04
for p in double single; do
    best=""
    for co in $coList; do
        r=$(runCase "$p" "$co" 30) || { status=1; continue; }
        read -r steps stepping loop writes <<< "$(figures "$r/log.savageHutterFoam")"
        l1=$(python3 "$project/benchmarks/damBreakL1.py" "$r/30/h" "$nx" "$ny" \
            $((nx/2)) 1.0 0.5 30 | awk '{print $2}')
        echo "| $p | $co | $steps | $stepping | $loop | $l1 |"
        [ "$co" = 0.4 ] && l1At04[$p]=$l1
        if awk "BEGIN { exit !($l1 <= ${l1At04[$p]:-0}) }"; then
            best="$co"
        fi
    done
    chosen[$p]="$best"
done

echo
echo "Targets at the largest maxCo whose L1 is not above maxCo 0.4's:"
echo
echo "| precision | maxCo | target | ours [s] | bound [s] | met |"
echo "|---|---:|---|---:|---:|---|"
verdict()
{
    awk "BEGIN { if ($1 < $2) print \"yes\"; else printf \"no: %.2fx the bound\", $1/$2 }"
}
for p in double single; do
    co="${chosen[$p]}"
    [ -n "$co" ] || { echo "| $p | - | no maxCo ran |  |  | no |"; status=1; continue; }
    r="$work/$p-co$co-w30"
    read -r steps stepping loop writes <<< "$(figures "$r/log.savageHutterFoam")"
    bytes=$(du -sb "$r/30" | cut -f1)
    dd1=$(ddSeconds "$bytes")
    echo "| $p | $co | stepping to 30 s < the other code's wall time | $stepping | ${peer[$p]} | $(verdict "$stepping" "${peer[$p]}") |"
    bound=$(awk "BEGIN { print 1.5*($stepping + $dd1) }")
    echo "| $p | $co | time loop with the final write ($((bytes/1000000)) MB; dd $dd1 s) < 1.5 (stepping + dd) | $loop | $bound | $(verdict "$loop" "$bound") |"
    r30=$(runCase "$p" "$co" 1) || { status=1; continue; }
    read -r steps30 stepping30 loop30 writes30 <<< "$(figures "$r30/log.savageHutterFoam")"
    bytes30=$(du -sb --exclude=0 "$r30"/[0-9]* 2>/dev/null | awk '$2 !~ /\/0$/ {s += $1} END {print s}')
    dd30=$(ddSeconds "$bytes30")
    alone="$writes30"
    [ "$alone" = "-" ] && alone="$dd30"
    bound30=$(awk "BEGIN { a = $stepping30; b = $alone; print 1.2*(a > b ? a : b) }")
    echo "| $p | $co | 30 writes ($((bytes30/1000000)) MB; writer $writes30 s, dd $dd30 s): time loop < 1.2 max(stepping $stepping30, writing $alone) | $loop30 | $bound30 | $(verdict "$loop30" "$bound30") |"
done
exit $status

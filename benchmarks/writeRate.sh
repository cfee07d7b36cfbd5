#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The write path's speed (issue 27 item 1): the dam break of
#     benchmarks/damBreakCase.sh (1 m cells, walls, fully wet, binary) on NX x NY
#     cells, written every writeInterval s to endTime so that several
#     writes happen (h, U, hU, zb, regime, hMax, UMax, tArrival), run with
#     the writes overlapped with the steps and again with them on the
#     solver's thread (SH_OVERLAP_WRITES=0).  Prints per run:
#       stepping     wall seconds stepping (the "Stepping:" line)
#       loop         wall seconds of the time loop ("Time loop:")
#       stall/write  seconds per write on the solver's thread: the copy
#                    from the solver, the fields filled and checked,
#                    waiting for the write before, the hand-off ("s in
#                    write on the solver's thread")
#       write/write  seconds per write of the write itself (Time's writer
#                    into the staging directory, fsync, renames), on the
#                    writer thread or the solver's, and its fsync part
#       dd           seconds dd takes for the same bytes per write, in the
#                    case directory, dd if=/dev/zero bs=1M conv=fsync,
#                    in the same call, and the write path's rate as a
#                    fraction of dd's
#
# Usage
#     writeRate.sh <project dir> <work dir> [NXxNY] [backend] [endTime]
#                  [writeInterval]
#     e.g. writeRate.sh . /tmp/wr 1024x1024 cpu 2 0.5
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
size="${3:-1024x1024}"
backend="${4:-cpu}"
endTime="${5:-2}"
writeInterval="${6:-0.5}"
nx="${size%x*}"
ny="${size#*x}"
. "$project/bin/tools/RunFunctions"

. "$project/benchmarks/damBreakCase.sh"

d="$work/dam$size/base"
rm -rf "$work/dam$size"
damBreakCase "$d" "$nx" "$ny" > /dev/null 2>&1 \
    && setEntry "$d/system/controlDict" endTime "$endTime" \
    && setEntry "$d/system/controlDict" writeInterval "$writeInterval" \
    || { echo "FAIL  case set-up (see $d)"; exit 1; }

#- num <log> <regex>: the first number after the regex on its line
num()
{
    grep -oE "$2 *[0-9.e+-]+" "$1" | tail -n1 | grep -oE '[0-9.e+-]+$'
}

status=0
for mode in overlapped sync
do
    r="$work/dam$size/$mode"
    cp -r "$d" "$r"
    if [ $mode = sync ]; then export SH_OVERLAP_WRITES=0; else unset SH_OVERLAP_WRITES; fi
    (cd "$r" && savageHutterFoam -backend "$backend" > log.savageHutterFoam 2>&1) \
        || { echo "FAIL  $mode: solver failed (see $r)"; status=1; continue; }
    unset SH_OVERLAP_WRITES
    log="$r/log.savageHutterFoam"
    line=$(grep '^Writes: ' "$log")
    n=$(echo "$line" | sed -E 's/^Writes: ([0-9]+) .*/\1/')
    writing=$(echo "$line" | sed -E 's/^Writes: [0-9]+ in ([0-9.]+) s.*/\1/')
    mb=$(echo "$line" | grep -oE '[0-9.]+ MB' | cut -d' ' -f1)
    fsync=$(echo "$line" | grep -oE '[0-9.]+ s of it fsync' | cut -d' ' -f1)
    called=$(echo "$line" | grep -oE '[0-9.]+ s in write on' | cut -d' ' -f1)
    stepping=$(grep -oE '\(([0-9.]+) s wall stepping' "$log" | grep -oE '[0-9.]+')
    loop=$(grep -oE '^Time loop: .* in [0-9.]+ s wall' "$log" | grep -oE '[0-9.]+ s wall' | cut -d' ' -f1)
    # dd for the bytes of one write, in the case directory, flushed
    perWrite=$(python3 -c "print(max(1, round($mb/$n)))")
    start=$(date +%s.%N)
    dd if=/dev/zero of="$r/dd.bin" bs=1M count="$perWrite" conv=fsync 2> /dev/null
    end=$(date +%s.%N)
    rm -f "$r/dd.bin"
    python3 - "$mode" "$size" "$n" "$mb" "$stepping" "$loop" "$called" \
        "$writing" "$fsync" "$start" "$end" "$perWrite" <<'EOF'
import sys
mode, size, n, mb, stepping, loop, called, writing, fsync, t0, t1, ddMB = sys.argv[1:]
n = int(n); mb = float(mb); dd = float(t1) - float(t0)
perWrite = float(writing)/n
print(f"{mode:10s} {size}: {n} writes of {mb/n:.1f} MB; stepping {float(stepping):.2f} s,"
      f" loop {float(loop):.2f} s; stall/write {float(called)/n:.3f} s;"
      f" write/write {perWrite:.3f} s (fsync {float(fsync)/n:.3f} s);"
      f" dd {dd:.3f} s for {ddMB} MB: write path at"
      f" {100*(mb/n/perWrite)/(float(ddMB)/dd):.0f} % of dd's rate")
EOF
done
exit $status

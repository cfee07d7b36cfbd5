#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Issue 27's targets (item 5) in one markdown table, from the two files
#     one `tests/gpuCheck -targets` call writes: timeToSolution.md
#     (benchmarks/timeToSolution.sh: the peers' dam break, its L1 table and
#     its target rows) and ensembleBenchmark.md (the 1000-member ensemble,
#     double and single).  Each row: the target, the other code's figure
#     where the issue gives one, ours, the bound, met or by how much it is
#     missed, and for a missed ensemble target the share of the batched
#     cell updates that were of wet cells (what the rest of the time went
#     to: dry cells of active tiles, docs/performance.md "What a finer skip
#     could gain").  The time-to-solution rows name their own timings
#     (stepping, the writer thread, dd) in the target's text.
#
# Usage
#     targetsTable.sh <timeToSolution.md> <ensembleBenchmark.md>
#     Exit status 1 when a file is missing or holds no rows.
#------------------------------------------------------------------------------
tts="$1"
ens="$2"
status=0

echo "## Issue 27's targets (item 5), one call"
echo
echo "The other code: the first-order GPU flood code of issue 27 (built from"
echo "its source, one H200, its time loop): 0.217 s (double) and 0.144 s"
echo "(single) for the 30 s of the peers' dam break on 2048²."
echo
if [ -s "$tts" ]; then
    # The L1 table of h at 30 s (the accuracy of each maxCo)
    sed -n '/^| precision | maxCo | steps/,/^$/p' "$tts"
else
    echo "(no timeToSolution.md: the time-to-solution rows are missing)"
    echo
    status=1
fi
echo "| precision | maxCo | target | the other code | ours | bound | met |"
echo "|---|---:|---|---:|---:|---:|---|"
if [ -s "$tts" ]; then
    rows=$(sed -n '/^Targets at/,$p' "$tts" | grep -E '^\| (double|single) ')
    [ -n "$rows" ] || status=1
    # | p | co | target | ours | bound | met |: the other code's figure
    # beside the stepping rows (the issue's)
    awk -F'|' 'function trim(x) { gsub(/^ +| +$/, "", x); return x }
    {
        p = trim($2)
        peer = "–"
        if ($4 ~ /other code/) peer = (p == "double" ? "0.217 s" : "0.144 s")
        printf "| %s | %s | %s | %s | %s s | %s s | %s |\n", p, trim($3), trim($4), peer, trim($5), trim($6), trim($7)
    }' <<< "$rows"
fi
if [ -s "$ens" ]; then
    # ensembleBenchmark's columns: backend, members, mesh, precision, t,
    # steps, batched wall, batched set-up, sequential wall, sequential
    # set-up, speed-up, cell updates/s, wet cell updates/s, bit for bit
    awk -F'|' 'function trim(x) { gsub(/^ +| +$/, "", x); return x }
    $3 ~ /1000/ && $2 ~ /cuda/ {
        p = trim($5)
        x = $12; gsub(/[ ~]/, "", x)
        all = $13 + 0; wet = $14 + 0
        met = (x + 0 >= 50) ? "yes" \
            : sprintf("no: %.2fx the target; %.0f %% of the batched cell updates were of wet cells, the rest dry cells of active tiles (performance.md, \"What a finer skip could gain\")", x/50, 100*wet/all)
        printf "| %s | – | ensemble speed-up >= 50x (1000 members of section 5.3, %s cells, t = %s; batched against one after the other, bit for bit: %s) | – | %.1fx | 50x | %s |\n", p, trim($4), trim($6), trim($15), x, met
        n++
    } END { exit n ? 0 : 1 }' "$ens" || status=1
else
    status=1
fi
exit $status

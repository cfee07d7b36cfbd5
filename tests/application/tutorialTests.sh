#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Runs every tutorial shortened (SH_SHORT=1, each Allrun says how), in
#     the style of OpenFOAM's Alltest, in copies under the work directory:
#     a tutorial fails when its Allrun fails, a log holds "FOAM FATAL", a
#     savageHutterFoam log lacks its final "End", or its plot script's own
#     checks (--check: the paper's tables, volume, h >= 0) fail, or a film
#     runs away (filmCheck.py: at the last time and in the peak maps no
#     cell with h > 1e-4 m faster than its flow's |u| + 2 sqrt(g h)).  A
#     tutorial with an Allrun-parallel is also run decomposed, shortened
#     (2 processes), and fails unless its fields are the serial run's
#     (log.compareDecomposed); without mpirun that run is skipped.
#     A tutorial holding a file notTested is skipped (its first line says
#     why) unless named on the command line.
#     Prints one line per run and "N passed, M failed, K skipped".
#
# Usage
#     tutorialTests.sh <project dir> <work dir> [tutorial ...]
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
shift 2
. "$project/etc/bashrc"

tutorials=("$@")
if [ ${#tutorials[@]} -eq 0 ]
then
    for d in "$project"/tutorials/*/Allrun
    do
        # A tutorial with a file notTested waits for what it needs
        [ -e "$(dirname "$d")/notTested" ] && continue
        tutorials+=("$(basename "$(dirname "$d")")")
    done
fi

passed=0
failed=0
skipped=0
for d in "$project"/tutorials/*/notTested
do
    [ -e "$d" ] || continue
    echo "SKIP  $(basename "$(dirname "$d")") (notTested: $(head -n1 "$d"))"
    skipped=$((skipped + 1))
done

#- verdict <run> <what it did> <its log>: PASS, or FAIL with $problems and
#  the log's end; counted
verdict()
{
    if [ -z "$problems" ]
    then
        echo "PASS  $1 ($2)"
        passed=$((passed + 1))
    else
        echo "FAIL  $1:$problems (see $3)"
        tail -n 20 "$3"
        failed=$((failed + 1))
    fi
    echo
}
rm -rf "$work"
mkdir -p "$work"
for t in "${tutorials[@]}"
do
    dir="$work/$t"
    cp -r "$project/tutorials/$t" "$dir"
    (cd "$dir" && ./Allclean > /dev/null 2>&1)
    problems=""
    if ! (cd "$dir" && SH_SHORT=1 ./Allrun > "$work/$t.Allrun.log" 2>&1)
    then
        problems="$problems Allrun failed;"
    fi
    fatal="$(grep -rl "FOAM FATAL" --include='log.*' "$dir")"
    [ -z "$fatal" ] || problems="$problems FOAM FATAL in $fatal;"
    nSolver=0
    while IFS= read -r log
    do
        nSolver=$((nSolver + 1))
        grep -q "^End" "$log" || problems="$problems no End in $log;"
    done < <(find "$dir" -name 'log.savageHutterFoam*')
    [ "$nSolver" -gt 0 ] || problems="$problems savageHutterFoam never ran;"
    if ! (cd "$dir" && ./plot --check > "$work/$t.check.log" 2>&1)
    then
        problems="$problems plot --check failed;"
    fi
    cat "$work/$t.check.log"
    # No runaway films: at the last time and in the peak maps no thin cell
    # faster than its flow allows (filmCheck.py)
    if ! "$project/tests/application/filmCheck.py" "$dir" > "$work/$t.films.log" 2>&1
    then
        problems="$problems a film runs away (filmCheck.py);"
    fi
    grep -v "^PASS" "$work/$t.films.log"
    echo "    filmCheck: $(grep -c "^PASS" "$work/$t.films.log") checks passed"
    verdict "$t" "$nSolver solver runs" "$work/$t.Allrun.log"

    # Its decomposed run, shortened (2 processes, checked against the
    # serial run cell by cell)
    [ -x "$project/tutorials/$t/Allrun-parallel" ] || continue
    if ! command -v mpirun > /dev/null
    then
        echo "SKIP  $t/Allrun-parallel: no mpirun (bin/installDependencies installs openmpi-bin)"
        skipped=$((skipped + 1))
        continue
    fi
    dir="$work/$t-parallel"
    cp -r "$project/tutorials/$t" "$dir"
    (cd "$dir" && ./Allclean > /dev/null 2>&1)
    problems=""
    if ! (cd "$dir" && SH_SHORT=1 ./Allrun-parallel > "$work/$t-parallel.Allrun.log" 2>&1)
    then
        problems="$problems Allrun-parallel failed;"
    fi
    fatal="$(grep -rl "FOAM FATAL" --include='log.*' "$dir")"
    [ -z "$fatal" ] || problems="$problems FOAM FATAL in $fatal;"
    compare="$dir/log.compareDecomposed"
    if [ ! -f "$compare" ] || grep -q "^FAIL" "$compare" || ! grep -q "^PASS" "$compare"
    then
        problems="$problems the decomposed run is not the serial one ($compare);"
    fi
    [ -f "$compare" ] && cat "$compare"
    verdict "$t/Allrun-parallel" "2 processes, the serial run's fields" \
        "$work/$t-parallel.Allrun.log"
done

echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]

#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Runs every tutorial shortened (SH_SHORT=1, each Allrun says how), in
#     the style of OpenFOAM's Alltest, in copies under the work directory:
#     a tutorial fails when its Allrun fails, a log holds "FOAM FATAL", a
#     savageHutterFoam log lacks its final "End", or its plot script's own
#     checks (--check: the paper's tables, volume, h >= 0) fail.
#     Prints one line per tutorial and "N passed, M failed".
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
        tutorials+=("$(basename "$(dirname "$d")")")
    done
fi

passed=0
failed=0
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
    if [ -z "$problems" ]
    then
        echo "PASS  $t ($nSolver solver runs)"
        passed=$((passed + 1))
    else
        echo "FAIL  $t:$problems (see $work/$t.Allrun.log)"
        tail -n 20 "$work/$t.Allrun.log"
        failed=$((failed + 1))
    fi
    echo
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]

#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     What the application's test scripts share (caseTests.sh,
#     signalTests.sh, soakTest.sh, fuzzTest.sh), sourced as they start
#     after setting project (the project's root) and work (their work
#     directory): sets -u, empties the work directory and makes it
#     absolute, sources bin/tools/RunFunctions, and defines
#       pass <text>, fail <text>   a check's outcome: a PASS or FAIL line,
#                                  counted in $passed and $failed
#       finish                     prints "N passed, M failed"; its status
#                                  (the script's, as its last command) is
#                                  0 when nothing failed
#       timeDirs <case>            the time directories but 0 (and *orig*),
#                                  in the order of their times
#       complete <case> <time>     whether every field and uniform/time of
#                                  a time directory ends with the end
#                                  divider of a finished write
#       waitFor <file> <regex> <seconds>   until the file has a matching
#                                  line (status 1 when it has none by then)
#------------------------------------------------------------------------------
set -u
rm -rf "$work"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
. "$project/bin/tools/RunFunctions"

passed=0
failed=0
pass() { echo "PASS  $*"; passed=$((passed + 1)); }
fail() { echo "FAIL  $*"; failed=$((failed + 1)); }

finish()
{
    echo
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}

timeDirs()
{
    (cd "$1" && ls -d [0-9]* 2>/dev/null | grep -v '^0$' | grep -v orig | sort -g)
}

complete()
{
    local f
    for f in h U hU zb regime hMax UMax tArrival uniform/time
    do
        tail -n 2 "$1/$2/$f" 2>/dev/null | grep -q '^// \*\*\*' || return 1
    done
}

waitFor()
{
    local i
    for i in $(seq $(($3 * 10)))
    do
        grep -qE "$2" "$1" 2>/dev/null && return 0
        sleep 0.1
    done
    return 1
}

#------------------------------------------------------------------------------

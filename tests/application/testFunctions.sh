#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     What the application's test scripts share (caseTests.sh,
#     signalTests.sh, soakTest.sh, fuzzTest.sh, terrainTests.sh,
#     surfaceTests.sh, energyLineTest.sh), sourced as they start after
#     setting project (the project's root) and work (their work directory):
#     sets -u, empties the work directory and makes it absolute, sources
#     bin/tools/RunFunctions, and defines
#       pass <text>, fail <text>   a check's outcome: a PASS or FAIL line,
#                                  counted in $passed and $failed
#       skip <text>                a check that cannot be made here (saying
#                                  why): a SKIP line, counted in $skipped
#       tally <status> <output> <what>   the PASS and FAIL lines of a check
#                                  program's output (a python script's)
#                                  counted as pass and fail, its other lines
#                                  printed; a FAIL more when it made no
#                                  check, or when it exited non-zero without
#                                  a FAIL line (a crash half-way)
#       finish                     prints "N passed, M failed, K skipped";
#                                  its status (the script's, as its last
#                                  command) is 0 when nothing failed and
#                                  something passed
#       timeDirs <case>            the time directories but 0 (and *orig*),
#                                  in the order of their times
#       complete <case> <time>     whether every field and uniform/time of
#                                  a time directory ends with the end
#                                  divider of a finished write
#       waitFor <file> <regex> <seconds>   until the file has a matching
#                                  line (status 1 when it has none by then)
#       planSlopeCase <case> <x0> <y0> <bump>   a plan-coordinates terrain
#                                  case before terrainToCase: the DEM
#                                  constant/dem.asc, its corner at
#                                  (x0, y0), a 35 deg slope turned by
#                                  30 deg rounded into a floor (2 m pixels,
#                                  84 x 60), with a bump of <bump> m;
#                                  system/terrainDict (4 m cells, one
#                                  release) and constant/transportProperties
#                                  (activePassive, Coulomb delta 24)
#
#     pass, fail and skip belong in the script's own shell: called in a
#     subshell (inside $(...), ( ... ) or a pipeline) their count would be
#     lost, so there they also note the line in $work/.subshellChecks and
#     finish counts each such line as a FAIL.
#------------------------------------------------------------------------------
set -u
rm -rf "$work"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
. "$project/bin/tools/RunFunctions"

passed=0
failed=0
skipped=0
subshellChecks="$work/.subshellChecks"

#- noteSubshell <line>: the line noted when not in the script's own shell
noteSubshell()
{
    [ "$BASHPID" = "$$" ] || echo "$*" >> "$subshellChecks"
}
pass() { echo "PASS  $*"; passed=$((passed + 1)); noteSubshell "PASS  $*"; }
fail() { echo "FAIL  $*"; failed=$((failed + 1)); noteSubshell "FAIL  $*"; }
skip() { echo "SKIP  $*"; skipped=$((skipped + 1)); noteSubshell "SKIP  $*"; }

tally()
{
    local rc="$1" out="$2" what="$3" line nPass=0 nFail=0
    while IFS= read -r line
    do
        case "$line" in
            "PASS  "*) pass "${line#PASS  }"; nPass=$((nPass + 1)) ;;
            "FAIL  "*) fail "${line#FAIL  }"; nFail=$((nFail + 1)) ;;
            *) [ -z "$line" ] || echo "$line" ;;
        esac
    done <<< "$out"
    [ $((nPass + nFail)) -gt 0 ] || fail "$what: no check ran (exit status $rc)"
    [ "$rc" -eq 0 ] || [ "$nFail" -gt 0 ] \
        || fail "$what: exit status $rc without a FAIL line"
}

finish()
{
    local line
    if [ -s "$subshellChecks" ]
    then
        while IFS= read -r line
        do
            fail "made in a subshell, its count lost (call pass, fail and skip in the script's own shell): $line"
        done < "$subshellChecks"
    fi
    [ "$passed" -gt 0 ] || [ "$failed" -gt 0 ] || fail "no check was made"
    echo
    echo "$passed passed, $failed failed, $skipped skipped"
    [ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
}

#- closeSlope: in the case of the current directory (the damBreak
#  tutorial's patches), walls up- and downslope too: U slip, h
#  zeroGradient there, so that the domain is closed
closeSlope()
{
    local side
    for side in upslope downslope
    do
        foamDictionary 0/U -entry "boundaryField/$side" \
            -set "{ type slip; }" > /dev/null
        foamDictionary 0/h -entry "boundaryField/$side" \
            -set "{ type zeroGradient; }" > /dev/null
    done
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

# Run case $1 on the CPU from its last time directory to that time + $2
# (log.restart); restartRc: its exit status; restartWarned: false where $3
# is true (a kill left a staging directory) and the log does not say it
# was removed
restartFromLast()
{
    local last
    last=$(timeDirs "$1" | tail -n1)
    setEntry "$1/system/controlDict" startFrom latestTime
    setEntry "$1/system/controlDict" endTime "$(python3 -c "print(round($last + $2, 6))")"
    (cd "$1" && savageHutterFoam -backend cpu > log.restart 2>&1)
    restartRc=$?
    restartWarned=true
    if $3 && ! grep -q "Removing .*savageHutterFoam-writing" "$1/log.restart"
    then
        restartWarned=false
    fi
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

planSlopeCase()
{
    local c="$1"
    mkdir -p "$c/system" "$c/constant"
    /usr/bin/python3 - "$c/constant/dem.asc" "$2" "$3" "$4" <<'PYEOF'
import math, sys
nx, ny, d = 84, 60, 2.0
x0, y0, bump = float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
t = math.tan(math.radians(35))
c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
def z(X, Y):
    # distance along the descent (turned by 30 deg), 35 deg for 90 m,
    # rounded into the floor over 40 m; a bump 10 m wide at (80, 50)
    a = (X - x0)*c + (Y - y0)*s - 10
    if a < 90:
        zs = -t*a
    elif a < 130:
        zs = -t*90 - t*(a - 90) + t*(a - 90)**2/80
    else:
        zs = -t*110
    return 1000 + zs + bump*math.exp(-((X - x0 - 80)**2 + (Y - y0 - 50)**2)/50)
with open(sys.argv[1], "w") as o:
    o.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\n"
            f"cellsize {d}\nNODATA_value -9999\n")
    for j in range(ny):
        Y = y0 + (ny - j - 0.5)*d
        o.write(" ".join("%.17g" % z(x0 + (i + 0.5)*d, Y)
                         for i in range(nx)) + "\n")
PYEOF
    local xa=$(($2 + 20)) xb=$(($2 + 48)) ya=$(($3 + 36)) yb=$(($3 + 64))
    cat > "$c/system/terrainDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "constant/dem.asc";
cellSize        4;
release
{
    r1
    {
        polygon     (($xa $ya) ($xb $ya) ($xb $yb) ($xa $yb));
        thickness   1;
        thicknessDirection vertical;
    }
}
EOF
    cat > "$c/constant/transportProperties" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
g               9.81;
coordinates     plan;
earthPressure   activePassive;
phi             35;
rho             1500;
frictionModel   Coulomb;
CoulombCoeffs   { delta 24; }
EOF
}

#------------------------------------------------------------------------------

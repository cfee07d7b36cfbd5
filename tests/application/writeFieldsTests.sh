#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The fields a user chooses to write (system/controlDict writeFields,
#     restartInterval; issue 27 item 2), on the dam break of section 5.1
#     (128 x 16 cells, writes every 0.1 s to 0.5 s):
#     all: without writeFields every time directory holds every field;
#     select: writeFields (hMax UMax), restartInterval 0.2: 0.1 and 0.3 hold
#       hMax and UMax only (and uniform/), 0.2, 0.4 and the last, 0.5, the
#       restart fields too; the fields written equal all's byte for byte;
#       avalancheSurface refuses a time without h, naming -time, and
#       converts the restart times;
#     restart: from 0.2 of select to 0.5: h, U, hU, hMax of 0.5 equal all's
#       byte for byte (the restart fields are what an exact restart needs);
#     lastOnly: writeFields without restartInterval: only 0.5 has them;
#     partial start: startFrom latestTime where the latest time holds the
#       chosen fields only: an error naming the latest time with the
#       restart fields, non-zero exit, nothing written;
#     sigterm: writeFields (hMax), SIGTERM during the run: the time written
#       on the signal holds the restart fields;
#     purge: purgeWrite 1 with restartInterval 0.3, SIGKILL while running:
#       a time directory with the restart fields is left at every moment;
#     rest: a run that ends at rest (steadyStateTolerance) ends with the
#       restart fields in its last time;
#     bad input: an unknown name, a name twice, a word instead of a list,
#       pMax without rho, H in slope coordinates, a negative
#       restartInterval: each an error naming system/controlDict,
#       writeFields or restartInterval and the valid choices, non-zero
#       exit, no time directory written.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     writeFieldsTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
export OMP_NUM_THREADS=1

restartSet="h U hU zb hMax UMax pMax tArrival"

#- makeCase <dir>: the damBreak tutorial on 128 x 16 cells, fields set
makeCase()
{
    rm -rf "$1"
    mkdir -p "$1"
    cp -r "$project/tutorials/damBreak/0.orig" "$project/tutorials/damBreak/constant" \
        "$project/tutorials/damBreak/system" "$1/"
    (
        cd "$1" || exit 1
        rm -rf constant/polyMesh
        setBlockCells 128 16
        blockMesh > log.blockMesh 2>&1 || exit 1
        restore0Dir > /dev/null
        postProcess -func writeCellCentres -time 0 > log.postProcess 2>&1 || exit 1
        setAvalancheFields > log.setAvalancheFields 2>&1 || exit 1
    )
}

#- fieldsOf <case> <time>: the field files of a time directory, sorted
fieldsOf()
{
    (cd "$1/$2" && ls -p | grep -v / | sort | tr '\n' ' ' | sed 's/ $//')
}

#- hasAll <case> <time> <names...>: every named file is there
hasAll()
{
    local c="$1" t="$2" f
    shift 2
    for f in "$@"
    do
        [ -f "$c/$t/$f" ] || return 1
    done
}

#- sameFiles <case a> <case b> <time> <names...>: byte for byte
sameFiles()
{
    local a="$1" b="$2" t="$3" f
    shift 3
    for f in "$@"
    do
        cmp -s "$a/$t/$f" "$b/$t/$f" || { echo "$f"; return 1; }
    done
}

run() { (cd "$1" && savageHutterFoam -backend cpu > "${2:-log.savageHutterFoam}" 2>&1); }

base="$work/base"
if ! makeCase "$base"
then
    fail "the damBreak case on 128 x 16 cells could not be made"
    finish
    exit
fi
grep -q "^rho" "$base/constant/transportProperties" || restartSet="${restartSet/pMax /}"

# all
all="$work/all"
cp -r "$base" "$all"
run "$all"
dirs="$(timeDirs "$all" | tr '\n' ' ')"
bad=""
for t in $(timeDirs "$all")
do
    hasAll "$all" "$t" $restartSet regime || bad="$bad $t"
done
[ "$dirs" = "0.1 0.2 0.3 0.4 0.5 " ] && [ -z "$bad" ] \
    && pass "all: no writeFields, every field at every write time ($dirs)" \
    || fail "all: time directories '$dirs', incomplete:$bad"

# select
sel="$work/select"
cp -r "$base" "$sel"
foamDictionary "$sel/system/controlDict" -entry writeFields -add "(hMax UMax)" > /dev/null
foamDictionary "$sel/system/controlDict" -entry restartInterval -add 0.2 > /dev/null
run "$sel"
f1="$(fieldsOf "$sel" 0.1)"
f3="$(fieldsOf "$sel" 0.3)"
[ "$f1" = "UMax hMax" ] && [ "$f3" = "UMax hMax" ] \
    && pass "select: 0.1 and 0.3 hold the chosen fields only: '$f1', '$f3' (and uniform/)" \
    || fail "select: 0.1 holds '$f1', 0.3 '$f3' (wanted 'UMax hMax')"
bad=""
for t in 0.2 0.4 0.5
do
    hasAll "$sel" "$t" $restartSet || bad="$bad $t"
done
[ -z "$bad" ] && [ ! -f "$sel/0.2/regime" ] \
    && pass "select: 0.2, 0.4 (restartInterval 0.2) and 0.5 (the last) hold the restart fields ($restartSet), not regime: $(fieldsOf "$sel" 0.2)" \
    || fail "select: restart fields missing at$bad, or regime written: $(fieldsOf "$sel" 0.2)"
[ -d "$sel/0.1/uniform" ] && grep -q "Fields written: 2(hMax UMax)" "$sel/log.savageHutterFoam" \
    && pass "select: uniform/ in every time; the log says what is written: $(grep "Fields written" "$sel/log.savageHutterFoam")" \
    || fail "select: no uniform/ in 0.1, or no 'Fields written' line in the log"
diff="$(sameFiles "$all" "$sel" 0.1 hMax UMax)$(sameFiles "$all" "$sel" 0.3 hMax UMax)$(sameFiles "$all" "$sel" 0.5 $restartSet)"
[ -z "$diff" ] \
    && pass "select: the fields written equal the full run's byte for byte (0.1, 0.3, 0.5)" \
    || fail "select: $diff differs from the full run's"

# avalancheSurface on a case with writeFields: refused at 0.1 with the
# hint, converts the restart times
(cd "$sel" && avalancheSurface > log.surfaceAll 2>&1)
rcAll=$?
(cd "$sel" && avalancheSurface -time '0.2,0.4' > log.surface 2>&1)
rcSome=$?
if [ $rcAll -ne 0 ] && grep -q "No field h in .*0.1" "$sel/log.surfaceAll" \
    && grep -q "choose those with -time <ranges> or -latestTime" "$sel/log.surfaceAll" \
    && [ $rcSome -eq 0 ] && [ -f "$sel/postProcessing/avalancheSurface/surface_0.2.vtp" ] \
    && [ -f "$sel/postProcessing/avalancheSurface/surface_0.4.vtp" ]
then
    pass "select: avalancheSurface refuses 0.1 (no h) naming -time, and converts the restart times 0.2 and 0.4"
else
    fail "select: avalancheSurface: exit $rcAll ($(grep -m1 "No field" "$sel/log.surfaceAll")), with -time 0.2,0.4 exit $rcSome"
fi

# restart from 0.2
rs="$work/restart"
cp -r "$sel" "$rs"
rm -rf "$rs/0.3" "$rs/0.4" "$rs/0.5"
foamDictionary "$rs/system/controlDict" -entry startFrom -set startTime > /dev/null
foamDictionary "$rs/system/controlDict" -entry startTime -set 0.2 > /dev/null
run "$rs" log.restart
diff="$(sameFiles "$all" "$rs" 0.5 $restartSet)"
[ -f "$rs/0.5/h" ] && [ -z "$diff" ] \
    && pass "restart: from 0.2 to 0.5, $restartSet equal the run without a stop byte for byte" \
    || fail "restart: 0.5 differs from the run without a stop: ${diff:-no 0.5/h}"

# lastOnly
lo="$work/lastOnly"
cp -r "$base" "$lo"
foamDictionary "$lo/system/controlDict" -entry writeFields -add "(h hMax)" > /dev/null
run "$lo"
bad=""
for t in 0.1 0.2 0.3 0.4
do
    [ "$(fieldsOf "$lo" "$t")" = "h hMax" ] || bad="$bad $t:$(fieldsOf "$lo" "$t")"
done
[ -z "$bad" ] && hasAll "$lo" 0.5 $restartSet \
    && pass "lastOnly: writeFields (h hMax) without restartInterval: 0.1-0.4 hold h and hMax, 0.5 the restart fields" \
    || fail "lastOnly: $bad; 0.5: $(fieldsOf "$lo" 0.5)"

# partial start
ps="$work/partialStart"
cp -r "$sel" "$ps"
rm -rf "$ps/0.4" "$ps/0.5"
foamDictionary "$ps/system/controlDict" -entry startFrom -set latestTime > /dev/null
before="$(timeDirs "$ps" | tr '\n' ' ')"
run "$ps" log.partial
rc=$?
after="$(timeDirs "$ps" | tr '\n' ' ')"
if [ $rc -ne 0 ] && [ "$before" = "$after" ] \
    && grep -q "time 0.3 holds the fields of writeFields (system/controlDict) only" "$ps/log.partial" \
    && grep -q "The latest time with them is 0.2: restart from it with 'startFrom startTime; startTime 0.2;'" "$ps/log.partial"
then
    pass "partial start: latestTime 0.3 without the restart fields: exit $rc, nothing written, '$(grep -o "is missing: time 0.3.*" "$ps/log.partial" | head -c 200)...'"
else
    fail "partial start: exit $rc, times '$before' -> '$after'; $(grep -i -m2 "missing\|error" "$ps/log.partial")"
fi

# sigterm
st="$work/sigterm"
cp -r "$base" "$st"
foamDictionary "$st/system/controlDict" -entry writeFields -add "(hMax)" > /dev/null
foamDictionary "$st/system/controlDict" -entry endTime -set 100 > /dev/null
foamDictionary "$st/system/controlDict" -entry writeInterval -set 50 > /dev/null
(cd "$st" && exec savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) &
pid=$!
waitFor "$st/log.savageHutterFoam" "^Time = " 60
kill -TERM $pid
wait $pid
rc=$?
last="$(timeDirs "$st" | tail -n1)"
if [ $rc -eq 0 ] && [ -n "$last" ] && hasAll "$st" "$last" $restartSet
then
    pass "sigterm: the time written on SIGTERM ($last) holds the restart fields"
else
    fail "sigterm: exit $rc, last time '$last': $(fieldsOf "$st" "${last:-none}" 2>/dev/null)"
fi

# purge
pu="$work/purge"
cp -r "$base" "$pu"
foamDictionary "$pu/system/controlDict" -entry writeFields -add "(hMax)" > /dev/null
foamDictionary "$pu/system/controlDict" -entry restartInterval -add 0.3 > /dev/null
foamDictionary "$pu/system/controlDict" -entry purgeWrite -set 1 > /dev/null
foamDictionary "$pu/system/controlDict" -entry endTime -set 100 > /dev/null
foamDictionary "$pu/system/controlDict" -entry writeInterval -set 0.02 > /dev/null
(cd "$pu" && exec savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) &
pid=$!
# restartHeld <dirs>: one of them (the start time 0 among them) holds h
restartHeld()
{
    local t
    for t in "$@"
    do
        [ -f "$pu/$t/h" ] && return 0
    done
    return 1
}
listTimes() { (cd "$pu" && ls -d [0-9]* 2>/dev/null | grep -v orig | sort -g | tr '\n' ' '); }
# The start time 0 (which holds them) removed once read, the looks begin
# at the first restart time, 0.3
waitFor "$pu/log.savageHutterFoam" "^Starting time loop" 60
rm -rf "$pu/0"
seen=0 lost=""
for i in $(seq 400)
do
    sleep 0.05
    dirs="$(listTimes)"
    echo "$dirs" | awk '{ for (i = 1; i <= NF; ++i) if ($i >= 0.3) f = 1 } END { exit !f }' \
        || continue
    restartHeld $dirs && held=true || held=false
    # A look counts where nothing changed while it looked
    [ "$(listTimes)" = "$dirs" ] || continue
    seen=$((seen + 1))
    $held || lost="$lost [$dirs]"
    [ "$seen" -ge 40 ] && break
done
kill -KILL $pid 2> /dev/null
wait $pid 2> /dev/null
dirs="$(listTimes)"
restartHeld $dirs && ok=true || ok=false
if [ "$seen" -ge 10 ] && [ -z "$lost" ] && $ok
then
    pass "purge: purgeWrite 1, restartInterval 0.3: at $seen looks while running (from t = 0.3, the start time 0 removed) and after SIGKILL ($dirs) a time with the restart fields remained"
else
    fail "purge: $seen looks; without the restart fields:$lost; after SIGKILL: $dirs"
fi

# rest
re="$work/rest"
cp -r "$base" "$re"
# A pile with delta 30 > zeta 20 (logTests.sh's rest case)
sed -i 's/delta       24.5;/delta       30;/; s/constant 40;/constant 20;/' \
    "$re/constant/transportProperties"
sed -i 's/upstream 10;/upstream 1;/' "$re/system/setAvalancheFieldsDict"
foamDictionary "$re/system/controlDict" -entry writeInterval -set 0.5 > /dev/null
rm -rf "$re/0" && (cd "$re" && restore0Dir > /dev/null \
    && postProcess -func writeCellCentres -time 0 > log.postProcess 2>&1 \
    && setAvalancheFields > log.setAvalancheFields 2>&1)
foamDictionary "$re/system/controlDict" -entry writeFields -add "(hMax)" > /dev/null
foamDictionary "$re/system/controlDict" -entry endTime -set 100 > /dev/null
foamDictionary "$re/system/fvSolution" -entry savageHutter/steadyStateTolerance -set 1e-4 > /dev/null
run "$re"
last="$(timeDirs "$re" | tail -n1)"
if grep -q "End of run at t = .*: at rest" "$re/log.savageHutterFoam" && [ -n "$last" ] \
    && hasAll "$re" "$last" $restartSet && [ "$(fieldsOf "$re" "$(timeDirs "$re" | head -n1)")" = "hMax" ]
then
    pass "rest: '$(grep "End of run" "$re/log.savageHutterFoam")', its last time $last holds the restart fields, the first only hMax"
else
    fail "rest: $(grep "End of run" "$re/log.savageHutterFoam"); last time '$last': $(fieldsOf "$re" "${last:-none}" 2>/dev/null)"
fi

# bad input
badCase()
{
    local name="$1" key="$2" value="$3" want="$4" c="$work/bad-$1"
    cp -r "$base" "$c"
    [ -z "${5:-}" ] || eval "$5"
    foamDictionary "$c/system/controlDict" -entry "$key" -add "$value" > /dev/null
    run "$c" log.bad
    local rc=$? times
    times="$(timeDirs "$c")"
    if [ $rc -ne 0 ] && [ -z "$times" ] && grep -q "controlDict" "$c/log.bad" \
        && grep -q "$want" "$c/log.bad" && grep -q "Valid" "$c/log.bad"
    then
        pass "bad input: $name refused, nothing written: $(grep -m1 -o "$want.*" "$c/log.bad" | head -c 150)"
    else
        fail "bad input: $name: exit $rc, times '$times'; $(grep -m2 -i "error\|invalid\|valid" "$c/log.bad")"
    fi
}
badCase unknownName writeFields "(h foo)" "Invalid writeFields '( h foo )' at line [0-9]*: foo"
badCase twice writeFields "(h h)" "h (twice)"
badCase notAList writeFields "h" "Invalid writeFields 'h'"
badCase planOnly writeFields "(h H)" "names H, which this case does not have"
badCase noRho writeFields "(h pMax)" "names pMax, which this case does not have" \
    'sed -i "/^rho /d" "$c/constant/transportProperties"'
badCase negative restartInterval "-1" "Invalid restartInterval '-1'"

finish

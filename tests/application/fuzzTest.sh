#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Fuzz test of the case: the damBreak tutorial on 16 x 2 cells run to
#     t = 0.02 s.  For every keyword of the dictionaries that savageHutterFoam
#     and setAvalancheFields read (constant/transportProperties with
#     CoulombCoeffs, system/fvSolution::savageHutter, the controlDict entries
#     the run depends on, system/setAvalancheFieldsDict) and of the field
#     files 0/h and 0/U (dimensions, internalField, each patch's type), a
#     copy of the prepared case is made with the entry
#         missing, of the wrong type, NaN, negative, zero, huge (1e300),
#         misspelt (the keyword, and for a name from a set also the value)
#     (variants that make no sense for a keyword are left out: an absent
#     optional entry cannot go missing).  Each variant is run directly (not
#     through Allrun) and must end one of two ways:
#       OK        exit 0, 'End' in the log, every field of every written
#                 time directory finite (no nan/inf);
#       REJECTED  non-zero exit, a FOAM FATAL message that names the keyword
#                 (its last path component, as a word; misspelt: the
#                 original or the misspelt keyword; an internalField: the
#                 keyword or the field file, as in "h = -1 in cell 0 ...
#                 file: 0/h"), no stack trace, and nothing written: no time
#                 directory besides 0 (setAvalancheFields: 0/h unchanged).
#     Anything else (a crash, a signal, NaN written, a message that does not
#     name the keyword, a run that hangs) is BAD: a FAIL line, except the
#     variants of the list "known" below, BAD today and reported (issue 13),
#     which print KNOWN lines and are counted apart.  Prints every variant's
#     outcome, a table per keyword, the counts, and "N passed, M failed"
#     (one check per variant).  Variants run two at a time (SH_FUZZ_JOBS).
#
#     Entries are changed with foamDictionary -set/-remove, except inside the
#     shape list of setAvalancheFieldsDict, which foamDictionary cannot
#     address: that dictionary is written out per variant.
#
# Usage
#     fuzzTest.sh <project dir> <work dir>
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
. "$project/bin/tools/RunFunctions"

passed=0
failed=0
pass() { echo "PASS  $*"; passed=$((passed + 1)); }
fail() { echo "FAIL  $*"; failed=$((failed + 1)); }

# A variant that runs longer than this is BAD (the base case takes 0.2 s)
limit=20
export OMP_NUM_THREADS=1

rm -rf "$work"
mkdir -p "$work"
# pre: mesh and 0.orig as 0, for setAvalancheFields; base: with h set, for
# savageHutterFoam
pre="$work/pre"
base="$work/base"
mkdir "$pre"
cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$pre"/
(
    cd "$pre" || exit 1
    setBlockCells 16 2
    setEntry system/controlDict endTime 0.02
    setEntry system/controlDict writeInterval 0.01
    runApplication blockMesh
    restore0Dir
    cp -r "$pre" "$base"
    cd "$base" || exit 1
    runApplication setAvalancheFields
    rm -f log.*
    runApplication savageHutterFoam -backend cpu
    grep -q '^End' log.savageHutterFoam || exit 1
    rm -rf log.* postProcessing
    ls -d [0-9]* | grep -v '^0$' | xargs rm -rf
) > "$work/setup.log" 2>&1 || { cat "$work/setup.log"; echo "0 passed, 1 failed"; exit 1; }

timeDirs()
{
    (cd "$1" && ls -d [0-9]* 2>/dev/null | grep -v '^0$' | grep -v orig)
}

# -- The keywords -------------------------------------------------------------
# app|file|entry|kind
#   kind: num (a number), fn1 (a Function1: constant <number>), word:<value>
#   (a name from a set), switch:<value>, dict (a sub-dictionary), optnum and
#   optswitch:<value> (absent from the tutorial, optional: no missing or
#   misspelt variant), dims, sfield/vfield (an internalField), shape (inside
#   setAvalancheFieldsDict's list), list (setAvalancheFieldsDict's h)
tp=constant/transportProperties
fs=system/fvSolution
cd_=system/controlDict
sa=system/setAvalancheFieldsDict
keywords="
savageHutterFoam|$tp|g|num
savageHutterFoam|$tp|epsilon|num
savageHutterFoam|$tp|lambda|num
savageHutterFoam|$tp|inclination|fn1
savageHutterFoam|$tp|earthPressure|word:isotropic
savageHutterFoam|$tp|phi|num
savageHutterFoam|$tp|frictionModel|word:Coulomb
savageHutterFoam|$tp|CoulombCoeffs|dict
savageHutterFoam|$tp|CoulombCoeffs/delta|num
savageHutterFoam|$fs|savageHutter|dict
savageHutterFoam|$fs|savageHutter/limiter|word:minmod
savageHutterFoam|$fs|savageHutter/stoppingCriterion|switch:on
savageHutterFoam|$fs|savageHutter/staticResistance|switch:on
savageHutterFoam|$fs|savageHutter/hDry|num
savageHutterFoam|$fs|savageHutter/holdResting|optswitch:on
savageHutterFoam|$fs|savageHutter/steadyStateTolerance|optnum
savageHutterFoam|$cd_|startFrom|word:startTime
savageHutterFoam|$cd_|startTime|num
savageHutterFoam|$cd_|stopAt|word:endTime
savageHutterFoam|$cd_|endTime|num
savageHutterFoam|$cd_|deltaT|num
savageHutterFoam|$cd_|adjustTimeStep|switch:yes
savageHutterFoam|$cd_|maxCo|num
savageHutterFoam|$cd_|maxDeltaT|optnum
savageHutterFoam|$cd_|writeControl|word:adjustableRunTime
savageHutterFoam|$cd_|writeInterval|num
savageHutterFoam|$cd_|purgeWrite|num
savageHutterFoam|$cd_|writeFormat|word:ascii
savageHutterFoam|$cd_|writePrecision|num
savageHutterFoam|$cd_|writeCompression|word:off
savageHutterFoam|$cd_|timeFormat|word:general
savageHutterFoam|$cd_|timePrecision|num
savageHutterFoam|$cd_|runTimeModifiable|switch:false
savageHutterFoam|0/h|dimensions|dims
savageHutterFoam|0/h|internalField|sfield
savageHutterFoam|0/h|boundaryField|dict
savageHutterFoam|0/h|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|0/h|boundaryField/downslope/type|word:zeroGradient
savageHutterFoam|0/h|boundaryField/sides/type|word:zeroGradient
savageHutterFoam|0/h|boundaryField/frontAndBack/type|word:empty
savageHutterFoam|0/U|dimensions|dims
savageHutterFoam|0/U|internalField|vfield
savageHutterFoam|0/U|boundaryField|dict
savageHutterFoam|0/U|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|0/U|boundaryField/downslope/type|word:zeroGradient
savageHutterFoam|0/U|boundaryField/sides/type|word:slip
savageHutterFoam|0/U|boundaryField/frontAndBack/type|word:empty
setAvalancheFields|$sa|h|list
setAvalancheFields|$sa|h/damBreak|dict
setAvalancheFields|$sa|h/damBreak/position|shape
setAvalancheFields|$sa|h/damBreak/upstream|shape
setAvalancheFields|$sa|h/damBreak/downstream|shape
setAvalancheFields|0/h|internalField|sfield
"

#- variants <kind>: lines "name|value"; value "-" removes the entry,
#  "~<key>" renames the keyword to <key> (misspelt)
variants()
{
    local kind="${1%%:*}"
    local val="${1#*:}"
    case "$kind" in
    num|optnum|shape)
        [ "$kind" = optnum ] || echo "missing|-"
        echo "wrongType|fuzzWord"
        echo "nan|nan"
        echo "negative|-1"
        echo "zero|0"
        echo "huge|1e300"
        [ "$kind" = optnum ] || echo "misspelt|~"
        ;;
    fn1)
        echo "missing|-"
        echo "wrongType|(1 2)"
        echo "nan|constant nan"
        echo "negative|constant -1"
        echo "zero|constant 0"
        echo "huge|constant 1e300"
        echo "misspelt|~"
        echo "misspeltValue|constnt 40"
        ;;
    word|switch|optswitch)
        [ "$kind" = optswitch ] || echo "missing|-"
        echo "wrongType|1.5"
        echo "nan|nan"
        echo "negative|-1"
        echo "zero|0"
        echo "huge|1e300"
        [ "$kind" = optswitch ] || echo "misspelt|~"
        echo "misspeltValue|${val}x"
        ;;
    dict|list)
        echo "missing|-"
        echo "wrongType|fuzzWord"
        echo "nan|nan"
        echo "negative|-1"
        echo "zero|0"
        echo "huge|1e300"
        echo "misspelt|~"
        ;;
    dims)
        echo "missing|-"
        echo "wrongType|fuzzWord"
        echo "nan|[0 nan 0 0 0 0 0]"
        echo "negative|[0 -1 0 0 0 0 0]"
        echo "zero|[0 0 0 0 0 0 0]"
        echo "huge|[0 1e300 0 0 0 0 0]"
        echo "misspelt|~"
        ;;
    sfield)
        echo "missing|-"
        echo "wrongType|uniform (1 0 0)"
        echo "nan|uniform nan"
        echo "negative|uniform -1"
        echo "zero|uniform 0"
        echo "huge|uniform 1e300"
        echo "misspelt|~"
        echo "misspeltValue|uniformm 1"
        ;;
    vfield)
        echo "missing|-"
        echo "wrongType|uniform 1"
        echo "nan|uniform (nan 0 0)"
        echo "negative|uniform (-1 0 0)"
        echo "zero|uniform (0 0 0)"
        echo "huge|uniform (1e300 0 0)"
        echo "misspelt|~"
        echo "misspeltValue|uniformm (0 0 0)"
        ;;
    esac
}

#- The misspelling of a keyword: one letter doubled, inside the name
misspell()
{
    local k="$1"
    if [ ${#k} -ge 2 ]
    then
        echo "${k:0:2}${k:1}"
    else
        echo "${k}${k}"
    fi
}

#- setAvalancheFieldsDict with one entry of the shape list changed:
#  saDict <file> <entry> <value>
saDict()
{
    local file="$1" entry="$2" value="$3"
    local position="position 0;" upstream="upstream 10;" downstream="downstream 0;"
    local shape="damBreak" list="h"
    local body
    case "$entry" in
    h/damBreak/*)
        local key="${entry##*/}" line original
        case "$key" in
        position) original=0 ;;
        upstream) original=10 ;;
        downstream) original=0 ;;
        esac
        case "$value" in
        -) line="" ;;
        "~"*) line="${value#\~} $original;" ;;
        *) line="$key $value;" ;;
        esac
        case "$key" in
        position) position="$line" ;;
        upstream) upstream="$line" ;;
        downstream) downstream="$line" ;;
        esac
        body="h ( damBreak { $position $upstream $downstream } );"
        ;;
    h/damBreak)
        case "$value" in
        -) body="h ( );" ;;
        "~"*) body="h ( ${value#\~} { $position $upstream $downstream } );" ;;
        *) body="h ( $value );" ;;
        esac
        ;;
    h)
        case "$value" in
        -) body="" ;;
        "~"*) body="${value#\~} ( damBreak { $position $upstream $downstream } );" ;;
        *) body="h $value;" ;;
        esac
        ;;
    esac
    sed -i '/^h$/,$d' "$file"
    echo "$body" >> "$file"
}

#- makeVariant <case> <app> <file> <entry> <kind> <value>
makeVariant()
{
    local d="$1" app="$2" file="$3" entry="$4" kind="$5" value="$6"
    local key="${entry##*/}" parent=""
    [ "$key" = "$entry" ] || parent="${entry%/*}/"
    if [ "$file" = "$sa" ]
    then
        saDict "$d/$file" "$entry" "$value"
        return
    fi
    case "$value" in
    -)
        foamDictionary "$d/$file" -entry "$entry" -remove > /dev/null
        ;;
    "~"*)
        local old
        old="$(foamDictionary "$d/$file" -entry "$entry" -value)" || return 1
        foamDictionary "$d/$file" -entry "$entry" -remove > /dev/null \
        && foamDictionary "$d/$file" -entry "$parent${value#\~}" \
               -add "$old" > /dev/null
        ;;
    *)
        foamDictionary "$d/$file" -entry "$entry" -set "$value" > /dev/null
        ;;
    esac
}

#- classify <case> <app> <log> <rc> <keyword pattern>...: prints
#  "OK <what>", "REJECTED <what>" or "BAD <what was wrong>"
classify()
{
    local d="$1" app="$2" log="$3" rc="$4"
    shift 4
    local written
    written="$(timeDirs "$d" | tr '\n' ' ')"
    local trace=""
    grep -qE "[Ss]tack trace|printStack|sigFpe::sigHandler|sigSegv::sigHandler|Segmentation fault|core dumped|^ *#[0-9]+ " "$log" \
        && trace=yes
    if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]
    then
        echo "BAD did not finish within $limit s"
        return
    fi
    if [ "$rc" -eq 0 ]
    then
        local problems=""
        grep -q '^End' "$log" || problems="$problems no 'End' in the log;"
        [ -z "$trace" ] || problems="$problems a stack trace;"
        local dirs="$written"
        [ "$app" = setAvalancheFields ] && dirs="0"
        local t bad
        for t in $dirs
        do
            bad="$(cd "$d/$t" && grep -liwE 'nan|-?inf|infinity' -- * 2>/dev/null | tr '\n' ' ')"
            [ -z "$bad" ] || problems="$problems non-finite values in $t: $bad;"
        done
        if [ -z "$problems" ]
        then
            if [ "$app" = setAvalancheFields ]
            then
                echo "OK wrote 0/h"
            else
                echo "OK wrote ${written:-nothing}"
            fi
        else
            echo "BAD exit 0 but$problems"
        fi
        return
    fi
    local problems=""
    [ "$rc" -lt 128 ] || problems="$problems killed by signal $((rc - 128));"
    grep -q "FOAM FATAL" "$log" || problems="$problems no FOAM FATAL message;"
    [ -z "$trace" ] || problems="$problems a stack trace;"
    [ -z "$written" ] || problems="$problems wrote $written;"
    if [ "$app" = setAvalancheFields ] && ! cmp -s "$d/0/h" "$d/h.before"
    then
        problems="$problems changed 0/h;"
    fi
    # The keyword, in the message (from the FOAM FATAL line on)
    local message named="" p
    message="$(sed -n '/FOAM FATAL/,$p' "$log")"
    for p in "$@"
    do
        grep -qwF -- "$p" <<< "$message" && named=yes
    done
    [ -n "$named" ] || problems="$problems the message does not name '$*';"
    if [ -z "$problems" ]
    then
        echo "REJECTED $(grep -m1 -A1 'FOAM FATAL' "$log" | tail -n1 | sed 's/^ *//' | cut -c1-70)"
    else
        echo "BAD exit $rc:$problems"
    fi
}

# -- Known BAD variants --------------------------------------------------------
# Reported, not fixed here (the fixes belong in src/savageHutter, avalancheRun.H,
# avalancheCase.H, setAvalancheFields.C): each prints a KNOWN line and counts
# in the table; one that stops being BAD prints a PASS line asking for its
# removal from this list.
known="
"

# -- Run the variants ---------------------------------------------------------
#- runVariant <n> <app> <file> <entry> <kind> <vname> <value>: writes the
#  outcome line to $work/result.<n>
runVariant()
{
    local n="$1" app="$2" file="$3" entry="$4" kind="$5" vname="$6" value="$7"
    local key="${entry##*/}"
    local d="$work/v$n"
    local out="$work/result.$n"
    if [ "$app" = setAvalancheFields ]
    then
        cp -r "$pre" "$d"
    else
        cp -r "$base" "$d"
    fi
    # The message must name the keyword; a misspelt keyword may be named as
    # written or as the missing original; a field file's value may be named
    # by the file (0/h: the field and cell)
    local patterns=("$key")
    if [ "${value:0:1}" = "~" ]
    then
        value="~$(misspell "$key")"
        patterns+=("${value#\~}")
    fi
    [ "$key" = internalField ] && patterns+=("$d/$file")
    [ "$vname" = misspeltValue ] && patterns+=("${value%% *}")
    if ! makeVariant "$d" "$app" "$file" "$entry" "$kind" "$value"
    then
        echo "BAD cannot make the variant (value '$value')|$value" > "$out"
        return
    fi
    local log="$d/log.$app"
    cp "$d/0/h" "$d/h.before"
    if [ "$app" = setAvalancheFields ]
    then
        (cd "$d" && timeout -s KILL "$limit" setAvalancheFields > "$log" 2>&1)
    else
        (cd "$d" && timeout -s KILL "$limit" savageHutterFoam -backend cpu > "$log" 2>&1)
    fi
    local rc=$?
    local outcome
    outcome="$(classify "$d" "$app" "$log" "$rc" "${patterns[@]}")"
    echo "$outcome|$value" > "$out"
    # Keep the work directory small: only BAD variants stay
    case "$outcome" in BAD*) ;; *) rm -rf "$d" ;; esac
}

start=$SECONDS
# Enumerate: n|app|file|entry|kind|vname|value
n=0
: > "$work/variants"
while IFS='|' read -r -u 3 app file entry kind
do
    [ -n "$app" ] || continue
    while IFS='|' read -r -u 4 vname value
    do
        n=$((n + 1))
        echo "$n|$app|$file|$entry|$kind|$vname|$value" >> "$work/variants"
    done 4< <(variants "$kind")
done 3<<< "$keywords"

# Two at a time (the CI machine has two cores; each run is one thread)
jobs=${SH_FUZZ_JOBS:-2}
while IFS='|' read -r -u 3 n app file entry kind vname value
do
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]
    do
        wait -n
    done
    runVariant "$n" "$app" "$file" "$entry" "$kind" "$vname" "$value" &
done 3< "$work/variants"
wait

nTried=0
nOK=0
nRejected=0
nBad=0
nKnown=0
table=""
lastKey=""
row=""
while IFS='|' read -r -u 3 n app file entry kind vname value
do
    thisKey="$app|$file|$entry"
    if [ "$thisKey" != "$lastKey" ]
    then
        [ -z "$lastKey" ] || table="$table$row
"
        row="$(printf '%-18s %-28s %-31s' "$app" "$file" "$entry")"
        lastKey="$thisKey"
    fi
    name="$app:$file:$entry:$vname"
    outcome="$(cut -d'|' -f1 "$work/result.$n" 2>/dev/null)"
    value="$(cut -d'|' -f2- "$work/result.$n" 2>/dev/null)"
    [ -n "$outcome" ] || outcome="BAD no result"
    what="${outcome#* }"
    isKnown=""
    grep -qxF "$name" <<< "$known" && isKnown=yes
    nTried=$((nTried + 1))
    case "$outcome" in
    OK*)
        nOK=$((nOK + 1)); row="$row $vname=OK"
        if [ -n "$isKnown" ]
        then
            pass "$name = '$value': OK ($what); no longer BAD: remove it from the known list"
        else
            pass "$name = '$value': OK ($what)"
        fi
        ;;
    REJECTED*)
        nRejected=$((nRejected + 1)); row="$row $vname=REJ"
        if [ -n "$isKnown" ]
        then
            pass "$name = '$value': REJECTED ($what); no longer BAD: remove it from the known list"
        else
            pass "$name = '$value': REJECTED ($what)"
        fi
        ;;
    *)
        if [ -n "$isKnown" ]
        then
            nKnown=$((nKnown + 1)); row="$row $vname=KNOWN"
            echo "KNOWN $name = '$value': $what (see $work/v$n)"
        else
            nBad=$((nBad + 1)); row="$row $vname=BAD"
            fail "$name = '$value': $what (see $work/v$n)"
        fi
        ;;
    esac
done 3< "$work/variants"
table="$table$row
"
echo
echo "Outcomes per keyword (REJ: rejected; KNOWN: a known BAD outcome, listed above):"
printf '%s' "$table"
echo
echo "Variants tried: $nTried   OK: $nOK   REJECTED: $nRejected   BAD: $nBad   KNOWN BAD: $nKnown   ($((SECONDS - start)) s)"
echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]

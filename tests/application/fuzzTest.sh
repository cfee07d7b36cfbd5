#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Fuzz test of the case: the damBreak tutorial on 16 x 2 cells run to
#     t = 0.02 s.  For every keyword of the dictionaries that savageHutterFoam
#     and setAvalancheFields read and of the field files, a copy of a
#     prepared case is made with the entry
#         missing, of the wrong type, NaN, negative, zero, huge (1e300 and a
#         finite 1e20), misspelt (the keyword, and for a name from a set
#         also the value), for vectors and fields also of the wrong size,
#     a whole file of a start time directory missing, empty, without its
#     header, of another class or cut short, and, for some keywords,
#     values that break a rule between two entries (delta > phi with
#     activePassive, zeta1 >= zeta2, a step that cannot reach endTime, ...;
#     these must be rejected; values at a listed bound or an accepted edge
#     case must run).  Variants that make no sense for a keyword
#     are left out (an absent optional entry cannot go missing; with
#     adjustableRunTime writes and no maxDeltaT, endTime 1e20 is a legal
#     run that ends when the user ends it).  The prepared cases:
#       base       Coulomb friction, isotropic earth pressure: the entries of
#                  transportProperties, fvSolution::savageHutter, controlDict,
#                  0/h and 0/U (dimensions, internalField, patch types);
#       timeStep, clockTime, fixedDt  writeControl timeStep (every step),
#                  clockTime (every second), adjustTimeStep no: their
#                  writeInterval, maxDeltaT, deltaT, endTime (steps that
#                  cannot reach endTime within 1e10), and with timeStep
#                  writes g, epsilon, 0/h, 0/U (no first write time bounds
#                  the steps there: speeds and wave speeds beyond light);
#       table      inclination as a table: empty, one entry, unsorted or
#                  repeated x, angles of +-90 degrees and beyond (also only
#                  between two cell centres), NaN, tuples of the wrong
#                  form, huge;
#       law<Name>  for every friction law that savageHutterFoam
#                  -listFrictionLaws lists (the list of the laws' headers,
#                  src/savageHutter/physics/frictionLaws): frictionModel
#                  <Name> with its required coefficients at their defaults:
#                  <Name>Coeffs and every coefficient, with the law's edge
#                  cases as further variants; for a law without a basal
#                  friction angle, earthPressure activePassive (rejected);
#       ap<Name>   for a law with a basal friction angle: law<Name> with
#                  earthPressure activePassive and phi 30, the coefficient
#                  of the angle (its edge cases: delta > phi, atan(mu) >
#                  phi are rejected);
#       ap         earthPressure activePassive with Coulomb: phi below
#                  delta is rejected;
#       ent<Name>  for every entrainment model that savageHutterFoam
#                  -listEntrainmentModels lists (src/savageHutter/physics/
#                  entrainmentModels): entrainmentModel <Name> with every
#                  coefficient at its default, 0/hEntrainable 0.1 m and
#                  0/cResistance 0.01 1/m: <Name>Coeffs (missing: rejected
#                  where a coefficient is required; for a model without
#                  coefficients empty, or with a keyword: rejected), a
#                  keyword it does not know (rejected), and every
#                  coefficient: the standard variants marked by its listed
#                  bound (outside: rejected; on a closed end: must run),
#                  just outside each end and on it, non-numeric, nan and a
#                  required one missing (rejected), and the model's edge
#                  cases (accepted: must run; rejected);
#                  in the first model's case (with coefficients) also
#                  entrainmentModel and the bed's cover: 0/hEntrainable
#                  (missing: rejected with a model; also with none) and
#                  0/cResistance, each whole, its dimensions (m and 1/m;
#                  others rejected), internalField (range [0, 1e30] in
#                  every cell: negative, nan, 1.01e30, one cell negative
#                  or nan, the wrong size rejected; 0 and 1e30 must run),
#                  boundaryField and a patch type;
#       restartCover, restartPlan  that case run to 0.01 and restarted
#                  from latestTime, in slope and in plan coordinates
#                  (coordinates plan, no inclination): in 0.01/ erodedDepth
#                  (whole, dimensions, internalField, boundaryField),
#                  hEntrainable and cResistance (whole, internalField),
#                  HEntrainable and HErodedDepth (whole, dimensions,
#                  internalField), the same range;
#       jet        system/fvOptions with an impingingJet: centre, R, R_imp,
#                  u_jet, type, active, selectionMode;
#       jetCoeffs  the same with the coefficients in impingingJetCoeffs:
#                  the sub-dictionary and each coefficient, type,
#                  selectionMode;
#       jetConstant  the jet in constant/fvOptions: its entries, and both
#                  files at once (rejected);
#       zb         a bed 0/zb (from setAvalancheFields): dimensions,
#                  internalField, boundaryField;
#       inflow     fixedValue inflow on the upslope side: the value of h
#                  and U there;
#       restart    a run to 0.01 (rho 1500) restarted from latestTime to
#                  0.02 (and its arrivalThreshold): in 0.01/ the files h,
#                  U, hU, hMax, UMax, pMax, tArrival (each whole, and
#                  its dimensions, internalField, boundaryField),
#                  uniform/time (whole, value, name, index, deltaT,
#                  deltaT0) and uniform/writeGrid (whole, origin);
#       mesh       system/blockMeshDict (nx, ny, convertToMeters, the block:
#                  3D, zero cells in z, graded, skewed, two blocks,
#                  rotated, named); blockMesh is run first (not for
#                  "stale": the counts edited and blockMesh not run), and
#                  the solver then meets the mesh blockMesh wrote, or, where
#                  blockMesh failed, the mesh of the case before the edit;
#       pre        mesh and 0.orig, for setAvalancheFields: its lists h, zb,
#                  U and every keyword of every shape (hemisphere, cone,
#                  paraboloid, box, damBreak, gaussian for h; plane, bowl,
#                  channel for zb; box, damBreak for U), 0/h.
#     Each variant is run directly (not through Allrun) and must end one of
#     two ways:
#       OK        exit 0, 'End' in the log, every field of every written
#                 time directory finite (no nan/inf);
#       REJECTED  non-zero exit, a FOAM FATAL message that names the keyword
#                 (its last path component, as a word; misspelt: the
#                 original or the misspelt keyword; an internalField or a
#                 patch value: the keyword or the field file, as in "h = -1
#                 in cell 0 ... file: 0/h"; the block of blockMeshDict:
#                 blocks, simpleGrading or "aligned"), no stack trace, and
#                 nothing written: no time directory besides 0 (and the
#                 start time of the restart; setAvalancheFields: 0/
#                 unchanged).
#     Anything else (a crash, a signal, NaN written, a message that does not
#     name the keyword, a run that hangs, a rule-breaking value that runs, a
#     misspelt keyword ignored: except in controlDict, where OpenFOAM's Time
#     takes any entry and a misspelt optional one falls back to its default,
#     and the name of an fvOptions source, which is free) is BAD: a FAIL
#     line, except the variants of the list "known" below,
#     BAD today and reported, which print KNOWN lines and are counted
#     apart.  blockMesh is OpenFOAM's (Debian's v1912): where it crashes
#     (it segfaults on a zero or negative cell count) the line says so and
#     the summary counts it; the variant's outcome is the solver's.
#     Prints every variant's outcome, a table per keyword, the counts, and
#     "N passed, M failed, K skipped" (one check per variant).  Variants run
#     two at a time (SH_FUZZ_JOBS).
#
#     Entries are changed with foamDictionary -set/-remove, except in
#     setAvalancheFieldsDict and fvOptions (written out per variant:
#     foamDictionary cannot address the shape lists) and blockMeshDict (sed:
#     foamDictionary would expand $nx).
#
# Usage
#     fuzzTest.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"

# A variant that runs longer than this is BAD (far longer than the base case
# takes)
limit=20
export OMP_NUM_THREADS=1

tp=constant/transportProperties
fs=system/fvSolution
cd_=system/controlDict
sa=system/setAvalancheFieldsDict
fo=system/fvOptions
foc=constant/fvOptions
bm=system/blockMeshDict

# -- The prepared cases ---------------------------------------------------------
#- The impinging jet of the jet case: a mesh point of the 16 x 2 mesh
jetOuter="type impingingJet; active yes; selectionMode all;"
jetCoeffs="centre (0 0 0); R 1; R_imp 2; u_jet 1;"
jetEntries="$jetOuter $jetCoeffs"
fvOptionsHeader='FoamFile { version 2.0; format ascii; class dictionary; object fvOptions; }'

# -- The friction laws: from the solver's own list -------------------------------
#- lawCases: a line "Name|{ coefficients }|angle keyword or none" per law;
#  lawKeywords: the keyword lines (below) of its cases
(cd "$work" && savageHutterFoam -listFrictionLaws > frictionLaws.log 2>&1) \
 && grep -q '^frictionModel ' "$work/frictionLaws.log" \
 || { cat "$work/frictionLaws.log"; fail "savageHutterFoam -listFrictionLaws"; finish; exit 1; }
lawCases=""
lawKeywords=""
declare -A edgeIso edgeAp
lawName=""
#- endLaw: the case and keyword lines of the law read so far
endLaw()
{
    [ -n "$lawName" ] || return 0
    local L="$lawName" key kind
    lawCases="$lawCases$L|{$lawEntries }|$lawAngle
"
    lawKeywords="${lawKeywords}savageHutterFoam|law$L|$tp|${L}Coeffs|dict
"
    for key in $lawKeys
    do
        kind=num
        [[ " $lawOptional " == *" $key "* ]] && kind=optnum
        lawKeywords="${lawKeywords}savageHutterFoam|law$L|$tp|${L}Coeffs/$key|$kind${edgeIso[$key]:+|${edgeIso[$key]#,}}
"
    done
    if [ "$lawAngle" = none ]
    then
        lawKeywords="${lawKeywords}savageHutterFoam|law$L|$tp|earthPressure|word:isotropic|activePassive=activePassive!
"
    else
        for key in $lawKeys
        do
            [ "$key" = "$lawAngle" ] || [ -n "${edgeAp[$key]:-}" ] || continue
            lawKeywords="${lawKeywords}savageHutterFoam|ap$L|$tp|${L}Coeffs/$key|num${edgeAp[$key]:+|${edgeAp[$key]#,}}
"
        done
    fi
    lawName=""
}
while read -r tag a b c d e _
do
    case "$tag" in
    frictionModel)
        endLaw
        lawName="$a"; lawEntries=""; lawKeys=""; lawOptional=""; lawAngle=none
        edgeIso=(); edgeAp=()
        ;;
    coefficient)
        lawKeys="$lawKeys $a"
        if [ "$c" = required ]
        then
            lawEntries="$lawEntries $a $b;"
        else
            lawOptional="$lawOptional $a"
        fi
        ;;
    activePassive)
        [ "$a" = none: ] || lawAngle="$a"
        ;;
    edge)
        # edge <name> <keyword> <value> accepted|rejected isotropic|activePassive
        local_v="$a=$c+"
        [ "$d" = rejected ] && local_v="$a=$c!"
        if [ "$e" = activePassive ]
        then
            edgeAp[$b]="${edgeAp[$b]:-},$local_v"
        else
            edgeIso[$b]="${edgeIso[$b]:-},$local_v"
        fi
        ;;
    esac
done < "$work/frictionLaws.log"
endLaw
[ -n "$lawCases" ] || { fail "no friction law in savageHutterFoam -listFrictionLaws"; finish; exit 1; }

# -- The entrainment models: from the solver's own list --------------------------
#- entCases: a line "Name|{ coefficients }" per model (every coefficient at
#  its default); entKeywords: the keyword lines (below) of its case ent<Name>
#  and, in the case of the first model with coefficients (entFirst), of the
#  bed's cover 0/hEntrainable and 0/cResistance
(cd "$work" && savageHutterFoam -listEntrainmentModels > entrainmentModels.log 2>&1) \
 && grep -q '^entrainmentModel ' "$work/entrainmentModels.log" \
 || { cat "$work/entrainmentModels.log"; fail "savageHutterFoam -listEntrainmentModels"; finish; exit 1; }

#- numIn <value> <bound>: status 0 when the number lies within the bound of
#  the listing (">= a", "> a", "<= b", "< b", "[a, b)" and the like,
#  "finite"), 1 when outside, 2 when the bound is of another form
numIn()
{
    awk -v v="$1" -v b="$2" 'BEGIN {
        gsub(/ /, "", b)
        if (b == "finite") exit 0
        if (b ~ /^>=/) { lo = substr(b, 3) + 0; exit !(v + 0 >= lo) }
        if (b ~ /^>/)  { lo = substr(b, 2) + 0; exit !(v + 0 >  lo) }
        if (b ~ /^<=/) { hi = substr(b, 3) + 0; exit !(v + 0 <= hi) }
        if (b ~ /^</)  { hi = substr(b, 2) + 0; exit !(v + 0 <  hi) }
        if (b ~ /^[[(][^,]+,[^,]+[])]$/) {
            lc = substr(b, 1, 1); hc = substr(b, length(b), 1)
            split(substr(b, 2, length(b) - 2), e, ",")
            lo = e[1] + 0; hi = e[2] + 0; x = v + 0
            ok = (lc == "[" ? x >= lo : x > lo) && (hc == "]" ? x <= hi : x < hi)
            exit !ok
        }
        exit 2
    }'
}

#- boundEnds <bound>: the finite ends of a bound, lines "lo|value|closed"
#  and "hi|value|closed" (closed yes or no)
boundEnds()
{
    awk -v b="$1" 'BEGIN {
        gsub(/ /, "", b)
        if (b ~ /^>=/) print "lo|" substr(b, 3) "|yes"
        else if (b ~ /^>/) print "lo|" substr(b, 2) "|no"
        else if (b ~ /^<=/) print "hi|" substr(b, 3) "|yes"
        else if (b ~ /^</) print "hi|" substr(b, 2) "|no"
        else if (b ~ /^[[(][^,]+,[^,]+[])]$/) {
            lc = substr(b, 1, 1); hc = substr(b, length(b), 1)
            split(substr(b, 2, length(b) - 2), e, ",")
            print "lo|" e[1] "|" (lc == "[" ? "yes" : "no")
            print "hi|" e[2] "|" (hc == "]" ? "yes" : "no")
        }
    }'
}

#- boundMark <value> <bound>: "!" outside the bound (must be rejected), "+"
#  on a closed end (must run), "" else
boundMark()
{
    numIn "$1" "$2"
    if [ $? -eq 1 ]; then echo "!"; return; fi
    local s e c
    while IFS='|' read -r s e c
    do
        [ "$c" = yes ] && awk -v a="$1" -v b="$e" 'BEGIN { exit !(a + 0 == b + 0) }' \
            && { echo "+"; return; }
    done < <(boundEnds "$2")
    echo ""
}

#- coeffExtras <bound> <required> <edges>: sets $extras, the variants of a
#  coefficient: every standard number marked by the bound (outside: must
#  be rejected "!"; on a closed end: must run "+"), just outside each end
#  (belowMin, aboveMax) and on it (atMin, atMax), missing (rejected when
#  required), non-numeric and nan rejected, and the model's edge cases
#  (",name=value!" or "+", as listed)
coeffExtras()
{
    local bound="$1" required="$2" edges="$3" name v side end closed
    local values=" " ev
    for ev in ${edges//,/ }
    do
        v="${ev#*=}"; v="${v%!}"; v="${v%+}"
        values="$values$v "
    done
    extras="-wrongType,wrongType=fuzzWord!,-nan,nan=nan!"
    [ "$required" = required ] && extras="$extras,-missing,missing=-!"
    for name in negative=-1 zero=0 huge=1e300 huge20=1e20
    do
        v="${name#*=}"
        extras="$extras,-${name%%=*},$name$(boundMark "$v" "$bound")"
    done
    while IFS='|' read -r side end closed
    do
        [ -n "$side" ] || continue
        local out
        if [ "$side" = lo ]
        then
            out="$(awk -v e="$end" 'BEGIN { d = (e < 0 ? -e : e); if (d < 1) d = 1; printf "%.6g", e - 1e-4*d }')"
            name=belowMin
        else
            out="$(awk -v e="$end" 'BEGIN { d = (e < 0 ? -e : e); if (d < 1) d = 1; printf "%.6g", e + 1e-4*d }')"
            name=aboveMax
        fi
        extras="$extras,$name=$out!"
        case " -1 0 1e300 1e20$values" in
        *" $end "*) ;;
        *) extras="$extras,at${name:5}=$end$(boundMark "$end" "$bound")" ;;
        esac
    done < <(boundEnds "$bound")
    numIn 0 "$bound"; [ $? -ne 2 ] || fail "-listEntrainmentModels: a bound of unknown form '$bound' (this test knows >=, >, <=, <, [a, b), finite)"
    extras="$extras$edges"
}

entCases=""
entKeywords=""
entFirst=""
entName=""
declare -A entEdges
declare -A entBound
coeffRe='^ *coefficient +([^ ]+) +([^ ]+) +(required|optional) +([^ ]+) +(finite|[<>]=? *[^ ]+|[[(][^],)]*, *[^],)]*[])]) +(.*)$'
edgeRe='^ *edge +([^ ]+) +([^ ]+) +([^ ]+) +(accepted|rejected) *$'
#- endModel: the case and keyword lines of the model read so far
endModel()
{
    [ -n "$entName" ] || return 0
    local M="$entName" key required
    entCases="$entCases$M|{$entEntries }
"
    if [ -n "$entKeys" ]
    then
        [ -n "$entFirst" ] || entFirst="$M"
        local dictExtras=""
        [ -z "${entRequired// /}" ] || dictExtras="|-missing,missing=-!"
        entKeywords="${entKeywords}savageHutterFoam|ent$M|$tp|${M}Coeffs|dict$dictExtras
savageHutterFoam|ent$M|$tp|${M}Coeffs/fuzzKeyword|unknown
"
        for key in $entKeys
        do
            required=optional
            [[ "$entRequired " == *" $key "* ]] && required=required
            coeffExtras "${entBound[$key]}" "$required" "${entEdges[$key]:-}"
            entKeywords="${entKeywords}savageHutterFoam|ent$M|$tp|${M}Coeffs/$key|num|$extras
"
        done
    else
        # A model without coefficients takes no <Model>Coeffs entries
        entKeywords="${entKeywords}savageHutterFoam|ent$M|$tp|${M}Coeffs|unknowndict
"
    fi
    entName=""
}
while IFS= read -r line
do
    if [[ $line =~ ^entrainmentModel\ +([^ ]+) ]]
    then
        endModel
        entName="${BASH_REMATCH[1]}"; entEntries=""; entKeys=""; entRequired=" "
        entEdges=(); entBound=()
    elif [ -n "$entName" ] && [[ $line =~ $coeffRe ]]
    then
        key="${BASH_REMATCH[1]}"
        entKeys="$entKeys $key"
        entEntries="$entEntries $key ${BASH_REMATCH[2]};"
        [ "${BASH_REMATCH[3]}" = required ] && entRequired="$entRequired$key "
        entBound[$key]="${BASH_REMATCH[5]}"
    elif [ -n "$entName" ] && [[ $line =~ $edgeRe ]]
    then
        # edge <name> <keyword> <value> accepted|rejected
        v="${BASH_REMATCH[1]}=${BASH_REMATCH[3]}+"
        [ "${BASH_REMATCH[4]}" = rejected ] && v="${BASH_REMATCH[1]}=${BASH_REMATCH[3]}!"
        entEdges[${BASH_REMATCH[2]}]="${entEdges[${BASH_REMATCH[2]}]:-},$v"
    elif [ -n "$entName" ] && [[ $line =~ ^\ *(coefficient|edge)\  ]]
    then
        fail "-listEntrainmentModels: a line of another form than this test reads: '$line'"
    fi
done < "$work/entrainmentModels.log"
endModel
[ -n "$entFirst" ] || { fail "no entrainment model with coefficients in savageHutterFoam -listEntrainmentModels"; finish; exit 1; }

#- The bed's cover: a field file's variants, range [0, 1e30] in every cell
#  (16 x 2 cells; a restart's files as well; values of 6 digits at most,
#  as foamDictionary writes them)
coverRange="-wrongType,wrongType=uniform (1 0 0)!,-nan,nan=uniform nan!,-negative,negative=uniform -1!,-huge,huge=uniform 1e300!,aboveMax=uniform 1.01e30!,oneCellNegative=nonuniform List<scalar> 32(0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 -0.001)!,oneCellNan=nonuniform List<scalar> 32(0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 nan 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1)!,-wrongSize,wrongSize=nonuniform List<scalar> 3(1 1 1)!,-misspeltValue,misspeltValue=uniformm 1!"
#  in 0/: 0 and 1e30 must run
coverRange0="$coverRange,-zero,zero=uniform 0+,atMax=uniform 1e30+"
dimsLength="-zero,zero=[0 0 0 0 0 0 0]!,-negative,negative=[0 -1 0 0 0 0 0]!"
dimsPerLength="-zero,zero=[0 0 0 0 0 0 0]!,-negative,right=[0 -1 0 0 0 0 0]+,metres=[0 1 0 0 0 0 0]!"
E="ent$entFirst"
entKeywords="${entKeywords}savageHutterFoam|$E|$tp|entrainmentModel|word:$entFirst
savageHutterFoam|entnone|0/hEntrainable|.|file
savageHutterFoam|$E|0/hEntrainable|.|file|-missing,missing=-!
savageHutterFoam|$E|0/hEntrainable|dimensions|dims|$dimsLength
savageHutterFoam|$E|0/hEntrainable|internalField|sfield|$coverRange0
savageHutterFoam|$E|0/hEntrainable|boundaryField|dict
savageHutterFoam|$E|0/hEntrainable|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|$E|0/cResistance|.|file
savageHutterFoam|$E|0/cResistance|dimensions|dims|$dimsPerLength
savageHutterFoam|$E|0/cResistance|internalField|sfield|$coverRange0
savageHutterFoam|$E|0/cResistance|boundaryField|dict
savageHutterFoam|$E|0/cResistance|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|restartCover|0.01/erodedDepth|.|file
savageHutterFoam|restartCover|0.01/erodedDepth|dimensions|dims|$dimsLength
savageHutterFoam|restartCover|0.01/erodedDepth|internalField|sfield|$coverRange
savageHutterFoam|restartCover|0.01/erodedDepth|boundaryField|dict
savageHutterFoam|restartCover|0.01/hEntrainable|.|file
savageHutterFoam|restartCover|0.01/hEntrainable|internalField|sfield|$coverRange
savageHutterFoam|restartCover|0.01/cResistance|.|file
savageHutterFoam|restartCover|0.01/cResistance|internalField|sfield|$coverRange
savageHutterFoam|restartPlan|0.01/erodedDepth|internalField|sfield|$coverRange
savageHutterFoam|restartPlan|0.01/HEntrainable|.|file
savageHutterFoam|restartPlan|0.01/HEntrainable|dimensions|dims|$dimsLength
savageHutterFoam|restartPlan|0.01/HEntrainable|internalField|sfield|$coverRange
savageHutterFoam|restartPlan|0.01/HErodedDepth|.|file
savageHutterFoam|restartPlan|0.01/HErodedDepth|dimensions|dims|$dimsLength
savageHutterFoam|restartPlan|0.01/HErodedDepth|internalField|sfield|$coverRange
"

#- clean <case>: no time directory but 0, no logs
clean()
{
    local t
    for t in "$1"/[0-9]*
    do
        case "${t##*/}" in 0|*orig*) ;; *) rm -rf "$t" ;; esac
    done
    rm -rf "$1"/log.* "$1/postProcessing"
}

#- coverField <case> <name> <dimensions> <value>: 0/<name> uniform value,
#  the boundary types of 0/h
coverField()
{
    sed -e "s/^\( *object  *\)h;/\1$2;/" -e "s/^dimensions .*/dimensions      $3;/" \
        "$1/0/h" > "$1/0/$2" \
    && setEntry "$1/0/$2" internalField "uniform $4"
}

#- runs <case>: savageHutterFoam runs there to End (set-up check)
runs()
{
    (cd "$1" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
        && grep -q '^End' "$1/log.savageHutterFoam" \
        || { echo "set-up: $1 does not run"; tail -n 20 "$1/log.savageHutterFoam"; return 1; }
    clean "$1"
}

(
    set -e
    pre="$work/pre"
    mkdir "$pre"
    cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$pre"/
    cd "$pre"
    setBlockCells 16 2
    setEntry system/controlDict endTime 0.02
    setEntry system/controlDict writeInterval 0.01
    runApplication blockMesh
    restore0Dir
    b="$work/base"
    cp -r "$pre" "$b"
    (cd "$b" && runApplication setAvalancheFields)
    runs "$b"

    # A case per friction law, and with activePassive where it has a
    # basal friction angle
    while IFS='|' read -r L entries angle
    do
        [ -n "$L" ] || continue
        d="$work/law$L"; cp -r "$b" "$d"
        setEntry "$d/$tp" frictionModel "$L"
        foamDictionary "$d/$tp" -entry CoulombCoeffs -remove > /dev/null
        setEntry "$d/$tp" "${L}Coeffs" "$entries"
        runs "$d"
        if [ "$angle" != none ]
        then
            cp -r "$d" "$work/ap$L"
            setEntry "$work/ap$L/$tp" earthPressure activePassive
            setEntry "$work/ap$L/$tp" phi 30
            runs "$work/ap$L"
        fi
    done <<< "$lawCases"

    # A case per entrainment model: every coefficient at its default, an
    # erodible layer 0/hEntrainable of 0.1 m and a resistance 0/cResistance
    # of 0.01 1/m (as 0/h, its boundary types)
    while IFS='|' read -r M entries
    do
        [ -n "$M" ] || continue
        d="$work/ent$M"; cp -r "$b" "$d"
        coverField "$d" hEntrainable '[0 1 0 0 0 0 0]' 0.1
        coverField "$d" cResistance '[0 -1 0 0 0 0 0]' 0.01
        setEntry "$d/$tp" entrainmentModel "$M"
        [ "$entries" = "{ }" ] || setEntry "$d/$tp" "${M}Coeffs" "$entries"
        runs "$d"
    done <<< "$entCases"

    # Restarts with the cover: the first model with coefficients run to
    # 0.01, restarted from there to 0.02; in slope and in plan coordinates
    # (the latter writes HEntrainable and HErodedDepth)
    for c in restartCover restartPlan
    do
        d="$work/$c"; cp -r "$work/ent$entFirst" "$d"
        if [ "$c" = restartPlan ]
        then
            setEntry "$d/$tp" coordinates plan
            foamDictionary "$d/$tp" -entry inclination -remove > /dev/null
        fi
        setEntry "$d/$cd_" endTime 0.01
        runs "$d"
        (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
        [ -f "$d/0.01/erodedDepth" ] && [ -f "$d/0.01/cResistance" ] \
            && { [ "$c" = restartCover ] || [ -f "$d/0.01/HErodedDepth" ]; } \
            || { echo "set-up: $d wrote no 0.01 with the cover"; exit 1; }
        rm -rf "$d"/log.* "$d/postProcessing"
        setEntry "$d/$cd_" endTime 0.02
        setEntry "$d/$cd_" startFrom latestTime
        (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
            && grep -q '^End' "$d/log.savageHutterFoam" \
            || { echo "set-up: $d does not restart"; tail -n 20 "$d/log.savageHutterFoam"; exit 1; }
        rm -rf "$d/0.02" "$d"/log.* "$d/postProcessing"
        echo 0.01 > "$d/.keep"
    done

    d="$work/ap"; cp -r "$b" "$d"
    setEntry "$d/$tp" earthPressure activePassive
    runs "$d"

    d="$work/jet"; cp -r "$b" "$d"
    echo "$fvOptionsHeader jet { $jetEntries }" > "$d/$fo"
    runs "$d"

    d="$work/jetCoeffs"; cp -r "$b" "$d"
    echo "$fvOptionsHeader jet { $jetOuter impingingJetCoeffs { $jetCoeffs } }" > "$d/$fo"
    runs "$d"

    d="$work/jetConstant"; cp -r "$b" "$d"
    echo "$fvOptionsHeader jet { $jetEntries }" > "$d/$foc"
    runs "$d"

    d="$work/table"; cp -r "$b" "$d"
    setEntry "$d/$tp" inclination 'table ((-12.8 40) (0 35) (12.8 30))'
    runs "$d"

    d="$work/timeStep"; cp -r "$b" "$d"
    setEntry "$d/$cd_" writeControl timeStep
    setEntry "$d/$cd_" writeInterval 1
    runs "$d"

    d="$work/clockTime"; cp -r "$b" "$d"
    setEntry "$d/$cd_" writeControl clockTime
    setEntry "$d/$cd_" writeInterval 1
    runs "$d"

    d="$work/fixedDt"; cp -r "$b" "$d"
    setEntry "$d/$cd_" adjustTimeStep no
    setEntry "$d/$cd_" deltaT 0.001
    runs "$d"

    # A restart: 0 -> 0.01 written, then latestTime -> 0.02; .keep names
    # the time directories that are no output of a variant
    d="$work/restart"; cp -r "$b" "$d"
    setEntry "$d/$cd_" endTime 0.01
    setEntry "$d/$tp" rho 1500
    runs "$d"
    (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    [ -f "$d/0.01/hU" ] && [ -f "$d/0.01/uniform/writeGrid" ] \
        && [ -f "$d/0.01/pMax" ] && [ -f "$d/0.01/tArrival" ] \
        || { echo "set-up: $d wrote no 0.01"; exit 1; }
    rm -rf "$d"/log.* "$d/postProcessing"
    setEntry "$d/$cd_" endTime 0.02
    setEntry "$d/$cd_" startFrom latestTime
    echo 0.01 > "$d/.keep"

    d="$work/zb"; cp -r "$b" "$d"
    echo 'FoamFile { version 2.0; format ascii; class dictionary; object zbDict; }
zb ( plane { gradient (0.02 0.05); } );' > "$d/system/zbDict"
    (cd "$d" && runApplication setAvalancheFields -dict system/zbDict)
    runs "$d"

    d="$work/inflow"; cp -r "$b" "$d"
    setEntry "$d/0/h" boundaryField/upslope '{ type fixedValue; value uniform 1; }'
    setEntry "$d/0/U" boundaryField/upslope '{ type fixedValue; value uniform (1 0 0); }'
    runs "$d"

    # Uniform fields: they fit a mesh of any size
    d="$work/mesh"; cp -r "$pre" "$d"
    setEntry "$d/0/h" internalField 'uniform 1'
    runs "$d"
) > "$work/setup.log" 2>&1 || { cat "$work/setup.log"; fail "setting up the cases (the log above)"; finish; exit 1; }

# -- The keywords -------------------------------------------------------------
# app|case|file|entry|kind|extras
#   kind: num (a number), fn1 (a Function1: constant <number>), word:<value>
#   (a name from a set), switch:<value>, dict (a sub-dictionary), optnum and
#   optswitch:<value> (absent from the case, optional: no missing or
#   misspelt variant), dims, sfield/vfield (an internalField or a patch
#   value), vec/vec2 (a vector, a 2D vector), list (a list of shapes of
#   setAvalancheFieldsDict), count (a cell count of blockMeshDict), block
#   (blockMeshDict's block)
#   extras: comma-separated name=value variants (name=value!: it must be
#   rejected; name=value+: it must run, OK), -name: a standard variant left
#   out; kinds unknown (a keyword set that the dictionary does not know)
#   and unknowndict (<Model>Coeffs of a model without coefficients)
#   app blockMesh: blockMesh, then savageHutterFoam on what it made
keywords="
savageHutterFoam|base|$tp|g|num
savageHutterFoam|base|$tp|epsilon|num
savageHutterFoam|base|$tp|lambda|num
savageHutterFoam|base|$tp|inclination|fn1
savageHutterFoam|table|$tp|inclination|table
savageHutterFoam|base|$tp|earthPressure|word:isotropic
savageHutterFoam|base|$tp|phi|num
savageHutterFoam|base|$tp|frictionModel|word:Coulomb
savageHutterFoam|base|$tp|rho|optnum
savageHutterFoam|base|$tp|arrivalThreshold|optnum
savageHutterFoam|ap|$tp|earthPressure|word:activePassive
savageHutterFoam|ap|$tp|phi|num|belowDelta=20!
savageHutterFoam|base|$fs|savageHutter|dict
savageHutterFoam|base|$fs|savageHutter/limiter|word:minmod
savageHutterFoam|base|$fs|savageHutter/stoppingCriterion|switch:on
savageHutterFoam|base|$fs|savageHutter/staticResistance|switch:on
savageHutterFoam|base|$fs|savageHutter/hDry|num
savageHutterFoam|base|$fs|savageHutter/holdResting|optswitch:on
savageHutterFoam|base|$fs|savageHutter/steadyStateTolerance|optnum
savageHutterFoam|base|$cd_|startFrom|word:startTime
savageHutterFoam|base|$cd_|startTime|num
savageHutterFoam|base|$cd_|stopAt|word:endTime
savageHutterFoam|base|$cd_|endTime|num|-huge20
savageHutterFoam|base|$cd_|deltaT|num
savageHutterFoam|base|$cd_|adjustTimeStep|switch:yes
savageHutterFoam|base|$cd_|maxCo|num
savageHutterFoam|base|$cd_|maxDeltaT|optnum|tiny=1e-200!,firstWrite=1e-11!
savageHutterFoam|base|$cd_|writeControl|word:adjustableRunTime
savageHutterFoam|base|$cd_|writeInterval|num|tiny=1e-12!
savageHutterFoam|base|$cd_|purgeWrite|num
savageHutterFoam|base|$cd_|writeFormat|word:ascii
savageHutterFoam|base|$cd_|writePrecision|num
savageHutterFoam|base|$cd_|writeCompression|word:off
savageHutterFoam|base|$cd_|timeFormat|word:general
savageHutterFoam|base|$cd_|timePrecision|num
savageHutterFoam|base|$cd_|runTimeModifiable|switch:false
savageHutterFoam|timeStep|$cd_|writeInterval|num|fraction=2.5!,large=2e9,aboveLabelMax=3e9!
savageHutterFoam|timeStep|$cd_|maxDeltaT|optnum|tiny=1e-200!,small=1e-12!
savageHutterFoam|timeStep|$tp|g|num
savageHutterFoam|timeStep|$tp|epsilon|num
savageHutterFoam|timeStep|0/h|internalField|sfield
savageHutterFoam|timeStep|0/U|internalField|vfield|light=uniform (3e8 0 0)!
savageHutterFoam|clockTime|$cd_|writeInterval|num|tiny=1e-12!,half=0.5!,one=1
savageHutterFoam|clockTime|$cd_|maxDeltaT|optnum|tiny=1e-200!
savageHutterFoam|fixedDt|$cd_|deltaT|num|tiny=1e-200!,small=1e-12!
savageHutterFoam|fixedDt|$cd_|endTime|num
savageHutterFoam|jet|$fo|jet|dict
savageHutterFoam|jet|$fo|jet/type|word:impingingJet
savageHutterFoam|jet|$fo|jet/active|switch:yes
savageHutterFoam|jet|$fo|jet/centre|vec|onCellCentre=(0.8 0.8 0)!,outside=(20 0 0)!
savageHutterFoam|jet|$fo|jet/R|num
savageHutterFoam|jet|$fo|jet/R_imp|num|noCellInside=0.5!
savageHutterFoam|jet|$fo|jet/u_jet|num|light=3e8!
savageHutterFoam|jet|$fo|jet/selectionMode|word:all|cellSet=cellSet!
savageHutterFoam|jetCoeffs|$fo|jet/type|word:impingingJet
savageHutterFoam|jetCoeffs|$fo|jet/selectionMode|word:all
savageHutterFoam|jetCoeffs|$fo|jet/impingingJetCoeffs|dict
savageHutterFoam|jetCoeffs|$fo|jet/impingingJetCoeffs/centre|vec|outside=(20 0 0)!
savageHutterFoam|jetCoeffs|$fo|jet/impingingJetCoeffs/R|num
savageHutterFoam|jetCoeffs|$fo|jet/impingingJetCoeffs/R_imp|num
savageHutterFoam|jetCoeffs|$fo|jet/impingingJetCoeffs/u_jet|num|light=3e8!
savageHutterFoam|jetConstant|$foc|jet|dict
savageHutterFoam|jetConstant|$foc|jet/type|word:impingingJet
savageHutterFoam|jetConstant|$foc|jet/active|switch:yes
savageHutterFoam|jetConstant|$foc|jet/selectionMode|word:all
savageHutterFoam|jetConstant|$foc|jet/centre|vec|onCellCentre=(0.8 0.8 0)!
savageHutterFoam|jetConstant|$foc|jet/R|num
savageHutterFoam|jetConstant|$foc|jet/R_imp|num
savageHutterFoam|jetConstant|$foc|jet/u_jet|num
savageHutterFoam|jetConstant|$foc|.|both
savageHutterFoam|base|0/h|dimensions|dims
savageHutterFoam|base|0/h|internalField|sfield
savageHutterFoam|base|0/h|boundaryField|dict
savageHutterFoam|base|0/h|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|base|0/h|boundaryField/downslope/type|word:zeroGradient
savageHutterFoam|base|0/h|boundaryField/sides/type|word:zeroGradient
savageHutterFoam|base|0/h|boundaryField/frontAndBack/type|word:empty
savageHutterFoam|base|0/U|dimensions|dims
savageHutterFoam|base|0/U|internalField|vfield
savageHutterFoam|base|0/U|boundaryField|dict
savageHutterFoam|base|0/U|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|base|0/U|boundaryField/downslope/type|word:zeroGradient
savageHutterFoam|base|0/U|boundaryField/sides/type|word:slip
savageHutterFoam|base|0/U|boundaryField/frontAndBack/type|word:empty
savageHutterFoam|zb|0/zb|dimensions|dims
savageHutterFoam|zb|0/zb|internalField|sfield
savageHutterFoam|zb|0/zb|boundaryField|dict
savageHutterFoam|zb|0/zb|boundaryField/upslope/type|word:zeroGradient
savageHutterFoam|zb|0/zb|boundaryField/downslope/type|word:zeroGradient
savageHutterFoam|zb|0/zb|boundaryField/sides/type|word:zeroGradient
savageHutterFoam|inflow|0/h|boundaryField/upslope/value|sfield
savageHutterFoam|inflow|0/U|boundaryField/upslope/value|vfield|light=uniform (3e8 0 0)!
savageHutterFoam|restart|0.01/h|.|file
savageHutterFoam|restart|0.01/h|dimensions|dims
savageHutterFoam|restart|0.01/h|internalField|sfield
savageHutterFoam|restart|0.01/h|boundaryField|dict
savageHutterFoam|restart|0.01/U|.|file
savageHutterFoam|restart|0.01/U|dimensions|dims
savageHutterFoam|restart|0.01/U|internalField|vfield
savageHutterFoam|restart|0.01/U|boundaryField|dict
savageHutterFoam|restart|0.01/hU|.|file
savageHutterFoam|restart|0.01/hU|dimensions|dims
savageHutterFoam|restart|0.01/hU|internalField|vfield
savageHutterFoam|restart|0.01/hU|boundaryField|dict
savageHutterFoam|restart|0.01/hMax|.|file
savageHutterFoam|restart|0.01/hMax|dimensions|dims
savageHutterFoam|restart|0.01/hMax|internalField|sfield
savageHutterFoam|restart|0.01/hMax|boundaryField|dict
savageHutterFoam|restart|0.01/UMax|.|file
savageHutterFoam|restart|0.01/UMax|dimensions|dims
savageHutterFoam|restart|0.01/UMax|internalField|sfield
savageHutterFoam|restart|0.01/UMax|boundaryField|dict
savageHutterFoam|restart|0.01/pMax|.|file
savageHutterFoam|restart|0.01/pMax|dimensions|dims
savageHutterFoam|restart|0.01/pMax|internalField|sfield
savageHutterFoam|restart|0.01/pMax|boundaryField|dict
savageHutterFoam|restart|0.01/tArrival|.|file
savageHutterFoam|restart|0.01/tArrival|dimensions|dims
savageHutterFoam|restart|0.01/tArrival|internalField|sfield
savageHutterFoam|restart|0.01/tArrival|boundaryField|dict
savageHutterFoam|restart|$tp|arrivalThreshold|optnum
savageHutterFoam|restart|0.01/uniform/time|.|file
savageHutterFoam|restart|0.01/uniform/time|value|num|offName=0.0100001!,withinName=0.0100000001
savageHutterFoam|restart|0.01/uniform/time|name|str
savageHutterFoam|restart|0.01/uniform/time|index|num
savageHutterFoam|restart|0.01/uniform/time|deltaT|num
savageHutterFoam|restart|0.01/uniform/time|deltaT0|num
savageHutterFoam|restart|0.01/uniform/writeGrid|.|file
savageHutterFoam|restart|0.01/uniform/writeGrid|origin|num|afterStart=0.015!
blockMesh|mesh|$bm|nx|count|fraction=1.5,one=1,stale=8!
blockMesh|mesh|$bm|ny|count
blockMesh|mesh|$bm|convertToMeters|optnum
blockMesh|mesh|$bm|blocks|block
setAvalancheFields|pre|$sa|h|list
setAvalancheFields|pre|$sa|h/damBreak|dict
setAvalancheFields|pre|$sa|h/damBreak/position|num
setAvalancheFields|pre|$sa|h/damBreak/upstream|num
setAvalancheFields|pre|$sa|h/damBreak/downstream|num
setAvalancheFields|pre|$sa|h/hemisphere/centre|vec2
setAvalancheFields|pre|$sa|h/hemisphere/radius|num
setAvalancheFields|pre|$sa|h/cone/centre|vec2
setAvalancheFields|pre|$sa|h/cone/radius|num
setAvalancheFields|pre|$sa|h/cone/height|num
setAvalancheFields|pre|$sa|h/paraboloid/centre|vec2
setAvalancheFields|pre|$sa|h/paraboloid/radius|num
setAvalancheFields|pre|$sa|h/paraboloid/height|num
setAvalancheFields|pre|$sa|h/box/min|vec2
setAvalancheFields|pre|$sa|h/box/max|vec2
setAvalancheFields|pre|$sa|h/box/value|num
setAvalancheFields|pre|$sa|h/gaussian/centre|vec2
setAvalancheFields|pre|$sa|h/gaussian/amplitude|num
setAvalancheFields|pre|$sa|h/gaussian/width|num
setAvalancheFields|pre|$sa|zb|list
setAvalancheFields|pre|$sa|zb/plane/origin|vec2
setAvalancheFields|pre|$sa|zb/plane/value|num
setAvalancheFields|pre|$sa|zb/plane/gradient|vec2
setAvalancheFields|pre|$sa|zb/bowl/centre|vec2
setAvalancheFields|pre|$sa|zb/bowl/slope|num
setAvalancheFields|pre|$sa|zb/channel/axis|num
setAvalancheFields|pre|$sa|zb/channel/curvature|num
setAvalancheFields|pre|$sa|U|list
setAvalancheFields|pre|$sa|U/box/min|vec2
setAvalancheFields|pre|$sa|U/box/max|vec2
setAvalancheFields|pre|$sa|U/box/value|vec
setAvalancheFields|pre|$sa|U/damBreak/position|num
setAvalancheFields|pre|$sa|U/damBreak/upstream|vec
setAvalancheFields|pre|$sa|U/damBreak/downstream|vec
setAvalancheFields|pre|0/h|internalField|sfield
"
# The friction laws' lines (from savageHutterFoam -listFrictionLaws, above)
# and the entrainment models' and the bed's cover's (-listEntrainmentModels)
keywords="$keywords
$lawKeywords
$entKeywords"

#- variants <kind> <extras>: lines "name|value"; value "-" removes the
#  entry, "~" renames the keyword (misspelt)
variants()
{
    local kind="${1%%:*}" val="${1#*:}" extras="$2"
    local list=""
    case "$kind" in
    num|optnum|count)
        list="missing|-
wrongType|fuzzWord
nan|nan
negative|-1
zero|0
huge|1e300
huge20|1e20
misspelt|~"
        ;;
    fn1)
        list="missing|-
wrongType|(1 2)
nan|constant nan
negative|constant -1
zero|constant 0
huge|constant 1e300
huge20|constant 1e20
misspelt|~
misspeltValue|constnt 40"
        ;;
    word|switch|optswitch)
        list="missing|-
wrongType|1.5
nan|nan
negative|-1
zero|0
huge|1e300
misspelt|~
misspeltValue|${val}x"
        ;;
    dict|list)
        list="missing|-
wrongType|fuzzWord
nan|nan
negative|-1
zero|0
huge|1e300
misspelt|~"
        ;;
    dims)
        list="missing|-
wrongType|fuzzWord
nan|[0 nan 0 0 0 0 0]
negative|[0 -1 0 0 0 0 0]
zero|[0 0 0 0 0 0 0]
huge|[0 1e300 0 0 0 0 0]
misspelt|~"
        ;;
    sfield)
        list="missing|-
wrongType|uniform (1 0 0)
nan|uniform nan
negative|uniform -1
zero|uniform 0
huge|uniform 1e300
huge20|uniform 1e20
misspelt|~
misspeltValue|uniformm 1
wrongSize|nonuniform List<scalar> 3(1 1 1)"
        ;;
    vfield)
        list="missing|-
wrongType|uniform 1
nan|uniform (nan 0 0)
negative|uniform (-1 0 0)
zero|uniform (0 0 0)
huge|uniform (1e300 0 0)
huge20|uniform (1e20 0 0)
misspelt|~
misspeltValue|uniformm (0 0 0)
wrongSize|nonuniform List<vector> 3((1 0 0) (1 0 0) (1 0 0))"
        ;;
    vec)
        list="missing|-
wrongType|fuzzWord
nan|(nan 0 0)
negative|(-1 -1 0)
zero|(0 0 0)
huge|(1e300 0 0)
huge20|(1e20 0 0)
misspelt|~
wrongSize|(0 0)"
        ;;
    vec2)
        list="missing|-
wrongType|fuzzWord
nan|(nan 0)
negative|(-1 -1)
zero|(0 0)
huge|(1e300 0)
huge20|(1e20 0)
misspelt|~
wrongSize|(0 0 0)"
        ;;
    table)
        # The table form of a Function1 (x ascending, zeta in degrees)
        list="missing|-
empty|table ()!
one|table ((0 35))
negative|table ((-12.8 -30) (12.8 -10))
zero|table ((-12.8 0) (12.8 0))
unsorted|table ((0 35) (-5 40) (12.8 30))!
duplicateX|table ((-12.8 40) (0 35) (0 30) (12.8 30))!
ninety|table ((-12.8 90) (12.8 30))!
minusNinety|table ((-12.8 30) (12.8 -90))!
above90|table ((-12.8 40) (12.8 95))!
above90BetweenCentres|table ((-0.1 0) (0 95) (0.1 0))!
nan|table ((0 nan))!
wrongType|table fuzzWord!
wrongTuple|table ((0 35 1))!
shortTuple|table ((0))!
notTuples|table (0 35)!
huge|table ((0 1e300))!
huge20|table ((0 1e20))!
hugeX|table ((1e300 35))
misspelt|~
misspeltValue|tabel ((0 35))!"
        ;;
    str)
        list="missing|-
wrongType|1.5
otherTime|\"0.02\"
misspelt|~"
        ;;
    file)
        # A whole file of a start time directory
        list="missing|-
empty|empty
noHeader|noHeader
wrongClass|wrongClass
truncated|truncated"
        ;;
    both)
        list="both|both!"
        ;;
    unknown)
        # A keyword the dictionary does not know (in <Model>Coeffs)
        list="unknown|1!"
        ;;
    unknowndict)
        # <Model>Coeffs of a model without coefficients: empty, or with a
        # keyword
        list="empty|{ }
unknown|{ fuzzKeyword 1; }!"
        ;;
    block)
        list="missing|-
wrongType|fuzzWord
3D|nz2
zeroCellsInZ|nz0
graded|graded
skewed|skewed
twoBlocks|twoBlocks
rotated|rotated
named|named"
        ;;
    esac
    if [ "$kind" = optnum ] || [ "$kind" = optswitch ]
    then
        list="$(grep -v '^missing|\|^misspelt|' <<< "$list")"
    fi
    local e
    IFS=',' read -r -a e <<< "$extras"
    for x in "${e[@]}"
    do
        case "$x" in
        -*) list="$(grep -v "^${x#-}|" <<< "$list")" ;;
        esac
    done
    echo "$list"
    for x in "${e[@]}"
    do
        case "$x" in
        -*|"") ;;
        *) echo "${x%%=*}|${x#*=}" ;;
        esac
    done
}

#- misspell <keyword>: sets $misspelt, one letter doubled inside the name
misspell()
{
    local k="$1"
    if [ ${#k} -ge 2 ]
    then
        misspelt="${k:0:2}${k:1}"
    else
        misspelt="${k}${k}"
    fi
}

#- shapeEntries <list/shape>: the entries of a shape in the variants
shapeEntries()
{
    case "$1" in
    h/damBreak) echo "position 0; upstream 10; downstream 0;" ;;
    h/hemisphere) echo "centre (0 0); radius 3;" ;;
    h/cone|h/paraboloid) echo "centre (0 0); radius 3; height 1;" ;;
    h/box) echo "min (-2 -2); max (2 2); value 1;" ;;
    h/gaussian) echo "centre (0 0); amplitude 1; width 2;" ;;
    zb/plane) echo "origin (0 0); value 0; gradient (0.1 0);" ;;
    zb/bowl) echo "centre (0 0); slope 0.5;" ;;
    zb/channel) echo "axis 0; curvature 0.1;" ;;
    U/box) echo "min (-2 -2); max (2 2); value (1 0 0);" ;;
    U/damBreak) echo "position 0; upstream (1 0 0); downstream (0 0 0);" ;;
    esac
}

#- withEntry <entries> <key> <value>: sets $entries to the entries with
#  key removed (-), renamed (~<new>) or set to value
withEntry()
{
    local in="$1" key="$2" value="$3" out="" e k
    local IFS=';'
    for e in $in
    do
        e="${e# }"
        [ -n "$e" ] || continue
        k="${e%% *}"
        if [ "$k" = "$key" ]
        then
            case "$value" in
            -) ;;
            "~"*) out="$out ${value#\~} ${e#* };" ;;
            *) out="$out $key $value;" ;;
            esac
        else
            out="$out $e;"
        fi
    done
    entries="$out"
}

#- saDict <file> <entry> <value>: setAvalancheFieldsDict with one entry
#  changed; a zb or U shape comes with the damBreak h, so that a refusal
#  must leave both as they were
saDict()
{
    local file="$1" entry="$2" value="$3"
    local hDam="h ( damBreak { $(shapeEntries h/damBreak) } );"
    local list="${entry%%/*}" body entries
    case "$entry" in
    */*/*)
        local shape="${entry#*/}"
        shape="${shape%%/*}"
        withEntry "$(shapeEntries "$list/$shape")" "${entry##*/}" "$value"
        body="$list ( $shape {$entries } );"
        ;;
    */*)
        local shape="${entry#*/}" inner
        inner="$(shapeEntries "$list/$shape")"
        case "$value" in
        -) body="$list ( );" ;;
        "~"*) body="$list ( ${value#\~} { $inner } );" ;;
        *) body="$list ( $value );" ;;
        esac
        ;;
    *)
        local shape
        case "$list" in h) shape=damBreak ;; zb) shape=plane ;; U) shape=box ;; esac
        case "$value" in
        -) body="" ;;
        "~"*) body="${value#\~} ( $shape { $(shapeEntries "$list/$shape") } );" ;;
        *) body="$list $value;" ;;
        esac
        ;;
    esac
    [ "$list" = h ] || body="$hDam
$body"
    printf '%s\n%s\n' 'FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }' "$body" > "$file"
}

#- fvDict <file> <entry> <value> <form>: fvOptions with one entry of the
#  jet changed; form direct (the coefficients in the entry) or coeffs (in
#  its impingingJetCoeffs)
fvDict()
{
    local file="$1" entry="$2" value="$3" form="$4" body entries inner
    local whole="$jetEntries"
    [ "$form" = coeffs ] && whole="$jetOuter impingingJetCoeffs { $jetCoeffs }"
    case "$entry" in
    jet/impingingJetCoeffs/*)
        withEntry "$jetCoeffs" "${entry##*/}" "$value"
        body="jet { $jetOuter impingingJetCoeffs {$entries } }"
        ;;
    jet/impingingJetCoeffs)
        case "$value" in
        -) body="jet { $jetOuter }" ;;
        "~"*) body="jet { $jetOuter ${value#\~} { $jetCoeffs } }" ;;
        *) body="jet { $jetOuter impingingJetCoeffs $value; }" ;;
        esac
        ;;
    jet/*)
        if [ "$form" = coeffs ]
        then
            withEntry "$jetOuter" "${entry#jet/}" "$value"
            body="jet {$entries impingingJetCoeffs { $jetCoeffs } }"
        else
            withEntry "$jetEntries" "${entry#jet/}" "$value"
            body="jet {$entries }"
        fi
        ;;
    jet)
        case "$value" in
        -) body="" ;;
        "~"*) body="${value#\~} { $whole }" ;;
        *) body="jet $value;" ;;
        esac
        ;;
    esac
    printf '%s\n%s\n' "$fvOptionsHeader" "$body" > "$file"
}

#- fileVariant <path> <vname>: a whole file of a time directory removed,
#  emptied, without its header, of another class or cut short
fileVariant()
{
    local f="$1"
    case "$2" in
    missing) rm -f "$f" ;;
    empty) : > "$f" ;;
    noHeader) echo "fuzzWord" > "$f" ;;
    wrongClass) sed -i '0,/^ *class /s/^\( *class  *\)[A-Za-z<>]*;/\1volTensorField;/' "$f" ;;
    truncated) truncate -s $(($(stat -c %s "$f") / 2)) "$f" ;;
    both) cp "$f" "${f/constant/system}" ;;
    esac
}

#- bmDict <file> <entry> <vname> <value>: blockMeshDict with nx, ny,
#  convertToMeters or the block changed
bmDict()
{
    local file="$1" entry="$2" vname="$3" value="$4"
    local hex='hex (0 1 2 3 4 5 6 7) ($nx $ny 1) simpleGrading (1 1 1)'
    case "$entry" in
    nx|ny|convertToMeters)
        case "$value" in
        -) sed -i "/^$entry .*;/d" "$file" ;;
        "~"*) sed -i "s/^$entry /${value#\~} /" "$file" ;;
        *)
            if grep -q "^$entry " "$file"
            then
                sed -i "s/^$entry .*;/$entry $value;/" "$file"
            else
                sed -i "s/^nx /$entry $value;\nnx /" "$file"
            fi
            ;;
        esac
        ;;
    blocks)
        case "$vname" in
        missing) sed -i '/^blocks/,/^);/d' "$file" ;;
        wrongType) sed -i '/^blocks/,/^);/c blocks fuzzWord;' "$file" ;;
        3D) sed -i 's/(\$nx \$ny 1)/($nx $ny 2)/' "$file" ;;
        zeroCellsInZ) sed -i 's/(\$nx \$ny 1)/($nx $ny 0)/' "$file" ;;
        graded) sed -i 's/simpleGrading (1 1 1)/simpleGrading (2 1 1)/' "$file" ;;
        skewed)
            # The yMax side tilted: not a rectangle
            sed -i -e 's/(12.8 1.6 0) (-12.8 1.6 0)/(12.8 2.6 0) (-12.8 1.6 0)/' \
                   -e 's/(12.8 1.6 1) (-12.8 1.6 1)/(12.8 2.6 1) (-12.8 1.6 1)/' "$file"
            ;;
        twoBlocks)
            # Two blocks side by side, x < 0 and x > 0
            sed -i -e '/^vertices/,/^);/c vertices ( (-12.8 -1.6 0) (0 -1.6 0) (0 1.6 0) (-12.8 1.6 0) (-12.8 -1.6 1) (0 -1.6 1) (0 1.6 1) (-12.8 1.6 1) (12.8 -1.6 0) (12.8 1.6 0) (12.8 -1.6 1) (12.8 1.6 1) );' \
                   -e '/^blocks/,/^);/c blocks ( hex (0 1 2 3 4 5 6 7) (8 2 1) simpleGrading (1 1 1) hex (1 8 9 2 5 10 11 6) (8 2 1) simpleGrading (1 1 1) );' \
                   -e '/^boundary/,/^);/c boundary ( upslope { type patch; faces ((0 4 7 3)); } downslope { type patch; faces ((8 9 11 10)); } sides { type wall; faces ((0 1 5 4) (1 8 10 5) (3 7 6 2) (2 6 11 9)); } frontAndBack { type empty; faces ((0 3 2 1) (1 2 9 8) (4 5 6 7) (5 10 11 6)); } );' "$file"
            ;;
        rotated) sed -i 's/hex (0 1 2 3 4 5 6 7) (\$nx \$ny 1)/hex (1 2 3 0 5 6 7 4) ($ny $nx 1)/' "$file" ;;
        named) sed -i 's/hex (0 1 2 3 4 5 6 7) /hex (0 1 2 3 4 5 6 7) release /' "$file" ;;
        esac
        ;;
    esac
}

#- makeVariant <case> <file> <entry> <vname> <value> <prepared case>
makeVariant()
{
    local d="$1" file="$2" entry="$3" vname="$4" value="$5" from="$6"
    local key="${entry##*/}" parent=""
    [ "$key" = "$entry" ] || parent="${entry%/*}/"
    if [ "$entry" = . ]
    then
        fileVariant "$d/$file" "$vname"
        return
    fi
    case "$file" in
    "$sa") saDict "$d/$file" "$entry" "$value"; return ;;
    "$fo"|"$foc")
        local form=direct
        [ "$from" = jetCoeffs ] && form=coeffs
        fvDict "$d/$file" "$entry" "$value" "$form"
        return
        ;;
    "$bm") bmDict "$d/$file" "$entry" "$vname" "$value"; return ;;
    esac
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
    nonuniform*nan*)
        # foamDictionary cannot read a list with nan: the internalField
        # written in place
        [ "$entry" = internalField ] || return 1
        FUZZ_VALUE="$value" perl -0pi -e 's/\binternalField\b[^;]*;/internalField   $ENV{FUZZ_VALUE};/' "$d/$file" \
            && grep -qF "$value" "$d/$file"
        ;;
    *)
        foamDictionary "$d/$file" -entry "$entry" -set "$value" > /dev/null
        ;;
    esac
}

endRe=$'(^|\n)End'
# Lines of a log that show a stack trace or a crash
traceRe=$'(Stack trace|stack trace|printStack|sigFpe::sigHandler|sigSegv::sigHandler|Segmentation fault|core dumped|(^|\n) *#[0-9]+ )'

#- classify <case> <app> <log> <rc> <keyword pattern>...: sets $outcome to
#  "OK <what>", "REJECTED <what>" or "BAD <what was wrong>"
classify()
{
    local d="$1" app="$2" log="$3" rc="$4"
    shift 4
    local written="" t keep=""
    [ -f "$d/.keep" ] && read -r keep < "$d/.keep"
    for t in "$d"/[0-9]*
    do
        [ -d "$t" ] || continue
        case "${t##*/}" in
        0|*orig*|"$keep") ;;
        *) written="$written ${t##*/}" ;;
        esac
    done
    written="${written# }"
    local text=""
    IFS= read -r -d '' text < "$log"
    local trace=""
    [[ $text =~ $traceRe ]] && trace=yes
    if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]
    then
        outcome="BAD did not finish within $limit s"
        return
    fi
    local problems=""
    if [ "$rc" -eq 0 ]
    then
        [[ $text =~ $endRe ]] || problems="$problems no 'End' in the log;"
        [ -z "$trace" ] || problems="$problems a stack trace;"
        local dirs=()
        if [ "$app" = setAvalancheFields ]
        then
            dirs=("$d/0")
        else
            for t in $written; do dirs+=("$d/$t"); done
        fi
        if [ ${#dirs[@]} -gt 0 ]
        then
            local bad
            bad="$(grep -rliwE 'nan|-?inf|infinity' -- "${dirs[@]}" 2>/dev/null)"
            bad="${bad//$d\//}"
            bad="${bad//$'\n'/ }"
            [ -z "$bad" ] || problems="$problems non-finite values in $bad;"
        fi
        if [ -z "$problems" ]
        then
            if [ "$app" = setAvalancheFields ]
            then
                outcome="OK wrote 0/"
            else
                outcome="OK wrote ${written:-nothing}"
            fi
        else
            outcome="BAD exit 0 but$problems"
        fi
        return
    fi
    [ "$rc" -lt 128 ] || problems="$problems killed by signal $((rc - 128));"
    [[ $text == *"FOAM FATAL"* ]] || problems="$problems no FOAM FATAL message;"
    [ -z "$trace" ] || problems="$problems a stack trace;"
    [ -z "$written" ] || problems="$problems wrote $written;"
    if [ "$app" = setAvalancheFields ] && ! diff -rq "$d/0" "$d/before.0" > /dev/null
    then
        problems="$problems changed 0/;"
    fi
    # The keyword, in the message (from the FOAM FATAL line on)
    local message="${text#*FOAM FATAL}" p args=()
    for p in "$@"
    do
        args+=(-e "$p")
    done
    grep -qwF "${args[@]}" <<< "$message" \
        || problems="$problems the message does not name '$*';"
    if [ -z "$problems" ]
    then
        local line="${message#*$'\n'}"
        line="${line%%$'\n'*}"
        line="${line#"${line%%[! ]*}"}"
        outcome="REJECTED ${line:0:70}"
    else
        outcome="BAD exit $rc:$problems"
    fi
}

# -- Known BAD variants --------------------------------------------------------
# Reported, not fixed: each prints a KNOWN line and counts in the table; one
# that stops being BAD prints a PASS line asking for its removal from this
# list.  (app:file:entry:variant)
known="
"

# -- Run the variants ---------------------------------------------------------
#- runVariant <n> <app> <case> <file> <entry> <kind> <vname> <value>: writes
#  the outcome line to $work/result.<n>
runVariant()
{
    local n="$1" app="$2" from="$3" file="$4" entry="$5" kind="$6" vname="$7" value="$8"
    local key="${entry##*/}" mustReject="" mustRun=""
    local d="$work/v$n"
    local out="$work/result.$n"
    if [ "${value: -1}" = "!" ]
    then
        mustReject=yes
        value="${value%!}"
    elif [ "${value: -1}" = "+" ]
    then
        mustRun=yes
        value="${value%+}"
    fi
    cp -r "$work/$from" "$d"
    # The message must name the keyword; a misspelt keyword may be named as
    # written or as the missing original; a field file's value may be named
    # by the file (0/h: the field and cell); the block by what is wrong
    local patterns=("$key")
    if [ "$value" = "~" ]
    then
        misspell "$key"
        value="~$misspelt"
        patterns+=("$misspelt")
    fi
    case "$key" in
    .) patterns=("$d/$file" "$file") ;;
    internalField|value) patterns+=("$d/$file") ;;
    nx|ny) patterns+=(blocks) ;;
    blocks) patterns+=(simpleGrading aligned) ;;
    esac
    [ "$vname" = misspeltValue ] && patterns+=("${value%% *}")
    case "$kind" in unknown|unknowndict) patterns+=(fuzzKeyword) ;; esac
    if ! makeVariant "$d" "$file" "$entry" "$vname" "$value" "$from"
    then
        echo "BAD cannot make the variant (value '$value')|$value" > "$out"
        return
    fi
    local log="$d/log.$app" note="" rc
    case "$app" in
    setAvalancheFields)
        cp -r "$d/0" "$d/before.0"
        (cd "$d" && exec timeout -s KILL "$limit" setAvalancheFields > "$log" 2>&1)
        rc=$?
        ;;
    blockMesh)
        if [ "$vname" = stale ]
        then
            note=" [blockMesh not run]"
        else
            (cd "$d" && exec timeout -s KILL "$limit" blockMesh > log.blockMesh 2>&1)
            rc=$?
            local bmText=""
            IFS= read -r -d '' bmText < "$d/log.blockMesh"
            if [ $rc -ge 128 ] || [[ $bmText =~ $traceRe ]]
            then
                note=" [blockMesh crashed: exit $rc]"
            elif [ $rc -ne 0 ]
            then
                note=" [blockMesh refused it]"
            fi
        fi
        log="$d/log.savageHutterFoam"
        app=savageHutterFoam
        (cd "$d" && exec timeout -s KILL "$limit" savageHutterFoam -backend cpu > "$log" 2>&1)
        rc=$?
        ;;
    *)
        (cd "$d" && exec timeout -s KILL "$limit" savageHutterFoam -backend cpu > "$log" 2>&1)
        rc=$?
        ;;
    esac
    local outcome
    classify "$d" "$app" "$log" "$rc" "${patterns[@]}"
    if [ -n "$mustReject" ] && [ "${outcome%% *}" = OK ]
    then
        outcome="BAD ran, but must be rejected: $outcome"
    fi
    if [ -n "$mustRun" ] && [ "${outcome%% *}" = REJECTED ]
    then
        outcome="BAD rejected, but must run: $outcome"
    fi
    # A misspelt keyword must not fall back to a default, except where any
    # entry is allowed: controlDict (OpenFOAM's Time takes any entry there)
    # and the name of an fvOptions source
    if [ "$vname" = misspelt ] && [ "${outcome%% *}" = OK ] \
    && [ "$file" != "$cd_" ] && [ "$entry" != jet ]
    then
        outcome="BAD the misspelt keyword was ignored: $outcome"
    fi
    echo "$outcome$note|$value" > "$out"
    # Keep the work directory small: only BAD variants stay
    case "$outcome" in BAD*) ;; *) rm -rf "$d" ;; esac
}

start=$SECONDS
# Enumerate: n|app|case|file|entry|kind|vname|value
n=0
: > "$work/variants"
while IFS='|' read -r -u 3 app from file entry kind extras
do
    [ -n "$app" ] || continue
    while IFS='|' read -r -u 4 vname value
    do
        [ -n "$vname" ] || continue
        n=$((n + 1))
        echo "$n|$app|$from|$file|$entry|$kind|$vname|$value" >> "$work/variants"
    done 4< <(variants "$kind" "${extras:-}")
done 3<<< "$keywords"

# Two at a time (the CI machine has two cores; each run is one thread)
jobs=${SH_FUZZ_JOBS:-2}
running=0
while IFS='|' read -r -u 3 n app from file entry kind vname value
do
    if [ "$running" -ge "$jobs" ]
    then
        wait -n
        running=$((running - 1))
    fi
    runVariant "$n" "$app" "$from" "$file" "$entry" "$kind" "$vname" "$value" &
    running=$((running + 1))
done 3< "$work/variants"
wait

nTried=0
nOK=0
nRejected=0
nBad=0
nKnown=0
nCrashedBlockMesh=0
table=""
lastKey=""
row=""
while IFS='|' read -r -u 3 n app from file entry kind vname value
do
    thisKey="$app|$from|$file|$entry"
    if [ "$thisKey" != "$lastKey" ]
    then
        [ -z "$lastKey" ] || table="$table$row
"
        row="$(printf '%-18s %-21s %-28s %-38s' "$app" "$from" "$file" "$entry")"
        lastKey="$thisKey"
    fi
    name="$app:$from:$file:$entry:$vname"
    line=""
    [ -f "$work/result.$n" ] && IFS= read -r line < "$work/result.$n"
    outcome="${line%|*}"
    value="${line##*|}"
    [ -n "$outcome" ] || outcome="BAD no result"
    what="${outcome#* }"
    [[ $what == *"[blockMesh crashed"* ]] && nCrashedBlockMesh=$((nCrashedBlockMesh + 1))
    isKnown=""
    [[ $known == *$'\n'"$name"$'\n'* ]] && isKnown=yes
    nTried=$((nTried + 1))
    case "$outcome" in
    OK*|REJECTED*)
        if [ "${outcome%% *}" = OK ]
        then
            nOK=$((nOK + 1)); row="$row $vname=OK"
        else
            nRejected=$((nRejected + 1)); row="$row $vname=REJ"
        fi
        if [ -n "$isKnown" ]
        then
            pass "$name = '$value': ${outcome%% *} ($what); no longer BAD: remove it from the known list"
        else
            pass "$name = '$value': ${outcome%% *} ($what)"
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
echo "blockMesh (OpenFOAM's) crashed on $nCrashedBlockMesh of them; the solver then met the mesh of the case before the edit"
finish

#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     savageHutterFoam with the bed's cover (issue 28, docs/design.md
#     section 7): entrainmentModel with its <Model>Coeffs in
#     constant/transportProperties, the fields 0/hEntrainable and
#     0/cResistance, the written hEntrainable (what is left) and
#     erodedDepth.  The case: the damBreak tutorial on 32 x 8 cells made a
#     closed box (walls all round), a cap of material upslope of an erodible
#     layer 0.08 m thick that covers most of the slope, entrainmentModel
#     constantRate with rate 0.1 m/s, written at 0.25, 0.5, 0.75 and 1 s
#     with 17 significant digits (the solver's ascii precision).  Checks:
#       1. the run: the log's model line, hEntrainable and erodedDepth at
#          every write time; at every time the sum over the cells of
#          (h + hEntrainable) dA equal to the initial one to 1e-12
#          (relative), erodedDepth = 0/hEntrainable - hEntrainable cell by
#          cell to 1e-12 of the layer, h and hEntrainable >= 0; something
#          taken up, the layer used up in some cells and partly left in
#          others at the last time; the same for every other model of
#          -listEntrainmentModels at the defaults of its required
#          coefficients (and something taken up);
#       2. entrainmentModel none with the layer and cResistance 0
#          everywhere writes h and U byte for byte as the case without
#          either, and hEntrainable as it was given; a cResistance of
#          0.3 1/m on the lower half of the slope slows the flow there;
#       3. refusals (non-zero exit, the file and the keyword named, no time
#          directory written): a negative rate, an unknown model, an unknown
#          keyword in constantRateCoeffs, constantRateCoeffs missing, a
#          negative hEntrainable in one cell, a model without
#          0/hEntrainable, writeFields naming hEntrainable in a case
#          without the layer;
#       4. a restart from 0.5 (startFrom latestTime) writes h, U,
#          hEntrainable, erodedDepth and cResistance at 0.75 and 1 byte for
#          byte as the uninterrupted run;
#       5. decomposed into 2 (simple 2 1), mpirun -parallel, reconstructPar:
#          every processor's h, U, hU, hEntrainable, erodedDepth and
#          cResistance and the
#          reconstructed ones the serial run's (bin/tools/compareDecomposed;
#          skipped, saying why, without mpirun or MPI);
#       6. a terrain case in plan coordinates (testFunctions.sh
#          planSlopeCase with an entrainment entry in terrainDict) run with
#          constantRate: a restart from 1 writes h, U, H, hU, hEntrainable,
#          erodedDepth, HEntrainable and HErodedDepth at 2 and 3 byte for
#          byte as the uninterrupted run; HEntrainable = J hEntrainable and
#          HErodedDepth = J erodedDepth (J = H/h); then hazardMaps:
#          report.dat's entrainedVolume > 0 and releasedVolume +
#          entrainedVolume = depositVolume + outflowVolume to the rounding
#          of the report's 10 digits.
#
# Usage
#     entrainmentRunTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
export OMP_NUM_THREADS=1

# -- helpers ------------------------------------------------------------------
cat > "$work/fields.py" <<'PYEOF'
"""Fields of the test's cases read at full precision"""
import re
def text(case, t, name):
    return open("%s/%s/%s" % (case, t, name)).read()
def field(case, t, name, n=None):
    """internalField of a volScalarField (uniform expanded to n cells)"""
    s = text(case, t, name)
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", s)
    if m:
        v = [float(x) for x in m.group(2).split()]
        assert len(v) == int(m.group(1))
        return v
    m = re.search(r"internalField\s+uniform\s+(\S+?)\s*;", s)
    return [float(m.group(1))]*n
PYEOF

#- check <what> <python>: a python snippet that sets ok and msg (fields.py
#  imported), a PASS or FAIL line
check()
{
    local out rc
    out="$(cd "$work" && python3 - <<PYEOF 2>&1
from fields import *
ok, msg = False, ""
$2
print(("PASS  " if ok else "FAIL  ") + "$1" + (": " + msg if msg else ""))
PYEOF
)"
    rc=$?
    tally "$rc" "$out" "$1"
}

#- refused <case> <what> <pattern>...: the run of case failed, its log has
#  every pattern (grep -E), and no time directory was written
refused()
{
    local dir="$1" what="$2" rc p missing=""
    shift 2
    (cd "$dir" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    rc=$?
    for p in "$@"
    do
        grep -qE -- "$p" "$dir/log.savageHutterFoam" || missing="$missing '$p'"
    done
    local written
    written="$(timeDirs "$dir" | tr '\n' ' ')"
    if [ $rc -ne 0 ] && [ -z "$missing" ] && [ -z "$written" ] \
    && [ -z "$(ls -A "$dir/.savageHutterFoam-writing" 2>/dev/null)" ]
    then
        pass "$what: refused (exit $rc), naming$(printf " '%s'" "$@"), nothing written"
    else
        fail "$what: exit $rc, missing from the log:${missing:- none}, written: '${written}' (see $dir/log.savageHutterFoam)"
    fi
}

# -- the base case ------------------------------------------------------------
base="$work/base"
mkdir "$base"
cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$base"/
(
    cd "$base" || exit 1
    setBlockCells 32 8
    setEntry system/controlDict endTime 1
    setEntry system/controlDict writeInterval 0.25
    # Every digit of the doubles (the solver's own writes have them in
    # any case; decomposePar and reconstructPar write with this)
    setEntry system/controlDict writePrecision 17
    setEntry system/controlDict startFrom latestTime
    cat > system/setAvalancheFieldsDict <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }
h ( hemisphere { centre (-7 0.4); radius 1.4; } );
hEntrainable ( box { min (-5 -1.6); max (8 1.0); value 0.08; } );
EOF
    runApplication blockMesh
    restore0Dir
    runApplication setAvalancheFields
    # A closed box: walls up- and downslope too
    closeSlope
) > "$work/base.log" 2>&1 \
    && [ -f "$base/0/hEntrainable" ] \
    || { cat "$work/base.log"; fail "setting up the base case (its log above)"; finish; exit 1; }

newCase()
{
    rm -rf "$work/$1"
    cp -r "$base" "$work/$1"
    echo "$work/$1"
}

#- model <case> <lines>: entrainment lines appended to transportProperties
model()
{
    printf '%s\n' "$2" >> "$1/constant/transportProperties"
}

#- resistance <case> <value>: 0/cResistance, <value> 1/m in the cells of
#  the lower half of the slope (x > 0), 0 elsewhere
resistance()
{
    python3 - "$1/0/cResistance" "$2" <<'PYEOF'
import sys
values = ["%s" % (sys.argv[2] if -12.8 + (k % 32 + 0.5)*0.8 > 0 else "0") for k in range(256)]
open(sys.argv[1], "w").write("""FoamFile { version 2.0; format ascii; class volScalarField; object cResistance; }
dimensions      [0 -1 0 0 0 0 0];
internalField   nonuniform List<scalar> 256 (%s);
boundaryField
{
    upslope      { type zeroGradient; }
    downslope    { type zeroGradient; }
    sides        { type zeroGradient; }
    frontAndBack { type empty; }
}
""" % " ".join(values))
PYEOF
}

#- entrainCase <name>: the case of check 1 (constantRate 0.1 m/s and a
#  resistance of 0.3 1/m on the lower half)
entrainCase()
{
    local dir
    dir="$(newCase "$1")"
    model "$dir" "entrainmentModel constantRate;
constantRateCoeffs { rate 0.1; }"
    resistance "$dir" 0.3
    echo "$dir"
}

times="0.25 0.5 0.75 1"

# -- 1. the run ---------------------------------------------------------------
ent="$(entrainCase entrain)"
(cd "$ent" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
rc=$?
written="$(timeDirs "$ent" | tr '\n' ' ')"
if [ $rc -eq 0 ] && [ "$written" = "$times " ]
then
    pass "constantRate run: exit 0, wrote $written"
else
    fail "constantRate run: exit $rc, wrote '$written' (see $ent/log.savageHutterFoam)"
fi
if grep -q "entrainmentModel constantRate { rate 0.1 m/s }" "$ent/log.savageHutterFoam"
then
    pass "the log says what was read: $(grep -m1 'entrainmentModel constantRate' "$ent/log.savageHutterFoam" | sed 's/^ *//')"
else
    fail "no line 'entrainmentModel constantRate { rate 0.1 m/s }' in the log"
fi
missing=""
for t in $times
do
    for f in hEntrainable erodedDepth
    do
        [ -f "$ent/$t/$f" ] || missing="$missing $t/$f"
    done
done
if [ -z "$missing" ]
then
    pass "hEntrainable and erodedDepth written at every write time"
else
    fail "not written:$missing"
fi

check "volume balance: sum (h + hEntrainable) dA at every time = at t = 0 (relative 1e-12)" '
case, A, n = "'"$ent"'", 0.8*0.4, 256
h0, l0 = field(case, "0", "h", n), field(case, "0", "hEntrainable", n)
v0 = sum(a + b for a, b in zip(h0, l0))*A
worst, lines = 0.0, []
for t in "'"$times"'".split():
    h, l = field(case, t, "h", n), field(case, t, "hEntrainable", n)
    v = sum(a + b for a, b in zip(h, l))*A
    rel = abs(v - v0)/v0
    worst = max(worst, rel)
    lines.append("t = %s: %.17g m^3 (flowing %.6g), relative %.2g" % (t, v, sum(h)*A, rel))
ok = worst <= 1e-12 and sum(h)*A > sum(h0)*A*1.05
msg = "t = 0: %.17g m^3 (flowing %.6g); " % (v0, sum(h0)*A) + "; ".join(lines)'

check "erodedDepth = 0/hEntrainable - hEntrainable cell by cell (1e-12 of the layer); h, hEntrainable >= 0" '
case, n = "'"$ent"'", 256
l0 = field(case, "0", "hEntrainable", n)
scale = max(l0)
worst, negative = 0.0, []
for t in "'"$times"'".split():
    l, e, h = field(case, t, "hEntrainable", n), field(case, t, "erodedDepth", n), field(case, t, "h", n)
    worst = max(worst, max(abs(e[c] - (l0[c] - l[c])) for c in range(n)))
    negative += ["%s: min h %g, min hEntrainable %g, min erodedDepth %g" % (t, min(h), min(l), min(e))] \
        if min(h) < 0 or min(l) < 0 or min(e) < 0 else []
l, e = field(case, "1", "hEntrainable", n), field(case, "1", "erodedDepth", n)
usedUp = sum(1 for c in range(n) if l0[c] > 0 and l[c] == 0)
partly = sum(1 for c in range(n) if 0 < l[c] < l0[c])
ok = worst <= 1e-12*scale and not negative and usedUp > 0 and partly > 0
msg = "largest difference %.3g m; at t = 1 the layer used up in %d cells, partly left in %d, eroded %.6g m^3 in all%s" % (
    worst, usedUp, partly, sum(e)*0.32, "; negative: " + "; ".join(negative) if negative else "")'

# Every other model of the list (savageHutterFoam -listEntrainmentModels) at
# the defaults of its required coefficients: the same balance and eroded
# depth, and something taken up
savageHutterFoam -listEntrainmentModels > "$work/models.txt" 2>&1
others="$(awk '$1 == "entrainmentModel" && $2 != "none" && $2 != "constantRate" {print $2}' "$work/models.txt")"
for m in $others
do
    coeffs="$(awk -v m="$m" '$1 == "entrainmentModel" {on = ($2 == m)}
        on && $1 == "coefficient" && $4 == "required" {printf " %s %s;", $2, $3}' "$work/models.txt")"
    dir="$(entrainCase "model-$m")"
    sed -i '/^entrainmentModel\|^constantRateCoeffs/d' "$dir/constant/transportProperties"
    model "$dir" "entrainmentModel $m;
${m}Coeffs {$coeffs }"
    (cd "$dir" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    rc=$?
    if [ $rc -ne 0 ] || [ ! -f "$dir/1/erodedDepth" ]
    then
        fail "entrainmentModel $m {$coeffs }: exit $rc, no 1/erodedDepth (see $dir/log.savageHutterFoam)"
        continue
    fi
    check "entrainmentModel $m {$coeffs }: the balance to 1e-12, erodedDepth = 0/hEntrainable - hEntrainable, h and the layer >= 0, something taken up" '
case, n, A = "'"$dir"'", 256, 0.32
h0, l0 = field(case, "0", "h", n), field(case, "0", "hEntrainable", n)
v0 = sum(a + b for a, b in zip(h0, l0))*A
rel, worst, low, eroded = 0.0, 0.0, 0.0, 0.0
for t in "'"$times"'".split():
    h, l, e = field(case, t, "h", n), field(case, t, "hEntrainable", n), field(case, t, "erodedDepth", n)
    rel = max(rel, abs(sum(a + b for a, b in zip(h, l))*A - v0)/v0)
    worst = max(worst, max(abs(e[c] - (l0[c] - l[c])) for c in range(n)))
    low = min(low, min(h), min(l), min(e))
    eroded = sum(e)*A
ok = rel <= 1e-12 and worst <= 1e-12*max(l0) and low >= 0 and eroded > 0
msg = "relative balance %.2g, erodedDepth off by %.2g m, smallest value %g, eroded %.6g m^3 at t = 1" % (rel, worst, low, eroded)'
done
[ -n "$others" ] || echo "(no entrainment model besides none and constantRate in the list)"

# -- 2. none with a layer and cResistance 0: the plain run, byte for byte -----
plain="$(newCase plain)"
rm -f "$plain/0/hEntrainable"
(cd "$plain" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
    || fail "the plain run (see $plain/log.savageHutterFoam)"
none="$(newCase noneLayer)"
model "$none" "entrainmentModel none;"
cat > "$none/0/cResistance" <<'EOF'
FoamFile { version 2.0; format ascii; class volScalarField; object cResistance; }
dimensions      [0 -1 0 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    upslope      { type zeroGradient; }
    downslope    { type zeroGradient; }
    sides        { type zeroGradient; }
    frontAndBack { type empty; }
}
EOF
(cd "$none" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
rc=$?
differ=""
for t in $times
do
    for f in h U
    do
        cmp -s "$plain/$t/$f" "$none/$t/$f" || differ="$differ $t/$f"
    done
done
if [ $rc -eq 0 ] && [ -z "$differ" ] && [ -f "$none/1/h" ] \
    && grep -q "Resistance cResistance: largest 0 1/m" "$none/log.savageHutterFoam"
then
    pass "entrainmentModel none with the layer and cResistance 0: h and U at $times byte for byte the plain run's"
else
    fail "entrainmentModel none with the layer and cResistance 0: exit $rc, differ:${differ:- none} (see $none/log.savageHutterFoam)"
fi
check "entrainmentModel none: hEntrainable written as given, erodedDepth 0, cResistance kept" '
case, n = "'"$none"'", 256
l0 = field(case, "0", "hEntrainable", n)
bad = [t for t in "'"$times"'".split()
       if field(case, t, "hEntrainable", n) != l0 or any(field(case, t, "erodedDepth", n))
       or any(field(case, t, "cResistance", n))]
ok = not bad and max(l0) > 0
msg = "differ at: %s" % bad if bad else "at every write time"'

# The resistance acts: with it alone the flow is slower than the plain run's
res="$(newCase resistanceOnly)"
rm -f "$res/0/hEntrainable"
resistance "$res" 0.3
(cd "$res" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
    || fail "the run with cResistance alone (see $res/log.savageHutterFoam)"
check "cResistance 0.3 1/m on the lower half: the flow there slower than without it, the upper half unchanged at t = 0.25" '
import re
def speeds(case, t):
    s = text(case, t, "U")
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*\d+\s*\((.*?)\)\s*;", s, re.S)
    return [float(v[0]) for v in re.findall(r"\(([^ ()]+) ([^ ()]+) ([^ ()]+)\)", m.group(1))]
lower = lambda k: -12.8 + (k % 32 + 0.5)*0.8 > 0
p1, r1 = speeds("'"$plain"'", "1"), speeds("'"$res"'", "1")
hp, hr = field("'"$plain"'", "1", "h", 256), field("'"$res"'", "1", "h", 256)
mp = sum(hp[k]*p1[k] for k in range(256) if lower(k))/sum(hp[k] for k in range(256) if lower(k))
mr = sum(hr[k]*r1[k] for k in range(256) if lower(k))/sum(hr[k] for k in range(256) if lower(k))
p0, r0 = speeds("'"$plain"'", "0.25"), speeds("'"$res"'", "0.25")
upperSame = all(p0[k] == r0[k] for k in range(256) if -12.8 + (k % 32 + 0.5)*0.8 < -4)
ok = mr < mp and upperSame
msg = "mean downslope speed on the lower half at t = 1: %.6g m/s with it, %.6g without; upper cells (x < -4) identical at 0.25: %s" % (mr, mp, upperSame)'

# -- 3. refusals --------------------------------------------------------------
r="$(newCase negativeRate)"
model "$r" "entrainmentModel constantRate;
constantRateCoeffs { rate -0.01; }"
refused "$r" "rate -0.01" "constant/transportProperties" "Invalid \"?rate" "Valid range: rate >= 0 m/s"

r="$(newCase unknownModel)"
model "$r" "entrainmentModel bogus;"
refused "$r" "entrainmentModel bogus" "constant/transportProperties" \
    "Unknown entrainmentModel 'bogus'" "Valid choices: .*constantRate.*none"

r="$(newCase unknownCoefficient)"
model "$r" "entrainmentModel constantRate;
constantRateCoeffs { rate 0.1; speed 2; }"
refused "$r" "constantRateCoeffs with an unknown keyword speed" "constant/transportProperties" \
    "Unknown coefficient 'speed' in constantRateCoeffs" "Valid coefficients: .*rate"

r="$(newCase noCoeffs)"
model "$r" "entrainmentModel constantRate;"
refused "$r" "constantRate without constantRateCoeffs" "constant/transportProperties" \
    "needs the sub-dictionary 'constantRateCoeffs'" "rate 0.05"

r="$(newCase negativeLayer)"
model "$r" "entrainmentModel constantRate;
constantRateCoeffs { rate 0.1; }"
python3 - "$r/0/hEntrainable" <<'PYEOF'
import re, sys
s = open(sys.argv[1]).read()
m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", s)
v = m.group(2).split()
v[37] = "-0.01"
s = s[:m.start(2)] + "\n" + "\n".join(v) + "\n" + s[m.end(2):]
open(sys.argv[1], "w").write(s)
PYEOF
refused "$r" "hEntrainable -0.01 in cell 37" "0/hEntrainable" "hEntrainable = -0.01 in cell 37" \
    "Valid range: \[0, 1e30\] m"

r="$(newCase noLayer)"
rm -f "$r/0/hEntrainable"
model "$r" "entrainmentModel constantRate;
constantRateCoeffs { rate 0.1; }"
refused "$r" "constantRate without 0/hEntrainable" "constant/transportProperties" \
    "entrainmentModel constantRate at line [0-9]+ needs the erodible layer" "0/hEntrainable"

r="$(newCase writeFieldsNoLayer)"
rm -f "$r/0/hEntrainable"
setEntry "$r/system/controlDict" writeFields "(h U hEntrainable)"
refused "$r" "writeFields (h U hEntrainable) without the layer" "system/controlDict" \
    "names hEntrainable, which this case does not have"

# -- 4. restart from 0.5 ------------------------------------------------------
rs="$(entrainCase restart)"
setEntry "$rs/system/controlDict" endTime 0.5
(cd "$rs" && savageHutterFoam -backend cpu > log.first 2>&1) || fail "restart: the run to 0.5 (see $rs/log.first)"
setEntry "$rs/system/controlDict" endTime 1
(cd "$rs" && savageHutterFoam -backend cpu > log.restart 2>&1)
rc=$?
differ=""
for t in 0.75 1
do
    for f in h U hEntrainable erodedDepth cResistance
    do
        cmp -s "$ent/$t/$f" "$rs/$t/$f" || differ="$differ $t/$f"
    done
done
if [ $rc -eq 0 ] && [ -z "$differ" ] && grep -q "Reading field erodedDepth" "$rs/log.restart"
then
    pass "restart from 0.5: h, U, hEntrainable, erodedDepth, cResistance at 0.75 and 1 byte for byte the uninterrupted run's"
else
    fail "restart from 0.5: exit $rc, differ:${differ:- none} (see $rs/log.restart)"
fi

# -- 5. decomposed ------------------------------------------------------------
if ! command -v mpirun > /dev/null
then
    skip "decomposed run: no mpirun (bin/installDependencies installs openmpi-bin)"
else
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    par="$(entrainCase decomposed)"
    cat > "$par/system/decomposeParDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2;
method simple;
simpleCoeffs { n (2 1 1); delta 0.001; }
EOF
    (
        cd "$par" || exit 1
        decomposePar -force > log.decomposePar 2>&1 || exit 2
        timeout 300 mpirun --oversubscribe -np 2 savageHutterFoam -parallel \
            -backend cpu > log.savageHutterFoam 2>&1 || exit 3
        reconstructPar > log.reconstructPar 2>&1 || exit 4
    )
    rc=$?
    if grep -q "built without MPI" "$par/log.savageHutterFoam" 2>/dev/null
    then
        skip "decomposed run: savageHutterFoam was built without MPI"
    elif [ $rc -ne 0 ]
    then
        fail "decomposed run: step $rc of decomposePar, mpirun, reconstructPar failed (see $par/log.*)"
    else
        out="$(python3 "$project/bin/tools/compareDecomposed" "decomposed (2 1 1)" \
            "$ent" "$par" "$times" "h U hU hEntrainable erodedDepth cResistance" 2>&1)"
        tally $? "$out" "decomposed (2 1 1)"
    fi
fi

# -- 6. plan coordinates and hazardMaps ---------------------------------------
pc="$work/plan"
planSlopeCase "$pc" 500 800 0
cat >> "$pc/system/terrainDict" <<'EOF'
entrainment
{
    bed
    {
        polygon     ((550 810) (660 810) (660 910) (550 910));
        thickness   0.3;
        thicknessDirection vertical;
    }
}
EOF
cat >> "$pc/constant/transportProperties" <<'EOF'
entrainmentModel constantRate;
constantRateCoeffs { rate 0.2; }
EOF
if (cd "$pc" && terrainToCase > log.terrainToCase 2>&1 && blockMesh > log.blockMesh 2>&1) \
    && setEntry "$pc/system/controlDict" endTime 3 \
    && setEntry "$pc/system/controlDict" writeInterval 1 \
    && setEntry "$pc/system/controlDict" writeFormat ascii \
    && setEntry "$pc/system/controlDict" writePrecision 17 \
    && setEntry "$pc/system/controlDict" startFrom latestTime \
    && cp -r "$pc" "$work/planRestart" \
    && (cd "$pc" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
    && (cd "$pc" && hazardMaps > log.hazardMaps 2>&1)
then
    # The restart: to 1, then from 1 to 3
    pr="$work/planRestart"
    setEntry "$pr/system/controlDict" endTime 1
    (cd "$pr" && savageHutterFoam -backend cpu > log.first 2>&1) || fail "plan restart: the run to 1 (see $pr/log.first)"
    setEntry "$pr/system/controlDict" endTime 3
    (cd "$pr" && savageHutterFoam -backend cpu > log.restart 2>&1)
    rc=$?
    differ=""
    for t in 2 3
    do
        for f in h U H hU hEntrainable erodedDepth HEntrainable HErodedDepth
        do
            cmp -s "$pc/$t/$f" "$pr/$t/$f" || differ="$differ $t/$f"
        done
    done
    if [ $rc -eq 0 ] && [ -z "$differ" ] \
        && grep -q "Reading fields HEntrainable and HErodedDepth" "$pr/log.restart"
    then
        pass "plan coordinates, restart from 1: h, U, H, hU, hEntrainable, erodedDepth, HEntrainable, HErodedDepth at 2 and 3 byte for byte the uninterrupted run's"
    else
        fail "plan coordinates, restart from 1: exit $rc, differ:${differ:- none} (see $pr/log.restart)"
    fi
    check "plan coordinates: HEntrainable = J hEntrainable, HErodedDepth = J erodedDepth (J = H/h where h > 0.01), erodedDepth = 0/hEntrainable - hEntrainable" '
case, n = "'"$pc"'", 1260
l0 = field(case, "0", "hEntrainable", n)
worst, cells, lines = 0.0, 0, []
for t in ["1", "2", "3"]:
    h, H = field(case, t, "h", n), field(case, t, "H", n)
    l, e = field(case, t, "hEntrainable", n), field(case, t, "erodedDepth", n)
    L, E = field(case, t, "HEntrainable", n), field(case, t, "HErodedDepth", n)
    for c in range(n):
        worst = max(worst, abs(e[c] - (l0[c] - l[c])))
        if h[c] > 0.01:
            J = H[c]/h[c]
            cells += 1
            assert abs(L[c] - J*l[c]) <= 1e-12*max(l0) and abs(E[c] - J*e[c]) <= 1e-12*max(l0), (t, c)
    lines.append("t = %s: eroded %.6g m (sum)" % (t, sum(e)))
ok = worst <= 1e-12*max(l0) and cells > 0 and sum(e) > 0
msg = "%d wet cells checked; largest |erodedDepth - (hEntrainable0 - hEntrainable)| %.3g m; %s" % (cells, worst, "; ".join(lines))'

    last="$(timeDirs "$pc" | tail -n1)"
    check "plan coordinates, hazardMaps at $last: releasedVolume + entrainedVolume = depositVolume + outflowVolume" '
import math
vals, raw = {}, {}
for line in open("'"$pc"'/postProcessing/hazardMaps/'"$last"'/report.dat"):
    if line.strip() and not line.startswith("#"):
        k, v = line.split()
        vals[k], raw[k] = float(v), v
keys = ["releasedVolume", "entrainedVolume", "depositVolume", "outflowVolume"]
r, e, d, o = (vals[k] for k in keys)
# each printed with 10 significant digits: rounded by at most half a unit
# of its tenth digit
tol = sum(0.5*10**(math.floor(math.log10(abs(vals[k]))) - 9) for k in keys if vals[k] != 0)
bal = r + e - d - o
ok = e > 0 and abs(bal) <= tol
msg = " ".join("%s %s" % (k, raw[k]) for k in keys) + "; balance %.3g m^3 (the rounding of the report: %.3g)" % (bal, tol)'
else
    fail "the plan case: terrainToCase, blockMesh, savageHutterFoam or hazardMaps failed (see $pc/log.*)"
fi

# -- the listing --------------------------------------------------------------
if savageHutterFoam -listEntrainmentModels 2>&1 | grep -qE "^ *coefficient rate +0.05 +required +m/s +>= 0"
then
    pass "-listEntrainmentModels lists constantRate's rate"
else
    fail "-listEntrainmentModels does not list constantRate's rate"
fi

finish

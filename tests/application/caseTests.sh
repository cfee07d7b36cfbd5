#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Tests of the OpenFOAM application on small copies of the damBreak
#     tutorial (64 x 8 cells):
#       - every bad input of the list below exits non-zero, prints a message
#         naming the problem (and the valid choices where there are some),
#         and writes no time directory;
#       - legal edge cases run (delta = 0), as do Voellmy friction and
#         Pouliquen-Forterre friction with an impinging jet (fvOptions),
#         whose |dh/dt| report is written;
#       - a restart from latestTime continues exactly (files identical);
#       - foamToVTK reads the output and finds h, U and hU.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     caseTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"

base="$work/base"
mkdir "$base"
cp -r "$project"/tutorials/damBreak/{0.orig,constant,system} "$base"/
(
    cd "$base" || exit 1
    setBlockCells 64 8
    setEntry system/controlDict endTime 0.1
    setEntry system/controlDict writeInterval 0.05
    runApplication blockMesh
    restore0Dir
    runApplication setAvalancheFields
) > "$work/base.log" 2>&1 || { cat "$work/base.log"; fail "setting up the base case (its log above)"; finish; exit 1; }

newCase()
{
    rm -rf "$work/$1"
    cp -r "$base" "$work/$1"
    rm -f "$work/$1"/log.*
    echo "$work/$1"
}

#- expectFailure <name> <pattern>... : run savageHutterFoam in case <name>
#  (prepared by the caller), which must fail, print every pattern, no stack
#  trace, and write no time directory
expectFailure()
{
    local name="$1"
    shift
    local dir="$work/$name"
    local log="$dir/log.savageHutterFoam"
    (cd "$dir" && savageHutterFoam $SH_ARGS > "$log" 2>&1)
    local rc=$?
    local problems=""
    [ $rc -ne 0 ] || problems="$problems exit status 0;"
    grep -q "FOAM FATAL" "$log" || problems="$problems no FOAM FATAL message;"
    ! grep -qE "printStack|sigFpe::sigHandler|^#[0-9]+ " "$log" \
        || problems="$problems a stack trace;"
    local p
    for p in "$@"
    do
        grep -qF -- "$p" "$log" || problems="$problems message lacks '$p';"
    done
    local written
    written="$(timeDirs "$dir")"
    [ -z "$written" ] || problems="$problems wrote time directories $written;"
    if [ -z "$problems" ]
    then
        pass "$name: rejected ($(grep -m1 -A1 -E 'FOAM FATAL' "$log" | tail -n1 | cut -c1-90))"
    else
        fail "$name:$problems (see $log)"
    fi
}

SH_ARGS="-backend cpu"

# -- Model parameters (constant/transportProperties) ---------------------------
tp=constant/transportProperties

d=$(newCase deltaAbovePhi)
setEntry "$d/$tp" earthPressure activePassive
setEntry "$d/$tp" phi 20
expectFailure deltaAbovePhi "delta" "complex" "transportProperties"

for v in 0 90 -5 100
do
    d=$(newCase phi$v)
    setEntry "$d/$tp" phi "$v"
    expectFailure "phi$v" "phi" "(0, 90)"
done

for v in -1 90
do
    d=$(newCase delta$v)
    setEntry "$d/$tp" CoulombCoeffs/delta "$v"
    expectFailure "delta$v" "delta" "[0, 90)"
done

for v in -0.1 1 1.5
do
    d=$(newCase kineticEnergyStop$v)
    setEntry "$d/system/fvSolution" savageHutter/kineticEnergyStop "$v"
    expectFailure "kineticEnergyStop$v" "kineticEnergyStop" "0 <= kineticEnergyStop < 1" "fvSolution"
done

d=$(newCase missingFrictionModel)
foamDictionary "$d/$tp" -entry frictionModel -remove > /dev/null
expectFailure missingFrictionModel "frictionModel" "Valid choices" "Coulomb"

d=$(newCase unknownFrictionModel)
setEntry "$d/$tp" frictionModel Voellmyy
expectFailure unknownFrictionModel "Voellmyy" "Valid choices" "Coulomb"

# Run-time selected friction models and their <Model>Coeffs
pf='{ zeta1 21; zeta2 30.7; zeta3 22.2; L 6e-3; beta 0.136; gamma 1e-3; }'
#- pfCase <name>: the case with PouliquenForterre and the paper's coefficients
pfCase()
{
    local d
    d=$(newCase "$1")
    setEntry "$d/$tp" frictionModel PouliquenForterre
    setEntry "$d/$tp" PouliquenForterreCoeffs "$pf"
    echo "$d"
}

d=$(newCase missingCoeffsDict)
setEntry "$d/$tp" frictionModel PouliquenForterre
expectFailure missingCoeffsDict "PouliquenForterreCoeffs"

d=$(pfCase missingCoefficient)
foamDictionary "$d/$tp" -entry PouliquenForterreCoeffs/zeta3 -remove > /dev/null
expectFailure missingCoefficient "zeta3" "PouliquenForterreCoeffs"

d=$(pfCase unknownCoefficient)
setEntry "$d/$tp" PouliquenForterreCoeffs/Lstop 1e-3
expectFailure unknownCoefficient "Lstop" "Valid coefficients" "zeta1" "gamma"

d=$(pfCase negativeL)
setEntry "$d/$tp" PouliquenForterreCoeffs/L -6e-3
expectFailure negativeL "L" "positive" "PouliquenForterreCoeffs"

d=$(pfCase zeta1AboveZeta2)
setEntry "$d/$tp" PouliquenForterreCoeffs/zeta1 35
expectFailure zeta1AboveZeta2 "zeta1" "zeta2" "PouliquenForterreCoeffs"

d=$(pfCase pfActivePassive)
setEntry "$d/$tp" earthPressure activePassive
expectFailure pfActivePassive "earthPressure" "isotropic"

d=$(newCase voellmyZeroXi)
setEntry "$d/$tp" frictionModel Voellmy
setEntry "$d/$tp" VoellmyCoeffs "{ mu 0.2; xi 0; }"
expectFailure voellmyZeroXi "xi" "positive" "VoellmyCoeffs"

# The impinging-jet source of system/fvOptions (stagnation point (0 0 0) is
# a mesh point of the 64 x 8 mesh of 0.4 m cells)
jet='{ type impingingJet; centre (0 0 0); R 0.5; R_imp 1; u_jet 2; }'
#- jetCase <name>: the PouliquenForterre case with a jet
jetCase()
{
    local d
    d=$(pfCase "$1")
    cp "$d/system/controlDict" "$d/system/fvOptions"
    foamDictionary "$d/system/fvOptions" -entry FoamFile/object -set fvOptions > /dev/null
    for k in $(foamDictionary "$d/system/fvOptions" -keywords | grep -v FoamFile)
    do
        foamDictionary "$d/system/fvOptions" -entry "$k" -remove > /dev/null
    done
    setEntry "$d/system/fvOptions" jet "$jet"
    echo "$d"
}

d=$(jetCase sourceNotDict)
setEntry "$d/system/fvOptions" jet impingingJet
expectFailure sourceNotDict "'jet' is not a source dictionary"

d=$(jetCase jetMisspeltActive)
setEntry "$d/system/fvOptions" jet/activ no
expectFailure jetMisspeltActive "activ" "Valid keywords"

d=$(jetCase unknownSourceType)
setEntry "$d/system/fvOptions" jet/type massSource
expectFailure unknownSourceType "massSource" "Valid types" "impingingJet"

d=$(jetCase jetNegativeRimp)
setEntry "$d/system/fvOptions" jet/R_imp -1
expectFailure jetNegativeRimp "R_imp" "positive" "fvOptions"

d=$(jetCase jetOnCellCentre)
setEntry "$d/system/fvOptions" jet/centre "(0.2 0.2 0)"
expectFailure jetOnCellCentre "centre" "centre of cell" "fvOptions"

d=$(jetCase jetUnknownKeyword)
setEntry "$d/system/fvOptions" jet/Ujet 2
expectFailure jetUnknownKeyword "Ujet" "Valid keywords" "u_jet"

d=$(newCase missingEarthPressure)
foamDictionary "$d/$tp" -entry earthPressure -remove > /dev/null
expectFailure missingEarthPressure "earthPressure" "activePassive" "isotropic"

d=$(newCase unknownEarthPressure)
setEntry "$d/$tp" earthPressure rankine
expectFailure unknownEarthPressure "rankine" "activePassive" "isotropic"

d=$(newCase missingInclination)
foamDictionary "$d/$tp" -entry inclination -remove > /dev/null
expectFailure missingInclination "inclination"

d=$(newCase steepInclination)
setEntry "$d/$tp" inclination "constant 95"
expectFailure steepInclination "inclination"

d=$(newCase misspeltTransportKeyword)
foamDictionary "$d/$tp" -entry lamda -add 0.5 > /dev/null
expectFailure misspeltTransportKeyword "lamda" "lambda" "transportProperties"

d=$(newCase negativeGravity)
setEntry "$d/$tp" g -9.81
expectFailure negativeGravity "gravity must be positive"

# -- Numerics (system/fvSolution, system/controlDict) --------------------------
fs=system/fvSolution

d=$(newCase missingLimiter)
foamDictionary "$d/$fs" -entry savageHutter/limiter -remove > /dev/null
expectFailure missingLimiter "limiter" "minmod" "vanLeer" "MC"

d=$(newCase unknownLimiter)
setEntry "$d/$fs" savageHutter/limiter superbee
expectFailure unknownLimiter "superbee" "minmod" "vanLeer" "MC"

d=$(newCase misspeltKeyword)
setEntry "$d/$fs" savageHutter/stopingCriterion off
expectFailure misspeltKeyword "stopingCriterion" "stoppingCriterion"

d=$(newCase negativeHDry)
setEntry "$d/$fs" savageHutter/hDry -1
expectFailure negativeHDry "hDry"

d=$(newCase maxCoAboveOne)
setEntry "$d/system/controlDict" maxCo 1.5
expectFailure maxCoAboveOne "maxCo" "(0, 1]"

d=$(newCase writeControlBogus)
setEntry "$d/system/controlDict" writeControl everyStep
expectFailure writeControlBogus "writeControl" "adjustableRunTime" "timeStep"

# Every controlDict entry the run depends on, checked before OpenFOAM's Time
# reads it (writeInterval 0 was a floating-point exception inside Time)
#- setRaw <file> <keyword> <value>: set a top-level entry as written, also
#  values foamDictionary cannot parse (nan, inf); "-" removes it
setRaw()
{
    sed -i "/^$2[ \t]/d" "$1"
    [ "$3" = - ] || echo "$2 $3;" >> "$1"
}
n=0
while IFS='|' read -r -u 3 key value expect
do
    n=$((n + 1))
    d=$(newCase "controlDict$n")
    setRaw "$d/system/controlDict" "$key" "$value"
    expectFailure "controlDict$n" "system/controlDict" "$key" "$expect"
done 3<<'LIST'
writeInterval|0|(0, inf)
writeInterval|-0.05|(0, inf)
writeInterval|nan|(0, inf)
writeInterval|-|Missing keyword
deltaT|0|(0, inf)
deltaT|inf|(0, inf)
deltaT|-|Missing keyword
endTime|nan|(-1e+30, 1e+30)
endTime|-|Missing keyword
endTime|-1|endTime >= 0
maxDeltaT|0|(0, inf)
maxCo|nan|(0, 1]
writePrecision|0|[1, 17]
writePrecision|18|[1, 17]
timePrecision|-1|[1, 17]
timePrecision|100|[1, 17]
purgeWrite|-1|[0,
purgeWrite|1.5|an integer
startFrom|beginning|(firstTime startTime latestTime)
stopAt|later|(endTime writeNow noWriteNow nextWrite)
writeFormat|hdf5|(ascii binary)
timeFormat|engineering|(general fixed scientific)
writeCompression|zip|(on off
adjustTimeStep|maybe|yes | no
runTimeModifiable|2|yes | no
writeControl|-|(adjustableRunTime runTime timeStep clockTime cpuTime)
LIST

d=$(newCase controlDictStartTimeNan)
setRaw "$d/system/controlDict" startTime nan
expectFailure controlDictStartTimeNan "system/controlDict" "startTime" "(-1e+30, 1e+30)"

d=$(newCase controlDictTimeStepFraction)
setRaw "$d/system/controlDict" writeControl timeStep
setRaw "$d/system/controlDict" writeInterval 2.5
expectFailure controlDictTimeStepFraction "system/controlDict" "writeInterval" "an integer in [1, 2147483647]"

d=$(newCase controlDictStopAtWriteNow)
setRaw "$d/system/controlDict" stopAt writeNow
expectFailure controlDictStopAtWriteNow "system/controlDict" "stopAt writeNow" "(endTime)"

# Values with which a run would write for ever: timeStep writes beyond a
# label, wall-clock writes below a second (OpenFOAM counts them as the label
# elapsed/writeInterval), steps that cannot reach endTime within 1e10 (for
# every writeControl) or the first write time within 1e8 (adjustableRunTime)
#- stepsCase <name> <keyword> <value>...: the case with controlDict entries
stepsCase()
{
    local name="$1"
    shift
    d=$(newCase "$name")
    while [ $# -ge 2 ]
    do
        setRaw "$d/system/controlDict" "$1" "$2"
        shift 2
    done
}
stepsCase timeStepBeyondLabel writeControl timeStep writeInterval 1e20
expectFailure timeStepBeyondLabel "system/controlDict" "writeInterval" "an integer in [1, 2147483647]"
stepsCase clockTimeTiny writeControl clockTime writeInterval 1e-12
expectFailure clockTimeTiny "system/controlDict" "writeInterval" "[1, inf)" "32-bit label"
stepsCase cpuTimeHalf writeControl cpuTime writeInterval 0.5
expectFailure cpuTimeHalf "system/controlDict" "writeInterval" "[1, inf)"
stepsCase timeStepTinyMaxDeltaT writeControl timeStep writeInterval 1 maxDeltaT 1e-200
expectFailure timeStepTinyMaxDeltaT "system/controlDict" "maxDeltaT" "never end" "maxDeltaT >= 1e-11"
stepsCase clockTimeTinyDeltaT writeControl clockTime writeInterval 1 adjustTimeStep no deltaT 1e-200
expectFailure clockTimeTinyDeltaT "system/controlDict" "deltaT" "never end" "deltaT >= 1e-11"
stepsCase cpuTimeSmallMaxDeltaT writeControl cpuTime writeInterval 1 maxDeltaT 1e-12
expectFailure cpuTimeSmallMaxDeltaT "system/controlDict" "maxDeltaT" "never end" "maxDeltaT >= 1e-11"
stepsCase tinyWriteInterval writeInterval 1e-12
expectFailure tinyWriteInterval "system/controlDict" "writeInterval" "land on every write time" "writeInterval >= 1e-11"
stepsCase firstWriteMaxDeltaT maxDeltaT 2e-10
expectFailure firstWriteMaxDeltaT "system/controlDict" "maxDeltaT" "seem to hang" "maxDeltaT >= 5e-10"
stepsCase fixedStepEndTime adjustTimeStep no endTime 1e20
expectFailure fixedStepEndTime "system/controlDict" "deltaT" "never end" "endTime <= "
# The initial state: speeds beyond light (U) and wave speeds beyond it (h),
# with timeStep writes, where no first write time bounds the steps
stepsCase lightSpeedU writeControl timeStep writeInterval 1
foamDictionary "$d/0/U" -entry internalField -set "uniform (1e20 0 0)" > /dev/null
expectFailure lightSpeedU "0/U" "U = (1e+20 0 0)" "speed of light"
stepsCase lightSpeedC writeControl timeStep writeInterval 1
foamDictionary "$d/0/h" -entry internalField -set "uniform 1e20" > /dev/null
expectFailure lightSpeedC "wave speed" "speed of light" "h = 1e+20" "0/h"

# -- Initial fields ------------------------------------------------------------
d=$(newCase negativeH)
python3 - "$d/0/h" <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r"\n10\n", "\n-0.5\n", s, count=1)
open(p, "w").write(s)
PY
expectFailure negativeH "h = -0.5" ">= 0"

d=$(newCase nanH)
python3 - "$d/0/h" <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
# one NaN among the values of the nonuniform list
s = re.sub(r"\n10\n", "\nnan\n", s, count=1)
open(p, "w").write(s)
PY
expectFailure nanH "h"

# -- Meshes --------------------------------------------------------------------
d=$(newCase gradedMesh)
sed -i 's/simpleGrading (1 1 1)/simpleGrading (3 1 1)/' "$d/system/blockMeshDict"
(cd "$d" && blockMesh > log.blockMesh 2>&1)
expectFailure gradedMesh "Graded"

d=$(newCase threeD)
sed -i 's/(\$nx \$ny 1)/($nx $ny 2)/' "$d/system/blockMeshDict"
(cd "$d" && blockMesh > log.blockMesh 2>&1)
expectFailure threeD "3D mesh" "one cell in z"

d=$(newCase twoBlocks)
cat > "$d/system/blockMeshDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices
(
    (-12.8 -1.6 0) (0 -1.6 0) (0 1.6 0) (-12.8 1.6 0)
    (-12.8 -1.6 1) (0 -1.6 1) (0 1.6 1) (-12.8 1.6 1)
    (12.8 -1.6 0) (12.8 1.6 0) (12.8 -1.6 1) (12.8 1.6 1)
);
blocks
(
    hex (0 1 2 3 4 5 6 7) (32 8 1) simpleGrading (1 1 1)
    hex (1 8 9 2 5 10 11 6) (32 8 1) simpleGrading (1 1 1)
);
boundary
(
    upslope   { type patch; faces ((0 4 7 3)); }
    downslope { type patch; faces ((8 9 11 10)); }
    sides     { type wall;  faces ((0 1 5 4) (3 7 6 2) (1 8 10 5) (2 6 11 9)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7) (1 2 9 8) (5 10 11 6)); }
);
DICT
(cd "$d" && blockMesh > log.blockMesh 2>&1 && restore0Dir)
expectFailure twoBlocks "2 blocks"

# -- A block numbered from its other corner (axes along -x and -y) gives the
#    same solution, cell by cell ------------------------------------------------
ref=$(newCase orderRef)
rev=$(newCase orderReversed)
sed -i 's/hex (0 1 2 3 4 5 6 7)/hex (2 3 0 1 6 7 4 5)/' "$rev/system/blockMeshDict"
(cd "$rev" && blockMesh > log.blockMesh 2>&1 && restore0Dir \
    && setAvalancheFields > log.setAvalancheFields 2>&1)
for d in "$ref" "$rev"
do
    (cd "$d" && postProcess -func writeCellCentres -time 0 > log.postProcess 2>&1 \
        && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
done
if /usr/bin/python3 - "$ref" "$rev" "$project/tutorials/tools" <<'PY'
import sys
sys.path.insert(0, sys.argv[3])
import foamCase
import numpy as np
a, b = sys.argv[1], sys.argv[2]
def keyed(case):
    C = foamCase.read_field(case, "0", "C")
    h = foamCase.read_field(case, "0.1", "h", len(C))
    order = np.lexsort((np.round(C[:, 0], 6), np.round(C[:, 1], 6)))
    return C[order], h[order]
Ca, ha = keyed(a)
Cb, hb = keyed(b)
same_cells = np.allclose(Ca, Cb, atol=1e-9)
differ = int(np.sum(ha != hb))
print("      reversed block: %d of %d cells differ" % (differ, len(ha)))
sys.exit(0 if same_cells and differ == 0 and np.max(ha) > 0 else 1)
PY
then
    pass "reversed block (hex (2 3 0 1 6 7 4 5)): h at t = 0.1 identical cell by cell"
else
    fail "reversed block gives a different solution (see $rev)"
fi

# -- Boundary conditions -------------------------------------------------------
d=$(newCase inletOutlet)
foamDictionary "$d/0/U" -entry boundaryField/downslope -set \
    "{ type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0); }" \
    > /dev/null
expectFailure inletOutlet "unsupported boundary condition" "zeroGradient" \
    "slip" "fixedValue"

d=$(newCase noSlipWall)
foamDictionary "$d/0/U" -entry boundaryField/sides/type -set noSlip > /dev/null
expectFailure noSlipWall "unsupported boundary condition" "noSlip"

# -- Options -------------------------------------------------------------------
d=$(newCase unknownBackend)
SH_ARGS="-backend opencl" expectFailure unknownBackend "opencl" "auto cpu cuda"

d=$(newCase unknownPrecision)
SH_ARGS="-precision half" expectFailure unknownPrecision "half" "double single"

# -- Legal input: a frictionless bed (delta = 0) runs ---------------------------
d=$(newCase frictionless)
setEntry "$d/$tp" CoulombCoeffs/delta 0
setEntry "$d/$tp" earthPressure activePassive
if (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
&& grep -q "^End" "$d/log.savageHutterFoam" && [ -f "$d/0.1/h" ]
then
    pass "frictionless: delta = 0 with activePassive runs to t = 0.1"
else
    fail "frictionless: delta = 0 did not run (see $d/log.savageHutterFoam)"
fi

# -- Legal input: Voellmy friction runs; PouliquenForterre with a jet runs ---
d=$(newCase voellmy)
setEntry "$d/$tp" frictionModel Voellmy
setEntry "$d/$tp" VoellmyCoeffs "{ mu 0.2; xi 500; }"
if (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
&& grep -q "frictionModel Voellmy { mu 0.2, xi 500 m/s^2 }" "$d/log.savageHutterFoam" \
&& [ -f "$d/0.1/h" ]
then
    pass "Voellmy (mu 0.2, xi 500) selected and runs to t = 0.1"
else
    fail "Voellmy did not run (see $d/log.savageHutterFoam)"
fi

d=$(jetCase jet)
setEntry "$d/$tp" earthPressure isotropic
if (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
&& grep -q "jet: impingingJet at (0 0 0), R 0.5, R_imp 1, u_jet 2" "$d/log.savageHutterFoam" \
&& grep -q "Steady-state check: |dh/dt| over [0-9]* wet cells: RMS" "$d/log.savageHutterFoam" \
&& [ -f "$d/postProcessing/steadyState/0/dhdt.dat" ] && [ -f "$d/0.1/h" ]
then
    pass "PouliquenForterre with an impinging jet runs; |dh/dt| reported and written"
else
    fail "PouliquenForterre with a jet did not run (see $d/log.savageHutterFoam)"
fi

# -- steadyStateTolerance ends a run; the |dh/dt| written is the RMS over
#    the wet cells; a restart writes its own postProcessing/steadyState/<t0>
d=$(jetCase steadyStop)
setEntry "$d/$tp" earthPressure isotropic
setEntry "$d/system/fvSolution" savageHutter/steadyStateTolerance 1e9
(cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
if grep -q "steady state reached at t = 0.05" "$d/log.savageHutterFoam" \
&& grep -q "^End" "$d/log.savageHutterFoam" \
&& [ -f "$d/0.05/h" ] && [ ! -d "$d/0.1" ]
then
    pass "steadyStateTolerance 1e9: the run ends at the first write time, 0.05 < endTime 0.1"
else
    fail "steadyStateTolerance did not end the run at t = 0.05 (see $d/log.savageHutterFoam)"
fi
setEntry "$d/system/fvSolution" savageHutter/steadyStateTolerance 0
setEntry "$d/system/controlDict" startFrom latestTime
(cd "$d" && savageHutterFoam -backend cpu > log.restart 2>&1)
dat="$d/postProcessing/steadyState/0.05/dhdt.dat"
if [ -f "$dat" ] && [ -f "$d/0.1/h" ] && python3 - "$d" "$dat" <<'PY'
import re, sys
def h(case, t):
    d = open("%s/%s/h" % (case, t)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", d)
    return [float(x) for x in m.group(2).split()]
a, b = h(sys.argv[1], "0.05"), h(sys.argv[1], "0.1")
r = [abs(y - x) / 0.05 for x, y in zip(a, b) if x > 1e-6 or y > 1e-6]
rms = (sum(v * v for v in r) / len(r)) ** 0.5
row = [l.split() for l in open(sys.argv[2]) if l.strip() and l[0] != "#"]
t, rmsW, maxW, n = float(row[0][0]), float(row[0][1]), float(row[0][2]), int(row[0][3])
print("      written: t %g RMS %.10g max %.10g over %d; from the fields: RMS %.10g max %.10g over %d"
      % (t, rmsW, maxW, n, rms, max(r), len(r)))
ok = len(row) == 1 and t == 0.1 and n == len(r) \
    and abs(rmsW - rms) <= 1e-9 * rms and abs(maxW - max(r)) <= 1e-9 * max(r)
sys.exit(0 if ok else 1)
PY
then
    pass "restart 0.05 -> 0.1: postProcessing/steadyState/0.05 holds the RMS and max of |dh/dt| over wet cells computed from the fields"
else
    fail "steady-state report of the restart wrong or missing ($dat)"
fi

# -- Inflow: a supercritical stream enters a dry bed through fixedValue ------
d=$(newCase inflow)
cp "$d/0.orig/h" "$d/0/h"
foamDictionary "$d/0/h" -entry boundaryField/upslope -set \
    "{ type fixedValue; value uniform 1; }" > /dev/null
foamDictionary "$d/0/U" -entry boundaryField/upslope -set \
    "{ type fixedValue; value uniform (5 0 0); }" > /dev/null
if (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) \
&& grep -q "xMin: patch upslope, inflow h 1 U (5 0 0)" "$d/log.savageHutterFoam"
then
    # h u W t = 1 x 5 x 3.2 x 0.1 m^3 (the stream is supercritical: nothing
    # goes back out, and the front is still inside the domain)
    vol=$(grep "^Time = 0.1 " "$d/log.savageHutterFoam" | tail -n1 \
        | sed 's/.*volume = \([^ ]*\).*/\1/')
    if python3 -c "import sys; sys.exit(abs(float('$vol') - 1.6) > 1e-7)"
    then
        pass "inflow: fixedValue h 1, U (5 0 0): volume at t = 0.1 is $vol = h u W t = 1.6"
    else
        fail "inflow: volume at t = 0.1 is $vol, not h u W t = 1.6"
    fi
else
    fail "inflow: the run failed or the inflow was not recognised (see $d/log.savageHutterFoam)"
fi

# -- controlDict functions run at the write times ------------------------------
d=$(newCase functionObjects)
foamDictionary "$d/system/controlDict" -entry functions -set \
    '{ hRange { type fieldMinMax; libs ("libfieldFunctionObjects.so"); fields (h); } }' \
    > /dev/null
(cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
dat="$(find "$d/postProcessing" -name 'fieldMinMax.dat' 2>/dev/null | head -n1)"
rows=$(grep -cv '^#' "$dat" 2>/dev/null)
if [ -n "$dat" ] && [ "$rows" -eq 2 ] && grep -q "^0.05 " "$dat" && grep -q "^0.1 " "$dat"
then
    pass "function objects: fieldMinMax wrote $rows rows (t = 0.05, 0.1)"
else
    fail "function objects: expected 2 rows of fieldMinMax, got '${rows:-none}' (see $d)"
fi

# -- writeControl timeStep: a time directory every 10 steps and at the end --
d=$(newCase writeControlTimeStep)
setEntry "$d/system/controlDict" writeControl timeStep
setEntry "$d/system/controlDict" writeInterval 10
if (cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
then
    steps=$(sed -n 's/^Time loop: \([0-9]*\) steps.*/\1/p' "$d/log.savageHutterFoam")
    nDirs=$(timeDirs "$d" | wc -l)
    expected=$(( (steps + 9) / 10 ))
    if [ -n "$steps" ] && [ "$nDirs" -eq "$expected" ] && [ -f "$d/0.1/h" ]
    then
        pass "writeControl timeStep: $steps steps, $nDirs time directories, the last at endTime 0.1"
    else
        fail "writeControl timeStep: $steps steps gave $nDirs time directories, expected $expected ending at 0.1"
    fi
else
    fail "writeControl timeStep: the run failed (see $d/log.savageHutterFoam)"
fi

# -- Restart continuity (hazard maps pMax and tArrival included) ---------------
full=$(newCase restartFull)
part=$(newCase restartPart)
setEntry "$full/system/controlDict" endTime 0.3
setEntry "$part/system/controlDict" endTime 0.15
setEntry "$full/constant/transportProperties" rho 1500
setEntry "$part/constant/transportProperties" rho 1500
(cd "$full" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
(cd "$part" && savageHutterFoam -backend cpu > log.1 2>&1)
setEntry "$part/system/controlDict" endTime 0.3
setEntry "$part/system/controlDict" startFrom latestTime
(cd "$part" && savageHutterFoam -backend cpu > log.2 2>&1)
same=true
for t in 0.15 0.2 0.25 0.3
do
    for f in h U hU regime hMax UMax pMax tArrival
    do
        if ! cmp -s "$full/$t/$f" "$part/$t/$f"
        then
            same=false
            echo "      $t/$f differs"
        fi
    done
done
if $same && grep -q "Reading field hU: the momentum" "$part/log.2" \
&& grep -q "^Time = 0.3 " "$part/log.2" \
&& ! grep -q "^Time = 0.1 " "$part/log.2"
then
    pass "restart: 0 -> 0.15, then latestTime -> 0.3, files identical to 0 -> 0.3 (pMax and tArrival included)"
else
    fail "restart does not continue exactly (see $part)"
fi

# -- Time directories appear complete or not at all --------------------------

# A run killed (SIGKILL) again and again while it writes a time directory
# every step: every time directory it leaves is complete; what it was
# writing is removed, with a warning, at the restart
d=$(newCase killedWhileWriting)
(
    cd "$d" || exit 1
    setBlockCells 256 32
    blockMesh > log.blockMesh 2>&1 && restore0Dir > /dev/null \
        && setAvalancheFields > log.setAvalancheFields 2>&1
) || fail "killedWhileWriting: set-up failed"
setEntry "$d/system/controlDict" writeControl timeStep
setEntry "$d/system/controlDict" writeInterval 1
setEntry "$d/system/controlDict" endTime 100
setEntry "$d/system/controlDict" startFrom latestTime
kills=0
incomplete=""
for pause in 1.0 1.3 1.7 2.2 2.8
do
    (cd "$d" && exec savageHutterFoam -backend cpu > "log.$pause" 2>&1) &
    pid=$!
    sleep "$pause"
    kill -KILL "$pid" 2>/dev/null && kills=$((kills + 1))
    wait "$pid" 2>/dev/null
    for t in $(timeDirs "$d")
    do
        complete "$d" "$t" || incomplete="$incomplete $t"
    done
done
nDirs=$(timeDirs "$d" | wc -l)
leftover=false
[ -d "$d/.savageHutterFoam-writing" ] && leftover=true
setEntry "$d/system/controlDict" writeControl adjustableRunTime
setEntry "$d/system/controlDict" writeInterval 0.05
restartFromLast "$d" 0.01 $leftover
rc=$restartRc
warned=$restartWarned
if [ "$kills" -eq 5 ] && [ "$nDirs" -gt 5 ] && [ -z "$incomplete" ] \
&& [ $rc -eq 0 ] && $warned && [ ! -d "$d/.savageHutterFoam-writing" ]
then
    pass "killed while writing: 5 SIGKILLs, $nDirs time directories, all complete; restart ran (staging left by a kill: $leftover, removed with a warning)"
else
    fail "killed while writing: kills $kills, $nDirs dirs, incomplete:${incomplete:- none}, restart rc $rc, leftover $leftover warned $warned (see $d)"
fi

# -- Signals: SIGUSR1 writes the state and the run goes on; SIGTERM writes
#    it and ends the run normally; a restart from there continues exactly
sig=$(newCase signals)
(
    cd "$sig" || exit 1
    setBlockCells 256 32
    blockMesh > log.blockMesh 2>&1 && restore0Dir > /dev/null \
        && setAvalancheFields > log.setAvalancheFields 2>&1
) || fail "signals: set-up failed"
ref="$work/signalsRef"
rm -rf "$ref" && cp -r "$sig" "$ref"
setEntry "$sig/system/controlDict" endTime 100
log="$sig/log.savageHutterFoam"
(cd "$sig" && exec savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) &
pid=$!
for i in $(seq 600)
do
    grep -q "^Starting time loop" "$log" 2>/dev/null && break
    sleep 0.1
done
sleep 0.5
kill -USR1 "$pid"
sleep 1
aliveAfterUsr1=false
kill -0 "$pid" 2>/dev/null && aliveAfterUsr1=true
t0=$(date +%s.%N)
kill -TERM "$pid"
wait "$pid"
rc=$?
took=$(python3 -c "print('%.2f' % ($(date +%s.%N) - $t0))")
stopDir=$(sed -n 's/^Stopped by SIGTERM at t = .*, written to \([^ ]*\) .*/\1/p' "$log")
usr1Line=$(grep -n "^SIGUSR1 at t = .*: writing$" "$log" | head -n1 | cut -d: -f1)
termLine=$(grep -n "^SIGTERM at t = .*: writing and stopping$" "$log" | head -n1 | cut -d: -f1)
if [ $rc -eq 0 ] && $aliveAfterUsr1 && [ -n "$usr1Line" ] && [ -n "$termLine" ] \
&& [ "$usr1Line" -lt "$termLine" ] && [ -n "$stopDir" ] && complete "$sig" "$stopDir" \
&& grep -q "^End" "$log" && python3 -c "import sys; sys.exit(not $took < 10)"
then
    pass "signals: SIGUSR1 wrote and the run went on; SIGTERM wrote $stopDir and ended the run (exit 0) in $took s"
else
    fail "signals: rc $rc, alive after SIGUSR1 $aliveAfterUsr1, lines $usr1Line/$termLine, stop dir '$stopDir', $took s (see $log)"
fi
# The reference runs without a stop to two write times past the stop; the
# stopped run restarts from latestTime to the same end
if [ -n "$stopDir" ]
then
    end=$(python3 -c "import math; print(round((math.floor($stopDir/0.05 + 1e-6) + 2)*0.05, 6))")
    setEntry "$ref/system/controlDict" endTime "$end"
    setEntry "$sig/system/controlDict" endTime "$end"
    setEntry "$sig/system/controlDict" startFrom latestTime
    (cd "$ref" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    (cd "$sig" && savageHutterFoam -backend cpu > log.restart 2>&1)
    same=true
    compared=""
    for t in $(timeDirs "$ref")
    do
        python3 -c "import sys; sys.exit(not $t > $stopDir)" || continue
        compared="$compared $t"
        for f in h U hU regime hMax UMax tArrival
        do
            cmp -s "$ref/$t/$f" "$sig/$t/$f" || { same=false; echo "      $t/$f differs"; }
        done
    done
    if $same && [ "$(echo $compared | wc -w)" -eq 2 ] \
    && grep -q "Write times on the grid of the run that wrote $stopDir: 0 + k 0.05" "$sig/log.restart"
    then
        pass "signals: restart from $stopDir continues exactly: files at$compared identical to an uninterrupted run"
    else
        fail "signals: restart from $stopDir differs from an uninterrupted run at$compared (see $sig/log.restart)"
    fi
fi

# -- A live controlDict (runTimeModifiable yes): changes to writeInterval,
#    endTime and stopAt act during the run; an invalid change is reported
#    and the run goes on as before
#- liveCase <name>: the 256 x 32 case of the signal test, endTime 100
liveCase()
{
    local d="$work/$1"
    rm -rf "$d" && cp -r "$ref" "$d"
    rm -rf "$d"/log.* "$d/postProcessing"
    for t in $(timeDirs "$d"); do rm -rf "${d:?}/$t"; done
    setEntry "$d/system/controlDict" startFrom startTime
    setEntry "$d/system/controlDict" endTime 100
    setEntry "$d/system/controlDict" runTimeModifiable yes
    echo "$d"
}
#- liveEdit <case> <keyword> <value>...: change entries of the running
#  case's controlDict (edited aside, then moved into place in one step)
liveEdit()
{
    local d="$1"
    shift
    cp "$d/system/controlDict" "$d/system/controlDict.new"
    while [ $# -ge 2 ]
    do
        setRaw "$d/system/controlDict.new" "$1" "$2"
        shift 2
    done
    mv "$d/system/controlDict.new" "$d/system/controlDict"
}
#- onGrid <time> <interval>: whether time is a multiple of interval
onGrid()
{
    python3 -c "import sys; k = $1/$2; sys.exit(abs(k - round(k)) > 1e-6)"
}

# writeInterval 0.05 -> 0.02, then endTime 100 -> a time ahead of the run
d=$(liveCase liveWriteInterval)
log="$d/log.savageHutterFoam"
(cd "$d" && exec savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) &
pid=$!
waitFor "$log" "^Starting time loop" 60
sleep 0.3
liveEdit "$d" writeInterval 0.02
waitFor "$log" "^controlDict changed at t = .* writeInterval 0.05 -> 0.02;" 20
tChange=$(sed -n 's/^controlDict changed at t = \([^:]*\):.*writeInterval 0.05 -> 0.02;.*/\1/p' "$log")
last=$(timeDirs "$d" | sort -g | tail -n1)
end=$(python3 -c "print('%.6g' % ((round(${last:-0}/0.02) + 50)*0.02))")
liveEdit "$d" endTime "$end"
waitFor "$log" "^End" 300 || kill -TERM "$pid"
wait "$pid"
rc=$?
offGrid=""
after=0
for t in $(timeDirs "$d")
do
    python3 -c "import sys; sys.exit(not $t > ${tChange:-1e9})" || continue
    after=$((after + 1))
    onGrid "$t" 0.02 || offGrid="$offGrid $t"
done
final=$(timeDirs "$d" | sort -g | tail -n1)
if [ $rc -eq 0 ] && [ -n "$tChange" ] && [ -z "$offGrid" ] && [ "$after" -ge 3 ] \
&& [ "$final" = "$end" ] && complete "$d" "$final" && grep -q "endTime 100 -> $end;" "$log"
then
    pass "live controlDict: writeInterval 0.05 -> 0.02 at t = $tChange ($after directories after it, all on the 0.02 grid), endTime 100 -> $end: the run ended there"
else
    fail "live controlDict: rc $rc, change at '$tChange', off the 0.02 grid:${offGrid:- none}, $after after, last '$final' (endTime $end) (see $log)"
fi

# The stop modes, with writeInterval 50 (no regular write time within the
# test: the live case advances far slower than that): writeNow writes
# the state where the change is seen, off the write grid, and ends the run;
# noWriteNow ends it writing nothing; nextWrite (writeInterval 0.5 there)
# runs on and ends at the first write time after the change; an endTime
# already passed ends the run at once, writing the state. An invalid change
# is reported and ignored.
#- changedAt <log> <regex>: t of the "controlDict changed" line matching
changedAt()
{
    sed -n "s/^controlDict changed at t = \([^:]*\):.*$2.*/\1/p" "$1" | head -n1
}
#- stoppedAt <log> <by>: t and directory of "Stopped by <by> at t = ..."
stoppedAt()
{
    sed -n "s/^Stopped by $2 at t = \([^,]*\), written to \([^ ]*\) .*/\1 \2/p" "$1"
}
#- liveStop <name> <writeInterval> <seconds to wait> <keyword> <value>...:
#  run the live case, change the entries after the start, wait for the end
liveStop()
{
    local d
    d=$(liveCase "$1")
    setEntry "$d/system/controlDict" writeInterval "$2"
    local wait="$3"
    shift 3
    (cd "$d" && exec savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) &
    local pid=$!
    waitFor "$d/log.savageHutterFoam" "^Starting time loop" 60
    sleep 0.3
    if [ "$1" = "invalid" ]
    then
        shift
        liveEdit "$d" writeInterval 0
        waitFor "$d/log.savageHutterFoam" "is invalid; the run goes on as before" 20
    fi
    liveEdit "$d" "$@"
    waitFor "$d/log.savageHutterFoam" "^End" "$wait" || kill -TERM "$pid"
    wait "$pid"
    echo $? > "$d/rc"
}

liveStop liveWriteNow 50 60 invalid writeInterval 50 stopAt writeNow
d="$work/liveWriteNow"
log="$d/log.savageHutterFoam"
tChange=$(changedAt "$log" "stopAt writeNow;")
read -r tStop stopDir <<< "$(stoppedAt "$log" "stopAt writeNow")"
if [ "$(cat "$d/rc")" = 0 ] && grep -q "Invalid writeInterval '0'" "$log" \
&& [ -n "$tChange" ] && [ "$tStop" = "$tChange" ] && [ -n "$stopDir" ] \
&& [ "$(timeDirs "$d" | tr '\n' ' ')" = "$stopDir " ] && complete "$d" "$stopDir" \
&& ! onGrid "$stopDir" 50
then
    pass "live controlDict: writeInterval 0 reported and ignored; stopAt writeNow seen at t = $tChange wrote $stopDir (off the write grid of 50, the only directory) and ended the run"
else
    fail "live controlDict: writeNow rc $(cat "$d/rc"), change at '$tChange', stop at '$tStop' in '$stopDir', directories: $(timeDirs "$d" | tr '\n' ' ') (see $log)"
fi

liveStop liveNoWriteNow 50 60 stopAt noWriteNow
d="$work/liveNoWriteNow"
log="$d/log.savageHutterFoam"
tChange=$(changedAt "$log" "stopAt noWriteNow;")
if [ "$(cat "$d/rc")" = 0 ] && [ -n "$tChange" ] \
&& grep -q "^Stopped by stopAt noWriteNow at t = $tChange, not written" "$log" \
&& [ -z "$(timeDirs "$d")" ] && [ ! -d "$d/.savageHutterFoam-writing" ]
then
    pass "live controlDict: stopAt noWriteNow seen at t = $tChange ended the run with no directory written"
else
    fail "live controlDict: noWriteNow rc $(cat "$d/rc"), change at '$tChange', directories: $(timeDirs "$d" | tr '\n' ' ') (see $log)"
fi

liveStop liveNextWrite 0.5 120 stopAt nextWrite
d="$work/liveNextWrite"
log="$d/log.savageHutterFoam"
tChange=$(changedAt "$log" "stopAt nextWrite;")
read -r tStop nextDir <<< "$(stoppedAt "$log" "stopAt nextWrite")"
expected=$(python3 -c "import math; print('%.6g' % ((math.floor(${tChange:-0}/0.5 + 1e-9) + 1)*0.5))")
if [ "$(cat "$d/rc")" = 0 ] && [ -n "$tChange" ] && [ "$nextDir" = "$expected" ] \
&& python3 -c "import sys; sys.exit(not $tChange < $tStop)" \
&& [ "$(timeDirs "$d" | sort -g | tail -n1)" = "$nextDir" ] && complete "$d" "$nextDir" \
&& [ -z "$(timeDirs "$d" | while read -r t; do python3 -c "import sys; sys.exit(not $tChange < $t < $nextDir)" && echo "$t"; done)" ]
then
    pass "live controlDict: stopAt nextWrite seen at t = $tChange: the run went on to the next write time $nextDir and ended there"
else
    fail "live controlDict: nextWrite rc $(cat "$d/rc"), change at '$tChange', stopped at '$tStop' in '$nextDir' (expected $expected) (see $log)"
fi

liveStop liveEndTimePassed 50 60 endTime 0.001
d="$work/liveEndTimePassed"
log="$d/log.savageHutterFoam"
tChange=$(changedAt "$log" "endTime 100 -> 0.001;")
read -r tStop stopDir <<< "$(stoppedAt "$log" "endTime")"
if [ "$(cat "$d/rc")" = 0 ] && [ -n "$tChange" ] && [ "$tStop" = "$tChange" ] \
&& python3 -c "import sys; sys.exit(not $tChange > 0.001)" \
&& [ "$(timeDirs "$d" | tr '\n' ' ')" = "$stopDir " ] && complete "$d" "$stopDir"
then
    pass "live controlDict: endTime 100 -> 0.001, already passed at t = $tChange: the run ended at once, writing $stopDir"
else
    fail "live controlDict: endTime passed: rc $(cat "$d/rc"), change at '$tChange', stop at '$tStop' in '$stopDir', directories: $(timeDirs "$d" | tr '\n' ' ') (see $log)"
fi

# writeControl adjustableRunTime -> timeStep (every 20 steps) during the
# run: the directories written after the change are those of time indices
# that are multiples of 20 (uniform/time: index), as Time writes them
d=$(liveCase liveWriteControl)
log="$d/log.savageHutterFoam"
(cd "$d" && exec savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1) &
pid=$!
waitFor "$log" "^Starting time loop" 60
sleep 0.3
liveEdit "$d" writeControl timeStep writeInterval 20
waitFor "$log" "^controlDict changed at t = .* writeControl timeStep, writeInterval 0.05 -> 20;" 20
tChange=$(sed -n 's/^controlDict changed at t = \([^:]*\):.*writeControl timeStep.*/\1/p' "$log")
before=$(timeDirs "$d" | wc -l)
waitFor "$log" "^Time = " 5
for i in $(seq 100)
do
    [ "$(timeDirs "$d" | wc -l)" -ge $((before + 3)) ] && break
    sleep 0.1
done
liveEdit "$d" stopAt writeNow
waitFor "$log" "^End" 60 || kill -TERM "$pid"
wait "$pid"
rc=$?
stopDir=$(sed -n 's/^Stopped by stopAt writeNow at t = .*, written to \([^ ]*\) .*/\1/p' "$log")
bad=""
stepDirs=0
for t in $(timeDirs "$d")
do
    python3 -c "import sys; sys.exit(not $t > ${tChange:-1e9})" || continue
    [ "$t" = "$stopDir" ] && continue
    idx=$(sed -n 's/^index *\([0-9]*\);/\1/p' "$d/$t/uniform/time")
    stepDirs=$((stepDirs + 1))
    [ -n "$idx" ] && [ $((idx % 20)) -eq 0 ] || bad="$bad $t(index $idx)"
done
if [ $rc -eq 0 ] && [ -n "$tChange" ] && [ "$stepDirs" -ge 2 ] && [ -z "$bad" ]
then
    pass "live controlDict: writeControl adjustableRunTime -> timeStep 20 at t = $tChange: $stepDirs directories after it, each at a time index that is a multiple of 20"
else
    fail "live controlDict: writeControl change at '$tChange', rc $rc, $stepDirs directories after it, off the index grid:${bad:- none} (see $log)"
fi

# A latest time directory cut short (an older version killed while
# writing, an edit): the restart stops naming the file and line and says
# what to remove; nothing is written
d=$(newCase truncatedLatest)
(cd "$d" && savageHutterFoam -backend cpu > log.1 2>&1)
size=$(stat -c %s "$d/0.1/U")
truncate -s $((size / 2)) "$d/0.1/U"
setEntry "$d/system/controlDict" startFrom latestTime
setEntry "$d/system/controlDict" endTime 0.2
(cd "$d" && savageHutterFoam -backend cpu > log.2 2>&1)
rc=$?
log="$d/log.2"
if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$log" && grep -qE "0\.1/U.* at line [0-9]+" "$log" \
&& grep -q "rm -r .*/truncatedLatest/0.1" "$log" && grep -q "To restart from 0.05" "$log" \
&& [ ! -d "$d/0.15" ] && ! grep -qE "printStack|^#[0-9]+ " "$log"
then
    pass "truncated latest time: stops naming $(grep -oE '[^ ]*0\.1/U[^ ]* at line [0-9]+' "$log" | head -n1 | sed "s|$work/||"), says 'rm -r .../0.1', writes nothing"
else
    fail "truncated latest time: rc $rc, message or hint missing, or something written (see $log)"
fi

# Other unreadable latest time directories (a file missing or empty, an
# empty directory, an optional hU, hMax, UMax or uniform/time present but
# without a header): the same message naming the file, the same hint (and
# the rm of an optional file alone); nothing written. A value read whole
# but invalid gets the plain validation error, without that hint.
lat=$(newCase latestBase)
(cd "$lat" && savageHutterFoam -backend cpu > log.1 2>&1)
setEntry "$lat/system/controlDict" startFrom latestTime
setEntry "$lat/system/controlDict" endTime 0.2
#- unreadableLatest <name> <edit in the case> <message regex> [file alone]
unreadableLatest()
{
    local name="$1" edit="$2" pattern="$3" alone="${4:-}"
    local d="$work/$name"
    rm -rf "$d" && cp -r "$lat" "$d"
    (cd "$d" && eval "$edit" && savageHutterFoam -backend cpu > log.2 2>&1)
    local rc=$?
    local log="$d/log.2"
    if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$log" && grep -qE "$pattern" "$log" \
    && grep -q "rm -r .*/$name/0.1\"*$" "$log" && grep -q "To restart from 0.05" "$log" \
    && { [ -z "$alone" ] || grep -q "^    rm .*/$name/0.1/$alone\"*$" "$log"; } \
    && [ ! -d "$d/0.15" ] && [ ! -d "$d/.savageHutterFoam-writing" ] \
    && ! grep -qE "printStack|^#[0-9]+ " "$log"
    then
        pass "$name: stops naming the file ($(grep -m1 -A1 "FOAM FATAL" "$log" | tail -n1 | sed "s|$work/||" | cut -c1-70)), says 'rm -r .../0.1'${alone:+ or 'rm .../0.1/$alone'}, writes nothing"
    else
        fail "$name: rc $rc, message '$pattern' or hint missing, or something written (see $log)"
    fi
}
unreadableLatest latestMissingU "rm 0.1/U" '0\.1/U" is missing'
unreadableLatest latestEmptyDir "rm -r 0.1/*" '0\.1/h" is missing'
unreadableLatest latestEmptyU ": > 0.1/U" '0\.1/U" cannot be read: no FoamFile header'
unreadableLatest latestEmptyhMax ": > 0.1/hMax" '0\.1/hMax" cannot be read' hMax
unreadableLatest latestEmptyUMax ": > 0.1/UMax" '0\.1/UMax" cannot be read' UMax
unreadableLatest latestHeaderlesshU "sed -i '1,/^}/d' 0.1/hU" '0\.1/hU" cannot be read' hU
unreadableLatest latestEmptyTime ": > 0.1/uniform/time" '0\.1/uniform/time" cannot be read' uniform/time
unreadableLatest latesthUClass "sed -i 's/volVectorField/volScalarField/' 0.1/hU" '0\.1/hU" is of class volScalarField, not volVectorField' hU

d="$work/latestNegativeh"
rm -rf "$d" && cp -r "$lat" "$d"
foamDictionary "$d/0.1/h" -entry internalField -set "uniform -0.5" > /dev/null
(cd "$d" && savageHutterFoam -backend cpu > log.2 2>&1)
rc=$?
log="$d/log.2"
if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$log" && grep -q "^h = -0.5 in cell" "$log" \
&& grep -q "^file: .*/latestNegativeh/0.1/h$" "$log" && ! grep -q "rm -r\|cut it short" "$log" \
&& [ ! -d "$d/0.15" ]
then
    pass "latestNegativeh: h = -0.5 in the start time is the plain validation error naming 0.1/h, no 'rm -r' hint, nothing written"
else
    fail "latestNegativeh: rc $rc, validation error missing or an 'rm -r' hint given (see $log)"
fi

# purgeWrite 2 keeps the last two time directories of the run
d=$(newCase purgeWrite)
setEntry "$d/system/controlDict" purgeWrite 2
setEntry "$d/system/controlDict" endTime 0.2
(cd "$d" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
kept="$(timeDirs "$d" | sort -g | tr '\n' ' ')"
if [ "$kept" = "0.15 0.2 " ] && complete "$d" 0.2
then
    pass "purgeWrite 2: the run to 0.2 keeps $kept"
else
    fail "purgeWrite 2: kept '$kept', expected '0.15 0.2 ' (see $d)"
fi

# -- Disk and permissions: a write that fails (here a file size limit,
#    ulimit -f, standing in for a full disk) stops the run naming the path;
#    the earlier time directories stay intact, nothing incomplete appears,
#    and the next start clears what the failed write left
d=$(newCase writeFails)
setEntry "$d/system/controlDict" endTime 0.05
(cd "$d" && savageHutterFoam -backend cpu > log.1 2>&1)
cp -r "$d/0.05" "$work/writeFails.0.05"
setEntry "$d/system/controlDict" endTime 0.1
setEntry "$d/system/controlDict" startFrom latestTime
# The log through a pipe: the limit is on every file the solver writes
(cd "$d" && ulimit -f 4 && trap '' XFSZ && exec savageHutterFoam -backend cpu 2>&1) \
    | cat > "$d/log.2"
rc=${PIPESTATUS[0]}
log="$d/log.2"
intact=true
diff -r "$work/writeFails.0.05" "$d/0.05" > /dev/null || intact=false
if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$log" \
&& grep -q "Cannot write .*writeFails/.savageHutterFoam-writing/0.1" "$log" \
&& grep -q "disk full" "$log" && ! grep -qE "printStack|^#[0-9]+ " "$log" \
&& $intact && [ ! -d "$d/0.1" ] && [ "$(timeDirs "$d")" = "0.05" ]
then
    (cd "$d" && savageHutterFoam -backend cpu > log.3 2>&1)
    if grep -q "Removing .*savageHutterFoam-writing" "$d/log.3" && complete "$d" 0.1 \
    && [ ! -d "$d/.savageHutterFoam-writing" ]
    then
        pass "write fails (ulimit -f 4): stops naming .savageHutterFoam-writing/0.1, 0.05 intact, no 0.1; the next start clears it and writes 0.1"
    else
        fail "write fails: the run after the failed write did not clear it or write 0.1 (see $d/log.3)"
    fi
else
    fail "write fails: rc $rc, message, 0.05 intact $intact, or directories $(timeDirs "$d" | tr '\n' ' ') (see $log)"
fi
# -- A read-only case directory: the run stops at once naming it, nothing
#    is written, the earlier time directories stay.  As root permissions
#    do not stop writes: a read-only bind mount does (skipped, saying why,
#    where mounting is not allowed)
d=$(newCase readOnly)
setEntry "$d/system/controlDict" endTime 0.05
(cd "$d" && savageHutterFoam -backend cpu > log.1 2>&1)
setEntry "$d/system/controlDict" endTime 0.1
setEntry "$d/system/controlDict" startFrom latestTime
roLog="$work/readOnly.log"
made=""
if [ "$(id -u)" -eq 0 ]
then
    if mount --bind "$d" "$d" 2>/dev/null && mount -o remount,ro,bind "$d" 2>/dev/null
    then
        made=mount
    else
        umount "$d" 2>/dev/null
    fi
else
    chmod a-w "$d" && made=chmod
fi
if [ -z "$made" ]
then
    skip "read-only case directory: as root, and a read-only bind mount is not allowed here"
else
    cp -r "$d/0.05" "$work/readOnly.0.05"
    (cd "$d" && savageHutterFoam -backend cpu > "$roLog" 2>&1)
    rc=$?
    [ "$made" = mount ] && umount "$d" || chmod u+w "$d"
    if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$roLog" \
    && grep -q "Cannot write into the case directory \"$d\"" "$roLog" \
    && ! grep -q "Starting time loop" "$roLog" \
    && ! grep -qE "printStack|^#[0-9]+ " "$roLog" \
    && [ "$(timeDirs "$d")" = "0.05" ] && diff -r "$work/readOnly.0.05" "$d/0.05" > /dev/null
    then
        pass "read-only case directory ($made): stops before the time loop naming it; 0.05 intact, nothing written"
    else
        fail "read-only case directory ($made): rc $rc (see $roLog)"
    fi
fi

# -- A full disk (a small tmpfs, where mounting is allowed): the write
#    that does not fit stops the run naming the path, the earlier time
#    directory stays intact, the next start (with room) clears the rest
fs="$work/fullDisk"
mkdir -p "$fs"
if [ "$(id -u)" -eq 0 ] && mount -t tmpfs -o size=64m tmpfs "$fs" 2>/dev/null
then
    d="$fs/case"
    cp -r "$base" "$d"
    rm -f "$d"/log.*
    setEntry "$d/system/controlDict" endTime 0.05
    (cd "$d" && savageHutterFoam -backend cpu > "$work/fullDisk.1.log" 2>&1)
    cp -r "$d/0.05" "$work/fullDisk.0.05"
    setEntry "$d/system/controlDict" endTime 0.1
    setEntry "$d/system/controlDict" startFrom latestTime
    used=$(du -sk "$fs" | cut -f1)
    one=$(du -sk "$d/0.05" | cut -f1)
    # Room for half a time directory more
    mount -o remount,size=$((used + one/2 + 8))k "$fs"
    (cd "$d" && savageHutterFoam -backend cpu > "$work/fullDisk.2.log" 2>&1)
    rc=$?
    log="$work/fullDisk.2.log"
    if [ $rc -ne 0 ] && grep -q "FOAM FATAL" "$log" \
    && grep -q "Cannot write .*fullDisk/case/.savageHutterFoam-writing/0.1" "$log" \
    && ! grep -qE "printStack|^#[0-9]+ " "$log" \
    && diff -r "$work/fullDisk.0.05" "$d/0.05" > /dev/null && [ ! -d "$d/0.1" ]
    then
        mount -o remount,size=64m "$fs"
        (cd "$d" && savageHutterFoam -backend cpu > "$work/fullDisk.3.log" 2>&1)
        if complete "$d" 0.1 && [ ! -d "$d/.savageHutterFoam-writing" ]
        then
            pass "full disk (tmpfs): stops naming .savageHutterFoam-writing/0.1, 0.05 intact; with room again the next start writes 0.1"
        else
            fail "full disk: the start after it did not write 0.1 (see $work/fullDisk.3.log)"
        fi
    else
        fail "full disk: rc $rc, message or 0.05 intact (see $log)"
    fi
    umount "$fs"
else
    skip "full disk on a tmpfs: mounting is not allowed here (the ulimit -f test above stands in)"
fi

# -- A restart whose U was edited after the write uses h U, not the stale hU --
d=$(newCase editedRestart)
setEntry "$d/system/controlDict" endTime 0.05
(cd "$d" && savageHutterFoam -backend cpu > log.1 2>&1)
foamDictionary "$d/0.05/U" -entry internalField -set "uniform (0 0 0)" > /dev/null
setEntry "$d/system/controlDict" startFrom latestTime
setEntry "$d/system/controlDict" endTime 0.1
(cd "$d" && savageHutterFoam -backend cpu > log.2 2>&1)
if grep -q "hU disagrees with h U" "$d/log.2" && grep -q "^End" "$d/log.2"
then
    pass "edited restart: U set to 0 in 0.05/U is used (hU ignored, with a warning)"
else
    fail "edited restart: no warning, or the run failed (see $d/log.2)"
fi

# -- Peak maps: hMax >= h and UMax >= |U| (wet cells) at every write time,
#    and neither decreases in time ------------------------------------------
if python3 - "$full" <<'PY'
import os, re, sys
case = sys.argv[1]
def field(t, name):
    text = open(os.path.join(case, t, name)).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*\(", text)
    if not m:
        v = re.search(r"internalField\s+uniform\s+\(?([^;)]*)", text).group(1).split()
        return None, [float(x) for x in v]
    body = text[m.end():text.index("\n)", m.end())]
    vals = [float(x) for x in body.replace("(", " ").replace(")", " ").split()]
    return (3 if m.group(1) == "vector" else 1), vals
times = sorted((d for d in os.listdir(case) if re.fullmatch(r"[0-9.]+", d) and d != "0"), key=float)
prev = None
bad = 0
for t in times:
    _, h = field(t, "h")
    _, U = field(t, "U")
    _, hMax = field(t, "hMax")
    _, UMax = field(t, "UMax")
    for c in range(len(h)):
        speed = (U[3*c]**2 + U[3*c+1]**2) ** 0.5
        if hMax[c] < h[c] or (h[c] > 1e-6 and UMax[c] < speed * (1 - 1e-12)):
            bad += 1
        if prev and (hMax[c] < prev[0][c] or UMax[c] < prev[1][c]):
            bad += 1
    prev = (hMax, UMax)
print("      %d times, %d cells, %d violations; max hMax %.6g, max UMax %.6g"
      % (len(times), len(h), bad, max(hMax), max(UMax)))
sys.exit(1 if bad or len(times) < 2 or max(UMax) <= 0 else 0)
PY
then
    pass "peak maps: hMax >= h, UMax >= |U|, both non-decreasing in time"
else
    fail "peak maps hMax/UMax inconsistent (see $full)"
fi

# -- foamToVTK reads the output --------------------------------------------------
if (cd "$full" && foamToVTK > log.foamToVTK 2>&1)
then
    vtu="$(ls "$full"/VTK/*/internal.vtu 2>/dev/null | sort -t_ -k2 -n | tail -n1)"
    names="$(grep -ao "Name='[a-zA-Z]*'" "$vtu" 2>/dev/null | sort -u | tr '\n' ' ')"
    missing=""
    for f in h U hU zb regime hMax UMax
    do
        case "$names" in *"Name='$f'"*) ;; *) missing="$missing $f" ;; esac
    done
    if [ -n "$vtu" ] && [ -z "$missing" ] \
    && grep -aq "NumberOfCells='512'" "$vtu" \
    && [ "$(ls "$full"/VTK/*.vtm | wc -l)" -eq 7 ]
    then
        pass "foamToVTK: 7 times, h U hU zb regime hMax UMax on 512 cells in ${vtu#$full/}"
    else
        fail "foamToVTK output lacks$missing or 512 cells or 7 times (see $full/VTK)"
    fi
else
    fail "foamToVTK failed (see $full/log.foamToVTK)"
fi

# -- Hazard maps pMax and tArrival ----------------------------------------------
# In the restart run above (rho 1500, arrivalThreshold 0.01 m): tArrival -1
# exactly where hMax <= 0.01, set once (the same at every later time), not
# after its time; pMax = rho UMax^2 to round-off; dimensions Pa and s
if python3 - "$full" <<'PY'
import os, re, sys
case = sys.argv[1]
def field(t, name):
    text = open(os.path.join(case, t, name)).read()
    dims = re.search(r"dimensions\s+(\[[^\]]*\])", text).group(1)
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    body = text[m.end():text.index("\n)", m.end())]
    return dims, [float(x) for x in body.split()]
times = sorted((d for d in os.listdir(case) if re.fullmatch(r"[0-9.]+", d) and d != "0"), key=float)
bad, prev, arrived, later = 0, None, 0, 0
for t in times:
    _, hMax = field(t, "hMax")
    _, UMax = field(t, "UMax")
    dp, pMax = field(t, "pMax")
    dt, ta = field(t, "tArrival")
    bad += dp != "[1 -1 -2 0 0 0 0]" or dt != "[0 0 1 0 0 0 0]"
    for c in range(len(hMax)):
        bad += (ta[c] >= 0) != (hMax[c] > 0.01) or ta[c] > float(t)
        bad += abs(pMax[c] - 1500 * UMax[c] ** 2) > 1e-12 * pMax[c]
        bad += prev is not None and prev[c] >= 0 and ta[c] != prev[c]
    prev = ta
arrived = sum(x >= 0 for x in prev)
later = sum(x > 0 for x in prev)
print("      %d times, %d cells arrived (%d after t = 0), last arrival %.6g, max pMax %.6g Pa, %d violations"
      % (len(times), arrived, later, max(prev), max(pMax), bad))
sys.exit(1 if bad or later == 0 else 0)
PY
then
    pass "hazard maps: tArrival set once, where hMax > arrivalThreshold only; pMax = rho UMax^2; dimensions Pa and s"
else
    fail "hazard maps pMax/tArrival inconsistent (see $full)"
fi

# arrivalThreshold: refused unless positive, finite and at most 1e30
for v in 0 -0.01 1e31
do
    d=$(newCase "arrivalThreshold$v")
    setEntry "$d/constant/transportProperties" arrivalThreshold "$v"
    expectFailure "arrivalThreshold$v" arrivalThreshold transportProperties
done

# A restart with another arrivalThreshold than tArrival was made with is
# refused, naming tArrival and what to do; without tArrival it runs, the
# cells already reached taking the start time (with a warning)
d=$(newCase arrivalRestart)
cp -r "$part/0.15" "$d/"
setEntry "$d/constant/transportProperties" arrivalThreshold 0.5
setEntry "$d/system/controlDict" startFrom latestTime
setEntry "$d/system/controlDict" endTime 0.2
(cd "$d" && savageHutterFoam -backend cpu > log.1 2>&1)
rc1=$?
written1="$(timeDirs "$d" | tr '\n' ' ')"
rm "$d/0.15/tArrival"
(cd "$d" && savageHutterFoam -backend cpu > log.2 2>&1)
rc2=$?
if [ $rc1 -ne 0 ] && grep -q "tArrival disagrees with hMax" "$d/log.1" \
&& grep -q "rm .*0.15/tArrival" "$d/log.1" && [ "$written1" = "0.15 " ] \
&& [ $rc2 -eq 0 ] && grep -q "No tArrival in 0.15: the .* cells" "$d/log.2" \
&& grep -q "^0\.15000000" "$d/0.2/tArrival"
then
    pass "restart with another arrivalThreshold: refused naming tArrival; without tArrival it runs (reached cells at the start time, warned)"
else
    fail "restart with another arrivalThreshold (rc $rc1, then $rc2; time directories after the first: $written1; see $d/log.1, log.2)"
fi

# hazardMaps at several times (timeSelector), on the terrainChute tutorial
# shortened (40 m cells, 20 s, a write every 10 s)
d="$work/hazardMapsTimes"
rm -rf "$d"
cp -r "$project/tutorials/terrainChute" "$d"
rm -f "$d"/log.*
if (
    cd "$d" && runApplication ./makeTerrain \
    && setEntry system/terrainDict cellSize 40 \
    && runApplication terrainToCase && runApplication blockMesh \
    && setEntry system/controlDict endTime 20 \
    && setEntry system/controlDict writeInterval 10 \
    && runApplication savageHutterFoam -backend cpu
) > "$d/log.prepare" 2>&1
then
    #- maps <args>: the times hazardMaps wrote, after a clean start
    maps()
    {
        rm -rf "$d/postProcessing/hazardMaps"
        (cd "$d" && hazardMaps "$@" > log.hazardMaps 2>&1) || { echo failed; return; }
        (cd "$d/postProcessing/hazardMaps" && ls | sort -g | tr '\n' ' ')
    }
    problems=""
    for spec in "-time 10,20|10 20 " "-time 10:20|10 20 " "-time 10|10 " \
                "-latestTime|20 " "|20 "
    do
        got="$(maps ${spec%%|*})"
        [ "$got" = "${spec#*|}" ] || problems="$problems '${spec%%|*}' gave '$got';"
    done
    maps -time 10,20 > /dev/null
    for t in 10 20
    do
        for f in hMax UMax pMax deposit tArrival
        do
            for e in asc tif
            do
                [ -f "$d/postProcessing/hazardMaps/$t/$f.$e" ] \
                    || problems="$problems no $t/$f.$e;"
            done
        done
    done
    # tArrival: nodata where never arrived (no -1), values within [0, t]
    python3 - "$d" <<'PY' || problems="$problems tArrival raster wrong;"
import sys
d = sys.argv[1]
for t in (10, 20):
    rows = open(f"{d}/postProcessing/hazardMaps/{t}/tArrival.asc").read().split("\n")[6:]
    v = [float(x) for r in rows for x in r.split()]
    flow = [x for x in v if x != -9999]
    if not flow or min(flow) < 0 or max(flow) > t or max(flow) <= 0:
        sys.exit(1)
PY
    # Without rho and without the field pMax at 20: the other maps
    # written there, pMax skipped and said so
    rm -rf "$d/postProcessing/hazardMaps"
    sed -i 's/^rho .*//' "$d/constant/transportProperties"
    rm "$d/20/pMax"
    (cd "$d" && hazardMaps -time 10,20 > log.noRho 2>&1) \
        || problems="$problems failed without rho and pMax;"
    grep -q "pMax skipped" "$d/log.noRho" \
        || problems="$problems no 'pMax skipped' without rho and pMax;"
    for m in hMax UMax deposit tArrival
    do
        [ -f "$d/postProcessing/hazardMaps/20/$m.asc" ] \
            || problems="$problems no $m at 20 without rho and pMax;"
    done
    [ ! -f "$d/postProcessing/hazardMaps/20/pMax.asc" ] \
        || problems="$problems a pMax at 20 without rho and pMax;"
    if [ -z "$problems" ]
    then
        pass "hazardMaps: -time 10,20, -time 10:20, -time 10, -latestTime and the default (latest) map the right times into postProcessing/hazardMaps/<time>; tArrival nodata where never reached; without rho and pMax the other maps written, pMax skipped and said so"
    else
        fail "hazardMaps times:$problems (see $d)"
    fi
else
    fail "hazardMaps times: the shortened terrainChute case failed (see $d/log.prepare)"
fi

finish

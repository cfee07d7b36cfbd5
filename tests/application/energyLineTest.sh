#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The energy line: a Coulomb slide with lambda = 0 (friction
#     mu g cos(zeta), whose work is mu g times the horizontal distance
#     travelled) on a concave chute stops with its centre of mass
#     on the line of slope tan(delta) from where it started, so hazardMaps'
#     comTravelAngle is delta.  The chute is a DEM this test writes: its
#     slope falls linearly from 35 deg at the top to 5 deg 600 m down, then
#     stays 5 deg to 900 m; a shallow parabolic trough across (10 m up at
#     100 m to either side) keeps the flow off the sides.  terrainToCase
#     (20 m cells, 47 x 10), the solver to rest (steadyStateTolerance),
#     hazardMaps; passes when |comTravelAngle - delta| < 0.5 deg, no volume
#     left the mesh and the run ended at rest.  Then the same chute with
#     Voellmy's friction must end by kineticEnergyStop (the flow's kinetic
#     energy below 1 % of its peak), log that energy as the fields' own,
#     and run no film away (filmCheck.py).
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     energyLineTest.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
python=/usr/bin/python3
delta=20

mkdir -p "$work/system" "$work/constant"
cd "$work" || exit 1
tutorial="$project/tutorials/terrainChute"
# In a subshell: setEntry and runApplication exit on a failure
(
    cp "$tutorial"/system/{controlDict,fvSolution,fvSchemes} system/ \
        && cp "$tutorial"/constant/transportProperties constant/ \
        && setEntry constant/transportProperties lambda 0 \
        && setEntry constant/transportProperties CoulombCoeffs/delta "$delta" \
        && setEntry system/controlDict endTime 400 \
        && setEntry system/controlDict writeInterval 50
) || fail "copying the terrainChute tutorial's dictionaries or setEntry failed"

$python - <<'PYEOF'
import math
NX, NY, D, X0, Y0 = 240, 70, 4.0, -20.0, -140.0
def angle(x):
    return math.radians(35 + (5 - 35)*min(max(x/600, 0), 1))
def profile(x):
    # elevation of the centre line: -int tan(angle) dx, midpoint rule on
    # 0.5 m steps
    n = max(1, int(abs(x)/0.5))
    h = x/n
    return 1000 - sum(math.tan(angle((k + 0.5)*h))*h for k in range(n))
with open("constant/chute.asc", "w") as o:
    o.write(f"ncols {NX}\nnrows {NY}\nxllcorner {X0}\nyllcorner {Y0}\n"
            f"cellsize {D}\nNODATA_value -9999\n")
    col = [profile(X0 + (i + 0.5)*D) for i in range(NX)]
    for j in range(NY):
        y = Y0 + (NY - j - 0.5)*D
        o.write(" ".join("%.17g" % (col[i] + 10*(y/100)**2)
                         for i in range(NX)) + "\n")
PYEOF
[ $? -eq 0 ] || fail "writing the DEM chute.asc"

cat > system/terrainDict <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "constant/chute.asc";
axis            ((0 0) (900 0));
halfWidth       100;
cellSize        20;
profileSmoothing 40;
release
{
    slab
    {
        polygon     ((40 -40) (120 -40) (120 40) (40 40));
        thickness   3;
        thicknessDirection vertical;
    }
}
EOD

start=$SECONDS
if (
    runApplication terrainToCase && runApplication blockMesh \
        && runApplication savageHutterFoam && runApplication hazardMaps
)
then
    latest="$(ls postProcessing/hazardMaps | sort -g | tail -n1)"
    report="postProcessing/hazardMaps/$latest/report.dat"
    get() { sed -n "s/^$1 //p" "$report"; }
    com="$(get comTravelAngle)"
    if $python -c "import sys; sys.exit(0 if abs($com - $delta) < 0.5 else 1)"
    then
        pass "energy line: comTravelAngle $com deg, delta $delta deg (|difference| < 0.5)"
    else
        fail "energy line: comTravelAngle $com deg, delta $delta deg (|difference| >= 0.5)"
    fi
    released="$(get releasedVolume)"
    deposit="$(get depositVolume)"
    outflow="$(get outflowVolume)"
    # outflowVolume from the unrounded sums (report.dat's volumes have 10
    # digits): 0 when the two agree to 1e-9 of the release
    if $python -c "import sys; sys.exit(0 if abs($outflow) <= 1e-9*$released else 1)"
    then
        pass "no volume left the mesh: released $released m^3, at t = $latest $deposit m^3, outflowVolume $outflow"
    else
        fail "volume left the mesh: released $released m^3, at t = $latest $deposit m^3, outflowVolume $outflow"
    fi
    if grep -q "steady state reached" log.savageHutterFoam
    then
        pass "at rest: $(grep -o 'steady state reached.*' log.savageHutterFoam)"
    else
        fail "not at rest by endTime (see $work/log.savageHutterFoam)"
    fi
else
    fail "terrainToCase, blockMesh, savageHutterFoam or hazardMaps failed (see $work/log.*)"
fi
echo "($((SECONDS - start)) s)"

# -- The end of a Voellmy run (kineticEnergyStop): the same chute with
#    Voellmy's friction (mu 0.2, xi 2000 m/s^2) never comes to rest where
#    it is steeper than atan(mu) = 11.3 deg (its films drain at their
#    terminal speed); the run must end when the kinetic energy falls
#    below 1 % of its peak, the energy logged must be sum h |u|^2/2 dA of
#    the fields written at that time, and no film may run away
#    (filmCheck.py)
start=$SECONDS
v="$work/voellmy"
rm -rf "$v"
mkdir -p "$v"
cp -r system constant 0 "$v"/
(
    cd "$v" || exit 1
    setEntry constant/transportProperties frictionModel Voellmy
    setEntry constant/transportProperties VoellmyCoeffs "{ mu 0.2; xi 2000; }"
    setEntry system/fvSolution savageHutter/kineticEnergyStop 0.01
    runApplication savageHutterFoam
) > "$work/voellmy.log" 2>&1
log="$v/log.savageHutterFoam"
stopped="$(sed -n 's/.*the flow has stopped at t = \([0-9.e+-]*\).*/\1/p' "$log")"
if [ -n "$stopped" ] && grep -q "^End" "$log" \
    && $python -c "import sys; sys.exit(0 if float('$stopped') < 400 else 1)"
then
    pass "Voellmy: the run ends at t = $stopped < endTime 400 (kinetic energy below 1 % of its peak)"
    if $python - "$v" "$stopped" "$log" <<'PYEOF'
import os, re, sys
sys.path.insert(0, os.path.join(os.environ["SAVAGEHUTTER_DIR"], "tutorials", "tools"))
import foamCase
case, t, log = sys.argv[1:]
t = foamCase.closest_time(case, float(t))
h = foamCase.read_field(case, t, "h")
hU = foamCase.read_field(case, t, "hU", h.size)
wet = h > 1e-6
m = re.search(r"Mesh: \d+ x \d+ cells of (\S+) x (\S+) m", open(log).read())
dA = float(m.group(1)) * float(m.group(2))
e = 0.5 * ((hU[wet, 0] ** 2 + hU[wet, 1] ** 2) / h[wet]).sum() * dA
logged = float(re.findall(r"Kinetic energy: (\S+) m", open(log).read())[-1])
print("      kinetic energy at t = %s: logged %.8g, from the fields %.8g" % (t, logged, e))
sys.exit(0 if abs(logged - e) <= 1e-6 * e else 1)
PYEOF
    then
        pass "Voellmy: the logged kinetic energy is sum h |u|^2/2 dA of the written fields"
    else
        fail "Voellmy: the logged kinetic energy is not that of the written fields ($log)"
    fi
    if "$project/tests/application/filmCheck.py" "$v"
    then
        pass "Voellmy: no film runs away (filmCheck.py)"
    else
        fail "Voellmy: a film runs away (filmCheck.py above)"
    fi
else
    fail "Voellmy: the run did not end by kineticEnergyStop before endTime (see $log)"
fi
echo "($((SECONDS - start)) s)"

finish

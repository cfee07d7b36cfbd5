#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     A case of system/terrainDict and a DEM in constant/ alone, as a new
#     user makes it: terrainToCase writes system/controlDict, fvSchemes,
#     fvSolution and a commented constant/transportProperties with
#     defaults, says so for each, and the case then runs (blockMesh,
#     savageHutterFoam) to rest.  The DEM (written here: a 30 deg slope
#     running out onto a flat floor, 240 x 80 m of 2 m pixels, and a
#     shallow trough across) is taken along an axis (4 m cells).  A second
#     terrainToCase keeps every file the user has (a marker put into each
#     survives, nothing "Wrote ... it was missing").  The commented sample
#     etc/caseDicts/terrainDict, its dem and polygon set for this DEM, makes
#     a case (the plan mode) that runs to rest as the README's first case
#     (blockMesh, savageHutterFoam, hazardMaps: runout downhill of the
#     release).  An axis drawn uphill is refused with its
#     elevations (nothing written); a stretch of the profile that rises is
#     a warning with figures.  terrainToCase -help gives every keyword of
#     terrainDict and of a release entry its own line with its range or
#     form (a keyword's mere word elsewhere in the help does not count).
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     terrainDefaultsTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
python=/usr/bin/python3

rm -rf "$work/user" "$work/sample"
mkdir -p "$work/user/system" "$work/user/constant" \
    "$work/sample/system" "$work/sample/constant"

$python - "$work/user/constant/dem.asc" <<'PYEOF'
import math, sys
nx, ny, d, x0, y0 = 120, 40, 2.0, 1000.0, 5000.0
t = math.tan(math.radians(30))
def z(X, Y):
    # 30 deg for 100 m, rounded into the floor over 40 m, then flat;
    # a trough 1 m deep at 40 m to either side of Y = 5040
    s = X - x0
    if s < 100:
        zs = -t*s
    elif s < 140:
        zs = -t*100 - t*(s - 100) + t*(s - 100)**2/80
    else:
        zs = -t*120
    return 2000 + zs + ((Y - 5040)/40)**2
with open(sys.argv[1], "w") as o:
    o.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\n"
            f"cellsize {d}\nNODATA_value -9999\n")
    for j in range(ny):
        Y = y0 + (ny - j - 0.5)*d
        o.write(" ".join("%.17g" % z(x0 + (i + 0.5)*d, Y)
                         for i in range(nx)) + "\n")
PYEOF
cp "$work/user/constant/dem.asc" "$work/sample/constant/"

cat > "$work/user/system/terrainDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "constant/dem.asc";
axis            ((1002 5040) (1236 5040));
halfWidth       30;
cellSize        4;
profileSmoothing 8;
release
{
    r1
    {
        polygon     ((1010 5032) (1030 5032) (1030 5048) (1010 5048));
        thickness   1;
        thicknessDirection normal;
    }
}
EOF

# 1. The defaults written, each announced; the case runs to rest
u="$work/user"
if (cd "$u" && terrainToCase > log.terrainToCase 2>&1)
then
    for f in system/controlDict system/fvSchemes system/fvSolution
    do
        if [ -f "$u/$f" ] && grep -q "^Wrote $f (.*it was missing)" "$u/log.terrainToCase"
        then
            pass "defaults: $f written and announced"
        else
            fail "defaults: $f not written or not announced (log.terrainToCase)"
        fi
    done
    if grep -q "^Writing constant/transportProperties with the defaults" "$u/log.terrainToCase" \
        && grep -q "^frictionModel *Coulomb;" "$u/constant/transportProperties" \
        && grep -q "^inclination *table" "$u/constant/transportProperties"
    then
        pass "defaults: constant/transportProperties written (Coulomb), announced, its inclination table set"
    else
        fail "defaults: constant/transportProperties not written as the defaults with the inclination table"
    fi
    if (cd "$u" && blockMesh > log.blockMesh 2>&1 \
        && savageHutterFoam > log.savageHutterFoam 2>&1)
    then
        if grep -q "steady state reached at t = " "$u/log.savageHutterFoam"
        then
            pass "defaults: the case runs to rest ($(grep -o 'steady state reached at t = [0-9.e+-]*' "$u/log.savageHutterFoam" | tail -n1))"
        else
            fail "defaults: the run did not end at rest (log.savageHutterFoam)"
        fi
    else
        fail "defaults: blockMesh or savageHutterFoam failed (see $u/log.*)"
    fi
else
    fail "defaults: terrainToCase failed on a case of terrainDict and a DEM (see $u/log.terrainToCase)"
fi

# 2. A second terrainToCase keeps the user's files
for f in system/controlDict system/fvSchemes system/fvSolution constant/transportProperties
do
    echo "// the user's own: kept" >> "$u/$f"
done
if (cd "$u" && terrainToCase > log.terrainToCase2 2>&1)
then
    kept=true
    for f in system/controlDict system/fvSchemes system/fvSolution constant/transportProperties
    do
        grep -q "^// the user's own: kept" "$u/$f" || kept=false
    done
    if $kept && ! grep -q "it was missing" "$u/log.terrainToCase2"
    then
        pass "defaults: a second terrainToCase keeps every file the case has"
    else
        fail "defaults: a second terrainToCase overwrote a file or announced a default"
    fi
else
    fail "defaults: the second terrainToCase failed (see $u/log.terrainToCase2)"
fi

# 3. The sample terrainDict, its dem and polygon set for this DEM
s="$work/sample"
$python - "$project/etc/caseDicts/terrainDict" "$s/system/terrainDict" <<'PYEOF'
import re, sys
t = open(sys.argv[1]).read()
t = t.replace('"constant/dem.tif"', '"constant/dem.asc"')
t, n = re.subn(r"polygon\s+\(\([^;]*\)\);",
               "polygon     ((1010 5032) (1030 5032) (1030 5048) (1010 5048));",
               t, count=1)
assert n == 1
t = re.sub(r"^cellSize\s+\S+;", "cellSize        4;", t, flags=re.M)
open(sys.argv[2], "w").write(t)
PYEOF
if (cd "$s" && terrainToCase > log.terrainToCase 2>&1) \
    && grep -q "^coordinates *plan;" "$s/constant/transportProperties" \
    && [ -f "$s/0/h" ] && [ -f "$s/system/controlDict" ]
then
    pass "sample: etc/caseDicts/terrainDict makes a case (plan mode, with the defaults)"
else
    fail "sample: etc/caseDicts/terrainDict did not make a case (see $s/log.terrainToCase)"
fi
# ... and runs to rest as the README's first case does (blockMesh,
# savageHutterFoam, hazardMaps): the end of run at rest before endTime, a
# report whose runout lies downhill of the release (travelAngle > 0, the
# runout beyond the polygon's X = 1030)
if [ -f "$s/0/h" ] && (cd "$s" && blockMesh > log.blockMesh 2>&1 \
        && savageHutterFoam > log.savageHutterFoam 2>&1 \
        && hazardMaps > log.hazardMaps 2>&1)
then
    endLine="$(grep '^End of run at t = ' "$s/log.savageHutterFoam")"
    last="$(timeDirs "$s" | tail -n 1)"
    r="$s/postProcessing/hazardMaps/$last/report.dat"
    runX="$(awk '$1 == "runoutX" {print $2}' "$r" 2>/dev/null)"
    angle="$(awk '$1 == "travelAngle" {print $2}' "$r" 2>/dev/null)"
    if [[ "$endLine" == "End of run at t = $last s: at rest ("*")" ]] \
        && $python -c "import sys; sys.exit(0 if float('${runX:-nan}') > 1030 and float('${angle:-nan}') > 0 else 1)"
    then
        pass "sample: runs to rest in plan coordinates ('$endLine'), hazardMaps: runoutX $runX m, travelAngle $angle deg"
    else
        fail "sample: final line '$endLine', runoutX '$runX', travelAngle '$angle' (see $s/log.*)"
    fi
else
    fail "sample: blockMesh, savageHutterFoam or hazardMaps failed (see $s/log.*)"
fi

# 4. An axis drawn bottom to top is refused with the figures and nothing
# written; a profile that rises for a stretch (a bump 2 m high on the
# floor, across the whole DEM) is a warning with where and how much
for c in uphill bump
do
    rm -rf "$work/$c"
    mkdir -p "$work/$c/system" "$work/$c/constant"
    cp "$u/system/terrainDict" "$work/$c/system/"
done
cp "$u/constant/dem.asc" "$work/uphill/constant/"
sed -i 's|^axis .*|axis            ((1236 5040) (1002 5040));|' "$work/uphill/system/terrainDict"
$python - "$u/constant/dem.asc" "$work/bump/constant/dem.asc" <<'PYEOF'
import math, sys
lines = open(sys.argv[1]).read().splitlines()
head, rows = lines[:6], [list(map(float, l.split())) for l in lines[6:]]
with open(sys.argv[2], "w") as o:
    o.write("\n".join(head) + "\n")
    for r in rows:
        # X = 1000 + (i + 0.5) 2: a cosine bump 2 m high over X in [1180, 1220]
        o.write(" ".join("%.17g" % (z + (1 + math.cos(math.pi*(1000 + (i + 0.5)*2 - 1200)/20)
                         if abs(1000 + (i + 0.5)*2 - 1200) < 20 else 0))
                         for i, z in enumerate(r)) + "\n")
PYEOF
if (cd "$work/uphill" && terrainToCase > log.terrainToCase 2>&1)
then
    fail "uphill axis: terrainToCase accepted an axis drawn bottom to top"
elif grep -q "keyword 'axis' runs uphill: the DEM is .* m high at its first point" "$work/uphill/log.terrainToCase" \
    && grep -q "Give its points top to" "$work/uphill/log.terrainToCase" \
    && [ ! -e "$work/uphill/0" ] && [ ! -e "$work/uphill/system/controlDict" ]
then
    pass "uphill axis: refused, its elevations and the reversed points named, nothing written"
else
    fail "uphill axis: refused without the figures or with files written (log.terrainToCase)"
fi
if (cd "$work/bump" && terrainToCase > log.terrainToCase 2>&1) \
    && grep -q "the profile along the axis rises (zeta < 0) at .* down to zeta = -" "$work/bump/log.terrainToCase"
then
    pass "counter-slope: a warning with its extent and steepest zeta ($(grep -o 'from [0-9.]* to [0-9.]* m along it' "$work/bump/log.terrainToCase"))"
else
    fail "counter-slope: no warning with figures (see $work/bump/log.terrainToCase)"
fi
if ! grep -q "rises (zeta < 0)" "$u/log.terrainToCase"
then
    pass "counter-slope: no warning on the profile without one"
else
    fail "counter-slope: a warning on a profile that never rises"
fi

# 5. -help: each keyword on its own line (a top-level keyword at the
# start of its line, a release entry's after a space or ';') followed by
# its range or form, so that a word that occurs elsewhere in the help
# ("file", "release") does not pass for its keyword
checks="$(terrainToCase -help 2>&1 | $python -c '
import re, sys
help = sys.stdin.read()
top = [("dem", "\"<file>.asc|.tif\"  vertical elevation [m]"),
       ("cellSize", "> 0 [m]  square cells"),
       ("extent", "((X0 Y0) (X1 Y1))  plan mode, optional"),
       ("axis", "((X0 Y0) (X1 Y1))  axis mode, top to bottom"),
       ("halfWidth", "> 0 [m]  axis mode"),
       ("profileSmoothing", ">= 0 [m]  axis mode"),
       ("release", "{ <name> { ... } ... }"),
       ("entrainment", "{ <name> { ... } ... }  optional: 0/hEntrainable"),
       ("resistance", "{ <name> { ... } ... }  optional: 0/cResistance")]
entry = [("polygon", "((X Y) ...);"), ("file", "\"<.shp>\";"),
         ("raster", "\"<.asc|.tif>\";"), ("thickness", "> 0 [m] (not with raster);"),
         ("thicknessDirection", "vertical | normal;"),
         ("cResistance", "> 0 [1/m] (not with raster);")]
missing = [k for k, r in top
           if not re.search(r"(?m)^ +" + re.escape(k) + r" +" + re.escape(r), help)]
missing += [k for k, r in entry
            if not re.search(r"(?m)(^ +|; +|, +)" + re.escape(k) + r" +" + re.escape(r), help)]
ok = not missing and "etc/caseDicts/terrainDict" in help
print(("PASS  " if ok else "FAIL  ") + "terrainToCase -help: each of the %d terrainDict, release and resistance "
      "keywords on its own line with its range, and the sample named%s"
      % (len(top) + len(entry), "; missing or without its range: " + " ".join(missing) if missing else ""))
')"
tally $? "$checks" "-help"

finish

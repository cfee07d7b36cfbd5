#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     The utility side of the entrainment and resistance areas (issue 28,
#     docs/design.md section 7): the fields 0/hEntrainable and 0/cResistance
#     as setAvalancheFields and terrainToCase write them, and hazardMaps'
#     maps and report of a run with an erodible layer.  Expected values are
#     worked out here from the inputs (cell centres, polygon corners, the
#     bed's slope), not read from the tools' output.
#       1. setAvalancheFields (the damBreak case on 16 x 4 cells): a box of
#          hEntrainable 0.5 gives 0.5 in the 16 cells whose centres it
#          holds and 0 elsewhere, volume 10.24 m^3 (the log's); cResistance
#          a box plus a plane, to 1e-12; both files created with
#          zeroGradient patches (frontAndBack empty) and their dimensions;
#          an existing file's patches kept; refused with nothing written:
#          a negative hEntrainable, a cResistance negative somewhere, a
#          misspelt entry (the valid ones listed), a misspelt shape keyword.
#       2. terrainToCase, plan mode (the planSlopeCase DEM, 4 m cells): an
#          entrainment square of vertical thickness 0.5 on the plane part
#          of the slope gives h = 0.5 cos(35) in its 64 cells, 0 elsewhere,
#          and the volume sum J h A = 0.5 x its plan area (J from 0/zb, and
#          the log's); a resistance polygon (0.02) and a raster (0.03, on
#          the DEM's grid, nodata around) overlapping it sum to 0.05 where
#          they overlap, exact per cell; patches and dimensions; an
#          entrainment raster (0.5 vertical over a 32 m square) in place
#          of the polygon gives 0.5 cos(35) in its 64 cells, volume 512.
#       3. terrainToCase, axis mode (a 35 deg plane): an entrainment square
#          of normal thickness 0.5 in (x, y) gives 0.5 in its 64 cells,
#          volume 800 m^3; a resistance square 0.01 in its 64 cells; the
#          patches upslope, downslope, sides; without the entrainment entry
#          an existing 0/hEntrainable is left byte for byte, with a
#          warning; with it, rewritten as 0/h is (a new thickness).
#       4. terrainToCase refusals: non-zero exit (not a signal), FOAM FATAL
#          IO ERROR naming terrainDict and the keyword, no stack trace,
#          nothing written (no 0/): negative, zero and non-finite values, a
#          polygon outside the grid, keywords of the other kind, a missing
#          thicknessDirection, an entry not a dictionary, an empty one, a
#          raster with a negative value or none > 0, a raster with a
#          thickness.
#       5. hazardMaps on time directories written here: in plan mode,
#          entrainedVolume the sum of J erodedDepth A (J from 0/zb), the
#          balance releasedVolume + entrainedVolume = depositVolume +
#          outflowVolume to 1e-9 with material gone (t = 1) and, with the
#          whole layer taken up and none gone (t = 2), entrainedVolume
#          = 512 m^3 (the layer's volume) and outflowVolume exactly 0;
#          erodedDepth and hEntrainable as .asc (each pixel its cell's,
#          erodedDepth nodata where 0, hEntrainable nowhere) and .tif
#          (read back by gdal_translate: the .asc's values); a time without
#          erodedDepth (t = 3): entrainedVolume 0, the log says why, no
#          erodedDepth map.  In axis mode entrainedVolume 64 x 0.1 x 25 =
#          160 m^3, outflow 0; a case without a layer has no
#          entrainedVolume line and no such maps.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     entrainmentAreaTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
python=/usr/bin/python3
start=$SECONDS

# The helpers of the python checks: a case's fields, patches, dimensions,
# its plan grid and bed (J by zb's centred differences, one-sided at the
# edges, as terrainToCase and hazardMaps take them), a field written into
# a time directory, report.dat and an .asc raster
cat > "$work/areas.py" <<'PYEOF'
import math, os, re
def text(case, t, name):
    return open(f"{case}/{t}/{name}").read()
def field(case, t, name):
    """the internal field: a list (uniform: None)"""
    txt = text(case, t, name)
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(([^)]*)\)", txt)
    return [float(v) for v in m.group(1).split()] if m else None
def patches(case, t, name):
    """{patch: type} of a field file"""
    txt = text(case, t, name)
    bf = txt[txt.index("{", txt.index("boundaryField")) + 1:]
    return dict(re.findall(r"(\w+)\s*\{[^}]*?type\s+(\w+);", bf))
def dims(case, t, name):
    return re.search(r"dimensions\s+(\[[^]]*\]);", text(case, t, name)).group(1)
def entry(txt, key):
    return re.search(r"^%s\s+([^;]*);" % key, txt, re.M).group(1)
def vec(txt, key):
    return [float(v) for v in entry(txt, key).strip("()").split()]
class plan:
    """the plan grid of a terrainToCase case and its bed"""
    def __init__(self, case):
        tm = open(f"{case}/constant/terrainMapping").read()
        self.case = case
        self.nx, self.ny = int(entry(tm, "nx")), int(entry(tm, "ny"))
        self.cs = float(entry(tm, "cellSize"))
        self.origin, self.xAxis, self.yAxis = vec(tm, "origin"), vec(tm, "xAxis"), vec(tm, "yAxis")
        self.zb = field(case, "0", "zb")
    def XY(self, c):
        x, y = (c % self.nx + 0.5)*self.cs, (c // self.nx + 0.5)*self.cs
        return (self.origin[0] + x*self.xAxis[0] + y*self.yAxis[0],
                self.origin[1] + x*self.xAxis[1] + y*self.yAxis[1])
    def J(self, c):
        nx, ny, zb, cs = self.nx, self.ny, self.zb, self.cs
        i, j = c % nx, c // nx
        im, ip, jm, jp = max(i - 1, 0), min(i + 1, nx - 1), max(j - 1, 0), min(j + 1, ny - 1)
        gx = (zb[ip + nx*j] - zb[im + nx*j])/((ip - im)*cs)
        gy = (zb[i + nx*jp] - zb[i + nx*jm])/((jp - jm)*cs)
        return math.sqrt(1 + gx*gx + gy*gy)
    def volume(self, v):
        return sum(self.J(c)*v[c]*self.cs**2 for c in range(len(v)))
def write(case, t, name, values):
    """a scalar field in time directory t, in the format of 0/h"""
    src = text(case, "0", "h")
    body = "nonuniform List<scalar>\n%d\n(\n%s\n)" % (len(values), "\n".join("%.17g" % v for v in values))
    txt = re.sub(r"internalField[^;]*;", lambda m: "internalField   " + body + ";", src, count=1)
    txt = re.sub(r"location\s+\"?[^;]*;", 'location    "%s";' % t, txt, count=1)
    txt = re.sub(r"object\s+\S+;", "object      %s;" % name, txt, count=1)
    os.makedirs(f"{case}/{t}", exist_ok=True)
    open(f"{case}/{t}/{name}", "w").write(txt)
def report(case, t):
    rep, raw = {}, {}
    for line in open(f"{case}/postProcessing/hazardMaps/{t}/report.dat"):
        if line.strip() and not line.startswith("#"):
            k, v = line.split()
            rep[k], raw[k] = float(v), v
    return rep, raw
def asc(path):
    """rows of an ESRI ASCII grid (the top row first) and its nodata"""
    with open(path) as f:
        head = dict(f.readline().split() for _ in range(6))
        rows = [[float(v) for v in l.split()] for l in f if l.strip()]
    return rows, float(head["NODATA_value"])
def close(a, b, rel=1e-9):
    return abs(a - b) <= rel*max(abs(b), 1e-300)
def verticalSquare(case, Y0):
    """0/hEntrainable of a vertical 0.5 over X in (40, 72), Y in (Y0, Y0 +
    32) on the 35 deg plane: 0.5 cos35 in its 64 cells, 0 elsewhere, the
    volume sum J h A and the log's 512 m^3; the grid, ok, the message"""
    g = plan(case)
    v = field(g.case, "0", "hEntrainable")
    inside = [c for c in range(len(v)) if 40 < g.XY(c)[0] < 72 and Y0 < g.XY(c)[1] < Y0 + 32]
    want = 0.5*math.cos(math.radians(35))
    e = max(abs(v[c] - want) for c in inside)
    out = max(abs(v[c]) for c in range(len(v)) if c not in inside)
    vol = g.volume(v)
    log = open(g.case + "/log.terrainToCase").read()
    logged = float(re.search(r"^Erodible volume \(hEntrainable\) (\S+) m\^3", log, re.M).group(1))
    ok = len(inside) == 64 and e < 1e-9 and out == 0 and close(vol, 512) and close(logged, 512, 1e-6)
    return g, ok, "%d cells of h = 0.5 cos35 within %.3g m, max |h| elsewhere %.3g; volume sum J h A %.12g m^3 (0.5 x 32 x 32 = 512), the log %s" % (len(inside), e, out, vol, logged)
PYEOF

#- check <what> <python: sets ok and msg, over areas.py's helpers>
check()
{
    local msg
    if msg="$(cd "$work" && $python - "$2" 2>&1 <<'PYEOF'
import math, sys
from areas import *
a35 = math.tan(math.radians(35))
c35 = math.cos(math.radians(35))
ok, msg = False, "no result"
exec(sys.argv[1])
print(msg)
sys.exit(0 if ok else 1)
PYEOF
)"
    then
        pass "$1: $msg"
    else
        fail "$1: $msg"
    fi
}

#- The case's files and their checksums (to see that nothing was written)
snapshot()
{
    (cd "$1" && find . -type f ! -name 'log.*' -print0 | sort -z \
        | xargs -0 md5sum)
}

#- refusal <case> <what> <command> <regex>...: the command exits non-zero
#  (not by a signal) with FOAM FATAL (IO) ERROR and every regex in its
#  log, no stack trace, and no file of the case written or changed
refusal()
{
    local c="$1" what="$2" cmd="$3" before after rc problems="" re
    shift 3
    before="$(snapshot "$c")"
    (cd "$c" && eval "$cmd" > log.refusal 2>&1)
    rc=$?
    after="$(snapshot "$c")"
    [ $rc -ne 0 ] || problems="$problems exit 0;"
    [ $rc -lt 128 ] || problems="$problems killed by signal $((rc - 128));"
    grep -q "FOAM FATAL" "$c/log.refusal" || problems="$problems no FOAM FATAL;"
    for re in "$@"
    do
        grep -q -- "$re" "$c/log.refusal" || problems="$problems no '$re' in the log;"
    done
    # (OpenFOAM's banner says "trapFpe: Floating point exception trapping")
    grep -v '^trapFpe:' "$c/log.refusal" \
        | grep -q "stack\|Segmentation\|sigFpe\|^#0 \|Floating point exception" \
        && problems="$problems stack trace;"
    [ "$before" = "$after" ] || problems="$problems files written;"
    if [ -z "$problems" ]
    then
        pass "refused, $what: $(grep -m1 -A1 'FOAM FATAL' "$c/log.refusal" | tail -n1 | cut -c1-150)"
    else
        fail "$what:$problems (see $c/log.refusal)"
    fi
}

# -- 1. setAvalancheFields -------------------------------------------------------
# The damBreak case on 16 x 4 cells of 1.6 x 0.8 m over [-12.8, 12.8] x
# [-1.6, 1.6]: cell centres x = -12.8 + 1.6 (i + 1/2), y = -1.6 + 0.8 (j +
# 1/2).  hEntrainable: a box x in [0, 6.4] holds the centres of columns 8
# to 11 (16 cells); cResistance 0.02 above y = 0 plus 0.013 + 0.001 x
sa="$work/setFields"
mkdir -p "$sa"
cp -r "$project"/tutorials/damBreak/{system,constant,0.orig} "$sa"/
writeShapes()
{
    cat > "$sa/system/setAvalancheFieldsDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }
h            ( damBreak { position 0; upstream 1; downstream 0; } );
hEntrainable ( box { min (0 -1.6); max (6.4 1.6); value ${1:-0.5}; } );
cResistance  ( box { min (-12.8 0); max (12.8 1.6); value 0.02; }
               plane { origin (0 0); value ${2:-0.013}; gradient (0.001 0); } );
EOF
}
writeShapes
if (cd "$sa" && setBlockCells 16 4 && rm -rf 0 && cp -r 0.orig 0 \
        && runApplication blockMesh > /dev/null \
        && runApplication setAvalancheFields > /dev/null)
then
    check "setAvalancheFields, hEntrainable of a box" '
case = "'"$sa"'"
v = field(case, "0", "hEntrainable")
xc = lambda c: -12.8 + 1.6*(c % 16 + 0.5)
inside = [c for c in range(64) if 0 <= xc(c) <= 6.4]
vol = sum(v)*1.6*0.8
log = open(case + "/log.setAvalancheFields").read()
logged = float(re.search(r"Writing hEntrainable: volume (\S+) m\^3", log).group(1))
ok = len(v) == 64 and len(inside) == 16 and all(v[c] == 0.5 for c in inside) \
    and all(v[c] == 0 for c in range(64) if c not in inside) \
    and close(vol, 10.24, 1e-12) and close(logged, 10.24, 1e-6)
msg = "%d cells of 0.5 (%d centres in the box), the rest 0; volume %.15g m^3 (16 x 1.6 x 0.8 x 0.5 = 10.24), the log %s" % (sum(1 for x in v if x == 0.5), len(inside), vol, logged)'
    check "setAvalancheFields, cResistance of a box and a plane" '
case = "'"$sa"'"
v = field(case, "0", "cResistance")
xc = lambda c: -12.8 + 1.6*(c % 16 + 0.5)
yc = lambda c: -1.6 + 0.8*(c // 16 + 0.5)
want = [(0.02 if yc(c) >= 0 else 0) + 0.013 + 0.001*xc(c) for c in range(64)]
e = max(abs(a - b) for a, b in zip(v, want))
ok = len(v) == 64 and e < 1e-12 and min(v) > 0
msg = "max |cResistance - (0.02 [y > 0] + 0.013 + 0.001 x)| = %.3g 1/m, range [%.4g, %.4g]" % (e, min(v), max(v))'
    check "setAvalancheFields, the files it created" '
case = "'"$sa"'"
want = {"upslope": "zeroGradient", "downslope": "zeroGradient", "sides": "zeroGradient", "frontAndBack": "empty"}
pe, pc = patches(case, "0", "hEntrainable"), patches(case, "0", "cResistance")
de, dc = dims(case, "0", "hEntrainable"), dims(case, "0", "cResistance")
ok = pe == want and pc == want and de == "[0 1 0 0 0 0 0]" and dc == "[0 -1 0 0 0 0 0]"
msg = "patches %s and %s, dimensions %s and %s" % (pe, pc, de, dc)'

    # An existing file's patches kept (a fixedValue upslope), its values set
    sed -i '/upslope/,/}/ s/type *zeroGradient;/type fixedValue; value uniform 0;/' "$sa/0/hEntrainable"
    writeShapes 0.25
    if (cd "$sa" && runApplication setAvalancheFields > /dev/null)
    then
        check "setAvalancheFields, an existing hEntrainable" '
case = "'"$sa"'"
p = patches(case, "0", "hEntrainable")
v = field(case, "0", "hEntrainable")
ok = p.get("upslope") == "fixedValue" and p.get("downslope") == "zeroGradient" \
    and sorted(set(v)) == [0, 0.25] and v.count(0.25) == 16
msg = "upslope kept %s, %d cells of 0.25" % (p.get("upslope"), v.count(0.25))'
    else
        fail "setAvalancheFields on an existing hEntrainable failed (see $sa/log.setAvalancheFields)"
    fi

    writeShapes -0.5
    refusal "$sa" "setAvalancheFields, hEntrainable -0.5" setAvalancheFields \
        "setAvalancheFieldsDict" "give hEntrainable = -0.5 < 0" "hEntrainable must be >= 0"
    # 0.005 + 0.001 x < 0 for x < -5 (the columns from x = -12 to -5.6)
    writeShapes 0.5 0.005
    refusal "$sa" "setAvalancheFields, cResistance negative where x < -5" setAvalancheFields \
        "setAvalancheFieldsDict" "give cResistance = -0.00" "cResistance must be >= 0"
    writeShapes
    sed -i 's/^hEntrainable /hEntrainible /' "$sa/system/setAvalancheFieldsDict"
    refusal "$sa" "setAvalancheFields, a misspelt entry" setAvalancheFields \
        "setAvalancheFieldsDict" "Unknown entry 'hEntrainible'" "(h U zb hEntrainable cResistance)"
    writeShapes
    sed -i '/^hEntrainable/ s/value/valeu/' "$sa/system/setAvalancheFieldsDict"
    refusal "$sa" "setAvalancheFields, a misspelt keyword of a shape" setAvalancheFields \
        "Unknown keyword 'valeu' of the box in hEntrainable"
else
    fail "setAvalancheFields on the damBreak case failed (see $sa/log.*)"
fi

# -- 2. terrainToCase, plan mode -------------------------------------------------
# The planSlopeCase DEM (2 m pixels from (0, 0), 84 x 60; 4 m cells: 42 x
# 30): a 35 deg plane where a = 0.866 X + 0.5 Y - 10 < 90.  Entrainment:
# the square X in [40, 72], Y in [0, 32] (cells i 10..17, j 0..7; a < 69
# there and at the neighbours the slope takes), vertical thickness 0.5.
# Resistance: f1 the square X in [100, 140], Y in [60, 100] of 0.02, f2 a
# raster of 0.03 over X in [120, 160], Y in [80, 112] (0 and nodata
# elsewhere; away from the DEM's outline, where a raster's pixels are
# dropped): 0.05 where they overlap
planAreas()
{
    cat >> "$1/system/terrainDict" <<'EOF'
entrainment
{
    e1
    {
        polygon     ((40 0) (72 0) (72 32) (40 32));
        thickness   0.5;
        thicknessDirection vertical;
    }
}
resistance
{
    f1 { polygon ((100 60) (140 60) (140 100) (100 100)); cResistance 0.02; }
    f2 { raster "constant/forest.asc"; }
}
EOF
    squareRaster "$1/constant/forest.asc" "${2:-0.03}" 120 160 80 112
}

#- squareRaster <file> <value> <X0> <X1> <Y0> <Y1>: an ESRI ASCII raster on
#  the planSlopeCase DEM's grid (2 m pixels from (0, 0), 84 x 60) of
#  <value> over X in [X0, X1], Y in [Y0, Y1], nodata where X < 20, 0 elsewhere
squareRaster()
{
    $python - "$@" <<'PYEOF'
import sys
nx, ny, d, v = 84, 60, 2.0, float(sys.argv[2])
X0, X1, Y0, Y1 = (float(a) for a in sys.argv[3:7])
with open(sys.argv[1], "w") as o:
    o.write(f"ncols {nx}\nnrows {ny}\nxllcorner 0\nyllcorner 0\ncellsize {d}\nNODATA_value -9999\n")
    for j in range(ny):
        Y = (ny - j - 0.5)*d
        row = []
        for i in range(nx):
            X = (i + 0.5)*d
            row.append(v if X0 < X < X1 and Y0 < Y < Y1 else (-9999 if X < 20 else 0))
        o.write(" ".join("%.17g" % x for x in row) + "\n")
PYEOF
}
pc="$work/plan"
planSlopeCase "$pc" 0 0 0
planAreas "$pc"
if (cd "$pc" && runApplication terrainToCase > /dev/null)
then
    check "terrainToCase plan mode, hEntrainable of a vertical 0.5 square" '
g, ok, msg = verticalSquare("'"$pc"'", 0)
ok = ok and (g.nx, g.ny) == (42, 30)'
    check "terrainToCase plan mode, cResistance of a polygon and a raster" '
g = plan("'"$pc"'")
v = field(g.case, "0", "cResistance")
def want(c):
    X, Y = g.XY(c)
    return (0.02 if 100 < X < 140 and 60 < Y < 100 else 0) + (0.03 if 120 < X < 160 and 80 < Y < 112 else 0)
e = max(abs(v[c] - want(c)) for c in range(len(v)))
n = [sum(1 for c in range(len(v)) if abs(want(c) - w) < 1e-12) for w in (0.02, 0.03, 0.05)]
ok = e < 1e-9 and n == [75, 55, 25]
msg = "max |cResistance - (0.02 [f1] + 0.03 [f2])| = %.3g 1/m; cells of 0.02, 0.03, 0.05: %s" % (e, n)'
    check "terrainToCase plan mode, patches and dimensions" '
case = "'"$pc"'"
want = {"xMin": "zeroGradient", "xMax": "zeroGradient", "yMin": "zeroGradient", "yMax": "zeroGradient", "frontAndBack": "empty"}
pe, pc = patches(case, "0", "hEntrainable"), patches(case, "0", "cResistance")
de, dc = dims(case, "0", "hEntrainable"), dims(case, "0", "cResistance")
ok = pe == want and pc == want and de == "[0 1 0 0 0 0 0]" and dc == "[0 -1 0 0 0 0 0]"
msg = "patches %s, dimensions %s and %s" % (pe, de, dc)'
else
    fail "terrainToCase, plan mode with entrainment and resistance failed (see $pc/log.terrainToCase)"
fi

# An entrainment raster in place of e1's polygon: a vertical thickness of
# 0.5 per pixel over X in [40, 72], Y in [16, 48] (cells i 10..17, j
# 4..11, on the plane part and away from the DEM's outline), 0 elsewhere
rc="$work/planRaster"
planSlopeCase "$rc" 0 0 0
planAreas "$rc"
squareRaster "$rc/constant/snow.asc" 0.5 40 72 16 48
sed -i -e 's/polygon     ((40 0) (72 0) (72 32) (40 32));/raster "constant\/snow.asc";/' \
    -e '/^        thickness   0.5;$/d' "$rc/system/terrainDict"
if grep -q 'raster "constant/snow.asc"' "$rc/system/terrainDict" \
    && ! grep -q '^        thickness   0.5;$' "$rc/system/terrainDict" \
    && (cd "$rc" && runApplication terrainToCase > /dev/null)
then
    check "terrainToCase plan mode, hEntrainable of a raster of vertical thickness 0.5" '
g, ok, msg = verticalSquare("'"$rc"'", 16)'
else
    fail "terrainToCase, plan mode with an entrainment raster failed (see $rc/system/terrainDict, $rc/log.terrainToCase)"
fi

# -- 3. terrainToCase, axis mode -------------------------------------------------
# A 35 deg plane down X (2 m pixels from (1000, 5000), 120 x 80); axis
# ((1010 5080) (1200 5080)), halfWidth 40, 5 m cells: x the arc length from
# X = 1010, so X = 1010 + x cos35; y = Y - 5080.  Entrainment: x in [20,
# 60], y in [-20, 20] (cells i 4..11, j 4..11), normal thickness 0.5, volume
# 0.5 x 40 x 40 = 800 m^3; resistance: x in [80, 120], y in [-40, 0]
# (cells i 16..23, j 0..7) of 0.01
ac="$work/axis"
mkdir -p "$ac/system" "$ac/constant"
$python - "$ac/constant/plane.asc" <<'PYEOF'
import math, sys
nx, ny, d, x0, y0 = 120, 80, 2.0, 1000.0, 5000.0
a = math.tan(math.radians(35))
with open(sys.argv[1], "w") as o:
    o.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\ncellsize {d}\nNODATA_value -9999\n")
    for j in range(ny):
        o.write(" ".join("%.17g" % (2000 - a*(i + 0.5)*d) for i in range(nx)) + "\n")
PYEOF
axisDict()
{
    local X
    X() { $python -c "import math; print('%.17g' % (1010 + $1*math.cos(math.radians(35))))"; }
    cat > "$ac/system/terrainDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "constant/plane.asc";
axis            ((1010 5080) (1200 5080));
halfWidth       40;
cellSize        5;
profileSmoothing 20;
release
{
    r1 { polygon (($(X 5) 5070) ($(X 15) 5070) ($(X 15) 5090) ($(X 5) 5090)); thickness 1; thicknessDirection normal; }
}
EOF
    [ "${1:-}" = noEntrainment ] || cat >> "$ac/system/terrainDict" <<EOF
entrainment
{
    e1 { polygon (($(X 20) 5060) ($(X 60) 5060) ($(X 60) 5100) ($(X 20) 5100)); thickness ${2:-0.5}; thicknessDirection normal; }
}
EOF
    cat >> "$ac/system/terrainDict" <<EOF
resistance
{
    f1 { polygon (($(X 80) 5040) ($(X 120) 5040) ($(X 120) 5080) ($(X 80) 5080)); cResistance 0.01; }
}
EOF
}
axisDict
if (cd "$ac" && runApplication terrainToCase > /dev/null)
then
    check "terrainToCase axis mode, hEntrainable and cResistance of squares" '
case = "'"$ac"'"
bm = open(case + "/system/blockMeshDict").read()
nx, ny = int(entry(bm, "nx")), int(entry(bm, "ny"))
v, r = field(case, "0", "hEntrainable"), field(case, "0", "cResistance")
ent = [c for c in range(nx*ny) if 4 <= c % nx <= 11 and 4 <= c // nx <= 11]
res = [c for c in range(nx*ny) if 16 <= c % nx <= 23 and c // nx <= 7]
e = max(abs(v[c] - (0.5 if c in ent else 0)) for c in range(nx*ny))
er = max(abs(r[c] - (0.01 if c in res else 0)) for c in range(nx*ny))
vol = sum(v)*25
log = open(case + "/log.terrainToCase").read()
logged = float(re.search(r"^Erodible volume \(hEntrainable\) (\S+) m\^3", log, re.M).group(1))
want = {"upslope": "zeroGradient", "downslope": "zeroGradient", "sides": "zeroGradient", "frontAndBack": "empty"}
p = [patches(case, "0", f) for f in ("hEntrainable", "cResistance")]
ok = ny == 16 and nx >= 30 and e < 1e-9 and er < 1e-9 and close(vol, 800) and close(logged, 800, 1e-6) \
    and p == [want, want]
msg = "%d x %d cells; max |hEntrainable - 0.5 [64 cells]| %.3g m, max |cResistance - 0.01 [64 cells]| %.3g; volume %.12g m^3 (800), the log %s; patches %s" % (nx, ny, e, er, vol, logged, p[0])'

    # Without the entrainment entry: 0/hEntrainable left, with a warning;
    # with it (thickness 0.7): rewritten
    before="$(md5sum < "$ac/0/hEntrainable")"
    axisDict noEntrainment
    if (cd "$ac" && runApplication terrainToCase > /dev/null) \
        && [ "$(md5sum < "$ac/0/hEntrainable")" = "$before" ] \
        && grep -q "hEntrainable\" is left as it is: terrainDict has no entrainment entry" "$ac/log.terrainToCase"
    then
        pass "terrainToCase without entrainment: the existing 0/hEntrainable left byte for byte, the log warns: $(grep -o 'is left as it is.*' "$ac/log.terrainToCase" | head -n 1)"
    else
        fail "terrainToCase without entrainment: 0/hEntrainable changed or no warning (see $ac/log.terrainToCase)"
    fi
    axisDict withEntrainment 0.7
    if (cd "$ac" && runApplication terrainToCase > /dev/null)
    then
        check "terrainToCase with entrainment again: 0/hEntrainable rewritten" '
v = field("'"$ac"'", "0", "hEntrainable")
n = sum(1 for x in v if abs(x - 0.7) < 1e-9)
ok = n == 64 and sum(1 for x in v if abs(x) > 1e-9) == 64
msg = "%d cells of 0.7" % n'
    else
        fail "terrainToCase with entrainment 0.7 failed (see $ac/log.terrainToCase)"
    fi
    axisDict
    (cd "$ac" && runApplication terrainToCase > /dev/null) \
        || fail "terrainToCase, the axis case again (see $ac/log.terrainToCase)"
else
    fail "terrainToCase, axis mode with entrainment and resistance failed (see $ac/log.terrainToCase)"
fi

# -- 4. terrainToCase refusals ----------------------------------------------------
#- badDict <name> <sed script on the plan case's terrainDict | -> <regex>...:
#  a fresh plan case with planAreas' entries, edited, refused with nothing
#  written (no 0/), naming terrainDict
badDict()
{
    local name="$1" edit="$2" c="$work/bad-${1// /-}"
    shift 2
    planSlopeCase "$c" 0 0 0
    planAreas "$c"
    [ "$edit" = - ] || sed -i "$edit" "$c/system/terrainDict"
    refusal "$c" "terrainToCase, $name" terrainToCase "terrainDict" "$@"
    [ ! -e "$c/0" ] || fail "terrainToCase, $name: 0/ made"
}
badDict "entrainment thickness -0.5" 's/thickness   0.5;/thickness   -0.5;/' \
    "keyword 'thickness' = -0.5: must be finite and > 0" "terrainDict.entrainment.e1"
badDict "entrainment thickness 0" 's/thickness   0.5;/thickness   0;/' \
    "keyword 'thickness' = 0: must be finite and > 0"
badDict "cResistance -0.02" 's/cResistance 0.02;/cResistance -0.02;/' \
    "keyword 'cResistance' = -0.02: must be finite and > 0" "terrainDict.resistance.f1"
badDict "cResistance 1e31" 's/cResistance 0.02;/cResistance 1e31;/' \
    "keyword 'cResistance' = 1e+31: must be finite"
badDict "entrainment polygon outside the grid" 's/(72 0) (72 32)/(272 0) (72 32)/' \
    "keyword 'polygon' of entrainment e1: the entrainment outline passes (X = 272, Y = 0)" "outside the plan grid"
badDict "resistance with thicknessDirection" 's/cResistance 0.02;/cResistance 0.02; thicknessDirection normal;/' \
    "Unknown keyword 'thicknessDirection' in resistance f1"
badDict "entrainment with cResistance" 's/thickness   0.5;/cResistance 0.5;/' \
    "Unknown keyword 'cResistance' in entrainment e1"
badDict "entrainment without thicknessDirection" '/^entrainment$/,/^}$/ {/thicknessDirection/d}' \
    "thicknessDirection" "terrainDict.entrainment.e1"
badDict "entrainment not a dictionary" '/^entrainment$/,/^}$/d; 1a entrainment 0.5;' \
    "keyword 'entrainment': a dictionary of one or more entrainment entries"
badDict "resistance empty" '/^    f[12] {/d' \
    "keyword 'resistance': a dictionary of one or more resistance entries"
badDict "resistance entry not a dictionary" 's/f2 { raster "constant\/forest.asc"; }/f2 0.03;/' \
    "keyword 'resistance': entry 'f2' is not a dictionary"
badDict "resistance raster with a thickness" 's/f2 { raster "constant\/forest.asc"; }/f2 { raster "constant\/forest.asc"; cResistance 0.03; }/' \
    "keyword 'cResistance' of resistance f2: a raster gives the cResistance itself"
c="$work/bad-negative-raster"
planSlopeCase "$c" 0 0 0
planAreas "$c" -0.03
refusal "$c" "terrainToCase, a resistance raster of -0.03" terrainToCase "terrainDict" \
    "keyword 'raster' of resistance f2: .*forest.asc\" holds the cResistance -0.03 at pixel" "must be finite and >= 0"
c="$work/bad-zero-raster"
planSlopeCase "$c" 0 0 0
planAreas "$c" 0
refusal "$c" "terrainToCase, a resistance raster of zeros" terrainToCase "terrainDict" \
    "keyword 'raster' of resistance f2: .*forest.asc\" holds no cResistance > 0"
c="$work/bad-entrainment-raster"
planSlopeCase "$c" 0 0 0
planAreas "$c"
sed -i 's/polygon     ((40 0) (72 0) (72 32) (40 32));/raster "constant\/forest.asc";/' "$c/system/terrainDict"
refusal "$c" "terrainToCase, an entrainment raster with a thickness" terrainToCase "terrainDict" \
    "keyword 'thickness' of entrainment e1: a raster gives the thickness itself"

# -- 5. hazardMaps ----------------------------------------------------------------
# The plan case of section 2 with times written here: t = 1, the release's
# cells with X > 36 emptied (gone from the domain), erodedDepth e1 = (0.2 +
# 0.1 (c mod 7)) of the layer, that added to h; t = 2 the whole layer taken
# up (erodedDepth = 0/hEntrainable, hEntrainable 0) and added to h0,
# nothing gone; t = 3 h0 alone, without erodedDepth and hEntrainable
if [ -f "$pc/0/hEntrainable" ] && (cd "$pc" && runApplication blockMesh > /dev/null) \
    && (cd "$work" && $python - "$pc" <<'PYEOF'
import sys
from areas import *
case = sys.argv[1]
g = plan(case)
h0, l0 = field(case, "0", "h"), field(case, "0", "hEntrainable")
n = len(h0)
e1 = [l0[c]*(0.2 + 0.1*(c % 7)) for c in range(n)]
h1 = [(0 if g.XY(c)[0] > 36 else h0[c]) + e1[c] for c in range(n)]
h2 = [h0[c] + l0[c] for c in range(n)]
for t, h, e, left in [("1", h1, e1, [l0[c] - e1[c] for c in range(n)]),
                      ("2", h2, l0, [0.0]*n), ("3", h0, None, None)]:
    write(case, t, "h", h)
    hMax = [max(a, b, c) for a, b, c in zip(h0, h1, h2)]
    write(case, t, "hMax", hMax)
    write(case, t, "UMax", [1.0 if v > 0 else 0.0 for v in hMax])
    if e is not None:
        write(case, t, "erodedDepth", e)
        write(case, t, "hEntrainable", left)
PYEOF
) && (cd "$pc" && runApplication hazardMaps -time '1:3' > /dev/null)
then
    check "hazardMaps plan mode, t = 1: entrainedVolume and the balance" '
g = plan("'"$pc"'")
r, raw = report(g.case, 1)
e1 = field(g.case, "1", "erodedDepth")
h0, h1 = field(g.case, "0", "h"), field(g.case, "1", "h")
ent, rel, dep = g.volume(e1), g.volume(h0), g.volume(h1)
gone = g.volume([h0[c] if g.XY(c)[0] > 36 else 0 for c in range(len(h0))])
bal = r["releasedVolume"] + r["entrainedVolume"] - r["depositVolume"] - r["outflowVolume"]
ok = close(r["entrainedVolume"], ent) and close(r["releasedVolume"], rel) \
    and close(r["depositVolume"], dep) and close(r["outflowVolume"], gone) and gone > 0 and ent > 0 \
    and abs(bal) <= 1e-9*(r["releasedVolume"] + r["entrainedVolume"])
msg = "entrainedVolume %s m^3 (sum J e A %.10g), outflowVolume %s (the emptied cells %.10g); released + entrained - deposit - outflow = %.3g m^3" % (raw["entrainedVolume"], ent, raw["outflowVolume"], gone, bal)'
    check "hazardMaps plan mode, t = 2: the whole layer taken up, nothing gone" '
r, raw = report("'"$pc"'", 2)
ok = close(r["entrainedVolume"], 512) and raw["outflowVolume"] == "0" \
    and close(r["depositVolume"], r["releasedVolume"] + 512)
msg = "entrainedVolume %s m^3 (0.5 x 1024 = 512), outflowVolume %s, depositVolume %s = releasedVolume %s + 512" % (raw["entrainedVolume"], raw["outflowVolume"], raw["depositVolume"], raw["releasedVolume"])'
    check "hazardMaps plan mode, the erodedDepth and hEntrainable rasters" '
g = plan("'"$pc"'")
out = g.case + "/postProcessing/hazardMaps/1/"
e1, l1 = field(g.case, "1", "erodedDepth"), field(g.case, "1", "hEntrainable")
E, nd = asc(out + "erodedDepth.asc")
L, ndL = asc(out + "hEntrainable.asc")
px = lambda R, c: R[g.ny - 1 - c // g.nx][c % g.nx]
eE = max(abs(px(E, c) - e1[c]) for c in range(len(e1)) if e1[c] > 0)
nodata = all(px(E, c) == nd for c in range(len(e1)) if e1[c] == 0)
eL = max(abs(px(L, c) - l1[c]) for c in range(len(l1)))
files = all(os.path.isfile(out + f) for f in ("erodedDepth.tif", "hEntrainable.tif"))
ok = len(E) == g.ny and len(E[0]) == g.nx and eE < 1e-9 and nodata and eL < 1e-9 and files \
    and sum(1 for x in e1 if x > 0) == 64
msg = "erodedDepth.asc %d x %d: max |pixel - cell| %.3g over the 64 eroded cells, nodata elsewhere %s; hEntrainable.asc every pixel its cell (%.3g); .tif written %s" % (len(E[0]), len(E), eE, nodata, eL, files)'
    tifOk=true
    for m in erodedDepth hEntrainable
    do
        gdal_translate -q -of AAIGrid "$pc/postProcessing/hazardMaps/1/$m.tif" "$work/$m.fromTif.asc" \
            > /dev/null 2>&1 || tifOk=false
    done
    if $tifOk
    then
        check "hazardMaps plan mode, the .tif maps hold the .asc values" '
out = "'"$pc"'/postProcessing/hazardMaps/1/"
d = 0
for m in ("erodedDepth", "hEntrainable"):
    A, _ = asc(out + m + ".asc")
    T, _ = asc("'"$work"'/" + m + ".fromTif.asc")
    d = max(d, max(abs(a - b) for ra, rb in zip(A, T) for a, b in zip(ra, rb)))
    ok = len(A) == len(T) and all(len(a) == len(b) for a, b in zip(A, T))
ok = ok and d < 1e-9
msg = "gdal_translate of erodedDepth.tif and hEntrainable.tif: max |tif - asc| %.3g" % d'
    else
        fail "hazardMaps plan mode: gdal_translate could not read erodedDepth.tif or hEntrainable.tif"
    fi
    out3="$pc/postProcessing/hazardMaps/3"
    if grep -q "^entrainedVolume 0$" "$out3/report.dat" \
        && grep -q "No field erodedDepth at time 3 (the run has an erodible layer, hEntrainable): entrainedVolume 0" "$pc/log.hazardMaps" \
        && [ ! -e "$out3/erodedDepth.asc" ] && [ ! -e "$out3/hEntrainable.tif" ] \
        && [ -e "$out3/hMax.asc" ]
    then
        pass "hazardMaps plan mode, t = 3 without erodedDepth: entrainedVolume 0, the log says why, no erodedDepth or hEntrainable map"
    else
        fail "hazardMaps plan mode, t = 3 without erodedDepth: $(grep entrainedVolume "$out3/report.dat"); $(ls "$out3")"
    fi
else
    fail "hazardMaps plan mode: writing the times or hazardMaps failed (see $pc/log.*)"
fi

# The axis case of section 3: t = 1 the release kept, erodedDepth 0.1 in
# the 64 cells of the layer, added to h: entrainedVolume 64 x 0.1 x 25 =
# 160 m^3, nothing gone.  Then the same case without a layer (no
# 0/hEntrainable, no erodedDepth): report.dat without entrainedVolume
if [ -f "$ac/0/hEntrainable" ] && (cd "$ac" && runApplication blockMesh > /dev/null) \
    && (cd "$work" && $python - "$ac" <<'PYEOF'
import sys
from areas import *
case = sys.argv[1]
h0, l0 = field(case, "0", "h"), field(case, "0", "hEntrainable")
e = [0.1 if v > 0.25 else 0.0 for v in l0]
write(case, "1", "h", [a + b for a, b in zip(h0, e)])
write(case, "1", "hMax", [a + b for a, b in zip(h0, e)])
write(case, "1", "UMax", [1.0]*len(h0))
write(case, "1", "erodedDepth", e)
write(case, "1", "hEntrainable", [a - b for a, b in zip(l0, e)])
PYEOF
) && (cd "$ac" && runApplication hazardMaps > /dev/null)
then
    check "hazardMaps axis mode: entrainedVolume, the balance, the erodedDepth raster" '
case = "'"$ac"'"
r, raw = report(case, 1)
E, nd = asc(case + "/postProcessing/hazardMaps/1/erodedDepth.asc")
vals = [v for row in E for v in row if v != nd]
# the eroded area in plan: 40 cos35 x 40 m, of 2 m pixels
want = 40*c35*40/4
ok = close(r["entrainedVolume"], 160) and raw["outflowVolume"] == "0" \
    and close(r["depositVolume"], r["releasedVolume"] + 160) \
    and all(abs(v - 0.1) < 1e-12 for v in vals) and abs(len(vals) - want) < 0.15*want \
    and os.path.isfile(case + "/postProcessing/hazardMaps/1/erodedDepth.tif")
msg = "entrainedVolume %s m^3 (160), outflowVolume %s, depositVolume %s (released %s + 160); erodedDepth.asc %d pixels of 0.1 (the area: %.0f)" % (raw["entrainedVolume"], raw["outflowVolume"], raw["depositVolume"], raw["releasedVolume"], len(vals), want)'
    rm -f "$ac/0/hEntrainable" "$ac/1/erodedDepth" "$ac/1/hEntrainable"
    rm -rf "$ac/postProcessing"
    if (cd "$ac" && runApplication hazardMaps > /dev/null) \
        && ! grep -q "entrainedVolume" "$ac/postProcessing/hazardMaps/1/report.dat" \
        && grep -q "^outflowVolume" "$ac/postProcessing/hazardMaps/1/report.dat" \
        && [ ! -e "$ac/postProcessing/hazardMaps/1/erodedDepth.asc" ] \
        && [ ! -e "$ac/postProcessing/hazardMaps/1/hEntrainable.asc" ]
    then
        pass "hazardMaps without an erodible layer: no entrainedVolume line, no erodedDepth or hEntrainable map"
    else
        fail "hazardMaps without an erodible layer: $(grep -c entrainedVolume "$ac/postProcessing/hazardMaps/1/report.dat" 2>/dev/null) entrainedVolume lines (see $ac/log.hazardMaps)"
    fi
else
    fail "hazardMaps axis mode: writing the time or hazardMaps failed (see $ac/log.*)"
fi
echo "($((SECONDS - start)) s)"

finish

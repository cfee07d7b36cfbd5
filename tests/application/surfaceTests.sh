#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Tests of avalancheSurface (the bed and the flow surface at their
#     world positions as .vtp files with a .series):
#       - a terrain case from a DEM that is exactly a plane, 35 deg down X
#         and 10 deg up Y (so zb is not zero), through terrainToCase and a
#         short run: every bed point lies on the DEM's plane (1e-9 m); the
#         flow surface is the bed + h along the reference surface's normal
#         (|top - bed| = h, direction the normal to 1e-9); the world
#         velocity is tangent to the reference surface;
#       - the analytic inclined plane of section 5.3 (tutorials/inclinedPlane
#         on 60 x 28 cells, to t = 0.5): the bed on the 35 deg part at
#         X = x cos 35, Z = -x sin 35 (1e-9), the chord slope of the bed
#         between neighbouring points zeta at their midpoint for eq. (35)'s
#         pieces (35, linear, 0 deg; 1e-9 deg), the points continuous (the
#         chord between neighbours the cell size within 1e-3 of it, nothing
#         jumps), Y = y;
#       - both cases: surface.vtp.series and bed.vtp.series list every time
#         directory, each .vtp parses (python3 xml.etree, base64 arrays
#         decoded; also by VTK's own reader when python3-vtk9 is there)
#         with nx ny points, (nx-1)(ny-1) quads, every array the
#         right length and finite; -latestTime writes that time alone;
#       - bad input (no time directory, h missing at a time, no inclination
#         and no terrainMapping): non-zero exit, FOAM FATAL (IO) ERROR naming
#         the file or keyword, nothing written.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     surfaceTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
python=/usr/bin/python3

#- Run the python checks of stdin on a case; count its PASS/FAIL lines
pyChecks()
{
    local out
    out="$($python - "$@" 2>&1)"
    tally $? "$out" "python checks on $1"
}

# Reading the .vtp files: shared by the checks below
cat > "$work/vtp.py" <<'PYEOF'
import base64, json, math, os, re, struct, sys
import xml.etree.ElementTree as ET
try:
    import vtk   # Debian's python3-vtk9, when installed
except ImportError:
    vtk = None
TYPES = {"Float32": "f", "Float64": "d", "Int64": "q", "Int32": "i", "UInt32": "I"}
ok = True
def say(good, msg):
    global ok
    ok = ok and good
    print(("PASS  " if good else "FAIL  ") + msg)
def array(e):
    raw = base64.b64decode("".join(e.text.split()))
    n = struct.unpack("<I", raw[:4])[0]
    t = TYPES[e.get("type")]
    vals = struct.unpack("<%d%s" % (n//struct.calcsize(t), t), raw[4:4 + n])
    k = int(e.get("NumberOfComponents", "1"))
    return [vals[i:i + k] for i in range(0, len(vals), k)] if k > 1 else list(vals)
def read(path):
    """points, quads, point data of a .vtp"""
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    pts = array(piece.find("Points/DataArray"))
    polys = {a.get("Name"): array(a) for a in piece.findall("Polys/DataArray")}
    data = {a.get("Name"): array(a) for a in piece.findall("PointData/DataArray")}
    return piece, pts, polys, data
def times(case):
    return sorted((d for d in os.listdir(case)
                   if re.fullmatch(r"[0-9.e+-]+", d) and os.path.isdir(f"{case}/{d}")),
                  key=float)
def checkFiles(case, nx, ny):
    """series and .vtp structure; returns {time: (bed, surface)}"""
    out = f"{case}/postProcessing/avalancheSurface"
    ts = times(case)
    res = {}
    for base in ["surface", "bed"]:
        s = json.load(open(f"{out}/{base}.vtp.series"))
        names = [f["name"] for f in s["files"]]
        st = [f["time"] for f in s["files"]]
        good = s["file-series-version"] == "1.0" \
            and names == [f"{base}_{t}.vtp" for t in ts] \
            and all(abs(a - float(b)) < 1e-12 for a, b in zip(st, ts))
        say(good, f"{base}.vtp.series lists every time directory {ts}: {names}")
        bad = []
        for t in ts:
            piece, pts, polys, data = read(f"{out}/{base}_{t}.vtp")
            n, m = nx*ny, (nx - 1)*(ny - 1)
            if int(piece.get("NumberOfPoints")) != n or len(pts) != n \
                or int(piece.get("NumberOfPolys")) != m \
                or len(polys["offsets"]) != m or len(polys["connectivity"]) != 4*m \
                or polys["offsets"][-1] != 4*m or max(polys["connectivity"]) != n - 1:
                bad.append(f"{t}: {piece.get('NumberOfPoints')} points, "
                           f"{piece.get('NumberOfPolys')} polys")
            for k, v in data.items():
                flat = [c for x in v for c in (x if isinstance(x, tuple) else (x,))]
                if len(v) != n or not all(map(math.isfinite, flat)):
                    bad.append(f"{t}: array {k} of {len(v)} values or not finite")
            if not all(math.isfinite(c) for p in pts for c in p):
                bad.append(f"{t}: points not finite")
            res.setdefault(t, {})[base] = (pts, data)
            if vtk:
                r = vtk.vtkXMLPolyDataReader()
                r.SetFileName(f"{out}/{base}_{t}.vtp")
                r.Update()
                pd = r.GetOutput()
                if r.GetErrorCode() or pd.GetNumberOfPoints() != len(pts) \
                    or pd.GetNumberOfPolys() != (nx - 1)*(ny - 1) \
                    or pd.GetPoints().GetPoint(len(pts) - 1) != tuple(pts[-1]) \
                    or pd.GetPointData().GetArray("h").GetNumberOfTuples() != len(pts):
                    bad.append(f"{t}: VTK's reader reads {pd.GetNumberOfPoints()} points, "
                               f"{pd.GetNumberOfPolys()} polys")
        say(not bad, f"{base}_<time>.vtp parse" + (" (and VTK's vtkXMLPolyDataReader reads them)" if vtk else " (as XML only: VTK's reader, python3-vtk9, is not installed here)")
            + f", {nx*ny} points, {(nx-1)*(ny-1)} quads, "
            f"arrays {sorted(data)} of that length and finite, at {len(ts)} times"
            + (": " + "; ".join(bad[:3]) if bad else ""))
    return res
PYEOF

#- The case's files and their checksums (to see that nothing was written)
snapshot()
{
    (cd "$1" && find . -type f ! -name 'log.*' -print0 | sort -z \
        | xargs -0 md5sum)
}

#- expectRefusal <what> <case> <pattern of the error> <pattern 2>
expectRefusal()
{
    local what="$1" c="$2"
    local before after
    before="$(snapshot "$c")"
    (cd "$c" && avalancheSurface > log.avalancheSurface 2>&1)
    local rc=$?
    after="$(snapshot "$c")"
    local log="$c/log.avalancheSurface"
    local problems=""
    [ $rc -ne 0 ] || problems="$problems exit 0;"
    grep -q "FOAM FATAL" "$log" || problems="$problems no FOAM FATAL error;"
    grep -q -- "$3" "$log" || problems="$problems '$3' not named;"
    grep -q -- "$4" "$log" || problems="$problems '$4' not named;"
    grep -q "stack\|Segmentation" "$log" && problems="$problems stack trace;"
    [ "$before" = "$after" ] || problems="$problems files written;"
    [ -e "$c/postProcessing/avalancheSurface" ] && problems="$problems postProcessing/avalancheSurface made;"
    if [ -z "$problems" ]
    then
        pass "refused, $what: $(grep -m1 -A1 'FOAM FATAL' "$log" | tail -n1 | cut -c1-150)"
    else
        fail "$what:$problems (see $log)"
    fi
}

# -- 1. A terrain case: a plane DEM, 35 deg down X and 10 deg up Y -------------
t="$work/terrain"
mkdir -p "$t/system" "$t/constant"
cp "$project"/tutorials/inclinedPlane/system/{controlDict,fvSolution,fvSchemes} "$t/system/"
cp "$project"/tutorials/inclinedPlane/constant/transportProperties "$t/constant/"
$python - "$t/constant" <<'PYEOF'
import math, sys
a = math.tan(math.radians(35)); b = math.tan(math.radians(10))
nx, ny, d, x0, y0 = 120, 80, 2.0, 1000.0, 5000.0
with open(f"{sys.argv[1]}/dem.asc", "w") as o:
    o.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\n"
            f"cellsize {d}\nNODATA_value -9999\n")
    for j in range(ny):
        Y = y0 + (ny - j - 0.5)*d
        o.write(" ".join("%.17g" % (2000 - a*(X - x0) + b*(Y - 5080))
                         for X in (x0 + (i + 0.5)*d for i in range(nx))) + "\n")
PYEOF
[ $? -eq 0 ] || fail "terrain case: writing its DEM dem.asc"
cat > "$t/system/terrainDict" <<'EOD'
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "constant/dem.asc";
axis            ((1010 5080) (1200 5080));
halfWidth       40;
cellSize        5;
profileSmoothing 20;
release
{
    r1
    {
        polygon     ((1040 5070) (1070 5070) (1070 5090) (1040 5090));
        thickness   2;
        thicknessDirection normal;
    }
}
EOD
if (
    cd "$t" && setEntry constant/transportProperties g 9.81 \
        && setEntry system/controlDict endTime 1 \
        && setEntry system/controlDict writeInterval 0.5 \
        && setEntry system/controlDict writeFormat ascii \
        && setEntry system/controlDict writePrecision 17 \
        && runApplication terrainToCase && runApplication blockMesh \
        && runApplication savageHutterFoam && runApplication avalancheSurface
)
then
    pyChecks "$t" <<'PYEOF'
import math, sys
case = sys.argv[1]
exec(open(case + "/../vtp.py").read())
mp = open(case + "/constant/terrainMapping").read()
nx, ny = (int(re.search(r"^%s\s+(\d+);" % k, mp, re.M).group(1)) for k in ("nx", "ny"))
res = checkFiles(case, nx, ny)
a = math.tan(math.radians(35)); b = math.tan(math.radians(10))
plane = lambda X, Y: 2000 - a*(X - 1000) + b*(Y - 5080)
N = (math.sin(math.radians(35)), 0.0, math.cos(math.radians(35)))
eBed = eDist = eDir = eU = 0.0
nFlow = 0
zbMax = 0.0
for t, r in res.items():
    bed, dBed = r["bed"]
    top, dTop = r["surface"]
    h = dTop["h"]
    zbMax = max(zbMax, max(map(abs, dTop["zb"])))
    for k in range(len(bed)):
        eBed = max(eBed, abs(bed[k][2] - plane(bed[k][0], bed[k][1])))
        d = [top[k][i] - bed[k][i] for i in range(3)]
        dist = math.sqrt(sum(c*c for c in d))
        eDist = max(eDist, abs(dist - h[k])/max(1.0, h[k]))
        if h[k] > 1e-3:
            nFlow += 1
            eDir = max(eDir, 1 - sum(d[i]*N[i] for i in range(3))/dist)
        U = dTop["U"][k]
        eU = max(eU, abs(sum(U[i]*N[i] for i in range(3)))/max(1.0, dTop["magU"][k]))
say(eBed < 1e-9 and zbMax > 1,
    f"terrain: bed points on the DEM plane, max |Z - Z_DEM(X, Y)| = {eBed:.3g} m (zb up to {zbMax:.3g} m)")
say(eDist < 1e-6 and eDir < 1e-9 and nFlow > 0,
    f"terrain: flow surface = bed + h along the normal: max | |top - bed| - h | = {eDist:.3g} "
    f"(h as Float32), direction 1 - cos = {eDir:.3g} at {nFlow} points with h > 1e-3")
say(eU < 1e-6, f"terrain: world U tangent to the reference surface, max |U.N|/|U| = {eU:.3g}")
sys.exit(0 if ok else 1)
PYEOF
else
    fail "terrain case: terrainToCase, blockMesh, savageHutterFoam or avalancheSurface failed (see $t/log.*)"
fi

# -- 2. The analytic inclined plane of section 5.3 -----------------------------
p="$work/inclinedPlane"
mkdir -p "$p"
cp -r "$project"/tutorials/inclinedPlane/{0.orig,constant,system} "$p/"
rm -rf "$p/constant/polyMesh"
if (
    cd "$p" && setBlockCells 60 28 \
        && setEntry system/controlDict endTime 0.5 \
        && setEntry system/controlDict writeInterval 0.25 \
        && runApplication blockMesh && restore0Dir \
        && runApplication postProcess -func writeCellCentres -time 0 \
        && runApplication setAvalancheFields \
        && runApplication savageHutterFoam && runApplication avalancheSurface
)
then
    pyChecks "$p" <<'PYEOF'
import math, sys
case = sys.argv[1]
exec(open(case + "/../vtp.py").read())
res = checkFiles(case, 60, 28)
nx, ny, dx = 60, 28, 0.5
def zeta(x):   # eq. (35) [deg]
    return 35.0 if x <= 17.5 else (35*(21.5 - x)/4 if x < 21.5 else 0.0)
bed, data = res["0"]["bed"]
x = [(i + 0.5)*dx for i in range(nx)]
rows = [bed[j*nx:(j + 1)*nx] for j in range(ny)]
ePlane = max(abs(r[i][0] - x[i]*math.cos(math.radians(35))) + abs(r[i][2] + x[i]*math.sin(math.radians(35)))
             for r in rows for i in range(nx) if x[i] <= 17.5)
say(ePlane < 1e-9, f"inclined plane: bed on the 35 deg part at X = x cos35, Z = -x sin35, max error {ePlane:.3g}")
eSlope, checked, samples = 0.0, 0, []
for r in rows:
    for i in range(nx - 1):
        a, b = x[i], x[i + 1]
        if (a < 17.5 < b) or (a < 21.5 < b):
            continue   # a chord across a kink of eq. (35)
        s = math.degrees(math.atan2(-(r[i + 1][2] - r[i][2]), r[i + 1][0] - r[i][0]))
        eSlope = max(eSlope, abs(s - zeta(0.5*(a + b))))
        checked += 1
        if r is rows[0] and i in (10, 36, 38, 40, 50):
            samples.append(f"x={0.5*(a + b):g}: {s:.6f} deg (eq. 35: {zeta(0.5*(a + b)):g})")
say(eSlope < 1e-9 and checked > 0,
    f"inclined plane: bed chord slope = zeta(x) of eq. (35) at {checked} chords, max error {eSlope:.3g} deg; " + ", ".join(samples))
eChord, eY, eJump = 0.0, 0.0, 0.0
for j, r in enumerate(rows):
    for i in range(nx - 1):
        c = math.dist(r[i], r[i + 1])
        eChord = max(eChord, abs(c - dx)/dx)
    for i in range(nx):
        eY = max(eY, abs(r[i][1] - (-7 + (j + 0.5)*14/ny)))
say(eChord < 1e-3 and eY < 1e-12,
    f"inclined plane: bed continuous, chords between neighbours = cell size within {eChord:.3g} (relative), |Y - y| <= {eY:.3g}")
curved = rows[0][-1][2] - rows[0][-2][2]
say(abs(curved) < 1e-12 and rows[0][0][2] - rows[0][1][2] > 0.28,
    f"inclined plane: bed flat at the end (dZ {curved:.3g}), 35 deg at the top (drop {rows[0][0][2] - rows[0][1][2]:.4g} over dx = 0.5)")
sys.exit(0 if ok else 1)
PYEOF
else
    fail "inclined plane: blockMesh, setAvalancheFields, savageHutterFoam or avalancheSurface failed (see $p/log.*)"
fi

# -- 3. -latestTime ---------------------------------------------------------------
c="$work/latest"
rm -rf "$c"
cp -r "$p" "$c"
rm -rf "$c/postProcessing"
if (cd "$c" && avalancheSurface -latestTime > log.avalancheSurface 2>&1)
then
    got="$(cd "$c/postProcessing/avalancheSurface" && ls | tr '\n' ' ')"
    if [ "$got" = "bed.vtp.series bed_0.5.vtp surface.vtp.series surface_0.5.vtp " ]
    then
        pass "-latestTime: writes time 0.5 alone: $got"
    else
        fail "-latestTime: wrote $got"
    fi
else
    fail "-latestTime: avalancheSurface failed (see $c/log.avalancheSurface)"
fi

# -- 4. Bad input ---------------------------------------------------------------------
bad()
{
    local c="$work/bad-$1"
    rm -rf "$c"
    cp -r "$p" "$c"
    rm -rf "$c/postProcessing"
    echo "$c"
}
c="$(bad noTimes)"
rm -rf "$c"/0 "$c"/0.25 "$c"/0.5
expectRefusal "no time directory" "$c" "No time directory" "$c"
c="$(bad noH)"
rm -f "$c/0.25/h"
expectRefusal "h missing at time 0.25" "$c" "No field h" "0.25"
c="$(bad noInclination)"
sed -i 's/^inclination .*//' "$c/constant/transportProperties"
expectRefusal "no inclination, no terrainMapping" "$c" "transportProperties" "'inclination'"

finish

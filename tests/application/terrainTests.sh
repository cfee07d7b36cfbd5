#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Tests of terrainToCase and hazardMaps (issue 14) on synthetic DEMs
#     (240 x 160 m, 2 m pixels, written here as .asc and, through
#     gdal_translate, .tif):
#       - a DEM that is exactly a 35 deg plane: zeta = 35 deg at every point
#         of the inclination table and zb = 0, both to round-off (1e-9);
#       - the plane tilted sideways by 10 deg: zb = y tan(10) cos(35) (1e-9);
#       - the DEM as .asc and as .tif give identical files;
#       - release polygons (a rotated quadrilateral, a triangle): volume
#         within one cell area x thickness of the analytic one, thickness
#         normal (h A / cos 35) and vertical (d A); the same polygon as a
#         shapefile gives the same volume;
#       - hazardMaps after a short run: its .asc and .tif rasters read back
#         by GDAL (gdalinfo) with the DEM's size, geotransform and nodata,
#         the hMax raster's maximum that of the field; report.dat with
#         every key and finite values, releasedVolume that of terrainToCase;
#       - bad input (no DEM, unknown raster format, axis leaving the DEM,
#         axis of zero length, mesh wider than the DEM, a nodata hole under
#         the mesh, a release outside the mesh, unknown keywords and
#         choices): non-zero exit, FOAM FATAL IO ERROR naming terrainDict and
#         the keyword, and no file written or changed.
#     Prints one line per check and "N passed, M failed".
#
# Usage
#     terrainTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
set -u
project="$1"
work="$2"
. "$project/bin/tools/RunFunctions"
python=/usr/bin/python3

passed=0
failed=0
pass() { echo "PASS  $*"; passed=$((passed + 1)); }
fail() { echo "FAIL  $*"; failed=$((failed + 1)); }

rm -rf "$work"
mkdir -p "$work/base/system" "$work/base/constant" "$work/dem"
cp "$project"/tutorials/inclinedPlane/system/{controlDict,fvSolution,fvSchemes} \
    "$work/base/system/"
cp "$project"/tutorials/inclinedPlane/constant/transportProperties \
    "$work/base/constant/"
(
    cd "$work/base" || exit 1
    setEntry constant/transportProperties g 9.81
    setEntry system/controlDict endTime 1
    setEntry system/controlDict writeInterval 0.5
    setEntry system/controlDict writeFormat ascii
)

# DEMs: plane (35 deg down X), tilted (and 10 deg up Y), hole (nodata under
# the mesh), each .asc with full precision; .tif through gdal_translate
$python - "$work/dem" <<'PYEOF'
import math, sys
out = sys.argv[1]
a = math.tan(math.radians(35)); b = math.tan(math.radians(10))
nx, ny, d, x0, y0 = 120, 80, 2.0, 1000.0, 5000.0
def write(name, f):
    with open(f"{out}/{name}.asc", "w") as o:
        o.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\n"
                f"cellsize {d}\nNODATA_value -9999\n")
        for j in range(ny):
            Y = y0 + (ny - j - 0.5)*d
            o.write(" ".join("%.17g" % f(x0 + (i + 0.5)*d, Y)
                             for i in range(nx)) + "\n")
plane = lambda X, Y: 2000 - a*(X - x0)
write("plane", plane)
write("tilted", lambda X, Y: plane(X, Y) + b*(Y - 5080))
write("hole", lambda X, Y: -9999 if abs(X - 1100) < 6 and abs(Y - 5090) < 6
      else plane(X, Y))
PYEOF
gdal_translate -q --config AAIGRID_DATATYPE Float64 -ot Float64 "$work/dem/plane.asc" "$work/dem/plane.tif" \
    || fail "gdal_translate plane.asc plane.tif"
cp "$work/dem"/*.asc "$work/dem"/*.tif "$work/base/constant/"

# terrainDict of the base case; release r1 a rotated quadrilateral (plan
# area 800 m^2; one vertex on an edge), r2 a triangle (600 m^2)
writeTerrainDict()
{
    cat > "$1/system/terrainDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "${2:-constant/plane.asc}";
axis            ((1010 5080) (1200 5080));
halfWidth       40;
cellSize        5;
profileSmoothing 20;
release
{
    r1
    {
        polygon     ((1040 5080) (1060 5060) (1080 5080) (1060 5100) (1050 5090));
        thickness   2;
        thicknessDirection ${3:-normal};
    }
    r2
    {
        polygon     ((1100 5060) (1130 5060) (1115 5100));
        thickness   1;
        thicknessDirection ${4:-vertical};
    }
}
EOD
}
writeTerrainDict "$work/base"

newCase()
{
    rm -rf "$work/$1"
    cp -r "$work/base" "$work/$1"
    echo "$work/$1"
}

#- Python check on a case: check <case> <python expression over zeta, x,
#  zb, y, h (lists)> <message>
fieldCheck()
{
    $python - "$1" "$2" <<'PYEOF'
import math, re, sys
case, expr = sys.argv[1], sys.argv[2]
def field(name):
    t = open(f"{case}/0/{name}").read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", t)
    return [float(v) for v in m.group(2).split()]
tp = open(f"{case}/constant/transportProperties").read()
table = re.search(r"inclination\s+table\s*\((.*?)\n\);", tp, re.S).group(1)
pairs = [tuple(map(float, p)) for p in re.findall(r"\(\s*(\S+)\s+(\S+)\s*\)", table)]
x = [p[0] for p in pairs]; zeta = [p[1] for p in pairs]
bm = open(f"{case}/system/blockMeshDict").read()
nx = int(re.search(r"^nx\s+(\d+);", bm, re.M).group(1))
ny = int(re.search(r"^ny\s+(\d+);", bm, re.M).group(1))
zb = field("zb")
cs = 5.0
y = [-ny*cs/2 + (c//nx + 0.5)*cs for c in range(nx*ny)]
ok, msg = eval(expr)
print(msg)
sys.exit(0 if ok else 1)
PYEOF
}

#- The case's files and their checksums (to see that nothing was written)
snapshot()
{
    (cd "$1" && find . -type f ! -name 'log.*' -print0 | sort -z \
        | xargs -0 md5sum)
}

# -- 1. A plane: zeta constant, zb = 0 --------------------------------------
c="$(newCase plane)"
if (cd "$c" && runApplication terrainToCase)
then
    if msg="$(fieldCheck "$c" '(max(abs(z - 35) for z in zeta) < 1e-9 and max(map(abs, zb)) < 1e-9, "max |zeta - 35| = %.3g deg over %d table points, max |zb| = %.3g m over %d cells" % (max(abs(z - 35) for z in zeta), len(zeta), max(map(abs, zb)), len(zb)))')"
    then
        pass "plane DEM: $msg"
    else
        fail "plane DEM: $msg"
    fi
else
    fail "plane DEM: terrainToCase failed"
fi

# -- 2. Tilted sideways: zb = y tan(10) cos(35) -----------------------------
c="$(newCase tilted)"
sed -i 's#constant/plane.asc#constant/tilted.asc#' "$c/system/terrainDict"
if (cd "$c" && runApplication terrainToCase)
then
    if msg="$(fieldCheck "$c" '(lambda e: (e < 1e-9 and max(abs(z - 35) for z in zeta) < 1e-9, "max |zb - y tan10 cos35| = %.3g m (zb up to %.1f m), max |zeta - 35| = %.3g deg" % (e, max(map(abs, zb)), max(abs(z - 35) for z in zeta))))(max(abs(zb[k] - y[k]*math.tan(math.radians(10))*math.cos(math.radians(35))) for k in range(len(zb))))')"
    then
        pass "sideways-tilted plane: $msg"
    else
        fail "sideways-tilted plane: $msg"
    fi
else
    fail "sideways-tilted plane: terrainToCase failed"
fi

# -- 3. .asc and .tif give identical cases -----------------------------------
c="$(newCase tif)"
sed -i 's#constant/plane.asc#constant/plane.tif#' "$c/system/terrainDict"
if (cd "$c" && runApplication terrainToCase)
then
    differ=""
    for f in 0/zb 0/h 0/U system/blockMeshDict
    do
        cmp -s "$work/plane/$f" "$c/$f" || differ="$differ $f"
    done
    # The inclination table; the mapping but for the DEM's name
    diff -q <(sed -n '/^inclination/,/^);/p' "$work/plane/constant/transportProperties") \
            <(sed -n '/^inclination/,/^);/p' "$c/constant/transportProperties") \
            > /dev/null || differ="$differ inclination"
    diff -q <(grep -v '^dem' "$work/plane/constant/terrainMapping") \
            <(grep -v '^dem' "$c/constant/terrainMapping") \
            > /dev/null || differ="$differ terrainMapping"
    if [ -z "$differ" ]
    then
        pass ".asc and .tif DEM: identical 0/zb, 0/h, 0/U, blockMeshDict, inclination table, terrainMapping"
    else
        fail ".asc and .tif DEM differ in:$differ"
    fi
else
    fail ".tif DEM: terrainToCase failed"
fi

# -- 4. Release volumes --------------------------------------------------------
#- volumeCheck <case> <release> <analytic> <tolerance> <what>
volumeCheck()
{
    local v
    v="$(sed -n "s/^Release $2: .* volume \([^ ]*\) m^3/\1/p" "$1/log.terrainToCase")"
    if [ -n "$v" ] && $python -c "import sys; sys.exit(0 if abs($v - $3) <= $4 else 1)"
    then
        pass "release volume, $5: $v m^3, analytic $3 (tolerance $4, one cell area x thickness)"
    else
        fail "release volume, $5: '${v}' m^3, analytic $3 (tolerance $4)"
    fi
}
cos35="$($python -c 'import math; print(math.cos(math.radians(35)))')"
volumeCheck "$work/plane" r1 "2*800/$cos35" 50 "quadrilateral, thickness 2 m normal"
volumeCheck "$work/plane" r2 "1*600" 25 "triangle, thickness 1 m vertical"
c="$(newCase swapped)"
writeTerrainDict "$c" constant/plane.asc vertical normal
(cd "$c" && runApplication terrainToCase) || fail "swapped thickness directions: terrainToCase failed"
volumeCheck "$c" r1 "2*800" 50 "quadrilateral, thickness 2 m vertical"
volumeCheck "$c" r2 "1*600/$cos35" 25 "triangle, thickness 1 m normal"

# The quadrilateral as a shapefile (written through ogr2ogr from GeoJSON)
c="$(newCase shapefile)"
cat > "$c/constant/release.geojson" <<'EOD'
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[1040, 5080], [1060, 5060],
 [1080, 5080], [1060, 5100], [1050, 5090], [1040, 5080]]]}}]}
EOD
ogr2ogr -f "ESRI Shapefile" "$c/constant/release.shp" "$c/constant/release.geojson" \
    || fail "ogr2ogr release.shp"
sed -i 's#polygon     ((1040 5080) (1060 5060) (1080 5080) (1060 5100) (1050 5090));#file "constant/release.shp";#' \
    "$c/system/terrainDict"
if (cd "$c" && runApplication terrainToCase)
then
    if cmp -s "$work/plane/0/h" "$c/0/h"
    then
        pass "release from a shapefile: 0/h identical to that of the same polygon in terrainDict"
    else
        volumeCheck "$c" r1 "2*800/$cos35" 50 "shapefile (0/h differs from the dictionary polygon's)"
    fi
else
    fail "release from a shapefile: terrainToCase failed"
fi

# -- 5. hazardMaps ---------------------------------------------------------------
c="$work/plane"
sed -i 's/^rho .*//' "$c/constant/transportProperties"
sed -i 's/^phi /rho             1500;\nphi /' "$c/constant/transportProperties"
if (
    cd "$c" && runApplication blockMesh && runApplication savageHutterFoam \
        && runApplication hazardMaps -threshold 0.01
)
then
    checks="$($python - "$c" 2>&1 <<'PYEOF'
import json, math, re, subprocess, sys
case = sys.argv[1]
out = f"{case}/postProcessing/hazardMaps/1"
ok = True
def say(good, msg):
    global ok
    ok = ok and good
    print(("PASS  " if good else "FAIL  ") + msg)
dem = json.loads(subprocess.run(["gdalinfo", "-json", f"{case}/constant/plane.asc"],
                                capture_output=True, text=True).stdout)
log = open(f"{case}/log.hazardMaps").read()
for name in ["hMax", "UMax", "pMax", "deposit"]:
    for ext in [".asc", ".tif"]:
        r = subprocess.run(["gdalinfo", "-json", "-stats", f"{out}/{name}{ext}"],
                           capture_output=True, text=True)
        if r.returncode:
            say(False, f"hazardMaps {name}{ext}: gdalinfo failed: {r.stderr}")
            continue
        info = json.loads(r.stdout)
        band = info["bands"][0]
        gtOk = all(abs(a - b) < 1e-9 for a, b in zip(info["geoTransform"], dem["geoTransform"]))
        sizeOk = info["size"] == dem["size"]
        ndOk = band.get("noDataValue") == -9999
        hi = float(band["metadata"][""]["STATISTICS_MAXIMUM"])
        m = re.search(rf"Wrote {name} \(.asc, .tif\): range \[(\S+), (\S+)\]", log)
        fieldMax = float(m.group(2)) if m else float("nan")
        maxOk = abs(hi - fieldMax) <= 1e-6*max(1, abs(fieldMax)) if name == "hMax" else hi > 0
        say(gtOk and sizeOk and ndOk and maxOk,
            f"hazardMaps {name}{ext}: read by GDAL, size {info['size']}, geotransform "
            f"{info['geoTransform']} (DEM {dem['geoTransform']}), nodata {band.get('noDataValue')}, "
            f"max {hi:.6g}" + (f" (field {fieldMax:.6g})" if name == "hMax" else ""))
keys = ["releasedVolume", "depositVolume", "runoutX", "runoutY", "runoutZ",
        "travelAngle", "comTravelAngle"]
rep = {}
for line in open(f"{out}/report.dat"):
    if line.strip() and not line.startswith("#"):
        k, v = line.split()
        rep[k] = float(v)
tt = open(f"{case}/log.terrainToCase").read()
vT = float(re.search(r"Released volume (\S+) m\^3", tt).group(1))
good = all(k in rep and math.isfinite(rep[k]) for k in keys) \
    and abs(rep["releasedVolume"] - vT) < 1e-6*vT \
    and 1000 < rep["runoutX"] < 1240 and 0 < rep["travelAngle"] < 90
say(good, "hazardMaps report.dat: " + ", ".join(f"{k} {rep.get(k)}" for k in keys)
    + f"; terrainToCase released {vT}")
sys.exit(0 if ok else 1)
PYEOF
)"
    echo "$checks" | grep -v '^PASS\|^FAIL'
    while IFS= read -r line
    do
        case "$line" in
            PASS*) passed=$((passed + 1)); echo "$line" ;;
            FAIL*) failed=$((failed + 1)); echo "$line" ;;
        esac
    done <<< "$checks"
    echo "$checks" | grep -q '^PASS' || fail "hazardMaps: no check ran"
else
    fail "hazardMaps: blockMesh, savageHutterFoam or hazardMaps failed"
fi

# -- 6. Bad input -----------------------------------------------------------------
#- expectRefusal <name> <keyword> <sed script on terrainDict | -> [<command>]
expectRefusal()
{
    local name="$1" keyword="$2" edit="$3"
    local c
    c="$(newCase "bad-${name// /-}")"
    [ "$edit" = - ] || sed -i "$edit" "$c/system/terrainDict"
    [ $# -ge 4 ] && (cd "$c" && eval "$4")
    local before after
    before="$(snapshot "$c")"
    (cd "$c" && terrainToCase > log.terrainToCase 2>&1)
    local rc=$?
    after="$(snapshot "$c")"
    local log="$c/log.terrainToCase"
    local problems=""
    [ $rc -ne 0 ] || problems="$problems exit 0;"
    grep -q "FOAM FATAL IO ERROR" "$log" || problems="$problems no FOAM FATAL IO ERROR;"
    grep -q "terrainDict" "$log" || problems="$problems terrainDict not named;"
    grep -q "$keyword" "$log" || problems="$problems keyword $keyword not named;"
    grep -q "stack\|Segmentation" "$log" && problems="$problems stack trace;"
    [ "$before" = "$after" ] || problems="$problems files written;"
    if [ -z "$problems" ]
    then
        pass "refused, $name: $(grep -m1 -A1 'FOAM FATAL IO ERROR' "$log" | tail -n1 | cut -c1-150)"
    else
        fail "$name:$problems (see $log)"
    fi
}
expectRefusal "no DEM" "'dem'" 's#constant/plane.asc#constant/missing.asc#'
expectRefusal "unknown raster format" "'dem'" 's#constant/plane.asc#constant/plane.xyz#' \
    'cp constant/plane.asc constant/plane.xyz'
expectRefusal "DEM not a raster" "'dem'" 's#constant/plane.asc#constant/junk.tif#' \
    'echo junk > constant/junk.tif'
expectRefusal "axis leaving the DEM" "'axis'" 's#((1010 5080) (1200 5080))#((1010 5080) (1300 5080))#'
expectRefusal "axis of zero length" "'axis'" 's#((1010 5080) (1200 5080))#((1010 5080) (1010 5080))#'
expectRefusal "axis of one point" "'axis'" 's#((1010 5080) (1200 5080))#((1010 5080))#'
expectRefusal "mesh wider than the DEM" "'halfWidth'" 's#halfWidth       40#halfWidth       100#'
expectRefusal "nodata hole under the mesh" "'dem'" 's#constant/plane.asc#constant/hole.asc#'
expectRefusal "release outside the mesh" "'polygon'" 's#(1100 5060) (1130 5060) (1115 5100)#(1100 5060) (1130 5060) (1115 5150)#'
expectRefusal "release without shape" "'polygon'" 's#polygon     ((1100 5060) (1130 5060) (1115 5100));##'
expectRefusal "missing release shapefile" "'file'" 's#polygon     ((1100 5060) (1130 5060) (1115 5100));#file "constant/none.shp";#'
expectRefusal "zero thickness" "'thickness'" 's#thickness   1;#thickness   0;#'
expectRefusal "unknown thicknessDirection" "'thicknessDirection'" 's#thicknessDirection vertical#thicknessDirection sideways#'
expectRefusal "misspelt keyword" "'cellsize'" 's#^cellSize#cellsize#'
expectRefusal "negative cellSize" "'cellSize'" 's#^cellSize        5#cellSize        -5#'

echo
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]

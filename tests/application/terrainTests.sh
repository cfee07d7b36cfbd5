#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Tests of terrainToCase and hazardMaps on synthetic DEMs
#     (240 x 160 m, 2 m pixels, written here as .asc and, through
#     gdal_translate, .tif):
#       - a DEM that is exactly a 35 deg plane: zeta = 35 deg at every point
#         of the inclination table and zb = 0, both to round-off (1e-9);
#       - the plane tilted sideways by 10 deg: zb = y tan(10) cos(35) (1e-9);
#       - the warning about a steep zb (|grad zb| > 0.5): the plane tilted
#         sideways so that |grad zb| = 0.55 everywhere warns, naming every
#         cell of the mesh and the largest 0.55; tilted to 0.45, the plane
#         and the 10 deg tilt do not warn, each with its largest |grad zb|
#         in the log (0.45, 0, tan(10) cos(35));
#       - the DEM as .asc and as .tif give identical files;
#       - release polygons (a rotated quadrilateral, a triangle): volume
#         within one cell area x thickness of the analytic one, thickness
#         normal (h A / cos 35) and vertical (d A); the same polygon as a
#         shapefile gives the same volume; a vertical thickness at the
#         DEM's edge (the tilted plane), h = f cos(theta) to 1e-9;
#       - hazardMaps after a short run: its .asc and .tif rasters read back
#         by GDAL (gdalinfo) with the DEM's size, geotransform and nodata,
#         the hMax raster's maximum that of the field; report.dat with
#         every key and finite values, releasedVolume that of terrainToCase;
#       - bad input (no DEM, unknown raster format, axis leaving the DEM,
#         axis of zero length, mesh wider than the DEM, a nodata hole under
#         the mesh, the normal from the reference surface leaving the DEM
#         before it meets the terrain, an infinite elevation in the DEM, a
#         release outside the mesh, unknown keywords and choices): non-zero
#         exit by exit(), not by a signal, FOAM FATAL IO ERROR naming
#         terrainDict and the keyword, no stack trace, and no file written
#         or changed (no 0/);
#       - release rasters on a grid of their own (3 m pixels, a thickness
#         ramp): volume that of the pixels, vertical (sum d A) and normal
#         (sum d A / cos 35), within one cell area x thickness and, a plane
#         being mapped exactly, to the log's 8 digits; a uniform raster
#         wider than the mesh gives h = 1.5 m in every cell (1e-9) and a
#         warning;
#       - coordinate reference systems, on the plane moved into UTM zone 32N
#         (EPSG:32632): the release as a shapefile in EPSG:4326 gives the
#         0/h of the polygon in the DEM's coordinates (1e-6 m),
#         without .prj the same with a warning, a .prj on a DEM without one
#         a warning; a release raster in EPSG:4326 (2e-6 deg pixels) the
#         analytic volume within one cell area x thickness;
#       - a DEM on a grid rotated by 30 deg: the plane gives zeta = 35 deg
#         and zb = 0, the tilted plane its zb (1e-9), 0/h that of the
#         north-up DEM (1e-9); hazardMaps writes .tif alone, with the DEM's
#         geotransform, each pixel the hMax of the cell under its centre;
#       - the plan mode (no axis): grid size and origin on a north-up DEM
#         (whole, cells below the pixel size: the edge lines without values
#         left out, an extent inside and one clipped) and on a rotated one
#         (x along its columns); zb the plane at the cell centres (1e-9);
#         the square's volume area on the slope x h (normal) and plan area
#         x d (vertical, h = d cos(theta) on the tilted plane, 1e-9);
#         coordinates plan in transportProperties, inclination removed;
#         refused as above: no cellSize, extent outside the DEM, halfWidth
#         or profileSmoothing without axis, extent with axis, nodata under
#         the grid, a release outside it;
#       - bad release rasters (not a raster, unknown format, missing,
#         negative or NaN thickness, none > 0, off the mesh, beside a
#         polygon or a thickness), a shapefile and a raster in a system no
#         transformation reaches, a DEM whose pixels have no area: refused
#         as above.
#       - hazardMaps and avalancheSurface in the plan mode, on time
#         directories written here (the solver's plan mode is not there
#         yet): a known centre-of-mass path on the plane (3 legs of 80 m:
#         comPathLength 240 m, comTravelAngle atan(2/3 tan 35), 1e-9) and
#         one read from postProcessing/centreOfMass.dat (an L of 100 + 50 m
#         dropping 50 m, a line after the report's time left out); the
#         runout cell horizontally furthest from the release (not the
#         lowest; a further cell below the threshold left out) and its
#         travel angle; the rasters on the plan grid (size, georeference,
#         cell values, nodata); on a quadratic bed, outflowVolume and
#         depositVolume as sums of J h A over the emptied and the kept
#         cells (J from 0/zb in python, 1e-9), releasedVolume
#         terrainMapping's, hazardMaps -statistics' raster a pixel a cell,
#         and avalancheSurface's bed (X, Y, zb) and flow surface bed + h n
#         (1e-9); on the grid rotated by 30 deg, .tif
#         alone with the rotated geotransform and the flow surface h (sin
#         35, 0, cos 35) above the bed; refused with nothing written: a
#         mapping mode polar, a plan mapping without coordinates plan (both
#         tools), a bad line of centreOfMass.dat, one starting after the
#         report's time, a time without h on the path.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     terrainTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
python=/usr/bin/python3

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
) || fail "base case: setEntry on its controlDict or transportProperties failed"

# DEMs: plane (35 deg down X), tilted (and 10 deg up Y), hole (nodata under
# the mesh), steep and gentle (tilted up Y so that zb's slope across is 0.55
# and 0.45; 320 m wide in X, from 960, as the normal from the mesh's first
# cells reaches X < 1000 where zb is -22 m), steepEdge (steep on the 240 m
# from X = 1000: that normal leaves the DEM, refused in section 6), each
# .asc with full precision; infinite (the plane with an elevation inf,
# refused); quad (quadratic, section 9); .tif through gdal_translate
$python - "$work/dem" <<'PYEOF'
import math, sys
out = sys.argv[1]
a = math.tan(math.radians(35)); b = math.tan(math.radians(10))
nx, ny, d, x0, y0 = 120, 80, 2.0, 1000.0, 5000.0
def write(name, f, nx=nx, x0=x0):
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
# zb = y tan(beta) cos(35) on a plane tilted by beta across: its slope g
for name, g in [("steep", 0.55), ("gentle", 0.45)]:
    t = g/math.cos(math.radians(35))
    write(name, lambda X, Y, t=t: plane(X, Y) + t*(Y - 5080), nx=160, x0=960.0)
t = 0.55/math.cos(math.radians(35))
write("steepEdge", lambda X, Y: plane(X, Y) + t*(Y - 5080))
write("infinite", lambda X, Y: math.inf if abs(X - 1100) < 2 and abs(Y - 5090) < 2
      else plane(X, Y))
# quad: a quadratic bed for the plan mode's maps (section 9)
write("quad", lambda X, Y: 2000 - 0.5*(X - 1000) + 0.002*(X - 1000)**2
      + 0.003*(Y - 5080)**2)
PYEOF
[ $? -eq 0 ] || fail "writing the DEMs plane.asc, tilted.asc, hole.asc, steep.asc, gentle.asc, steepEdge.asc, infinite.asc, quad.asc"
gdal_translate -q --config AAIGRID_DATATYPE Float64 -ot Float64 "$work/dem/plane.asc" "$work/dem/plane.tif" \
    || fail "gdal_translate plane.asc plane.tif"
cp "$work/dem"/*.asc "$work/dem"/*.tif "$work/base/constant/" \
    || fail "copying the DEMs into the base case"

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

#- runCase <name> <terrainDict edit: a command run in the case>: a copy of
#  base, edited, through terrainToCase; sets c to the case directory, and
#  on a failure (a FAIL) returns 1.  Called in this shell, not in $(...),
#  so that the FAIL is counted
runCase()
{
    c="$work/$1"
    newCase "$1" > /dev/null
    (cd "$c" && eval "$2" && runApplication terrainToCase > /dev/null) \
        && return 0
    fail "$1: edit or terrainToCase failed (see $c/log.terrainToCase)"
    return 1
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

# -- 2b. The warning about a steep zb ------------------------------------------
#- gradCheck <case> <what> <its largest |grad zb|> <warned: yes | no>: the
#  largest |grad zb| in terrainToCase's log within 1e-6 of the given one;
#  warned: the warning names every cell of the mesh as steeper than 0.5 and
#  that largest value, and terrainToCase ended normally; not warned: no
#  warning about |grad zb|
gradCheck()
{
    local log="$1/log.terrainToCase" what="$2" want="$3" warned="$4"
    local largest cells warning problems=""
    largest="$(sed -n 's/^zb in .*; largest |grad zb| \([^ ]*\) (.*/\1/p' "$log")"
    cells="$(sed -n 's/^Mesh: \([0-9]*\) x \([0-9]*\) cells .*/\1*\2/p' "$log")"
    cells=$((${cells:-0}))
    warning="$(grep -o '[0-9]* of [0-9]* cells have |grad zb| > .*' "$log" | cut -c1-100)"
    [ -n "$largest" ] && $python -c "import sys; sys.exit(0 if abs($largest - $want) <= 1e-6 else 1)" \
        || problems="$problems largest |grad zb| '$largest' in the log, not $want;"
    [ "$cells" -gt 0 ] || problems="$problems no mesh size in the log;"
    if [ "$warned" = yes ]
    then
        grep -q "FOAM Warning" "$log" || problems="$problems no FOAM Warning;"
        case "$warning" in
            "$cells of $cells cells have |grad zb| > 0.5 (26.565051 deg), the largest $largest "*) ;;
            *) problems="$problems warning '$warning', not one naming $cells of $cells cells > 0.5 and the largest $largest;" ;;
        esac
        grep -q "^End" "$log" || problems="$problems no End;"
    else
        [ -z "$warning" ] || problems="$problems warned: '$warning';"
    fi
    if [ -z "$problems" ]
    then
        if [ "$warned" = yes ]
        then
            pass "steep zb warned, $what: $warning..."
        else
            pass "gentle zb not warned, $what: largest |grad zb| $largest in the log, no warning"
        fi
    else
        fail "warning about a steep zb, $what:$problems (see $log)"
    fi
}
if runCase steep "sed -i 's#constant/plane.asc#constant/steep.asc#' system/terrainDict"
then
    gradCheck "$c" "plane tilted across to |grad zb| = 0.55" 0.55 yes
fi
if runCase gentle "sed -i 's#constant/plane.asc#constant/gentle.asc#' system/terrainDict"
then
    gradCheck "$c" "plane tilted across to |grad zb| = 0.45" 0.45 no
fi
gradCheck "$work/plane" "plane" 0 no
gradCheck "$work/tilted" "plane tilted 10 deg across" \
    "$($python -c 'import math; print(math.tan(math.radians(10))*math.cos(math.radians(35)))')" no

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
#- volumeCheck <case> <release> <analytic> <tolerance> <what> [<what the
#  tolerance is>]
volumeCheck()
{
    local v
    v="$(sed -n "s/^Release $2: .* volume \([^ ]*\) m^3/\1/p" "$1/log.terrainToCase")"
    if [ -n "$v" ] && $python -c "import sys; sys.exit(0 if abs($v - $3) <= $4 else 1)"
    then
        pass "release volume, $5: $v m^3, analytic $3 (tolerance $4, ${6:-one cell area x thickness})"
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

# Vertical thickness at the DEM's edge: the tilted plane, the mesh reaching
# to within a pixel of where the DEM has values (halfWidth 80: the bed
# points of the first and last rows of cells at Y = 5002.5 and 5157.5, the
# values from 5001 to 5159), a rectangle X in [1040, 1100], Y in [5001,
# 5159] of vertical thickness 1: h = f cos(theta), f the cell's area
# covered (0.8 in those rows, 1 between), cos(theta) = 1/sqrt(1 + tan^2 35
# + tan^2 10), the slope across one-sided in those rows (taken as 0 there
# before: h 0.8 cos 35), exact on a plane
if runCase vertical-edge "sed -i 's#constant/plane.asc#constant/tilted.asc#; s#halfWidth       40#halfWidth       80#; s#((1040 5080) (1060 5060) (1080 5080) (1060 5100) (1050 5090))#((1040 5001) (1100 5001) (1100 5159) (1040 5159))#; s#thickness   2#thickness   1#; s#thicknessDirection normal#thicknessDirection vertical#; /^    r2/,/^    }/d' system/terrainDict"
then
    if msg="$(fieldCheck "$c" '(lambda h, ct: (lambda e0, e1, e: (max(e0, e1, e) < 1e-9, "max h in the first row of cells %.12g, in the last %.12g, over all %.12g; 0.8 cos(theta) = %.12g, cos(theta) = %.12g" % (max(h[:nx]), max(h[-nx:]), max(h), 0.8*ct, ct)))(abs(max(h[:nx]) - 0.8*ct), abs(max(h[-nx:]) - 0.8*ct), abs(max(h) - ct)))(field("h"), 1/math.sqrt(1 + math.tan(math.radians(35))**2 + math.tan(math.radians(10))**2))')"
    then
        pass "vertical thickness at the DEM's edge (slope one-sided there): $msg"
    else
        fail "vertical thickness at the DEM's edge: $msg"
    fi
fi

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
for name in ["hMax", "UMax", "pMax", "deposit", "tArrival"]:
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
    tally $? "$checks" "hazardMaps' checks"
else
    fail "hazardMaps: blockMesh, savageHutterFoam or hazardMaps failed"
fi

# -- 6. Bad input -----------------------------------------------------------------
#- expectRefusal <name> <keyword> <sed script on terrainDict | -> [<command>
#  ("" for none) [<regex the log must hold>]]
expectRefusal()
{
    local name="$1" keyword="$2" edit="$3"
    local c
    c="$(newCase "bad-${name// /-}")"
    [ "$edit" = - ] || sed -i "$edit" "$c/system/terrainDict"
    if [ $# -ge 4 ] && ! (cd "$c" && eval "$4")
    then
        fail "$name: the set-up command failed: $4"
        return
    fi
    local before after
    before="$(snapshot "$c")"
    (cd "$c" && terrainToCase > log.terrainToCase 2>&1)
    local rc=$?
    after="$(snapshot "$c")"
    local log="$c/log.terrainToCase"
    local problems=""
    [ $rc -ne 0 ] || problems="$problems exit 0;"
    [ $rc -lt 128 ] || problems="$problems killed by signal $((rc - 128));"
    grep -q "FOAM FATAL IO ERROR" "$log" || problems="$problems no FOAM FATAL IO ERROR;"
    grep -q "terrainDict" "$log" || problems="$problems terrainDict not named;"
    grep -q "$keyword" "$log" || problems="$problems keyword $keyword not named;"
    [ $# -lt 5 ] || grep -q "$5" "$log" || problems="$problems no '$5' in the log;"
    # (OpenFOAM's banner says "trapFpe: Floating point exception trapping")
    grep -v '^trapFpe:' "$log" \
        | grep -q "stack\|Segmentation\|sigFpe\|^#0 \|Floating point exception" \
        && problems="$problems stack trace;"
    [ "$before" = "$after" ] || problems="$problems files written;"
    [ ! -e "$c/0" ] || problems="$problems 0/ made;"
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
# The steep DEM from X = 1000: the normal from the mesh's first cells (zb
# about -22 m) reaches X < 1000 (it crashed with SIGFPE, or called that a
# nodata hole)
expectRefusal "normal leaving the DEM" "'dem'" 's#constant/plane.asc#constant/steepEdge.asc#' "" \
    "the normal from the reference surface at x = .* leaves the DEM .*steepEdge.asc"
expectRefusal "infinite DEM elevation" "'dem'" 's#constant/plane.asc#constant/infinite.asc#' "" \
    "infinite.asc\" holds the elevation inf"
expectRefusal "release outside the mesh" "'polygon'" 's#(1100 5060) (1130 5060) (1115 5100)#(1100 5060) (1130 5060) (1115 5150)#'
expectRefusal "release without shape" "'polygon'" 's#polygon     ((1100 5060) (1130 5060) (1115 5100));##'
expectRefusal "missing release shapefile" "'file'" 's#polygon     ((1100 5060) (1130 5060) (1115 5100));#file "constant/none.shp";#'
expectRefusal "zero thickness" "'thickness'" 's#thickness   1;#thickness   0;#'
expectRefusal "unknown thicknessDirection" "'thicknessDirection'" 's#thicknessDirection vertical#thicknessDirection sideways#'
expectRefusal "misspelt keyword" "'cellsize'" 's#^cellSize#cellsize#'
expectRefusal "negative cellSize" "'cellSize'" 's#^cellSize        5#cellSize        -5#'

# -- 7. Release rasters, coordinate reference systems, rotated DEMs -----------
# This section's inputs: a release raster on a grid of its own (3 m pixels,
# not aligned with the DEM's 2 m ones), a thickness ramp in a rectangle
# (rel.asc; its sum of thickness x pixel area in rel.volume), a uniform one
# over the mesh and beyond (uniform.asc), bad ones; the plane moved into
# UTM zone 32N (utm.asc, utm.tif in EPSG:32632); the plane and the tilted
# plane on a grid rotated by 30 deg (rplane.tif, rtilted.tif, through a
# VRT) and a grid whose pixels have no area (degenerate.tif)
$python - "$work/base/constant" <<'PYEOF'
import math, sys
out = sys.argv[1]
a = math.tan(math.radians(35)); b = math.tan(math.radians(10))
def asc(name, nx, ny, d, x0, y0, f):
    with open(f"{out}/{name}", "w") as o:
        o.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\n"
                f"cellsize {d}\nNODATA_value -9999\n")
        for j in range(ny):
            Y = y0 + (ny - j - 0.5)*d
            o.write(" ".join(str(f(i, x0 + (i + 0.5)*d, Y)) for i in range(nx))
                    + "\n")
def ramp(i, X, Y):
    if i == 0:
        return -9999
    return 0.5 + 0.01*(X - 1040) if 1040 < X < 1100 and 5060 < Y < 5100 else 0
asc("rel.asc", 40, 30, 3.0, 1031.5, 5041.7, lambda i, X, Y: "%.17g" % ramp(i, X, Y))
volume = sum(max(ramp(i, 1031.5 + (i + 0.5)*3, 5041.7 + (j + 0.5)*3), 0)*9
             for i in range(40) for j in range(30))
open(f"{out}/rel.volume", "w").write("%.17g\n" % volume)
asc("uniform.asc", 33, 15, 7.0, 1003, 5030, lambda i, X, Y: 1.5)
asc("negative.asc", 40, 30, 3.0, 1031.5, 5041.7,
    lambda i, X, Y: -0.1 if (i, round(Y, 6)) == (20, 5085.2) else "%.17g" % ramp(i, X, Y))
asc("nan.asc", 40, 30, 3.0, 1031.5, 5041.7,
    lambda i, X, Y: "nan" if (i, round(Y, 6)) == (20, 5085.2) else "%.17g" % ramp(i, X, Y))
asc("zero.asc", 40, 30, 3.0, 1031.5, 5041.7, lambda i, X, Y: 0)
asc("far.asc", 5, 5, 2.0, 1210, 5140, lambda i, X, Y: 1)
asc("utm.asc", 120, 80, 2.0, 600000, 5200000,
    lambda i, X, Y: "%.17g" % (2000 - a*(X - 600000)))
# Rotated by 30 deg about the mesh's middle, 130 x 130 pixels of 2 m
n, d, t = 130, 2.0, math.radians(30)
gt = [927.0, d*math.cos(t), d*math.sin(t), 5128.0, d*math.sin(t), -d*math.cos(t)]
for name, f in [("rplane", lambda X, Y: 2000 - a*(X - 1000)),
                ("rtilted", lambda X, Y: 2000 - a*(X - 1000) + b*(Y - 5080))]:
    with open(f"{out}/{name}.values.asc", "w") as o:
        o.write(f"ncols {n}\nnrows {n}\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
                "NODATA_value -9999\n")
        for r in range(n):
            o.write(" ".join("%.17g" % f(gt[0] + (c + 0.5)*gt[1] + (r + 0.5)*gt[2],
                                         gt[3] + (c + 0.5)*gt[4] + (r + 0.5)*gt[5])
                             for c in range(n)) + "\n")
    with open(f"{out}/{name}.vrt", "w") as o:
        o.write(f'<VRTDataset rasterXSize="{n}" rasterYSize="{n}">\n'
                f'  <GeoTransform>{", ".join("%.17g" % g for g in gt)}</GeoTransform>\n'
                '  <VRTRasterBand dataType="Float64" band="1">\n'
                '    <NoDataValue>-9999</NoDataValue>\n'
                f'    <SimpleSource><SourceFilename relativeToVRT="1">{name}.values.asc'
                '</SourceFilename><SourceBand>1</SourceBand></SimpleSource>\n'
                '  </VRTRasterBand>\n</VRTDataset>\n')
with open(f"{out}/degenerate.vrt", "w") as o:
    o.write(open(f"{out}/rplane.vrt").read().replace(
        ", ".join("%.17g" % g for g in gt), "1000, 2, 0, 5000, 0, 0"))
PYEOF
[ $? -eq 0 ] || fail "writing this section's rasters (rel.asc, utm.asc, rplane.vrt, ...)"
(
    cd "$work/base/constant" || exit 1
    t="gdal_translate -q --config AAIGRID_DATATYPE Float64 -ot Float64"
    $t nan.asc nan.tif && $t -a_srs EPSG:32632 utm.asc utm.tif \
        && $t rplane.vrt rplane.tif && $t rtilted.vrt rtilted.tif \
        && $t degenerate.vrt degenerate.tif \
        && $t -a_srs 'LOCAL_CS["arbitrary",UNIT["metre",1]]' rel.asc local.tif \
        && echo junk > junk.tif && cp rel.asc rel.xyz
) || fail "gdal_translate: this section's rasters"

# The quadrilateral r1 in UTM coordinates: a shapefile in EPSG:4326
# (longitude, latitude), one in the DEM's system without .prj, one in a
# local engineering system no transformation reaches; rasterised on a
# longitude-latitude grid of 2e-6 deg (0.15 x 0.22 m) with thickness 2
(
    cd "$work/base/constant" || exit 1
    cat > utm.geojson <<'EOD'
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[600040, 5200080], [600060, 5200060],
 [600080, 5200080], [600060, 5200100], [600050, 5200090], [600040, 5200080]]]}}]}
EOD
    ogr2ogr -f "ESRI Shapefile" -s_srs EPSG:32632 -t_srs EPSG:4326 lonlat.shp utm.geojson \
        && ogr2ogr -f "ESRI Shapefile" noprj.shp utm.geojson && rm noprj.prj \
        && ogr2ogr -f "ESRI Shapefile" -a_srs 'LOCAL_CS["arbitrary",UNIT["metre",1]]' \
            local.shp utm.geojson \
        && gdal_rasterize -q -burn 2 -init 0 -ot Float64 -tr 2e-6 2e-6 lonlat.shp lonlat.tif
) || fail "ogr2ogr, gdal_rasterize: this section's shapefiles"

#- terrainDict on the UTM DEM: writeUtmDict <case> <r1's shape entry>
#  [<r1's thickness entry>]
writeUtmDict()
{
    cat > "$1/system/terrainDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "constant/utm.tif";
axis            ((600010 5200080) (600200 5200080));
halfWidth       40;
cellSize        5;
profileSmoothing 20;
release
{
    r1
    {
        $2
        ${3-thickness   2;}
        thicknessDirection normal;
    }
}
EOD
}

#- r1 of terrainDict replaced: setR1 <case> <entries>
setR1()
{
    sed -i "s#polygon     ((1040 5080) (1060 5060) (1080 5080) (1060 5100) (1050 5090));#$2#; /thickness   2;/d" \
        "$1/system/terrainDict"
}

#- compareH <case> <reference case> <tolerance> <what>: 0/h of the two
compareH()
{
    local msg
    if msg="$($python - "$1" "$2" "$3" <<'PYEOF'
import re, sys
def h(case):
    t = open(f"{case}/0/h").read()
    m = re.search(r"List<scalar>\s*\d+\s*\(([^)]*)\)", t)
    return [float(v) for v in m.group(1).split()]
a, b, tol = h(sys.argv[1]), h(sys.argv[2]), float(sys.argv[3])
e = max(abs(u - v) for u, v in zip(a, b)) if len(a) == len(b) else float("inf")
print("max |h - h_ref| = %.3g m over %d cells (tolerance %g m)" % (e, len(a), tol))
sys.exit(0 if e <= tol else 1)
PYEOF
)"
    then
        pass "$4: $msg"
    else
        fail "$4: $msg"
    fi
}

# Release rasters: the ramp on its own grid, vertical and normal; the
# uniform raster, wider than the mesh
relVolume="$(cat "$work/base/constant/rel.volume")"
cellArea=25
if runCase raster-vertical "setR1 . 'raster \"constant/rel.asc\";'; sed -i 's/thicknessDirection normal/thicknessDirection vertical/' system/terrainDict"
then
    volumeCheck "$c" r1 "$relVolume" "$cellArea*1.1" "release raster (3 m pixels, ramp 0.5 to 1.1 m), vertical"
    volumeCheck "$c" r1 "$relVolume" "1e-7*$relVolume" "release raster, vertical, exact on a plane DEM" "the log's 8 digits"
fi
if runCase raster-normal "setR1 . 'raster \"constant/rel.asc\";'"
then
    volumeCheck "$c" r1 "$relVolume/$cos35" "$cellArea*1.1" "release raster, normal (sum d A / cos 35)"
    volumeCheck "$c" r1 "$relVolume/$cos35" "1e-7*$relVolume/$cos35" "release raster, normal, exact on a plane DEM" "the log's 8 digits"
fi
if runCase raster-uniform "setR1 . 'raster \"constant/uniform.asc\";'; sed -i '/^    r2/,/^    }/d' system/terrainDict"
then
    if msg="$(fieldCheck "$c" '(lambda h: (max(abs(v - 1.5) for v in h) < 1e-9, "h in [%.15g, %.15g] m over %d cells" % (min(h), max(h), len(h))))(field("h"))')"
    then
        pass "uniform release raster of 1.5 m (7 m pixels) over the whole mesh and beyond: $msg"
    else
        fail "uniform release raster of 1.5 m over the whole mesh: $msg"
    fi
    if grep -q "reach outside the mesh" "$c/log.terrainToCase"
    then
        pass "uniform release raster beyond the mesh: warned ($(grep -o '[0-9]* of the [0-9]* pixels.*' "$c/log.terrainToCase" | head -n1 | cut -c1-80)...)"
    else
        fail "uniform release raster beyond the mesh: no warning"
    fi
fi

# Coordinate reference systems: r1 in the UTM DEM's coordinates in the
# dictionary, as a shapefile in longitude-latitude, without .prj, and as a
# longitude-latitude raster
ref="$(newCase utm-dictionary)"
writeUtmDict "$ref" "polygon ((600040 5200080) (600060 5200060) (600080 5200080) (600060 5200100) (600050 5200090));"
sed -i '/^    r2/,/^    }/d' "$ref/system/terrainDict"
(cd "$ref" && runApplication terrainToCase > /dev/null) || fail "UTM DEM: terrainToCase failed"
volumeCheck "$ref" r1 "2*800/$cos35" 50 "UTM DEM (EPSG:32632), polygon in the dictionary"
c="$(newCase utm-lonlat)"
writeUtmDict "$c" 'file "constant/lonlat.shp";'
if (cd "$c" && runApplication terrainToCase > /dev/null)
then
    if grep -q "transformed from 'WGS 84' (EPSG:4326) to 'WGS 84 / UTM zone 32N' (EPSG:32632)" "$c/log.terrainToCase"
    then
        compareH "$c" "$ref" 1e-6 "shapefile in EPSG:4326 on a DEM in EPSG:32632: transformed, 0/h that of the polygon in the DEM's coordinates"
    else
        fail "shapefile in EPSG:4326 on a DEM in EPSG:32632: no transformation announced"
    fi
else
    fail "shapefile in EPSG:4326 on a DEM in EPSG:32632: terrainToCase failed"
fi
c="$(newCase utm-noprj)"
writeUtmDict "$c" 'file "constant/noprj.shp";'
if (cd "$c" && runApplication terrainToCase > /dev/null) \
    && grep -q "noprj.shp gives no coordinate reference system, the DEM is in 'WGS 84 / UTM zone 32N'" "$c/log.terrainToCase"
then
    compareH "$c" "$ref" 1e-12 "shapefile without .prj on a DEM in EPSG:32632: warned, taken in the DEM's coordinates"
else
    fail "shapefile without .prj on a DEM in EPSG:32632: terrainToCase failed or no warning"
fi
if grep -q "release.shp is in 'WGS 84' (EPSG:4326), the DEM gives no coordinate reference system" "$work/shapefile/log.terrainToCase"
then
    pass "shapefile with a .prj on a DEM without one: warned, taken in the DEM's coordinates (0/h as checked in section 4)"
else
    fail "shapefile with a .prj on a DEM without one: no warning"
fi
c="$(newCase utm-lonlat-raster)"
writeUtmDict "$c" 'raster "constant/lonlat.tif";' ""
if (cd "$c" && runApplication terrainToCase > /dev/null)
then
    volumeCheck "$c" r1 "2*800/$cos35" 50 "release raster in EPSG:4326 (2e-6 deg pixels, thickness 2 m normal) on a DEM in EPSG:32632"
else
    fail "release raster in EPSG:4326 on a DEM in EPSG:32632: terrainToCase failed"
fi

# Rotated DEMs: the plane and the tilted plane on a grid rotated by 30 deg
if runCase rotated "sed -i 's#constant/plane.asc#constant/rplane.tif#' system/terrainDict"
then
    if msg="$(fieldCheck "$c" '(max(abs(z - 35) for z in zeta) < 1e-9 and max(map(abs, zb)) < 1e-9, "max |zeta - 35| = %.3g deg, max |zb| = %.3g m" % (max(abs(z - 35) for z in zeta), max(map(abs, zb))))')"
    then
        pass "plane DEM on a grid rotated by 30 deg: $msg"
    else
        fail "plane DEM on a grid rotated by 30 deg: $msg"
    fi
    compareH "$c" "$work/plane" 1e-9 "plane DEM on a rotated grid: 0/h that of the north-up DEM"
fi
if runCase rotated-tilted "sed -i 's#constant/plane.asc#constant/rtilted.tif#' system/terrainDict"
then
    if msg="$(fieldCheck "$c" '(lambda e: (e < 1e-9, "max |zb - y tan10 cos35| = %.3g m" % e))(max(abs(zb[k] - y[k]*math.tan(math.radians(10))*math.cos(math.radians(35))) for k in range(len(zb))))')"
    then
        pass "sideways-tilted plane on a grid rotated by 30 deg: $msg"
    else
        fail "sideways-tilted plane on a grid rotated by 30 deg: $msg"
    fi
fi

# hazardMaps on the rotated plane: GeoTIFF alone, with the DEM's
# geotransform; each pixel the hMax of the cell under its centre
c="$work/rotated"
sed -i 's/^rho .*//' "$c/constant/transportProperties"
sed -i 's/^phi /rho             1500;\nphi /' "$c/constant/transportProperties"
if (
    cd "$c" && runApplication blockMesh && runApplication savageHutterFoam \
        && runApplication hazardMaps -threshold 0.01 \
        && gdal_translate -q -of AAIGrid postProcessing/hazardMaps/1/hMax.tif hMax.values.asc
) > /dev/null
then
    if msg="$($python - "$c" 2>&1 <<'PYEOF'
import json, math, os, re, subprocess, sys
case = sys.argv[1]
out = f"{case}/postProcessing/hazardMaps/1"
info = lambda f: json.loads(subprocess.run(["gdalinfo", "-json", f], capture_output=True, text=True).stdout)
gt = info(f"{out}/hMax.tif")["geoTransform"]
gtDem = info(f"{case}/constant/rplane.tif")["geoTransform"]
asc = [f for f in os.listdir(out) if f.endswith(".asc")]
rows = open(f"{case}/hMax.values.asc").read().split("\n")[6:]
v = [[float(s) for s in r.split()] for r in rows if r.strip()]
t = open(f"{case}/1/hMax").read()
hMax = [float(s) for s in re.search(r"List<scalar>\s*\d+\s*\(([^)]*)\)", t).group(1).split()]
bm = open(f"{case}/system/blockMeshDict").read()
nx = int(re.search(r"^nx\s+(\d+);", bm, re.M).group(1))
ny = int(re.search(r"^ny\s+(\d+);", bm, re.M).group(1))
cs, yMax, c35 = 5.0, 2.5*ny, math.cos(math.radians(35))
n = bad = 0
for r, row in enumerate(v):
    for c, val in enumerate(row):
        X = gt[0] + (c + 0.5)*gt[1] + (r + 0.5)*gt[2]
        Y = gt[3] + (c + 0.5)*gt[4] + (r + 0.5)*gt[5]
        fx, fy = (X - 1010)/c35/cs, (Y - 5080 + yMax)/cs
        if not (0 < fx < nx and 0 < fy < ny) or min(fx % 1, 1 - fx % 1, fy % 1, 1 - fy % 1) < 1e-6:
            continue
        h = hMax[int(fx) + nx*int(fy)]
        want = h if h > 0.01 else -9999
        n += 1
        bad += abs(val - want) > 1e-6*max(1, abs(want))
good = gt == gtDem and not asc and n > 1000 and bad == 0
print(f"geotransform {gt} (DEM {gtDem}), .asc written: {asc or 'none'}, "
      f"{n} pixels over the mesh, {bad} not the hMax of the cell under their centre")
sys.exit(0 if good else 1)
PYEOF
)"
    then
        pass "hazardMaps on a rotated DEM: hMax.tif $msg"
    else
        fail "hazardMaps on a rotated DEM: $msg"
    fi
else
    fail "hazardMaps on a rotated DEM: blockMesh, savageHutterFoam, hazardMaps or gdal_translate failed"
fi

# Bad release rasters and coordinate systems, a degenerate DEM
r1='polygon     ((1040 5080) (1060 5060) (1080 5080) (1060 5100) (1050 5090));'
r1raster() { echo "s#$r1#raster \"constant/$1\";#; /thickness   2;/d"; }
expectRefusal "release raster not a raster" "'raster'" "$(r1raster junk.tif)"
expectRefusal "release raster of unknown format" "'raster'" "$(r1raster rel.xyz)"
expectRefusal "missing release raster" "'raster'" "$(r1raster none.tif)"
expectRefusal "negative release thickness" "'raster'" "$(r1raster negative.asc)"
expectRefusal "NaN release thickness" "'raster'" "$(r1raster nan.tif)"
expectRefusal "release raster without thickness" "'raster'" "$(r1raster zero.asc)"
expectRefusal "release raster off the mesh" "'raster'" "$(r1raster far.asc)"
expectRefusal "polygon and raster in one release" "'raster'" "s#$r1#$r1 raster \"constant/rel.asc\";#; /thickness   2;/d"
expectRefusal "thickness beside a release raster" "'thickness'" "s#$r1#raster \"constant/rel.asc\";#"
expectRefusal "shapefile no transformation reaches" "local.shp" - \
    "cp ../utm-dictionary/system/terrainDict system/ && sed -i 's#polygon ((600040.*#file \"constant/local.shp\";#' system/terrainDict"
expectRefusal "release raster no transformation reaches" "local.tif" - \
    "cp ../utm-dictionary/system/terrainDict system/ && sed -i 's#polygon ((600040.*#raster \"constant/local.tif\";#; /thickness   2;/d' system/terrainDict"
expectRefusal "DEM of pixels without area" "'dem'" 's#constant/plane.asc#constant/degenerate.tif#'

# -- 8. The plan mode: no axis, the DEM's own plan grid ---------------------------
#- writePlanDict <case> [<dem>] [<thicknessDirection>] [<extra entries>]: a
#  terrainDict without axis, cellSize 5, release r1 the square X in [1040,
#  1100], Y in [5040, 5100] (3600 m^2 in plan) of thickness 2
writePlanDict()
{
    cat > "$1/system/terrainDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object terrainDict; }
dem             "${2:-constant/plane.asc}";
cellSize        5;
${4:-}
release
{
    r1
    {
        polygon     ((1040 5040) (1100 5040) (1100 5100) (1040 5100));
        thickness   2;
        thicknessDirection ${3:-normal};
    }
}
EOD
}

#- planCase <name> <writePlanDict's arguments but the case> [<edit>]: a copy
#  of base with that terrainDict through terrainToCase; sets c
planCase()
{
    local name="$1"
    shift
    c="$work/$name"
    newCase "$name" > /dev/null
    (cd "$c" && writePlanDict . "$@" && runApplication terrainToCase > /dev/null) \
        && return 0
    fail "$name: terrainToCase failed (see $c/log.terrainToCase)"
    return 1
}

#- planCheck <case> <what> <python: sets ok and msg>: over nx, ny (the
#  blockMeshDict's), cs, origin, xAxis, yAxis (terrainMapping's), the
#  fields zb and h, X(c), Y(c) (world centre of cell c), volume (the log's
#  released volume), tp (transportProperties' text), log
planCheck()
{
    local msg
    if msg="$($python - "$1" "$3" 2>&1 <<'PYEOF'
import math, re, sys
case, code = sys.argv[1], sys.argv[2]
def field(name):
    t = open(f"{case}/0/{name}").read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", t)
    return [float(v) for v in m.group(2).split()]
def entry(text, key):
    return re.search(r"^%s\s+([^;]*);" % key, text, re.M).group(1)
def vec(text, key):
    return [float(v) for v in entry(text, key).strip("()").split()]
bm = open(f"{case}/system/blockMeshDict").read()
nx, ny = int(entry(bm, "nx")), int(entry(bm, "ny"))
tm = open(f"{case}/constant/terrainMapping").read()
cs = float(entry(tm, "cellSize"))
origin, xAxis, yAxis = vec(tm, "origin"), vec(tm, "xAxis"), vec(tm, "yAxis")
zb, h = field("zb"), field("h")
def X(c):
    x, y = (c % nx + 0.5)*cs, (c // nx + 0.5)*cs
    return origin[0] + x*xAxis[0] + y*yAxis[0]
def Y(c):
    x, y = (c % nx + 0.5)*cs, (c // nx + 0.5)*cs
    return origin[1] + x*xAxis[1] + y*yAxis[1]
log = open(f"{case}/log.terrainToCase").read()
volume = float(re.search(r"^Released volume (\S+) m\^3", log, re.M).group(1))
tp = open(f"{case}/constant/transportProperties").read()
a35, a10 = math.tan(math.radians(35)), math.tan(math.radians(10))
ok, msg = False, "no result"
exec(code)
print(msg)
sys.exit(0 if ok else 1)
PYEOF
)"
    then
        pass "plan mode, $2: $msg"
    else
        fail "plan mode, $2: $msg"
    fi
}

# North-up plane, the DEM's whole extent: 48 x 32 cells of 5 m from the
# DEM's lower-left corner; zb the plane at the cell centres; the square's
# volume 2 x 3600 / cos 35 (normal thickness: area on the slope x h)
if planCase plan-plane constant/plane.asc
then
    planCheck "$c" "north-up plane DEM" '
e = max(abs(zb[k] - (2000 - a35*(X(k) - 1000))) for k in range(len(zb)))
want = 2*3600/math.cos(math.radians(35))
ok = (nx, ny) == (48, 32) and origin == [1000, 5000] and xAxis == [1, 0] \
    and yAxis == [0, 1] and len(zb) == nx*ny and e < 1e-9 \
    and abs(volume - want) < 1e-6*want and abs(max(h) - 2) < 1e-12
msg = "%d x %d cells, origin %s, xAxis %s, yAxis %s, max |zb - plane| = %.3g m, volume %.10g m^3 (2 x 3600/cos35 = %.10g), max h %.17g" % (nx, ny, origin, xAxis, yAxis, e, volume, want, max(h))'
    planCheck "$c" "transportProperties" '
ok = re.search(r"^coordinates\s+plan;", tp, re.M) is not None \
    and re.search(r"^\s*inclination", tp, re.M) is None \
    and re.search(r"^g\s+9.81;", tp, re.M) is not None \
    and "inclination" in log and "removed" in log
msg = "coordinates plan, no inclination (removed, the log says so), g kept"'
fi

# A cell size below the pixel's: the edge lines of cells whose centres lie
# in the band half a pixel wide along the outline are left out (160 x 106
# cells of 1.5 m, less the first and last column and the first row)
c="$work/plan-fine"
newCase plan-fine > /dev/null
if (cd "$c" && writePlanDict . && sed -i 's/^cellSize .*/cellSize 1.5;/' system/terrainDict \
    && runApplication terrainToCase > /dev/null)
then
    planCheck "$c" "cells of 1.5 m on 2 m pixels" '
ok = (nx, ny) == (158, 105) and abs(origin[0] - 1001.5) < 1e-9 and abs(origin[1] - 5001.5) < 1e-9 \
    and max(abs(zb[k] - (2000 - a35*(X(k) - 1000))) for k in range(len(zb))) < 1e-9
msg = "%d x %d cells, origin %s" % (nx, ny, origin)'
else
    fail "plan mode, cells of 1.5 m: terrainToCase failed (see $c/log.terrainToCase)"
fi

# extent: within the DEM, and reaching beyond it (clipped)
if planCase plan-extent constant/plane.asc normal "extent ((1020 5010) (1180 5150));"
then
    planCheck "$c" "extent ((1020 5010) (1180 5150))" '
ok = (nx, ny) == (32, 28) and origin == [1020, 5010]
msg = "%d x %d cells, origin %s" % (nx, ny, origin)'
fi
if planCase plan-clipped constant/plane.asc normal "extent ((900 5010) (1100 5300));"
then
    planCheck "$c" "extent ((900 5010) (1100 5300)) clipped to the DEM" '
ok = (nx, ny) == (20, 30) and origin == [1000, 5010] and "clipped" in log
msg = "%d x %d cells, origin %s, clipped in the log" % (nx, ny, origin)'
fi

# Vertical thickness on the plane tilted both ways: h = 2 cos(theta),
# cos(theta) = 1/sqrt(1 + tan^2 35 + tan^2 10), volume 2 x 3600 (vertical
# column)
if planCase plan-vertical constant/tilted.asc vertical
then
    planCheck "$c" "vertical thickness on a tilted plane" '
ct = 1/math.sqrt(1 + a35**2 + a10**2)
full = [v for v in h if v > 0 and abs(v - 2*ct) < 1e-6]
e = max(abs(v - 2*ct) for v in full)
ez = max(abs(zb[k] - (2000 - a35*(X(k) - 1000) + a10*(Y(k) - 5080))) for k in range(len(zb)))
ok = len(full) == 144 and e < 1e-9 and abs(volume - 7200) < 1e-6*7200 and ez < 1e-9
msg = "%d full cells with h = 2 cos(theta) within %.3g m, volume %.10g m^3 (7200), max |zb - plane| %.3g m" % (len(full), e, volume, ez)'
fi

# A DEM on a grid rotated by 30 deg: x along its columns; 52 x 52 cells,
# origin the outline corner (927, 5128) - 260 yAxis; zb the plane; the
# square's volume as on the north-up DEM
if planCase plan-rotated constant/rplane.tif
then
    planCheck "$c" "plane DEM on a grid rotated by 30 deg" '
t = math.radians(30)
o = [927 + 260*math.sin(t), 5128 - 260*math.cos(t)]
e = max(abs(zb[k] - (2000 - a35*(X(k) - 1000))) for k in range(len(zb)))
want = 2*3600/math.cos(math.radians(35))
ok = (nx, ny) == (52, 52) and max(abs(origin[i] - o[i]) for i in (0, 1)) < 1e-9 \
    and abs(xAxis[0] - math.cos(t)) < 1e-15 and abs(xAxis[1] - math.sin(t)) < 1e-15 \
    and abs(yAxis[0] + math.sin(t)) < 1e-15 and abs(yAxis[1] - math.cos(t)) < 1e-15 \
    and e < 1e-9 and abs(volume - want) < 1e-6*want
msg = "%d x %d cells, origin %s (%s), xAxis %s, max |zb - plane| = %.3g m, volume %.10g m^3 (%.10g)" % (nx, ny, origin, o, xAxis, e, volume, want)'
fi

# A release raster (the thickness ramp on its own 3 m pixels), vertical:
# its volume that of the pixels (sum d A: the plan frame maps it exactly)
c="$work/plan-raster"
newCase plan-raster > /dev/null
if (cd "$c" && writePlanDict . constant/plane.asc vertical \
    && sed -i 's#polygon .*#raster "constant/rel.asc";#; /thickness   2;/d' system/terrainDict \
    && runApplication terrainToCase > /dev/null)
then
    planCheck "$c" "release raster, vertical thickness" '
want = float(open(case + "/constant/rel.volume").read())
ok = abs(volume - want) < 1e-6*want
msg = "volume %.10g m^3, the pixels %.10g" % (volume, want)'
else
    fail "plan mode, release raster: terrainToCase failed (see $c/log.terrainToCase)"
fi

# Refused, nothing written
expectRefusal "plan mode, missing cellSize" "'cellSize'" - \
    "writePlanDict . && sed -i '/^cellSize/d' system/terrainDict"
expectRefusal "plan mode, extent outside the DEM" "'extent'" - \
    "writePlanDict . constant/plane.asc normal 'extent ((0 0) (100 100));'"
expectRefusal "plan mode, halfWidth without axis" "'halfWidth'" - \
    "writePlanDict . constant/plane.asc normal 'halfWidth 40;'" "belongs to the axis mode"
expectRefusal "plan mode, profileSmoothing without axis" "'profileSmoothing'" - \
    "writePlanDict . constant/plane.asc normal 'profileSmoothing 20;'" "belongs to the axis mode"
expectRefusal "axis mode, extent with axis" "'extent'" \
    's#^cellSize.*#cellSize 5; extent ((1000 5000) (1100 5100));#' "" "belongs to the plan mode"
expectRefusal "plan mode, nodata under the grid" "'dem'" - \
    "writePlanDict . constant/hole.asc" "cell centres of the plan grid lie next to nodata"
expectRefusal "plan mode, release outside the grid" "'polygon'" - \
    "writePlanDict . constant/plane.asc normal 'extent ((1000 5000) (1080 5160));'" "outside the plan grid"

# -- 9. hazardMaps and avalancheSurface in the plan mode (synthetic times) -------
# The solver's plan mode is not there yet: the time directories are written
# here (h, hMax, UMax, U per cell, the formats of 0/h and 0/U), on plan
# cases of the plane (35 deg down X), a quadratic bed (quad.asc) and
# the plane on the grid rotated by 30 deg.  The expected values are worked
# out by hand or in python from the case's own 0/zb (centred differences,
# one-sided at the edges), not taken from the tools' output.

# The helpers of this section's python: the plan case's grid and bed, the
# fields written into a time directory, report.dat, the .vtp files
cat > "$work/synth.py" <<'PYEOF'
import base64, math, os, re, struct
import xml.etree.ElementTree as ET
case = None
def entry(text, key):
    return re.search(r"^%s\s+([^;]*);" % key, text, re.M).group(1)
def vec(text, key):
    return [float(v) for v in entry(text, key).strip("()").split()]
def load(c):
    """the plan case c: nx, ny, cs, origin, xAxis, yAxis, zb (0/zb)"""
    global case, nx, ny, cs, origin, xAxis, yAxis, zb
    case = c
    tm = open(f"{c}/constant/terrainMapping").read()
    nx, ny, cs = int(entry(tm, "nx")), int(entry(tm, "ny")), float(entry(tm, "cellSize"))
    origin, xAxis, yAxis = vec(tm, "origin"), vec(tm, "xAxis"), vec(tm, "yAxis")
    zb = readField("0", "zb")
def readField(t, name):
    txt = open(f"{case}/{t}/{name}").read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\(([^)]*)\)", txt)
    return [float(v) for v in m.group(1).split()]
def cell(i, j):
    return i + nx*j
def XY(c):
    x, y = (c % nx + 0.5)*cs, (c // nx + 0.5)*cs
    return (origin[0] + x*xAxis[0] + y*yAxis[0], origin[1] + x*xAxis[1] + y*yAxis[1])
def grad(c):
    """centred differences of zb, one-sided at the edges (case x, y)"""
    i, j = c % nx, c // nx
    im, ip, jm, jp = max(i - 1, 0), min(i + 1, nx - 1), max(j - 1, 0), min(j + 1, ny - 1)
    gx = (zb[cell(ip, j)] - zb[cell(im, j)])/((ip - im)*cs) if ip > im else 0
    gy = (zb[cell(i, jp)] - zb[cell(i, jm)])/((jp - jm)*cs) if jp > jm else 0
    return gx, gy
def J(c):
    gx, gy = grad(c)
    return math.sqrt(1 + gx*gx + gy*gy)
def write(t, name, values):
    """a field in time directory t: a list of numbers (volScalarField) or
    of 3-tuples (volVectorField), in the format of 0/h or 0/U"""
    vector = isinstance(values[0], tuple)
    src = open(f"{case}/0/{'U' if vector else 'h'}").read()
    if vector:
        body = "nonuniform List<vector>\n%d\n(\n%s\n)" % (len(values), "\n".join(
            "(%.17g %.17g %.17g)" % v for v in values))
    else:
        body = "nonuniform List<scalar>\n%d\n(\n%s\n)" % (len(values), "\n".join(
            "%.17g" % v for v in values))
    txt = re.sub(r"internalField[^;]*;", lambda m: "internalField   " + body + ";", src, count=1)
    txt = re.sub(r"location\s+\"?[^;]*;", 'location    "%s";' % t, txt, count=1)
    txt = re.sub(r"object\s+\S+;", "object      %s;" % name, txt, count=1)
    os.makedirs(f"{case}/{t}", exist_ok=True)
    open(f"{case}/{t}/{name}", "w").write(txt)
def cells(d):
    """a scalar list from {(i, j): value}, 0 elsewhere"""
    v = [0.0]*(nx*ny)
    for (i, j), a in d.items():
        v[cell(i, j)] = a
    return v
def report(t):
    rep = {}
    for line in open(f"{case}/postProcessing/hazardMaps/{t}/report.dat"):
        if line.strip() and not line.startswith("#"):
            k, v = line.split()
            rep[k] = float(v)
    return rep
def close(a, b, rel=1e-9):
    return abs(a - b) <= rel*max(abs(b), 1e-300)
def vtpPoints(path):
    """points and point data of a .vtp (VTK XML binary, UInt32 headers)"""
    def array(e):
        raw = base64.b64decode("".join(e.text.split()))
        n = struct.unpack("<I", raw[:4])[0]
        t = {"Float32": "f", "Float64": "d"}[e.get("type")]
        vals = struct.unpack("<%d%s" % (n//struct.calcsize(t), t), raw[4:4 + n])
        k = int(e.get("NumberOfComponents", "1"))
        return [vals[i:i + k] for i in range(0, len(vals), k)] if k > 1 else list(vals)
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    return array(piece.find("Points/DataArray")), \
        {a.get("Name"): array(a) for a in piece.findall("PointData/DataArray")}
PYEOF

#- synth <case> <what> <python over synth.py's helpers, the case loaded;
#  sets ok and msg>: PASS or FAIL with msg (a python error is a FAIL)
synth()
{
    local msg
    if msg="$(cd "$work" && $python - "$1" "$3" 2>&1 <<'PYEOF'
import math, sys
from synth import *
load(sys.argv[1])
from synth import *   # (the names load set)
a35 = math.tan(math.radians(35))
ok, msg = False, "no result"
exec(sys.argv[2])
print(msg)
sys.exit(0 if ok else 1)
PYEOF
)"
    then
        pass "plan-mode maps, $2: $msg"
    else
        fail "plan-mode maps, $2: $msg"
    fi
}

#- hazPlanCase <name> <dem>: a plan case (writePlanDict's release) with
#  rho, through blockMesh; sets c
hazPlanCase()
{
    planCase "$1" "$2" || return 1
    sed -i 's/^phi /rho             1500;\nphi /' "$c/constant/transportProperties"
    (cd "$c" && runApplication blockMesh > /dev/null) && return 0
    fail "$1: blockMesh failed (see $c/log.blockMesh)"
    return 1
}

#- toolRefusal <case> <what> <regex the log must hold> <command>: the tool
#  exits non-zero (not by a signal) with the regex in its log and no file
#  written or changed
toolRefusal()
{
    local c="$1" what="$2" want="$3" before after rc problems=""
    before="$(snapshot "$c")"
    (cd "$c" && eval "$4" > log.refusal 2>&1)
    rc=$?
    after="$(snapshot "$c")"
    [ $rc -ne 0 ] || problems="$problems exit 0;"
    [ $rc -lt 128 ] || problems="$problems killed by signal $((rc - 128));"
    grep -q "$want" "$c/log.refusal" || problems="$problems no '$want' in the log;"
    [ "$before" = "$after" ] || problems="$problems files written;"
    if [ -z "$problems" ]
    then
        pass "refused, $what: $(grep -m1 -A1 'FOAM FATAL' "$c/log.refusal" | tail -n1 | cut -c1-150)"
    else
        fail "$what:$problems (see $c/log.refusal)"
    fi
}

# 9a. On the plane: the mass in cell (4, 4) at t = 0, (19, 4) and (21, 4)
# at t = 1 (their centre (20, 4)), (20, 20) at t = 2, (36, 20) at t = 3: a
# path of 3 x 16 cells of 5 m, s = 240 m, dropping 160 tan 35 (x from 4 to
# 36), so comTravelAngle = atan(2/3 tan 35).  hMax > 0.01 also at (30, 31):
# horizontally furthest from the release (4, 4), sqrt(130^2 + 135^2) m,
# though higher than (36, 20); (47, 31) further still has hMax 0.005, below
# the threshold.  So runout (1152.5, 5157.5, 2000 - 152.5 tan 35) and alpha
# = atan(130 tan 35 / sqrt(130^2 + 135^2)); nothing leaves: outflow 0.
if hazPlanCase haz-path constant/plane.asc
then
    if (cd "$work" && $python - "$c" <<'PYEOF'
import sys
from synth import *
load(sys.argv[1])
from synth import *   # (the names load set)
path = {0: {(4, 4): 2}, 1: {(19, 4): 1, (21, 4): 1}, 2: {(20, 20): 2}, 3: {(36, 20): 2}}
for t, d in path.items():
    write(str(t), "h", cells(d))
peak = {k: 2 for d in path.values() for k in d}
peak.update({(30, 31): 0.5, (47, 31): 0.005})
write("3", "hMax", cells(peak))
write("3", "UMax", cells({k: 1 for k in peak}))
write("3", "U", [(1.0, 0.0, 0.0)]*(nx*ny))
PYEOF
    ) && (cd "$c" && runApplication hazardMaps > /dev/null)
    then
        synth "$c" "centre of mass' path on the plane" '
r = report(3)
want = math.degrees(math.atan(2*a35/3))
ok = close(r["comPathLength"], 240) and close(r["comTravelAngle"], want)
msg = "comPathLength %.15g m (240), comTravelAngle %.15g deg (atan(2/3 tan35) = %.15g)" % (r["comPathLength"], r["comTravelAngle"], want)'
        synth "$c" "runout and travel angle on the plane" '
r = report(3)
want = [1152.5, 5157.5, 2000 - 152.5*a35]
alpha = math.degrees(math.atan(130*a35/math.hypot(130, 135)))
keys = ["releasedVolume", "depositVolume", "runoutX", "runoutY", "runoutZ", "travelAngle",
        "comTravelAngle", "outflowVolume", "comPathLength", "reachesBoundary"]
ok = sorted(r) == sorted(keys) \
    and all(close(r[k], w) for k, w in zip(["runoutX", "runoutY", "runoutZ"], want)) \
    and close(r["travelAngle"], alpha) and abs(r["outflowVolume"]) < 1e-9*r["releasedVolume"] \
    and close(r["releasedVolume"], 2*25/math.cos(math.radians(35))) \
    and close(r["depositVolume"], r["releasedVolume"])
msg = "keys %s; runout (%.15g %.15g %.15g), want %s; travelAngle %.15g deg (%.15g); released %.15g m^3 (50/cos35), outflow %.3g m^3" % (" ".join(r), r["runoutX"], r["runoutY"], r["runoutZ"], want, r["travelAngle"], alpha, r["releasedVolume"], r["outflowVolume"])'
        synth "$c" "rasters on the plan grid" '
out = case + "/postProcessing/hazardMaps/3/"
lines = open(out + "hMax.asc").read().split("\n")
head = dict(l.split() for l in lines[:6])
rows = [l.split() for l in lines[6:] if l.strip()]
px = lambda i, j: float(rows[ny - 1 - j][i])
import json, subprocess
info = json.loads(subprocess.run(["gdalinfo", "-json", out + "hMax.tif"], capture_output=True, text=True).stdout)
gt = [1000, 5, 0, 5160, 0, -5]
ok = (int(head["ncols"]), int(head["nrows"])) == (nx, ny) == (48, 32) \
    and float(head["xllcorner"]) == 1000 and float(head["yllcorner"]) == 5000 \
    and float(head["cellsize"]) == 5 and px(30, 31) == 0.5 and px(4, 4) == 2 \
    and px(47, 31) == -9999 and px(0, 0) == -9999 \
    and all(abs(a - b) < 1e-9 for a, b in zip(info["geoTransform"], gt)) \
    and info["size"] == [48, 32]
msg = "hMax.asc %sx%s cells of %s m from (%s, %s), cell (30, 31) %s, (4, 4) %s, (47, 31) below the threshold %s; hMax.tif geotransform %s" % (head["ncols"], head["nrows"], head["cellsize"], head["xllcorner"], head["yllcorner"], px(30, 31), px(4, 4), px(47, 31), info["geoTransform"])'
    else
        fail "plan-mode maps, the plane: writing the times or hazardMaps failed (see $c/log.hazardMaps)"
    fi

    # postProcessing/centreOfMass.dat instead of the time directories: an
    # L-shaped path to t = 2 (100 m along x, 50 m along y, a drop of 50 m),
    # its line at t = 5 after the report's time left out: s = 150 m,
    # comTravelAngle atan(1/3)
    rm -rf "$work/haz-comfile"
    cp -r "$c" "$work/haz-comfile"
    rm -rf "$work/haz-comfile/postProcessing"
    mkdir -p "$work/haz-comfile/postProcessing"
    printf '# time x y z\n0 10 10 1990\n1 110 10 1950\n2 110 60 1940\n5 300 300 0\n' \
        > "$work/haz-comfile/postProcessing/centreOfMass.dat"
    if (cd "$work/haz-comfile" && runApplication hazardMaps > /dev/null)
    then
        synth "$work/haz-comfile" "centre of mass' path from postProcessing/centreOfMass.dat" '
r = report(3)
want = math.degrees(math.atan(1/3))
ok = close(r["comPathLength"], 150) and close(r["comTravelAngle"], want) \
    and "centreOfMass.dat" in open(case + "/log.hazardMaps").read()
msg = "comPathLength %.15g m (150), comTravelAngle %.15g deg (atan(1/3) = %.15g)" % (r["comPathLength"], r["comTravelAngle"], want)'
    else
        fail "plan-mode maps, centreOfMass.dat: hazardMaps failed (see $work/haz-comfile/log.hazardMaps)"
    fi
    rm -rf "$work/haz-comfile/postProcessing"
    mkdir -p "$work/haz-comfile/postProcessing"
    printf '5 10 10 1990\n6 110 10 1950\n' > "$work/haz-comfile/postProcessing/centreOfMass.dat"
    toolRefusal "$work/haz-comfile" "hazardMaps, centreOfMass.dat starting after the report's time" \
        "centreOfMass.dat.* starts at time 5, after the chosen time 3" "hazardMaps"
    printf '0 10 10 1990\n1 110 10\n' > "$work/haz-comfile/postProcessing/centreOfMass.dat"
    toolRefusal "$work/haz-comfile" "hazardMaps, a line of centreOfMass.dat without z" \
        "centreOfMass.dat.* line 2: .*is not .time x y z." "hazardMaps"
    rm -rf "$work/haz-comfile/postProcessing" "$work/haz-comfile/2/h"
    toolRefusal "$work/haz-comfile" "hazardMaps, a time directory without h on the path" \
        "No field h in .*/2.: the centre of mass' path" "hazardMaps"
fi

# 9a'. A release below its runout: released at (36, 20) at t = 0, the
# mass at (4, 4), 32 cells (160 m) up the plane, at t = 1: hazardMaps
# warns with both points and the negative travel angle
if hazPlanCase haz-below constant/plane.asc
then
    if (cd "$work" && $python - "$c" <<'PYEOF'
import sys
from synth import *
load(sys.argv[1])
from synth import *   # (the names load set)
write("0", "h", cells({(36, 20): 2}))
write("1", "h", cells({(4, 4): 2}))
write("1", "hMax", cells({(36, 20): 2, (4, 4): 2}))
write("1", "UMax", cells({(36, 20): 1, (4, 4): 1}))
write("1", "U", [(1.0, 0.0, 0.0)]*(nx*ny))
PYEOF
    ) && (cd "$c" && runApplication hazardMaps > /dev/null) \
      && grep -q "the release is below its runout (travelAngle -" "$c/log.hazardMaps"
    then
        pass "plan-mode maps, a release below its runout: warned ($(grep -m1 -o 'lies [0-9.e+]* m above' "$c/log.hazardMaps"))"
    else
        fail "plan-mode maps, a release below its runout: no warning (see $c/log.hazardMaps)"
    fi
fi

# 9b. On the quadratic bed (J varies from cell to cell): the release of
# terrainToCase at t = 0; at t = 1 the cells of it with X > 1080 emptied
# (left the domain), the rest kept.  releasedVolume that of terrainMapping
# (1e-9: report.dat writes volumes to 10 significant digits),
# outflowVolume the sum of J h A over the emptied cells, depositVolume over
# the rest (J from 0/zb here); then avalancheSurface at t = 1: the bed at
# (X, Y, zb), the flow surface bed + h n, n = (-grad zb, 1)/J, the velocity
# (U_x, U_y, grad zb . U) to 1e-9
if hazPlanCase haz-quad constant/quad.asc
then
    if (cd "$work" && $python - "$c" <<'PYEOF'
import sys
from synth import *
load(sys.argv[1])
from synth import *   # (the names load set)
h0 = readField("0", "h")
h1 = [0.0 if XY(c)[0] > 1080 else h0[c] for c in range(nx*ny)]
write("1", "h", h1)
write("1", "hMax", h0)
write("1", "UMax", [1.0 if v > 0 else 0.0 for v in h0])
write("1", "U", [(0.3 + 0.001*c, -0.2, 0.0) if h1[c] > 0 else (0.0, 0.0, 0.0) for c in range(nx*ny)])
PYEOF
    ) && (cd "$c" && runApplication hazardMaps > /dev/null \
        && runApplication avalancheSurface -time 1 > /dev/null)
    then
        synth "$c" "outflowVolume on the quadratic bed" '
r = report(1)
h0, h1 = readField("0", "h"), readField("1", "h")
gone = sum(J(c)*h0[c]*cs*cs for c in range(nx*ny) if h0[c] > 0 and h1[c] == 0)
kept = sum(J(c)*h1[c]*cs*cs for c in range(nx*ny))
mapped = float(entry(open(case + "/constant/terrainMapping").read(), "releasedVolume"))
nGone = sum(1 for c in range(nx*ny) if h0[c] > 0 and h1[c] == 0)
Js = [J(c) for c in range(nx*ny) if h0[c] > 0]
ok = close(r["outflowVolume"], gone) and close(r["depositVolume"], kept) \
    and close(r["releasedVolume"], mapped) and nGone > 0 and gone > 0 \
    and max(Js) - min(Js) > 0.01
msg = "outflowVolume %.15g m^3 (%d emptied cells: %.15g), depositVolume %.15g (%.15g), releasedVolume %.15g (terrainMapping %.15g); J in [%.4f, %.4f]" % (r["outflowVolume"], nGone, gone, r["depositVolume"], kept, r["releasedVolume"], mapped, min(Js), max(Js))'
        synth "$c" "avalancheSurface on the quadratic bed" '
out = case + "/postProcessing/avalancheSurface/"
bed, data = vtpPoints(out + "bed_1.vtp")
top, _ = vtpPoints(out + "surface_1.vtp")
h1 = readField("1", "h")
U = [(0.3 + 0.001*c, -0.2) if h1[c] > 0 else (0.0, 0.0) for c in range(nx*ny)]
eb = et = eu = 0
for c in range(nx*ny):
    X, Y = XY(c)
    gx, gy = grad(c)
    j = J(c)
    n = (-gx/j, -gy/j, 1/j)
    eb = max(eb, max(abs(a - b) for a, b in zip(bed[c], (X, Y, zb[c]))))
    et = max(et, max(abs(top[c][k] - (bed[c][k] + h1[c]*n[k])) for k in range(3)))
    want = (U[c][0], U[c][1], gx*U[c][0] + gy*U[c][1])
    eu = max(eu, max(abs(data["U"][c][k] - want[k]) for k in range(3))/max(1, abs(want[0])))
nWet = sum(1 for v in h1 if v > 0)
ok = len(bed) == len(top) == nx*ny and eb < 1e-9 and et < 1e-9 and eu < 1e-6 and nWet > 0
msg = "%d points (%d wet): max |bed - (X, Y, zb)| %.3g m, max |surface - (bed + h n)| %.3g m, max |U - (Ux, Uy, grad zb.U)| %.3g (Float32 data)" % (len(bed), nWet, eb, et, eu)'
        # -statistics: an ensemble's field (here hMax of t = 1 as
        # hMaxMean) as a raster on the plan grid, every cell its pixel
        mkdir -p "$c/ensemble/statistics/1"
        sed 's/^\( *object *\)hMax;/\1hMaxMean;/' "$c/1/hMax" > "$c/ensemble/statistics/1/hMaxMean"
        if (cd "$c" && runApplication -s statistics hazardMaps -statistics > /dev/null)
        then
            synth "$c" "hazardMaps -statistics on the plan grid" '
lines = open(case + "/postProcessing/hazardMaps/ensemble/1/hMaxMean.asc").read().split("\n")
rows = [l.split() for l in lines[6:] if l.strip()]
f = readField("1", "hMax")
e = max(abs(float(rows[ny - 1 - c // nx][c % nx]) - f[c]) for c in range(nx*ny))
ok = len(rows) == ny and all(len(r) == nx for r in rows) and e < 1e-9 and max(f) > 0
msg = "hMaxMean.asc %d x %d, max |pixel - cell| %.3g" % (len(rows[0]), len(rows), e)'
        else
            fail "plan-mode maps, hazardMaps -statistics failed (see $c/log.hazardMaps.statistics)"
        fi
    else
        fail "plan-mode maps, the quadratic bed: writing the times, hazardMaps or avalancheSurface failed (see $c/log.*)"
    fi

    # Refused, nothing written: a mapping mode neither plan nor axis; a
    # plan mapping with transportProperties not in plan coordinates
    cp "$c/constant/terrainMapping" "$c/constant/terrainMapping.good"
    sed -i 's/^mode .*/mode            polar;/' "$c/constant/terrainMapping"
    toolRefusal "$c" "hazardMaps, terrainMapping of mode polar" \
        "keyword 'mode' = polar" "hazardMaps"
    grep -q "terrainMapping" "$c/log.refusal" \
        || fail "hazardMaps, mode polar: terrainMapping not named"
    toolRefusal "$c" "avalancheSurface, terrainMapping of mode polar" \
        "keyword 'mode' = polar" "avalancheSurface"
    grep -q "terrainMapping" "$c/log.refusal" \
        || fail "avalancheSurface, mode polar: terrainMapping not named"
    cp "$c/constant/terrainMapping.good" "$c/constant/terrainMapping"
    sed -i '/^coordinates/d' "$c/constant/transportProperties"
    toolRefusal "$c" "hazardMaps, a plan mapping without coordinates plan" \
        "keyword 'coordinates'" "hazardMaps"
    grep -q "transportProperties" "$c/log.refusal" \
        || fail "hazardMaps, no coordinates plan: transportProperties not named"
    toolRefusal "$c" "avalancheSurface, a plan mapping without coordinates plan" \
        "keyword 'coordinates'" "avalancheSurface"
    grep -q "transportProperties" "$c/log.refusal" \
        || fail "avalancheSurface, no coordinates plan: transportProperties not named"
fi

# 9c. The plane on the grid rotated by 30 deg: hazardMaps writes .tif alone
# with the plan grid's rotated geotransform; avalancheSurface's flow
# surface lies h (sin 35, 0, cos 35) above the bed, the bed on the plane
if hazPlanCase haz-rotated constant/rplane.tif
then
    if (cd "$work" && $python - "$c" <<'PYEOF'
import sys
from synth import *
load(sys.argv[1])
from synth import *   # (the names load set)
write("1", "h", [1.0]*(nx*ny))
write("1", "hMax", [1.0]*(nx*ny))
write("1", "UMax", [1.0]*(nx*ny))
write("1", "U", [(0.0, 0.0, 0.0)]*(nx*ny))
PYEOF
    ) && (cd "$c" && runApplication hazardMaps > /dev/null \
        && runApplication avalancheSurface -time 1 > /dev/null)
    then
        synth "$c" "rotated grid: the rasters" '
import glob, json, subprocess
out = case + "/postProcessing/hazardMaps/1/"
info = json.loads(subprocess.run(["gdalinfo", "-json", out + "hMax.tif"], capture_output=True, text=True).stdout)
gt = [origin[0] + ny*cs*yAxis[0], cs*xAxis[0], -cs*yAxis[0], origin[1] + ny*cs*yAxis[1], cs*xAxis[1], -cs*yAxis[1]]
ok = not glob.glob(out + "*.asc") and info["size"] == [nx, ny] \
    and all(abs(a - b) < 1e-9 for a, b in zip(info["geoTransform"], gt)) \
    and abs(xAxis[1] - 0.5) < 1e-12
msg = ".tif alone, geotransform %s (origin + ny cs yAxis, cs xAxis, -cs yAxis: %s)" % (info["geoTransform"], gt)'
        synth "$c" "rotated grid: avalancheSurface" '
out = case + "/postProcessing/avalancheSurface/"
bed, _ = vtpPoints(out + "bed_1.vtp")
top, _ = vtpPoints(out + "surface_1.vtp")
s, k = math.sin(math.radians(35)), math.cos(math.radians(35))
ez = max(abs(p[2] - (2000 - a35*(p[0] - 1000))) for p in bed)
en = max(max(abs(t[i] - b[i] - (s, 0, k)[i]) for i in range(3)) for b, t in zip(bed, top))
ok = len(bed) == nx*ny and ez < 1e-9 and en < 1e-9
msg = "%d points: max |bed Z - plane| %.3g m, max |surface - bed - (sin35, 0, cos35)| %.3g m" % (len(bed), ez, en)'
    else
        fail "plan-mode maps, the rotated grid: hazardMaps or avalancheSurface failed (see $c/log.*)"
    fi
fi

finish

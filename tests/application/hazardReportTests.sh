#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     hazardMaps' report and maps, the ensemble's report against it, and
#     bin/plotHazardMaps, on the terrainChute tutorial's DEM (makeTerrain)
#     with 40 m cells:
#     (a) without rho and without the field pMax every other map is written
#         (hMax, UMax, deposit, tArrival) and pMax is skipped, the log
#         saying why (no rho, no field pMax), exit status 0;
#     (b) the deposit is masked by itself: every deposit pixel holds h >
#         threshold (no 1e-198 along the track) and the deposit covers
#         fewer pixels than hMax;
#     (c) report.dat: every key line "key value" (two fields) preceded by
#         its comment line "# key [unit] ...", with outflowVolume and
#         reachesBoundary; reachesBoundary 0 on the full chute (the flow
#         stops on the fan) and 1 on the chute cut at 700 m along the axis;
#         volumes to at most 10 significant digits, outflowVolume exactly
#         0 on the full chute (the sums' round-off clamped), the log's
#         released volume the report's;
#     (d) savageHutterFoam -ensemble (delta 19 and 24) on the full chute:
#         ensemble/report.dat's runoutX, runoutY, runoutZ, travelAngle and
#         reachesBoundary of each member equal (1e-6 m, 1e-6 deg)
#         hazardMaps -case ensemble/member<k> at the same time, and the
#         report's header names its definition and coordinates; the same
#         in plan coordinates (terrainToCase without an axis, delta 20 and
#         26, endTime 4) on a DEM whose corner lies at (100000, 200000), so
#         that the world's coordinates are not the mesh's;
#     (e) plotHazardMaps writes its PNG (a PNG signature, > 20 kB) on the
#         axis case, and refuses (non-zero, no PNG) a case without
#         hazardMaps output.
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     hazardReportTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
python=/usr/bin/python3
start=$SECONDS
tutorial="$project/tutorials/terrainChute"

# A case of the terrainChute tutorial on 40 m cells, the axis ending at $2
makeCase()
{
    local c="$1" end="$2"
    mkdir -p "$c"
    cp -r "$tutorial"/{system,constant,makeTerrain} "$c"/
    (
        cd "$c" || exit 1
        setEntry system/terrainDict cellSize 40
        setEntry system/terrainDict axis "((0 0) ($end 0))"
        setEntry system/controlDict endTime 80
        setEntry system/controlDict writeInterval 40
        ./makeTerrain > log.makeTerrain 2>&1 \
            && terrainToCase > log.terrainToCase 2>&1 \
            && blockMesh > log.blockMesh 2>&1
    )
}

# (a)-(c) on the full chute, without rho
full="$work/full"
if makeCase "$full" 1950 \
    && (cd "$full" && savageHutterFoam > log.savageHutterFoam 2>&1)
then
    last="$(timeDirs "$full" | tail -n 1)"
    sed -i 's/^rho .*//' "$full/constant/transportProperties"
    rm -f "$full/$last/pMax"
    if (cd "$full" && hazardMaps > log.hazardMaps 2>&1)
    then
        out="$full/postProcessing/hazardMaps/$last"
        missing=""
        for f in hMax UMax deposit tArrival
        do
            [ -f "$out/$f.asc" ] && [ -f "$out/$f.tif" ] || missing="$missing $f"
        done
        if [ -z "$missing" ] && [ ! -e "$out/pMax.asc" ] \
            && grep -q "pMax skipped: no rho in constant/transportProperties and no field pMax" \
                "$full/log.hazardMaps"
        then
            pass "(a) without rho and pMax: hMax, UMax, deposit, tArrival written, pMax skipped: $(grep -o 'pMax skipped.*' "$full/log.hazardMaps")"
        else
            fail "(a) without rho: missing:$missing; pMax.asc there: $([ -e "$out/pMax.asc" ] && echo yes || echo no); log: $(grep skipped "$full/log.hazardMaps")"
        fi
        if grep -q "^Time $last (release from time 0)" "$full/log.hazardMaps"
        then
            pass "(a) the log names the time readably: $(grep '(release from time' "$full/log.hazardMaps")"
        else
            fail "(a) the log's time line: $(grep '(release from time' "$full/log.hazardMaps")"
        fi
        checks="$($python - "$out" <<'PYEOF'
import sys
import numpy as np
out = sys.argv[1]
def asc(name):
    with open(f"{out}/{name}.asc") as f:
        head = dict(f.readline().split() for _ in range(6))
        z = np.loadtxt(f)
    return z, float(head["NODATA_value"])
dep, nd = asc("deposit")
hmax, _ = asc("hMax")
d = dep[dep != nd]
nD, nH = d.size, int(np.sum(hmax != nd))
ok = nD > 0 and d.min() > 0.01 and nD < nH
print(("PASS  " if ok else "FAIL  ") + "(b) deposit masked by itself: %d pixels, "
      "min %.3g m (> threshold 0.01 m), hMax covers %d" % (nD, d.min() if nD else float("nan"), nH))
lines = [l.rstrip("\n") for l in open(f"{out}/report.dat")]
rep, bad = {}, []
for k, l in enumerate(lines):
    if l.startswith("#") or not l.strip():
        continue
    f = l.split()
    if len(f) != 2:
        bad.append(l)
        continue
    rep[f[0]] = float(f[1])
    if not (k > 0 and lines[k - 1].startswith(f"# {f[0]} [")):
        bad.append(l + " (no '# key [unit]' line above)")
keys = ["releasedVolume", "depositVolume", "runoutX", "runoutY", "runoutZ",
        "travelAngle", "comTravelAngle", "outflowVolume", "reachesBoundary"]
ok = not bad and all(k in rep for k in keys) and rep["reachesBoundary"] == 0
print(("PASS  " if ok else "FAIL  ") + "(c) report.dat: %d keys each with its unit line, "
      "reachesBoundary %s on the full chute (runoutX %.1f m), outflowVolume %.3g m^3%s"
      % (len(rep), rep.get("reachesBoundary"), rep.get("runoutX", float("nan")),
         rep.get("outflowVolume", float("nan")), "; bad: %s" % bad if bad else ""))
# the volumes to 10 significant digits, an outflow of round-off written as 0
# (nothing leaves the full chute), the log's released volume the report's
raw = {l.split()[0]: l.split()[1] for l in lines if l.strip() and not l.startswith("#")}
def digits(v):
    return len(v.lower().split("e")[0].replace("-", "").replace(".", "").lstrip("0"))
vols = ["releasedVolume", "depositVolume", "outflowVolume"]
log = open(f"{out}/../../../log.hazardMaps").read()
logged = [l for l in log.splitlines() if "Released volume" in l]
ok = (all(k in raw and digits(raw[k]) <= 10 for k in vols) and raw.get("outflowVolume") == "0"
      and any(("Released volume %s m^3" % raw.get("releasedVolume")) in l for l in logged))
print(("PASS  " if ok else "FAIL  ") + "(c) volumes to at most 10 significant digits (%s), "
      "outflowVolume '%s' (round-off clamped to 0), the log: %s"
      % (", ".join("%s %s" % (k, raw.get(k)) for k in vols), raw.get("outflowVolume"),
         logged[0].strip() if logged else "no 'Released volume' line"))
PYEOF
)"
        tally $? "$checks" "(b), (c)"
    else
        fail "(a) hazardMaps without rho failed: $(grep -A3 'FATAL' "$full/log.hazardMaps" | head -n 4)"
    fi
else
    fail "(a)-(c): the 40 m chute did not run (see $full)"
fi

# (c) the chute cut at 700 m: the flow reaches the mesh's end
cut="$work/cut"
if makeCase "$cut" 700 \
    && (cd "$cut" && savageHutterFoam > log.savageHutterFoam 2>&1 \
        && hazardMaps > log.hazardMaps 2>&1)
then
    last="$(timeDirs "$cut" | tail -n 1)"
    r="$cut/postProcessing/hazardMaps/$last/report.dat"
    flag="$(awk '$1 == "reachesBoundary" {print $2}' "$r")"
    if [ "$flag" = 1 ] && grep -q "reaches the domain's boundary" "$cut/log.hazardMaps"
    then
        pass "(c) the chute cut at 700 m: reachesBoundary 1 (runoutX $(awk '$1 == "runoutX" {print $2}' "$r") m), the log warns"
    else
        fail "(c) the chute cut at 700 m: reachesBoundary '$flag' (see $r)"
    fi
else
    fail "(c) the chute cut at 700 m did not run (see $cut)"
fi

# (d) the ensemble's report = hazardMaps on each member

#- compareEnsemble <case> <what> <min distance> <plan 0/1>: each member's row
#  of ensemble/report.dat against hazardMaps -case ensemble/member<k>, the
#  runout's distance (from the world's origin in plan, else runoutX) above
#  the minimum, and the report's header naming its definition
compareEnsemble()
{
    local ens="$1" what="$2" minRun="$3" plan="$4" m checks
    for m in 0 1
    do
        (cd "$ens" && hazardMaps -case "ensemble/member000$m" \
            > "log.hazardMaps.$m" 2>&1) \
            || fail "(d) $what: hazardMaps -case ensemble/member000$m failed (see $ens/log.hazardMaps.$m)"
    done
    checks="$($python - "$ens" "$what" "$minRun" "$plan" <<'PYEOF'
import math, os, sys
ens, what, minRun, plan = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4] == "1"
rows, head = [], []
for line in open(f"{ens}/ensemble/report.dat"):
    if line.startswith("# member"):
        header = line[2:].split()
    elif line.startswith("#"):
        head.append(line.strip())
    elif line.strip():
        rows.append(dict(zip(header, line.split())))
text = " ".join(head)
if plan:
    ok = ("horizontally furthest" in text and "world (the plan grid" in text
          and "unfolded inclination" not in text)
else:
    ok = "furthest along the slope" in text and "world (constant/terrainMapping)" in text
print(("PASS  " if ok else "FAIL  ") + "(d) %s: the header names the definition and the "
      "coordinates: %s" % (what, " | ".join(head[1:3])))
for r in rows:
    m = int(r["member"])
    out = f"{ens}/ensemble/member{m:04d}/postProcessing/hazardMaps"
    t = max(os.listdir(out), key=float)
    rep, raw = {}, {}
    for line in open(f"{out}/{t}/report.dat"):
        if line.strip() and not line.startswith("#"):
            k, v = line.split()
            rep[k], raw[k] = float(v), v
    if plan:
        # the plan report's volumes to 10 digits (not 15), no outflow yet
        mant = raw.get("releasedVolume", "").lower().split("e")[0].replace(".", "").lstrip("0")
        ok = 0 < len(mant) <= 10 and raw.get("outflowVolume") == "0"
        print(("PASS  " if ok else "FAIL  ") + "(d) %s, member %d: hazardMaps' plan report: "
              "releasedVolume %s, outflowVolume %s (10 digits, round-off clamped)"
              % (what, m, raw.get("releasedVolume"), raw.get("outflowVolume")))
    diffs = {k: abs(float(r.get(k, "nan")) - rep.get(k, float("nan"))) for k in
             ["runoutX", "runoutY", "runoutZ", "travelAngle", "reachesBoundary"]}
    far = (math.hypot(rep.get("runoutX", 0), rep.get("runoutY", 0)) if plan
           else rep.get("runoutX", 0))
    ok = all(d <= 1e-6 for d in diffs.values()) and far > minRun
    print(("PASS  " if ok else "FAIL  ") + "(d) %s, member %d (delta %s): ensemble runout "
          "(%s, %s, %s), travel angle %s deg; hazardMaps at t = %s (%.15g, %.15g, %.15g), "
          "%.15g deg; largest difference %s" % (what, m, r["CoulombCoeffs/delta"],
          r["runoutX"], r["runoutY"], r.get("runoutZ"), r["travelAngle"], t,
          rep.get("runoutX", math.nan), rep.get("runoutY", math.nan),
          rep.get("runoutZ", math.nan), rep.get("travelAngle", math.nan),
          max(diffs.values())))
if len(rows) != 2:
    print("FAIL  (d) %s: %d members in ensemble/report.dat, not 2" % (what, len(rows)))
PYEOF
)"
    tally $? "$checks" "(d) $what"
}

#- ensembleDict <case> <deltas>
ensembleDict()
{
    cat > "$1/system/ensembleDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object ensembleDict; }
parameters { "CoulombCoeffs/delta" ($2); }
combine         product;
thresholds      (0.1);
percentiles     (50);
runoutThreshold 0.01;
EOF
}

ens="$work/ensemble"
if makeCase "$ens" 1950
then
    ensembleDict "$ens" "19 24"
    if (cd "$ens" && savageHutterFoam -ensemble > log.ensemble 2>&1)
    then
        compareEnsemble "$ens" "axis" 500 0
    else
        fail "(d) savageHutterFoam -ensemble failed (see $ens/log.ensemble)"
    fi
else
    fail "(d) the ensemble case could not be made (see $ens)"
fi

# (d) in plan coordinates: terrainToCase without an axis, on a DEM whose
# corner lies at (100000, 200000), so that the world's coordinates are not
# the mesh's: a 35 deg slope whose descent is turned by 30 deg from the
# columns, rounded into a floor (2 m pixels, 4 m cells, 42 x 30 cells)
plan="$work/planEnsemble"
planSlopeCase "$plan" 100000 200000 0
ensembleDict "$plan" "20 26"
if (cd "$plan" && terrainToCase > log.terrainToCase 2>&1 \
        && blockMesh > log.blockMesh 2>&1 \
        && setEntry system/controlDict endTime 4 \
        && setEntry system/controlDict writeInterval 2)
then
    if (cd "$plan" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
    then
        compareEnsemble "$plan" "plan, DEM corner (100000, 200000)" 100000 1
    else
        fail "(d) plan: savageHutterFoam -ensemble failed (see $plan/log.ensemble)"
    fi
else
    fail "(d) plan: the case could not be made (see $plan/log.*)"
fi

# (e) plotHazardMaps
if [ -d "$full/postProcessing/hazardMaps" ]
then
    png="$work/full.png"
    if "$python" "$project/bin/plotHazardMaps" -case "$full" -o "$png" \
        > "$work/log.plot" 2>&1 \
        && [ "$(head -c 8 "$png" | od -An -c | tr -d ' ')" = '211PNG\r\n032\n' ] \
        && [ "$(stat -c %s "$png")" -gt 20000 ]
    then
        pass "(e) plotHazardMaps wrote $png ($(stat -c %s "$png") bytes; the missing pMax a panel saying so)"
    else
        fail "(e) plotHazardMaps on the chute: $(tail -n 3 "$work/log.plot")"
    fi
fi
mkdir -p "$work/empty/constant"
if "$python" "$project/bin/plotHazardMaps" -case "$work/empty" -o "$work/empty.png" \
    > "$work/log.plotEmpty" 2>&1 || [ -e "$work/empty.png" ]
then
    fail "(e) plotHazardMaps on a case without hazardMaps output did not refuse"
else
    pass "(e) plotHazardMaps refuses a case without hazardMaps output: $(head -n 1 "$work/log.plotEmpty")"
fi
echo "($((SECONDS - start)) s)"

finish

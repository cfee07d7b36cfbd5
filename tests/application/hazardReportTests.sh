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
#     (d) savageHutterFoam -ensemble (delta 19 and 24) on the full chute:
#         ensemble/report.dat's runoutX, runoutY, runoutZ, travelAngle and
#         reachesBoundary of each member equal (1e-6 m, 1e-6 deg)
#         hazardMaps -case ensemble/member<k> at the same time;
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
ens="$work/ensemble"
if makeCase "$ens" 1950
then
    cat > "$ens/system/ensembleDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object ensembleDict; }
parameters { "CoulombCoeffs/delta" (19 24); }
combine         product;
thresholds      (0.1);
percentiles     (50);
runoutThreshold 0.01;
EOF
    if (cd "$ens" && savageHutterFoam -ensemble > log.ensemble 2>&1)
    then
        for m in 0 1
        do
            (cd "$ens" && hazardMaps -case "ensemble/member000$m" \
                > "log.hazardMaps.$m" 2>&1) \
                || fail "(d) hazardMaps -case ensemble/member000$m failed (see $ens/log.hazardMaps.$m)"
        done
        checks="$($python - "$ens" <<'PYEOF'
import os, sys
ens = sys.argv[1]
rows = []
for line in open(f"{ens}/ensemble/report.dat"):
    if line.startswith("# member"):
        header = line[2:].split()
    elif not line.startswith("#") and line.strip():
        rows.append(dict(zip(header, line.split())))
for r in rows:
    m = int(r["member"])
    out = f"{ens}/ensemble/member{m:04d}/postProcessing/hazardMaps"
    t = max(os.listdir(out), key=float)
    rep = {}
    for line in open(f"{out}/{t}/report.dat"):
        if line.strip() and not line.startswith("#"):
            k, v = line.split()
            rep[k] = float(v)
    diffs = {k: abs(float(r.get(k, "nan")) - rep.get(k, float("nan"))) for k in
             ["runoutX", "runoutY", "runoutZ", "travelAngle", "reachesBoundary"]}
    ok = all(d <= 1e-6 for d in diffs.values()) and rep.get("runoutX", 0) > 500
    print(("PASS  " if ok else "FAIL  ") + "(d) member %d (delta %s): ensemble runout (%s, %s, %s), "
          "travel angle %s deg; hazardMaps at t = %s (%.10g, %.10g, %.10g), %.10g deg; "
          "largest difference %s" % (m, r["CoulombCoeffs/delta"], r["runoutX"], r["runoutY"],
          r.get("runoutZ"), r["travelAngle"], t, rep["runoutX"], rep["runoutY"], rep["runoutZ"],
          rep["travelAngle"], max(diffs.values())))
if len(rows) != 2:
    print("FAIL  (d) %d members in ensemble/report.dat, not 2" % len(rows))
PYEOF
)"
        tally $? "$checks" "(d)"
    else
        fail "(d) savageHutterFoam -ensemble failed (see $ens/log.ensemble)"
    fi
else
    fail "(d) the ensemble case could not be made (see $ens)"
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

#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     savageHutterFoam -ensemble on a small copy of the ensemble tutorial
#     (the inclined plane of section 5.3 on 60 x 28 cells, t = 2):
#       - member exactness: two members picked at random (the seed is
#         printed) run as single cases with their parameters (delta in
#         transportProperties, their release as 0/h, hScale applied by
#         the test with exact factors 0.5 and 2): h, hU, hMax, UMax,
#         tArrival byte for byte the ensemble's ensemble/member<k>/<time>/;
#       - the statistics against the members counted by hand (a python
#         check reading every member's hMax and UMax): hMaxExceedance_<thr>
#         equals the count of members above thr over their number, the
#         mean and the percentiles (linear between order statistics, the
#         same formula) exactly;
#       - a restart: the ensemble run to t = 1, then on to t = 2 with
#         startFrom latestTime, byte for byte the run straight to 2
#         (members and statistics); an ensemble/ of other or more members
#         refused under latestTime and kept, replaced by startFrom
#         startTime;
#       - the members' order in a product (the last parameter fastest, two
#         coefficients of one law with another between them), and a
#         Voellmy member byte for byte its single run;
#       - samples: the same seed draws the same members, another seed
#         others; parameters files hold what was drawn, within the ranges;
#       - the bed's cover (docs/design.md section 7): on the plane with an
#         erodible layer and a resistance patch (setAvalancheFields) and
#         entrainmentModel constantRate, an ensemble of the rate (the
#         keyword path constantRateCoeffs/rate) x cResistanceScale: every
#         member's h, hU, hMax, UMax, tArrival, hEntrainable, erodedDepth
#         and cResistance at t = 1 and 2 byte for byte its single run
#         (its rate in transportProperties, 0/cResistance scaled by the
#         test with the exact factors 0.5 and 2); report.dat's
#         entrainedVolume of each member the sum of its erodedDepth dA
#         and, in this closed box, releasedVolume + entrainedVolume =
#         volume; the members differ where their parameters do; a
#         restart of it at t = 1 byte for byte the run straight to 2; in
#         plan coordinates (an erodible bed on planSlopeCase, two rates)
#         each member byte for byte its single run (h, U, H, hU,
#         hEntrainable, erodedDepth, HEntrainable, HErodedDepth at t = 1
#         and 2) and the restart exact, HEntrainable and HErodedDepth too;
#       - foamToVTK -case ensemble/statistics and -case ensemble/member<k>
#         (they are cases by links to constant/ and system/);
#       - a terrain ensemble (terrainChute on 40 m cells): hazardMaps
#         -statistics writes every statistic as .asc and .tif, each pixel
#         a value of its field;
#       - the log: every progress line counts to endTime, the last at
#         100 % ending with "end", then "End of run at t = 2 s: endTime
#         (every member)";
#       - bad ensembleDicts: each exits non-zero with a FOAM FATAL message
#         naming the problem, no stack trace, and writes nothing (no
#         ensemble/).
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     ensembleTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"

base="$work/base"
mkdir "$base"
cp -r "$project"/tutorials/ensemble/{0.orig,constant,system} "$base"/
(
    cd "$base" || exit 1
    setBlockCells 60 28
    setEntry system/controlDict endTime 2
    setEntry system/controlDict writeInterval 1
    runApplication blockMesh
    restore0Dir
    runApplication postProcess -func writeCellCentres -time 0
    runApplication -s small setAvalancheFields -dict system/setAvalancheFieldsDict.small
    cp 0/h 0/h.small
    runApplication setAvalancheFields
    cp 0/h 0/h.large
) > "$work/base.log" 2>&1 || { cat "$work/base.log"; fail "setting up the base case (its log above)"; finish; exit 1; }

#- newCase <name> [<from>]: a copy of the base case (or of the case
#  <from>) as $work/<name>
newCase()
{
    rm -rf "$work/$1"
    cp -r "${2:-$base}" "$work/$1"
    rm -f "$work/$1"/log.*
    echo "$work/$1"
}

#- differing <dir> <dir> [<fields>]: the fields (default h hU hMax UMax
#  tArrival) of a single run's time directory that are missing from the
#  first or differ from the second's ("" if none)
differing()
{
    local f bad=""
    for f in ${3:-h hU hMax UMax tArrival}
    do
        [ -f "$1/$f" ] && same "$1/$f" "$2/$f" || bad="$bad $f"
    done
    echo "$bad"
}

#- likeSingle <single run> <member dir> <fields> <what>: pass when the
#  member's fields at t = 1 and 2 are byte for byte the single run's
likeSingle()
{
    local bad
    bad="$(differing "$1/1" "$2/1" "$3")$(differing "$1/2" "$2/2" "$3")"
    if [ -z "$bad" ]
    then
        pass "$4: $3 at t = 1 and 2 byte for byte its single run"
    else
        fail "$4: differs from its single run in:$bad"
    fi
}

ensembleDict()
{
    cat > "$1/system/ensembleDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object ensembleDict; }
$2
DICT
}

#- The field files of a time directory from internalField on (the header
#  names the directory)
same()
{
    cmp -s <(sed -n '/^internalField/,$p' "$1") <(sed -n '/^internalField/,$p' "$2")
}

# The ensemble: delta x release x hScale, 12 members
product='parameters
{
    "CoulombCoeffs/delta" (22 26 30);
    release (h.large h.small);
    hScale (0.5 2);
}
combine product;
thresholds (0.01 0.2);
percentiles (0 25 50 90 100);'
main="$(newCase main)"
ensembleDict "$main" "$product"
(cd "$main" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
rc=$?
if [ $rc -eq 0 ] && [ -f "$main/ensemble/member0011/2/hMax" ] \
    && [ -f "$main/ensemble/statistics/2/hMaxExceedance_0.2" ] \
    && [ -f "$main/ensemble/report.dat" ]
then
    pass "-ensemble: 12 members (3 delta x 2 releases x 2 hScale) written at t = 0, 1, 2, statistics and report.dat"
else
    tail -n 20 "$main/log.ensemble"
    fail "-ensemble run (exit $rc; log above)"
fi

# The log: every progress line counts to endTime ("Time = t (slowest
# member, N% of endTime 2), next write w, steps per member a .. b  ETA
# h:mm:ss"), the last one at t = 2, 100 %, ending with "end" as a single
# run's, then "End of run at t = 2 s: endTime ..."
progress='^Time = [0-9.e+-]+ \(slowest member, [0-9]+% of endTime 2\), next write [0-9.e+-]+, steps per member [0-9]+ \.\. [0-9]+  (ETA [0-9:]+|end)$'
nProgress="$(grep -c '^Time = ' "$main/log.ensemble")"
nGood="$(grep -cE "$progress" "$main/log.ensemble")"
lastProgress="$(grep '^Time = ' "$main/log.ensemble" | tail -n 1)"
nEnd="$(grep -c '  end$' "$main/log.ensemble")"
endLine="$(grep '^End of run' "$main/log.ensemble")"
if [ "$nProgress" -gt 1 ] && [ "$nGood" = "$nProgress" ] \
    && [[ "$lastProgress" == "Time = 2 (slowest member, 100% of endTime 2), next write 2,"*"  end" ]] \
    && [ "$nEnd" = 1 ] \
    && [ "$endLine" = "End of run at t = 2 s: endTime (every member)" ] \
    && [ "$(grep -n '^End of run' "$main/log.ensemble" | cut -d: -f1)" -gt \
         "$(grep -n '  end$' "$main/log.ensemble" | cut -d: -f1)" ]
then
    pass "-ensemble log: $nProgress progress lines to endTime, the last '$lastProgress', then '$endLine'"
else
    fail "-ensemble log: $nGood of $nProgress progress lines in the format, $nEnd ending with 'end', last '$lastProgress', final line '$endLine'"
fi

# The statistics and a member open as cases (links to constant/, system/)
if command -v foamToVTK > /dev/null
then
    (cd "$main" && foamToVTK -case ensemble/statistics > log.foamToVTK.statistics 2>&1 \
        && foamToVTK -case ensemble/member0003 -latestTime > log.foamToVTK.member 2>&1)
    if [ $? -eq 0 ] \
        && grep -q "volScalar.*hMaxExceedance_0.2.*hMaxMean" "$main/log.foamToVTK.statistics" \
        && [ -f "$main/ensemble/statistics/VTK/statistics.vtm.series" ] \
        && grep -q "volScalar.*hMax" "$main/log.foamToVTK.member"
    then
        pass "foamToVTK -case ensemble/statistics (3 times, the statistics' fields) and -case ensemble/member0003"
    else
        fail "foamToVTK on ensemble/statistics or a member failed (logs in $main)"
    fi
else
    skip "foamToVTK on the ensemble: no foamToVTK here"
fi

# Member exactness: single runs of two members picked at random
seed="${SH_TEST_SEED:-$((RANDOM % 1000))}"
echo "members picked with seed $seed"
RANDOM=$seed
first=$((RANDOM % 12))
picks="$first $(( (first + 1 + RANDOM % 11) % 12 ))"
for k in $picks
do
    m="$(printf 'member%04d' "$k")"
    par="$main/ensemble/$m/parameters"
    delta="$(foamDictionary "$par" -entry CoulombCoeffs/delta -value)"
    release="$(foamDictionary "$par" -entry release -value)"
    scale="$(foamDictionary "$par" -entry hScale -value)"
    one="$(newCase "single$k")"
    (
        cd "$one" || exit 1
        rm -f system/ensembleDict
        setEntry constant/transportProperties CoulombCoeffs/delta "$delta"
        # 0/h: the release scaled (x 0.5 and x 2 are exact in binary)
        python3 - "$release" "$scale" <<'PY'
import re, sys, struct
rel, s = sys.argv[1], float(sys.argv[2])
data = open("0/" + rel, "rb").read()
m = re.search(rb"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", data)
n = int(m.group(1))
vals = struct.unpack_from("<%dd" % n, data, m.end())
body = struct.pack("<%dd" % n, *[v * s for v in vals])
open("0/h", "wb").write(data[:m.end()] + body + data[m.end() + 8 * n:])
PY
        savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1
    )
    bad="$(differing "$one/2" "$main/ensemble/$m/2")"
    if [ -z "$bad" ]
    then
        pass "member $k (delta $delta, $release, hScale $scale): h hU hMax UMax tArrival at t = 2 byte for byte its single run"
    else
        fail "member $k (delta $delta, $release, hScale $scale): differs from its single run in:$bad"
    fi
done

# The statistics counted by hand
out="$(/usr/bin/python3 - "$main" <<'PY'
import math, os, sys
sys.path.insert(0, os.path.join(os.environ["SAVAGEHUTTER_DIR"], "tutorials", "tools"))
import foamCase
import numpy as np
case = sys.argv[1]
g = foamCase.Grid(case)
ens = os.path.join(case, "ensemble")
members = sorted(d for d in os.listdir(ens) if d.startswith("member"))
n = len(members)
stats = os.path.join(ens, "statistics")
for t in ("1", "2"):
    h = np.array([foamCase.read_field(os.path.join(ens, m), t, "hMax", g.n) for m in members])
    u = np.array([foamCase.read_field(os.path.join(ens, m), t, "UMax", g.n) for m in members])
    bad = []
    for thr in (0.01, 0.2):
        want = np.array([sum(1 for k in range(n) if h[k, c] > thr) / n for c in range(g.n)])
        got = foamCase.read_field(stats, t, "hMaxExceedance_%g" % thr, g.n)
        if not np.array_equal(want, got):
            bad.append("hMaxExceedance_%g" % thr)
    for name, v in (("hMax", h), ("UMax", u)):
        # summed in member order, as the solver sums
        mean = np.array([0.0] * g.n)
        for c in range(g.n):
            s = 0.0
            for k in range(n):
                s += float(v[k, c])
            mean[c] = s / n
        if not np.array_equal(mean, foamCase.read_field(stats, t, name + "Mean", g.n)):
            bad.append(name + "Mean")
        for p in (0, 25, 50, 90, 100):
            want = np.zeros(g.n)
            for c in range(g.n):
                s = sorted(float(v[k, c]) for k in range(n))
                r = p / 100 * (n - 1)
                lo = min(int(math.floor(r)), n - 1)
                hi = min(lo + 1, n - 1)
                want[c] = s[lo] + (r - lo) * (s[hi] - s[lo])
            if not np.array_equal(want, foamCase.read_field(stats, t, "%sP%g" % (name, p), g.n)):
                bad.append("%sP%g" % (name, p))
    reached = int(np.sum(foamCase.read_field(stats, t, "hMaxExceedance_0.2", g.n) > 0))
    if bad:
        print("FAIL  statistics at t = %s differ from the members counted by hand: %s" % (t, " ".join(bad)))
    else:
        print("PASS  statistics at t = %s: hMaxExceedance_0.01/0.2, hMax and UMax mean and P0/25/50/90/100 equal the %d members counted by hand (%d cells reached by 0.2 m)" % (t, n, reached))
PY
)"
tally $? "$out" "statistics by hand"

#- restartLegs <case>: its ensemble to t = 1, then on to 2 (startFrom
#  latestTime), logs log.first and log.second; the exit status of the
#  legs
restartLegs()
{
    (
        cd "$1" || exit 1
        setEntry system/controlDict endTime 1
        savageHutterFoam -ensemble -backend cpu > log.first 2>&1 || exit 1
        setEntry system/controlDict endTime 2
        savageHutterFoam -ensemble -backend cpu > log.second 2>&1
    )
}

#- sameAt2 <straight> <restarted>: in $bad, the files at t = 2 of every
#  member and of the statistics, and report.dat, that differ
sameAt2()
{
    bad=""
    local d f
    for d in "$1"/ensemble/member* "$1/ensemble/statistics"
    do
        for f in "$d"/2/*
        do
            [ -f "$f" ] || continue
            cmp -s "$f" "$2/ensemble/$(basename "$d")/2/$(basename "$f")" \
                || bad="$bad $(basename "$d")/$(basename "$f")"
        done
    done
    cmp -s "$1/ensemble/report.dat" "$2/ensemble/report.dat" \
        || bad="$bad report.dat"
}

# Restart: to 1, then on to 2, against the run straight to 2
re="$(newCase restart)"
ensembleDict "$re" "$product"
restartLegs "$re"
rc=$?
sameAt2 "$main" "$re"
if [ $rc -eq 0 ] && grep -q "Restart of the ensemble from t = 1" "$re/log.second" && [ -z "$bad" ]
then
    pass "restart: to t = 1, then on to 2 (startFrom latestTime): every member's files, the statistics and report.dat byte for byte the run straight to 2"
else
    fail "restart (exit $rc): differs in:${bad:- (no restart line?)}"
fi
# Another ensemble in ensemble/ is not continued
other="$(newCase other)"
cp -r "$re/ensemble" "$other/"
ensembleDict "$other" "${product/(22 26 30)/(22 26 29)}"
(cd "$other" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
if [ $? -ne 0 ] && grep -q "holds another ensemble" "$other/log.ensemble"
then
    pass "restart with another ensembleDict than ensemble/ holds: refused (remove ensemble/, it says)"
else
    fail "restart with another ensembleDict: not refused"
fi

# More members than ensemble/ holds: refused under latestTime, replaced
# (with a warning) by a fresh start, which a restart then continues
more="$(newCase more)"
cp -r "$re/ensemble" "$more/"
ensembleDict "$more" "${product/(22 26 30)/(22 26 30 24)}"
setEntry "$more/system/controlDict" endTime 1
(cd "$more" && savageHutterFoam -ensemble -backend cpu > log.latest 2>&1)
rcLatest=$?
[ -d "$more/ensemble/member0003/2" ] && kept=yes || kept=no
setEntry "$more/system/controlDict" startFrom startTime
(cd "$more" && savageHutterFoam -ensemble -backend cpu > log.fresh 2>&1)
rcFresh=$?
setEntry "$more/system/controlDict" startFrom latestTime
setEntry "$more/system/controlDict" endTime 2
(cd "$more" && savageHutterFoam -ensemble -backend cpu > log.again 2>&1)
rcAgain=$?
if [ $rcLatest -ne 0 ] && grep -q "holds another ensemble" "$more/log.latest" && [ $kept = yes ] \
    && [ $rcFresh -eq 0 ] && grep -q "Replacing" "$more/log.fresh" \
    && [ $rcAgain -eq 0 ] && grep -q "Restart of the ensemble from t = 1" "$more/log.again" \
    && [ -f "$more/ensemble/member0015/2/h" ] \
    && [ "$(foamDictionary "$more/ensemble/member0012/parameters" -entry CoulombCoeffs/delta -value)" = 24 ]
then
    pass "16 members over an ensemble/ of 12: refused under latestTime (kept), replaced by startFrom startTime (warned), then continued from t = 1 by latestTime"
else
    fail "16 members over 12: latestTime exit $rcLatest (kept: $kept), fresh start exit $rcFresh, restart exit $rcAgain"
fi

# The members' order: product nests the parameters as listed, the last
# varying fastest, also with two coefficients of one law (read into one
# sub-dictionary) and another parameter between them
order="$(newCase order)"
(
    cd "$order" || exit 1
    setEntry constant/transportProperties frictionModel Voellmy
    foamDictionary constant/transportProperties -entry VoellmyCoeffs -set "{ mu 0.3; xi 500; }" > /dev/null
    setEntry system/controlDict endTime 0.1
    setEntry system/controlDict writeInterval 0.1
) || fail "order: setting up a Voellmy case"
ensembleDict "$order" 'parameters
{
    "VoellmyCoeffs/mu" (0.2 0.3);
    hScale (1 2);
    "VoellmyCoeffs/xi" (400 800 1600);
}'
(cd "$order" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
got=""
want=""
for k in $(seq 0 11)
do
    f="$order/ensemble/$(printf 'member%04d' "$k")/parameters"
    got="$got $(foamDictionary "$f" -entry VoellmyCoeffs/mu -value 2>/dev/null)/$(foamDictionary "$f" -entry hScale -value 2>/dev/null)/$(foamDictionary "$f" -entry VoellmyCoeffs/xi -value 2>/dev/null)"
    mu=$(echo "0.2 0.3" | cut -d' ' -f$((k / 6 + 1)))
    hs=$(echo "1 2" | cut -d' ' -f$(((k / 3) % 2 + 1)))
    xi=$(echo "400 800 1600" | cut -d' ' -f$((k % 3 + 1)))
    want="$want $mu/$hs/$xi"
done
if [ "$got" = "$want" ]
then
    pass "product order (mu, hScale, xi as listed, xi fastest):$(echo "$got" | cut -c1-60)..."
else
    fail "product order: got$got, want$want"
fi

# A Voellmy member (coefficients of another law through memberModel)
# against its single run: member 7 = mu 0.3, hScale 1, xi 800
vm="$(newCase voellmySingle)"
rm -rf "$vm/constant" "$vm/system"
cp -r "$order/constant" "$order/system" "$vm/"
rm -f "$vm/system/ensembleDict"
(
    cd "$vm" || exit 1
    setEntry constant/transportProperties VoellmyCoeffs/mu 0.3
    setEntry constant/transportProperties VoellmyCoeffs/xi 800
    savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1
)
bad="$(differing "$vm/0.1" "$order/ensemble/member0007/0.1")"
if [ -z "$bad" ]
then
    pass "Voellmy member 7 (mu 0.3, xi 800): h hU hMax UMax tArrival at t = 0.1 byte for byte its single run"
else
    fail "Voellmy member 7 differs from its single run in:$bad"
fi

# Samples: reproducible from the seed
sampled='parameters
{
    "CoulombCoeffs/delta" uniform (20 28);
    hScale normal (1 0.1);
    release (h.large h.small);
}
samples 5;
seed 11;'
params()
{
    cat "$1"/ensemble/member*/parameters | grep -v "location\|^ *$"
}
for s in a b c
do
    d="$(newCase "samples$s")"
    setEntry "$d/system/controlDict" endTime 0.2
    setEntry "$d/system/controlDict" writeInterval 0.2
    if [ $s = c ]
    then
        ensembleDict "$d" "${sampled/seed 11/seed 12}"
    else
        ensembleDict "$d" "$sampled"
    fi
    (cd "$d" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1) || fail "samples$s: run failed"
done
deltas="$(for f in "$work"/samplesa/ensemble/member*/parameters; do foamDictionary "$f" -entry CoulombCoeffs/delta -value; done | tr '\n' ' ')"
inRange=yes
for v in $deltas
do
    awk -v v="$v" 'BEGIN { exit !(v >= 20 && v <= 28) }' || inRange=no
done
if [ "$(params "$work/samplesa")" = "$(params "$work/samplesb")" ] \
    && [ "$(params "$work/samplesa")" != "$(params "$work/samplesc")" ] \
    && [ $inRange = yes ] && [ -f "$work/samplesa/ensemble/member0004/parameters" ]
then
    pass "samples 5, seed 11: the same members twice (delta $deltas), seed 12 others; delta within uniform (20 28)"
else
    fail "samples: seed 11 twice gave different members, seed 12 the same, or delta out of range ($deltas)"
fi

# The bed's cover: a layer of 0.1 m across the track (x in [6, 12]) and a
# resistance patch (x in [7, 14], |y| < 4) on the plane, constantRate;
# the rate and cResistanceScale varied, every member against its single run
coverBase="$(newCase coverBase)"
(
    cd "$coverBase" || exit 1
    cat > system/setAvalancheFieldsDict.cover <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }
h            ( hemisphere { centre (4 0); radius 1.85; } );
hEntrainable ( box { min (6 -7); max (12 7); value 0.1; } );
cResistance  ( box { min (7 -4); max (14 4); value 0.05; } );
DICT
    runApplication -s cover setAvalancheFields -dict system/setAvalancheFieldsDict.cover
    foamDictionary constant/transportProperties -entry entrainmentModel -add constantRate
    foamDictionary constant/transportProperties -entry constantRateCoeffs -add "{ rate 0.02; }"
) > "$work/coverBase.log" 2>&1 || { cat "$work/coverBase.log"; fail "setting up the case with a cover (its log above)"; }
cover="$(newCase cover "$coverBase")"
ensembleDict "$cover" 'parameters
{
    "constantRateCoeffs/rate" (0.01 0.04);
    cResistanceScale (0.5 2);
}'
(cd "$cover" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
rc=$?
if [ $rc -eq 0 ] && [ -f "$cover/ensemble/member0003/2/erodedDepth" ]
then
    pass "-ensemble with a cover: 4 members (constantRateCoeffs/rate x cResistanceScale) written with hEntrainable, erodedDepth, cResistance"
else
    tail -n 20 "$cover/log.ensemble"
    fail "-ensemble with a cover (exit $rc; log above)"
fi
coverFields="h hU hMax UMax tArrival hEntrainable erodedDepth cResistance"
for k in 0 1 2 3
do
    m="$(printf 'member%04d' "$k")"
    par="$cover/ensemble/$m/parameters"
    rate="$(foamDictionary "$par" -entry constantRateCoeffs/rate -value)"
    scale="$(foamDictionary "$par" -entry cResistanceScale -value)"
    one="$(newCase "coverSingle$k" "$coverBase")"
    (
        cd "$one" || exit 1
        setEntry constant/transportProperties constantRateCoeffs/rate "$rate"
        # 0/cResistance scaled (x 0.5 and x 2 are exact in binary)
        python3 - "$scale" <<'PY'
import re, sys, struct
s = float(sys.argv[1])
data = open("0/cResistance", "rb").read()
m = re.search(rb"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", data)
n = int(m.group(1))
vals = struct.unpack_from("<%dd" % n, data, m.end())
body = struct.pack("<%dd" % n, *[v * s for v in vals])
open("0/cResistance", "wb").write(data[:m.end()] + body + data[m.end() + 8 * n:])
PY
        savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1
    )
    likeSingle "$one" "$cover/ensemble/$m" "$coverFields" \
        "cover member $k (rate $rate, cResistanceScale $scale)"
done
out="$(/usr/bin/python3 - "$cover" <<'PY'
import os, sys
sys.path.insert(0, os.path.join(os.environ["SAVAGEHUTTER_DIR"], "tutorials", "tools"))
import foamCase
case = sys.argv[1]
g = foamCase.Grid(case)
ens = os.path.join(case, "ensemble")
lines = [l for l in open(os.path.join(ens, "report.dat")) if l.strip()]
head = [l for l in lines if l.startswith("# member")][0].split()[1:]
rows = [dict(zip(head, l.split())) for l in lines if not l.startswith("#")]
bad = []
eroded = {}
for r in rows:
    k = int(r["member"])
    e = foamCase.read_field(os.path.join(ens, "member%04d" % k), "2", "erodedDepth", g.n)
    # cells of 0.5 x 0.5 m
    want = float(sum(float(x) for x in e)) * 0.25
    got = float(r["entrainedVolume"])
    eroded[k] = got
    if not (got > 0 and abs(got - want) <= 1e-9 * want):
        bad.append("member %d: entrainedVolume %r, its erodedDepth sums to %r" % (k, got, want))
    balance = float(r["releasedVolume"]) + got - float(r["volume"])
    if abs(balance) > 1e-9 * float(r["volume"]):
        bad.append("member %d: releasedVolume + entrainedVolume - volume = %g" % (k, balance))
# The rate sets what is taken up; members 0, 1 (rate 0.01) below 2, 3 (0.04)
if not (max(eroded[0], eroded[1]) < min(eroded[2], eroded[3])):
    bad.append("entrained volumes %s do not grow with the rate" % eroded)
# The resistance: members of one rate differ in their hMax
h = [foamCase.read_field(os.path.join(ens, "member%04d" % k), "2", "hMax", g.n) for k in range(4)]
if list(h[0]) == list(h[1]) or list(h[2]) == list(h[3]):
    bad.append("cResistanceScale 0.5 and 2 give the same hMax")
if bad:
    print("FAIL  cover report: " + "; ".join(bad))
else:
    print("PASS  cover report: entrainedVolume of each member the sum of its erodedDepth dA (%s m^3), releasedVolume + entrainedVolume = volume (closed box) to 1e-9, more taken up at the higher rate, hMax differing with cResistanceScale" % ", ".join("%.6g" % eroded[k] for k in sorted(eroded)))
PY
)"
tally $? "$out" "cover report"
# A restart of it: to t = 1, then on to 2, each member's layer and eroded
# depth read back as a single run's restart reads them
coverRe="$(newCase coverRestart "$coverBase")"
cp "$cover/system/ensembleDict" "$coverRe/system/"
restartLegs "$coverRe"
rc=$?
sameAt2 "$cover" "$coverRe"
if [ $rc -eq 0 ] && grep -q "Restart of the ensemble from t = 1" "$coverRe/log.second" && [ -z "$bad" ]
then
    pass "cover restart: to t = 1, then on to 2: every member's files (hEntrainable, erodedDepth too), the statistics and report.dat byte for byte the run straight to 2"
else
    fail "cover restart (exit $rc): differs in:${bad:- (no restart line?)}"
fi

# The cover in plan coordinates (testFunctions.sh planSlopeCase with an
# erodible bed, constantRate): two rates; each member byte for byte its
# single run at t = 1 and 2 (a single run in plan coordinates also stops
# at the samples of its centre of mass, avalancheCase::nextComTime, and
# so does every member: the same steps); the ensemble restarted at t = 1
# byte for byte the run straight to 2 (each member's layer and eroded
# depth per plan area read back, as HEntrainable and HErodedDepth)
pcov="$work/planCover"
planSlopeCase "$pcov" 500 800 0
cat >> "$pcov/system/terrainDict" <<'DICT'
entrainment
{
    bed
    {
        polygon     ((550 810) (660 810) (660 910) (550 910));
        thickness   0.3;
        thicknessDirection vertical;
    }
}
DICT
cat >> "$pcov/constant/transportProperties" <<'DICT'
entrainmentModel constantRate;
constantRateCoeffs { rate 0.2; }
DICT
planFields="h U H hU hEntrainable erodedDepth HEntrainable HErodedDepth"
if (cd "$pcov" && terrainToCase > log.terrainToCase 2>&1 && blockMesh > log.blockMesh 2>&1) \
    && setEntry "$pcov/system/controlDict" endTime 2 \
    && setEntry "$pcov/system/controlDict" writeInterval 1 \
    && setEntry "$pcov/system/controlDict" startFrom latestTime \
    && ensembleDict "$pcov" 'parameters { "constantRateCoeffs/rate" (0.1 0.3); }' \
    && cp -r "$pcov" "$work/planCoverRestart" \
    && rm -rf "$work/planCoverBase" && cp -r "$pcov" "$work/planCoverBase" \
    && (cd "$pcov" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
then
    # Each member against its single run (its rate in transportProperties)
    for k in 0 1
    do
        m="$(printf 'member%04d' "$k")"
        rate="$(foamDictionary "$pcov/ensemble/$m/parameters" -entry constantRateCoeffs/rate -value)"
        one="$(newCase "planCoverSingle$k" "$work/planCoverBase")"
        (
            cd "$one" || exit 1
            setEntry constant/transportProperties constantRateCoeffs/rate "$rate"
            savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1
        )
        likeSingle "$one" "$pcov/ensemble/$m" "$planFields" \
            "plan coordinates with a cover: member $k (rate $rate)"
    done
    pre="$work/planCoverRestart"
    restartLegs "$pre"
    rc=$?
    bad=""
    for k in 0 1
    do
        m="$(printf 'member%04d' "$k")"
        for f in $planFields
        do
            cmp -s "$pcov/ensemble/$m/2/$f" "$pre/ensemble/$m/2/$f" || bad="$bad $m/$f"
        done
    done
    if [ $rc -eq 0 ] && grep -q "Restart of the ensemble from t = 1" "$pre/log.second" && [ -z "$bad" ]
    then
        pass "plan coordinates with a cover: the ensemble restarted at t = 1: both members' $planFields at t = 2 byte for byte the run straight to 2"
    else
        fail "plan coordinates with a cover, restart (exit $rc): differs in:${bad:- (no restart line?)}"
    fi
else
    fail "plan coordinates with a cover: terrainToCase, blockMesh or -ensemble failed (see $pcov/log.*)"
fi

# A terrain case: hazardMaps -statistics writes the statistics as rasters
ter="$work/terrain"
cp -r "$project/tutorials/terrainChute" "$ter"
(
    cd "$ter" || exit 1
    rm -f log.*
    runApplication ./makeTerrain
    setEntry system/terrainDict cellSize 40
    runApplication terrainToCase
    runApplication blockMesh
    setEntry system/controlDict endTime 20
    setEntry system/controlDict writeInterval 10
    setEntry system/fvSolution savageHutter/steadyStateTolerance 0
    cat > system/ensembleDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object ensembleDict; }
parameters { "CoulombCoeffs/delta" (17 21 25); hScale (0.5 1); }
thresholds (0.1 1);
DICT
    runApplication savageHutterFoam -ensemble -backend cpu
    runApplication hazardMaps -statistics
) > "$work/terrain.log" 2>&1
if [ $? -ne 0 ]
then
    tail -n 20 "$work/terrain.log"
    fail "terrain ensemble: terrainToCase, -ensemble or hazardMaps -statistics failed (log above)"
else
    out="$(/usr/bin/python3 - "$ter" <<'PY'
import bisect, os, sys
sys.path.insert(0, os.path.join(os.environ["SAVAGEHUTTER_DIR"], "tutorials", "tools"))
import foamCase
case = sys.argv[1]
stats = os.path.join(case, "ensemble", "statistics")
out = os.path.join(case, "postProcessing", "hazardMaps", "ensemble", "20")
names = sorted(f for f in os.listdir(os.path.join(stats, "20")) if f not in ("zb", "uniform"))
want = {"hMaxExceedance_0.1", "hMaxExceedance_1", "hMaxMean", "hMaxP50", "UMaxMean", "pMaxMean", "pMaxP95"}
bad = sorted(want - set(names))
checked = 0
for name in names:
    path = os.path.join(out, name + ".asc")
    if not os.path.isfile(path) or not os.path.isfile(os.path.join(out, name + ".tif")):
        bad.append(name + " (no .asc/.tif)")
        continue
    lines = open(path).read().split("\n")
    head = {}
    k = 0
    while lines[k].split() and lines[k].split()[0][0].isalpha():
        key, val = lines[k].split()[:2]
        head[key.lower()] = float(val)
        k += 1
    nodata = head.get("nodata_value", -9999)
    vals = [float(v) for l in lines[k:] for v in l.split()]
    valid = [v for v in vals if v != nodata]
    field = sorted(foamCase.read_field(stats, "20", name, None).tolist())
    def near(v):
        i = bisect.bisect_left(field, v)
        return any(abs(field[j] - v) <= 1e-6 * max(1.0, abs(v)) for j in (i - 1, i) if 0 <= j < len(field))
    if not valid or not all(near(v) for v in valid):
        bad.append(name + " (values not the field's)")
    if name.startswith("hMaxExceedance") and not all(0 <= v <= 1 for v in valid):
        bad.append(name + " (outside [0, 1])")
    checked += 1
if bad:
    print("FAIL  hazardMaps -statistics: " + ", ".join(bad))
else:
    print("PASS  hazardMaps -statistics on a terrain ensemble (6 members): %d rasters (.asc, .tif) of ensemble/statistics/20, every pixel a value of its field (to the .asc's digits), probabilities in [0, 1]" % checked)
PY
)"
    tally $? "$out" "hazardMaps -statistics"
fi

# Bad ensembleDicts: rejected, nothing written
expectRejected()
{
    local name="$1" dict="$2"
    shift 2
    local d
    d="$(newCase "bad$name" "${rejectFrom:-$base}")"
    ensembleDict "$d" "$dict"
    (cd "$d" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
    local rc=$? problems="" p
    [ $rc -ne 0 ] || problems="$problems exit status 0;"
    grep -q "FOAM FATAL" "$d/log.ensemble" || problems="$problems no FOAM FATAL message;"
    ! grep -qE "printStack|sigFpe::sigHandler|^#[0-9]+ " "$d/log.ensemble" || problems="$problems a stack trace;"
    [ ! -e "$d/ensemble" ] || problems="$problems ensemble/ written;"
    for p in "$@"
    do
        grep -qF -- "$p" "$d/log.ensemble" || problems="$problems no '$p';"
    done
    if [ -z "$problems" ]
    then
        pass "$name: rejected ($(grep -m1 -A1 'FOAM FATAL' "$d/log.ensemble" | tail -n1 | cut -c1-100))"
    else
        fail "$name:$problems"
    fi
}
expectRejected unknownParameter 'parameters { "CoulombCoeffs/deltaa" (20 22); }' \
    "Unknown parameter 'CoulombCoeffs/deltaa'" "CoulombCoeffs/delta" "ensembleDict"
expectRejected otherLawsCoefficient 'parameters { "VoellmyCoeffs/mu" (0.2 0.3); }' \
    "Unknown parameter 'VoellmyCoeffs/mu'"
expectRejected deltaAbovePhi 'parameters { "CoulombCoeffs/delta" (20 35); }' \
    "Member 1" "not a valid case" "delta"
expectRejected badUniform 'parameters { "CoulombCoeffs/delta" uniform (28 20); } samples 4; seed 1;' \
    "uniform" "a <= b"
expectRejected badNormal 'parameters { hScale normal (1 -0.1); } samples 4; seed 1;' \
    "normal" "sd >= 0"
expectRejected noSeed 'parameters { hScale normal (1 0.1); } samples 4;' "seed"
expectRejected listLengths 'parameters { "CoulombCoeffs/delta" (20 22); hScale (1 2 3); } combine list;' \
    "combine list" "as many values"
expectRejected unknownCombine 'parameters { hScale (1 2); } combine cartesian;' \
    "Unknown combine 'cartesian'" "product list"
expectRejected negativeScale 'parameters { hScale (1 -2); }' "hScale" "positive"
expectRejected missingRelease 'parameters { release (h.large h.medium); }' \
    "h.medium" "not found"
expectRejected noParameters 'parameters { }' "No parameters"
expectRejected unknownKeyword 'parameters { hScale (1 2); } sample 4;' \
    "Unknown keyword 'sample'" "samples"
expectRejected distributionWithCombine 'parameters { hScale uniform (1 2); }' \
    "needs 'samples N; seed S;'"
expectRejected badThreshold 'parameters { hScale (1 2); } thresholds (0.1 -1);' "thresholds"
expectRejected sameThreshold 'parameters { hScale (1 2); } thresholds (0.1 0.1000000001);' "twice"
expectRejected seedWithoutSamples 'parameters { hScale (1 2); } seed 3;' "seed without samples"
expectRejected resistanceWithoutField 'parameters { cResistanceScale (0.5 2); }' \
    "cResistanceScale" "does not have"
expectRejected rateWithoutModel 'parameters { "constantRateCoeffs/rate" (0.01 0.02); }' \
    "Unknown parameter 'constantRateCoeffs/rate'"
rejectFrom="$coverBase"
expectRejected negativeResistanceScale 'parameters { cResistanceScale (1 -0.5); }' \
    "ensembleDict" "Member 1" "cResistanceScale -0.5" ">= 0"
expectRejected negativeRate 'parameters { "constantRateCoeffs/rate" (0.02 -0.01); }' \
    "ensembleDict" "Member 1" "not a valid case" "rate"
unset rejectFrom
rm -f "$base/system/ensembleDict.x"
noDict="$(newCase noDict)"
rm -f "$noDict/system/ensembleDict"
(cd "$noDict" && savageHutterFoam -ensemble -backend cpu > log.ensemble 2>&1)
if [ $? -ne 0 ] && grep -q "needs.*ensembleDict" "$noDict/log.ensemble" && [ ! -e "$noDict/ensemble" ]
then
    pass "no system/ensembleDict: rejected with an example, nothing written"
else
    fail "no system/ensembleDict: not rejected as it should be"
fi

finish

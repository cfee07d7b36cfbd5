#!/bin/bash
#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     savageHutterFoam in plan coordinates (coordinates plan: the general-
#     terrain model, docs/generalTerrain.md), on a case terrainToCase makes
#     without an axis from a DEM written here: a 35 deg slope whose line of
#     steepest descent is turned by 30 deg from the DEM's columns, rounded
#     into a flat floor, with a bump (2 m pixels, 4 m cells, 42 x 30
#     cells), a release of 1 m (vertical) on the slope.  Written in ascii
#     with 17 digits, so that the files hold the doubles themselves.
#       1. The run writes h normal to the bed and U along it: at every
#          written time and interior cell (a ring of one cell left out,
#          where the bed's differences reach the ghost cells) H = J h and
#          hU = H (Ux, Uy), Uz = p Ux + q Uy, with J, p, q the centred
#          differences of zb (relative 1e-12); the volume sum H dA at
#          every time equals the released volume (terrainMapping's) to
#          1e-12 while no material reaches a side; the flow moves (UMax
#          > 1 m/s) and stays out of the dry far side.
#       2. postProcessing/centreOfMass.dat: ten lines per write interval
#          (times k 0.1), times strictly increasing, its volume column the
#          log's; hazardMaps reads it (the log says so) and reports
#          comPathLength > 0.
#       3. Exact restarts: 0 -> 2, then latestTime -> 4 against 0 -> 4 in
#          one go: every field of time 4 and centreOfMass.dat byte for
#          byte the same; H edited (h no longer J h) and U edited (hU no
#          longer H U) are warned about and the edited fields win.
#       4. SIGTERM during a run (maxDeltaT 5e-4, so that it lasts): the
#          time written is complete, and the restart from it to the end
#          gives time 4 byte for byte as the run without a stop.
#       5. Decomposed, 2 x 1 and 1 x 2 (mpirun -np 2): every field of every
#          time, on every processor, bit for bit the serial run's
#          (bin/tools/compareDecomposed); skipped without mpirun.
#       6. -precision single: runs to the end, its volume the released to
#          1e-5, h within 1e-2 m of the double run's (max over cells).
#       7. -ensemble -backend cpu (delta 20 and 24): the member with the
#          case's delta 24 is the single run to 1e-2 m in h (the single
#          run's steps land on the centre of mass' samples, the
#          ensemble's do not) and its volume, the delta 20 member far from
#          it.  Refusals,
#          each naming the keyword, nothing written: an inclination other
#          than 0 (coordinates); an unknown coordinates (the valid
#          choices).
#     Prints one line per check and "N passed, M failed, K skipped".
#
# Usage
#     planRunTests.sh <project dir> <work dir>
#------------------------------------------------------------------------------
project="$1"
work="$2"
. "$project/tests/application/testFunctions.sh"
. "$project/etc/bashrc"
python=/usr/bin/python3

base="$work/base"
planSlopeCase "$base" 500 800 1.5

# The defaults of terrainToCase, then ascii with 17 digits, endTime 4
(cd "$base" && terrainToCase > log.terrainToCase 2>&1 && blockMesh > log.blockMesh 2>&1) \
    || { fail "terrainToCase and blockMesh (see $base/log.*)"; finish; exit 1; }
foamDictionary -entry endTime -set 4 "$base/system/controlDict" > /dev/null
foamDictionary -entry writeInterval -set 1 "$base/system/controlDict" > /dev/null
foamDictionary -entry writeFormat -set ascii "$base/system/controlDict" > /dev/null
foamDictionary -entry writePrecision -set 17 "$base/system/controlDict" > /dev/null
foamDictionary -entry timePrecision -set 6 "$base/system/controlDict" > /dev/null
foamDictionary -entry savageHutter/steadyStateTolerance -set 0 "$base/system/fvSolution" > /dev/null

newCase()
{
    rm -rf "$work/$1"
    cp -r "$base" "$work/$1"
    echo "$work/$1"
}

fields="h U hU H zb regime hMax UMax pMax tArrival"

#- sameTime <case a> <case b> <time> <what>: every field of a time and
#  centreOfMass.dat byte for byte
sameTime()
{
    local f bad=""
    for f in $fields
    do
        cmp -s "$1/$3/$f" "$2/$3/$f" || bad="$bad $f"
    done
    cmp -s "$1/postProcessing/centreOfMass.dat" "$2/postProcessing/centreOfMass.dat" \
        || bad="$bad postProcessing/centreOfMass.dat"
    if [ -z "$bad" ]
    then
        pass "$4: every field of $3 and centreOfMass.dat byte for byte the same"
    else
        fail "$4: differs in$bad"
    fi
}

# 1. The run, the fields' relations and the volume
ref="$(newCase ref)"
if ! (cd "$ref" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
then
    fail "the plan run (see $ref/log.savageHutterFoam)"
    finish
    exit 1
fi
out="$($python - "$ref" "$project" <<'PYEOF'
import math, os, re, sys
sys.path.insert(0, os.path.join(sys.argv[2], "tutorials", "tools"))
import foamCase
import numpy as np
case = sys.argv[1]
mp = open(case + "/constant/terrainMapping").read()
nx = int(re.search(r"\bnx\s+(\d+);", mp).group(1))
ny = int(re.search(r"\bny\s+(\d+);", mp).group(1))
d = float(re.search(r"cellSize\s+([0-9.eE+-]+);", mp).group(1))
released = float(re.search(r"releasedVolume\s+([0-9.eE+-]+);", mp).group(1))
zb = np.asarray(foamCase.read_field(case, "0", "zb")).reshape(ny, nx)
p = np.zeros_like(zb); q = np.zeros_like(zb)
p[:, 1:-1] = (zb[:, 2:] - zb[:, :-2])/(2*d)
q[1:-1, :] = (zb[2:, :] - zb[:-2, :])/(2*d)
J = np.sqrt(1 + (p*p + q*q))
inner = np.zeros((ny, nx), bool); inner[1:-1, 1:-1] = True
worst = {"H": 0.0, "hU": 0.0, "Uz": 0.0, "volume": 0.0}
side = 0.0
umax = 0.0
for t in foamCase.times(case):
    if t == "0":
        continue
    h = np.asarray(foamCase.read_field(case, t, "h")).reshape(ny, nx)
    H = np.asarray(foamCase.read_field(case, t, "H")).reshape(ny, nx)
    U = np.asarray(foamCase.read_field(case, t, "U")).reshape(ny, nx, 3)
    hU = np.asarray(foamCase.read_field(case, t, "hU")).reshape(ny, nx, 3)
    rel = lambda a, b: np.abs(a - b)/np.maximum(np.abs(a) + np.abs(b), 1e-300)
    wet = inner & (H > 1e-6)
    worst["H"] = max(worst["H"], rel(H, J*h)[wet].max())
    for k in range(2):
        worst["hU"] = max(worst["hU"], np.where(np.abs(hU[..., k]) > 1e-12, rel(hU[..., k], H*U[..., k]), 0)[wet].max())
    uz = p*U[..., 0] + q*U[..., 1]
    worst["Uz"] = max(worst["Uz"], np.where(np.abs(uz) > 1e-12, rel(U[..., 2], uz), 0)[wet].max())
    worst["volume"] = max(worst["volume"], abs(H.sum()*d*d - released)/released)
    edge = np.ones((ny, nx), bool); edge[2:-2, 2:-2] = False
    side = max(side, H[edge].max())
    umax = max(umax, float(np.asarray(foamCase.read_field(case, t, "UMax")).max()))
for k, b in (("H", 1e-12), ("hU", 1e-12), ("Uz", 1e-12), ("volume", 1e-12)):
    what = {"H": "H = J h", "hU": "hU = H (Ux, Uy)", "Uz": "Uz = p Ux + q Uy",
            "volume": "sum H dA = releasedVolume"}[k]
    print("%s  %s: largest relative difference %.3g over the interior wet cells and times 1-4, bound %g"
          % ("PASS" if worst[k] <= b else "FAIL", what, worst[k], b))
print("%s  no material within two cells of a side (largest H there %.3g m), so the volume is closed"
      % ("PASS" if side < 1e-9 else "FAIL", side))
print("%s  the flow moves: UMax %.3f m/s (> 1)" % ("PASS" if umax > 1 else "FAIL", umax))
PYEOF
)"
tally $? "$out" "plan fields"

# 2. The centre of mass' samples, and hazardMaps reading them
com="$ref/postProcessing/centreOfMass.dat"
out="$($python - "$com" "$ref/log.savageHutterFoam" <<'PYEOF'
import re, sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith("#")]
t = [float(r[0]) for r in rows]
want = [k/10 for k in range(41)]
ok = len(t) == 41 and all(abs(a - b) < 1e-9 for a, b in zip(t, want)) \
    and all(b > a for a, b in zip(t, t[1:]))
print("%s  centreOfMass.dat: %d lines at t = %s ... %s (0, 0.1, ..., 4 wanted), increasing"
      % ("PASS" if ok else "FAIL", len(t), t[:3], t[-2:]))
vols = [float(m.group(1)) for m in re.finditer(r"volume = ([0-9.eE+-]+)", open(sys.argv[2]).read())]
v = [float(r[4]) for r in rows]
ok = vols and all(abs(x - vols[0]) <= 1e-9*vols[0] for x in v)
print("%s  centreOfMass.dat's volume %.12g .. %.12g m^3, the log's %s"
      % ("PASS" if ok else "FAIL", min(v), max(v), vols[:1]))
PYEOF
)"
tally $? "$out" "centreOfMass.dat"
if (cd "$ref" && hazardMaps > log.hazardMaps 2>&1) \
    && grep -q 'from "postProcessing/centreOfMass.dat"' "$ref/log.hazardMaps"
then
    s="$(awk '$1 == "comPathLength" {print $2}' "$ref"/postProcessing/hazardMaps/4/report.dat)"
    if $python -c "import sys; sys.exit(0 if float('$s') > 0 else 1)" 2>/dev/null
    then
        pass "hazardMaps takes the path from centreOfMass.dat: comPathLength $s m"
    else
        fail "hazardMaps: comPathLength '$s'"
    fi
else
    fail "hazardMaps on the plan run, from centreOfMass.dat (see $ref/log.hazardMaps)"
fi

# 3. Exact restarts
rs="$(newCase restart)"
foamDictionary -entry endTime -set 2 "$rs/system/controlDict" > /dev/null
(cd "$rs" && savageHutterFoam -backend cpu > log.first 2>&1)
foamDictionary -entry endTime -set 4 "$rs/system/controlDict" > /dev/null
foamDictionary -entry startFrom -set latestTime "$rs/system/controlDict" > /dev/null
if (cd "$rs" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
then
    grep -q "Reading fields H and hU" "$rs/log.savageHutterFoam" \
        && pass "restart: H and hU read (the exact state)" \
        || fail "restart: no 'Reading fields H and hU' in $rs/log.savageHutterFoam"
    sameTime "$ref" "$rs" 4 "0 -> 2, restart -> 4 against 0 -> 4"
else
    fail "restart from 2 (see $rs/log.savageHutterFoam)"
fi
for edit in H U
do
    ed="$(newCase "edit$edit")"
    rm -rf "$ed/3" "$ed/4"
    cp -r "$ref/2" "$ed/2"
    cp -r "$ref/postProcessing" "$ed/"
    foamDictionary -entry startFrom -set latestTime "$ed/system/controlDict" > /dev/null
    foamDictionary -entry endTime -set 2.1 "$ed/system/controlDict" > /dev/null
    $python - "$ed/2/$edit" <<'PYEOF'
import re, sys
t = open(sys.argv[1]).read()
# scale every value of the internal field by 1.1 (the first vector's or
# scalar's numbers after the count)
head, rest = t.split("internalField", 1)
m = re.search(r"\(\s*(.*?)\n\)\s*;", rest, re.S)
body = re.sub(r"-?\d+\.?\d*(?:[eE][-+]?\d+)?", lambda x: repr(1.1*float(x.group(0))), m.group(1))
open(sys.argv[1], "w").write(head + "internalField" + rest[:m.start(1)] + body + rest[m.end(1):])
PYEOF
    (cd "$ed" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    if [ "$edit" = H ]
    then
        want="H (the volume per plan area) disagrees with J h"
    else
        want="hU disagrees with H U"
    fi
    grep -q "$want" "$ed/log.savageHutterFoam" \
        && pass "restart with $edit scaled by 1.1: warned ($want)" \
        || fail "restart with $edit scaled by 1.1: no '$want' in $ed/log.savageHutterFoam"
done

# 4. SIGTERM and the restart from the time it wrote (maxDeltaT 5e-4: the
# run takes seconds, so that the signal comes before its end)
sg="$(newCase signal)"
full="$(newCase signalFull)"
for d in "$sg" "$full"
do
    foamDictionary -entry writeInterval -set 4 "$d/system/controlDict" > /dev/null
    foamDictionary -entry maxDeltaT -set 5e-4 "$d/system/controlDict" > /dev/null
done
(cd "$sg" && exec savageHutterFoam -backend cpu -logInterval 0.2 > log.savageHutterFoam 2>&1) &
pid=$!
if waitFor "$sg/log.savageHutterFoam" "^Time = " 120
then
    kill -TERM "$pid"
fi
wait "$pid"
at="$(timeDirs "$sg" | tail -n1)"
if grep -q "Stopped by SIGTERM" "$sg/log.savageHutterFoam" && [ -n "$at" ] \
    && [ "$at" != 4 ] && complete "$sg" "$at"
then
    pass "SIGTERM: stopped, time $at written complete"
    foamDictionary -entry startFrom -set latestTime "$sg/system/controlDict" > /dev/null
    (cd "$full" && savageHutterFoam -backend cpu > log.savageHutterFoam 2>&1)
    (cd "$sg" && savageHutterFoam -backend cpu > log.restart 2>&1)
    bad=""
    for f in $fields
    do
        cmp -s "$full/4/$f" "$sg/4/$f" || bad="$bad $f"
    done
    [ -z "$bad" ] && pass "SIGTERM at $at, restart -> 4: time 4 byte for byte the run without a stop" \
        || fail "SIGTERM at $at, restart -> 4: differs in$bad"
else
    fail "SIGTERM: not stopped before t = 4 with a complete time written (last time '$at', see $sg/log.savageHutterFoam)"
fi

# 5. Decomposed runs
if command -v mpirun > /dev/null
then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    for split in "2 1" "1 2"
    do
        set -- $split
        dir="$(newCase "split$1x$2")"
        {
            echo 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }'
            echo "numberOfSubdomains 2;"
            echo "method simple;"
            echo "simpleCoeffs { n ($1 $2 1); delta 0.001; }"
        } > "$dir/system/decomposeParDict"
        if (
            cd "$dir" && decomposePar -force > log.decomposePar 2>&1 \
         && timeout 300 mpirun --oversubscribe -np 2 savageHutterFoam -parallel \
                -backend cpu > log.savageHutterFoam 2>&1 \
         && reconstructPar > log.reconstructPar 2>&1
        )
        then
            out="$($python "$project/bin/tools/compareDecomposed" "plan, $1 x $2" \
                "$ref" "$dir" "1 2 3 4" "$fields" 2>&1)"
            tally $? "$out" "plan, $1 x $2"
        elif grep -q "built without MPI" "$dir/log.savageHutterFoam" 2>/dev/null
        then
            skip "decomposed plan runs: savageHutterFoam was built without MPI"
            break
        else
            fail "decomposed plan run $1 x $2 (see $dir/log.*)"
        fi
    done
else
    skip "decomposed plan runs: no mpirun (bin/installDependencies installs openmpi-bin)"
fi

# 6. Single precision
sp="$(newCase single)"
if (cd "$sp" && savageHutterFoam -backend cpu -precision single > log.savageHutterFoam 2>&1)
then
    out="$($python - "$sp" "$ref" "$project" <<'PYEOF'
import os, re, sys
sys.path.insert(0, os.path.join(sys.argv[3], "tutorials", "tools"))
import foamCase
import numpy as np
sp, ref = sys.argv[1], sys.argv[2]
mp = open(ref + "/constant/terrainMapping").read()
d = float(re.search(r"cellSize\s+([0-9.eE+-]+);", mp).group(1))
released = float(re.search(r"releasedVolume\s+([0-9.eE+-]+);", mp).group(1))
H = np.asarray(foamCase.read_field(sp, "4", "H"))
dv = abs(H.sum()*d*d - released)/released
print("%s  single precision: volume at t = 4 the released to %.3g (bound 1e-5)" % ("PASS" if dv <= 1e-5 else "FAIL", dv))
dh = np.abs(np.asarray(foamCase.read_field(sp, "4", "h")) - np.asarray(foamCase.read_field(ref, "4", "h"))).max()
print("%s  single precision: h at t = 4 within %.3g m of the double run's (max over cells, bound 1e-2)" % ("PASS" if dh <= 1e-2 else "FAIL", dh))
PYEOF
)"
    tally $? "$out" "single precision"
else
    fail "-precision single (see $sp/log.savageHutterFoam)"
fi

# 7. Refusals
refusal()
{
    local dir="$1" what="$2" pattern="$3"
    shift 3
    (cd "$dir" && savageHutterFoam -backend cpu "$@" > log.refusal 2>&1)
    local rc=$?
    if [ $rc -ne 0 ] && grep -q "$pattern" "$dir/log.refusal" && [ -z "$(timeDirs "$dir")" ]
    then
        pass "$what: refused ('$pattern'), nothing written"
    else
        fail "$what: exit $rc, '$pattern' not in $dir/log.refusal or a time written"
    fi
}
en="$(newCase ensemble)"
cat > "$en/system/ensembleDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object ensembleDict; }
parameters { "CoulombCoeffs/delta" (20 24); }
combine         product;
thresholds      (0.01);
percentiles     (50);
runoutThreshold 0.01;
EOF
if (cd "$en" && savageHutterFoam -ensemble -backend cpu > log.savageHutterFoam 2>&1)
then
    # Member 1 has delta 24, the case's own: its fields the single run's
    # but for the steps (the single run's land on the centre of mass'
    # samples, ten per write interval, the ensemble's, which writes no
    # centreOfMass.dat, do not): h to 1e-2 m, the volume to 1e-12
    out="$($python - "$ref" "$en/ensemble" "$project" <<'EOF'
import os, sys
sys.path.insert(0, os.path.join(sys.argv[3], "tutorials", "tools"))
import foamCase
import numpy as np
ref, ens = sys.argv[1], sys.argv[2]
for t in ("2", "4"):
    a = np.asarray(foamCase.read_field(ref, t, "h"))
    b = np.asarray(foamCase.read_field(ens + "/member0001", t, "h"))
    c = np.asarray(foamCase.read_field(ens + "/member0000", t, "h"))
    Ha = np.asarray(foamCase.read_field(ref, t, "H")).sum()
    Hb = np.asarray(foamCase.read_field(ens + "/member0001", t, "H")).sum()
    d = np.abs(a - b).max()
    dv = abs(Ha - Hb)/Ha
    print("%s  -ensemble, plan: member delta 24 at t = %s: max |h - h_single| %.3g m (bound 1e-2), volume %.3g (bound 1e-12); member delta 20 %.3g m from it"
          % ("PASS" if d <= 1e-2 and dv <= 1e-12 and np.abs(c - b).max() > 10*d else "FAIL", t, d, dv, np.abs(c - b).max()))
EOF
)"
    tally $? "$out" "-ensemble in plan coordinates"
else
    fail "-ensemble -backend cpu in plan coordinates (see $en/log.savageHutterFoam)"
fi
inc="$(newCase inclination)"
foamDictionary -entry inclination -set "constant 10" "$inc/constant/transportProperties" > /dev/null
refusal "$inc" "coordinates plan with inclination 10" "the inclination must be 0"
unk="$(newCase unknown)"
foamDictionary -entry coordinates -set curvy "$unk/constant/transportProperties" > /dev/null
refusal "$unk" "coordinates curvy" "Valid choices: .*(slope plan)"

finish

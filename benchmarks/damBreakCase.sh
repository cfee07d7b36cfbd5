#------------------------------------------------------------------------------
# savageHutterFoam: Savage-Hutter granular avalanche solver
#
# Description
#     Sourced: damBreakCase <dir> <nx> <ny> makes the peers' common case
#     (docs/design.md section 4) in <dir> from tutorials/damBreak: a dam
#     break 1.0 | 0.5 m at x = nx/2 on a flat bed, 1 m cells, walls on
#     all sides (slip), fully wet, t = 0...30 s, written at 30 s, binary.
#     Shallow water as the Savage-Hutter equations give it: eps = 1,
#     K = 1 (isotropic), no friction (delta = 0), g = 9.81.  Expects
#     $project (the project's root) and the RunFunctions (runApplication,
#     setEntry, restore0Dir) and the application on the path.
#------------------------------------------------------------------------------
damBreakCase()
{
    local d="$1" nx="$2" ny="$3"
    mkdir -p "$d"
    cp -r "$project/tutorials/damBreak"/{0.orig,constant,system} "$d"/
    (
        cd "$d" || exit 1
        rm -rf constant/polyMesh
        cat > system/blockMeshDict <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices
(
    (0 0 0) ($nx 0 0) ($nx $ny 0) (0 $ny 0)
    (0 0 1) ($nx 0 1) ($nx $ny 1) (0 $ny 1)
);
blocks ( hex (0 1 2 3 4 5 6 7) ($nx $ny 1) simpleGrading (1 1 1) );
boundary
(
    upslope   { type wall; faces ((0 4 7 3)); }
    downslope { type wall; faces ((1 2 6 5)); }
    sides     { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOD
        cat > system/setAvalancheFieldsDict <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object setAvalancheFieldsDict; }
h ( damBreak { position $((nx/2)); upstream 1.0; downstream 0.5; } );
EOD
        sed -i -e '/upslope\|downslope\|sides/s/zeroGradient; }/slip; }/' 0.orig/U
        setEntry constant/transportProperties inclination "constant 0"
        setEntry constant/transportProperties CoulombCoeffs/delta 0
        setEntry system/controlDict endTime 30
        setEntry system/controlDict writeInterval 30
        setEntry system/controlDict writeFormat binary
        runApplication blockMesh
        restore0Dir
        runApplication setAvalancheFields
    )
}
#------------------------------------------------------------------------------

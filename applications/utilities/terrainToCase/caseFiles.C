/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "caseFiles.H"
#include "OSspecific.H"

#include "terrainFiles.H"
#include "defaultCaseFiles.H"

namespace Foam
{

namespace
{

//- The text of constant/transportProperties (terrainToCase sets its
//  entry `sets` and keeps the rest), or, where the case has none, the
//  commented defaults (defaultCaseFiles.H), announced
std::string transportPropertiesText(const fileName& tpFile, bool plan)
{
    if (!isFile(tpFile))
    {
        Info<< "Writing constant/transportProperties with the defaults"
            << " (Coulomb friction, delta 20 deg, phi 35 deg, rho 1500"
            << " kg/m^3; it was missing): check it before running"
            << " savageHutterFoam" << nl;
        return defaultTransportProperties(plan);
    }
    return terrainFiles::readText(tpFile);
}


//- What maps (x, y, z) back to the DEM's world coordinates
terrainFiles::mapping terrainMapping
(
    const terrainDem& dem, const chuteAxis& axis,
    const thalwegProfile& profile, const chuteGrid& grid,
    const releasedLayer& layer
)
{
    terrainFiles::mapping m;
    m.dem = dem.name;
    m.axis[0] = {axis.points[0].x(), axis.points[0].y()};
    m.axis[1] = {axis.points[1].x(), axis.points[1].y()};
    m.origin = {axis.P0.x(), axis.P0.y(), profile.Z0};
    m.tangent = {axis.t.x(), axis.t.y()};
    m.cellSize = grid.cellSize;
    m.nx = grid.nx;
    m.ny = grid.ny;
    m.yMax = grid.yMax;
    m.x = profile.x;
    m.zetaDeg = profile.zetaDeg;
    m.releasedVolume = layer.volume;
    return m;
}

} // End anonymous namespace


void writeCaseFiles
(
    const Time& runTime, const IOdictionary& dict, const terrainDem& dem,
    const chuteAxis& axis, const thalwegProfile& profile,
    const chuteGrid& grid, const scalarField& zb, const releasedLayer& layer
)
{
    const fileName tpFile = runTime.path()/"constant"/"transportProperties";
    const std::string tpText = transportPropertiesText(tpFile, false);

    terrainFiles::writeBlockMeshDict
    (
        runTime.path()/"system"/"blockMeshDict",
        grid.nx, grid.ny, grid.xMax, grid.yMax
    );
    terrainFiles::writeText
    (
        tpFile,
        terrainFiles::setInclination
        (
            tpText, profile.x, profile.zetaDeg, dict.name()
        )
    );
    mkDir(runTime.path()/"0");
    terrainFiles::writeScalarField
    (
        runTime.path()/"0"/"zb", "zb", "[0 1 0 0 0 0 0]", zb, "zeroGradient"
    );
    terrainFiles::writeScalarField
    (
        runTime.path()/"0"/"h", "h", "[0 1 0 0 0 0 0]", layer.h,
        "zeroGradient"
    );
    terrainFiles::writeVelocityField(runTime.path()/"0"/"U");
    terrainFiles::writeMapping
    (
        runTime.path()/"constant"/"terrainMapping",
        terrainMapping(dem, axis, profile, grid, layer)
    );
    writeMissingCaseFiles(runTime.path());

    Info<< "Wrote system/blockMeshDict, constant/transportProperties"
        << " (inclination), 0/zb, 0/h, 0/U, constant/terrainMapping" << nl
        << "Next: blockMesh, then savageHutterFoam" << nl << nl;
}

void writePlanCaseFiles
(
    const Time& runTime, const IOdictionary& dict, const terrainDem& dem,
    const planGrid& grid, const planBed& bed, const releasedLayer& layer
)
{
    const fileName tpFile = runTime.path()/"constant"/"transportProperties";
    bool hadInclination = false;
    const std::string tpText = terrainFiles::setPlanCoordinates
    (
        transportPropertiesText(tpFile, true),
        hadInclination
    );

    terrainFiles::writePlanBlockMeshDict
    (
        runTime.path()/"system"/"blockMeshDict",
        grid.nx, grid.ny, grid.xMax(), grid.yMax()
    );
    terrainFiles::writeText(tpFile, tpText);
    if (hadInclination)
    {
        Info<< "constant/transportProperties: its 'inclination' entry"
            << " removed (the plan mode has none: the bed zb is the DEM's"
            << " elevation)" << nl;
    }
    mkDir(runTime.path()/"0");
    terrainFiles::writePlanField
    (
        runTime.path()/"0"/"zb", "volScalarField", "zb", "[0 1 0 0 0 0 0]",
        bed.zb
    );
    terrainFiles::writePlanField
    (
        runTime.path()/"0"/"h", "volScalarField", "h", "[0 1 0 0 0 0 0]",
        layer.h
    );
    terrainFiles::writePlanField
    (
        runTime.path()/"0"/"U", "volVectorField", "U", "[0 1 -1 0 0 0 0]",
        std::vector<double>(), "(0 0 0)"
    );
    terrainFiles::planMapping m;
    m.dem = dem.name;
    m.origin = grid.origin;
    m.xAxis = grid.xAxis;
    m.yAxis = grid.yAxis;
    m.cellSize = grid.cellSize;
    m.nx = grid.nx;
    m.ny = grid.ny;
    m.releasedVolume = layer.volume;
    terrainFiles::writePlanMapping
    (
        runTime.path()/"constant"/"terrainMapping", m
    );
    writeMissingCaseFiles(runTime.path());

    Info<< "Wrote system/blockMeshDict, constant/transportProperties"
        << " (coordinates plan), 0/zb, 0/h, 0/U, constant/terrainMapping"
        << " (mode plan)" << nl
        << "Next: blockMesh, then savageHutterFoam" << nl << nl;
}

} // End namespace Foam

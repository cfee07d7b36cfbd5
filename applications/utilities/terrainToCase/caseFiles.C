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
    const areaLayer& layer
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


//- The optional fields of the areas (docs/design.md section 7): written
//  by `write` (path, name, dimensions, values) where terrainDict has the
//  entry; where it has none, a file the case has is left as it is, with
//  a warning (it was not made from this terrainDict); the names written
//  appended to `wrote`
template<class Writer>
void writeAreaFields
(
    const fileName& path, const caseLayers& layers, const Writer& write,
    std::string& wrote
)
{
    const struct
    {
        const char* name;
        const char* kind;
        const char* dims;
        const areaLayer& f;
    } fields[] =
    {
        {"hEntrainable", "entrainment", "[0 1 0 0 0 0 0]", layers.hEntrainable},
        {"cResistance", "resistance", "[0 -1 0 0 0 0 0]", layers.cResistance}
    };
    for (const auto& field : fields)
    {
        const fileName file = path/"0"/field.name;
        if (field.f.values.size())
        {
            write(file, field.name, field.dims, field.f.values);
            wrote += std::string(", 0/") + field.name;
        }
        else if (isFile(file))
        {
            WarningInFunction
                << file << " is left as it is: terrainDict has no "
                << field.kind << " entry to make it of (delete it if it"
                << " belongs to an earlier mesh)" << nl << endl;
        }
    }
}

} // End anonymous namespace


void writeCaseFiles
(
    const Time& runTime, const IOdictionary& dict, const terrainDem& dem,
    const chuteAxis& axis, const thalwegProfile& profile,
    const chuteGrid& grid, const scalarField& zb, const caseLayers& layers
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
        runTime.path()/"0"/"h", "h", "[0 1 0 0 0 0 0]", layers.h.values,
        "zeroGradient"
    );
    terrainFiles::writeVelocityField(runTime.path()/"0"/"U");
    std::string areaFiles;
    writeAreaFields
    (
        runTime.path(), layers,
        [](const fileName& file, const char* name, const char* dims,
            const scalarField& values)
        {
            terrainFiles::writeScalarField
            (
                file, name, dims, values, "zeroGradient"
            );
        },
        areaFiles
    );
    terrainFiles::writeMapping
    (
        runTime.path()/"constant"/"terrainMapping",
        terrainMapping(dem, axis, profile, grid, layers.h)
    );
    writeMissingCaseFiles(runTime.path());

    Info<< "Wrote system/blockMeshDict, constant/transportProperties"
        << " (inclination), 0/zb, 0/h, 0/U" << areaFiles.c_str()
        << ", constant/terrainMapping" << nl
        << "Next: blockMesh, then savageHutterFoam" << nl << nl;
}

void writePlanCaseFiles
(
    const Time& runTime, const IOdictionary& dict, const terrainDem& dem,
    const planGrid& grid, const planBed& bed, const caseLayers& layers
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
        layers.h.values
    );
    terrainFiles::writePlanField
    (
        runTime.path()/"0"/"U", "volVectorField", "U", "[0 1 -1 0 0 0 0]",
        std::vector<double>(), "(0 0 0)"
    );
    std::string areaFiles;
    writeAreaFields
    (
        runTime.path(), layers,
        [](const fileName& file, const char* name, const char* dims,
            const scalarField& values)
        {
            terrainFiles::writePlanField
            (
                file, "volScalarField", name, dims, values
            );
        },
        areaFiles
    );
    terrainFiles::planMapping m;
    m.dem = dem.name;
    m.origin = grid.origin;
    m.xAxis = grid.xAxis;
    m.yAxis = grid.yAxis;
    m.cellSize = grid.cellSize;
    m.nx = grid.nx;
    m.ny = grid.ny;
    m.releasedVolume = layers.h.volume;
    terrainFiles::writePlanMapping
    (
        runTime.path()/"constant"/"terrainMapping", m
    );
    writeMissingCaseFiles(runTime.path());

    Info<< "Wrote system/blockMeshDict, constant/transportProperties"
        << " (coordinates plan), 0/zb, 0/h, 0/U" << areaFiles.c_str()
        << ", constant/terrainMapping (mode plan)" << nl
        << "Next: blockMesh, then savageHutterFoam" << nl << nl;
}

} // End namespace Foam

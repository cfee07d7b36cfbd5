/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "hazardInput.H"
#include "timeSelector.H"
#include "IOdictionary.H"

namespace Foam
{

namespace
{

//- Which fields a time directory lacks for the maps ("" if none)
word missingFields(const fvMesh& mesh, const word& t)
{
    word missing;
    for (const word& name : {"hMax", "UMax", "h"})
    {
        if (!hasField(mesh, t, name))
        {
            missing += " " + name;
        }
    }
    return missing;
}


//- FatalError for the fields time t lacks
void missingFieldsError
(
    const fvMesh& mesh, const word& t, const word& missing
)
{
    FatalErrorInFunction
        << "No field" << missing << " in " << mesh.time().path()/t
        << " (h, hMax and UMax are written by savageHutterFoam)" << nl
        << "Nothing written." << nl << exit(FatalError);
}

} // End anonymous namespace


void declareOptions()
{
    argList::addNote
    (
        "Hazard maps (hMax, UMax, pMax, deposit, tArrival) of a terrain case"
        " as rasters on the DEM's grid, and a runout report, for each chosen"
        " time (default: the latest)"
    );
    timeSelector::addOptions(false, false);
    argList::addOption
    (
        "threshold", "scalar",
        "hMax [m] above which a cell belongs to the flow (default 0.01)"
    );
    argList::addBoolOption
    (
        "statistics",
        "rasters of an ensemble's statistics (ensemble/statistics/<time>/)"
        " instead of a run's hazard maps"
    );
    argList::noParallel();
    argList::noFunctionObjects();
}


scalar readThreshold(const argList& args)
{
    const scalar threshold = args.getOrDefault<scalar>("threshold", 0.01);
    if (!(threshold >= 0) || !(threshold < 1e30))
    {
        FatalErrorInFunction
            << "-threshold " << threshold << ": must be finite and >= 0"
            << nl << exit(FatalError);
    }
    return threshold;
}


fileName statisticsDir(const argList& args)
{
    return args.path()/"ensemble"/"statistics";
}


word statisticsTime(const argList& args)
{
    const fileName statsDir = statisticsDir(args);
    word statsTime;
    scalar best = -GREAT;
    const word wanted = args.getOrDefault<word>("time", word::null);
    scalar wantedValue = 0;
    const bool numeric = !wanted.empty() && readScalar(wanted, wantedValue);
    for (const instant& i : TimePaths::findTimes(statsDir))
    {
        if
        (
            wanted.empty() ? i.value() > best
          : (i.name() == wanted || (numeric && i.equal(wantedValue)))
        )
        {
            best = i.value();
            statsTime = i.name();
        }
    }
    if (statsTime.empty())
    {
        FatalErrorInFunction
            << "-statistics: no time directory"
            << (wanted.empty() ? "" : " " + wanted) << " in " << statsDir
            << " (written by savageHutterFoam -ensemble)" << nl
            << "Nothing written." << nl << exit(FatalError);
    }
    return statsTime;
}


hazardTimes selectTimes
(
    const Time& runTime, const argList& args, bool statistics
)
{
    hazardTimes times;
    times.numeric = numericTimes(runTime);
    if (!statistics && (args.found("time") || args.found("latestTime")))
    {
        times.chosen = selectedTimes(runTime, args, times.numeric);
    }
    else
    {
        times.chosen.append(times.numeric.last());
    }
    times.first = times.numeric.first().name();
    Info<< (times.chosen.size() == 1 ? "Time" : "Times");
    for (const instant& ti : times.chosen)
    {
        Info<< ' ' << ti.name();
    }
    Info<< " (release from time " << times.first << ")" << nl << endl;
    return times;
}


hazardTerrain readTerrain(const Time& runTime, const fvMesh& mesh)
{
    const IOdictionary mapDict(terrainMappingIO(runTime));
    const IOdictionary tp(transportPropertiesIO(runTime));
    hazardTerrain ht;
    ht.plan = planMode(mapDict, tp);
    if (ht.plan)
    {
        ht.grid = mappingPlan(mapDict);
        ht.cellSize = ht.grid.cellSize;
        ht.nx = ht.grid.nx;
        ht.ny = ht.grid.ny;
        ht.yMin = 0;
    }
    else
    {
        ht.surface = mappingSurface(mapDict);
        ht.cellSize = mapDict.get<scalar>("cellSize");
        ht.nx = mapDict.get<label>("nx");
        ht.ny = mapDict.get<label>("ny");
        ht.yMin = mapDict.get<scalar>("yMin");
    }
    if (mesh.nCells() != ht.nx*ht.ny)
    {
        FatalIOErrorInFunction(mapDict)
            << "nx " << ht.nx << " x ny " << ht.ny << " cells, but the mesh"
            << " has " << mesh.nCells() << ": run blockMesh after"
            << " terrainToCase" << nl << exit(FatalIOError);
    }
    fileName demFile = mapDict.get<fileName>("dem");
    demFile.expand();
    if (!demFile.isAbsolute())
    {
        demFile = runTime.path()/demFile;
    }
    try
    {
        ht.dem = terrain::readRaster(demFile);
    }
    catch (const terrain::gdalError& e)
    {
        FatalIOErrorInFunction(mapDict)
            << "keyword 'dem': " << e.what() << nl << exit(FatalIOError);
    }
    if (ht.plan)
    {
        ht.planRaster = planRaster(ht.grid, ht.dem.wkt);
    }
    return ht;
}


terrain::Raster planRaster(const planGrid& g, const std::string& wkt)
{
    // Pixel corner (c, r) at X = origin + cellSize (c xAxis + (ny - r)
    // yAxis): row 0 the grid's last row (largest y), as rasters run
    const double cs = g.cellSize;
    terrain::Raster r;
    r.nx = int(g.nx);
    r.ny = int(g.ny);
    r.gt =
    {
        g.origin[0] + g.ny*cs*g.yAxis[0], cs*g.xAxis[0], 0 - cs*g.yAxis[0],
        g.origin[1] + g.ny*cs*g.yAxis[1], cs*g.xAxis[1], 0 - cs*g.yAxis[1]
    };
    r.wkt = wkt;
    return r;
}


densityInput readDensity(const Time& runTime)
{
    const IOdictionary tp(transportPropertiesIO(runTime));
    densityInput d;
    d.hasRho = tp.found("rho");
    d.rho = tp.getOrDefault<scalar>("rho", 0);
    d.file = tp.objectPath();
    if (d.hasRho && (!(d.rho > 0) || !(d.rho < 1e30)))
    {
        FatalIOErrorInFunction(tp)
            << "keyword 'rho' = " << d.rho << ": must be > 0" << nl
            << exit(FatalIOError);
    }
    return d;
}


void checkTimes
(
    const fvMesh& mesh, const hazardTimes& times, const volScalarField& h0,
    const densityInput& density, scalar threshold, bool statistics
)
{
    if (!statistics && !(gMax(h0.primitiveField()) > 0))
    {
        FatalErrorInFunction
            << "No release: h = 0 at the first time, " << times.first << nl
            << exit(FatalError);
    }
    for (const instant& ti : statistics ? instantList() : times.chosen)
    {
        const word missing = missingFields(mesh, ti.name());
        if (!missing.empty())
        {
            missingFieldsError(mesh, ti.name(), missing);
        }
        const volScalarField hMax(fieldIO(mesh, ti.name(), "hMax"), mesh);
        if (!(gMax(hMax.primitiveField()) > threshold))
        {
            FatalErrorInFunction
                << "No cell has hMax above the threshold " << threshold
                << " m at time " << ti.name() << " (-threshold)." << nl
                << "Nothing written." << nl << exit(FatalError);
        }
    }
}

} // End namespace Foam

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    hazardMaps

Description
    Hazard maps of a terrain case (made by terrainToCase) on the DEM's grid
    and georeference, and a report of volumes, runout and travel angles.
    Run in the case directory after savageHutterFoam; reads
    constant/terrainMapping and, at each chosen time (default the latest),
    hMax, UMax, pMax, tArrival, h and zb as savageHutterFoam wrote them.
    pMax is the solver's field (rho |u|^2 peaked every step; written when
    constant/transportProperties has rho); without it, rho UMax^2 from the
    rho of transportProperties (the same to round-off: the peak of |u|^2
    is the square of the peak of |u|); with neither, an error.  A run of
    an older version without tArrival gets no arrival-time map (said so).

    Writes postProcessing/hazardMaps/<time>/ for each time:
        hMax, UMax, pMax, deposit (h at that time), tArrival
                        as .asc and .tif: each DEM pixel takes the value of
                        the mesh cell that holds the foot of its normal on
                        the reference surface; nodata (-9999) outside the
                        mesh and where hMax <= threshold (outside the
                        flow), and in tArrival where the material never
                        arrived (-1: h never exceeded arrivalThreshold);
                        a rotated DEM's as .tif alone (ESRI ASCII grids are
                        north-up)
        report.dat      lines "key value":
            releasedVolume  sum of h dA at the first time directory [m^3]
            depositVolume   sum of h dA at that time [m^3]
            runoutX/Y/Z     world position of the bed in the cell furthest
                            along the axis with hMax > threshold (of that
                            row of cells, the one with the largest hMax)
            travelAngle     [deg] atan(drop / horizontal distance) from the
                            highest released point to the runout point
            comTravelAngle  [deg] the same between the centres of mass of
                            the release and of the material at that time
    Every chosen time is checked (hMax, UMax, h, and pMax or rho) before
    anything is written.

    -statistics: instead, the statistics of an ensemble (savageHutterFoam
    -ensemble, ensemble/statistics/<time>/: hMaxExceedance_<thr>,
    hMaxMean, hMaxP<p>, UMax..., pMax...) as rasters in
    postProcessing/hazardMaps/ensemble/<time>/, each pixel the value of its
    cell, nodata outside the mesh only (a probability of 0 is a value).
    The latest time of ensemble/statistics, or the one -time names.

Usage
    hazardMaps [-time <ranges> | -latestTime] [-threshold 0.01]
        -time 10,20, -time '10:30' (OpenFOAM's time ranges; a single value
        picks the nearest time), -latestTime; default: the latest time
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "vector2D.H"
#include "OSspecific.H"
#include "timeSelector.H"

#include "gdalIO.H"
#include "referenceSurface.H"

#include <fstream>
#include <iomanip>

using namespace Foam;

namespace
{

IOobject fieldIO(const fvMesh& mesh, const word& instance, const word& name)
{
    return IOobject
    (
        name, instance, mesh, IOobject::MUST_READ, IOobject::NO_WRITE
    );
}

bool hasField(const fvMesh& mesh, const word& instance, const word& name)
{
    return fieldIO(mesh, instance, name).typeHeaderOk<volScalarField>(true);
}

//- The world position of cell c's bed
terrain::vec3 bedPoint
(
    const terrain::referenceSurface& s, const point& C, scalar zb
)
{
    return s.world(C.x(), C.y(), zb);
}

scalar travelAngle(const terrain::vec3& a, const terrain::vec3& b)
{
    const scalar dist = std::hypot(b[0] - a[0], b[1] - a[1]);
    return radToDeg(std::atan2(a[2] - b[2], dist));
}

//- Which fields a time directory lacks for the maps ("" if none)
word missingFields(const fvMesh& mesh, const word& t, const bool hasRho)
{
    word missing;
    for (const word& name : {"hMax", "UMax", "h"})
    {
        if (!hasField(mesh, t, name))
        {
            missing += " " + name;
        }
    }
    if (!hasRho && !hasField(mesh, t, "pMax"))
    {
        missing += " pMax";
    }
    return missing;
}

//- A raster on the DEM's grid from the value of each pixel's cell where
//  `keep` says so, nodata (-9999) elsewhere, written as .asc and .tif (a
//  rotated DEM's grid as GeoTIFF alone: ESRI ASCII is north-up)
template<class Keep>
void writeMap
(
    const fileName& base,
    const terrain::Raster& dem,
    const labelList& pixelCell,
    const scalarField& f,
    const Keep& keep
)
{
    terrain::Raster r;
    r.nx = dem.nx;
    r.ny = dem.ny;
    r.gt = dem.gt;
    r.wkt = dem.wkt;
    r.hasNodata = true;
    r.nodata = -9999;
    r.z.assign(std::size_t(r.nx)*r.ny, r.nodata);
    forAll(pixelCell, p)
    {
        const label c = pixelCell[p];
        if (c >= 0 && keep(c))
        {
            r.z[p] = f[c];
        }
    }
    for (const std::string& ext : terrain::rasterExtensions(dem))
    {
        try
        {
            terrain::writeRaster(base + ext, r);
        }
        catch (const terrain::gdalError& e)
        {
            FatalErrorInFunction << e.what() << nl << exit(FatalError);
        }
    }
}

} // namespace


int main(int argc, char *argv[])
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

    #include "setRootCase.H"
    #include "createTime.H"

    const scalar threshold = args.getOrDefault<scalar>("threshold", 0.01);
    if (!(threshold >= 0) || !(threshold < 1e30))
    {
        FatalErrorInFunction
            << "-threshold " << threshold << ": must be finite and >= 0"
            << nl << exit(FatalError);
    }

    const bool statistics = args.found("statistics");
    const fileName statsDir = args.path()/"ensemble"/"statistics";
    word statsTime;
    if (statistics)
    {
        // The statistics' time: the latest, or the one -time names
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
    }

    // Numeric time directories (times() also lists constant)
    instantList numeric;
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant())
        {
            numeric.append(t);
        }
    }
    if (numeric.empty())
    {
        FatalErrorInFunction
            << "No time directory in " << runTime.path() << nl
            << exit(FatalError);
    }
    instantList chosen;
    if (!statistics && (args.found("time") || args.found("latestTime")))
    {
        for
        (
            const instant& t
          : timeSelector::select(runTime.times(), args, runTime.constant())
        )
        {
            if (t.name() != runTime.constant())
            {
                chosen.append(t);
            }
        }
    }
    else
    {
        chosen.append(numeric.last());
    }
    if (chosen.empty())
    {
        FatalErrorInFunction
            << "No time selected in " << runTime.path() << "; times: "
            << flatOutput(numeric) << nl << exit(FatalError);
    }
    runTime.setTime(chosen.first(), 0);
    const word first = numeric.first().name();
    Info<< "Times " << flatOutput(chosen) << " (release from time " << first
        << ")" << nl << endl;

    #include "createMesh.H"

    // -- The terrain mapping and the DEM ------------------------------------
    const IOdictionary mapDict
    (
        IOobject
        (
            "terrainMapping", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const List<vector2D> table = mapDict.get<List<vector2D>>("inclination");
    std::vector<double> xT, zT;
    for (const vector2D& p : table)
    {
        xT.push_back(p.x());
        zT.push_back(p.y());
    }
    const vector o = mapDict.get<vector>("origin");
    const vector2D t = mapDict.get<vector2D>("tangent");
    const terrain::referenceSurface surface
    (
        {o.x(), o.y(), o.z()}, t.x(), t.y(), xT, zT
    );
    const scalar cellSize = mapDict.get<scalar>("cellSize");
    const label nx = mapDict.get<label>("nx");
    const label ny = mapDict.get<label>("ny");
    const scalar yMin = mapDict.get<scalar>("yMin");
    if (mesh.nCells() != nx*ny)
    {
        FatalIOErrorInFunction(mapDict)
            << "nx " << nx << " x ny " << ny << " cells, but the mesh has "
            << mesh.nCells() << ": run blockMesh after terrainToCase" << nl
            << exit(FatalIOError);
    }
    fileName demFile = mapDict.get<fileName>("dem");
    demFile.expand();
    if (!demFile.isAbsolute())
    {
        demFile = runTime.path()/demFile;
    }
    terrain::Raster dem;
    try
    {
        dem = terrain::readRaster(demFile);
    }
    catch (const terrain::gdalError& e)
    {
        FatalIOErrorInFunction(mapDict)
            << "keyword 'dem': " << e.what() << nl << exit(FatalIOError);
    }

    // rho of transportProperties: pMax where the solver wrote none
    const IOdictionary tp
    (
        IOobject
        (
            "transportProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const bool hasRho = tp.found("rho");
    const scalar rho = tp.getOrDefault<scalar>("rho", 0);
    if (hasRho && (!(rho > 0) || !(rho < 1e30)))
    {
        FatalIOErrorInFunction(tp)
            << "keyword 'rho' = " << rho << ": must be > 0" << nl
            << exit(FatalIOError);
    }

    // -- Every chosen time has what the maps need -----------------------------
    const volScalarField h0(fieldIO(mesh, first, "h"), mesh);
    if (!statistics && !(gMax(h0.primitiveField()) > 0))
    {
        FatalErrorInFunction
            << "No release: h = 0 at the first time, " << first << nl
            << exit(FatalError);
    }
    for (const instant& ti : statistics ? instantList() : chosen)
    {
        const word missing = missingFields(mesh, ti.name(), hasRho);
        if (missing.empty())
        {
            const volScalarField hMax(fieldIO(mesh, ti.name(), "hMax"), mesh);
            if (!(gMax(hMax.primitiveField()) > threshold))
            {
                FatalErrorInFunction
                    << "No cell has hMax above the threshold " << threshold
                    << " m at time " << ti.name() << " (-threshold)." << nl
                    << "Nothing written." << nl << exit(FatalError);
            }
            continue;
        }
        FatalErrorInFunction
            << "No field" << missing << " in " << runTime.path()/ti.name()
            << " (hMax, UMax and tArrival are written by savageHutterFoam,"
            << " pMax when constant/transportProperties has rho)" << nl;
        if (missing.find("pMax") != std::string::npos)
        {
            FatalError
                << "The peak pressure map needs the field pMax or rho [kg/m^3]"
                << " in " << tp.objectPath() << " (then pMax = rho UMax^2)"
                << nl;
        }
        FatalError << "Nothing written." << nl << exit(FatalError);
    }

    // Mesh cell of each (i, j) of the structured grid
    labelList cellOf(nx*ny, -1);
    const volVectorField& C = mesh.C();
    forAll(C, c)
    {
        const label i = label(std::floor(C[c].x()/cellSize));
        const label j = label(std::floor((C[c].y() - yMin)/cellSize));
        if (i >= 0 && i < nx && j >= 0 && j < ny)
        {
            cellOf[i + nx*j] = c;
        }
    }

    // -- Pixels to cells -----------------------------------------------------
    labelList pixelCell(dem.nx*dem.ny, -1);
    for (label j = 0; j < dem.ny; ++j)
    {
        for (label i = 0; i < dem.nx; ++i)
        {
            const double Z = dem.at(i, j);
            if (!dem.valid(Z))
            {
                continue;
            }
            const std::array<double, 2> P = dem.point(i + 0.5, j + 0.5);
            const double X = P[0], Y = P[1];
            double x = 0, y = 0, z = 0;
            if (!surface.local({X, Y, Z}, x, y, z))
            {
                continue;
            }
            const label ci = label(std::floor(x/cellSize));
            const label cj = label(std::floor((y - yMin)/cellSize));
            if (ci >= 0 && ci < nx && cj >= 0 && cj < ny)
            {
                pixelCell[i + dem.nx*j] = cellOf[ci + nx*cj];
            }
        }
    }

    if (statistics)
    {
        // Every scalar field of the statistics' time but zb
        const fileName inst = fileName("ensemble")/"statistics"/statsTime;
        const fileName outDir =
            runTime.path()/"postProcessing"/"hazardMaps"/"ensemble"/statsTime;
        wordList names;
        for (const fileName& f : readDir(statsDir/statsTime, fileName::FILE))
        {
            if (f != "zb")
            {
                names.append(f);
            }
        }
        Foam::sort(names);
        if (names.empty())
        {
            FatalErrorInFunction
                << "-statistics: no fields in " << statsDir/statsTime << nl
                << "Nothing written." << nl << exit(FatalError);
        }
        PtrList<volScalarField> fields;
        for (const word& name : names)
        {
            fields.append
            (
                new volScalarField
                (
                    IOobject
                    (
                        name, inst, mesh, IOobject::MUST_READ,
                        IOobject::NO_WRITE, false
                    ),
                    mesh
                )
            );
        }
        mkDir(outDir);
        forAll(fields, k)
        {
            const scalarField& f = fields[k].primitiveField();
            writeMap
            (
                outDir/names[k], dem, pixelCell, f,
                [](const label) { return true; }
            );
            Info<< "    Wrote " << names[k] << ": range [" << gMin(f) << ", "
                << gMax(f) << "]" << nl;
        }
        Info<< "    Wrote " << outDir << nl << nl << "End\n" << endl;
        return 0;
    }

    for (const instant& ti : chosen)
    {
        const word now = ti.name();
        Info<< "Time " << now << nl;

        // -- Fields ----------------------------------------------------------
        const volScalarField hMax(fieldIO(mesh, now, "hMax"), mesh);
        const volScalarField UMax(fieldIO(mesh, now, "UMax"), mesh);
        const volScalarField h(fieldIO(mesh, now, "h"), mesh);
        const word zbTime = hasField(mesh, now, "zb") ? now : first;
        const volScalarField zb(fieldIO(mesh, zbTime, "zb"), mesh);

        HashTable<scalarField> maps;
        maps.insert("hMax", hMax.primitiveField());
        maps.insert("UMax", UMax.primitiveField());
        maps.insert("deposit", h.primitiveField());
        if (hasField(mesh, now, "pMax"))
        {
            maps.insert
            (
                "pMax",
                volScalarField(fieldIO(mesh, now, "pMax"), mesh)
                    .primitiveField()
            );
        }
        else
        {
            Info<< "    No field pMax: pMax = rho UMax^2, rho " << rho
                << " kg/m^3 (transportProperties)" << nl;
            maps.insert("pMax", scalarField(rho*sqr(UMax.primitiveField())));
        }
        if (hasField(mesh, now, "tArrival"))
        {
            maps.insert
            (
                "tArrival",
                volScalarField(fieldIO(mesh, now, "tArrival"), mesh)
                    .primitiveField()
            );
        }
        else
        {
            Info<< "    No field tArrival (a run of an older version): no"
                << " arrival-time map" << nl;
        }

        // -- Rasters ---------------------------------------------------------
        const fileName outDir =
            runTime.path()/"postProcessing"/"hazardMaps"/now;
        mkDir(outDir);
        for (const word& name : maps.sortedToc())
        {
            const scalarField& f = maps[name];
            // -1 in tArrival: never arrived
            const bool arrival = name == "tArrival";
            writeMap
            (
                outDir/name, dem, pixelCell, f,
                [&](const label c)
                {
                    return hMax[c] > threshold && !(arrival && f[c] < 0);
                }
            );
            Info<< "    Wrote " << name << " ("
                << (dem.northUp() ? ".asc, .tif" : ".tif") << "): range ["
                << gMin(f) << ", " << gMax(f) << "]" << nl;
        }

        // -- Report ----------------------------------------------------------
        const scalar cellArea = cellSize*cellSize;
        scalar released = 0, deposit = 0;
        terrain::vec3 top{0, 0, -GREAT}, com0{0, 0, 0}, com1{0, 0, 0};
        label runoutCell = -1;
        forAll(C, c)
        {
            const terrain::vec3 W = bedPoint(surface, C[c], zb[c]);
            released += h0[c]*cellArea;
            deposit += h[c]*cellArea;
            for (int k = 0; k < 3; ++k)
            {
                com0[k] += h0[c]*W[k];
                com1[k] += h[c]*W[k];
            }
            if (h0[c] > 0 && W[2] > top[2])
            {
                top = W;
            }
            if (hMax[c] > threshold)
            {
                if
                (
                    runoutCell < 0
                 || C[c].x() > C[runoutCell].x() + 0.5*cellSize
                 || (
                        C[c].x() > C[runoutCell].x() - 0.5*cellSize
                     && hMax[c] > hMax[runoutCell]
                    )
                )
                {
                    runoutCell = c;
                }
            }
        }
        for (int k = 0; k < 3; ++k)
        {
            com0[k] /= released/cellArea;
            com1[k] /= deposit > 0 ? deposit/cellArea : 1;
        }
        const terrain::vec3 runout =
            bedPoint(surface, C[runoutCell], zb[runoutCell]);

        OFstream report(outDir/"report.dat");
        report.precision(10);
        report
            << "# hazardMaps: time " << now << ", threshold "
            << threshold << " m on hMax" << nl
            << "releasedVolume " << released << nl
            << "depositVolume " << deposit << nl
            << "runoutX " << runout[0] << nl
            << "runoutY " << runout[1] << nl
            << "runoutZ " << runout[2] << nl
            << "travelAngle " << travelAngle(top, runout) << nl
            << "comTravelAngle " << travelAngle(com0, com1) << nl;
        Info<< "    Released volume " << released << " m^3, at time "
            << now << " " << deposit << " m^3" << nl
            << "    Runout point (" << runout[0] << " " << runout[1] << " "
            << runout[2] << "), travel angle " << travelAngle(top, runout)
            << " deg, centre of mass " << travelAngle(com0, com1) << " deg"
            << nl << "    Wrote " << outDir << nl << endl;
    }
    Info<< "End\n" << endl;
    return 0;
}

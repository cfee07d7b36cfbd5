/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "hazardRasters.H"
#include "OSspecific.H"
#include "PtrList.H"

namespace Foam
{

namespace
{

//- A raster on the maps' grid (the DEM's or the plan grid) from the
//  value of each pixel's cell where `keep` says so, nodata (-9999)
//  elsewhere, written as .asc and .tif (a rotated grid as GeoTIFF alone:
//  ESRI ASCII is north-up)
template<class Keep>
void writeMap
(
    const fileName& base,
    const terrain::Raster& grid,
    const labelList& pixelCell,
    const scalarField& f,
    const Keep& keep
)
{
    terrain::Raster r;
    r.nx = grid.nx;
    r.ny = grid.ny;
    r.gt = grid.gt;
    r.wkt = grid.wkt;
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
    for (const std::string& ext : terrain::rasterExtensions(grid))
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


} // End anonymous namespace


labelList gridCells(const fvMesh& mesh, const hazardTerrain& t)
{
    labelList cellOf(t.nx*t.ny, -1);
    const volVectorField& C = mesh.C();
    forAll(C, c)
    {
        const label i = label(std::floor(C[c].x()/t.cellSize));
        const label j = label(std::floor((C[c].y() - t.yMin)/t.cellSize));
        if (i >= 0 && i < t.nx && j >= 0 && j < t.ny)
        {
            cellOf[i + t.nx*j] = c;
        }
    }
    return cellOf;
}


labelList pixelCells(const fvMesh& mesh, const hazardTerrain& t)
{
    const labelList cellOf = gridCells(mesh, t);
    if (t.plan)
    {
        // Pixel (i, r) of the plan raster: cell (i, ny - 1 - r)
        labelList pixelCell(t.nx*t.ny, -1);
        for (label r = 0; r < t.ny; ++r)
        {
            for (label i = 0; i < t.nx; ++i)
            {
                pixelCell[i + t.nx*r] = cellOf[i + t.nx*(t.ny - 1 - r)];
            }
        }
        return pixelCell;
    }
    const terrain::Raster& dem = t.dem;
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
            if (!t.surface.local({X, Y, Z}, x, y, z))
            {
                continue;
            }
            const label ci = label(std::floor(x/t.cellSize));
            const label cj = label(std::floor((y - t.yMin)/t.cellSize));
            if (ci >= 0 && ci < t.nx && cj >= 0 && cj < t.ny)
            {
                pixelCell[i + dem.nx*j] = cellOf[ci + t.nx*cj];
            }
        }
    }
    return pixelCell;
}


void writeStatistics
(
    const argList& args, const fvMesh& mesh, const terrain::Raster& grid,
    const labelList& pixelCell, const word& statsTime
)
{
    // Every scalar field of the statistics' time but zb
    const fileName statsDir = statisticsDir(args);
    const fileName inst = fileName("ensemble")/"statistics"/statsTime;
    const fileName outDir = mesh.time().path()/"postProcessing"/"hazardMaps"
        /"ensemble"/statsTime;
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
            outDir/names[k], grid, pixelCell, f,
            [](const label) { return true; }
        );
        Info<< "    Wrote " << names[k] << ": range [" << gMin(f) << ", "
            << gMax(f) << "]" << nl;
    }
    Info<< "    Wrote " << outDir << nl << endl;
}


hazardFields::hazardFields
(
    const fvMesh& mesh, const word& now, const word& first,
    const densityInput& density
)
:
    hMax(fieldIO(mesh, now, "hMax"), mesh),
    UMax(fieldIO(mesh, now, "UMax"), mesh),
    h(fieldIO(mesh, now, "h"), mesh),
    zb(fieldIO(mesh, hasField(mesh, now, "zb") ? now : first, "zb"), mesh),
    erodible
    (
        hasField(mesh, now, "erodedDepth")
     || hasField(mesh, now, "hEntrainable")
     || hasField(mesh, first, "hEntrainable")
    )
{
    maps.insert("hMax", hMax.primitiveField());
    maps.insert("UMax", UMax.primitiveField());
    maps.insert("deposit", h.primitiveField());
    if (hasField(mesh, now, "pMax"))
    {
        maps.insert
        (
            "pMax",
            volScalarField(fieldIO(mesh, now, "pMax"), mesh).primitiveField()
        );
    }
    else if (density.hasRho)
    {
        Info<< "    No field pMax: pMax = rho UMax^2, rho " << density.rho
            << " kg/m^3 (transportProperties)" << nl;
        maps.insert
        (
            "pMax", scalarField(density.rho*sqr(UMax.primitiveField()))
        );
    }
    else
    {
        skipped.append
        (
            "pMax skipped: no rho in " + density.file.relative
            (
                mesh.time().path()
            )
          + " and no field pMax in " + now
          + " (add rho [kg/m^3] to have pMax = rho UMax^2)"
        );
    }
    // The erodible layer's maps, where the run had one (section 7)
    if (hasField(mesh, now, "erodedDepth"))
    {
        erodedDepth =
            volScalarField(fieldIO(mesh, now, "erodedDepth"), mesh)
                .primitiveField();
        maps.insert("erodedDepth", erodedDepth);
    }
    if (hasField(mesh, now, "hEntrainable"))
    {
        maps.insert
        (
            "hEntrainable",
            volScalarField(fieldIO(mesh, now, "hEntrainable"), mesh)
                .primitiveField()
        );
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
        skipped.append
        (
            "tArrival skipped: no field tArrival in " + now
          + " (a run of an older version)"
        );
    }
}


void writeMaps
(
    const fileName& outDir, const hazardFields& fields,
    const terrain::Raster& grid, const labelList& pixelCell,
    scalar threshold
)
{
    const volScalarField& hMax = fields.hMax;
    mkDir(outDir);
    for (const word& name : fields.maps.sortedToc())
    {
        const scalarField& f = fields.maps[name];
        // -1 in tArrival: never arrived; the deposit masked by itself
        // (h > threshold at that time), the eroded depth too (where
        // anything was eroded: its volume is in the report whatever hMax
        // was there), the layer left not at all, the others by hMax
        const bool arrival = name == "tArrival";
        const bool deposit = name == "deposit";
        const bool eroded = name == "erodedDepth";
        const bool layer = name == "hEntrainable";
        writeMap
        (
            outDir/name, grid, pixelCell, f,
            [&](const label c)
            {
                if (deposit)
                {
                    return f[c] > threshold;
                }
                if (eroded)
                {
                    return f[c] > 0;
                }
                if (layer)
                {
                    return true;
                }
                return hMax[c] > threshold && !(arrival && f[c] < 0);
            }
        );
        Info<< "    Wrote " << name << " ("
            << (grid.northUp() ? ".asc, .tif" : ".tif") << "): range ["
            << gMin(f) << ", " << gMax(f) << "]" << nl;
    }
    for (const string& why : fields.skipped)
    {
        Info<< "    " << why.c_str() << nl;
    }
}

} // End namespace Foam

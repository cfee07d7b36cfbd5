/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "terrainDem.H"
#include "terrainInput.H"

#include <sstream>

namespace Foam
{

namespace
{

//- FatalIOError for keyword dem with GDAL's complaint
void demError(const dictionary& dict, const terrain::gdalError& e)
{
    FatalIOErrorInFunction(dict)
        << "keyword 'dem': " << e.what() << nl << exit(FatalIOError);
}


//- Elevations finite where not nodata (NaN pixels count as nodata)
void checkElevations
(
    const terrain::Raster& dem, const fileName& demFile,
    const dictionary& dict
)
{
    for (int j = 0; j < dem.ny; ++j)
    {
        for (int i = 0; i < dem.nx; ++i)
        {
            const double v = dem.at(i, j);
            if (dem.valid(v) && !std::isfinite(v))
            {
                const std::array<double, 2> P = dem.point(i + 0.5, j + 0.5);
                FatalIOErrorInFunction(dict)
                    << "keyword 'dem': " << demFile << " holds the elevation "
                    << v << " at pixel (" << i << ", " << j << ") (X = "
                    << P[0] << ", Y = " << P[1] << "): elevations must be"
                    << " finite (nodata: the raster's nodata value or NaN)"
                    << nl << exit(FatalIOError);
            }
        }
    }
}


//- Where the DEM has values: between its outermost pixel centres
std::string valueExtentOf(const terrain::Raster& dem)
{
    const std::array<double, 4> valueBox = dem.sampledBounds();
    std::ostringstream valueExtent;
    valueExtent
        << "its values (bilinear between pixel centres) reach X in ["
        << valueBox[0] << ", " << valueBox[1] << "], Y in [" << valueBox[2]
        << ", " << valueBox[3] << "]"
        << (dem.northUp() ? "" : " (rotated; their bounding box)")
        << ", half a pixel inside its outline";
    return valueExtent.str();
}

} // End anonymous namespace


terrainDem readDem(const Time& runTime, const dictionary& dict)
{
    terrainDem d;
    d.name = dict.get<fileName>("dem");
    try
    {
        terrain::rasterDriver(d.name);
    }
    catch (const terrain::gdalError& e)
    {
        demError(dict, e);
    }
    d.file = caseFile(runTime, dict, "dem");
    try
    {
        d.raster = terrain::readRaster(d.file);
    }
    catch (const terrain::gdalError& e)
    {
        demError(dict, e);
    }
    const terrain::Raster& dem = d.raster;
    checkElevations(dem, d.file, dict);
    d.valueExtent = valueExtentOf(dem);

    const std::array<double, 4> demBox = dem.bounds();
    Info<< "DEM " << d.file << ": " << dem.nx << " x " << dem.ny
        << " pixels of " << std::hypot(dem.gt[1], dem.gt[4]) << " x "
        << std::hypot(dem.gt[2], dem.gt[5]) << " m, "
        << (dem.northUp() ? "" : "rotated grid, bounding box ")
        << "X in [" << demBox[0] << ", " << demBox[1] << "], Y in ["
        << demBox[2] << ", " << demBox[3] << "]" << nl;
    return d;
}

} // End namespace Foam

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "releaseInput.H"
#include "terrainInput.H"
#include "vector2D.H"

namespace Foam
{

namespace
{

//- FatalIOError for keyword key of release name with GDAL's complaint
void releaseError
(
    const dictionary& d, const word& key, const word& name,
    const terrain::gdalError& err
)
{
    FatalIOErrorInFunction(d)
        << "keyword '" << key << "' of release " << name << ": "
        << err.what() << nl << exit(FatalIOError);
}


//- A crsTransform from a file's system to the DEM's, its warning and
//  what it does announced; FatalIOError naming the keyword when none
std::unique_ptr<terrain::crsTransform> toDemSystem
(
    const std::string& wkt, const std::string& demWkt, const fileName& file,
    const dictionary& d, const word& key, const word& releaseName
)
{
    std::unique_ptr<terrain::crsTransform> t;
    try
    {
        t.reset(new terrain::crsTransform(wkt, demWkt, file));
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, key, releaseName, err);
    }
    if (!t->warning().empty())
    {
        WarningInFunction
            << "release " << releaseName << ": " << t->warning().c_str()
            << nl << endl;
    }
    if (!t->identity())
    {
        Info<< "    release " << releaseName << ": " << file
            << " transformed " << t->description().c_str() << nl;
    }
    return t;
}


//- The release raster's values as thickness: finite and >= 0 where not
//  nodata (nodata and 0: no release)
void checkThicknessRaster
(
    const terrain::Raster& r, const fileName& file, const dictionary& d,
    const word& releaseName
)
{
    const bool nanIsNodata = r.hasNodata && std::isnan(r.nodata);
    for (int j = 0; j < r.ny; ++j)
    {
        for (int i = 0; i < r.nx; ++i)
        {
            const double v = r.at(i, j);
            const bool bad =
                std::isnan(v) ? !nanIsNodata
              : r.valid(v) && (v < 0 || !(v < 1e30));
            if (bad)
            {
                const std::array<double, 2> P = r.point(i + 0.5, j + 0.5);
                FatalIOErrorInFunction(d)
                    << "keyword 'raster' of release " << releaseName << ": "
                    << file << " holds the thickness " << v << " at pixel ("
                    << i << ", " << j << ") (X = " << P[0] << ", Y = " << P[1]
                    << "): thickness must be finite and >= 0 (nodata and 0:"
                    << " no release)" << nl << exit(FatalIOError);
            }
        }
    }
}


//- Which of polygon, file and raster the release gives: exactly one
word shapeKeyOf(const dictionary& d, const word& name)
{
    wordList shapes;
    for (const word& key : {"polygon", "file", "raster"})
    {
        if (d.found(key))
        {
            shapes.append(key);
        }
    }
    if (shapes.size() != 1)
    {
        std::string given = shapes.empty() ? " none" : " several:";
        for (const word& key : shapes)
        {
            given += " '" + key + "'";
        }
        FatalIOErrorInFunction(d)
            << "release " << name << ": give one of 'polygon' ((X Y)"
            << " ...), 'file' (a shapefile) or 'raster' (a thickness"
            << " raster), not" << given.c_str() << nl
            << exit(FatalIOError);
    }
    return shapes[0];
}


//- polygon ((X Y) ...): at least three vertices
void readPolygon(const dictionary& d, release& r)
{
    const List<vector2D> pts = d.get<List<vector2D>>("polygon");
    if (pts.size() < 3)
    {
        FatalIOErrorInFunction(d)
            << "keyword 'polygon' of release " << r.name
            << ": at least 3 vertices expected, got " << pts.size()
            << nl << exit(FatalIOError);
    }
    terrain::Ring ring;
    for (const vector2D& p : pts)
    {
        ring.push_back({p.x(), p.y()});
    }
    r.polygons.push_back({ring});
}


//- file: the shapefile's polygons, in the DEM's system
void readShapefile
(
    const Time& runTime, const dictionary& d, const terrainDem& dem,
    release& r
)
{
    const fileName f = caseFile(runTime, d, "file");
    std::string wkt;
    try
    {
        r.polygons = terrain::readPolygons(f, wkt);
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, "file", r.name, err);
    }
    const auto tr = toDemSystem(wkt, dem.raster.wkt, f, d, "file", r.name);
    try
    {
        for (terrain::Polygon& poly : r.polygons)
        {
            for (terrain::Ring& ring : poly)
            {
                tr->apply(ring);
            }
        }
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, "file", r.name, err);
    }
}


//- raster: the thickness raster, checked, and its transformation to the
//  DEM's system
void readThicknessRaster
(
    const Time& runTime, const dictionary& d, const terrainDem& dem,
    release& r
)
{
    try
    {
        terrain::rasterDriver(d.get<fileName>("raster"));
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, "raster", r.name, err);
    }
    r.rasterFile = caseFile(runTime, d, "raster");
    try
    {
        r.raster = terrain::readRaster(r.rasterFile);
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, "raster", r.name, err);
    }
    checkThicknessRaster(r.raster, r.rasterFile, d, r.name);
    if (d.found("thickness"))
    {
        FatalIOErrorInFunction(d)
            << "keyword 'thickness' of release " << r.name
            << ": a release raster gives the thickness itself;"
            << " remove 'thickness' (or scale the raster)" << nl
            << exit(FatalIOError);
    }
    r.rasterToDem = toDemSystem
    (
        r.raster.wkt, dem.raster.wkt, r.rasterFile, d, "raster", r.name
    );
}


//- One entry of the release dictionary
release readRelease
(
    const Time& runTime, const entry& e, const terrainDem& dem
)
{
    const dictionary& d = e.dict();
    checkKeywords(d, releaseKeywords, "release " + e.keyword());
    release r;
    r.name = e.keyword();
    r.dict = &d;
    r.shapeKey = shapeKeyOf(d, r.name);
    if (r.shapeKey == "polygon")
    {
        readPolygon(d, r);
    }
    else if (r.shapeKey == "file")
    {
        readShapefile(runTime, d, dem, r);
    }
    else
    {
        readThicknessRaster(runTime, d, dem, r);
    }
    if (r.shapeKey != "raster")
    {
        r.thickness = readPositive(d, "thickness");
    }
    const word dir = d.get<word>("thicknessDirection");
    if (dir != "normal" && dir != "vertical")
    {
        FatalIOErrorInFunction(d)
            << "keyword 'thicknessDirection' of release " << r.name
            << ": unknown '" << dir << "'. Valid choices: (normal"
            << " vertical)" << nl << exit(FatalIOError);
    }
    r.vertical = (dir == "vertical");
    return r;
}

} // End anonymous namespace


std::vector<release> readReleases
(
    const Time& runTime, const dictionary& dict, const terrainDem& dem
)
{
    if (!dict.isDict("release") || dict.subDict("release").empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'release': a dictionary of one or more release"
            << " entries { polygon ((X Y) ...); thickness 1;"
            << " thicknessDirection normal; } expected" << nl
            << exit(FatalIOError);
    }
    const dictionary& releaseDict = dict.subDict("release");
    std::vector<release> releases;
    for (const entry& e : releaseDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(releaseDict)
                << "keyword 'release': entry '" << e.keyword()
                << "' is not a dictionary { polygon ...; thickness ...; }"
                << nl << exit(FatalIOError);
        }
        releases.push_back(readRelease(runTime, e, dem));
    }
    return releases;
}

} // End namespace Foam

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

//- FatalIOError for keyword key of area r with GDAL's complaint
void releaseError
(
    const dictionary& d, const word& key, const release& r,
    const terrain::gdalError& err
)
{
    FatalIOErrorInFunction(d)
        << "keyword '" << key << "' of " << r.kind << ' ' << r.name << ": "
        << err.what() << nl << exit(FatalIOError);
}


//- A crsTransform from a file's system to the DEM's, its warning and
//  what it does announced; FatalIOError naming the keyword when none
std::unique_ptr<terrain::crsTransform> toDemSystem
(
    const std::string& wkt, const std::string& demWkt, const fileName& file,
    const dictionary& d, const word& key, const release& a
)
{
    std::unique_ptr<terrain::crsTransform> t;
    try
    {
        t.reset(new terrain::crsTransform(wkt, demWkt, file));
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, key, a, err);
    }
    if (!t->warning().empty())
    {
        WarningInFunction
            << a.kind << ' ' << a.name << ": " << t->warning().c_str()
            << nl << endl;
    }
    if (!t->identity())
    {
        Info<< "    " << a.kind << ' ' << a.name << ": " << file
            << " transformed " << t->description().c_str() << nl;
    }
    return t;
}


//- The raster's values (thickness or cResistance): finite and >= 0 where
//  not nodata (nodata and 0: none)
void checkValueRaster
(
    const terrain::Raster& r, const fileName& file, const dictionary& d,
    const release& a
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
                    << "keyword 'raster' of " << a.kind << ' ' << a.name
                    << ": " << file << " holds the " << a.valueKey << ' '
                    << v << " at pixel (" << i << ", " << j << ") (X = "
                    << P[0] << ", Y = " << P[1] << "): " << a.valueKey
                    << " must be finite and >= 0 (nodata and 0: no "
                    << a.kind << ")" << nl << exit(FatalIOError);
            }
        }
    }
}


//- Which of polygon, file and raster the area gives: exactly one
word shapeKeyOf(const dictionary& d, const release& a)
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
            << a.kind << ' ' << a.name << ": give one of 'polygon' ((X Y)"
            << " ...), 'file' (a shapefile) or 'raster' (a raster of "
            << a.valueKey << "), not" << given.c_str() << nl
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
            << "keyword 'polygon' of " << r.kind << ' ' << r.name
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
        releaseError(d, "file", r, err);
    }
    const auto tr = toDemSystem(wkt, dem.raster.wkt, f, d, "file", r);
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
        releaseError(d, "file", r, err);
    }
}


//- raster: the raster of the value, checked, and its transformation to
//  the DEM's system
void readValueRaster
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
        releaseError(d, "raster", r, err);
    }
    r.rasterFile = caseFile(runTime, d, "raster");
    try
    {
        r.raster = terrain::readRaster(r.rasterFile);
    }
    catch (const terrain::gdalError& err)
    {
        releaseError(d, "raster", r, err);
    }
    checkValueRaster(r.raster, r.rasterFile, d, r);
    if (d.found(r.valueKey))
    {
        FatalIOErrorInFunction(d)
            << "keyword '" << r.valueKey << "' of " << r.kind << ' '
            << r.name << ": a raster gives the " << r.valueKey
            << " itself; remove '" << r.valueKey << "' (or scale the"
            << " raster)" << nl << exit(FatalIOError);
    }
    r.rasterToDem = toDemSystem
    (
        r.raster.wkt, dem.raster.wkt, r.rasterFile, d, "raster", r
    );
}


//- One entry of the area dictionary `kind`
release readArea
(
    const Time& runTime, const entry& e, const terrainDem& dem,
    const word& kind
)
{
    const dictionary& d = e.dict();
    const bool thickness = valueKeyOf(kind) == "thickness";
    checkKeywords
    (
        d, thickness ? releaseKeywords : resistanceKeywords,
        kind + " " + e.keyword()
    );
    release r;
    r.kind = kind;
    r.name = e.keyword();
    r.valueKey = valueKeyOf(kind);
    r.dict = &d;
    r.shapeKey = shapeKeyOf(d, r);
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
        readValueRaster(runTime, d, dem, r);
    }
    if (r.shapeKey != "raster")
    {
        r.value = readPositive(d, r.valueKey);
    }
    if (!thickness)
    {
        // A coefficient per area of the bed: no direction to convert
        return r;
    }
    const word dir = d.get<word>("thicknessDirection");
    if (dir != "normal" && dir != "vertical")
    {
        FatalIOErrorInFunction(d)
            << "keyword 'thicknessDirection' of " << r.kind << ' ' << r.name
            << ": unknown '" << dir << "'. Valid choices: (normal"
            << " vertical)" << nl << exit(FatalIOError);
    }
    r.vertical = (dir == "vertical");
    return r;
}

} // End anonymous namespace


word valueKeyOf(const word& kind)
{
    return kind == "resistance" ? "cResistance" : "thickness";
}


std::vector<release> readAreas
(
    const Time& runTime, const dictionary& dict, const terrainDem& dem,
    const word& kind
)
{
    std::vector<release> areas;
    if (kind != "release" && !dict.found(kind))
    {
        return areas;
    }
    const std::string example = kind == "resistance"
      ? "{ polygon ((X Y) ...); cResistance 0.01; }"
      : "{ polygon ((X Y) ...); thickness 1; thicknessDirection normal; }";
    if (!dict.isDict(kind) || dict.subDict(kind).empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword '" << kind << "': a dictionary of one or more "
            << kind << " entries " << example.c_str() << " expected" << nl
            << exit(FatalIOError);
    }
    const dictionary& areaDict = dict.subDict(kind);
    for (const entry& e : areaDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(areaDict)
                << "keyword '" << kind << "': entry '" << e.keyword()
                << "' is not a dictionary " << example.c_str() << nl
                << exit(FatalIOError);
        }
        areas.push_back(readArea(runTime, e, dem, kind));
    }
    return areas;
}

} // End namespace Foam

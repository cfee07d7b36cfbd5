/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    GDAL/OGR behind gdalIO.H.
\*---------------------------------------------------------------------------*/

#include "gdalIO.H"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <ogr_spatialref.h>
#include <cpl_conv.h>

namespace terrain
{

namespace
{

struct gdalInit
{
    gdalInit()
    {
        // ESRI ASCII grids as doubles (GDAL's default, Float32, rounds
        // elevations of 1000 m to 1e-4 m)
        CPLSetConfigOption("AAIGRID_DATATYPE", "Float64");
        GDALAllRegister();
        // Errors become exceptions with GDAL's own message, not stderr
        CPLSetErrorHandler(CPLQuietErrorHandler);
    }
};

void init()
{
    static gdalInit once;
}

std::string lastError()
{
    const char* msg = CPLGetLastErrorMsg();
    return (msg && *msg) ? std::string(": ") + msg : std::string();
}

std::string extension(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    {
        return "";
    }
    std::string e = path.substr(dot + 1);
    for (char& c : e)
    {
        c = char(std::tolower(static_cast<unsigned char>(c)));
    }
    return e;
}

//- A spatial reference from WKT, traditional GIS axis order; null for ""
std::unique_ptr<OGRSpatialReference> spatialReference
(
    const std::string& wkt, const std::string& file
)
{
    if (wkt.empty())
    {
        return nullptr;
    }
    std::unique_ptr<OGRSpatialReference> s(new OGRSpatialReference);
    if (s->importFromWkt(wkt.c_str()) != OGRERR_NONE)
    {
        throw gdalError
        (
            file + ": cannot read its coordinate reference system" + lastError()
        );
    }
    s->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    return s;
}

std::string crsName(const OGRSpatialReference& s)
{
    const char* name = s.GetName();
    const char* auth = s.GetAuthorityName(nullptr);
    const char* code = s.GetAuthorityCode(nullptr);
    std::string n = name ? std::string("'") + name + "'" : "(unnamed)";
    if (auth && code)
    {
        n += std::string(" (") + auth + ":" + code + ")";
    }
    return n;
}

bool sameCrs
(
    const std::string& a, const std::string& b, const std::string& file
)
{
    if (a.empty() || b.empty())
    {
        return a.empty() == b.empty();
    }
    const auto sa = spatialReference(a, file);
    const auto sb = spatialReference(b, file);
    return sa->IsSame(sb.get());
}

std::string layerWkt(OGRLayer* layer)
{
    const OGRSpatialReference* s = layer->GetSpatialRef();
    if (!s)
    {
        return "";
    }
    char* w = nullptr;
    s->exportToWkt(&w);
    const std::string wkt = w ? w : "";
    CPLFree(w);
    return wkt;
}

struct closeDataset
{
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using datasetPtr = std::unique_ptr<GDALDataset, closeDataset>;

} // namespace


void Raster::pixel(double X, double Y, double& c, double& r) const
{
    const double dX = X - gt[0];
    const double dY = Y - gt[3];
    if (northUp())
    {
        c = dX/gt[1];
        r = dY/gt[5];
        return;
    }
    const double det = gt[1]*gt[5] - gt[2]*gt[4];
    c = (gt[5]*dX - gt[2]*dY)/det;
    r = (gt[1]*dY - gt[4]*dX)/det;
}


// A NaN X or Y must not reach the ordered comparisons below: OpenFOAM's
// applications trap FE_INVALID (FOAM_SIGFPE), which they raise for NaN
bool Raster::covers(double X, double Y) const
{
    if (!(std::isfinite(X) && std::isfinite(Y)))
    {
        return false;
    }
    double c = 0, r = 0;
    pixel(X, Y, c, r);
    return c >= 0 && r >= 0 && c <= nx && r <= ny;
}


bool Raster::sampled(double X, double Y) const
{
    if (!(std::isfinite(X) && std::isfinite(Y)))
    {
        return false;
    }
    double fi = 0, fj = 0;
    pixel(X, Y, fi, fj);
    fi -= 0.5;
    fj -= 0.5;
    return fi >= 0 && fj >= 0 && fi <= nx - 1 && fj <= ny - 1;
}


std::array<double, 4> Raster::sampledBounds() const
{
    std::array<double, 4> b
    {
        std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
        std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()
    };
    for (int k = 0; k < 4; ++k)
    {
        const std::array<double, 2> P =
            point(k % 2 ? nx - 0.5 : 0.5, k/2 ? ny - 0.5 : 0.5);
        b[0] = std::min(b[0], P[0]);
        b[1] = std::max(b[1], P[0]);
        b[2] = std::min(b[2], P[1]);
        b[3] = std::max(b[3], P[1]);
    }
    return b;
}


double Raster::pixelSize() const
{
    return std::min(std::hypot(gt[1], gt[4]), std::hypot(gt[2], gt[5]));
}


std::array<double, 4> Raster::bounds() const
{
    std::array<double, 4> b
    {
        std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
        std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()
    };
    for (int k = 0; k < 4; ++k)
    {
        const std::array<double, 2> P = point(k % 2 ? nx : 0, k/2 ? ny : 0);
        b[0] = std::min(b[0], P[0]);
        b[1] = std::max(b[1], P[0]);
        b[2] = std::min(b[2], P[1]);
        b[3] = std::max(b[3], P[1]);
    }
    return b;
}


double Raster::value(double X, double Y) const
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!(std::isfinite(X) && std::isfinite(Y)))
    {
        return nan;
    }
    // Fractional pixel-centre coordinates (as sampled() tests them)
    double fi = 0, fj = 0;
    pixel(X, Y, fi, fj);
    fi -= 0.5;
    fj -= 0.5;
    if (!(fi >= 0 && fj >= 0 && fi <= nx - 1 && fj <= ny - 1))
    {
        return nan;
    }
    int i = std::min(int(fi), nx - 2 < 0 ? 0 : nx - 2);
    int j = std::min(int(fj), ny - 2 < 0 ? 0 : ny - 2);
    const double a = fi - i;
    const double b = fj - j;
    const int i1 = std::min(i + 1, nx - 1);
    const int j1 = std::min(j + 1, ny - 1);
    const double z00 = at(i, j), z10 = at(i1, j);
    const double z01 = at(i, j1), z11 = at(i1, j1);
    if (!(valid(z00) && valid(z10) && valid(z01) && valid(z11)))
    {
        return nan;
    }
    // An infinite pixel (not nodata) would make 0*inf: NaN, FE_INVALID
    if
    (
        !(std::isfinite(z00) && std::isfinite(z10)
       && std::isfinite(z01) && std::isfinite(z11))
    )
    {
        return nan;
    }
    return (1 - b)*((1 - a)*z00 + a*z10) + b*((1 - a)*z01 + a*z11);
}


std::string rasterDriver(const std::string& path)
{
    const std::string e = extension(path);
    if (e == "asc")
    {
        return "AAIGrid";
    }
    if (e == "tif" || e == "tiff")
    {
        return "GTiff";
    }
    throw gdalError
    (
        "unknown raster format '." + e + "' of " + path
      + ": valid formats .asc (ESRI ASCII grid), .tif (GeoTIFF)"
    );
}


Raster readRaster(const std::string& path)
{
    init();
    const std::string driver = rasterDriver(path);
    const char* allowed[] = {driver.c_str(), nullptr};
    CPLErrorReset();
    datasetPtr ds
    (
        static_cast<GDALDataset*>
        (
            GDALOpenEx
            (
                path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, allowed,
                nullptr, nullptr
            )
        )
    );
    if (!ds)
    {
        throw gdalError("cannot read " + path + " as " + driver + lastError());
    }
    Raster r;
    r.nx = ds->GetRasterXSize();
    r.ny = ds->GetRasterYSize();
    if (ds->GetRasterCount() < 1 || r.nx < 2 || r.ny < 2)
    {
        throw gdalError(path + ": no band, or fewer than 2 x 2 pixels");
    }
    if (ds->GetGeoTransform(r.gt.data()) != CE_None)
    {
        throw gdalError(path + ": no georeference (geotransform)");
    }
    const double det = r.gt[1]*r.gt[5] - r.gt[2]*r.gt[4];
    if (!std::isfinite(det) || det == 0 || !std::isfinite(r.gt[0] + r.gt[3]))
    {
        throw gdalError
        (
            path + ": degenerate georeference (geotransform "
          + std::to_string(r.gt[0]) + " " + std::to_string(r.gt[1]) + " "
          + std::to_string(r.gt[2]) + " " + std::to_string(r.gt[3]) + " "
          + std::to_string(r.gt[4]) + " " + std::to_string(r.gt[5])
          + "): its pixels have no area"
        );
    }
    if (const char* w = ds->GetProjectionRef())
    {
        r.wkt = w;
    }
    GDALRasterBand* band = ds->GetRasterBand(1);
    int has = 0;
    const double nd = band->GetNoDataValue(&has);
    r.hasNodata = has;
    if (has)
    {
        r.nodata = nd;
    }
    r.z.resize(std::size_t(r.nx)*r.ny);
    if
    (
        band->RasterIO
        (
            GF_Read, 0, 0, r.nx, r.ny, r.z.data(), r.nx, r.ny, GDT_Float64,
            0, 0
        ) != CE_None
    )
    {
        throw gdalError("cannot read the values of " + path + lastError());
    }
    return r;
}


std::vector<std::string> rasterExtensions(const Raster& r)
{
    if (r.northUp())
    {
        return {".asc", ".tif"};
    }
    return {".tif"};
}


void writeRaster(const std::string& path, const Raster& r)
{
    init();
    const std::string driverName = rasterDriver(path);
    if (driverName == "AAIGrid" && !r.northUp())
    {
        throw gdalError
        (
            "cannot write " + path + ": an ESRI ASCII grid holds north-up"
            " grids only, and this one is rotated (write it as .tif)"
        );
    }
    GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
    GDALDriver* out = GetGDALDriverManager()->GetDriverByName
    (
        driverName.c_str()
    );
    if (!mem || !out)
    {
        throw gdalError("GDAL lacks the driver " + driverName);
    }
    datasetPtr tmp(mem->Create("", r.nx, r.ny, 1, GDT_Float64, nullptr));
    tmp->SetGeoTransform(const_cast<double*>(r.gt.data()));
    if (!r.wkt.empty())
    {
        tmp->SetProjection(r.wkt.c_str());
    }
    GDALRasterBand* band = tmp->GetRasterBand(1);
    if (r.hasNodata)
    {
        band->SetNoDataValue(r.nodata);
    }
    if
    (
        band->RasterIO
        (
            GF_Write, 0, 0, r.nx, r.ny, const_cast<double*>(r.z.data()),
            r.nx, r.ny, GDT_Float64, 0, 0
        ) != CE_None
    )
    {
        throw gdalError("cannot fill the raster for " + path + lastError());
    }
    std::remove(path.c_str());
    CPLErrorReset();
    datasetPtr file
    (
        out->CreateCopy(path.c_str(), tmp.get(), TRUE, nullptr, nullptr, nullptr)
    );
    if (!file)
    {
        throw gdalError("cannot write " + path + lastError());
    }
}


namespace
{

//- The rings of polygon p, the exterior first, each without the repeated
//  first point of a closed ring
Polygon rings(const OGRPolygon* p)
{
    Polygon poly;
    for (int k = 0; k <= p->getNumInteriorRings(); ++k)
    {
        const OGRLinearRing* ring =
            k == 0 ? p->getExteriorRing() : p->getInteriorRing(k - 1);
        if (!ring)
        {
            continue;
        }
        Ring pts;
        for (int i = 0; i < ring->getNumPoints(); ++i)
        {
            pts.push_back({ring->getX(i), ring->getY(i)});
        }
        // A closed ring repeats its first point
        if (pts.size() > 1 && pts.front() == pts.back())
        {
            pts.pop_back();
        }
        poly.push_back(pts);
    }
    return poly;
}

//- The polygons of the layer's features (polygons and multipolygons),
//  appended to polygons
void layerPolygons(OGRLayer* layer, std::vector<Polygon>& polygons)
{
    const auto addPolygon = [&polygons](const OGRPolygon* p)
    {
        const Polygon poly = rings(p);
        if (!poly.empty())
        {
            polygons.push_back(poly);
        }
    };
    layer->ResetReading();
    while (OGRFeature* f = layer->GetNextFeature())
    {
        const OGRGeometry* g = f->GetGeometryRef();
        if (g)
        {
            const auto type = wkbFlatten(g->getGeometryType());
            if (type == wkbPolygon)
            {
                addPolygon(g->toPolygon());
            }
            else if (type == wkbMultiPolygon)
            {
                for (const OGRPolygon* p : *g->toMultiPolygon())
                {
                    addPolygon(p);
                }
            }
        }
        OGRFeature::DestroyFeature(f);
    }
}

} // namespace


std::vector<Polygon> readPolygons
(
    const std::string& path, std::string& wkt
)
{
    init();
    CPLErrorReset();
    datasetPtr ds
    (
        static_cast<GDALDataset*>
        (
            GDALOpenEx
            (
                path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr,
                nullptr, nullptr
            )
        )
    );
    if (!ds)
    {
        throw gdalError("cannot read " + path + " as a vector file" + lastError());
    }
    std::vector<Polygon> polygons;
    wkt.clear();
    bool first = true;
    for (OGRLayer* layer : ds->GetLayers())
    {
        const std::string w = layerWkt(layer);
        if (first)
        {
            wkt = w;
            first = false;
        }
        else if (!sameCrs(w, wkt, path))
        {
            throw gdalError
            (
                path + ": its layers are in different coordinate reference"
                " systems (layer " + layer->GetName() + ")"
            );
        }
        layerPolygons(layer, polygons);
    }
    if (polygons.empty())
    {
        throw gdalError(path + " holds no polygon");
    }
    return polygons;
}

void crsTransform::deleter::operator()(OGRCoordinateTransformation* t) const
{
    OGRCoordinateTransformation::DestroyCT(t);
}


crsTransform::crsTransform
(
    const std::string& fromWkt, const std::string& toWkt,
    const std::string& file
)
:
    file_(file)
{
    init();
    CPLErrorReset();
    const auto from = spatialReference(fromWkt, file);
    const auto to = spatialReference(toWkt, file + " (the DEM's system)");
    if (!from && !to)
    {
        return;
    }
    if (!from || !to)
    {
        warning_ =
            from
          ? file + " is in " + crsName(*from) + ", the DEM gives no"
            " coordinate reference system: its coordinates are taken as"
            " the DEM's"
          : file + " gives no coordinate reference system, the DEM is in "
          + crsName(*to) + ": its coordinates are taken as the DEM's";
        return;
    }
    if (from->IsSame(to.get()))
    {
        return;
    }
    t_.reset(OGRCreateCoordinateTransformation(from.get(), to.get()));
    if (!t_)
    {
        throw gdalError
        (
            file + ": no transformation from its coordinate reference system "
          + crsName(*from) + " to the DEM's " + crsName(*to) + lastError()
        );
    }
    description_ = "from " + crsName(*from) + " to " + crsName(*to);
}


void crsTransform::apply(std::vector<std::array<double, 2>>& pts) const
{
    if (!t_ || pts.empty())
    {
        return;
    }
    const std::size_t n = pts.size();
    std::vector<double> X(n), Y(n);
    std::vector<int> ok(n, 0);
    for (std::size_t k = 0; k < n; ++k)
    {
        X[k] = pts[k][0];
        Y[k] = pts[k][1];
    }
    CPLErrorReset();
    t_->Transform(int(n), X.data(), Y.data(), nullptr, ok.data());
    for (std::size_t k = 0; k < n; ++k)
    {
        if (!ok[k] || !std::isfinite(X[k]) || !std::isfinite(Y[k]))
        {
            throw gdalError
            (
                file_ + ": cannot transform the point ("
              + std::to_string(pts[k][0]) + ", " + std::to_string(pts[k][1])
              + ") " + description_ + lastError()
            );
        }
        pts[k] = {X[k], Y[k]};
    }
}

} // namespace terrain

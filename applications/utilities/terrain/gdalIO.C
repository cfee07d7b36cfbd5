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

struct closeDataset
{
    void operator()(GDALDataset* d) const { GDALClose(d); }
};
using datasetPtr = std::unique_ptr<GDALDataset, closeDataset>;

} // namespace


double Raster::value(double X, double Y) const
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    // Fractional pixel-centre coordinates
    const double fi = (X - gt[0])/gt[1] - 0.5;
    const double fj = (Y - gt[3])/gt[5] - 0.5;
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
    if (r.gt[2] != 0 || r.gt[4] != 0 || !(r.gt[1] > 0) || r.gt[5] == 0)
    {
        throw gdalError
        (
            path + ": rotated or sheared grid (geotransform terms 2 and 4"
            " non-zero): only north-up grids are supported"
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


void writeRaster(const std::string& path, const Raster& r)
{
    init();
    const std::string driverName = rasterDriver(path);
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


std::vector<Polygon> readPolygons(const std::string& path)
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
    const auto addPolygon = [&polygons](const OGRPolygon* p)
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
        if (!poly.empty())
        {
            polygons.push_back(poly);
        }
    };
    for (OGRLayer* layer : ds->GetLayers())
    {
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
    if (polygons.empty())
    {
        throw gdalError(path + " holds no polygon");
    }
    return polygons;
}

} // namespace terrain

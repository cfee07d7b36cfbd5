/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "releaseThickness.H"

#include "polygonClip.H"
#include "rasterRelease.H"

#include <cctype>
#include <limits>
#include <sstream>

namespace Foam
{

namespace
{

//- A release's thickness mapped onto the mesh: the DEM, the reference
//  surface, the grid and the bed it is mapped with
class releaseMapper
{
    const terrainDem& dem_;
    const terrain::referenceSurface& surface_;
    const chuteGrid& g_;
    const scalarField& zb_;
    const scalar cellArea_;

    //- FatalIOError: r's outline passes (X, Y), Z the DEM there, off the
    //  mesh; ok: its foot on the reference surface found, at (x, y)
    void outlineFailure
    (
        const release& r, double X, double Y, double Z, bool ok,
        double x, double y
    ) const;

    //- A ring of r's polygons densified and mapped to (x, y): edges
    //  straight in plan stay close to straight on the mesh
    std::vector<terrain::point2> ringOnMesh
    (
        const terrain::Ring& ring, const release& r
    ) const;

    //- Add sign times the fraction of each cell polygon xy covers
    void addCover
    (
        const std::vector<terrain::point2>& xy, double sign,
        scalarField& frac
    ) const;

public:

    releaseMapper
    (
        const terrainDem& dem, const thalwegProfile& profile,
        const chuteGrid& grid, const scalarField& zb
    )
    :
        dem_(dem),
        surface_(profile.surface),
        g_(grid),
        zb_(zb),
        cellArea_(grid.cellSize*grid.cellSize)
    {}

    scalar cellArea() const { return cellArea_; }

    //- Cos of the DEM's slope at cell c's bed point (vertical thickness of
    //  release r)
    double cosSlope(label c, const release& r) const;

    //- The thickness of polygon release r in each cell, as given
    scalarField polygonThickness(const release& r) const;

    //- The thickness of raster release r in each cell, as given, and how
    //  it was mapped
    scalarField rasterThickness
    (
        const release& r, terrain::rasterRelease& mapped
    ) const;
};


// Central differences over a pixel, one-sided where one side has no value
// (the DEM's edge, nodata); FatalIOError where neither has
double releaseMapper::cosSlope(label c, const release& r) const
{
    const terrain::Raster& dem = dem_.raster;
    const double x = g_.x(c % g_.nx);
    const double y = g_.y(c/g_.nx);
    const terrain::vec3 W = surface_.world(x, y, zb_[c]);
    const double d = dem.pixelSize();
    const double Zc = dem.value(W[0], W[1]);
    const auto slope = [&](double dX, double dY)
    {
        const double zp = dem.value(W[0] + dX, W[1] + dY);
        const double zm = dem.value(W[0] - dX, W[1] - dY);
        if (std::isfinite(zp) && std::isfinite(zm))
        {
            return (zp - zm)/(2*d);
        }
        if (std::isfinite(zp) && std::isfinite(Zc))
        {
            return (zp - Zc)/d;
        }
        if (std::isfinite(zm) && std::isfinite(Zc))
        {
            return (Zc - zm)/d;
        }
        return std::numeric_limits<double>::quiet_NaN();
    };
    const double gx = slope(d, 0);
    const double gy = slope(0, d);
    if (!(std::isfinite(gx) && std::isfinite(gy)))
    {
        FatalIOErrorInFunction(*r.dict)
            << "keyword 'thicknessDirection' of " << r.kind << ' ' << r.name
            << ": the DEM " << dem_.file << " has too few values around"
            << " the bed point (X = " << W[0] << ", Y = " << W[1]
            << ") of the mesh cell at x = " << x << ", y = " << y
            << " for its slope there (a pixel either side in X and in"
            << " Y: nodata or the DEM's edge), which a vertical"
            << " thickness needs; " << dem_.valueExtent.c_str() << nl
            << exit(FatalIOError);
    }
    return 1/std::sqrt(1 + gx*gx + gy*gy);
}


void releaseMapper::outlineFailure
(
    const release& r, double X, double Y, double Z, bool ok,
    double x, double y
) const
{
    std::ostringstream why;
    if (!std::isfinite(Z))
    {
        why << (dem_.raster.sampled(X, Y)
            ? "over a nodata hole of the DEM \""
            : "outside the DEM \"")
            << dem_.file.c_str() << "\"; " << dem_.valueExtent;
    }
    else if (!ok)
    {
        why << "where its foot on the reference"
            << " surface was not found (the Newton"
            << " iteration did not converge)";
    }
    else
    {
        why << "(x = " << x << ", y = " << y
            << ") outside the mesh, x in [0, "
            << g_.xMax << "], y in [" << -g_.yMax << ", "
            << g_.yMax << "]";
    }
    FatalIOErrorInFunction(*r.dict)
        << "keyword '" << r.shapeKey
        << "' of " << r.kind << ' ' << r.name
        << ": the " << r.kind << " outline passes (X = "
        << X << ", Y = " << Y << ") "
        << why.str().c_str()
        << nl << exit(FatalIOError);
}


std::vector<terrain::point2> releaseMapper::ringOnMesh
(
    const terrain::Ring& ring, const release& r
) const
{
    const scalar xMax = g_.xMax, yMax = g_.yMax;
    std::vector<terrain::point2> xy;
    const label n = label(ring.size());
    for (label k = 0; k < n; ++k)
    {
        const auto& a = ring[k];
        const auto& b = ring[(k + 1) % n];
        const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
        const label m = max(label(1), label(std::ceil(4*len/g_.cellSize)));
        for (label s = 0; s < m; ++s)
        {
            const double f = double(s)/m;
            const double X = a[0] + f*(b[0] - a[0]);
            const double Y = a[1] + f*(b[1] - a[1]);
            const double Z = dem_.raster.value(X, Y);
            double x = 0, y = 0, z = 0;
            const bool onDem = std::isfinite(Z);
            const bool ok = onDem && surface_.local({X, Y, Z}, x, y, z);
            if
            (
                !ok || x < -1e-9*xMax || x > xMax*(1 + 1e-9)
             || std::fabs(y) > yMax*(1 + 1e-9)
            )
            {
                outlineFailure(r, X, Y, Z, ok, x, y);
            }
            xy.push_back({x, y});
        }
    }
    return xy;
}


void releaseMapper::addCover
(
    const std::vector<terrain::point2>& xy, double sign, scalarField& frac
) const
{
    const label nx = g_.nx, ny = g_.ny;
    const scalar cellSize = g_.cellSize, yMax = g_.yMax;
    double bx0 = GREAT, bx1 = -GREAT, by0 = GREAT, by1 = -GREAT;
    for (const auto& p : xy)
    {
        bx0 = std::min(bx0, p[0]);
        bx1 = std::max(bx1, p[0]);
        by0 = std::min(by0, p[1]);
        by1 = std::max(by1, p[1]);
    }
    const label i0 = max(label(0), label(std::floor(bx0/cellSize)));
    const label i1 = min(nx - 1, label(std::floor(bx1/cellSize)));
    const label j0 = max(label(0), label(std::floor((by0 + yMax)/cellSize)));
    const label j1 = min(ny - 1, label(std::floor((by1 + yMax)/cellSize)));
    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            const double a = terrain::clippedArea
            (
                xy, i*cellSize, (i + 1)*cellSize,
                -yMax + j*cellSize, -yMax + (j + 1)*cellSize
            );
            frac[i + nx*j] += sign*a/cellArea_;
        }
    }
}


scalarField releaseMapper::polygonThickness(const release& r) const
{
    scalarField frac(g_.nCells(), Zero);
    for (const terrain::Polygon& poly : r.polygons)
    {
        forAll(poly, ringi)
        {
            // The exterior adds, the holes take away
            const double sign = ringi == 0 ? 1 : -1;
            addCover(ringOnMesh(poly[ringi], r), sign, frac);
        }
    }
    scalarField d(g_.nCells(), Zero);
    forAll(frac, c)
    {
        // Overlapping polygons of one release count once
        d[c] = r.value*min(max(frac[c], scalar(0)), scalar(1));
    }
    return d;
}


scalarField releaseMapper::rasterThickness
(
    const release& r, terrain::rasterRelease& mapped
) const
{
    return rasterReleaseThickness
    (
        r, dem_.raster, surface_, {g_.nx, g_.ny, g_.cellSize, g_.yMax},
        mapped
    );
}


} // End anonymous namespace


scalarField rasterReleaseThickness
(
    const release& r, const terrain::Raster& dem,
    const terrain::referenceSurface& surface, const terrain::meshGrid& grid,
    terrain::rasterRelease& mapped
)
{
    try
    {
        mapped = terrain::mapRasterRelease
        (
            r.raster, *r.rasterToDem, dem, surface, grid
        );
    }
    catch (const terrain::gdalError& err)
    {
        FatalIOErrorInFunction(*r.dict)
            << "keyword 'raster' of " << r.kind << ' ' << r.name << ": "
            << err.what() << nl << exit(FatalIOError);
    }
    if (!mapped.nPixels)
    {
        FatalIOErrorInFunction(*r.dict)
            << "keyword 'raster' of " << r.kind << ' ' << r.name << ": "
            << r.rasterFile << " holds no " << r.valueKey << " > 0" << nl
            << exit(FatalIOError);
    }
    scalarField d(label(grid.nx*grid.ny), Zero);
    forAll(d, c)
    {
        d[c] = mapped.h[c];
    }
    return d;
}


namespace
{

//- The kind of an area as a log line starts it: Release, Entrainment,
//  Resistance
std::string capitalised(const word& kind)
{
    std::string k(kind);
    if (!k.empty())
    {
        k[0] = std::toupper(k[0]);
    }
    return k;
}

//- What the log says of a value of area r: the thickness's direction, a
//  coefficient's unit
std::string valueText(const release& r)
{
    if (r.valueKey == "thickness")
    {
        return r.vertical ? "vertical" : "normal";
    }
    return "1/m";
}

//- What area r gives, for the log: a thickness' volume, a coefficient's
//  cells
void writeAmount
(
    Ostream& os, const release& r, scalar volume, const scalarField& values
)
{
    if (r.valueKey == "thickness")
    {
        os  << "volume " << volume << " m^3";
        return;
    }
    label n = 0;
    for (const scalar v : values)
    {
        n += v > 0;
    }
    os  << n << " cells";
}

} // End anonymous namespace


void reportRelease
(
    const release& r, const terrain::rasterRelease& mapped, scalar volume,
    const scalarField& values
)
{
    const std::string kind = capitalised(r.kind);
    const bool thickness = r.valueKey == "thickness";
    if (r.shapeKey != "raster")
    {
        Info<< kind.c_str() << ' ' << r.name << ": " << r.polygons.size()
            << " polygon(s), " << r.valueKey << ' ' << r.value
            << (thickness ? " m " : " ") << valueText(r).c_str() << ", ";
        writeAmount(Info, r, volume, values);
        Info<< nl;
        return;
    }
    Info<< "    raster " << r.rasterFile << ": " << mapped.nPixels
        << " pixels of " << r.valueKey << " in [" << mapped.dMin << ", "
        << mapped.dMax << "] " << (thickness ? "m" : "1/m")
        << ", sum of " << r.valueKey << " x pixel area in"
        << " the DEM's plan " << mapped.planVolume
        << (thickness ? " m^3; " : " m; ")
        << mapped.subdivisions << " x " << mapped.subdivisions
        << " sub-pixels" << nl;
    if (mapped.nOutside || mapped.nOffDem)
    {
        WarningInFunction
            << r.kind << ' ' << r.name << ": " << mapped.nOutside
            << " of the " << mapped.nPixels << " pixels of "
            << r.rasterFile << " with " << r.valueKey << " > 0 reach outside"
            << " the mesh (" << mapped.outsideVolume
            << (thickness ? " m^3" : " m") << " of "
            << r.valueKey << " x area there is dropped), "
            << mapped.nOffDem << " reach off the DEM (dropped)"
            << nl << endl;
    }
    Info<< kind.c_str() << ' ' << r.name << ": raster, " << r.valueKey << ' '
        << valueText(r).c_str() << ", ";
    writeAmount(Info, r, volume, values);
    Info<< nl;
}


void reportLayer(const std::vector<release>& areas, const areaLayer& layer)
{
    if (areas.empty())
    {
        return;
    }
    const word& kind = areas.front().kind;
    if (kind == "release")
    {
        Info<< "Released volume " << layer.volume << " m^3";
    }
    else if (kind == "entrainment")
    {
        Info<< "Erodible volume (hEntrainable) " << layer.volume << " m^3";
    }
    else
    {
        label n = 0;
        for (const scalar v : layer.values)
        {
            n += v > 0;
        }
        Info<< "Resistance areas: cResistance > 0 in " << n << " cells, up"
            << " to " << max(layer.values) << " 1/m";
    }
}


areaLayer releaseThickness
(
    const std::vector<release>& releases, const terrainDem& dem,
    const thalwegProfile& profile, const chuteGrid& grid,
    const scalarField& zb
)
{
    areaLayer layer;
    if (releases.empty())
    {
        return layer;
    }
    const releaseMapper mapper(dem, profile, grid, zb);
    layer.values.setSize(grid.nCells(), Zero);
    for (const release& r : releases)
    {
        // The value in each cell, a thickness normal or vertical as given
        terrain::rasterRelease mapped;
        const scalarField d = r.shapeKey == "raster"
          ? mapper.rasterThickness(r, mapped)
          : mapper.polygonThickness(r);
        scalar volume = 0;
        scalarField values(d.size(), Zero);
        forAll(d, c)
        {
            if (d[c] > 0)
            {
                values[c] = d[c]*(r.vertical ? mapper.cosSlope(c, r) : 1);
                volume += values[c]*mapper.cellArea();
            }
        }
        if (!(volume > 0))
        {
            FatalIOErrorInFunction(*r.dict)
                << "keyword '" << r.shapeKey << "' of " << r.kind << ' '
                << r.name << ": the " << r.kind << ' '
                << (r.shapeKey == "raster" ? r.rasterFile + " " : "")
                << "covers no area of the mesh" << nl
                << exit(FatalIOError);
        }
        reportRelease(r, mapped, volume, values);
        layer.values += values;
        layer.volume += volume;
    }
    reportLayer(releases, layer);
    Info<< nl << endl;
    return layer;
}

} // End namespace Foam

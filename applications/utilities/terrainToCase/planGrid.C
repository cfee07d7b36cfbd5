/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "planGrid.H"
#include "terrainInput.H"
#include "zbGradient.H"
#include "vector2D.H"
#include "unitConversion.H"

#include <algorithm>
#include <cmath>

namespace Foam
{

namespace
{

//- FatalIOError for a keyword of the axis mode in a terrainDict without axis
void noAxisKeywords(const dictionary& dict)
{
    for (const word key : {"halfWidth", "profileSmoothing"})
    {
        if (dict.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "keyword '" << key << "' belongs to the axis mode (a"
                << " terrainDict with 'axis'): without 'axis' terrainToCase"
                << " builds the case on the DEM's plan grid, from"
                << " 'cellSize' and the optional 'extent'.  Remove '" << key
                << "' or give 'axis'" << nl << exit(FatalIOError);
        }
    }
}


//- A rectangle on the DEM's axes: u along xAxis, v along yAxis [m], from
//  the DEM's origin point(0, 0)
struct frameBox
{
    double u0 = GREAT, u1 = -GREAT, v0 = GREAT, v1 = -GREAT;

    void add(double u, double v)
    {
        u0 = std::min(u0, u);
        u1 = std::max(u1, u);
        v0 = std::min(v0, v);
        v1 = std::max(v1, v);
    }
};


//- The DEM's own frame as a planGrid without cells: x along the DEM's
//  columns, y to its left (+90 deg), the origin at the DEM's point(0, 0);
//  world() and local() map between it and the world
planGrid demFrame(const terrain::Raster& dem)
{
    planGrid f{};
    const double len = std::hypot(dem.gt[1], dem.gt[4]);
    f.xAxis = {dem.gt[1]/len, dem.gt[4]/len};
    f.yAxis = {-f.xAxis[1] + 0.0, f.xAxis[0]};
    f.origin = dem.point(0, 0);
    return f;
}


//- The DEM's outline on the frame's axes, clipped to the optional
//  'extent' (a message where it clips; FatalIOError where 'extent' is
//  not two finite corners or lies outside the DEM)
frameBox gridBox
(
    const dictionary& dict, const terrainDem& d, const planGrid& f
)
{
    const terrain::Raster& dem = d.raster;
    frameBox demBox;
    const int corners[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (const auto& c : corners)
    {
        const std::array<double, 2> P = dem.point(c[0]*dem.nx, c[1]*dem.ny);
        const std::array<double, 2> uv = f.local(P[0], P[1]);
        demBox.add(uv[0], uv[1]);
    }

    frameBox box = demBox;
    if (!dict.found("extent"))
    {
        return box;
    }
    const List<vector2D> pts = dict.get<List<vector2D>>("extent");
    if (pts.size() != 2)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'extent': two corners ((X0 Y0) (X1 Y1)) of the"
            << " plan rectangle expected; got " << pts.size() << nl
            << exit(FatalIOError);
    }
    frameBox given;
    for (const vector2D& p : pts)
    {
        if (!(std::isfinite(p.x()) && std::isfinite(p.y())))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'extent': corner " << p << " not finite"
                << nl << exit(FatalIOError);
        }
        const std::array<double, 2> uv = f.local(p.x(), p.y());
        given.add(uv[0], uv[1]);
    }
    box.u0 = std::max(given.u0, demBox.u0);
    box.u1 = std::min(given.u1, demBox.u1);
    box.v0 = std::max(given.v0, demBox.v0);
    box.v1 = std::min(given.v1, demBox.v1);
    const std::array<double, 4> outline = dem.bounds();
    if (!(box.u1 > box.u0 && box.v1 > box.v0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'extent': the rectangle " << pts << " lies"
            << " outside the DEM " << d.file << " (its outline: X in ["
            << outline[0] << ", " << outline[1] << "], Y in ["
            << outline[2] << ", " << outline[3] << "]"
            << (dem.northUp() ? "" : ", a rotated grid's bounding box")
            << ")" << nl << exit(FatalIOError);
    }
    if
    (
        box.u0 > given.u0 || box.u1 < given.u1
     || box.v0 > given.v0 || box.v1 < given.v1
    )
    {
        Info<< "extent " << pts << " clipped to the DEM's outline" << nl;
    }
    return box;
}


//- The cells of size cs from the box's lower-left corner, the edge lines
//  of cells whose centre has no DEM value (half a pixel along the
//  outline) left out: the first and last column (i0, i1) and row (j0, j1)
//  kept
std::array<label, 4> trimmedCells
(
    const terrain::Raster& dem, const planGrid& f, const frameBox& box,
    double cs, label nx0, label ny0
)
{
    const auto sampled = [&](label i, label j)
    {
        const double u = box.u0 + (i + 0.5)*cs, v = box.v0 + (j + 0.5)*cs;
        const std::array<double, 2> W = f.world(u, v);
        return dem.sampled(W[0], W[1]);
    };
    label i0 = 0, i1 = nx0 - 1, j0 = 0, j1 = ny0 - 1;
    for (bool trimmed = true; trimmed && i0 <= i1 && j0 <= j1; )
    {
        trimmed = false;
        const auto column = [&](label i)
        {
            for (label j = j0; j <= j1; ++j)
            {
                if (!sampled(i, j)) { return false; }
            }
            return true;
        };
        const auto row = [&](label j)
        {
            for (label i = i0; i <= i1; ++i)
            {
                if (!sampled(i, j)) { return false; }
            }
            return true;
        };
        if (!column(i0)) { ++i0; trimmed = true; }
        if (i0 <= i1 && !column(i1)) { --i1; trimmed = true; }
        if (i0 <= i1 && !row(j0)) { ++j0; trimmed = true; }
        if (i0 <= i1 && j0 <= j1 && !row(j1)) { --j1; trimmed = true; }
    }
    return {i0, i1, j0, j1};
}


//- The grid's size, axes, origin and world bounding box on Info; the
//  edge lines left out of the nx0 x ny0 cells of the box
void reportPlanGrid
(
    const planGrid& g, const terrain::Raster& dem, label nx0, label ny0
)
{
    const scalar cs = g.cellSize;

    // The grid's world bounding box
    double X0 = GREAT, X1 = -GREAT, Y0 = GREAT, Y1 = -GREAT;
    for (const double x : {0.0, g.xMax()})
    {
        for (const double y : {0.0, g.yMax()})
        {
            const std::array<double, 2> W = g.world(x, y);
            X0 = std::min(X0, W[0]);
            X1 = std::max(X1, W[0]);
            Y0 = std::min(Y0, W[1]);
            Y1 = std::max(Y1, W[1]);
        }
    }
    Info<< "Plan grid: " << g.nx << " x " << g.ny << " cells of " << cs
        << " m, x along (" << g.xAxis[0] << " " << g.xAxis[1]
        << "), y along (" << g.yAxis[0] << " " << g.yAxis[1]
        << "), origin (x = y = 0) at X = " << g.origin[0] << ", Y = "
        << g.origin[1] << "; extent X in [" << X0 << ", " << X1
        << "], Y in [" << Y0 << ", " << Y1 << "]"
        << (dem.northUp() ? "" : " (bounding box)") << nl;
    if (nx0 != g.nx || ny0 != g.ny)
    {
        Info<< "    " << (nx0 - g.nx) << " column(s) and " << (ny0 - g.ny)
            << " row(s) along the edges left out: their cell centres lie"
            << " where the DEM has no values (half a pixel along its"
            << " outline)" << nl;
    }
}

} // End anonymous namespace


planGrid readPlanGrid(const dictionary& dict, const terrainDem& d)
{
    noAxisKeywords(dict);
    const terrain::Raster& dem = d.raster;
    if (!dict.found("cellSize"))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'cellSize' missing: without 'axis' (the plan mode)"
            << " the case's square cells [m] on the DEM's plan grid are"
            << " needed" << nl << exit(FatalIOError);
    }
    planGrid g;
    g.cellSize = readPositive(dict, "cellSize");
    const scalar cs = g.cellSize;

    const planGrid f = demFrame(dem);
    g.xAxis = f.xAxis;
    g.yAxis = f.yAxis;
    const frameBox box = gridBox(dict, d, f);

    const label nx0 = label(std::floor((box.u1 - box.u0)/cs + 1e-9));
    const label ny0 = label(std::floor((box.v1 - box.v0)/cs + 1e-9));
    const std::array<label, 4> kept = trimmedCells(dem, f, box, cs, nx0, ny0);
    const label i0 = kept[0], j0 = kept[2];
    g.nx = kept[1] - i0 + 1;
    g.ny = kept[3] - j0 + 1;
    if (!(g.nx > 0 && g.ny > 0))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'cellSize' = " << cs << ": no cell of the plan"
            << " grid has its centre where the DEM " << d.file << " has"
            << " values " << (dict.found("extent") ? "within 'extent'" : "")
            << " (" << (box.u1 - box.u0) << " x " << (box.v1 - box.v0)
            << " m on the DEM's axes; " << d.valueExtent.c_str() << ")"
            << nl << exit(FatalIOError);
    }
    const double u0 = box.u0 + i0*cs, v0 = box.v0 + j0*cs;
    g.origin = f.world(u0, v0);
    reportPlanGrid(g, dem, nx0, ny0);
    return g;
}


planBed bedOnPlan
(
    const dictionary& dict, const terrainDem& d, const planGrid& g
)
{
    const terrain::Raster& dem = d.raster;
    const label nx = g.nx, ny = g.ny;
    planBed bed{scalarField(g.nCells()), scalarField(g.nCells())};

    // Elevation at the cell centres; nodata under them counted
    label nNodata = 0;
    double bx0 = GREAT, bx1 = -GREAT, by0 = GREAT, by1 = -GREAT;
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const std::array<double, 2> W = g.world(g.x(i), g.y(j));
            const double z = dem.value(W[0], W[1]);
            if (!std::isfinite(z))
            {
                ++nNodata;
                bx0 = std::min(bx0, W[0]);
                bx1 = std::max(bx1, W[0]);
                by0 = std::min(by0, W[1]);
                by1 = std::max(by1, W[1]);
                bed.zb[i + nx*j] = 0;
                continue;
            }
            bed.zb[i + nx*j] = z;
        }
    }
    if (nNodata)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'dem': " << nNodata << " of the " << g.nCells()
            << " cell centres of the plan grid lie next to nodata pixels"
            << " of the DEM " << d.file << " (no bilinear value there),"
            << " their centres within X in [" << bx0 << ", " << bx1
            << "], Y in [" << by0 << ", " << by1 << "]: fill the DEM's"
            << " nodata or give an 'extent' that leaves them out" << nl
            << exit(FatalIOError);
    }

    // Slope: centred differences, one-sided at the edges
    const scalarField& zb = bed.zb;
    scalar gMin = GREAT, gMax = 0;
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const vector2D G = zbGradient(zb, nx, ny, g.cellSize, i, j);
            const scalar grad2 = G.x()*G.x() + G.y()*G.y();
            bed.cosTheta[i + nx*j] = 1/std::sqrt(1 + grad2);
            gMin = min(gMin, std::sqrt(grad2));
            gMax = max(gMax, std::sqrt(grad2));
        }
    }
    Info<< "Bed elevation zb in [" << min(zb) << ", " << max(zb)
        << "] m; slope in [" << radToDeg(std::atan(gMin)) << ", "
        << radToDeg(std::atan(gMax)) << "] deg (centred differences of"
        << " zb)" << nl;
    return bed;
}

} // End namespace Foam

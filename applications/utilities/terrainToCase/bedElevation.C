/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "bedElevation.H"
#include "unitConversion.H"

#include <sstream>

namespace Foam
{

namespace
{

//- The terrain's vertical distance from the reference surface at W and on
//  the axis at this x, for the message of a normal leaving the DEM
std::string gapText
(
    const terrain::Raster& dem, const terrain::referenceSurface& surface,
    const terrain::vec3& W, double x
)
{
    const double gap = W[2] - dem.value(W[0], W[1]);
    const terrain::vec3 A = surface.world(x, 0, 0);
    const double gapAxis = A[2] - dem.value(A[0], A[1]);
    // (both gaps finite: offset() and the axis' check sampled them);
    // in mm
    const auto mm = [](double v) { return std::round(1000*v)/1000; };
    std::ostringstream text;
    if (std::isfinite(gap))
    {
        text << "The terrain lies " << mm(std::fabs(gap)) << " m "
            << (mm(gap) >= 0 ? "below" : "above")
            << " the reference surface there (vertically";
        if (std::isfinite(gapAxis))
        {
            text << ", " << mm(std::fabs(gapAxis)) << " m "
                << (mm(gapAxis) >= 0 ? "below" : "above")
                << " it on the axis at this x";
        }
        text << "), and the";
    }
    else
    {
        text << "The";
    }
    return text.str();
}


//- FatalIOError: the normal at (x, y) (world W) leaves the DEM at E,
//  zNoValue along it, without meeting the terrain
void normalLeavesDem
(
    const dictionary& dict, const terrainDem& d,
    const terrain::referenceSurface& surface, double x, double y,
    double zNoValue, const terrain::vec3& W, const terrain::vec3& E
)
{
    // The normal runs along the axis in plan (N = (sin zeta t, cos
    // zeta))
    const double along =
        (E[0] - W[0])*surface.tX() + (E[1] - W[1])*surface.tY();
    const bool back = along < 0;
    const std::string gap = gapText(d.raster, surface, W, x);
    FatalIOErrorInFunction(dict)
        << "keyword 'dem': the normal from the reference surface at"
        << " x = " << x << ", y = " << y << " (world X = " << W[0]
        << ", Y = " << W[1] << ") leaves the DEM " << d.file
        << " at X = " << E[0] << ", Y = " << E[1] << " (" << zNoValue
        << " m along it, " << std::fabs(along) << " m in plan towards"
        << " the axis' " << (back ? "first" : "last") << " point)"
        << " without meeting the terrain; "
        << d.valueExtent.c_str() << "." << nl
        << gap.c_str()
        << " normal, along which zb is measured, runs along the axis in"
        << " plan.  A DEM reaching further beyond the axis' "
        << (back ? "first" : "last") << " point, an axis that "
        << (back ? "begins" : "ends") << " further inside the DEM, or"
        << " less departure of the terrain from the reference surface"
        << " there (a smaller halfWidth where it comes from the terrain"
        << " across the axis, a smaller profileSmoothing where it comes"
        << " from the profile along it) keep the normal on the DEM."
        << nl << exit(FatalIOError);
}


//- FatalIOError for the cell at (x, y) where offset() found no zb, with
//  zNoValue, the offset along the normal of the point with no DEM value
void bedFailure
(
    const dictionary& dict, const terrainDem& d,
    const terrain::referenceSurface& surface, double x, double y,
    double zNoValue
)
{
    const terrain::Raster& dem = d.raster;
    const terrain::vec3 W = surface.world(x, y, 0);
    if (zNoValue == 0)
    {
        const bool inside = dem.sampled(W[0], W[1]);
        FatalIOErrorInFunction(dict)
            << "keyword '" << (inside ? "dem" : "halfWidth")
            << "': the mesh cell at x = " << x << ", y = " << y
            << " (world X = " << W[0] << ", Y = " << W[1] << ") "
            << (inside
                ? "lies over a nodata hole of the DEM "
                : "lies outside the DEM ")
            << d.file << "; " << d.valueExtent.c_str() << nl
            << "(the mesh spans the axis' profile and +-halfWidth)"
            << nl << exit(FatalIOError);
    }
    if (!std::isfinite(zNoValue))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'dem': the offset of the DEM " << d.file
            << " from the reference surface along its normal at x = "
            << x << ", y = " << y << " (world X = " << W[0] << ", Y = "
            << W[1] << ") was not found: the secant iteration did not"
            << " converge there" << nl << exit(FatalIOError);
    }
    const terrain::vec3 E = surface.world(x, y, zNoValue);
    if (dem.sampled(E[0], E[1]))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'dem': the normal from the reference surface at"
            << " x = " << x << ", y = " << y << " (world X = " << W[0]
            << ", Y = " << W[1] << ") meets a nodata hole of the DEM "
            << d.file << " at X = " << E[0] << ", Y = " << E[1]
            << " (" << zNoValue << " m along it) before it meets the"
            << " terrain: fill the DEM's nodata there" << nl
            << exit(FatalIOError);
    }
    normalLeavesDem(dict, d, surface, x, y, zNoValue, W, E);
}


//- The steepest cell of zb (central differences, one-sided at the edges)
//  and how many are steeper than steep
struct bedSlope
{
    scalar gradMax = 0;
    label cellMax = 0;
    label nSteep = 0;
};

bedSlope steepestCell(const scalarField& zb, const chuteGrid& g, scalar steep)
{
    const label nx = g.nx, ny = g.ny;
    const scalar cellSize = g.cellSize;
    bedSlope s;
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label c = i + nx*j;
            const vector2D G = zbGradient(zb, nx, ny, cellSize, i, j);
            const scalar grad = std::sqrt(G.x()*G.x() + G.y()*G.y());
            s.nSteep += (grad > steep);
            if (grad > s.gradMax)
            {
                s.gradMax = grad;
                s.cellMax = c;
            }
        }
    }
    return s;
}

} // End anonymous namespace


scalarField bedElevation
(
    const dictionary& dict, const terrainDem& dem,
    const thalwegProfile& profile, const chuteGrid& g
)
{
    const terrain::Raster& raster = dem.raster;
    const auto elevation = [&raster](double X, double Y)
    {
        return raster.value(X, Y);
    };
    scalarField zb(g.nCells());
    for (label j = 0; j < g.ny; ++j)
    {
        for (label i = 0; i < g.nx; ++i)
        {
            const double x = g.x(i);
            const double y = g.y(j);
            double zNoValue = 0;
            const double z =
                profile.surface.offset(x, y, elevation, &zNoValue);
            if (!std::isfinite(z))
            {
                bedFailure(dict, dem, profile.surface, x, y, zNoValue);
            }
            zb[i + g.nx*j] = z;
        }
    }
    return zb;
}


void reportBedSlope
(
    const scalarField& zb, const thalwegProfile& profile,
    const chuteGrid& g
)
{
    const scalar steep = 0.5;
    const bedSlope s = steepestCell(zb, g, steep);
    const double x = g.x(s.cellMax % g.nx);
    const double y = g.y(s.cellMax/g.nx);
    const terrain::vec3 W = profile.surface.world(x, y, zb[s.cellMax]);
    Info<< "zb in [" << gMin(zb) << ", " << gMax(zb) << "] m; largest"
        << " |grad zb| " << s.gradMax << " ("
        << radToDeg(std::atan(s.gradMax)) << " deg) at x = " << x
        << ", y = " << y << " (X = " << W[0] << ", Y = " << W[1]
        << ", Z = " << W[2] << ")" << nl;
    if (s.nSteep)
    {
        WarningInFunction
            << s.nSteep << " of " << g.nCells() << " cells have |grad zb| > "
            << steep << " (" << radToDeg(std::atan(steep)) << " deg),"
            << " the largest " << s.gradMax << " ("
            << radToDeg(std::atan(s.gradMax)) << " deg) at x = " << x
            << ", y = " << y << " (X = " << W[0] << ", Y = " << W[1]
            << "): there the terrain departs from the reference surface"
            << " more steeply than the shallow-flow model assumes"
            << " (a straighter axis, more profileSmoothing or a smaller"
            << " halfWidth help)" << nl << endl;
    }
}

} // End namespace Foam

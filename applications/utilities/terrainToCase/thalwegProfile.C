/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "thalwegProfile.H"
#include "unitConversion.H"

#include <algorithm>

namespace Foam
{

namespace
{

//- The DEM's elevation at nS points dS apart along the axis; FatalIOError
//  where it has none
std::vector<double> sampleAxis
(
    const dictionary& dict, const terrainDem& d, const chuteAxis& axis,
    label nS, double dS
)
{
    const terrain::Raster& dem = d.raster;
    const std::array<double, 4> demBox = dem.bounds();
    std::vector<double> Zraw(nS);
    for (label k = 0; k < nS; ++k)
    {
        const vector2D P = axis.P0 + (k*dS)*axis.t;
        Zraw[k] = dem.value(P.x(), P.y());
        if (!std::isfinite(Zraw[k]))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'axis': the axis from " << axis.points[0]
                << " to " << axis.points[1] << " leaves the DEM"
                << " or crosses nodata at " << P << " (distance " << k*dS
                << " m from its first point); the DEM " << d.file
                << (dem.northUp() ? "" : " (rotated; its bounding box)")
                << " covers X in [" << demBox[0] << ", " << demBox[1]
                << "], Y in [" << demBox[2] << ", " << demBox[3] << "]" << nl
                << exit(FatalIOError);
        }
    }
    return Zraw;
}


//- Slopes dZ/dS of the profile at its samples and Z at the first one: a
//  local linear fit with biweight weights over +-L (L = 0: differences)
void fitProfile
(
    const std::vector<double>& Z, double dS, double L,
    std::vector<double>& slope, double& Z0
)
{
    const label n = label(Z.size());
    slope.assign(Z.size(), 0);
    if (L < 1.5*dS)
    {
        for (label k = 0; k < n; ++k)
        {
            const label a = max(k - 1, label(0));
            const label b = min(k + 1, n - 1);
            slope[k] = (Z[b] - Z[a])/((b - a)*dS);
        }
        Z0 = Z[0];
        return;
    }
    const label w = label(std::ceil(L/dS));
    for (label k = 0; k < n; ++k)
    {
        double sw = 0, su = 0, sz = 0, suu = 0, suz = 0;
        for (label m = max(k - w, label(0)); m <= min(k + w, n - 1); ++m)
        {
            const double u = (m - k)*dS;
            const double r = u/L;
            if (std::fabs(r) >= 1)
            {
                continue;
            }
            const double wt = sqr(1 - r*r);
            sw += wt;
            su += wt*u;
            sz += wt*Z[m];
            suu += wt*u*u;
            suz += wt*u*Z[m];
        }
        const double det = sw*suu - su*su;
        slope[k] = (sw*suz - su*sz)/det;
        if (k == 0)
        {
            Z0 = (suu*sz - su*suz)/det;
        }
    }
}


//- x of the table's points: where the profile has advanced dS in plan
std::vector<double> tablePoints
(
    const std::vector<double>& zetaDeg, double dS
)
{
    const label nS = label(zetaDeg.size());
    std::vector<double> xTable(nS, 0.0);
    for (label k = 1; k < nS; ++k)
    {
        const double z0 = degToRad(zetaDeg[k - 1]);
        const double z1 = degToRad(zetaDeg[k]);
        double dx = dS/std::cos(0.5*(z0 + z1));
        for (int it = 0; it < 20; ++it)
        {
            dx *= dS/terrain::referenceSurface::planAdvance(z0, z1, dx);
        }
        xTable[k] = xTable[k - 1] + dx;
    }
    return xTable;
}

//- A warning with figures where the fitted profile rises along the axis
//  (zeta < 0: a counter-slope the flow must climb)
void reportCounterSlopes(const std::vector<double>& zetaDeg, double dS)
{
    label n = 0;
    double first = -1, last = -1, lowest = 0;
    for (std::size_t k = 0; k < zetaDeg.size(); ++k)
    {
        if (zetaDeg[k] < 0)
        {
            ++n;
            first = first < 0 ? k*dS : first;
            last = k*dS;
            lowest = std::min(lowest, zetaDeg[k]);
        }
    }
    if (n > 0)
    {
        WarningInFunction
            << "the profile along the axis rises (zeta < 0) at " << n
            << " of its " << zetaDeg.size() << " points, from " << first
            << " to " << last << " m along it in plan, down to zeta = "
            << lowest << " deg: a counter-slope the flow must climb.  Is"
            << " the axis on the thalweg, top to bottom?" << nl;
    }
}

} // End anonymous namespace


thalwegProfile readProfile
(
    const dictionary& dict, const terrainDem& dem, const chuteAxis& axis
)
{
    const label nS =
        max(label(2), label(std::ceil(2*axis.length/axis.cellSize)) + 1);
    const double dS = axis.length/(nS - 1);
    const std::vector<double> Zraw = sampleAxis(dict, dem, axis, nS, dS);
    if (Zraw.back() > Zraw.front())
    {
        // x runs downslope: the upslope end is a wall, the flow leaves at
        // the other; an axis drawn bottom to top gives neither
        FatalIOErrorInFunction(dict)
            << "keyword 'axis' runs uphill: the DEM is " << Zraw.front()
            << " m high at its first point " << axis.points[0] << " and "
            << Zraw.back() << " m at its last " << axis.points[1]
            << " (a rise of " << Zraw.back() - Zraw.front() << " m over "
            << axis.length << " m in plan).  Give its points top to"
            << " bottom: (" << axis.points[1] << " " << axis.points[0]
            << ")" << nl << exit(FatalIOError);
    }

    thalwegProfile p;
    std::vector<double> slope;
    p.Z0 = 0;
    fitProfile(Zraw, dS, axis.smoothing, slope, p.Z0);
    p.zetaDeg.resize(nS);
    for (label k = 0; k < nS; ++k)
    {
        p.zetaDeg[k] = radToDeg(std::atan(-slope[k]));
    }
    p.x = tablePoints(p.zetaDeg, dS);
    reportCounterSlopes(p.zetaDeg, dS);
    p.surface = terrain::referenceSurface
    (
        {axis.P0.x(), axis.P0.y(), p.Z0}, axis.t.x(), axis.t.y(),
        p.x, p.zetaDeg
    );
    return p;
}


chuteGrid gridOnProfile
(
    const dictionary& dict, const chuteAxis& axis,
    const thalwegProfile& profile
)
{
    const terrain::referenceSurface& surface = profile.surface;
    const scalar cellSize = axis.cellSize;
    chuteGrid g;
    g.cellSize = cellSize;
    g.nx = label(std::floor(surface.xEnd()/cellSize*(1 + 1e-12)));
    g.ny = max(label(1), label(std::round(2*axis.halfWidth/cellSize)));
    if (g.nx < 1)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'axis': the profile along the axis is "
            << surface.xEnd() << " m long, shorter than one cell"
            << " (cellSize " << cellSize << ")" << nl << exit(FatalIOError);
    }
    g.xMax = g.nx*cellSize;
    g.yMax = 0.5*g.ny*cellSize;
    const std::vector<double>& zeta = profile.zetaDeg;
    // The points as written in terrainDict, without OpenFOAM's list size
    Info<< "Axis (";
    forAll(axis.points, i)
    {
        Info<< (i ? " " : "") << "(" << axis.points[i].x() << " "
            << axis.points[i].y() << ")";
    }
    Info<< "): " << axis.length << " m in plan,"
        << " profile " << surface.xEnd() << " m long, zeta from "
        << *std::min_element(zeta.begin(), zeta.end()) << " to "
        << *std::max_element(zeta.begin(), zeta.end()) << " deg" << nl
        << "Mesh: " << g.nx << " x " << g.ny << " cells of " << cellSize
        << " m, x in [0, " << g.xMax << "], y in [" << -g.yMax << ", "
        << g.yMax << "]" << nl;
    return g;
}

} // End namespace Foam

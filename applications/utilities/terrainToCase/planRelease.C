/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "planRelease.H"

#include "polygonClip.H"
#include "rasterRelease.H"

namespace Foam
{

namespace
{

//- A ring of r's polygons in the grid's (x, y); FatalIOError for a vertex
//  outside the grid
std::vector<terrain::point2> ringOnGrid
(
    const terrain::Ring& ring, const release& r, const planGrid& g
)
{
    const scalar xMax = g.xMax(), yMax = g.yMax();
    std::vector<terrain::point2> xy;
    for (const auto& P : ring)
    {
        const std::array<double, 2> p = g.local(P[0], P[1]);
        if
        (
            !(p[0] >= -1e-9*xMax && p[0] <= xMax*(1 + 1e-9)
           && p[1] >= -1e-9*yMax && p[1] <= yMax*(1 + 1e-9))
        )
        {
            const std::array<double, 2> A = g.world(0, 0);
            const std::array<double, 2> B = g.world(xMax, yMax);
            FatalIOErrorInFunction(*r.dict)
                << "keyword '" << r.shapeKey << "' of " << r.kind << ' '
                << r.name << ": the " << r.kind << " outline passes (X = " << P[0] << ", Y = "
                << P[1] << ") (x = " << p[0] << ", y = " << p[1]
                << ") outside the plan grid, x in [0, " << xMax
                << "], y in [0, " << yMax << "] (corners X = " << A[0]
                << ", Y = " << A[1] << " and X = " << B[0] << ", Y = "
                << B[1] << ")" << nl << exit(FatalIOError);
        }
        xy.push_back({p[0], p[1]});
    }
    return xy;
}


//- Add sign times the fraction of each cell polygon xy covers
void addCover
(
    const std::vector<terrain::point2>& xy, double sign, const planGrid& g,
    scalarField& frac
)
{
    const scalar cs = g.cellSize;
    double bx0 = GREAT, bx1 = -GREAT, by0 = GREAT, by1 = -GREAT;
    for (const auto& p : xy)
    {
        bx0 = std::min(bx0, p[0]);
        bx1 = std::max(bx1, p[0]);
        by0 = std::min(by0, p[1]);
        by1 = std::max(by1, p[1]);
    }
    const label i0 = max(label(0), label(std::floor(bx0/cs)));
    const label i1 = min(g.nx - 1, label(std::floor(bx1/cs)));
    const label j0 = max(label(0), label(std::floor(by0/cs)));
    const label j1 = min(g.ny - 1, label(std::floor(by1/cs)));
    for (label j = j0; j <= j1; ++j)
    {
        for (label i = i0; i <= i1; ++i)
        {
            const double a = terrain::clippedArea
            (
                xy, i*cs, (i + 1)*cs, j*cs, (j + 1)*cs
            );
            frac[i + g.nx*j] += sign*a/(cs*cs);
        }
    }
}


scalarField polygonThickness(const release& r, const planGrid& g)
{
    scalarField frac(g.nCells(), Zero);
    for (const terrain::Polygon& poly : r.polygons)
    {
        forAll(poly, ringi)
        {
            // The exterior adds, the holes take away
            addCover(ringOnGrid(poly[ringi], r, g), ringi == 0 ? 1 : -1, g, frac);
        }
    }
    scalarField d(g.nCells(), Zero);
    forAll(frac, c)
    {
        // Overlapping polygons of one release count once
        d[c] = r.value*min(max(frac[c], scalar(0)), scalar(1));
    }
    return d;
}


scalarField rasterThickness
(
    const release& r, const terrainDem& dem, const planGrid& g,
    terrain::rasterRelease& mapped
)
{
    // The plan frame as a flat reference surface: its x the grid's, its y
    // the grid's less yMax/2 (y symmetric, as rasterRelease's mesh), z up
    const scalar yHalf = 0.5*g.yMax();
    const std::array<double, 2> O = g.world(0, yHalf);
    const terrain::referenceSurface flat
    (
        {O[0], O[1], 0}, g.xAxis[0], g.xAxis[1], {0, g.xMax()}, {0, 0}
    );
    return rasterReleaseThickness
    (
        r, dem.raster, flat, {g.nx, g.ny, g.cellSize, yHalf}, mapped
    );
}

} // End anonymous namespace


areaLayer planReleaseThickness
(
    const std::vector<release>& releases, const terrainDem& dem,
    const planGrid& g, const planBed& bed
)
{
    areaLayer layer;
    if (releases.empty())
    {
        return layer;
    }
    const scalar cellArea = g.cellSize*g.cellSize;
    layer.values.setSize(g.nCells(), Zero);
    for (const release& r : releases)
    {
        // The value in each cell, a thickness normal or vertical as given
        terrain::rasterRelease mapped;
        const scalarField d = r.shapeKey == "raster"
          ? rasterThickness(r, dem, g, mapped)
          : polygonThickness(r, g);
        scalar volume = 0;
        scalarField values(d.size(), Zero);
        forAll(d, c)
        {
            if (d[c] > 0)
            {
                const scalar cosTheta = bed.cosTheta[c];
                values[c] = d[c]*(r.vertical ? cosTheta : 1);
                volume += values[c]/cosTheta*cellArea;
            }
        }
        if (!(volume > 0))
        {
            FatalIOErrorInFunction(*r.dict)
                << "keyword '" << r.shapeKey << "' of " << r.kind << ' '
                << r.name << ": the " << r.kind << ' '
                << (r.shapeKey == "raster" ? r.rasterFile + " " : "")
                << "covers no area of the plan grid" << nl
                << exit(FatalIOError);
        }
        reportRelease(r, mapped, volume, values);
        layer.values += values;
        layer.volume += volume;
    }
    reportLayer(releases, layer);
    if (releases.front().valueKey == "thickness")
    {
        Info<< " (sum of h J A, J = 1/cos(theta) the surface area per plan"
            << " area)";
    }
    Info<< nl << endl;
    return layer;
}

} // End namespace Foam

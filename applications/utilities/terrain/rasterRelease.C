/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    mapRasterRelease step by step (rasterRelease.H says what it computes):
    the window of the pixels with d > 0 (releaseWindow), the lattice of
    sub-pixels over it (releaseLattice: s, and its rows in the DEM's plan
    and in (x, y)), each pixel's outline on it (pixelOutline) and the
    pixel deposited onto the cells it overlaps (depositPixel).
\*---------------------------------------------------------------------------*/

#include "rasterRelease.H"
#include "polygonClip.H"

#include <algorithm>
#include <cmath>

namespace terrain
{

namespace
{

//- The pixels i0..i1 x j0..j1 of the raster that hold all with d > 0
struct pixelWindow
{
    int i0, i1, j0, j1;

    int width() const
    {
        return i1 - i0 + 1;
    }
};

//- The window of the pixels with d > 0; their number and the range of d
//  in out
pixelWindow releaseWindow(const Raster& r, rasterRelease& out)
{
    pixelWindow w{r.nx, -1, r.ny, -1};
    for (int j = 0; j < r.ny; ++j)
    {
        for (int i = 0; i < r.nx; ++i)
        {
            const double d = r.at(i, j);
            if (r.valid(d) && d > 0)
            {
                w.i0 = std::min(w.i0, i);
                w.i1 = std::max(w.i1, i);
                w.j0 = std::min(w.j0, j);
                w.j1 = std::max(w.j1, j);
                out.dMin = out.nPixels ? std::min(out.dMin, d) : d;
                out.dMax = out.nPixels ? std::max(out.dMax, d) : d;
                ++out.nPixels;
            }
        }
    }
    return w;
}


//- A row of the lattice: its W s + 1 points in the DEM's plan, their
//  (x, y) and whether they have one
struct latticeRow
{
    std::vector<std::array<double, 2>> plan;
    std::vector<point2> xy;
    std::vector<char> ok;
};


//- The lattice of s x s sub-pixels over the window's pixels
class releaseLattice
{
    const Raster& r_;
    const crsTransform& tr_;
    const Raster& dem_;
    const referenceSurface& surface_;
    const pixelWindow w_;

public:

    releaseLattice
    (
        const Raster& r, const crsTransform& tr, const Raster& dem,
        const referenceSurface& surface, const pixelWindow& w
    )
    :
        r_(r), tr_(tr), dem_(dem), surface_(surface), w_(w)
    {}

    //- Lattice points of pixel rows' edges in the DEM's plan: at row (a
    //  pixel row's index, fractional between its edges), s a pixel
    std::vector<std::array<double, 2>> planRow(double row, int s) const
    {
        const int W = w_.width();
        std::vector<std::array<double, 2>> P(std::size_t(W*s + 1));
        for (int a = 0; a <= W*s; ++a)
        {
            P[a] = r_.point(w_.i0 + double(a)/s, row);
        }
        tr_.apply(P);
        return P;
    }

    //- s from the largest pixel edge in the DEM's plan (corners only): 4
    //  samples a cell along an edge, 1 to 16
    int subdivisions(double cellSize) const
    {
        const int W = w_.width();
        double edge = 0;
        std::vector<std::array<double, 2>> top = planRow(w_.j0, 1);
        for (int j = w_.j0; j <= w_.j1; ++j)
        {
            const std::vector<std::array<double, 2>> bottom =
                planRow(j + 1, 1);
            for (int a = 0; a < W; ++a)
            {
                const auto& p = top[a];
                edge = std::max
                ({
                    edge,
                    std::hypot(top[a + 1][0] - p[0], top[a + 1][1] - p[1]),
                    std::hypot(bottom[a][0] - p[0], bottom[a][1] - p[1])
                });
            }
            top = bottom;
        }
        return std::max
        (
            1, std::min(16, int(std::ceil(4*edge/cellSize - 1e-9)))
        );
    }

    //- Lattice row b of pixel row j (b = 0 its top edge, s its bottom),
    //  taken onto the DEM and to (x, y) by the foot of the normal
    latticeRow mapRow(int j, int b, int s) const
    {
        latticeRow L;
        L.plan = planRow(j + double(b)/s, s);
        L.xy.resize(L.plan.size());
        L.ok.assign(L.plan.size(), 0);
        for (std::size_t a = 0; a < L.plan.size(); ++a)
        {
            const double X = L.plan[a][0], Y = L.plan[a][1];
            const double Z = dem_.value(X, Y);
            double x = 0, y = 0, z = 0;
            if (std::isfinite(Z) && surface_.local({X, Y, Z}, x, y, z))
            {
                L.xy[a] = {x, y};
                L.ok[a] = 1;
            }
        }
        return L;
    }
};


//- The outline of the pixel of lattice columns a0 .. a0 + s between
//  rows[0] and rows[s] (top, right, bottom, left edge) in (x, y), ring,
//  and in the DEM's plan, plan; false where a point of it has no (x, y)
bool pixelOutline
(
    const std::vector<latticeRow>& rows, int a0, int s,
    std::vector<point2>& ring, std::vector<point2>& plan
)
{
    ring.clear();
    plan.clear();
    bool ok = true;
    const auto add = [&](int b, int a)
    {
        ok = ok && rows[b].ok[a];
        ring.push_back(rows[b].xy[a]);
        plan.push_back(rows[b].plan[a]);
    };
    for (int a = 0; a < s; ++a) { add(0, a0 + a); }
    for (int b = 0; b < s; ++b) { add(b, a0 + s); }
    for (int a = s; a > 0; --a) { add(s, a0 + a); }
    for (int b = s; b > 0; --b) { add(b, a0); }
    return ok;
}


//- A pixel of thickness d and outline ring in (x, y) onto the cells of g
//  it overlaps (out.h), what lies off the mesh counted in out
void depositPixel
(
    const std::vector<point2>& ring, double d, const meshGrid& g,
    rasterRelease& out
)
{
    const double cellArea = g.cellSize*g.cellSize;
    const double xMax = g.nx*g.cellSize;
    double bx0 = ring[0][0], bx1 = bx0, by0 = ring[0][1], by1 = by0;
    for (const point2& p : ring)
    {
        bx0 = std::min(bx0, p[0]);
        bx1 = std::max(bx1, p[0]);
        by0 = std::min(by0, p[1]);
        by1 = std::max(by1, p[1]);
    }
    const double area = std::fabs(signedArea(ring));
    double inside = 0;
    if (bx1 > 0 && bx0 < xMax && by1 > -g.yMax && by0 < g.yMax)
    {
        const long ci0 = std::max(0L, long(std::floor(bx0/g.cellSize)));
        const long ci1 =
            std::min(g.nx - 1, long(std::floor(bx1/g.cellSize)));
        const long cj0 = std::max
        (
            0L, long(std::floor((by0 + g.yMax)/g.cellSize))
        );
        const long cj1 = std::min
        (
            g.ny - 1, long(std::floor((by1 + g.yMax)/g.cellSize))
        );
        for (long cj = cj0; cj <= cj1; ++cj)
        {
            for (long ci = ci0; ci <= ci1; ++ci)
            {
                const double A = clippedArea
                (
                    ring, ci*g.cellSize, (ci + 1)*g.cellSize,
                    -g.yMax + cj*g.cellSize,
                    -g.yMax + (cj + 1)*g.cellSize
                );
                out.h[std::size_t(ci + g.nx*cj)] += d*A/cellArea;
                inside += A;
            }
        }
    }
    if (area - inside > 1e-9*area)
    {
        ++out.nOutside;
        out.outsideVolume += d*(area - inside);
    }
}

} // End anonymous namespace


rasterRelease mapRasterRelease
(
    const Raster& r, const crsTransform& tr, const Raster& dem,
    const referenceSurface& surface, const meshGrid& g
)
{
    rasterRelease out;
    out.h.assign(std::size_t(g.nx*g.ny), 0.0);
    const pixelWindow w = releaseWindow(r, out);
    if (!out.nPixels)
    {
        return out;
    }
    const releaseLattice lattice(r, tr, dem, surface, w);
    const int s = lattice.subdivisions(g.cellSize);
    out.subdivisions = s;

    // Pixel row by pixel row, its lattice rows 0 .. s (0: the previous
    // row's s)
    std::vector<latticeRow> rows(std::size_t(s + 1));
    rows[0] = lattice.mapRow(w.j0, 0, s);
    std::vector<point2> ring, plan;
    for (int j = w.j0; j <= w.j1; ++j)
    {
        for (int b = 1; b <= s; ++b)
        {
            rows[b] = lattice.mapRow(j, b, s);
        }
        for (int i = w.i0; i <= w.i1; ++i)
        {
            const double d = r.at(i, j);
            if (!(r.valid(d) && d > 0))
            {
                continue;
            }
            const bool ok = pixelOutline(rows, (i - w.i0)*s, s, ring, plan);
            out.planVolume += d*std::fabs(signedArea(plan));
            if (!ok)
            {
                ++out.nOffDem;
                continue;
            }
            depositPixel(ring, d, g, out);
        }
        rows[0] = std::move(rows[s]);
    }
    return out;
}

} // namespace terrain

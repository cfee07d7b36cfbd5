/*---------------------------------------------------------------------------*\
  The cut of the CUDA backend's launch grids on a subdomain (cuda/overlap.H):
  the interior computed while the halos travel, the frame after.
  Host code, checked without a GPU.

    For every part of the splits 1x1, 2x1, 1x2, 2x2, 3x1, 3x3 of grids from
    3 x 3 to 200 x 72 cells, with the cell tiles (32 x 8, cuda/tiles.H) and
    the face blocks (31 x 7 faces, shifted by one cell: stepKernels.H
    fluxKernel), and with other tile sizes:
      - the interior and the four pieces of the frame cover every block of
        the launch grid exactly once;
      - no block of the interior covers a cell within Overlap::margin
        cells of a processor side (it reads no ghost cell the exchange
        fills);
      - exactly one part leads (does the once-per-step work);
      - without a processor side the interior is the whole grid.
    For the 200 x 72 grid of tests/common/parallelCases.H wideSlope, every part of
    the splits the decomposed tests use (2x1, 1x2, 2x2, 3x1) has a
    non-empty interior with the default tiles, for the cells and for the
    faces: tests parallelGpu_* do run the overlap.  The table printed
    gives each part's interior blocks.
\*---------------------------------------------------------------------------*/

#include "cuda/overlap.H"
#include "parallel/halo.H"
#include "testing.H"

#include <cstdio>
#include <string>
#include <vector>

using namespace sh;
using shtest::Counter;

namespace
{

//- The tiling of a kernel: tileX x tileY cells per block, shifted
struct Tiling
{
    const char* name;
    int tileX, tileY, shift;
};

const Tiling cellTiles = {"cells 32x8", 32, 8, 0};
const Tiling faceTiles = {"faces 31x7", 31, 7, -1};

BoundarySpec<double> sidesOf(const Subdomain& s)
{
    BoundarySpec<double> bc;
    for (int side = 0; side < 4; ++side)
    {
        bc.type[side] = s.processorSide(side)
            ? BCType::processor : BCType::wall;
    }
    return bc;
}

Overlap cut(const Subdomain& s, const Tiling& t)
{
    const int nbx = (s.nx - t.shift + t.tileX - 1)/t.tileX;
    const int nby = (s.ny - t.shift + t.tileY - 1)/t.tileY;
    return Overlap(nbx, nby, t.tileX, t.tileY, t.shift, s.nx, s.ny, sidesOf(s));
}

//- What is wrong with the cut o of part s, "" if nothing
std::string cutError(const Subdomain& s, const Tiling& t, const Overlap& o)
{
    const int nbx = (s.nx - t.shift + t.tileX - 1)/t.tileX;
    const int nby = (s.ny - t.shift + t.tileY - 1)/t.tileY;
    std::vector<int> count(std::size_t(nbx)*nby, 0);
    const BlockRect* parts[5] =
        {&o.interior, &o.frame[0], &o.frame[1], &o.frame[2], &o.frame[3]};
    for (const BlockRect* r : parts)
    {
        if (r->empty())
        {
            continue;
        }
        if (r->x0 < 0 || r->y0 < 0 || r->x0 + r->nx > nbx || r->y0 + r->ny > nby)
        {
            return "a part reaches beyond the launch grid";
        }
        for (int by = r->y0; by < r->y0 + r->ny; ++by)
        {
            for (int bx = r->x0; bx < r->x0 + r->nx; ++bx)
            {
                ++count[bx + std::size_t(by)*nbx];
            }
        }
    }
    for (int c : count)
    {
        if (c != 1)
        {
            return "a block in " + std::to_string(c) + " parts";
        }
    }
    if (!o.interior.empty())
    {
        const int m = Overlap::margin;
        const int i0 = o.interior.x0*t.tileX + t.shift;
        const int i1 = (o.interior.x0 + o.interior.nx)*t.tileX + t.shift - 1;
        const int j0 = o.interior.y0*t.tileY + t.shift;
        const int j1 = (o.interior.y0 + o.interior.ny)*t.tileY + t.shift - 1;
        if
        (
            (s.processorSide(xMin) && i0 - m < 0)
         || (s.processorSide(xMax) && i1 + m > s.nx - 1)
         || (s.processorSide(yMin) && j0 - m < 0)
         || (s.processorSide(yMax) && j1 + m > s.ny - 1)
        )
        {
            return "the interior comes within the margin of a processor side";
        }
    }
    // The leader: a frame piece with blocks, or the interior when the
    // frame has none (launchFrame and launchInterior lead by it)
    const int lead = o.leader();
    const bool frameEmpty = o.frame[0].empty() && o.frame[1].empty()
        && o.frame[2].empty() && o.frame[3].empty();
    if (lead < 0 ? !(frameEmpty && !o.interior.empty()) : o.frame[lead].empty())
    {
        return "no part leads";
    }
    bool anyProcessor = false;
    for (int side = 0; side < 4; ++side)
    {
        anyProcessor = anyProcessor || s.processorSide(side);
    }
    if
    (
        !anyProcessor
     && (o.interior.nx != nbx || o.interior.ny != nby || o.leader() != -1)
    )
    {
        return "a grid without processor sides is not all interior";
    }
    return "";
}

void properties(Counter& t)
{
    const int sizes[][2] =
        {{3, 3}, {7, 5}, {40, 36}, {64, 32}, {100, 40}, {200, 72}, {333, 129}};
    const int splits[][2] = {{1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 1}, {3, 3}};
    const Tiling others[] =
        {{"cells 8x4", 8, 4, 0}, {"faces 7x3", 7, 3, -1}, {"cells 4x2", 4, 2, 0}};
    int parts = 0;
    std::string first;
    for (const auto& n : sizes)
    {
        for (const auto& p : splits)
        {
            if (n[0]/p[0] < Grid<double>::ng || n[1]/p[1] < Grid<double>::ng)
            {
                continue;
            }
            for (int r = 0; r < p[0]*p[1]; ++r)
            {
                const Subdomain s = splitGrid(n[0], n[1], p[0], p[1], r);
                const Tiling tilings[] =
                    {cellTiles, faceTiles, others[0], others[1], others[2]};
                for (const Tiling& tl : tilings)
                {
                    ++parts;
                    const std::string e = cutError(s, tl, cut(s, tl));
                    if (!e.empty() && first.empty())
                    {
                        first = std::to_string(n[0]) + "x"
                          + std::to_string(n[1]) + " split "
                          + std::to_string(p[0]) + "x" + std::to_string(p[1])
                          + " part " + std::to_string(r) + ", " + tl.name
                          + ": " + e;
                    }
                }
            }
        }
    }
    t.check
    (
        first.empty(),
        "cuts of " + std::to_string(parts) + " parts and tilings: every block"
        " once, the interior clear of the processor sides, one leader"
      + (first.empty() ? std::string() : " (" + first + ")")
    );
}

void wideSlope(Counter& t)
{
    std::printf
    (
        "\n  wideSlope, 200 x 72: interior blocks [x0, x1) x [y0, y1) of each"
        " part\n  %-6s %-5s %-14s %-22s %-22s\n",
        "split", "part", "cells", "cell blocks", "face blocks"
    );
    const int splits[][2] = {{2, 1}, {1, 2}, {2, 2}, {3, 1}};
    bool all = true;
    for (const auto& p : splits)
    {
        for (int r = 0; r < p[0]*p[1]; ++r)
        {
            const Subdomain s = splitGrid(200, 72, p[0], p[1], r);
            const Overlap c = cut(s, cellTiles);
            const Overlap f = cut(s, faceTiles);
            all = all && !c.interior.empty() && !f.interior.empty();
            const auto show = [](const BlockRect& b)
            {
                return "[" + std::to_string(b.x0) + "," + std::to_string(b.x0 + b.nx)
                  + ")x[" + std::to_string(b.y0) + ","
                  + std::to_string(b.y0 + b.ny) + ")";
            };
            std::printf
            (
                "  %dx%-4d %-5d %3d x %-8d %-22s %-22s\n", p[0], p[1], r,
                s.nx, s.ny, show(c.interior).c_str(), show(f.interior).c_str()
            );
        }
    }
    t.check
    (
        all,
        "wideSlope: every part of 2x1, 1x2, 2x2, 3x1 has an interior of"
        " cells and of faces (the GPU tests run the overlap)"
    );
}

} // namespace


int main()
{
    Counter t;
    properties(t);
    wideSlope(t);
    return t.finish();
}

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    How much of the batched ensemble's work a finer skip of dry cells
    could remove (issue 27 item 4): the members of ensembleBenchmark
    (tests/common/ensembleCases.H inclinedPlaneMember, k x k x (30 x 14)
    cells, t = 0 .. tEnd) run on the CPU backend, and after every step the
    cells the CUDA kernels would compute are counted for several rules of
    skipping, as a share of the threads a step launches (the grid padded
    to whole 32 x 8 tiles: 128 x 56 on 120 x 56):

      tiles X x Y     tiles of X x Y cells skipped as cuda/tiles.H does:
                      a tile runs when a tile within the dependence
                      radius (6 cells, tiles.H dependenceRadius) holds
                      material now or before the step (32 x 8 is what the
                      kernels do; the others would need other blocks)
      warp rows       a row of 32 cells of a tile (one warp) runs when
                      material lies within 6 rows and within the tiles
                      left and right of it, now or before
      within r        a cell runs when material lies within r cells of it
                      (a square), now or before: the finest skip there is
                      with that radius
      wet within r    a cell runs when a wet cell (h > hDry) lies within
                      r cells of it, now or before: the finest skip if
                      layers at most hDry thick away from wet cells are
                      left as they are (two dry sides exchange no flux,
                      hllc.H; a partial-wet cell with no wet neighbour
                      takes no velocity): a skip that would need the
                      equality of such cells with their unskipped values
                      shown, bit for bit
      occupied        cells that hold material (a non-zero bit of h, hu
                      or hv, tiles.H occupied): cells no skip may leave
                      out, whatever its radius
      wet             cells with h > hDry after the step

    and the steps after which no wet cell moves (|u| = 0: what stopping
    members at rest could save).  Counts, not timings: the same on any
    machine.  If every skipped cell cost nothing and every computed one
    what it costs now, the batched run's time scales with the share: the
    table gives that bound on the speed-up from a measured one
    (-measured S, the ensembleBenchmark figure of the 32 x 8 tiles).

    Usage: ensembleActivity [-k K] [-members N] [-stride S] [-tEnd T]
                            [-measured SPEEDUP]
      members 0, S, 2S, ... below N (default 20 members, stride 1)
\*---------------------------------------------------------------------------*/

#include "cpu/cpuSolver.H"
#include "ensembleCases.H"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace sh;

namespace
{

//- tiles.H dependenceRadius: the cells a step's results of a cell depend on
constexpr int radius = 6;

//- Cells of a grid with a flag each, i fastest
struct Mask
{
    int nx, ny;
    std::vector<char> v;

    Mask(int x, int y) : nx(x), ny(y), v(std::size_t(x)*y, 0) {}

    bool at(int i, int j) const
    {
        return i >= 0 && i < nx && j >= 0 && j < ny && v[i + j*nx];
    }
};

//- Cells counted under one rule over all steps
struct Rule
{
    std::string name;
    double cells = 0;
};

//- The cells that tiles of bx x by compute: those of every tile with an
//  occupied tile within the radius (in tiles)
double tileCells(const Mask& u, int bx, int by)
{
    const int nTx = (u.nx + bx - 1)/bx;
    const int nTy = (u.ny + by - 1)/by;
    Mask t(nTx, nTy);
    for (int j = 0; j < u.ny; ++j)
    {
        for (int i = 0; i < u.nx; ++i)
        {
            if (u.v[i + j*u.nx]) { t.v[i/bx + (j/by)*nTx] = 1; }
        }
    }
    const int rx = (radius + bx - 1)/bx;
    const int ry = (radius + by - 1)/by;
    double n = 0;
    for (int ty = 0; ty < nTy; ++ty)
    {
        for (int tx = 0; tx < nTx; ++tx)
        {
            bool run = false;
            for (int dy = -ry; dy <= ry && !run; ++dy)
            {
                for (int dx = -rx; dx <= rx && !run; ++dx)
                {
                    run = t.at(tx + dx, ty + dy);
                }
            }
            if (run) { n += bx*by; }
        }
    }
    return n;
}

//- The cells that warps of one row of 32 cells compute
double warpRowCells(const Mask& u)
{
    const int w = 32;
    const int nSx = (u.nx + w - 1)/w;
    Mask s(nSx, u.ny);
    for (int j = 0; j < u.ny; ++j)
    {
        for (int i = 0; i < u.nx; ++i)
        {
            if (u.v[i + j*u.nx]) { s.v[i/w + j*nSx] = 1; }
        }
    }
    double n = 0;
    for (int j = 0; j < u.ny; ++j)
    {
        for (int sx = 0; sx < nSx; ++sx)
        {
            bool run = false;
            for (int dy = -radius; dy <= radius && !run; ++dy)
            {
                for (int dx = -1; dx <= 1 && !run; ++dx)
                {
                    run = s.at(sx + dx, j + dy);
                }
            }
            if (run) { n += w; }
        }
    }
    return n;
}

//- The cells with material within r cells (a square)
double withinCells(const Mask& u, int r)
{
    double n = 0;
    for (int j = 0; j < u.ny; ++j)
    {
        for (int i = 0; i < u.nx; ++i)
        {
            bool run = false;
            for (int dy = -r; dy <= r && !run; ++dy)
            {
                for (int dx = -r; dx <= r && !run; ++dx)
                {
                    run = u.at(i + dx, j + dy);
                }
            }
            if (run) { ++n; }
        }
    }
    return n;
}

bool nonZero(double a)
{
    unsigned long long b;
    std::memcpy(&b, &a, sizeof b);
    return b != 0;
}

} // namespace


int main(int argc, char* argv[])
{
    int k = 4, members = 20, stride = 1;
    double tEnd = 24, measured = 0;
    for (int a = 1; a < argc; ++a)
    {
        const std::string o = argv[a];
        const bool more = a + 1 < argc;
        if (o == "-k" && more) { k = std::atoi(argv[++a]); }
        else if (o == "-members" && more) { members = std::atoi(argv[++a]); }
        else if (o == "-stride" && more) { stride = std::atoi(argv[++a]); }
        else if (o == "-tEnd" && more) { tEnd = std::atof(argv[++a]); }
        else if (o == "-measured" && more) { measured = std::atof(argv[++a]); }
        else
        {
            std::fprintf
            (
                stderr, "ensembleActivity: unknown option %s (valid: -k,"
                " -members, -stride, -tEnd, -measured)\n", o.c_str()
            );
            return 1;
        }
    }
    if (k < 1 || members < 1 || stride < 1 || !(tEnd > 0))
    {
        std::fprintf(stderr, "ensembleActivity: k, members, stride >= 1,"
            " tEnd > 0\n");
        return 1;
    }

    std::vector<Rule> rules =
    {
        {"tiles 32 x 8 (the kernels)"}, {"tiles 32 x 4"}, {"tiles 16 x 8"},
        {"tiles 16 x 4"}, {"tiles 8 x 8"}, {"warp rows (32 x 1)"},
        {"within 6 cells"}, {"within 3 cells"}, {"wet within 6 cells"},
        {"wet within 3 cells"}, {"occupied"}, {"wet"}
    };
    double threads = 0, steps = 0, atRest = 0;
    int nx = 0, ny = 0, run = 0;
    for (int m = 0; m < members; m += stride, ++run)
    {
        Problem<double> pb = shcases::inclinedPlaneMember<double>(k, m);
        CpuSolver<double> s(pb, false);
        nx = pb.grid.nx;
        ny = pb.grid.ny;
        const double hDry = pb.params.hDry;
        const double launched = double((nx + 31)/32*32)*((ny + 7)/8*8);
        std::vector<double> h, hu, hv;
        s.getState(h, hu, hv);
        Mask before(nx, ny), now(nx, ny), either(nx, ny);
        Mask wetBefore(nx, ny), wetNow(nx, ny), wetEither(nx, ny);
        const auto wetOf = [&](Mask& o)
        {
            for (std::size_t c = 0; c < o.v.size(); ++c)
            {
                o.v[c] = h[c] > hDry;
            }
        };
        const auto occupy = [&](Mask& o)
        {
            for (std::size_t c = 0; c < o.v.size(); ++c)
            {
                o.v[c] = nonZero(h[c]) || nonZero(hu[c]) || nonZero(hv[c]);
            }
        };
        occupy(before);
        wetOf(wetBefore);
        while (s.time() < tEnd)
        {
            occupy(now);
            wetOf(wetNow);
            for (std::size_t c = 0; c < now.v.size(); ++c)
            {
                either.v[c] = now.v[c] | before.v[c];
                wetEither.v[c] = wetNow.v[c] | wetBefore.v[c];
            }
            rules[0].cells += tileCells(either, 32, 8);
            rules[1].cells += tileCells(either, 32, 4);
            rules[2].cells += tileCells(either, 16, 8);
            rules[3].cells += tileCells(either, 16, 4);
            rules[4].cells += tileCells(either, 8, 8);
            rules[5].cells += warpRowCells(either);
            rules[6].cells += withinCells(either, 6);
            rules[7].cells += withinCells(either, 3);
            rules[8].cells += withinCells(wetEither, 6);
            rules[9].cells += withinCells(wetEither, 3);
            threads += launched;
            ++steps;

            double dt = double(s.stableDt());
            const double left = tEnd - s.time();
            const bool last = dt >= left;
            if (last) { dt = left; }
            s.step(dt, last ? tEnd : s.time() + dt);

            before.v.swap(now.v);
            wetBefore.v.swap(wetNow.v);
            s.getState(h, hu, hv);
            double speed2 = 0;
            for (std::size_t c = 0; c < h.size(); ++c)
            {
                rules[10].cells += nonZero(h[c]) || nonZero(hu[c]) || nonZero(hv[c]);
                if (h[c] > hDry)
                {
                    rules[11].cells += 1;
                    const double u2 =
                        (hu[c]*hu[c] + hv[c]*hv[c])/(h[c]*h[c]);
                    if (u2 > speed2) { speed2 = u2; }
                }
            }
            if (speed2 == 0) { ++atRest; }
        }
    }

    std::printf
    (
        "## Work of the batched kernels under finer skips: %d members"
        " (0 to %d, stride %d) on %d x %d, t = 0 .. %g, %.0f steps\n\n",
        run, members - 1, stride, nx, ny, tEnd, steps
    );
    std::printf("| cells computed | share of the threads launched |"
        " share of today's (32 x 8 tiles) | bound on the speed-up%s |\n",
        measured > 0 ? " (from the measured one)" : "");
    std::printf("|---|---:|---:|---:|\n");
    for (const Rule& r : rules)
    {
        const double share = r.cells/threads;
        const double ofTiles = r.cells/rules[0].cells;
        char bound[64] = "-";
        if (measured > 0)
        {
            std::snprintf(bound, sizeof bound, "%.1f x", measured/ofTiles);
        }
        std::printf("| %s | %.3f | %.3f | %s |\n", r.name.c_str(), share,
            ofTiles, bound);
    }
    std::printf("\nSteps after which no wet cell moves: %.0f of %.0f"
        " (%.1f %%)\n", atRest, steps, 100*atRest/steps);
    return 0;
}

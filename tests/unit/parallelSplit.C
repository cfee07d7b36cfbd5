/*---------------------------------------------------------------------------*\
  The decomposition of a grid, without MPI (parallel/halo.H)

    splitGrid
      - refuses a split that leaves a part narrower than the Grid::ng = 2
        ghost layers (nx/px < 2 or ny/py < 2), a rank outside 0..px py - 1
        and a number of parts below 1, with std::invalid_argument;
      - accepts parts of exactly 2 cells;
      - tiles the grid: every cell in exactly one part; in x (and y) the
        parts differ by at most one cell, the larger first; rank = a + b px;
        each neighbour is the part across that side, and names this one
        across the opposite side; the whole grid's sides have none.
    subProblem, for every part of a 2x2 and a 3x1 split of the cases of
    tests/common/parallelCases.H (double and float)
      - cell centres xc, yc the whole grid's to the bit;
      - zeta, kappa, zb, h, hu, hv the whole problem's cells;
      - BCType::processor on the processor sides (no inflow state), the
        whole problem's condition and inflow state on the others;
      - the jet's cell ranges moved by the offset;
      - a subdomain that does not fit the whole grid refused.
    A part built on its own, as a decomposed application builds it (the
    Problem constructor of a Subdomain, its inclination and its jet, no
    whole arrays), for every part of 2x2, 3x1 and 1x3 splits of a jet on
    an inclination varying with x: grid, zeta, kappa, the jet's state and
    parameters bit for bit those of the part cut out of the whole; the
    parts' jet cells add up to the whole's; a part without jet cells is
    not refused.
\*---------------------------------------------------------------------------*/

#include "parallelCases.H"
#include "testing.H"

#include "host/decomposition.H"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

using namespace sh;
using namespace shtest;

namespace
{

bool refused(int nx, int ny, int px, int py, int rank, const char* words)
{
    try
    {
        splitGrid(nx, ny, px, py, rank);
    }
    catch (const std::invalid_argument& e)
    {
        const bool named = std::string(e.what()).find(words) != std::string::npos;
        std::printf("    %s\n", e.what());
        return named;
    }
    return false;
}


void refusals(Counter& t)
{
    std::printf("\nsplitGrid refusals\n");
    t.check(refused(3, 8, 2, 1, 0, "narrower"), "3 columns cut in 2 (a part of 1 column)");
    t.check(refused(8, 3, 1, 2, 1, "narrower"), "3 rows cut in 2");
    t.check(refused(5, 9, 3, 1, 2, "narrower"), "5 columns cut in 3 (parts 2, 2, 1)");
    t.check(refused(40, 36, 4, 19, 0, "narrower"), "36 rows cut in 19");
    t.check(refused(8, 8, 2, 2, 4, "rank"), "rank 4 of a 2 x 2 split");
    t.check(refused(8, 8, 2, 2, -1, "rank"), "rank -1");
    t.check(refused(8, 8, 0, 1, 0, "split"), "0 parts in x");
    bool accepted = true;
    try
    {
        for (int r = 0; r < 4; ++r)
        {
            const Subdomain s = splitGrid(4, 5, 2, 2, r);
            accepted = accepted && s.nx == 2 && s.ny == (r < 2 ? 3 : 2);
        }
    }
    catch (const std::exception& e)
    {
        std::printf("    %s\n", e.what());
        accepted = false;
    }
    t.check(accepted, "parts of exactly 2 cells accepted (4 x 5 cut 2 x 2)");
}


//- Whether the px x py split of nx x ny tiles it as the header says
bool tiles(int nx, int ny, int px, int py)
{
    std::vector<int> owner(std::size_t(nx)*ny, -1);
    std::vector<Subdomain> subs;
    bool ok = true;
    for (int r = 0; r < px*py; ++r)
    {
        subs.push_back(splitGrid(nx, ny, px, py, r));
    }
    for (int r = 0; r < px*py; ++r)
    {
        const Subdomain& s = subs[r];
        const int a = r%px;
        const int b = r/px;
        ok = ok && s.nxWhole == nx && s.nyWhole == ny;
        ok = ok && (s.nx == nx/px + (a < nx%px)) && (s.ny == ny/py + (b < ny%py));
        for (int j = 0; j < s.ny; ++j)
        {
            for (int i = 0; i < s.nx; ++i)
            {
                int& o = owner[(s.i0 + i) + std::size_t(s.j0 + j)*nx];
                ok = ok && o < 0;
                o = r;
            }
        }
        const int expect[4] =
        {
            a > 0 ? r - 1 : -1,
            a < px - 1 ? r + 1 : -1,
            b > 0 ? r - px : -1,
            b < py - 1 ? r + px : -1
        };
        for (int side = 0; side < 4; ++side)
        {
            const int m = s.neighbour[side];
            ok = ok && m == expect[side];
            if (m < 0)
            {
                continue;
            }
            const Subdomain& n = subs[m];
            ok = ok && n.neighbour[side ^ 1] == r;
            switch (side)
            {
                case xMin: ok = ok && n.i0 + n.nx == s.i0 && n.j0 == s.j0 && n.ny == s.ny; break;
                case xMax: ok = ok && s.i0 + s.nx == n.i0 && n.j0 == s.j0 && n.ny == s.ny; break;
                case yMin: ok = ok && n.j0 + n.ny == s.j0 && n.i0 == s.i0 && n.nx == s.nx; break;
                default:   ok = ok && s.j0 + s.ny == n.j0 && n.i0 == s.i0 && n.nx == s.nx; break;
            }
        }
    }
    for (const int o : owner)
    {
        ok = ok && o >= 0;
    }
    return ok;
}


void tiling(Counter& t)
{
    std::printf("\nsplitGrid tiles the grid\n");
    struct Split { int nx, ny, px, py; };
    const Split splits[] =
    {
        {40, 36, 1, 1}, {40, 36, 2, 1}, {40, 36, 1, 2}, {40, 36, 2, 2},
        {40, 36, 3, 1}, {13, 11, 3, 4}, {13, 11, 6, 5}, {101, 7, 50, 3},
        {64, 32, 7, 3}
    };
    for (const Split& s : splits)
    {
        t.check
        (
            tiles(s.nx, s.ny, s.px, s.py),
            std::to_string(s.nx) + " x " + std::to_string(s.ny) + " cut "
          + std::to_string(s.px) + " x " + std::to_string(s.py)
        );
    }
}


template<class T>
bool sameBits(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}


template<class Real>
bool cutsRight(const Problem<Real>& w, const Subdomain& s)
{
    const Problem<Real> p = subProblem(w, s);
    const Grid<Real>& g = p.grid;
    bool ok = g.nx == s.nx && g.ny == s.ny && g.i0 == s.i0 && g.j0 == s.j0;
    ok = ok && int(p.zeta.size()) == s.nx && int(p.kappa.size()) == s.nx
      && int(p.zb.size()) == s.nx*s.ny && int(p.h.size()) == s.nx*s.ny;
    if (!ok)
    {
        return false;
    }
    for (int i = 0; i < s.nx; ++i)
    {
        ok = ok && sameBits(g.xc(i), w.grid.xc(s.i0 + i))
          && sameBits(p.zeta[i], w.zeta[s.i0 + i])
          && sameBits(p.kappa[i], w.kappa[s.i0 + i]);
    }
    for (int j = 0; j < s.ny; ++j)
    {
        ok = ok && sameBits(g.yc(j), w.grid.yc(s.j0 + j));
        for (int i = 0; i < s.nx; ++i)
        {
            const int c = p.cell(i, j);
            const int cw = w.cell(s.i0 + i, s.j0 + j);
            ok = ok && sameBits(p.zb[c], w.zb[cw]) && sameBits(p.h[c], w.h[cw])
              && sameBits(p.hu[c], w.hu[cw]) && sameBits(p.hv[c], w.hv[cw]);
        }
    }
    for (int side = 0; side < 4; ++side)
    {
        if (s.processorSide(side))
        {
            ok = ok && p.bc.type[side] == BCType::processor
              && p.bc.inflow[side].h == Real(0);
        }
        else
        {
            ok = ok && p.bc.type[side] == w.bc.type[side]
              && sameBits(p.bc.inflow[side].h, w.bc.inflow[side].h)
              && sameBits(p.bc.inflow[side].hu, w.bc.inflow[side].hu)
              && sameBits(p.bc.inflow[side].hv, w.bc.inflow[side].hv);
        }
    }
    const JetParams<Real>& jp = p.params.jet;
    const JetParams<Real>& jw = w.params.jet;
    ok = ok && jp.on == jw.on && jp.iMin == jw.iMin - s.i0
      && jp.iMax == jw.iMax - s.i0 && jp.jMin == jw.jMin - s.j0
      && jp.jMax == jw.jMax - s.j0;
    return ok;
}


template<class Real>
void subProblems(Counter& t)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    std::printf("\nsubProblem, %s\n", prec);
    for (const shparallel::Case<Real>& c : shparallel::cases<Real>())
    {
        const Problem<Real> w = c.make();
        for (const int split : {22, 31})
        {
            const int px = split/10;
            const int py = split%10;
            bool ok = true;
            for (int r = 0; r < px*py; ++r)
            {
                ok = ok && cutsRight(w, splitGrid(w.grid.nx, w.grid.ny, px, py, r));
            }
            t.check
            (
                ok,
                c.name + ", " + prec + ", split " + std::to_string(px) + "x"
              + std::to_string(py) + ": every part cut out of the whole"
            );
        }
    }
    const Problem<Real> w = shparallel::wallsPile<Real>();
    bool refusedOther = false;
    try
    {
        subProblem(w, splitGrid(w.grid.nx + 1, w.grid.ny, 2, 1, 1));
    }
    catch (const std::invalid_argument& e)
    {
        std::printf("    %s\n", e.what());
        refusedOther = true;
    }
    t.check(refusedOther, std::string("a part of another grid refused, ") + prec);
}

//- A part built on its own equals the part cut out of the whole
template<class Real>
void directParts(Counter& t)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    std::printf("\nparts built on their own, %s\n", prec);
    const double x0 = -0.1, x1 = 0.3, y0 = -0.1, y1 = 0.1;
    const int nx = 48, ny = 24;
    const Params<Real> params = makeParams<Real>(ModelInput());
    const auto zetaOfX = [](double x) { return 0.4 + 0.5*x; };
    JetInput jet;
    jet.xc = 0.1;
    jet.yc = 0;
    jet.R = 7.5e-3;
    jet.rImp = 2*jet.R;
    jet.uJet = 0.99;
    jet.zeta = zetaOfX(jet.xc);
    Problem<Real> w(params, nx, ny, x0, x1, y0, y1);
    w.bc.type[xMin] = BCType::wall;
    w.setInclination(zetaOfX);
    const int wholeCells = w.setImpingingJet(jet);
    for (const int split : {22, 31, 13})
    {
        const int px = split/10;
        const int py = split%10;
        bool ok = true;
        int cells = 0;
        for (int r = 0; r < px*py; ++r)
        {
            const Subdomain s = splitGrid(nx, ny, px, py, r);
            const Problem<Real> q = subProblem(w, s);
            Problem<Real> p(params, s, x0, x1, y0, y1);
            for (int side = 0; side < 4; ++side)
            {
                if (!s.processorSide(side))
                {
                    p.bc.type[side] = w.bc.type[side];
                }
            }
            p.setInclination(zetaOfX);
            cells += p.setImpingingJet(jet);
            ok = ok && sameBits(p.grid, q.grid) && p.zeta == q.zeta
              && p.kappa == q.kappa && p.h == q.h && p.hu == q.hu
              && p.hv == q.hv && sameBits(p.params.jet, q.params.jet)
              && p.wholeNx == nx && p.wholeNy == ny && p.isPart()
              && sameBits(p.bc.type, q.bc.type);
        }
        t.check
        (
            ok && cells == wholeCells && wholeCells > 0,
            std::string("jet on an inclination, ") + prec + ", split "
          + std::to_string(px) + "x" + std::to_string(py) + ": every part"
            " built on its own is the part cut out (" + std::to_string(cells)
          + " jet cells in the parts, " + std::to_string(wholeCells)
          + " in the whole)"
        );
    }
}

} // namespace


int main()
{
    Counter t;
    refusals(t);
    tiling(t);
    subProblems<double>(t);
    subProblems<float>(t);
    directParts<double>(t);
    directParts<float>(t);
    return t.finish();
}

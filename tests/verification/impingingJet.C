/*---------------------------------------------------------------------------*\
  The impinging-jet source (physics/impingingJet.H) on the granular jet of
  section 5.4 (tests/common/gpuCases.H granularJet, 128 x 64 cells, 3.125 mm):

    - inside R_imp every cell holds the analytic state (37)-(38), computed
      here independently from the printed equations (relative 1e-14), at
      t = 0 and, bit for bit the same, after the flow has run to t = 0.5 s;
    - outside R_imp the flow is free: the cells next to the circle carry
      material, h >= 0 everywhere, the regime has a moving thin layer;
    - the volume grows at the jet's volume flux pi R^2 u_jet until the
      material reaches the open sides (5 %), and by no more later;
    - serial and OpenMP runs agree bit for bit;
    - bad jet input is rejected naming its keyword.
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "gpuCases.H"

#include <functional>

using namespace sh;
using namespace shtest;

namespace
{

constexpr double R = 7.5e-3;
constexpr double uJet = 0.99;

//- Eqs (37)-(38) at the centre of cell (i, j), stagnation point (0, 0)
State<double> analytic(const Problem<double>& pb, int i, int j, bool& inside)
{
    const double x = pb.grid.xc(i);
    const double y = pb.grid.yc(j);
    const double r = std::hypot(x, y);
    inside = r < 2*R;
    const double zeta = 26.7*deg;
    const double cosTheta = x/r;
    const double sinTheta = y/r;
    const double h = R*R*std::pow(std::cos(zeta), 3)
       /(2*r*std::pow(1 - std::sin(zeta)*cosTheta, 2));
    return {h, h*uJet*cosTheta, h*uJet*sinTheta};
}

//- Kept in one piece: one verification scenario read top to bottom (set-up,
//  run, table, assertions).
void analyticRegion(Counter& t)
{
    std::printf("\nThe analytic region inside R_imp = 2R\n");
    const Problem<double> pb = shcases::granularJet<double>(128);
    const int nx = pb.grid.nx, ny = pb.grid.ny;

    int nInside = 0;
    double maxRel = 0;
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            bool inside = false;
            const State<double> a = analytic(pb, i, j, inside);
            const int c = pb.cell(i, j);
            if (!inside)
            {
                continue;
            }
            ++nInside;
            maxRel = std::max
            ({
                maxRel,
                std::fabs(pb.h[c] - a.h)/a.h,
                std::fabs(pb.hu[c] - a.hu)/(a.h*uJet),
                std::fabs(pb.hv[c] - a.hv)/(a.h*uJet)
            });
        }
    }
    std::printf("  %d cells inside R_imp, max relative difference from (37)-(38): %.2e\n",
        nInside, maxRel);
    t.check(nInside > 50 && maxRel < 1e-14, "initial state inside R_imp is (37)-(38) (rel. 1e-14)");

    double vol0 = pb.volume();
    const double flux = 3.14159265358979323846*R*R*uJet;

    // Before material reaches the open sides the circle feeds the plane
    // at the jet's volume flux pi R^2 u_jet (up to the staircase of the
    // discrete circle and the half-step state at its rim)
    {
        CpuSolver<double> early(pb, true);
        std::printf("  %8s %14s %14s %8s\n", "t [s]", "gain [m^3]", "pi R^2 u t", "ratio");
        bool ok = true;
        for (const double te : {0.02, 0.05})
        {
            early.advanceTo(te);
            const double gain = early.diagnostics().volume - vol0;
            std::printf("  %8g %14.6e %14.6e %8.4f\n", te, gain, flux*te, gain/(flux*te));
            ok = ok && std::fabs(gain/(flux*te) - 1) < 0.05;
        }
        t.check(ok, "volume gained at t = 0.02, 0.05 s is pi R^2 u_jet t within 5 %");
    }

    CpuSolver<double> s(pb, false);
    CpuSolver<double> so(pb, true);
    const double tEnd = 0.5;
    s.advanceTo(tEnd);
    so.advanceTo(tEnd);
    std::vector<double> h, hu, hv, ho, huo, hvo;
    s.getState(h, hu, hv);
    so.getState(ho, huo, hvo);
    t.check(h == ho && hu == huo && hv == hvo && s.steps() == so.steps(),
        "serial and OpenMP bit-identical");

    bool same = true, ring = true;
    double hMin = 1e300;
    long moving = 0;
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            const int c = pb.cell(i, j);
            bool inside = false;
            analytic(pb, i, j, inside);
            hMin = std::min(hMin, h[c]);
            if (inside)
            {
                same = same && h[c] == pb.h[c] && hu[c] == pb.hu[c] && hv[c] == pb.hv[c];
            }
            else
            {
                const double r = std::hypot(pb.grid.xc(i), pb.grid.yc(j));
                if (r < 2*R + 2*pb.grid.dx)
                {
                    ring = ring && h[c] > 0;
                }
                moving += (hu[c] != 0 || hv[c] != 0);
            }
        }
    }
    std::printf("  t = %g s after %ld steps: min h %.3g, moving cells outside R_imp %ld\n",
        tEnd, s.steps(), hMin, moving);
    t.check(same, "inside R_imp the state at t = 0.5 s is bit for bit the imposed one");
    t.check(ring && hMin >= 0 && moving > 200, "outside: material around the circle, flowing, h >= 0");

    const double vol1 = s.diagnostics().volume;
    std::printf("  volume gained %.4e m^3 in %g s; the jet delivers pi R^2 u_jet t = %.4e\n",
        vol1 - vol0, tEnd, flux*tEnd);
    t.check(vol1 > vol0 && vol1 - vol0 <= 1.05*flux*tEnd,
        "volume grows by at most the jet's delivery (5 % for the staircase circle)");
}

void rejects
(
    Counter& t,
    const char* what,
    const std::function<void(JetInput&)>& edit,
    const std::string& keyword
)
{
    Problem<double> pb = shcases::granularJet<double>(64);
    JetInput in;
    in.R = R;
    in.rImp = 2*R;
    in.uJet = uJet;
    in.zeta = 26.7*deg;
    edit(in);
    try
    {
        pb.setImpingingJet(in);
        t.check(false, std::string(what) + " rejected");
    }
    catch (const InputError& e)
    {
        std::printf("    %s\n", e.what());
        t.check(e.keyword() == keyword, std::string(what) + " rejected, naming " + keyword);
    }
}

void badInput(Counter& t)
{
    std::printf("\nBad jet input\n");
    rejects(t, "R = 0", [](JetInput& j) { j.R = 0; }, "R");
    rejects(t, "R_imp < 0", [](JetInput& j) { j.rImp = -1; }, "R_imp");
    rejects(t, "u_jet < 0", [](JetInput& j) { j.uJet = -0.5; }, "u_jet");
    rejects(t, "centre outside the mesh", [](JetInput& j) { j.xc = 0.5; }, "centre");
    rejects(t, "centre on a cell centre",
        [](JetInput& j) { j.xc = 0.5*0.4/64; j.yc = 0.5*0.2/32; }, "centre");
    rejects(t, "R_imp holding no cell centre", [](JetInput& j) { j.rImp = 1e-4; }, "R_imp");
}

} // namespace


int main()
{
    Counter t;
    analyticRegion(t);
    badInput(t);
    return t.finish();
}

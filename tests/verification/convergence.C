/*---------------------------------------------------------------------------*\
  Observed orders of convergence

  Errors are L1 norms sum |e_i| dx against the exact cell averages (Simpson
  on the pieces between kinks: exact for h and hu, piecewise cubics), the
  observed order is log2(e(N/2)/e(N)).  Every run is one row of cells along
  x (dy = 8 dx, transmissive sides, v = 0), CPU backend, double, the
  default ModelInput but for the values named; every limiter of
  limiters.H (minmod is the default).

  1. Smooth exact solution: the spreading parabolic cap of Savage & Hutter
     (1989) on a constant slope with Coulomb friction and active Kx.  With
     beta = eps g cos(zeta) Kx_act and a = g (sin zeta - tan delta cos zeta),
        h  = H(t) (1 - xi^2),   xi = (x - xc(t))/G(t)   (|xi| <= 1, else 0)
        u  = uc(t) + (x - xc(t)) G'(t)/G(t)
        xc = xc0 + uc0 t + a t^2/2,   uc = uc0 + a t,
        H G = M = H0 G0,   G'' = 2 beta M/G^2
     solves eqs (1)-(2) in the dimensional form of docs/design.md section 2
     (zb = 0, kappa = 0): xi is constant along particle paths, so
     Dh/Dt + h du/dx = (1 - xi^2)(H' + H G'/G) = 0, and
     Du/Dt + beta dh/dx = xc'' + xi (G'' - 2 beta H/G) = a, the source
     h (g sin zeta - g cos zeta tan delta) of u > 0.  It holds while u > 0
     in the whole cap (friction points upslope everywhere: the rear speed
     uc - G' stays positive) and du/dx = G'/G > 0 (the flow extends: Kx
     active everywhere, eq. 9).  G(t) by RK4 (2e4 steps; checked against
     4e4 steps and against the invariant G'^2/2 + 2 beta M/G).
     zeta = 35, delta = 25, phi = 30 deg, g = 9.81, eps = 1; H0 = 1 m,
     G0 = 5 m, G'0 = 1 m/s, uc0 = 3 m/s, xc0 = 0; t = 1 s; x in [-6, 14].
     The margin |xi| -> 1 is a wet/dry front where h has a corner: the
     errors are measured over the core, the cells inside |xi| <= 0.7 at
     t = 1.  The characteristics leaving the edges, dxi/dt =
     -+ sqrt(beta H (1 - xi^2))/G, reach only |xi| = cos(int sqrt(beta H)/G
     dt) (printed, about 0.92) by t = 1, so the core is outside the domain
     of dependence of the fronts and the solution there is smooth: the
     scheme's order must show.  Asserted: L1 order >= 1.8 of h and of hu
     in the core on the finest pair of meshes, for every limiter (the
     default, minmod, included).  The whole line is printed.

  2. The dam break of section 5.1 (h0 = 10 m, zeta = 40, delta = 24.5 deg,
     K = 1, t = 0.5 s, x in [-12.8, 12.8]; exact solution (33), testing.H)
     a) from the Riemann data of the paper.  The solution has kinks at the
        rarefaction head and at the dry front; "smooth" are the cells
        farther than 5 % of the fan's width from both.  Every centred fan
        started from a discontinuity carries an O(dx) start-up error: the
        discrete fan at time t is the fan of mesh 1 at time t/dx, which
        approaches the similarity solution only as dx/t (a shifted virtual
        origin), and it fills the whole fan, kinks or not.  So the
        Riemann start converges at first order everywhere, for any
        second-order scheme; asserted: L1 order >= 0.8 of h over the line
        and over the smooth part on the finest pair.
     b) the same exact solution started from its exact cell averages at
        t0 = 0.1 s (the fan already 3 c0 t0 = 2.6 m wide) and run to
        t = 0.5 s: no start-up error, so the scheme's order shows where the
        solution is smooth.  Asserted: L1 order >= 1.8 of h and hu over the
        smooth part on the finest pair, every limiter.  The whole line
        (kinks included) is printed.

  With MUSCL on the conservative variables (vanLeer and MC second order)
  minmod fell short of second order, with grid-scale noise in the cells
  the maximum of hu has swept through (the momentum maximum moves through
  the material when the flow accelerates, and every limiter clips at it);
  limiting u instead of hu (physics/reconstruction.H slopesOf) gives
  second order with every limiter.  The Riemann start converges at first
  order with every limiter.  The orders measured are in docs/numerics.md.
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "exactCap.H"

#include <chrono>
#include <functional>
#include <initializer_list>

using namespace sh;
using namespace shtest;

namespace
{

// * * * * * * * * * * * * * * One-dimensional runs * * * * * * * * * * * * //

//- A line of nx cells on [xMin, xMax] and one row across, dy = 8 dx and
//  transmissive sides, so that v stays 0 and dt/dx is the same on every
//  mesh (the transverse term of eq. 24 adds c/(8 dx)).  Starts from the
//  given cell averages, advances to tEnd; returns h and hu.
struct LineRun
{
    std::vector<double> h, hu;
    long steps = 0;
};

LineRun runLine
(
    const Params<double>& p,
    int nx,
    double xMin,
    double xMax,
    double zeta,
    const std::vector<double>& h0,
    const std::vector<double>& hu0,
    double tEnd
)
{
    const double dx = (xMax - xMin)/nx;
    Problem<double> pb(p, nx, 1, xMin, xMax, 0, 8*dx);
    pb.setInclination([&](double) { return zeta; });
    pb.setState([](double, double) { return Primitive{0, 0, 0}; });
    for (int i = 0; i < nx; ++i)
    {
        pb.h[pb.cell(i, 0)] = h0[i];
        pb.hu[pb.cell(i, 0)] = hu0[i];
    }
    CpuSolver<double> s(pb, false);
    s.advanceTo(tEnd);
    LineRun r;
    std::vector<double> hv;
    s.getState(r.h, r.hu, hv);
    r.steps = s.steps();
    return r;
}

//- L1 norm sum |a - b| dx over the cells where mask is set
double l1(const std::vector<double>& a, const std::vector<double>& b,
          const std::vector<char>& mask, double dx)
{
    double s = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
    {
        if (mask[k]) { s += std::fabs(a[k] - b[k]); }
    }
    return s*dx;
}

double linf(const std::vector<double>& a, const std::vector<double>& b,
            const std::vector<char>& mask)
{
    double s = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
    {
        if (mask[k]) { s = std::max(s, std::fabs(a[k] - b[k])); }
    }
    return s;
}

//- Orders of one error column: e[k] on mesh k, "-" on the first
struct Column
{
    std::vector<double> e;
    double lastOrder() const { return shtest::order(e[e.size() - 2], e.back()); }
    std::string order() const
    {
        return e.size() < 2 ? "-" : fmt("%.3f", lastOrder());
    }
};


// * * * * * * * * * * * * * * * The cap tables  * * * * * * * * * * * * * //

const char* limiterLabel(Limiter l)
{
    return l == ModelInput().limiter ? " (default)" : "";
}

//- Kept in one piece: the tables of the cap, printed and asserted in the
//  order they appear.
void capTables(Counter& test)
{
    const double g = 9.81, zeta = 35*deg, tEnd = 1, xMin = -6, xMax = 14;
    const double xiCore = 0.7;
    const double minOrder = 1.8;
    const int meshes[] = {50, 100, 200, 400, 800, 1600};

    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::activePassive;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 25;
    const double Kx = makeParams<double>(in).K.kx[0];

    ParabolicCap cap;
    cap.a = g*(std::sin(zeta) - std::tan(in.coulomb.deltaDeg*deg)*std::cos(zeta));
    cap.beta = in.epsilon*g*std::cos(zeta)*Kx;
    cap.xc0 = 0;
    cap.uc0 = 3;
    cap.G0 = 5;
    cap.Gdot0 = 1;
    cap.H0 = 1;

    double minRear = 0, theta = 0;
    const CapState e0 = cap.at(0, 1);
    const CapState e = cap.at(tEnd, 20000, &minRear, &theta);
    const CapState e2 = cap.at(tEnd, 40000);
    const double xiReach = std::cos(theta);

    std::printf("\n1. Spreading parabolic cap, Coulomb friction, active Kx "
                "(Savage & Hutter 1989)\n");
    std::printf("   g = %g, eps = %g, zeta = %g deg, delta = %g deg, phi = %g deg: "
                "Kx_act = %.6f, beta = %.6f, a = %.6f m/s^2\n",
        g, in.epsilon, zeta/deg, in.coulomb.deltaDeg, in.phiDeg, Kx, cap.beta, cap.a);
    std::printf("   t = 0: xc = %g, uc = %g, G = %g, G' = %g, H = %g\n",
        e0.xc, e0.uc, e0.G, e0.Gdot, e0.H);
    std::printf("   t = %g: xc = %.6f, uc = %.6f, G = %.9f, G' = %.9f, H = %.9f\n",
        tEnd, e.xc, e.uc, e.G, e.Gdot, e.H);
    std::printf("   core: cells inside |xi| <= %g at t = %g (x in [%.4f, %.4f]); "
                "the edges' characteristics reach |xi| = %.4f\n",
        xiCore, tEnd, e.xc - xiCore*e.G, e.xc + xiCore*e.G, xiReach);

    test.check(std::fabs(e.G - e2.G) < 1e-12*e.G && std::fabs(e.Gdot - e2.Gdot) < 1e-12,
        fmt("exact G(t): RK4 with 2e4 and 4e4 steps agree (|dG| = %.1e, |dG'| = %.1e)",
            std::fabs(e.G - e2.G), std::fabs(e.Gdot - e2.Gdot)));
    test.check(std::fabs(cap.energy(e) - cap.energy(e0)) < 1e-12*cap.energy(e0),
        fmt("exact G(t): G'^2/2 + 2 beta M/G conserved (drift %.1e)",
            std::fabs(cap.energy(e) - cap.energy(e0))));
    test.check(minRear > 0 && e0.Gdot > 0,
        fmt("u > 0 and du/dx = G'/G > 0 in the whole cap at all t (min rear speed "
            "%.3f m/s): Coulomb friction and Kx_act hold everywhere", minRear));
    test.check(e0.xc - e0.G > xMin + 0.5 && e.xc + e.G < xMax - 0.5,
        "the cap stays 0.5 m or more inside the domain");
    test.check(xiCore < xiReach,
        fmt("core |xi| <= 0.7 outside the edges' domain of influence (|xi| >= %.3f)", xiReach));

    for (const std::string& limName : limiterNames())
    {
        in.limiter = parseLimiter(limName);
        const Params<double> p = makeParams<double>(in);
        std::printf("\n   limiter %s%s\n", limName.c_str(), limiterLabel(in.limiter));
        std::printf("   %5s %8s | %10s %6s %10s %6s %10s %6s | %10s %6s %10s %6s | %5s\n",
            "N", "dx", "L1 h core", "order", "L1 hu core", "order", "Linf h cor",
            "order", "L1 h all", "order", "L1 hu all", "order", "steps");
        Column ch, chu, chi, cha, chua;
        for (const int n : meshes)
        {
            const double dx = (xMax - xMin)/n;
            std::vector<double> h0(n), hu0(n), hE(n), huE(n);
            std::vector<char> core(n), all(n, 1);
            for (int i = 0; i < n; ++i)
            {
                const double xl = xMin + i*dx, xr = xl + dx;
                const auto b0 = {e0.xc - e0.G, e0.xc + e0.G};
                const auto b = {e.xc - e.G, e.xc + e.G};
                h0[i] = cellMean([&](double x) { return cap.h(e0, x); }, xl, xr, b0);
                hu0[i] = cellMean([&](double x) { return cap.hu(e0, x); }, xl, xr, b0);
                hE[i] = cellMean([&](double x) { return cap.h(e, x); }, xl, xr, b);
                huE[i] = cellMean([&](double x) { return cap.hu(e, x); }, xl, xr, b);
                core[i] = std::fabs(xl - e.xc) <= xiCore*e.G
                       && std::fabs(xr - e.xc) <= xiCore*e.G;
            }
            const LineRun r = runLine(p, n, xMin, xMax, zeta, h0, hu0, tEnd);
            ch.e.push_back(l1(r.h, hE, core, dx));
            chu.e.push_back(l1(r.hu, huE, core, dx));
            chi.e.push_back(linf(r.h, hE, core));
            cha.e.push_back(l1(r.h, hE, all, dx));
            chua.e.push_back(l1(r.hu, huE, all, dx));
            std::printf("   %5d %8.5f | %10.3e %6s %10.3e %6s %10.3e %6s | %10.3e %6s %10.3e %6s | %5ld\n",
                n, dx, ch.e.back(), ch.order().c_str(), chu.e.back(), chu.order().c_str(),
                chi.e.back(), chi.order().c_str(), cha.e.back(), cha.order().c_str(),
                chua.e.back(), chua.order().c_str(), r.steps);
        }
        test.check(ch.lastOrder() >= minOrder && chu.lastOrder() >= minOrder,
            limName + fmt(": L1 order in the core on N = 800/1600 >= 1.8 (h %.3f, hu %.3f)",
                ch.lastOrder(), chu.lastOrder()));
    }
}


// * * * * * * * * * * * * * * The dam break tables * * * * * * * * * * * * //

//- Section 5.1 from t0 (0: the Riemann data) to 0.5 s.  minOrder: the
//  order asserted on the finest pair, of h over the line and the smooth
//  part (t0 = 0) or of h and hu over the smooth part (t0 > 0)
//  Kept in one piece: the tables of the dam break, printed and asserted in
//  the order they appear.
void damBreakTables(Counter& test, double t0, double minOrder)
{
    const double h0 = 10, zeta = 40*deg, delta = 24.5*deg, g = 9.81, tEnd = 0.5;
    const double xMin = -12.8, xMax = 12.8;
    const int meshes[] = {64, 128, 256, 512, 1024, 2048};

    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 40;
    in.coulomb.deltaDeg = 24.5;

    // The exact solution (testing.H), its fan's edges and momentum
    const GranularDamBreak db{h0, g, zeta, delta};
    const auto xHead = [&](double t) { return db.xHead(t); };
    const auto xFront = [&](double t) { return db.xFront(t); };
    const double band = 0.05*(xFront(tEnd) - xHead(tEnd));
    const auto hExact = [&](double x, double t) { return db.h(x, t); };
    const auto huExact = [&](double x, double t) { return db.hu(x, t); };

    std::printf("\n2%s. Dam break on the incline (section 5.1) %s: h0 = %g m, "
                "zeta = %g deg, delta = %g deg, K = 1, t = %g s\n",
        t0 > 0 ? "b" : "a",
        t0 > 0 ? fmt("from the exact solution at t0 = %g s", t0).c_str()
               : "from the Riemann data",
        h0, zeta/deg, delta/deg, tEnd);
    std::printf("   kinks at t: rarefaction head x = %.4f, dry front x = %.4f; "
                "smooth: cells farther than %.4f m (5%% of the fan) from both\n",
        xHead(tEnd), xFront(tEnd), band);

    for (const std::string& limName : limiterNames())
    {
        in.limiter = parseLimiter(limName);
        const Params<double> p = makeParams<double>(in);
        std::printf("\n   limiter %s%s\n", limName.c_str(), limiterLabel(in.limiter));
        std::printf("   %5s %8s | %10s %6s %10s %6s | %10s %6s %10s %6s | %5s\n",
            "N", "dx", "L1 h all", "order", "L1 hu all", "order",
            "L1 h smth", "order", "L1 hu smth", "order", "steps");
        Column ha, hua, hs, hus;
        for (const int n : meshes)
        {
            const double dx = (xMax - xMin)/n;
            std::vector<double> hI(n), huI(n, 0), hE(n), huE(n);
            std::vector<char> smooth(n), all(n, 1);
            for (int i = 0; i < n; ++i)
            {
                const double xl = xMin + i*dx, xr = xl + dx;
                if (t0 > 0)
                {
                    const auto b0 = {xHead(t0), xFront(t0)};
                    hI[i] = cellMean([&](double x) { return hExact(x, t0); }, xl, xr, b0);
                    huI[i] = cellMean([&](double x) { return huExact(x, t0); }, xl, xr, b0);
                }
                else
                {
                    hI[i] = xl + 0.5*dx < 0 ? h0 : 0;
                }
                const auto b = {xHead(tEnd), xFront(tEnd)};
                hE[i] = cellMean([&](double x) { return hExact(x, tEnd); }, xl, xr, b);
                huE[i] = cellMean([&](double x) { return huExact(x, tEnd); }, xl, xr, b);
                smooth[i] = (xr < xHead(tEnd) - band || xl > xHead(tEnd) + band)
                         && (xr < xFront(tEnd) - band || xl > xFront(tEnd) + band);
            }
            // The equations are autonomous: tEnd - t0 from the state at t0
            const LineRun r = runLine(p, n, xMin, xMax, zeta, hI, huI, tEnd - t0);
            ha.e.push_back(l1(r.h, hE, all, dx));
            hua.e.push_back(l1(r.hu, huE, all, dx));
            hs.e.push_back(l1(r.h, hE, smooth, dx));
            hus.e.push_back(l1(r.hu, huE, smooth, dx));
            std::printf("   %5d %8.5f | %10.3e %6s %10.3e %6s | %10.3e %6s %10.3e %6s | %5ld\n",
                n, dx, ha.e.back(), ha.order().c_str(), hua.e.back(), hua.order().c_str(),
                hs.e.back(), hs.order().c_str(), hus.e.back(), hus.order().c_str(), r.steps);
        }
        if (t0 > 0)
        {
            test.check(hs.lastOrder() >= minOrder && hus.lastOrder() >= minOrder,
                limName + fmt(": L1 order over the smooth part on N = 1024/2048 >= 1.8 "
                    "(h %.3f, hu %.3f)", hs.lastOrder(), hus.lastOrder()));
        }
        else
        {
            test.check(ha.lastOrder() >= minOrder && hs.lastOrder() >= minOrder,
                limName + fmt(": L1 order of h on N = 1024/2048 >= 0.8 (first order: "
                    "the fan's start-up error), line %.3f, smooth part %.3f",
                    ha.lastOrder(), hs.lastOrder()));
        }
    }
}

} // namespace


int main()
{
    Counter test;
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    const auto seconds = [&]
    {
        return std::chrono::duration<double>(clock::now() - start).count();
    };

    std::printf("Observed orders of convergence: L1 = sum |e| dx against the exact "
                "cell averages, order = log2(e(N/2)/e(N))\n");
    capTables(test);
    const double tCap = seconds();
    damBreakTables(test, 0, 0.8);
    damBreakTables(test, 0.1, 1.8);
    std::printf("\nwall time %.1f s (cap %.1f s, dam break %.1f s)\n",
        seconds(), tCap, seconds() - tCap);
    return test.finish();
}

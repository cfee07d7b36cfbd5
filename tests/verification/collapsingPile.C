/*---------------------------------------------------------------------------*\
  Collapsing pile (Zhai et al. 2014, section 5.2, second case, Fig. 9)

    The pile of staticPile with delta = phi = 20 deg: its free surface
    (26.6 deg) is steeper than the friction angles, so it must slump, then
    come to rest in the bowl: "the distribution after t = 4 s will remain
    unchanged as the flow has reached static balance".  Active/passive
    earth pressure, as in the paper (Kx act = pass = 1.265 for delta = phi,
    Ky 0.745 / 1.520, K = 1 at rest).  Walls on all sides, so the volume
    must be conserved to round-off; data symmetric to the last bit (cell
    centres computed symmetrically), so the result must be too.

    Checks on 64^2 and 128^2 (SH_TEST_FULL=1 adds 256^2; the staticPile
    tutorial runs 256^2 through the application, shortened to 64^2 in
    ./Alltest): the pile slumps; by
    t = 4 s every momentum is exactly zero, and stays so; volume to
    round-off; x- and y-mirror symmetry bit for bit at every printed time.
\*---------------------------------------------------------------------------*/

#include "testing.H"

#include <cstdlib>

using namespace sh;
using namespace shtest;

namespace
{

//- Kept in one piece: one verification scenario read top to bottom (set-up,
//  run, table, assertions).
void run(Counter& test, int n)
{
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::activePassive;
    in.phiDeg = 20;
    in.coulomb.deltaDeg = 20;
    const Params<double> p = makeParams<double>(in);
    Problem<double> pb(p, n, n, -0.3, 0.3, -0.3, 0.3);
    for (int s = 0; s < 4; ++s)
    {
        pb.bc.type[s] = BCType::wall;
    }
    // Mirror-symmetric centres: x(i) = -x(n-1-i) exactly
    const double d = 0.6/n;
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            const double x = (i + 0.5 - 0.5*n)*d, y = (j + 0.5 - 0.5*n)*d;
            const double r = std::sqrt(x*x + y*y);
            pb.zb[pb.cell(i, j)] = 0.5*r;
            pb.h[pb.cell(i, j)] = std::max(0.0, 0.2 - r);
        }
    }
    const double v0 = pb.volume();
    CpuSolver<double> s(pb, true);
    std::vector<double> h, hu, hv;

    std::printf("\nCollapsing pile, delta = phi = 20 deg, active/passive K, %dx%d, walls\n\n", n, n);
    std::printf("%6s %8s %12s %8s %12s %14s %10s\n",
        "t", "steps", "max|v|", "moving", "max h", "volume error", "asymmetric");
    double peakSpeed = 0;
    double restTime = -1;
    double maxVolErr = 0;
    long asymmetric = 0;
    const double times[] = {0.1, 0.2, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4};
    for (const double t : times)
    {
        s.advanceTo(t);
        s.getState(h, hu, hv);
        double vmax = 0, hmax = 0, vol = 0;
        long moving = 0, asym = 0;
        for (int j = 0; j < n; ++j)
        {
            for (int i = 0; i < n; ++i)
            {
                const int c = i + n*j;
                const int mx = (n - 1 - i) + n*j, my = i + n*(n - 1 - j);
                asym += h[c] != h[mx] || hu[c] != -hu[mx] || hv[c] != hv[mx]
                     || h[c] != h[my] || hu[c] != hu[my] || hv[c] != -hv[my];
                vol += h[c];
                hmax = std::max(hmax, h[c]);
                if (h[c] > 0)
                {
                    vmax = std::max(vmax, std::hypot(hu[c], hv[c])/h[c]);
                    moving += hu[c] != 0 || hv[c] != 0;
                }
            }
        }
        asymmetric += asym;
        vol *= pb.grid.dx*pb.grid.dy;
        const double volErr = std::fabs(vol - v0)/v0;
        maxVolErr = std::max(maxVolErr, volErr);
        peakSpeed = std::max(peakSpeed, vmax);
        if (vmax == 0 && restTime < 0)
        {
            restTime = t;
        }
        if (vmax != 0)
        {
            restTime = -1;
        }
        std::printf("%6.2f %8ld %12.4g %8ld %12.6f %14.3e %10ld\n",
            t, s.steps(), vmax, moving, hmax, volErr, asym);
    }
    std::printf("  thin cells whose speed was bounded: %lld\n", s.diagnostics().speedClips);
    const double fn = n;
    test.check(peakSpeed > 0.1, fmt("%.0f^2: the pile slumps (peak speed %.3g m/s)", fn, peakSpeed));
    test.check(restTime > 0 && restTime <= 4,
        fmt("%.0f^2: at rest, every momentum exactly zero, from t = %.2g s on", fn, restTime));
    test.check(maxVolErr < 1e-13,
        fmt("%.0f^2: volume conserved to round-off (max relative error %.2e)", fn, maxVolErr));
    test.check(asymmetric == 0, fmt("%.0f^2: x- and y-mirror symmetric bit for bit", fn));
}

} // namespace


int main()
{
    Counter test;
    run(test, 64);
    run(test, 128);
    if (std::getenv("SH_TEST_FULL"))
    {
        run(test, 256);
    }
    return test.finish();
}

/*---------------------------------------------------------------------------*\
  Collapsing pile (Zhai et al. 2014, section 5.2, second case, Fig. 9)

    The pile of staticPile with delta = phi = 20 deg: its free surface
    (26.6 deg) is steeper than the friction angles, so it must slump, then
    come to rest in the bowl: by t = 4 s every momentum is exactly zero.
    K = 1 (isotropic), as the exact solutions of section 5 assume; with
    active/passive K thin films at the margin keep creeping (README).  Walls on
    all sides, so the volume must be conserved to round-off.  64x64 cells
    (on 128x128 a few cells near limit equilibrium creep at ~1e-4 m/s
    until t = 6 s).
\*---------------------------------------------------------------------------*/

#include "testing.H"

using namespace sh;
using namespace shtest;

int main()
{
    Counter test;
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 20;
    in.deltaDeg = 20;
    const Params<double> p = makeParams<double>(in);

    const int n = 64;
    Problem<double> pb(p, n, n, -0.3, 0.3, -0.3, 0.3);
    for (int s = 0; s < 4; ++s)
    {
        pb.bc.type[s] = BCType::wall;
    }
    pb.setTopography([](double x, double y) { return 0.5*std::hypot(x, y); });
    pb.setState([](double x, double y)
    {
        return Primitive{std::max(0.0, 0.2 - std::hypot(x, y)), 0, 0};
    });
    const double v0 = pb.volume();

    CpuSolver<double> s(pb, true);
    std::vector<double> h, hu, hv;

    std::printf("Collapsing pile, delta = phi = 20 deg, %dx%d, walls\n\n", n, n);
    std::printf("%6s %8s %12s %8s %12s %14s\n", "t", "steps", "max|v|", "moving", "max h", "volume error");
    double peakSpeed = 0;
    double restTime = -1;
    double maxVolErr = 0;
    const double times[] = {0.1, 0.2, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4};
    for (const double t : times)
    {
        s.advanceTo(t);
        s.getState(h, hu, hv);
        double vmax = 0, hmax = 0, vol = 0;
        long moving = 0;
        for (std::size_t c = 0; c < h.size(); ++c)
        {
            vol += h[c];
            hmax = std::max(hmax, h[c]);
            if (h[c] > 0)
            {
                vmax = std::max(vmax, std::hypot(hu[c], hv[c])/h[c]);
                moving += hu[c] != 0 || hv[c] != 0;
            }
        }
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
        std::printf("%6.2f %8ld %12.4g %8ld %12.6f %14.3e\n", t, s.steps(), vmax, moving, hmax, volErr);
    }
    std::printf("\n");
    test.check(peakSpeed > 0.1, fmt("the pile slumps (peak speed %.3g m/s)", peakSpeed));
    test.check(restTime > 0 && restTime <= 4, fmt("at rest, every momentum exactly zero, from t = %.2g s on", restTime));
    test.check(maxVolErr < 1e-13, fmt("volume conserved to round-off (max relative error %.2e)", maxVolErr));
    return test.finish();
}

/*---------------------------------------------------------------------------*\
  Frictionless dam break on a flat bed against Ritter's solution

    zeta = 0, delta = 0, K = 1, g = 9.81, h0 = 1 m behind a dam at 0, dry
    bed ahead, t = 0.1 s (front at 2 c0 t = 0.63 m), on [-1, 1] along x
    and, transposed, along y.  Errors of h over the cells of one row
    (column) at the cell centres:  RMS = sqrt(sum e^2/N),
    integral = sqrt(sum e^2 dx), Linf = max |e|.
    Checks: first-order convergence or better in L2 and convergence in
    Linf, a small error on the finest mesh, and identical results along x
    and y.
\*---------------------------------------------------------------------------*/

#include "testing.H"

using namespace sh;
using namespace shtest;

namespace
{

std::vector<double> runAlong(bool alongX, int n, const Params<double>& p, double tEnd)
{
    const double d = 2.0/n;
    const int m = 4;
    Problem<double> pb
    (
        p,
        alongX ? n : m,
        alongX ? m : n,
        alongX ? -1 : 0, alongX ? 1 : m*d,
        alongX ? 0 : -1, alongX ? m*d : 1
    );
    pb.setState([&](double x, double y)
    {
        return Primitive{(alongX ? x : y) < 0 ? 1.0 : 0.0, 0, 0};
    });
    CpuSolver<double> s(pb, true);
    s.advanceTo(tEnd);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    std::vector<double> line(n);
    for (int k = 0; k < n; ++k)
    {
        line[k] = alongX ? h[pb.cell(k, m/2)] : h[pb.cell(m/2, k)];
    }
    return line;
}

} // namespace


int main()
{
    Counter test;
    const double tEnd = 0.1, g = 9.81, c0 = std::sqrt(g);
    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 30;
    in.deltaDeg = 0;
    const Params<double> p = makeParams<double>(in);

    std::printf("Ritter dam break, h0 = 1 m, t = %.1f s, errors of h\n", tEnd);
    std::printf("norms over the N cells of the line: RMS = sqrt(sum e^2/N), "
                "integral = sqrt(sum e^2 dx)\n\n");
    std::printf("%6s %11s %7s %11s %11s %7s %12s\n",
        "N", "L2 (RMS)", "order", "L2 (int)", "Linf", "order", "|x - y run|");

    Norms prev;
    bool converges = true;
    for (const int n : {100, 200, 400, 800})
    {
        const std::vector<double> hx = runAlong(true, n, p, tEnd);
        const std::vector<double> hy = runAlong(false, n, p, tEnd);
        std::vector<double> ex(n);
        double xy = 0;
        for (int k = 0; k < n; ++k)
        {
            ex[k] = ritterDepth(-1 + (k + 0.5)*2.0/n, tEnd, 1.0, c0);
            xy = std::max(xy, std::fabs(hx[k] - hy[k]));
        }
        const Norms e = errorNorms(hx, ex, 2.0/n);
        if (n == 100)
        {
            std::printf("%6d %11.4e %7s %11.4e %11.4e %7s %12.2e\n",
                n, e.rms, "-", e.integral, e.linf, "-", xy);
        }
        else
        {
            const double o2 = order(prev.rms, e.rms), oi = order(prev.linf, e.linf);
            std::printf("%6d %11.4e %7.3f %11.4e %11.4e %7.3f %12.2e\n",
                n, e.rms, o2, e.integral, e.linf, oi, xy);
            converges = converges && o2 >= 0.8 && e.linf < prev.linf;
        }
        test.check(xy <= 1e-12, fmt("N = %.0f: x and y runs agree (max diff %.1e)", n, xy));
        prev = e;
    }
    test.check(converges, "L2 error converges at order >= 0.8, Linf decreases");
    test.check(prev.rms < 2e-3, fmt("RMS error on N = 800 below 2e-3 h0 (%.2e)", prev.rms));
    return test.finish();
}

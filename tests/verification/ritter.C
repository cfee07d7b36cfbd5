/*---------------------------------------------------------------------------*\
  Frictionless dam break on a flat bed against Ritter's solution

    zeta = 0, delta = 0, g = 9.81, h0 = 1 m behind a dam at 0, dry bed
    ahead, t = 0.1 s, on [-1, 1] along x and, transposed, along y (with
    transverse cells 1.5 times longer).  K = 1, and active/passive K, for
    which the whole rarefaction extends and Ritter's solution holds with
    c0 = sqrt(g Kx_act h0).  Errors of h over the cells of one row
    (column) at the cell centres:  RMS = sqrt(sum e^2/N),
    integral = sqrt(sum e^2 dx), Linf = max |e|.
    Checks: first-order convergence or better in L2 and convergence in
    Linf, a small error on the finest mesh, the position of the front, and
    identical results along x and y.
\*---------------------------------------------------------------------------*/

#include "testing.H"

using namespace sh;
using namespace shtest;

namespace
{

std::vector<double> runAlong(bool alongX, int n, const Params<double>& p, double tEnd)
{
    // Transverse cells 1.5 times longer, so that dx != dy
    const double d = 2.0/n, dT = 1.5*d;
    const int m = 4;
    Problem<double> pb
    (
        p,
        alongX ? n : m,
        alongX ? m : n,
        alongX ? -1 : 0, alongX ? 1 : m*dT,
        alongX ? 0 : -1, alongX ? m*dT : 1
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


//- Where h falls through level along the line (linear interpolation)
double frontPosition(const std::vector<double>& h, double level)
{
    const int n = h.size();
    for (int k = n - 1; k > 0; --k)
    {
        if (h[k - 1] >= level)
        {
            const double x0 = -1 + (k - 0.5)*2.0/n;
            return x0 + (h[k - 1] - level)/(h[k - 1] - h[k])*2.0/n;
        }
    }
    return -1;
}

//- One table: K = 1 or active/passive (the rarefaction extends, so Kx act
//  everywhere and c0 = sqrt(g Kx_act h0)).  With active/passive K the x
//  and y runs legitimately differ where the numerical front compresses:
//  Kx pass = 3.69 but Ky pass = 1 for delta = 0 (eq. 8).
void table(Counter& test, bool activePassive)
{
    const double tEnd = 0.1, g = 9.81;
    ModelInput in;
    in.g = g;
    in.earthPressure = activePassive
        ? EarthPressureModel::activePassive : EarthPressureModel::isotropic;
    in.phiDeg = 35;
    in.coulomb.deltaDeg = 0;
    // Frictionless: no static resistance, and so no K = 1 for material at
    // rest (earthPressure.H); the reservoir at rest is active like the fan
    in.staticResistance = false;
    in.stoppingCriterion = false;
    const Params<double> p = makeParams<double>(in);
    const double K = p.K.kx[0];
    const double c0 = std::sqrt(g*K);
    // Ritter's depth is 0.05 h0 where 2 - x/(c0 t) = sqrt(0.45)
    const double level = 0.05;
    const double xFront = (2 - std::sqrt(9*level))*c0*tEnd;

    std::printf("\n%s: Kx = %.6f, c0 = %.4f m/s, t = %.1f s, exact front "
                "(h = 0.05 h0) at x = %.4f m\n",
        activePassive ? "Active/passive K (Rankine, delta = 0)" : "K = 1",
        K, c0, tEnd, xFront);
    std::printf("%6s %11s %7s %11s %11s %7s %12s %10s\n",
        "N", "L2 (RMS)", "order", "L2 (int)", "Linf", "order", "|x - y run|",
        "front err");

    Norms prev;
    bool converges = true;
    double frontErr = 0;
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
        frontErr = frontPosition(hx, level) - xFront;
        if (n == 100)
        {
            std::printf("%6d %11.4e %7s %11.4e %11.4e %7s %12.2e %10.4f\n",
                n, e.rms, "-", e.integral, e.linf, "-", xy, frontErr);
        }
        else
        {
            const double o2 = order(prev.rms, e.rms), oi = order(prev.linf, e.linf);
            std::printf("%6d %11.4e %7.3f %11.4e %11.4e %7.3f %12.2e %10.4f\n",
                n, e.rms, o2, e.integral, e.linf, oi, xy, frontErr);
            // The order from N = 200 on: 100 -> 200 is short of the
            // asymptotic range (printed, not checked)
            converges = converges && (n < 400 || o2 >= 0.8) && e.linf < prev.linf;
        }
        if (!activePassive)
        {
            test.check(xy <= 1e-12, fmt("N = %.0f: x and y runs agree (max diff %.1e)", n, xy));
        }
        prev = e;
    }
    test.check(converges, "L2 error converges at order >= 0.8 from N = 200 on, Linf decreases");
    test.check(prev.rms < 2e-3, fmt("RMS error on N = 800 below 2e-3 h0 (%.2e)", prev.rms));
    test.check(std::fabs(frontErr) < 0.02*c0*tEnd,
        fmt("front (h = 0.05 h0) within 2%% of c0 t of Ritter's on N = 800 (%.4f m)", frontErr));
}

} // namespace


int main()
{
    Counter test;
    std::printf("Ritter dam break, h0 = 1 m, zeta = delta = 0: errors of h\n");
    std::printf("norms over the N cells of the line: RMS = sqrt(sum e^2/N), "
                "integral = sqrt(sum e^2 dx); transverse cells 1.5 dx\n");
    table(test, false);
    table(test, true);
    return test.finish();
}

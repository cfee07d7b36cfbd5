/*---------------------------------------------------------------------------*\
  Dam break on an incline (Zhai et al. 2014, section 5.1, Table II)

    h0 = 10 m, zeta = 40 deg, delta = 24.5 deg, K = 1 (isotropic, as the
    exact solution assumes), g = 9.81, t = 0.5 s, domain
    [-12.8, 12.8] x [-1.6, 1.6], transmissive sides.  Errors of h along
    y = 0 (the row just above the axis; all rows are equal for this 1D
    problem) against the exact solution (33) at the cell centres.  The
    paper's L2 norm is the RMS over the cells of the row: with it our
    errors sit within a few per cent of Table II, while the integral norm
    is sqrt(25.6) = 5.06 times larger.
\*---------------------------------------------------------------------------*/

#include "testing.H"

using namespace sh;
using namespace shtest;

int main()
{
    Counter test;
    const double h0 = 10, zeta = 40*deg, delta = 24.5*deg, g = 9.81, tEnd = 0.5;

    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 40;
    in.coulomb.deltaDeg = 24.5;
    const Params<double> p = makeParams<double>(in);

    // Table II of the paper: L2, Linf
    const int nxs[] = {64, 128, 256, 512};
    const double paperL2[] = {0.130163, 0.073894, 0.0409712, 0.0223083};
    const double paperLinf[] = {0.452701, 0.345509, 0.252918, 0.177114};

    std::printf("Dam break on the incline, t = %.2f s: errors of h along y = 0\n", tEnd);
    std::printf("norms over the nx cells of the row: RMS = sqrt(sum e^2/nx), "
                "integral = sqrt(sum e^2 dx)\n\n");
    std::printf("%-9s %11s %7s %11s %7s %11s %7s | %11s %11s\n",
        "grid", "L2 (RMS)", "order", "L2 (int)", "order", "Linf", "order",
        "paper L2", "paper Linf");

    Norms prev;
    for (int k = 0; k < 4; ++k)
    {
        const int nx = nxs[k], ny = nx/8;
        Problem<double> pb(p, nx, ny, -12.8, 12.8, -1.6, 1.6);
        pb.setInclination([&](double) { return zeta; });
        pb.setState([&](double x, double) { return Primitive{x < 0 ? h0 : 0, 0, 0}; });

        CpuSolver<double> s(pb, true);
        s.advanceTo(tEnd);
        std::vector<double> h, hu, hv;
        s.getState(h, hu, hv);

        const int j = ny/2;
        std::vector<double> num(nx), ex(nx);
        for (int i = 0; i < nx; ++i)
        {
            num[i] = h[pb.cell(i, j)];
            ex[i] = granularDamBreakDepth(pb.grid.xc(i), tEnd, h0, g, zeta, delta);
        }
        const Norms e = errorNorms(num, ex, pb.grid.dx);
        char label[32];
        std::snprintf(label, sizeof label, "%dx%d", nx, ny);
        if (k == 0)
        {
            std::printf("%-9s %11.6g %7s %11.6g %7s %11.6g %7s | %11.6g %11.6g\n",
                label, e.rms, "-", e.integral, "-", e.linf, "-", paperL2[k], paperLinf[k]);
        }
        else
        {
            std::printf("%-9s %11.6g %7.4f %11.6g %7.4f %11.6g %7.4f | %11.6g %11.6g\n",
                label, e.rms, order(prev.rms, e.rms), e.integral,
                order(prev.integral, e.integral), e.linf, order(prev.linf, e.linf),
                paperL2[k], paperLinf[k]);
        }
        prev = e;
        test.check(e.rms <= paperL2[k] && e.linf <= paperLinf[k],
            std::string(label) + ": L2 (RMS) and Linf no worse than Table II");
    }
    return test.finish();
}

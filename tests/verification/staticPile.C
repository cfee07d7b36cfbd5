/*---------------------------------------------------------------------------*\
  Static pile in a conical bowl (Zhai et al. 2014, section 5.2, Table III)

    zb = r/2, H = zb + h = 0.2 - zb, so h = max(0, 0.2 - r); domain
    [-0.3, 0.3]^2, g = 9.81, flat reference surface (zeta = 0).

    delta = phi = 40 deg: the free surface slope (26.6 deg) is below the
    friction angles, so the pile must stay at rest.  Active/passive earth
    pressure, which takes K = 1 for material at rest, the paper's choice
    (section 3.2); a moving cell would take Kx = 2.41.

    Two variants are run: the default scheme, in which two cells at rest
    exchange only their hydrostatic pressure (holdResting,
    physics/scheme.H), and the paper's scheme without it, where the HLLC
    numerical viscosity makes the resting pile creep (less since the bed
    is well-balanced).  Both must do no worse than Table III; the default
    must keep every momentum exactly zero.  Errors of h at t = 1 s against the initial state, over
    all cells: RMS = sqrt(sum e^2/N), integral = sqrt(sum e^2 dx dy).
    Velocities must stay exactly zero.

    SH_TEST_FULL=1 adds the 512x512 mesh of Table III.
\*---------------------------------------------------------------------------*/

#include "testing.H"

#include <cstdlib>

using namespace sh;
using namespace shtest;

namespace
{

const double paperL2[] = {0.00348176, 0.00160774, 0.000719244, 0.00032317};
const double paperLinf[] = {0.0337154, 0.0225977, 0.0148297, 0.00963436};

//- Run the meshes, print the table and check it
void run(int nMesh, bool holdResting, Counter& test)
{
    const double tEnd = 1.0;
    ModelInput in;
    in.g = 9.81;
    in.phiDeg = 40;
    in.coulomb.deltaDeg = 40;
    in.holdResting = holdResting;
    const Params<double> p = makeParams<double>(in);

    std::printf("\n%s, t = %.1f s\n",
        holdResting ? "Default scheme (material at rest holds its mass)"
                    : "Paper's scheme (holdResting off)",
        tEnd);
    std::printf("%-9s %11s %7s %11s %11s %7s | %11s %11s | %9s\n",
        "mesh", "L2 (RMS)", "order", "L2 (int)", "Linf", "order",
        "paper L2", "paper Linf", "max|m|");

    Norms prev;
    for (int k = 0; k < nMesh; ++k)
    {
        const int n = 64 << k;
        Problem<double> pb(p, n, n, -0.3, 0.3, -0.3, 0.3);
        pb.setTopography([](double x, double y) { return 0.5*std::hypot(x, y); });
        pb.setState([](double x, double y)
        {
            return Primitive{std::max(0.0, 0.2 - std::hypot(x, y)), 0, 0};
        });
        const std::vector<double> h0 = pb.h;

        CpuSolver<double> s(pb, true);
        s.advanceTo(tEnd);
        std::vector<double> h, hu, hv;
        s.getState(h, hu, hv);

        double mmax = 0;
        for (std::size_t c = 0; c < h.size(); ++c)
        {
            mmax = std::max(mmax, std::max(std::fabs(hu[c]), std::fabs(hv[c])));
        }
        const Norms e = errorNorms(h, h0, pb.grid.dx*pb.grid.dy);
        char label[32];
        std::snprintf(label, sizeof label, "%dx%d", n, n);
        if (k == 0 || prev.rms == 0 || e.rms == 0)
        {
            std::printf("%-9s %11.6g %7s %11.6g %11.6g %7s | %11.6g %11.6g | %9.3g\n",
                label, e.rms, "-", e.integral, e.linf, "-",
                paperL2[k], paperLinf[k], mmax);
        }
        else
        {
            std::printf("%-9s %11.6g %7.4f %11.6g %11.6g %7.4f | %11.6g %11.6g | %9.3g\n",
                label, e.rms, order(prev.rms, e.rms), e.integral, e.linf,
                order(prev.linf, e.linf), paperL2[k], paperLinf[k], mmax);
        }
        prev = e;
        const std::string which = holdResting ? "default" : "paper's scheme";
        test.check(e.rms <= paperL2[k], which + fmt(", %.0f^2: L2 (RMS) no worse than Table III", n));
        test.check(e.linf <= paperLinf[k], which + fmt(", %.0f^2: Linf no worse than Table III", n));
        if (holdResting)
        {
            test.check(mmax == 0, fmt("default, %.0f^2: momentum exactly zero everywhere", n));
        }
    }
}

} // namespace


int main()
{
    Counter test;
    const int nMesh = std::getenv("SH_TEST_FULL") ? 4 : 3;
    std::printf("Static pile, delta = phi = 40 deg: errors of h against the "
                "initial state\n");
    std::printf("norms over all N cells: RMS = sqrt(sum e^2/N), "
                "integral = sqrt(sum e^2 dx dy)\n");
    run(nMesh, true, test);
    run(nMesh, false, test);
    return test.finish();
}

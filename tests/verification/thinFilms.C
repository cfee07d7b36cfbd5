/*---------------------------------------------------------------------------*\
  Thin films do not run away.  CPU backend, double.

  A thin layer is fed by the flow around it: it can be no faster than
  that flow and its own sliding allow.  Two ways it was not: the
  hydrostatic reconstruction held a thin moving layer behind any rise of
  its bed higher than K h while gravity went on accelerating it in its
  cell (reconstruction.H onFaceBed), and Voellmy's drag, explicit, was
  unstable in thin fast layers, where the friction cap then stopped them
  (friction.H applyBasalFriction).

  1. A chute: 2000 m x 300 m, 10 m cells, zeta = 31 deg to x = 600 m, then
     down to 5 deg by x = 900 m; a parabolic channel zb = 0.002 y^2 with
     1 cm bumps, 0.01 sin(2 pi x/35) cos(2 pi y/27) m; a cap of 3 m, radius
     40 m, released at x = 100 m; phi = 35 deg, lambda = 0, a wall upslope,
     open sides.
       a) Coulomb, delta = 19 deg, t = 150 s: every momentum exactly zero
          (the deposit at rest);
       b) Voellmy, mu = 0.2, xi = 2000 m/s^2, t = 300 s (material on the
          slopes steeper than atan(mu) drains for ever, slower and slower):
          every cell with h > 1e-4 m no faster than 1.5 times the terminal
          speed sqrt(xi h' (sin zeta - mu cos zeta)) of the thickest cell
          h' of its five-point stencil (plus 0.1 m/s).
  2. The paper's section 5.3 (the cap sliding down 35 deg onto the flat,
     delta = phi = 30 deg, g = 1), 120 x 56, t = 60: at the end no cell
     with h > 1e-4 faster than a tenth of the flow's peak speed.
  In both chute runs the CFL rate of the last step must be no larger
  than the largest a cell of the body (h >= 5 % of the peak) can have,
  (|u| + 2 sqrt(g K_max h))/dx + (|v| + 2 sqrt(g K_max h))/dy: the time
  step at the end of the deposit is not set by thin cells.
  In every case the peak speed map UMax over the cells that were wet
  (hMax > 1e-4 m) must not exceed 1.05 times its maximum over the flow's
  body (hMax at least 5 % of the peak thickness): the maps show the body,
  not films; nor the speed of a frictionless fall from rest through the
  largest drop of the domain with the release's pressure head K h0 on
  top, sqrt(2 g (dz + K h0)): no material can be faster.
\*---------------------------------------------------------------------------*/

#include "testing.H"

using namespace sh;
using namespace shtest;

namespace
{

struct Speeds
{
    double all = 0;     //!< largest UMax where hMax > 1e-4 m
    double body = 0;    //!< largest UMax where hMax >= 5 % of the peak
};

Speeds peakSpeeds(Solver<double>& s)
{
    const PeakMaps<double> pm = s.peakMaps();
    double hPeak = 0;
    for (const double h : pm.h)
    {
        hPeak = std::max(hPeak, h);
    }
    Speeds r;
    for (std::size_t c = 0; c < pm.h.size(); ++c)
    {
        if (pm.h[c] > 1e-4)
        {
            r.all = std::max(r.all, pm.speed[c]);
        }
        if (pm.h[c] >= 0.05*hPeak)
        {
            r.body = std::max(r.body, pm.speed[c]);
        }
    }
    return r;
}

//- The peak speed map against the body's and against the speed of a
//  frictionless fall through the largest drop of the domain, dz, from
//  rest with the release's head K h0 (energy: no material can be faster)
void checkMaps
(
    Counter& test,
    const std::string& name,
    const Speeds& u,
    double g,
    double dz,
    double head
)
{
    const double fall = std::sqrt(2*g*(dz + head));
    std::printf("  UMax: %.2f m/s over the cells that were wet, %.2f m/s over the body; "
                "a frictionless fall through %.1f m from rest: %.2f m/s\n",
        u.all, u.body, dz, fall);
    test.check(u.all <= 1.05*u.body,
        name + fmt(": the peak speed map is the body's (%.2f <= 1.05 x %.2f)", u.all, u.body));
    test.check(u.all <= fall,
        name + fmt(": no peak speed beyond the frictionless fall (%.2f <= %.2f)", u.all, fall));
}

//- The drop of the reference surface from x0 to x1, int sin(zeta) dx
double drop(double (*zeta)(double), double x0, double x1)
{
    const int n = 10000;
    double s = 0;
    for (int k = 0; k < n; ++k)
    {
        s += std::sin(zeta(x0 + (k + 0.5)*(x1 - x0)/n));
    }
    return s*(x1 - x0)/n;
}

double planeZeta(double x)
{
    const double z0 = 35*deg;
    return x <= 17.5 ? z0 : (x < 21.5 ? z0*(1 - (x - 17.5)/4) : 0.0);
}

double chuteZeta(double x)
{
    return (x < 600 ? 31.0 : (x < 900 ? 31.0 - 26.0*(x - 600)/300 : 5.0))*deg;
}

//- Kept in one piece: one verification scenario read top to bottom (set-up,
//  run, table, assertions).
void chute(Counter& test, bool voellmy)
{
    ModelInput in;
    in.g = 9.81;
    in.lambda = 0;
    in.phiDeg = 35;
    in.coulomb.deltaDeg = 19;
    if (voellmy)
    {
        in.frictionLaw = FrictionLaw::Voellmy;
        in.voellmy.mu = 0.2;
        in.voellmy.xi = 2000;
    }
    const int nx = 200, ny = 30;
    Problem<double> pb(makeParams<double>(in), nx, ny, 0, 2000, -150, 150);
    pb.bc.type[xMin] = BCType::wall;
    pb.setInclination(chuteZeta);
    pb.setTopography([](double x, double y)
    {
        return 0.002*y*y + 0.01*std::sin(2*pi*x/35)*std::cos(2*pi*y/27);
    });
    pb.setState([](double x, double y)
    {
        const double r2 = ((x - 100)*(x - 100) + y*y)/(40*40);
        return Primitive{r2 < 1 ? 3*(1 - r2) : 0, 0, 0};
    });
    const std::string name = voellmy
        ? "1b. chute, Voellmy mu = 0.2, xi = 2000" : "1a. chute, Coulomb delta = 19 deg";
    std::printf("\n%s\n  %6s %7s %9s %10s %12s %10s %14s\n", name.c_str(), "t", "steps",
        "dt", "max|v|", "at h", "moving", "moving volume");
    CpuSolver<double> s(pb, false);
    const double tEnd = voellmy ? 300 : 150;
    std::vector<double> h, hu, hv;
    for (double t = 30; t <= tEnd + 1e-9; t += 30)
    {
        s.advanceTo(t);
        s.getState(h, hu, hv);
        double vmax = 0, hAt = 0, movingVolume = 0;
        long moving = 0;
        for (int c = 0; c < nx*ny; ++c)
        {
            if (hu[c] != 0 || hv[c] != 0)
            {
                ++moving;
                movingVolume += h[c]*100;
            }
            if (h[c] > 1e-4)
            {
                const double v = std::hypot(hu[c], hv[c])/h[c];
                if (v > vmax) { vmax = v; hAt = h[c]; }
            }
        }
        std::printf("  %6.0f %7ld %9.4f %10.3f %12.3e %10ld %14.3f\n", t, s.steps(),
            s.lastDt(), vmax, hAt, moving, movingVolume);
    }
    if (!voellmy)
    {
        long moving = 0;
        for (int c = 0; c < nx*ny; ++c)
        {
            moving += hu[c] != 0 || hv[c] != 0;
        }
        test.check(moving == 0, name + ": at rest by t = 150 s, every momentum exactly zero");
    }
    else
    {
        // The terminal speed of the thickest cell of each stencil
        double worst = 0;
        int at = -1;
        for (int j = 0; j < ny; ++j)
        {
            for (int i = 0; i < nx; ++i)
            {
                const int c = i + nx*j;
                if (!(h[c] > 1e-4))
                {
                    continue;
                }
                double hs = h[c];
                if (i > 0) { hs = std::max(hs, h[c - 1]); }
                if (i < nx - 1) { hs = std::max(hs, h[c + 1]); }
                if (j > 0) { hs = std::max(hs, h[c - nx]); }
                if (j < ny - 1) { hs = std::max(hs, h[c + nx]); }
                const double z = chuteZeta((i + 0.5)*10);
                const double drive = std::max(0.0, std::sin(z) - 0.2*std::cos(z));
                const double terminal = std::sqrt(in.voellmy.xi*hs*drive);
                const double ratio =
                    std::hypot(hu[c], hv[c])/h[c]/(1.5*terminal + 0.1);
                if (ratio > worst) { worst = ratio; at = c; }
            }
        }
        std::printf("  the largest speed over 1.5 times the terminal speed plus 0.1 m/s: "
                    "%.3f (cell %d, %d)\n", worst, at % nx, at/nx);
        test.check(worst <= 1, name + ": no cell with h > 1e-4 m faster than 1.5 times "
            "its stencil's terminal speed (+ 0.1 m/s) at t = 300 s");
    }
    // The time step at the end is the body's: the CFL rate of eq. (24)
    // is no larger than the largest a cell of the body (h >= 5 % of the
    // peak) can have, (|u| + 2 sqrt(g K_max h))/dx + (|v| + ...)/dy
    {
        const Params<double> p = makeParams<double>(in);
        const double kMax = std::max(p.K.kxMax, p.K.kyMax);
        double hPeak = 0, bodyRate = 0;
        for (int c = 0; c < nx*ny; ++c)
        {
            hPeak = std::max(hPeak, h[c]);
        }
        for (int c = 0; c < nx*ny; ++c)
        {
            if (h[c] >= 0.05*hPeak)
            {
                const double c2 = 2*std::sqrt(in.g*kMax*h[c]);
                bodyRate = std::max(bodyRate,
                    (std::fabs(hu[c])/h[c] + c2)/10 + (std::fabs(hv[c])/h[c] + c2)/10);
            }
        }
        const double rate = s.diagnostics().maxRate;
        std::printf("  CFL rate at the end %.4g 1/s, the body's largest possible %.4g 1/s\n",
            rate, bodyRate);
        test.check(rate <= bodyRate,
            name + ": the time step at the end is the body's, not set by thin cells");
    }
    // From the release's top (x = 60 m) to the end; the bumps' and the
    // channel's relief (22.5 m at its rim) on top
    checkMaps(test, name, peakSpeeds(s), in.g, drop(chuteZeta, 60, 2000) + 22.5,
        makeParams<double>(in).K.kxMax*3);
}

void inclinedPlane(Counter& test)
{
    ModelInput in;
    in.g = 1;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 30;
    const int nx = 120, ny = 56;
    Problem<double> pb(makeParams<double>(in), nx, ny, 0, 30, -7, 7);
    pb.setInclination(planeZeta);
    pb.setState([](double x, double y)
    {
        const double r2 = (x - 4)*(x - 4) + y*y;
        return Primitive{r2 < 1.85*1.85 ? std::sqrt(1.85*1.85 - r2) : 0, 0, 0};
    });
    const std::string name = "2. section 5.3, the cap into the flat runout, 120 x 56";
    std::printf("\n%s\n", name.c_str());
    CpuSolver<double> s(pb, false);
    s.advanceTo(60);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    double vmax = 0;
    long moving = 0;
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        moving += hu[c] != 0 || hv[c] != 0;
        if (h[c] > 1e-4)
        {
            vmax = std::max(vmax, std::hypot(hu[c], hv[c])/h[c]);
        }
    }
    const Speeds u = peakSpeeds(s);
    std::printf("  t = 60 after %ld steps: %ld cells moving, the fastest with h > 1e-4 "
                "at %.4f (peak body speed %.3f)\n", s.steps(), moving, vmax, u.body);
    test.check(vmax <= 0.1*u.body,
        name + ": at t = 60 no cell with h > 1e-4 faster than a tenth of the flow's peak speed");
    checkMaps(test, name, u, in.g, drop(planeZeta, 4 - 1.85, 30),
        makeParams<double>(in).K.kxMax*1.85);
}

} // namespace


int main()
{
    Counter test;
    std::printf("Thin films: no cell faster than the flow that feeds it\n");
    chute(test, false);
    chute(test, true);
    inclinedPlane(test);
    return test.finish();
}

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
#include "thinFilmCases.H"

using namespace sh;
using namespace shtest;

namespace
{

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
    const double fall = frictionlessFall(g, dz, head);
    std::printf("  UMax: %.2f m/s over the cells that were wet, %.2f m/s over the body; "
                "a frictionless fall through %.1f m from rest: %.2f m/s\n",
        u.all, u.body, dz, fall);
    test.check(u.all <= 1.05*u.body,
        name + fmt(": the peak speed map is the body's (%.2f <= 1.05 x %.2f)", u.all, u.body));
    test.check(u.all <= fall,
        name + fmt(": no peak speed beyond the frictionless fall (%.2f <= %.2f)", u.all, fall));
}

//- One verification scenario read top to bottom (run, table, assertions);
//  its set-up and measures in thinFilmCases.H
void chute(Counter& test, bool voellmy)
{
    const ModelInput in = chuteInput(voellmy);
    const int nx = chuteNx, ny = chuteNy;
    const Problem<double> pb = chuteProblem(in);
    const std::string name = voellmy
        ? "1b. chute, Voellmy mu = 0.2, xi = 2000" : "1a. chute, Coulomb delta = 19 deg";
    std::printf("\n%s\n  %6s %7s %9s %10s %12s %10s %14s\n", name.c_str(), "t", "steps",
        "dt", "max|v|", "at h", "moving", "moving volume");
    CpuSolver<double> s(pb, false);
    std::vector<double> h, hu, hv;
    advanceChute(s, voellmy, [&](double t)
    {
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
    });
    if (!voellmy)
    {
        test.check(movingCells(hu, hv) == 0,
            name + ": at rest by t = 150 s, every momentum exactly zero");
    }
    else
    {
        // The terminal speed of the thickest cell of each stencil
        int at = -1;
        const double worst = terminalExcess(in, h, hu, hv, at);
        std::printf("  the largest speed over 1.5 times the terminal speed plus 0.1 m/s: "
                    "%.3f (cell %d, %d)\n", worst, at % nx, at/nx);
        test.check(worst <= 1, name + ": no cell with h > 1e-4 m faster than 1.5 times "
            "its stencil's terminal speed (+ 0.1 m/s) at t = 300 s");
    }
    // The time step at the end is the body's: the CFL rate of eq. (24)
    // is no larger than the largest a cell of the body (h >= 5 % of the
    // peak) can have, (|u| + 2 sqrt(g K_max h))/dx + (|v| + ...)/dy
    {
        const double body = bodyRate(in, h, hu, hv);
        const double rate = s.diagnostics().maxRate;
        std::printf("  CFL rate at the end %.4g 1/s, the body's largest possible %.4g 1/s\n",
            rate, body);
        test.check(rate <= body,
            name + ": the time step at the end is the body's, not set by thin cells");
    }
    checkMaps(test, name, peakSpeeds(s), in.g, chuteDrop(), chuteHead(in));
}

void inclinedPlane(Counter& test)
{
    const ModelInput in = filmPlaneInput();
    const Problem<double> pb = filmPlaneProblem(in);
    const std::string name = "2. section 5.3, the cap into the flat runout, 120 x 56";
    std::printf("\n%s\n", name.c_str());
    CpuSolver<double> s(pb, false);
    s.advanceTo(filmPlaneEnd);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    const double vmax = maxSpeed(h, hu, hv);
    const long moving = movingCells(hu, hv);
    const Speeds u = peakSpeeds(s);
    std::printf("  t = 60 after %ld steps: %ld cells moving, the fastest with h > 1e-4 "
                "at %.4f (peak body speed %.3f)\n", s.steps(), moving, vmax, u.body);
    test.check(vmax <= 0.1*u.body,
        name + ": at t = 60 no cell with h > 1e-4 faster than a tenth of the flow's peak speed");
    checkMaps(test, name, u, in.g, filmPlaneDrop(), filmPlaneHead(in));
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

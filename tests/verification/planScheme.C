/*---------------------------------------------------------------------------*\
  The scheme on the plan grid (physics/planScheme.H, coordinates plan), CPU
  backend, double: the state holds H = J h, H u, H v per plan area.

    a  mass sum H dX dY in a closed box, a layer moving over a bumpy DEM:
       conserved to round-off (double, and float)
    b  a layer of varying thickness over the whole domain held by friction
       on a plane below delta (descent along X and turned by 30 deg in
       plan, inputs perturbed by round-off) and a
       frictionless lake on a flat floor: exactly at rest (momentum 0, H
       unchanged bit for bit)
    c  a moving layer on a bumpy DEM in a closed box and its transposed
       (X <-> Y) and mirrored (X -> -X) images: the transposed and
       mirrored results bit for bit after N steps of the same dt
    d  H >= 0 in every cell of every run
    e  a uniform layer on a 35 deg plane turned by 30 deg, Coulomb 20 deg:
       3D speed (g sin(theta) - mu g cos(theta)) t; the hazard maps' peak
       h (normal to the bed) and speed (3D)
    f  the dam break on the 40 deg incline (damBreak.C, Zhai et al.
       section 5.1) as the DEM b = -X tan(zeta) against the
       slope-coordinate run (x = X/cos(zeta)): L1 difference of h and the
       fronts
    g  the same dam break on the plane turned by 30 deg in plan and along
       X on cells of the same size, against the exact solution (33) over a
       band along the descent away from the sides: L1 errors and fronts
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "planCases.H"

#include <functional>

using namespace sh;
using namespace shtest;

namespace
{

using Layer = std::function<Primitive(double, double)>;   // H, u, v

template<class Real>
struct Run
{
    std::vector<Real> H, Hu, Hv;
    double minH = 0;
};

//- nx x nx cells on [-L, L]^2 (dX = dY exactly), the bed and the state
//  (H, u, v) from functions, all sides of type bc
template<class Real = double>
Problem<Real> planProblem
(
    const ModelInput& in,
    int nx,
    double L,
    BCType bc,
    const Bed& bed,
    const Layer& layer
)
{
    ModelInput pin = in;
    pin.coordinates = Coordinates::plan;
    Problem<Real> pb(makeParams<Real>(pin), nx, nx, -L, L, -L, L);
    for (int s = 0; s < 4; ++s)
    {
        pb.bc.type[s] = bc;
    }
    pb.setTopography(bed);
    pb.setState(layer);
    return pb;
}

//- n steps of dt (dt <= 0: the stable one of each step)
template<class Real>
Run<Real> runSteps(const Problem<Real>& pb, int n, Real dt)
{
    CpuSolver<Real> s(pb, false);
    Run<Real> r;
    r.minH = minOf(pb.h);
    for (int k = 0; k < n; ++k)
    {
        s.step(dt > 0 ? dt : s.stableDt());
        std::vector<Real> H, Hu, Hv;
        s.getState(H, Hu, Hv);
        r.minH = std::min(r.minH, minOf(H));
    }
    s.getState(r.H, r.Hu, r.Hv);
    return r;
}

//- The same bits, or both zero (a zero momentum negated for the mirror
//  image is -0)
template<class Real>
bool sameValue(Real a, Real b)
{
    return sameBits(a, b) || (a == 0 && b == 0);
}

template<class Real>
const char* precision()
{
    return sizeof(Real) == sizeof(float) ? "float" : "double";
}

double bumpy(double x, double y)
{
    return 0.4*std::sin(0.6*x + 0.3)*std::cos(0.5*y - 0.2) + 0.05*x*y/10
        - 0.2*x;
}

//- J of the bed b = -tan(theta) (X cos(psi) + Y sin(psi))
double planeJ(double theta)
{
    return 1/std::cos(theta);
}

//- (a): the mass of a layer moving over a bumpy DEM in a closed box
template<class Real>
void massInBox(Counter& test, const ModelInput& in, double& minH)
{
    const Problem<Real> pb = planProblem<Real>
    (
        in, 48, 12, BCType::wall, bumpy,
        [](double x, double y)
        {
            const double r2 = (x + 3)*(x + 3) + y*y;
            return Primitive{r2 < 16 ? 1.5 - 0.09*r2 : 0, 4, 1};
        }
    );
    const Run<Real> r = runSteps(pb, 300, Real(-1));
    double v0 = 0, v1 = 0;
    for (Real H : pb.h) { v0 += H; }
    for (Real H : r.H) { v1 += H; }
    const double dA = double(pb.grid.dx)*pb.grid.dy;
    const double rel = std::fabs(v1 - v0)/v0;
    double moving = 0;
    for (std::size_t k = 0; k < r.H.size(); ++k)
    {
        moving += r.Hu[k] != 0 || r.Hv[k] != 0;
    }
    // The sum of the cells' changes, each a difference of fluxes shared
    // with the neighbour, is 0 up to the rounding of the state's sums
    const double bound = sizeof(Real) == sizeof(float) ? 1e-6 : 1e-13;
    std::printf("a  %-6s mass, closed box, bumpy DEM, 300 steps: V0 = %.15g m3,"
        " V = %.15g m3, relative change %.2e, moving cells %g\n",
        precision<Real>(), v0*dA, v1*dA, rel, moving);
    test.check(rel < bound && moving > 0,
        fmt("a: mass conserved to round-off (%g)", bound));
    minH = std::min(minH, r.minH);
}

//- (c): a moving layer on a bumpy DEM in a closed box and its transposed
//  and mirrored images, N steps of each run's stable dt
template<class Real>
void transposedAndMirrored(Counter& test, const ModelInput& in, double& minH)
{
    const int n = 40;
    const Problem<Real> pb = planProblem<Real>
    (
        in, n, 10, BCType::wall, bumpy,
        [](double x, double y)
        {
            const double r2 = (x + 2)*(x + 2) + (y - 1)*(y - 1);
            return Primitive{r2 < 12 ? 1.2 - 0.1*r2 : 0, 3, -2};
        }
    );
    CpuSolver<Real> probe(pb, false);
    const Real dt = probe.stableDt();
    Problem<Real> tp = pb, mp = pb;
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            const int c = pb.cell(i, j), t = pb.cell(j, i);
            const int mi = pb.cell(n - 1 - i, j);
            tp.zb[t] = pb.zb[c];
            tp.h[t] = pb.h[c];
            tp.hu[t] = pb.hv[c];
            tp.hv[t] = pb.hu[c];
            mp.zb[mi] = pb.zb[c];
            mp.h[mi] = pb.h[c];
            mp.hu[mi] = -pb.hu[c];
            mp.hv[mi] = pb.hv[c];
        }
    }
    const int steps = 80;
    const Run<Real> r = runSteps(pb, steps, Real(-1));
    const Run<Real> rt = runSteps(tp, steps, Real(-1));
    const Run<Real> rm = runSteps(mp, steps, Real(-1));
    long tBad = 0, mBad = 0;
    for (int j = 0; j < n; ++j)
    {
        for (int i = 0; i < n; ++i)
        {
            const int c = pb.cell(i, j), t = pb.cell(j, i);
            const int mi = pb.cell(n - 1 - i, j);
            tBad += !sameBits(r.H[c], rt.H[t]) || !sameBits(r.Hu[c], rt.Hv[t])
                || !sameBits(r.Hv[c], rt.Hu[t]);
            mBad += !sameBits(r.H[c], rm.H[mi]) || !sameValue(Real(-r.Hu[c]), rm.Hu[mi])
                || !sameBits(r.Hv[c], rm.Hv[mi]);
        }
    }
    double moving = 0;
    for (std::size_t k = 0; k < r.H.size(); ++k)
    {
        moving += r.Hu[k] != 0 || r.Hv[k] != 0;
    }
    std::printf("c  %-6s %d steps of the stable dt (first %.4g s), %g moving cells: cells differing"
        " from the transposed run %ld, from the mirrored run %ld\n",
        precision<Real>(), steps, double(dt), moving, tBad, mBad);
    test.check(tBad == 0 && moving > 0,
        std::string("c: 90 deg rotation (transposition) bit for bit, ") + precision<Real>());
    test.check(mBad == 0 && moving > 0,
        std::string("c: mirror X -> -X bit for bit, ") + precision<Real>());
    minH = std::min({minH, r.minH, rt.minH, rm.minH});
}

} // namespace


int main()
{
    Counter test;
    const double g = 9.81;
    double minH = 0;

    ModelInput in;
    in.g = g;
    in.phiDeg = 35;
    in.coulomb.deltaDeg = 25;

    // (a) mass in a closed box, (c) transposed and mirrored runs
    massInBox<double>(test, in, minH);
    transposedAndMirrored<double>(test, in, minH);
    massInBox<float>(test, in, minH);
    transposedAndMirrored<float>(test, in, minH);

    // (b) held by friction on planes; a frictionless lake
    {
        ModelInput hold = in;
        hold.phiDeg = 40;
        hold.coulomb.deltaDeg = 35;
        const double theta = 20*deg;
        for (const double psiDeg : {0.0, 30.0})
        {
            const double psi = psiDeg*deg;
            const double J = planeJ(theta);
            const auto bed = [=](double x, double y)
            {
                const double b = -std::tan(theta)*(x*std::cos(psi) + y*std::sin(psi));
                return b*(1 + 1e-15*std::sin(7*x + 3*y));
            };
            const Problem<double> pb = planProblem
            (
                hold, 60, 15, BCType::transmissive, bed,
                [=](double x, double y)
                {
                    const double h = 1 + 0.2*std::sin(0.3*x)*std::cos(0.25*y);
                    return Primitive{J*h*(1 + 1e-15*std::cos(5*x - 2*y)), 0, 0};
                }
            );
            const Run<double> r = runSteps(pb, 200, -1.0);
            bool rest = true, same = true;
            for (std::size_t k = 0; k < r.H.size(); ++k)
            {
                rest = rest && r.Hu[k] == 0 && r.Hv[k] == 0;
                same = same && sameBits(r.H[k], pb.h[k]);
            }
            std::printf("b  layer 1 +- 0.2 m over the whole domain (open sides) on a"
                " 20 deg plane, descent turned %2.0f deg,"
                " delta 35 deg, 200 steps: momentum %s, H %s\n", psiDeg,
                rest ? "exactly 0" : "NOT 0", same ? "unchanged" : "CHANGED");
            test.check(rest && same, fmt("b: held at rest, plane turned %g deg", psiDeg));
            minH = std::min(minH, r.minH);
        }
        ModelInput lake = in;
        lake.earthPressure = EarthPressureModel::isotropic;
        lake.coulomb.deltaDeg = 0;
        lake.phiDeg = 30;
        const Problem<double> pb = planProblem
        (
            lake, 40, 10, BCType::wall, [](double, double) { return 2.0; },
            [](double, double) { return Primitive{1.25, 0, 0}; }
        );
        const Run<double> r = runSteps(pb, 200, -1.0);
        bool rest = true, same = true;
        for (std::size_t k = 0; k < r.H.size(); ++k)
        {
            rest = rest && r.Hu[k] == 0 && r.Hv[k] == 0;
            same = same && sameBits(r.H[k], pb.h[k]);
        }
        std::printf("b  frictionless lake on a flat floor, 200 steps: momentum %s,"
            " H %s\n", rest ? "exactly 0" : "NOT 0", same ? "unchanged" : "CHANGED");
        test.check(rest && same, "b: frictionless lake at rest");
        minH = std::min(minH, r.minH);
    }

    // (e) a uniform layer sliding on a turned plane
    {
        ModelInput sl = in;
        sl.phiDeg = 30;
        sl.coulomb.deltaDeg = 20;
        const double theta = 35*deg, psi = 30*deg, J = planeJ(theta);
        const Problem<double> pb = planProblem
        (
            sl, 20, 10, BCType::transmissive,
            [=](double x, double y)
            {
                return -std::tan(theta)*(x*std::cos(psi) + y*std::sin(psi));
            },
            [=](double, double) { return Primitive{0.5*J, 0, 0}; }
        );
        CpuSolver<double> s(pb, false);
        const double tEnd = 2;
        s.advanceTo(tEnd);
        std::vector<double> H, Hu, Hv;
        s.getState(H, Hu, Hv);
        const int c = pb.cell(10, 10);
        const double u = Hu[c]/H[c], v = Hv[c]/H[c];
        const double p = -std::tan(theta)*std::cos(psi), q = -std::tan(theta)*std::sin(psi);
        const double w = p*u + q*v;
        const double speed = std::sqrt(u*u + v*v + w*w);
        const double exact = g*(std::sin(theta) - std::tan(20*deg)*std::cos(theta))*s.time();
        const double rel = std::fabs(speed - exact)/exact;
        // Direction: along the steepest descent (cos(psi), sin(psi)) in plan
        const double turn = std::atan2(v, u) - psi;
        std::printf("e  uniform layer, 35 deg plane turned 30 deg, delta 20 deg,"
            " t = %.3f s: 3D speed %.12g m/s, exact %.12g m/s, relative error"
            " %.2e, direction off the descent by %.2e rad\n",
            s.time(), speed, exact, rel, turn);
        test.check(rel < 1e-12 && std::fabs(turn) < 1e-12,
            "e: g sin(theta) - mu g cos(theta) along the descent");
        const PeakMaps<double> pk = s.peakMaps();
        std::printf("e  hazard maps there: peak h %.15g m (normal to the bed;"
            " 0.5 m), peak speed %.12g m/s (the 3D speed)\n", pk.h[c], pk.speed[c]);
        test.check(std::fabs(pk.h[c] - 0.5) < 1e-14 && std::fabs(pk.speed[c] - speed) < 1e-12*speed,
            "e: hazard maps keep the normal thickness and the 3D speed");
        minH = std::min(minH, minOf(H));
    }

    // (f) the dam break on the incline, slope against plan coordinates
    {
        ModelInput db;
        db.g = g;
        db.earthPressure = EarthPressureModel::isotropic;
        db.phiDeg = 40;
        db.coulomb.deltaDeg = 24.5;
        const double h0 = 10, zeta = 40*deg, tEnd = 0.5, cz = std::cos(zeta);
        const int nx = 256, ny = 32;
        Problem<double> sp(makeParams<double>(db), nx, ny, -12.8, 12.8, -1.6, 1.6);
        sp.setInclination([&](double) { return zeta; });
        sp.setState([&](double x, double) { return Primitive{x < 0 ? h0 : 0, 0, 0}; });
        ModelInput dbp = db;
        dbp.coordinates = Coordinates::plan;
        Problem<double> pp
        (
            makeParams<double>(dbp), nx, ny, -12.8*cz, 12.8*cz, -1.6, 1.6
        );
        pp.setTopography([&](double x, double) { return -x*std::tan(zeta); });
        pp.setState([&](double x, double) { return Primitive{x < 0 ? h0/cz : 0, 0, 0}; });
        CpuSolver<double> ss(sp, false), ps(pp, false);
        ss.advanceTo(tEnd);
        ps.advanceTo(tEnd);
        std::vector<double> hs, a, b, Hp, c, d;
        ss.getState(hs, a, b);
        ps.getState(Hp, c, d);
        const int j = ny/2;
        double l1 = 0, l1ex = 0, mass = 0;
        int fs = 0, fp = 0, rs = nx, rp = nx;
        for (int i = 0; i < nx; ++i)
        {
            const double h1 = hs[sp.cell(i, j)];
            const double h2 = Hp[pp.cell(i, j)]*cz;
            const double ex = granularDamBreakDepth(sp.grid.xc(i), tEnd, h0, g, zeta, 24.5*deg);
            l1 += std::fabs(h1 - h2);
            l1ex += std::fabs(h2 - ex);
            mass += h1;
            if (h1 > 1e-3) { fs = i; rs = std::min(rs, i); }
            if (h2 > 1e-3) { fp = i; rp = std::min(rp, i); }
        }
        const double dx = sp.grid.dx;
        std::printf("f  dam break on the 40 deg incline, %dx%d, t = %.2f s:"
            " L1(h_plan - h_slope)/L1(h) = %.3e, L1(h_plan - exact)/L1(h) = %.3e\n"
            "   front (last cell with h > 1e-3): slope x = %.4f m, plan"
            " X/cos(zeta) = %.4f m (%d cells apart); rear: %.4f, %.4f m\n",
            nx, ny, tEnd, l1/mass, l1ex/mass, sp.grid.xc(fs),
            pp.grid.xc(fp)/cz, std::abs(fs - fp), sp.grid.xc(rs), pp.grid.xc(rp)/cz);
        test.check(std::abs(fs - fp) <= 2 && std::abs(rs - rp) <= 2,
            "f: fronts within 2 cells of the slope-coordinate run");
        test.check(l1/mass < 0.02, "f: L1 difference of h below 2 %");
        (void)dx;
        minH = std::min(minH, minOf(Hp));
    }

    // (g) the dam break on a 40 deg plane turned by 30 deg in plan, and
    // along X on the same cells
    {
        const DamBreak turned = turnedDamBreak(30*deg, 160, 160, 10, 10);
        const DamBreak along = turnedDamBreak(0, 160, 16, 10, 1);
        std::printf("g  dam break on the 40 deg plane, t = 0.5 s, cells of"
            " %.3f m along the slope: L1(h - exact)/L1(exact) %.3e turned 30"
            " deg (160x160, band along the descent), %.3e along X (160x16);"
            " front (h > 0.1 m = h0/100) turned x = %.3f m, along X %.3f m,"
            " exact %.3f m\n", turned.dx, turned.e1, along.e1, turned.front,
            along.front, turned.frontExact);
        test.check(turned.e1 < 2*along.e1,
            "g: turned dam break's L1 error within twice the aligned one's");
        test.check(std::fabs(turned.front - along.front) <= 2*turned.dx,
            "g: turned dam break's front within 2 cells of the aligned one's");
        minH = std::min(minH, turned.minH);
    }

    std::printf("d  smallest H of all runs: %g\n", minH);
    test.check(minH >= 0, "d: H >= 0 everywhere");
    return test.finish();
}

/*---------------------------------------------------------------------------*\
  The pointwise physics of the general-topography model on the plan grid
  (physics/planTerrain.H, docs/generalTerrain.md), checked point by point,
  double precision, no grid and no scheme:

  a) Tilted planes, slope theta 20, 35, 40 deg, the line of steepest
     descent turned by 0, 30, 90, 135 deg in plan, a uniform layer (h =
     1.5 m) sliding down it at 4 m/s, Coulomb delta 12 and 38 deg: the plan
     acceleration of the sources equals (g sin(theta) - mu g cos(theta))
     along the line of steepest descent, projected (cos(theta) times its
     plan direction), to 1e-13 relative: the rate (driving plus friction
     force over H) and the step (planSourceStep over dt = 0.1 s).
  b) The same planes with the flow across them too (4 m/s down, 1.5 m/s
     across), against the slope-coordinate model of the present scheme for
     a constant zeta = theta (scheme.H drivingAcceleration, coulombImpulse):
     the accelerations in slope coordinates agree to 1e-13; and with the
     descent along X the faces' fluxes are the paper's (hllc.H
     physicalFlux) as docs/generalTerrain.md maps them: x-face (F_h,
     cos F_hu, F_hv), y-face (F_h/cos, F_hu, F_hv/cos), to 1e-14.
  c) Random states and beds (2000 each, Coulomb and Voellmy): transposing
     X <-> Y transposes the fluxes, the pressure's curvature term, the
     driving and the source and static steps bit for bit (memcmp), and
     mirroring X -> -X mirrors them bit for bit.
  d) Material at rest on a plane below the friction angle (delta = 35 deg,
     theta 20, 30, 34.9 deg, times (1 + 1e-15), four directions), with a
     trial momentum of round-off size: the static step and the moving
     step both leave it exactly at rest; at 35.1 deg it moves (the check
     can fail).
  e) h -> 0 (H from 0 to 1, down to the smallest subnormal) and |u| up to
     1e6 m/s on steep curved beds: h >= 0, Pi_nn >= 0, g_n >= 0, every
     result finite.
  f) The curvature term on a cylinder b = R - sqrt(R^2 - X^2) (concave) and
     its negative (convex), R = 50 m, at X = 10, 25, 40 m, the 3D speed s
     at angle psi to the circle:
        g_n = max(0, g cos(theta) +- lambda s^2 cos^2(psi)/R)
     (the normal curvature cos^2(psi)/R, Euler), to 1e-13; a particle
     sliding down the circle (psi = 0, no pressure, no friction) has the
     plan acceleration of motion on the circle, -+ g sin(theta) cos(theta)
     - s^2 sin(theta)/R (X > 0: the centripetal part towards the axis, the
     constraint kept also where the convex bed would have to pull,
     s^2/R > g cos(theta)); and the pressure's curvature term of a layer of
     thickness h is tr(Pi B)/H = eps g K h/(2R), isotropic K.
  g) The stretching rates along and across the flow that the earth
     pressure's switch reads (flowStretching): a flow down a plane (20 and
     40 deg, turned by 0, 30, 135 deg) stretched at a = 0.3 1/s along the
     slope and b = -0.2 1/s across it gives (a, b); flow at uniform speed
     round a cylinder stretched b along its axis gives (0, b); to 1e-14
     1/s; transposed and mirrored bit for bit on random inputs.
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "physics/planTerrain.H"

#include <cstring>
#include <random>

using namespace sh;
using namespace shtest;

namespace
{

const double g = 9.81;

Params<double> coulombParams(double deltaDeg, double lambda)
{
    ModelInput in;
    in.g = g;
    in.lambda = lambda;
    in.earthPressure = EarthPressureModel::isotropic;
    in.frictionLaw = FrictionLaw::Coulomb;
    in.coulomb.deltaDeg = deltaDeg;
    return makeParams<double>(in);
}

Params<double> voellmyParams()
{
    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::isotropic;
    in.frictionLaw = FrictionLaw::Voellmy;
    in.voellmy.mu = 0.3;
    in.voellmy.xi = 1000;
    return makeParams<double>(in);
}

//- The plan acceleration of the sources for a uniform layer (no pressure
//  gradient): (driving - mu H g_n u/|V| - J k |V| u)/H
PlanForce<double> rateAcceleration
(
    const Params<double>& par,
    const PlanMetric<double>& m,
    double H,
    double u,
    double v,
    const PlanK<double>& K
)
{
    const PlanState<double> s{H, u, v};
    const double trPiB = pressureCurvature(m, s, K, par.g*par.epsilon);
    const PlanForce<double> D = planDriving(m, par.g, s, trPiB);
    const double speed = planSpeed(m, u, v);
    const double f =
        planFrictionImpulse(par, m, s, 1.0)
      + m.J*dragCoefficient(par.friction)*speed*speed;
    return {(D.x - f*u/speed)/H, (D.y - f*v/speed)/H};
}

//- A plane of slope theta whose steepest descent points along (c, s)
PlanMetric<double> plane(double theta, double c, double s)
{
    const double t = std::tan(theta);
    return planMetric(-t*c, -t*s, 0.0, 0.0, 0.0);
}

double rel(double ax, double ay, double bx, double by)
{
    return std::hypot(ax - bx, ay - by)/std::hypot(bx, by);
}

//- The planes of a) and b): slope, direction of the descent in plan
//  (cos, sin), Coulomb friction angle
struct PlaneCase
{
    double thetaDeg, alphaDeg, deltaDeg;
    double th, dc, ds;
    PlanMetric<double> m;
    Params<double> par;
};

std::vector<PlaneCase> planeCases()
{
    std::vector<PlaneCase> cases;
    for (double thetaDeg : {20.0, 35.0, 40.0})
    for (double alphaDeg : {0.0, 30.0, 90.0, 135.0})
    for (double deltaDeg : {12.0, 38.0})
    {
        const double th = thetaDeg*deg;
        const double dc = std::cos(alphaDeg*deg);
        const double ds = std::sin(alphaDeg*deg);
        cases.push_back
        ({
            thetaDeg, alphaDeg, deltaDeg, th, dc, ds, plane(th, dc, ds),
            coulombParams(deltaDeg, 1)
        });
    }
    return cases;
}

// * * * * * * * * * * * * * * * a) Tilted planes  * * * * * * * * * * * * //

void tiltedPlanes(Counter& c)
{
    std::printf
    (
        "\na) uniform layer sliding down tilted planes (h 1.5 m, 4 m/s)\n"
        "  theta  dir  delta  exact a [m/s^2]  rel err rate  rel err step\n"
    );
    double worst = 0;
    for (const PlaneCase& k : planeCases())
    {
        const double th = k.th, dc = k.dc, ds = k.ds;
        const double mu = std::tan(k.deltaDeg*deg);
        const double H = planVolume(k.m, 1.5);
        const double s = 4;
        const double u = s*std::cos(th)*dc;
        const double v = s*std::cos(th)*ds;
        const double A = g*std::sin(th) - mu*g*std::cos(th);
        const double ex = A*std::cos(th)*dc;
        const double ey = A*std::cos(th)*ds;

        const PlanK<double> K{1, 1};
        const PlanForce<double> a = rateAcceleration(k.par, k.m, H, u, v, K);
        const double eRate = rel(a.x, a.y, ex, ey);

        const double dt = 0.1;
        const State<double> q0{H, H*u, H*v};
        State<double> r = q0;
        planSourceStep(k.par, k.m, {H, u, v}, 0.0, q0, dt, r);
        const double eStep =
            rel((r.hu - H*u)/(dt*H), (r.hv - H*v)/(dt*H), ex, ey);
        std::printf
        (
            "  %5.1f  %3.0f  %5.1f  %15.10f  %12.2e  %12.2e\n",
            k.thetaDeg, k.alphaDeg, k.deltaDeg, A, eRate, eStep
        );
        worst = std::max(worst, std::max(eRate, eStep));
    }
    c.check(worst <= 1e-13, fmt("a) plan acceleration = g sin - mu g cos along the descent, projected: worst %.2e <= 1e-13", worst));
}

// * * * * * * * * * * * * * b) Slope coordinates * * * * * * * * * * * * * //

//- The slope-coordinate acceleration of the present scheme for a constant
//  zeta, state (h, us, vs): drivingAcceleration and coulombImpulse
Acceleration<double> slopeAcceleration
(
    const Params<double>& par,
    double zeta,
    double h,
    double us,
    double vs
)
{
    const int n = 1 + 2*Grid<double>::ng;
    std::vector<double> cz(n, std::cos(zeta)), sz(n, std::sin(zeta));
    std::vector<double> kap(n, 0.0), zb(n*n, 0.0);
    Model<double> mod;
    mod.p = par;
    mod.g.nx = 1;
    mod.g.ny = 1;
    mod.g.dx = mod.g.dy = 1;
    mod.g.rdx = mod.g.rdy = 1;
    mod.g.x0 = mod.g.y0 = 0;
    mod.geo = {cz.data(), sz.data(), kap.data(), zb.data()};
    const Acceleration<double> d = drivingAcceleration(mod, 0, 0.0, 0.0);
    const CellState<double> cs{{h, h*us, h*vs}, us, vs};
    const double f = coulombImpulse(mod, 0, cs, 1.0)/h;
    const double speed = std::sqrt(us*us + vs*vs);
    return {d.x - f*us/speed, d.y - f*vs/speed};
}

double relState(const State<double>& a, const State<double>& b)
{
    const double n = std::sqrt(b.h*b.h + b.hu*b.hu + b.hv*b.hv);
    return std::sqrt
    (
        (a.h - b.h)*(a.h - b.h) + (a.hu - b.hu)*(a.hu - b.hu)
      + (a.hv - b.hv)*(a.hv - b.hv)
    )/n;
}

void slopeCoordinates(Counter& c)
{
    std::printf
    (
        "\nb) against the slope-coordinate model (zeta = theta, 4 m/s down,"
        " 1.5 m/s across)\n"
        "  theta  dir  delta  slope a_x, a_y [m/s^2]      rel diff\n"
    );
    double worst = 0;
    for (const PlaneCase& k : planeCases())
    {
        const double th = k.th, dc = k.dc, ds = k.ds;
        const double h = 1.5;
        const double us = 4;
        const double vs = 1.5;
        // Plan velocity: us cos(theta) along the descent, vs across it
        const double u = us*std::cos(th)*dc - vs*ds;
        const double v = us*std::cos(th)*ds + vs*dc;
        const PlanForce<double> a =
            rateAcceleration(k.par, k.m, planVolume(k.m, h), u, v, {1, 1});
        const double ax = (a.x*dc + a.y*ds)/std::cos(th);
        const double ay = -a.x*ds + a.y*dc;
        const Acceleration<double> s = slopeAcceleration(k.par, th, h, us, vs);
        const double e = rel(ax, ay, s.x, s.y);
        std::printf
        (
            "  %5.1f  %3.0f  %5.1f  %12.8f %12.8f  %10.2e\n",
            k.thetaDeg, k.alphaDeg, k.deltaDeg, s.x, s.y, e
        );
        worst = std::max(worst, e);
    }
    c.check(worst <= 1e-13, fmt("b) plan = slope-coordinate acceleration: worst %.2e <= 1e-13", worst));

    // Fluxes, descent along X
    std::printf("  fluxes, descent along X (K along, across):\n");
    double worstF = 0;
    for (double thetaDeg : {20.0, 35.0, 40.0})
    {
        const double th = thetaDeg*deg;
        const double cz = std::cos(th);
        const PlanMetric<double> m = plane(th, 1, 0);
        const double h = 1.5;
        struct Case { double Ka, Kc, vs; };
        for (const Case& k : {Case{1, 1, 1.5}, Case{1.4, 1.4, 1.5}, Case{1.6, 0.9, 0}})
        {
            const double us = 4;
            const double u = us*cz;
            const double v = k.vs;
            const double H = planVolume(m, h);
            const PlanK<double> K{k.Ka, k.Kc};
            const State<double> fx = planFlux(m, {H, u, v}, K, g, false);
            const State<double> fy = planFlux(m, {H, u, v}, K, g, true);
            const State<double> sx = physicalFlux<double>({h, us, k.vs}, g*cz*k.Ka);
            const State<double> sy = physicalFlux<double>({h, k.vs, us}, g*cz*k.Kc);
            const double ex = relState(fx, {sx.h, cz*sx.hu, sx.hv});
            const double ey = relState(fy, {sy.h/cz, sy.hv, sy.hu/cz});
            std::printf
            (
                "    theta %4.1f  K %.1f %.1f  x-face %.2e  y-face %.2e\n",
                thetaDeg, k.Ka, k.Kc, ex, ey
            );
            worstF = std::max(worstF, std::max(ex, ey));
        }
    }
    c.check(worstF <= 1e-14, fmt("b) plan fluxes = the paper's, mapped: worst %.2e <= 1e-14", worstF));
}

// * * * * * * * * * * * * * * c) Transposition  * * * * * * * * * * * * * //

bool same(double a, double b)
{
    return std::memcmp(&a, &b, sizeof a) == 0;
}

//- b is -a bit for bit (or both zero)
bool opposite(double a, double b)
{
    const double nb = -b;
    return same(a, nb) || (a == 0 && b == 0);
}

struct Sample
{
    double p, q, bxx, bxy, byy;
    double H, u, v, Hh, uh, vh, H0, u0, v0, HEnd, Mx, My;
    PlanK<double> K;
};

struct Result
{
    State<double> fx, fy;
    double trPiB;
    PlanForce<double> D;
    double sx, sy;      //!< planSourceStep
    double rx, ry;      //!< planStaticStep
};

Result evaluate(const Params<double>& par, const Sample& s)
{
    const PlanMetric<double> m = planMetric(s.p, s.q, s.bxx, s.bxy, s.byy);
    const double eg = par.epsilon*par.g;
    const PlanState<double> st{s.H, s.u, s.v};
    const PlanState<double> sh{s.Hh, s.uh, s.vh};
    Result r;
    r.fx = planFlux(m, st, s.K, eg, false);
    r.fy = planFlux(m, st, s.K, eg, true);
    r.trPiB = pressureCurvature(m, st, s.K, eg);
    r.D = planDriving(m, par.g, st, r.trPiB);
    State<double> q{s.HEnd, s.Mx, s.My};
    planSourceStep
    (
        par, m, sh, pressureCurvature(m, sh, s.K, eg),
        {s.H0, s.H0*s.u0, s.H0*s.v0}, 0.05, q
    );
    r.sx = q.hu;
    r.sy = q.hv;
    r.rx = s.Mx;
    r.ry = s.My;
    planStaticStep(par, m, s.H, r.trPiB, 0.05, r.rx, r.ry);
    return r;
}

Sample transposedSample(Sample s)
{
    std::swap(s.p, s.q);
    std::swap(s.bxx, s.byy);
    std::swap(s.u, s.v);
    std::swap(s.uh, s.vh);
    std::swap(s.u0, s.v0);
    std::swap(s.Mx, s.My);
    return s;
}

Sample mirroredSample(Sample s)
{
    s.p = -s.p;
    s.bxy = -s.bxy;
    s.u = -s.u;
    s.uh = -s.uh;
    s.u0 = -s.u0;
    s.Mx = -s.Mx;
    return s;
}

bool transposedOf(const Result& a, const Result& t)
{
    return
        same(a.fx.h, t.fy.h) && same(a.fx.hu, t.fy.hv) && same(a.fx.hv, t.fy.hu)
     && same(a.fy.h, t.fx.h) && same(a.fy.hu, t.fx.hv) && same(a.fy.hv, t.fx.hu)
     && same(a.trPiB, t.trPiB)
     && same(a.D.x, t.D.y) && same(a.D.y, t.D.x)
     && same(a.sx, t.sy) && same(a.sy, t.sx)
     && same(a.rx, t.ry) && same(a.ry, t.rx);
}

bool mirroredOf(const Result& a, const Result& r)
{
    return
        opposite(a.fx.h, r.fx.h) && same(a.fx.hu, r.fx.hu) && opposite(a.fx.hv, r.fx.hv)
     && same(a.fy.h, r.fy.h) && opposite(a.fy.hu, r.fy.hu) && same(a.fy.hv, r.fy.hv)
     && same(a.trPiB, r.trPiB)
     && opposite(a.D.x, r.D.x) && same(a.D.y, r.D.y)
     && opposite(a.sx, r.sx) && same(a.sy, r.sy)
     && opposite(a.rx, r.rx) && same(a.ry, r.ry);
}

void transposition(Counter& c)
{
    std::printf("\nc) transposition X <-> Y and mirror X -> -X, random inputs\n");
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> U(-1, 1);
    const int n = 2000;
    const Params<double> laws[2] = {coulombParams(30, 1), voellmyParams()};
    const char* names[2] = {"Coulomb", "Voellmy"};
    for (int l = 0; l < 2; ++l)
    {
        int badT = 0, badM = 0, stopped = 0;
        for (int k = 0; k < n; ++k)
        {
            Sample s;
            s.p = 2*U(rng); s.q = 2*U(rng);
            s.bxx = 0.05*U(rng); s.bxy = 0.05*U(rng); s.byy = 0.05*U(rng);
            s.H = 3*(1 + U(rng)); s.u = 15*U(rng); s.v = 15*U(rng);
            s.Hh = 3*(1 + U(rng)); s.uh = 15*U(rng); s.vh = 15*U(rng);
            s.H0 = 3*(1 + U(rng)); s.u0 = 15*U(rng); s.v0 = 15*U(rng);
            s.HEnd = 3*(1 + U(rng)) + 1e-3;
            s.Mx = s.H0*s.u0 + 5*U(rng); s.My = s.H0*s.v0 + 5*U(rng);
            s.K = {1.5 + U(rng), 1.5 + U(rng)};
            const Result a = evaluate(laws[l], s);
            badT += transposedOf(a, evaluate(laws[l], transposedSample(s))) ? 0 : 1;
            badM += mirroredOf(a, evaluate(laws[l], mirroredSample(s))) ? 0 : 1;
            stopped += (a.rx == 0 && a.ry == 0) ? 1 : 0;
        }
        std::printf
        (
            "  %-8s %d samples: %d not transposed, %d not mirrored bit for"
            " bit (%d held by the static step)\n",
            names[l], n, badT, badM, stopped
        );
        c.check(badT == 0, std::string("c) ") + names[l] + ": transposed bit for bit");
        c.check(badM == 0, std::string("c) ") + names[l] + ": mirrored bit for bit");
    }
}

// * * * * * * * * * * * * * * * d) At rest * * * * * * * * * * * * * * * * //

void atRest(Counter& c)
{
    std::printf
    (
        "\nd) at rest on a plane, delta = 35 deg, theta (1 + 1e-15)\n"
        "  theta   dir  static step (Mx, My)     moving step (Mx, My)\n"
    );
    const Params<double> par = coulombParams(35, 1);
    bool allRest = true;
    bool moves = true;
    for (double thetaDeg : {20.0, 30.0, 34.9, 35.1})
    for (double alphaDeg : {0.0, 30.0, 90.0, 135.0})
    {
        const double th = thetaDeg*deg*(1 + 1e-15);
        const PlanMetric<double> m =
            plane(th, std::cos(alphaDeg*deg), std::sin(alphaDeg*deg));
        const double H = planVolume(m, 2.0)*(1 + 1e-15);
        const double dt = 0.05;
        // Round-off of the fluxes of a uniform layer
        const double eps = 1e-16*H*g*dt;
        double rx = eps, ry = -eps;
        planStaticStep(par, m, H, 0.0, dt, rx, ry);
        State<double> q{H, eps, -eps};
        planSourceStep(par, m, {H, 0.0, 0.0}, 0.0, {H, 0.0, 0.0}, dt, q);
        const double sx = q.hu, sy = q.hv;
        std::printf
        (
            "  %5.1f  %4.0f  %11.3e %11.3e  %11.3e %11.3e\n",
            thetaDeg, alphaDeg, rx, ry, sx, sy
        );
        const bool rest = rx == 0 && ry == 0 && sx == 0 && sy == 0;
        if (thetaDeg < 35)
        {
            allRest = allRest && rest;
        }
        else
        {
            moves = moves && rx != 0 && sx*sx + sy*sy > 0;
        }
    }
    c.check(allRest, "d) below the friction angle the static and the moving step leave it exactly at rest");
    c.check(moves, "d) above it, it moves");
}

// * * * * * * * * * * * * * * e) Thin and fast * * * * * * * * * * * * * * //

bool finite(double a)
{
    return std::isfinite(a);
}

void thinAndFast(Counter& c)
{
    std::printf("\ne) h -> 0 and |u| large\n");
    const Params<double> laws[2] = {coulombParams(30, 1), voellmyParams()};
    const double Hs[] = {0, 5e-324, 1e-300, 1e-30, 1e-8, 1e-3, 1};
    const double speeds[] = {0, 1e-3, 1, 1e3, 1e6};
    int bad = 0, n = 0;
    for (int l = 0; l < 2; ++l)
    for (double H : Hs)
    for (double s : speeds)
    for (double slope : {0.0, 0.7, 3.0})
    for (double curv : {-0.2, 0.0, 0.2})
    {
        const PlanMetric<double> m =
            planMetric(slope, -0.5*slope, curv, -0.3*curv, 0.5*curv);
        const double u = 0.8*s, v = -0.6*s;
        const PlanK<double> K{2.5, 0.6};
        const double eg = g;
        const double h = planThickness(m, H);
        const PlanState<double> st{H, u, v};
        const State<double> fx = planFlux(m, st, K, eg, false);
        const State<double> fy = planFlux(m, st, K, eg, true);
        const PlanPressure<double> P =
            planPressure(h, u, v, m.p, m.q, m.rJ2, K, eg);
        const double tr = pressureCurvature(m, st, K, eg);
        const PlanForce<double> D = planDriving(m, g, st, tr);
        const double gn = planNormalLoad(laws[l], m, u, v);
        // The scheme solves momentum only above hDry (1e-6 m by default):
        // the drag's factor divides by the thickness at the end
        const double HEnd = l == 1 ? std::max(H, 1e-6) : H;
        State<double> q{HEnd, H*u, H*v};
        planSourceStep(laws[l], m, st, tr, {H, H*u, H*v}, 0.05, q);
        const double Mx = q.hu, My = q.hv;
        double Rx = H*u, Ry = H*v;
        planStaticStep(laws[l], m, H, tr, 0.05, Rx, Ry);
        const bool ok =
            h >= 0 && P.nn >= 0 && gn >= 0
         && finite(fx.h) && finite(fx.hu) && finite(fx.hv)
         && finite(fy.h) && finite(fy.hu) && finite(fy.hv)
         && finite(tr) && finite(D.x) && finite(D.y) && finite(gn)
         && finite(Mx) && finite(My) && finite(Rx) && finite(Ry);
        if (!ok)
        {
            std::printf
            (
                "  not finite or negative: law %d H %g speed %g slope %g"
                " curvature %g\n", l, H, s, slope, curv
            );
        }
        bad += ok ? 0 : 1;
        ++n;
    }
    std::printf("  %d states (H 0 ... 1, 0 ... 1e6 m/s, slopes to 3, both laws): %d bad\n", n, bad);
    c.check(bad == 0, "e) h >= 0, Pi_nn >= 0, g_n >= 0 and every result finite");
}

// * * * * * * * * * * * * * * * f) Cylinder  * * * * * * * * * * * * * * * //

void cylinder(Counter& c)
{
    std::printf
    (
        "\nf) cylinder R = 50 m: g_n = max(0, g cos(theta) +- lambda s^2"
        " cos^2(psi)/R)\n"
        "  side     X   psi  lambda   s      g_n           rel err\n"
    );
    const double R = 50;
    double worst = 0, worstA = 0, worstP = 0;
    for (int side : {1, -1})
    for (double X : {10.0, 25.0, 40.0})
    for (double psiDeg : {0.0, 30.0, 90.0})
    for (double lambda : {0.0, 0.5, 1.0})
    for (double s : {8.0, 30.0})
    {
        const double r = std::sqrt(R*R - X*X);
        const PlanMetric<double> m =
            planMetric(side*X/r, 0.0, side*R*R/(r*r*r), 0.0, 0.0);
        const double cth = r/R;
        const double sth = X/R;
        const double psi = psiDeg*deg;
        // Down the circle (towards the axis' low line) at angle psi
        const double u = -side*s*std::cos(psi)*cth;
        const double v = s*std::sin(psi);
        const Params<double> par = coulombParams(20, lambda);
        const double gn = planNormalLoad(par, m, u, v);
        const double cp = std::cos(psi);
        const double exact =
            std::max(0.0, g*cth + side*lambda*s*s*cp*cp/R);
        const double e = exact > 0
            ? std::fabs(gn - exact)/exact : std::fabs(gn);
        worst = std::max(worst, e);
        if (psiDeg != 30.0 && s == 8.0)
        {
            std::printf
            (
                "  %-7s %4.0f  %3.0f  %5.1f  %4.0f  %12.8f  %10.2e\n",
                side > 0 ? "concave" : "convex", X, psiDeg, lambda, s, gn, e
            );
        }
        if (psiDeg == 0.0 && lambda == 1.0)
        {
            // A particle down the circle: no pressure, no friction
            const PlanForce<double> D = planDriving(m, g, {1.0, u, v}, 0.0);
            const double ax = -side*g*sth*cth - s*s*sth/R;
            worstA = std::max(worstA, std::fabs(D.x - ax)/std::fabs(ax) + std::fabs(D.y));
            // The pressure's curvature term of a layer 2 m thick, K 1.3
            const double h = 2;
            const double tr =
                pressureCurvature(m, {planVolume(m, h), u, v}, {1.3, 1.3}, g);
            const double exactP = side*g*1.3*h/(2*R);
            worstP = std::max(worstP, std::fabs(tr/planVolume(m, h) - exactP)/std::fabs(exactP));
        }
    }
    c.check(worst <= 1e-13, fmt("f) g_n on the cylinder: worst %.2e <= 1e-13", worst));
    c.check(worstA <= 1e-13, fmt("f) particle on the circle: plan acceleration, worst %.2e <= 1e-13", worstA));
    c.check(worstP <= 1e-13, fmt("f) tr(Pi B)/H = eps g K h/(2R): worst %.2e <= 1e-13", worstP));
}

// * * * * * * * * * * * * * * g) Stretching  * * * * * * * * * * * * * * //

void stretching(Counter& c)
{
    std::printf
    (
        "\ng) stretching along and across the flow (K's switch), exact a, b\n"
        "  bed               along err   across err\n"
    );
    const double a = 0.3, bb = -0.2;
    double worst = 0;
    for (double thetaDeg : {20.0, 40.0})
    for (double alphaDeg : {0.0, 30.0, 135.0})
    {
        // Slope speed U0 + a x_s along the descent d, b y across it
        const double th = thetaDeg*deg;
        const double dc = std::cos(alphaDeg*deg), ds = std::sin(alphaDeg*deg);
        const PlanMetric<double> m = plane(th, dc, ds);
        const VelocityGradient<double> L
        {
            a*dc*dc + bb*ds*ds, (a - bb)*dc*ds, (a - bb)*dc*ds,
            a*ds*ds + bb*dc*dc
        };
        const double u0 = 5*std::cos(th);
        const AlongAcross<double> st = flowStretching(m, u0*dc, u0*ds, L);
        const double e = std::max(std::fabs(st.along - a), std::fabs(st.across - bb));
        std::printf("  plane %4.1f %5.1f   %10.2e  %10.2e\n", thetaDeg, alphaDeg, st.along - a, st.across - bb);
        worst = std::max(worst, e);
    }
    for (double X : {10.0, 40.0})
    {
        // Round a cylinder at uniform 3D speed s, stretched b along its axis
        const double R = 50, s = 8;
        const double r = std::sqrt(R*R - X*X);
        const PlanMetric<double> m = planMetric(X/r, 0.0, R*R/(r*r*r), 0.0, 0.0);
        const VelocityGradient<double> L{s*X/(R*r), 0, 0, bb};
        const AlongAcross<double> st = flowStretching(m, -s*r/R, 0.0, L);
        const double e = std::max(std::fabs(st.along), std::fabs(st.across - bb));
        std::printf("  cylinder X %4.0f   %10.2e  %10.2e\n", X, st.along, st.across - bb);
        worst = std::max(worst, e);
    }
    c.check(worst <= 1e-14, fmt("g) stretching rates along and across the flow: worst %.2e 1/s <= 1e-14", worst));

    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    int bad = 0;
    for (int k = 0; k < 2000; ++k)
    {
        const double p = 2*U(rng), q = 2*U(rng);
        const double bxx = 0.05*U(rng), bxy = 0.05*U(rng), byy = 0.05*U(rng);
        const double u = 10*U(rng), v = 10*U(rng);
        const VelocityGradient<double> L{U(rng), U(rng), U(rng), U(rng)};
        const AlongAcross<double> s0 =
            flowStretching(planMetric(p, q, bxx, bxy, byy), u, v, L);
        const AlongAcross<double> sT = flowStretching
        (
            planMetric(q, p, byy, bxy, bxx), v, u, {L.yy, L.yx, L.xy, L.xx}
        );
        const AlongAcross<double> sM = flowStretching
        (
            planMetric(-p, q, bxx, -bxy, byy), -u, v, {L.xx, -L.xy, -L.yx, L.yy}
        );
        const bool ok =
            same(s0.along, sT.along) && same(s0.across, sT.across)
         && same(s0.along, sM.along) && same(s0.across, sM.across);
        bad += ok ? 0 : 1;
    }
    std::printf("  2000 random states: %d not transposed or not mirrored bit for bit\n", bad);
    c.check(bad == 0, "g) stretching rates transposed and mirrored bit for bit");
}

} // namespace

int main()
{
    std::printf("General-topography model, pointwise (physics/planTerrain.H)\n");
    Counter c;
    tiltedPlanes(c);
    slopeCoordinates(c);
    transposition(c);
    atRest(c);
    thinAndFast(c);
    cylinder(c);
    stretching(c);
    return c.finish();
}

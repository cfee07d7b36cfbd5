/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The bed's cover (physics/entrainment.H) against exact solutions and
    conservation, CPU backend, double:

    1. A uniform layer sliding on a plane (zeta 30 deg, Coulomb delta 20
       deg, open sides: it stays uniform) entraining at constantRate r:
       h = h0 + r t, h u = h0 u0 + S (h0 t + r t^2/2), S = g (sin zeta -
       tan delta cos zeta).  The scheme takes the layer up after the
       corrector whose source used h^n, so its momentum is the left sum
       h0 u0 + S sum h^n dt: below the exact one by S r sum dt^2/2, at most
       S r t dtMax/2 (first order in the coupling; asserted with that
       bound, the measured error printed).  a: slope coordinates (the
       layer uniform to the bit).  b: the plan grid (coordinates plan),
       the DEM b = -tan(zeta) (X cos psi + Y sin psi) falling along psi =
       30 deg in plan, H = J h per plan area, J = 1/cos(zeta), the layer
       J L0: in every cell H = J (h0 + r t), eroded depth J r t and layer
       J (L0 - r t) per plan area (normal to the bed: r t, L0 - r t), to
       1e-12 relative per step; h = H/J and h times the 3D speed as in a;
       the motion along the descent.  A J dropped from planEntrainCell's
       take-up fails b.  c: at fixed dt 0.02, 0.01, 0.005 s to t = 4 s the
       speed u = hu/h against the exact u(t): hu is the left sum
       h0 u0 + S (h0 t + r t (t - dt)/2) to round-off, and u converges at
       first order (error ratios 2).
    2. The volume balance in a closed box (walls), a cap released on the
       plane over an erodible layer of 0.2 m with a gap: sum (h + layer)
       dA conserved to round-off (relative 1e-13), layer >= 0, h >= 0,
       erodedVolume = the layer's loss; in slope coordinates and on the
       plan grid (a tilted DEM, H = J h per plan area); for every model
       but none (constantRate 0.05 m/s; frontal phi_b 25 deg, where the
       bed at 30 deg is unstable by itself and fails under the thin parts
       of the flow; erosionEnergy e_b 100 J/kg); each run again with h,
       the layer and (plan) the bed perturbed by round-off, times 1 + k
       eps with k in -4..4 per cell, under the same bounds.
    3. Resistance only (cResistance c, Coulomb delta 20 deg): the uniform
       layer from rest reaches the terminal speed u_t = sqrt(S/c) of
       du/dt = S - c u^2, u = u_t tanh(sqrt(S c) t).  u(5 s) at fixed dt
       0.02, 0.01, 0.005 s: the drag's step u_{n+1} = u_n + dt (S - c u_n
       u_{n+1}) is second order (u_n u_{n+1} = u(t + dt/2)^2 + O(dt^2)),
       asserted: halving dt divides the error by 4 (within [3.8, 4.2];
       measured 4.0000), and the Richardson extrapolation (4 u(dt/2) -
       u(dt))/3 is the tanh to 1e-3 of the error at dt 0.005 (measured
       8e-13 against 9e-7).  At t = 120 s (CFL steps) u = u_t: a, slope
       coordinates, to 1e-12 relative (the implicit drag's fixed point is
       the model's); b, the plan grid's plane turned by 30 deg and along
       X (3D speed), to 1e-9 in every cell, since the open sides of the
       DEM's plane let h drift (1.7e-7 turned, 2e-9 along X, asserted
       below 1e-6), moving the speed by 4e-10, 3e-12.  A J in the
       resistance's thickness (c H for c h) fails b.
    3c. The drag on the plan grid step by step against slope
       coordinates, with resistance 0.01 1/m and a law that reaches the
       J of the thickness: Voellmy (mu 0.2, xi 500; the drag k/h with
       h = H/J of the corrector) and Pouliquen-Forterre (L 0.2 m; mu of
       the predictor's speed, so the predictor's drag cellDrag(...,
       H/J) reaches the corrector), the uniform layer h 1 m, u0 5 m/s
       on the plane turned 30 deg and along X: the 3D speed and h of
       every cell those of the slope run after every one of 250 steps of
       0.02 s, to 1e-12 relative per step.
    4. Nothing changes without a model and resistance: a run given a
       layer with entrainmentModel none, and one given cResistance 0
       everywhere, write h, hu, hv bit for bit those of the plain run.
    6. frontal (Medina et al. 2008) on a plane of 20 deg, bed phi_b 25
       deg, cohesion c, a uniform layer h0 0.5 m, u0 10 m/s under Coulomb
       delta 27 deg (decelerating, still moving after the 40 steps of
       0.01 s): the bed fails to e = k h - c/D, k = g cos(zeta) (tan delta
       - tan phi_b)/D, D = g (cos(zeta) tan phi_b - sin(zeta)), and the
       cell takes up e - eroded each step, so the eroded depth after step
       n is E_n = (k h0 - c/D)(1 - k^n)/(1 - k) (E_{n+1} = k (h0 + E_n) -
       c/D): asserted to 1e-12 relative at every step, the first step's
       E_1 = min(layer, e(h0)) with a thick and a thin layer.  On a plane
       of 30 deg > phi_b (D < 0, delta 27) the layer's base decides: the
       whole layer goes in the first step where N - D L >= 0 (L 0.5 m),
       none where not (L 0.2 m), N = tau_b - c - tan(phi_b) g_n h0.
    7. erosionEnergy (AvaFrame com1DFA) on the plane of 1., e_b 100 J/kg:
       dh/dt = a h u, d(hu)/dt = S h, a = tan(delta) g cos(zeta)/e_b, so
       h = h0 cosh(w t) + (a m0/w) sinh(w t), m = m0 cosh(w t) + (w h0/a)
       sinh(w t), w = sqrt(a S).  The scheme takes up after the corrector:
       m_{n+1} = m_n + S h_n dt, h_{n+1} = h_n + a m_{n+1} dt (symplectic
       Euler), replayed here: h, hu equal it to 1e-12 relative at fixed
       dt 0.01 s to t = 4 s; against the exact solution the error is
       first order (halving dt divides it by 2, within [1.8, 2.2]) and
       below 1e-2 relative.  The critical shear stress: nothing taken
       where tau_b <= tau_c, tau_b |u| dt/e_b above.
    5. Bad input refused: a negative layer or resistance (InputError
       naming hEntrainable / cResistance), every model's edge cases
       (accepted or refused, naming the keyword), each model's worked
       examples.
\*---------------------------------------------------------------------------*/

#include "../common/testing.H"
#include "physics/entrainment.H"

#include <cstring>
#include <limits>

using namespace sh;
using namespace shtest;

namespace
{

constexpr double pi = 3.14159265358979323846;

//- printf into a string, for the checks' lines
template<class... A>
std::string say(const char* f, A... a)
{
    char buf[512];
    std::snprintf(buf, sizeof buf, f, a...);
    return buf;
}
constexpr double deg = pi/180.0;

ModelInput planeInput()
{
    ModelInput in;
    in.g = 9.81;
    in.phiDeg = 35;
    in.frictionLaw = FrictionLaw::Coulomb;
    in.coulomb.deltaDeg = 20;
    in.cfl = 0.4;
    return in;
}

double slopeAcceleration(const ModelInput& in, double zetaDeg)
{
    return in.g*(std::sin(zetaDeg*deg) - std::tan(in.coulomb.deltaDeg*deg)*std::cos(zetaDeg*deg));
}

//- A uniform layer h0, u0 on a plane of zeta, open sides, 8 x 8 cells of 1 m
Problem<double> uniformLayer(const ModelInput& in, double zetaDeg, double h0, double u0)
{
    Problem<double> pb(makeParams<double>(in), 8, 8, 0, 8, 0, 8);
    pb.setInclination([&](double) { return zetaDeg*deg; });
    pb.setState([&](double, double) { return Primitive{h0, u0, 0}; });
    return pb;
}

double mean(const std::vector<double>& a)
{
    double s = 0;
    for (double x : a) { s += x; }
    return s/double(a.size());
}

//- The plan grid's tilted plane (ModelInput::coordinates plan): the DEM
//  b = -tan(zeta) (X cos(psi) + Y sin(psi)), falling along the plan
//  direction psi, open sides, 12 x 12 cells of 1 m; a uniform layer of
//  normal thickness h0 (H = J h0 per plan area, J = 1/cos(zeta)) moving
//  down the slope at the 3D speed u0: plan components u0 cos(zeta)
//  (cos(psi), sin(psi))
struct PlanPlane
{
    double zeta, psi;       //!< [rad]
    double J() const { return 1/std::cos(zeta); }
    double p() const { return -std::tan(zeta)*std::cos(psi); }
    double q() const { return -std::tan(zeta)*std::sin(psi); }
    //- The 3D speed of plan velocity (u, v): sqrt(u^2 + v^2 + w^2), w =
    //  p u + q v
    double speed(double u, double v) const
    {
        const double w = p()*u + q()*v;
        return std::sqrt(u*u + v*v + w*w);
    }
    //- Off the line of steepest descent in plan [rad]
    double turn(double u, double v) const { return std::atan2(v, u) - psi; }
};

Problem<double> planLayer(ModelInput in, const PlanPlane& pl, double h0, double u0)
{
    in.coordinates = Coordinates::plan;
    Problem<double> pb(makeParams<double>(in), 12, 12, -6, 6, -6, 6);
    for (int s = 0; s < 4; ++s) { pb.bc.type[s] = BCType::transmissive; }
    pb.setTopography([&](double x, double y) { return -std::tan(pl.zeta)*(x*std::cos(pl.psi) + y*std::sin(pl.psi)); });
    const double uh = u0*std::cos(pl.zeta);
    pb.setState([&](double, double) { return Primitive{pl.J()*h0, uh*std::cos(pl.psi), uh*std::sin(pl.psi)}; });
    return pb;
}

//- The layer of a run in the bed's measures, over all cells: the normal
//  thickness h (= H/J), the 3D speed and h times it, the direction in plan
//  off the descent, and the spread of h and speed over the cells
struct Bedwise
{
    double h, speed, m, turn, spread;
};

Bedwise bedwise(CpuSolver<double>& s, const PlanPlane* pl)
{
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    const double J = pl ? pl->J() : 1.0;
    Bedwise b{0, 0, 0, 0, 0};
    double hMin = 1e300, hMax = -1e300, sMin = 1e300, sMax = -1e300;
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        const double u = hu[c]/h[c], v = hv[c]/h[c];
        const double sp = pl ? pl->speed(u, v) : std::sqrt(u*u + v*v);
        const double hn = h[c]/J;
        b.h += hn/double(h.size());
        b.speed += sp/double(h.size());
        b.turn = std::max(b.turn, pl ? std::fabs(pl->turn(u, v)) : std::fabs(v));
        hMin = std::min(hMin, hn); hMax = std::max(hMax, hn);
        sMin = std::min(sMin, sp); sMax = std::max(sMax, sp);
    }
    b.m = b.h*b.speed;
    b.spread = std::max((hMax - hMin)/hMax, sMax > 0 ? (sMax - sMin)/sMax : 0.0);
    return b;
}

//- Test 1 in slope coordinates (pl null) or on the plan grid's plane pl
void constantRateRun(Counter& test, const PlanPlane* pl)
{
    ModelInput in = planeInput();
    in.entrainmentModel = EntrainmentModel::ConstantRate;
    in.constantRate.rate = 0.02;
    const double zeta = 30, h0 = 0.5, u0 = 2, r = in.constantRate.rate, L0 = 10;
    const double J = pl ? pl->J() : 1.0;
    const std::string tag = pl ? say("1b. plan grid, descent turned %g deg: ", pl->psi/deg) : "1a. ";
    Problem<double> pb = pl ? planLayer(in, *pl, h0, u0) : uniformLayer(in, zeta, h0, u0);
    // The layer in the state's measure: J L0 per plan area
    pb.hEntrainable.assign(pb.nCells(), J*L0);
    const double S = slopeAcceleration(in, zeta);
    CpuSolver<double> s(pb, false);
    if (pl)
    {
        std::printf("  plan grid, plane of 30 deg falling along %g deg in plan, J = %.15f, H0 = J h0, layer J %g m\n",
            pl->psi/deg, J, L0);
    }
    else
    {
        std::printf("  slope coordinates\n");
    }
    std::printf("  %6s %6s %14s %14s %12s %14s %14s %12s %12s %14s %14s %10s\n", "t", "steps", "h = H/J",
        "h exact", "err h", "h |u|", "exact", "err h |u|", "bound", "eroded/J", "layer/J", "spread");
    double dtMax = 0, worstH = 0, worstE = 0, worstL = 0, worstHJ = 0, spread = 0, turn = 0;
    bool hOk = true, huOk = true, uniform = true, coverOk = true;
    for (double t : {1.0, 2.0, 4.0})
    {
        // The CFL step shrinks as the layer speeds up and thickens: the
        // largest is that of the interval's start
        dtMax = std::max(dtMax, double(s.stableDt()));
        s.advanceTo(t);
        std::vector<double> H, hu, hv, layer, eroded;
        s.getState(H, hu, hv);
        s.getCover(layer, eroded);
        if (!pl)
        {
            for (std::size_t c = 0; c < H.size(); ++c)
            {
                uniform = uniform && H[c] == H[0] && hu[c] == hu[0] && hv[c] == 0;
            }
        }
        const Bedwise b = bedwise(s, pl);
        spread = std::max(spread, b.spread);
        turn = std::max(turn, b.turn);
        const double hEx = h0 + r*t;
        const double huEx = h0*u0 + S*(h0*t + 0.5*r*t*t);
        // The left sum's defect, S r sum dt^2/2 <= S r t dtMax/2
        const double bound = 0.5*S*r*t*dtMax + 1e-12*huEx;
        // Per cell: H = J (h0 + r t) (the depth r dt normal to the bed is
        // J r dt per plan area), eroded J r t, layer J (L0 - r t)
        const double tol = 1e-12*double(s.steps());
        for (std::size_t c = 0; c < H.size(); ++c)
        {
            worstHJ = std::max(worstHJ, std::fabs(H[c] - J*hEx)/(J*hEx));
            worstE = std::max(worstE, std::fabs(eroded[c] - J*r*t)/(J*r*t));
            worstL = std::max(worstL, std::fabs(layer[c] - J*(L0 - r*t))/(J*(L0 - r*t)));
        }
        worstH = std::max(worstH, std::fabs(b.h - hEx)/hEx);
        std::printf("  %6.1f %6ld %14.10f %14.10f %12.3e %14.10f %14.10f %12.3e %12.3e %14.10f %14.10f %10.2e\n",
            t, s.steps(), b.h, hEx, b.h - hEx, b.m, huEx, b.m - huEx, bound, mean(eroded)/J, mean(layer)/J, b.spread);
        hOk = hOk && std::fabs(b.h - hEx) <= tol*hEx && worstHJ <= tol;
        coverOk = coverOk && worstE <= tol && worstL <= tol;
        huOk = huOk && b.m <= huEx + 1e-12*huEx && huEx - b.m <= bound;
    }
    if (pl)
    {
        // Not to the bit: the DEM's slopes per cell differ in round-off,
        // and the open sides amplify it (the spread printed); every cell's
        // H is held to round-off per step below
        test.check(turn <= 1e-12,
            tag + say("the layer moves along the descent (%.2e rad off it; spread of h, |u| over the cells %.2e)",
                turn, spread));
    }
    else
    {
        test.check(uniform, tag + "the layer stays uniform to the bit (h, hu equal in every cell, hv = 0)");
    }
    test.check(hOk, tag + say("h = H/J = h0 + r t normal to the bed, and H = J (h0 + r t) in every cell, to round-off "
        "(1e-12 relative per step; worst %.2e, %.2e)", worstH, worstHJ));
    test.check(huOk, tag + "h |u| below the exact h0 u0 + S (h0 t + r t^2/2) by at most S r t dtMax/2");
    test.check(coverOk, tag + say("eroded depth J r t and layer J (L0 - r t) per plan area in every cell, to round-off "
        "(worst relative %.2e, %.2e)", worstE, worstL));
}

//- Test 1c: the same layer at fixed dt to t = 4 s, its speed u = hu/h
//  against the exact u(t) = (h0 u0 + S (h0 t + r t^2/2))/(h0 + r t).  At
//  fixed dt the left sum is S (h0 t + r t (t - dt)/2) exactly, so hu
//  equals that to round-off and the error of u is S r t dt/(2 h): first
//  order, halving dt halves it
void constantRateSpeed(Counter& test)
{
    const double zeta = 30, h0 = 0.5, u0 = 2, t = 4;
    ModelInput in = planeInput();
    in.entrainmentModel = EntrainmentModel::ConstantRate;
    in.constantRate.rate = 0.02;
    const double r = in.constantRate.rate, S = slopeAcceleration(in, zeta);
    const double hEx = h0 + r*t, uEx = (h0*u0 + S*(h0*t + 0.5*r*t*t))/hEx;
    std::printf("  1c. fixed dt to t = %g s: exact h %.10f, u %.10f m/s\n", t, hEx, uEx);
    std::printf("  %8s %14s %14s %14s %12s %12s\n", "dt", "h", "u = hu/h", "u left sum", "err u", "|hu - sum|");
    const double dts[3] = {0.02, 0.01, 0.005};
    double err[3];
    bool sumOk = true, hOk = true;
    for (int i = 0; i < 3; ++i)
    {
        Problem<double> pb = uniformLayer(in, zeta, h0, u0);
        pb.hEntrainable.assign(pb.nCells(), 10.0);
        CpuSolver<double> s(pb, false);
        const int n = int(std::lround(t/dts[i]));
        for (int k = 0; k < n; ++k)
        {
            s.step(dts[i]);
        }
        std::vector<double> hs, hu, hv;
        s.getState(hs, hu, hv);
        const double sum = h0*u0 + S*(h0*t + 0.5*r*t*(t - dts[i]));
        const double dev = std::fabs(hu[0] - sum)/sum;
        err[i] = std::fabs(hu[0]/hs[0] - uEx)/uEx;
        std::printf("  %8g %14.10f %14.10f %14.10f %12.3e %12.3e\n", dts[i], hs[0], hu[0]/hs[0], sum/hs[0], err[i], dev);
        sumOk = sumOk && dev <= 1e-12;
        hOk = hOk && std::fabs(hs[0] - hEx) <= 1e-12*hEx;
    }
    test.check(hOk, "1c. h = h0 + r t at every dt, to 1e-12 relative");
    test.check(sumOk, "1c. hu = h0 u0 + S (h0 t + r t (t - dt)/2), the left sum at fixed dt, to 1e-12 relative");
    const double r1 = err[0]/err[1], r2 = err[1]/err[2];
    test.check(err[2] < 1e-3 && r1 >= 1.9 && r1 <= 2.1 && r2 >= 1.9 && r2 <= 2.1,
        say("1c. u(t) converges to the exact speed at first order: errors %.2e %.2e %.2e, ratios %.3f %.3f "
            "within [1.9, 2.1]", err[0], err[1], err[2], r1, r2));
}

void constantRate(Counter& test)
{
    std::printf("\n1. uniform layer with constantRate r 0.02 m/s, zeta 30, delta 20, h0 0.5 m, u0 2 m/s, layer 10 m\n");
    constantRateRun(test, nullptr);
    const PlanPlane turned{30*deg, 30*deg};
    constantRateRun(test, &turned);
    constantRateSpeed(test);
}

struct Balance
{
    double v0, v1, layerMin, hMin, erodedVol, layerLoss;
};

//- A relative round-off perturbation, k eps with k in -4..4, from a hash
//  of the integers a, b (a cell's indices, a field's number)
double roundOff(int a, int b)
{
    const unsigned x = (unsigned(a)*2654435761u) ^ (unsigned(b)*40503u + 977u);
    return double(int((x >> 7) % 9u) - 4)*std::numeric_limits<double>::epsilon();
}

//- The closed box of test 2; `perturb`: h, the layer and (plan) the bed
//  each times 1 + k eps, k in -4..4 per cell (roundOff)
Balance boxRun(ModelInput in, bool plan, bool perturb = false)
{
    const double wiggle = perturb ? 1.0 : 0.0;
    const double zeta = 30;
    if (plan)
    {
        in.coordinates = Coordinates::plan;
    }
    Problem<double> pb(makeParams<double>(in), 40, 20, 0, 40, -10, 10);
    for (int s = 0; s < 4; ++s) { pb.bc.type[s] = BCType::wall; }
    const double tz = std::tan(zeta*deg);
    if (plan)
    {
        pb.setTopography([&](double x, double y)
        {
            return -tz*x*(1 + wiggle*roundOff(int(std::floor(x*7)), int(std::floor(y*7)) + 3));
        });
    }
    else
    {
        pb.setInclination([&](double) { return zeta*deg; });
    }
    // J = 1/cos(zeta) on the plan grid's tilted plane: H = J h
    const double J = plan ? 1/std::cos(zeta*deg) : 1.0;
    pb.setState([&](double x, double y)
    {
        const double r2 = ((x - 8)*(x - 8) + y*y)/16.0;
        const double p = 1 + wiggle*roundOff(int(std::floor(x)), int(std::floor(y)) + 100);
        return Primitive{J*std::max(0.0, 1 - r2)*p, 0, 0};
    });
    pb.hEntrainable.assign(pb.nCells(), 0.0);
    for (int j = 0; j < 20; ++j)
    {
        for (int i = 0; i < 40; ++i)
        {
            // a layer downslope of the cap, with a gap of bare bed
            const bool covered = i >= 12 && !(i >= 20 && i < 24);
            pb.hEntrainable[pb.cell(i, j)] = covered ? J*0.2*(1 + wiggle*roundOff(i, j + 200)) : 0.0;
        }
    }
    CpuSolver<double> s(pb, false);
    const Diagnostics d0 = s.diagnostics();
    s.advanceTo(6.0);
    const Diagnostics d1 = s.diagnostics();
    std::vector<double> h, hu, hv, layer, eroded;
    s.getState(h, hu, hv);
    s.getCover(layer, eroded);
    Balance b{d0.volume + d0.layerVolume, d1.volume + d1.layerVolume,
              *std::min_element(layer.begin(), layer.end()),
              *std::min_element(h.begin(), h.end()),
              d1.erodedVolume, d0.layerVolume - d1.layerVolume};
    std::printf("  %-13s %-27s volume %.6f -> %.6f m^3, layer %.6f -> %.6f m^3, eroded %.6f m^3, steps %ld\n",
        toString(in.entrainmentModel).c_str(),
        (std::string(plan ? "plan grid" : "slope coordinates") + (perturb ? ", perturbed" : "")).c_str(),
        d0.volume, d1.volume, d0.layerVolume,
        d1.layerVolume, d1.erodedVolume, s.steps());
    return b;
}

//- The models' coefficients of the box run (2.)
ModelInput boxInput(EntrainmentModel e)
{
    ModelInput in = planeInput();
    in.entrainmentModel = e;
    in.constantRate.rate = 0.05;
    in.frontal.bedFrictionAngleDeg = 25;
    in.erosionEnergy.erosionEnergy = 100;
    return in;
}

void volumeBalance(Counter& test)
{
    std::printf("\n2. closed box, a cap over an erodible layer of 0.2 m, t = 0..6 s\n");
    forEachEntrainmentModel([&](auto model)
    {
        const EntrainmentModel e = entrainmentModelOf(model);
        if (e == EntrainmentModel::NoEntrainment) { return; }
        for (int run = 0; run < 4; ++run)
        {
            const bool plan = run % 2, perturb = run >= 2;
            const Balance b = boxRun(boxInput(e), plan, perturb);
            const std::string name = std::string(plan ? "2b. plan grid, " : "2a. slope coordinates, ")
                + (perturb ? "input perturbed by round-off, " : "") + toString(e);
            const double rel = std::fabs(b.v1 - b.v0)/b.v0;
            test.check(rel <= 1e-13, name + say(": flowing + erodible volume conserved (relative change %.2e <= 1e-13)", rel));
            test.check(b.layerMin >= 0 && b.hMin >= 0, name + ": layer and h never negative");
            test.check(b.erodedVol > 0.1 && std::fabs(b.erodedVol - b.layerLoss) <= 1e-12*b.v0,
                name + say(": material was entrained (%.4f m^3) and the eroded volume is the layer's loss", b.erodedVol));
        }
    });
}

//- Test 3's layer (h 1 m from rest, cResistance c): slope coordinates
//  (pl null) or the plan grid's plane pl
Problem<double> resistanceLayer(const PlanPlane* pl, double c)
{
    const ModelInput in = planeInput();
    Problem<double> pb = pl ? planLayer(in, *pl, 1.0, 0.0) : uniformLayer(in, 30, 1.0, 0.0);
    pb.cResistance.assign(pb.nCells(), c);
    return pb;
}

//- The 3D speed at t = 5 s after 5/dt steps of dt
double speedAt5(const PlanPlane* pl, double c, double dt)
{
    CpuSolver<double> s(resistanceLayer(pl, c), false);
    const int n = int(std::lround(5.0/dt));
    for (int k = 0; k < n; ++k) { s.step(dt); }
    return bedwise(s, pl).speed;
}

void resistanceRun(Counter& test, const PlanPlane* pl)
{
    const ModelInput in = planeInput();
    const double zeta = 30, c = 0.01;
    const std::string tag = pl ? say("3b. plan grid, descent turned %g deg: ", pl->psi/deg) : "3a. ";
    const double S = slopeAcceleration(in, zeta);
    const double ut = std::sqrt(S/c), w = std::sqrt(S*c);
    const double ex5 = ut*std::tanh(w*5.0);
    std::printf("  %s: u_t = sqrt(S/c) = %.12f m/s, u(5 s) = u_t tanh(sqrt(S c) 5 s) = %.12f m/s\n",
        pl ? say("plan grid, descent turned %g deg, J %.6f", pl->psi/deg, pl->J()).c_str() : "slope coordinates",
        ut, ex5);

    // The corrector takes m'' from m + dt S h with the drag c h |u0| u''
    // (friction.H applyBasalFriction: (|u0| u'' + |u''| u0)/2 = u0 u''
    // along a line), i.e. u_{n+1} = u_n + dt (S - c u_n u_{n+1}); u_n u_{n+1}
    // = u(t + dt/2)^2 + O(dt^2), so the step is consistent with the
    // midpoint rule to O(dt^3) and the error at a fixed time is second
    // order: halving dt divides it by 4.  The uniform layer's predictor
    // does not reach the corrector (no flux differences, Coulomb's mu
    // independent of the speed), so nothing first order enters.  Fixed
    // steps below the CFL step (0.036 s at 5 s).
    std::printf("  %8s %18s %12s %10s\n", "dt", "u(5 s)", "err", "ratio");
    const double dts[3] = {0.02, 0.01, 0.005};
    double u[3], err[3];
    bool order = true;
    for (int i = 0; i < 3; ++i)
    {
        u[i] = speedAt5(pl, c, dts[i]);
        err[i] = u[i] - ex5;
        const double ratio = i > 0 ? err[i - 1]/err[i] : 0;
        std::printf("  %8g %18.12f %12.3e %10s\n", dts[i], u[i], err[i], i > 0 ? say("%.4f", ratio).c_str() : "-");
        order = order && err[i] != 0 && (i == 0 || (ratio >= 3.8 && ratio <= 4.2));
    }
    // Richardson: (4 u(dt/2) - u(dt))/3 removes the dt^2 term
    const double rich = (4*u[2] - u[1])/3, errRich = std::fabs(rich - ex5);
    std::printf("  Richardson (4 u(0.005) - u(0.01))/3 = %.12f, error %.3e (u(0.005)'s %.3e)\n",
        rich, errRich, std::fabs(err[2]));
    test.check(order, tag + say("u(5 s) second order in dt towards u_t tanh(sqrt(S c) t): halving dt divides the "
        "error by %.4f, %.4f (within [3.8, 4.2])", err[0]/err[1], err[1]/err[2]));
    // The ratios 4.000 to four digits put the dt^3 remainder below 1e-4
    // of the dt^2 term: the extrapolation is the tanh to 1e-3 of the
    // error at dt 0.005 -- the limit is the model's u_t tanh(sqrt(S c) t)
    test.check(errRich <= 1e-3*std::fabs(err[2]),
        tag + say("the Richardson extrapolation of u(5 s) is u_t tanh(sqrt(S c) t) to %.2e (<= 1e-3 of the error "
            "at dt 0.005)", errRich));

    CpuSolver<double> s(resistanceLayer(pl, c), false);
    s.advanceTo(120.0);
    const Bedwise b = bedwise(s, pl);
    std::printf("  t = 120 s (CFL steps): u %.12f, u_t %.12f (rel %.2e), spread over the cells %.2e, off the descent %.2e\n",
        b.speed, ut, std::fabs(b.speed - ut)/ut, b.spread, b.turn);
    if (!pl)
    {
        test.check(std::fabs(b.speed - ut) <= 1e-12*ut && b.spread == 0 && b.turn == 0,
            tag + "the terminal speed sqrt(S/c) to 1e-12 relative, the same in every cell");
        return;
    }
    // On the plan grid the open sides of the DEM's plane are not exactly
    // uniform: H drifts at the boundary faces (-2e-9 relative over 120 s
    // along X, -1.7e-7 on the turned plane; the scheme's sides, not the
    // drag), and the pressure of that gradient moves the speed by 3e-12,
    // 4e-10.  Asserted: the drift below 1e-6 and the speed to 1e-9; a J
    // of the resistance's thickness (c J h for c h) would move it by
    // J^(1/2) - 1 = 7 %, and the 5 s checks above hold it to 1e-12.
    std::vector<double> H, hu, hv;
    s.getState(H, hu, hv);
    double drift = 0, worst = 0;
    for (std::size_t k = 0; k < H.size(); ++k)
    {
        drift = std::max(drift, std::fabs(H[k]/pl->J() - 1));
        worst = std::max(worst, std::fabs(pl->speed(hu[k]/H[k], hv[k]/H[k]) - ut)/ut);
    }
    std::printf("  largest drift of h = H/J from 1 m: %.2e; worst cell's speed off u_t: %.2e\n", drift, worst);
    test.check(worst <= 1e-9 && b.turn <= 1e-9 && drift <= 1e-6,
        tag + say("the terminal speed sqrt(S/c) to 1e-9 relative in every cell (worst %.2e), along the "
            "descent (%.2e rad), h drift %.2e <= 1e-6", worst, b.turn, drift));
}

void resistance(Counter& test)
{
    std::printf("\n3. resistance only, c = 0.01 1/m, zeta 30, delta 20, h 1 m from rest\n");
    resistanceRun(test, nullptr);
    const PlanPlane turned{30*deg, 30*deg};
    resistanceRun(test, &turned);
    const PlanPlane along{30*deg, 0};
    resistanceRun(test, &along);
}

//- 3c: the drag of a friction law with resistance on the plan grid, step
//  by step against slope coordinates: the uniform layer h 1 m, u0 5 m/s
//  on the plane of 30 deg (turned 30 deg in plan and along X) and in
//  slope coordinates, fixed dt 0.02 s, 250 steps; the 3D speed and h =
//  H/J of every cell against the slope run's after every step
void resistanceLaws(Counter& test)
{
    std::printf("\n3c. friction laws with a drag or a speed-dependent mu, cResistance 0.01 1/m, zeta 30, h 1 m, "
        "u0 5 m/s, 250 steps of 0.02 s: plan grid against slope coordinates\n");
    struct Law { const char* name; ModelInput in; };
    std::vector<Law> laws(2);
    laws[0].name = "Voellmy mu 0.2, xi 500";
    laws[0].in = planeInput();
    laws[0].in.frictionLaw = FrictionLaw::Voellmy;
    laws[0].in.voellmy.mu = 0.2;
    laws[0].in.voellmy.xi = 500;
    laws[1].name = "Pouliquen-Forterre L 0.2";
    laws[1].in = planeInput();
    laws[1].in.frictionLaw = FrictionLaw::PouliquenForterre;
    laws[1].in.pouliquenForterre.L = 0.2;
    for (Law& l : laws) { l.in.earthPressure = EarthPressureModel::isotropic; }
    const double c = 0.01, dt = 0.02;
    for (const Law& law : laws)
    {
        for (double psiDeg : {30.0, 0.0})
        {
            const PlanPlane pl{30*deg, psiDeg*deg};
            Problem<double> sp = uniformLayer(law.in, 30, 1.0, 5.0);
            Problem<double> pp = planLayer(law.in, pl, 1.0, 5.0);
            sp.cResistance.assign(sp.nCells(), c);
            pp.cResistance.assign(pp.nCells(), c);
            CpuSolver<double> ss(sp, false), ps(pp, false);
            double worstU = 0, worstH = 0;
            for (int n = 0; n < 250; ++n)
            {
                ss.step(dt);
                ps.step(dt);
                const double us = bedwise(ss, nullptr).speed, hs = bedwise(ss, nullptr).h;
                std::vector<double> H, hu, hv;
                ps.getState(H, hu, hv);
                for (std::size_t k = 0; k < H.size(); ++k)
                {
                    worstU = std::max(worstU, std::fabs(pl.speed(hu[k]/H[k], hv[k]/H[k]) - us)/us);
                    worstH = std::max(worstH, std::fabs(H[k]/pl.J() - hs)/hs);
                }
            }
            std::printf("  %-26s turned %2.0f deg: u(5 s) slope %.12f, plan %.12f; worst relative difference "
                "over cells and steps: speed %.2e, h %.2e\n", law.name, psiDeg, bedwise(ss, nullptr).speed,
                bedwise(ps, &pl).speed, worstU, worstH);
            // Round-off, 1e-12 relative per step as in 1.: the two grids
            // round differently (the DEM's slopes per cell, J), and the
            // turned plane's open sides amplify it (3b)
            const double tol = 1e-12*250;
            test.check(worstU <= tol && worstH <= tol,
                say("3c. %s, plan grid turned %g deg: the 3D speed and h of every cell those of slope coordinates "
                    "after every step, to round-off (1e-12 relative per step: %.1e; worst %.2e, %.2e)", law.name,
                    psiDeg, tol, worstU, worstH));
        }
    }
}

std::vector<double> plainRun(const Problem<double>& pb)
{
    CpuSolver<double> s(pb, false);
    s.advanceTo(3.0);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    h.insert(h.end(), hu.begin(), hu.end());
    h.insert(h.end(), hv.begin(), hv.end());
    return h;
}

void unchanged(Counter& test)
{
    std::printf("\n4. without a model and with zero resistance nothing changes\n");
    const ModelInput in = planeInput();
    Problem<double> pb(makeParams<double>(in), 30, 16, 0, 30, -8, 8);
    pb.setInclination([](double) { return 35*deg; });
    pb.setState([](double x, double y)
    {
        return Primitive{std::max(0.0, 1 - ((x - 6)*(x - 6) + y*y)/9.0), 0, 0};
    });
    const std::vector<double> ref = plainRun(pb);
    Problem<double> a = pb;
    a.hEntrainable.assign(a.nCells(), 0.3);
    Problem<double> b = pb;
    b.cResistance.assign(b.nCells(), 0.0);
    const std::vector<double> ra = plainRun(a), rb = plainRun(b);
    test.check(ra.size() == ref.size() && std::memcmp(ra.data(), ref.data(), ref.size()*sizeof(double)) == 0,
        "4. a layer with entrainmentModel none: h, hu, hv bit for bit the plain run's");
    test.check(rb.size() == ref.size() && std::memcmp(rb.data(), ref.data(), ref.size()*sizeof(double)) == 0,
        "4. cResistance 0 everywhere: bit for bit the plain run's");
}

template<class F>
bool refused(F&& f, const std::string& keyword)
{
    try { f(); }
    catch (const InputError& e) { return e.keyword() == keyword; }
    return false;
}

void badInput(Counter& test)
{
    std::printf("\n5. bad input\n");
    ModelInput in = planeInput();
    in.entrainmentModel = EntrainmentModel::ConstantRate;
    Problem<double> pb = uniformLayer(in, 30, 0.5, 1);
    Problem<double> a = pb;
    a.hEntrainable.assign(a.nCells(), 0.1);
    a.hEntrainable[5] = -1e-3;
    test.check(refused([&]() { CpuSolver<double> s(a, false); }, "hEntrainable"),
        "5. a negative erodible thickness refused, naming hEntrainable");
    Problem<double> b = pb;
    b.cResistance.assign(b.nCells(), 0.01);
    b.cResistance[3] = std::nan("");
    test.check(refused([&]() { CpuSolver<double> s(b, false); }, "cResistance"),
        "5. a NaN resistance refused, naming cResistance");
    Problem<double> c = pb;
    c.hEntrainable.assign(3, 0.1);
    test.check(refused([&]() { CpuSolver<double> s(c, false); }, "hEntrainable"),
        "5. a layer of the wrong size refused");
    forEachEntrainmentModel([&](auto model)
    {
        using M = decltype(model);
        for (const auto& e : M::edgeCases)
        {
            ModelInput mi = planeInput();
            mi.entrainmentModel = entrainmentModelOf(model);
            for (const auto& k : M::coefficients)
            {
                if (std::string(k.keyword) == e.keyword) { mi.of(model).*k.value = e.value; }
            }
            bool ok = true;
            try { makeParams<double>(mi); }
            catch (const InputError& err) { ok = false; test.check(!e.accepted && err.keyword() == e.keyword,
                say("5. %s %s: ", M::name, e.name) + err.what()); }
            if (ok) { test.check(e.accepted, say("5. %s %s %g accepted", M::name, e.name, e.value)); }
        }
        for (const auto& x : M::examples)
        {
            const Params<double> p = makeParams<double>([&]()
            {
                ModelInput mi = planeInput();
                mi.entrainmentModel = entrainmentModelOf(model);
                return mi;
            }());
            const EntrainmentState<double> st{x.h, x.speed, x.tauB, x.gn, x.cosTheta, x.eroded, x.dt, x.layer};
            const double d = entrainmentDepth(p.entrainment, st);
            test.check(std::fabs(d - x.depth) <= 1e-12*std::max(1.0, std::fabs(x.depth)),
                say("5. %s example (%s): depth %.6g, expected %.6g", M::name, x.what, d, x.depth));
        }
    });
}

//- The frontal model's first moving step on a uniform layer: the eroded
//  depth of the cells after one step of dt (-1 if they differ)
double frontalFirstStep(const ModelInput& in, double zeta, double h0, double u0, double layer)
{
    Problem<double> pb = uniformLayer(in, zeta, h0, u0);
    pb.hEntrainable.assign(pb.nCells(), layer);
    CpuSolver<double> s(pb, false);
    s.step(0.01);
    std::vector<double> l, e;
    s.getCover(l, e);
    for (double x : e)
    {
        if (x != e[0]) { return -1; }   // not uniform: fails every check
    }
    return e[0];
}

void frontal(Counter& test)
{
    const double zeta = 20, h0 = 0.5, u0 = 10, c = 0.05, dt = 0.01;
    ModelInput in = planeInput();
    in.coulomb.deltaDeg = 27;
    in.entrainmentModel = EntrainmentModel::FrontalEntrainment;
    in.frontal.bedFrictionAngleDeg = 25;
    in.frontal.cohesion = c;
    const double tp = std::tan(25*deg), cz = std::cos(zeta*deg), sz = std::sin(zeta*deg);
    const double D = in.g*(cz*tp - sz);
    const double k = in.g*cz*(std::tan(27*deg) - tp)/D;
    const double e0 = k*h0 - c/D;
    std::printf("\n6. frontal: zeta %g, phi_b 25, delta 27, cohesion %g m^2/s^2, h0 %g m, u0 %g m/s, dt %g s\n"
        "   D = %.12f m/s^2, k = %.12f, e(h0) = %.12f m, E_inf = %.12f m\n",
        zeta, c, h0, u0, dt, D, k, e0, e0/(1 - k));
    Problem<double> pb = uniformLayer(in, zeta, h0, u0);
    pb.hEntrainable.assign(pb.nCells(), 10.0);
    CpuSolver<double> s(pb, false);
    test.check(dt <= s.stableDt(), say("6. dt %g within the CFL step %g", dt, double(s.stableDt())));
    std::printf("  %4s %16s %16s %10s %12s %10s\n", "n", "E_n", "closed form", "rel err", "h", "u");
    bool ok = true, uniform = true, moving = true, volume = true;
    double worst = 0;
    for (int n = 1; n <= 40; ++n)
    {
        s.step(dt);
        std::vector<double> h, hu, hv, layer, eroded;
        s.getState(h, hu, hv);
        s.getCover(layer, eroded);
        for (std::size_t i = 0; i < h.size(); ++i)
        {
            uniform = uniform && h[i] == h[0] && eroded[i] == eroded[0] && hv[i] == 0;
        }
        const double En = e0*(1 - std::pow(k, n))/(1 - k);
        const double rel = std::fabs(eroded[0] - En)/En;
        worst = std::max(worst, rel);
        ok = ok && rel <= 1e-12;
        moving = moving && hu[0] > 0;
        volume = volume && std::fabs(h[0] + layer[0] - (h0 + 10.0)) <= 1e-13*(h0 + 10.0);
        if (n <= 5 || n % 10 == 0)
        {
            std::printf("  %4d %16.12f %16.12f %10.2e %12.9f %10.6f\n", n, eroded[0], En, rel, h[0], hu[0]/h[0]);
        }
    }
    test.check(uniform, "6. the layer stays uniform to the bit");
    test.check(moving, "6. the layer still moves after 40 steps (the model is asked every step)");
    test.check(ok, say("6. eroded depth E_n = (k h0 - c/D)(1 - k^n)/(1 - k) at every step (worst relative error %.2e <= 1e-12)", worst));
    test.check(volume, "6. h + layer = h0 + 10 m in every step (1e-13 relative)");

    const double thick = frontalFirstStep(in, zeta, h0, u0, 10.0);
    const double thin = frontalFirstStep(in, zeta, h0, u0, 0.05);
    std::printf("  first step: layer 10 m -> %.15f m (e(h0) %.15f), layer 0.05 m -> %.15f m\n", thick, e0, thin);
    test.check(std::fabs(thick - e0) <= 1e-12*e0, "6. first step on a thick layer takes up e(h0) = k h0 - c/D");
    test.check(thin == 0.05, "6. first step on a layer thinner than e(h0) takes up the whole layer, exactly");

    // The bed steeper than phi_b (D < 0): its base decides.  Cohesion 0.5
    // m^2/s^2: N = g_n h0 (tan delta - tan phi_b) - c < 0, so a thin layer
    // holds and a thick one fails at its base
    ModelInput steep = in;
    steep.frontal.cohesion = 0.5;
    const double z2 = 30, c2 = std::cos(z2*deg), s2 = std::sin(z2*deg);
    const double D2 = in.g*(c2*tp - s2);
    const double N2 = in.g*c2*h0*(std::tan(27*deg) - tp) - 0.5;
    std::printf("  zeta 30: D = %.6f m/s^2, N = %.6f m^2/s^2, N - D L: L 0.2 m %.6f, L 0.5 m %.6f\n",
        D2, N2, N2 - D2*0.2, N2 - D2*0.5);
    const double held = frontalFirstStep(steep, z2, h0, u0, 0.2);
    const double failed = frontalFirstStep(steep, z2, h0, u0, 0.5);
    test.check(D2 < 0 && N2 - D2*0.2 < 0 && N2 - D2*0.5 > 0, "6. the steep case's signs are as designed (D < 0, L 0.2 holds, L 0.5 fails)");
    test.check(held == 0, say("6. zeta 30 > phi_b, layer 0.2 m: its base holds, nothing taken (%g)", held));
    test.check(failed == 0.5, say("6. zeta 30 > phi_b, layer 0.5 m: its base fails, all of it taken (%g)", failed));
}

//- The erosionEnergy run at fixed dt to t = 4 s: h, hu of the (uniform)
//  layer, the symplectic Euler replay and the exact solution
struct EnergyRun
{
    double h, m, hReplay, mReplay, hExact, mExact;
    bool uniform;
};

EnergyRun energyRun(double dt)
{
    const double zeta = 30, h0 = 0.5, u0 = 2, eb = 100, t = 4;
    ModelInput in = planeInput();
    in.entrainmentModel = EntrainmentModel::ErosionEnergy;
    in.erosionEnergy.erosionEnergy = eb;
    Problem<double> pb = uniformLayer(in, zeta, h0, u0);
    pb.hEntrainable.assign(pb.nCells(), 10.0);
    CpuSolver<double> s(pb, false);
    const int n = int(std::lround(t/dt));
    const double mu = std::tan(in.coulomb.deltaDeg*deg), gn = in.g*std::cos(zeta*deg);
    const double S = slopeAcceleration(in, zeta), a = mu*gn/eb, w = std::sqrt(a*S);
    double h = h0, m = h0*u0;
    for (int i = 0; i < n; ++i)
    {
        s.step(dt);
        m += S*h*dt;
        h += (mu*h*gn)*(m/h)*dt/eb;
    }
    std::vector<double> hs, hu, hv;
    s.getState(hs, hu, hv);
    bool uniform = true;
    for (std::size_t c = 0; c < hs.size(); ++c)
    {
        uniform = uniform && hs[c] == hs[0] && hu[c] == hu[0] && hv[c] == 0;
    }
    const double m0 = h0*u0;
    return {hs[0], hu[0], h, m, h0*std::cosh(w*t) + a*m0/w*std::sinh(w*t),
            m0*std::cosh(w*t) + w*h0/a*std::sinh(w*t), uniform};
}

void erosionEnergy(Counter& test)
{
    std::printf("\n7. erosionEnergy e_b 100 J/kg, zeta 30, delta 20, h0 0.5 m, u0 2 m/s, to t = 4 s\n");
    std::printf("  %8s %14s %14s %14s %10s %14s %14s %10s %10s %10s\n", "dt", "h", "h replay", "h exact",
        "err h", "hu", "hu replay", "hu exact", "err hu", "|replay|");
    double errH[2], errM[2];
    bool replay = true, uniform = true;
    const double dts[2] = {0.01, 0.005};
    for (int i = 0; i < 2; ++i)
    {
        const EnergyRun r = energyRun(dts[i]);
        errH[i] = std::fabs(r.h - r.hExact)/r.hExact;
        errM[i] = std::fabs(r.m - r.mExact)/r.mExact;
        const double rep = std::max(std::fabs(r.h - r.hReplay)/r.hReplay, std::fabs(r.m - r.mReplay)/r.mReplay);
        std::printf("  %8g %14.10f %14.10f %14.10f %10.2e %14.10f %14.10f %10.6f %10.2e %10.2e\n", dts[i], r.h,
            r.hReplay, r.hExact, errH[i], r.m, r.mReplay, r.mExact, errM[i], rep);
        replay = replay && rep <= 1e-12;
        uniform = uniform && r.uniform;
    }
    test.check(uniform, "7. the layer stays uniform to the bit");
    test.check(replay, "7. h, hu equal the replayed m += S h dt, h += a m dt to 1e-12 relative");
    test.check(errH[0] < 1e-2 && errM[0] < 1e-2 && errH[0] > 0,
        say("7. within 1e-2 of the exact cosh/sinh solution at dt 0.01 (h %.2e, hu %.2e)", errH[0], errM[0]));
    const double rh = errH[0]/errH[1], rm = errM[0]/errM[1];
    test.check(rh >= 1.8 && rh <= 2.2 && rm >= 1.8 && rm <= 2.2,
        say("7. first order: halving dt divides the error by %.3f (h), %.3f (hu), within [1.8, 2.2]", rh, rm));

    // The threshold, on the model itself
    ErosionEnergy::Input ei;
    ei.erosionEnergy = 100;
    ei.tauCritical = 2;
    const auto p = ErosionEnergy::params<double>(ei, EntrainmentContext{9.81, 1});
    const auto at = [&](double tau) { return ErosionEnergy::depth(p, EntrainmentState<double>{1, 4, tau, 9, 1, 0, 0.5, 1}); };
    std::printf("  tauCritical 2: depth at tau_b 1.5, 2, 2.5 m^2/s^2 (|u| 4 m/s, dt 0.5 s): %g %g %g\n", at(1.5), at(2), at(2.5));
    test.check(at(1.5) == 0 && at(2) == 0 && at(2.5) == 2.5*4*0.5/100,
        "7. tauCritical: nothing where tau_b <= tau_c, tau_b |u| dt/e_b above");
}

} // namespace

int main()
{
    Counter test;
    constantRate(test);
    volumeBalance(test);
    resistance(test);
    resistanceLaws(test);
    unchanged(test);
    badInput(test);
    frontal(test);
    erosionEnergy(test);
    return test.finish();
}

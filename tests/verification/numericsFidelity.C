/*---------------------------------------------------------------------------*\
  Properties the scheme must hold by construction (physics/scheme.H,
  physics/earthPressure.H), each checked on the CPU backend in double:

  1. Lakes at rest.  A frictionless layer (delta = 0) with a flat free
     surface h + zb = 0.3 m on a flat reference surface (zeta = 0), walls,
     64 x 64 cells on [-1, 1]^2, t = 1 s, both earth-pressure options:
       wet        the bed a Gaussian bump (0.2 m), fully covered;
       shoreline  the bed the bowl of section 5.2, zb = r/2, so the lake
                  ends at r = 0.6 m and the bed beyond is dry.
     max |v| over the wet cells must stay at round-off (1e-12 m/s).  With
     the static resistance on (the default) K = 1 at rest, the paper's
     rule, so with activePassive too: with K != 1 a flat lake is no rest
     state.
     And a rest state with a varying reference surface: a uniform layer
     (h = 0.3 m) on the profile of eq. (35) with zeta0 = 20 deg and
     delta = 25 deg, plus a Gaussian bump, 60 x 28 cells, walls, t = 2 s:
     the static resistance holds it, so it must keep every momentum
     exactly zero and h unchanged.
     And a sloping bed at open sides: a uniform layer (h = 0.5 m, at rest)
     on the plane zb = -0.1 x (zeta = 0, delta = 0, transmissive sides,
     20 x 6 cells): after one step every cell, those next to the open sides
     too, has gained the same momentum -eps g cos(zeta) h dzb/dx dt, to
     round-off (the bed continues linearly beyond an open side).
  2. Exact mirror symmetry.  The collapse of the pile of section 5.2 in
     its bowl, active/passive K with delta = phi = 20 deg (Ky switches) and
     with phi = 30, delta = 20 deg (Kx and Ky switch), and K = 1, every
     limiter,
     40 x 40 cells, t = 0.15 s (flowing), from data symmetric to the last bit: the
     state must equal its mirror image in x and in y bit for bit (momenta
     negated across the mirror).
  3. Momentum in a closed flat box.  A tilted elliptic pile with a swirling
     velocity, active/passive K (which switches all over it), no friction
     (delta = 0, no static resistance), zeta = 0 and a flat bed, walls
     that the material never reaches: no force acts, so the total momentum
     sum(hu, hv) dA must stay what it was, to round-off (relative to
     sum |hU| dA), from t = 0.5 s (by then the pile's sharp initial
     edge, whose draining cells have their speed bounded, the counted
     non-conservative rule of scheme.H, limitThinCell, has spread, and the
     bounds after it take far less momentum than the tolerance: measured
     on this case, docs/numerics.md) to t = 1 s (the thin cells bounded
     in between, counted and printed, hold too little mass to register).  hDry = 1e-12: the
     partial-wet cells of eq. (29), which take a neighbour's velocity, are
     the paper's one non-conservative rule.  Before
     the face carried one K, the pressure of two different K's on its two
     sides broke this by ~K jumps x beta h^2/2.
  4. Float and double take the same active/passive decisions.  On the
     state of the collapsing pile at t = 0.2 s the regularised
     coefficients (earthPressure.H) of every wet cell are computed in both
     precisions from the same state; they must agree to 1e-4.  The switch
     amplifies float's rounding of the velocity difference, 6e-8 of |u|,
     by the slope of the blend, 1.5 dK over the band s0 (c/h) d in du: at
     most 1.5 dK 6e-8 |u| h/(s0 c d), 2e-5 for the pile's Froude numbers
     below 1 and h/d below 20 (dK = 1.3).  The coefficients are those the
     scheme computes (cellStencil).
  5. The time step with the front speed: next to a dry cell the CFL rate of
     eq. (24) takes |u| + 2c (eq. 28), elsewhere |u| + c.
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "gpuCases.H"

#include "host/padded.H"

using namespace sh;
using namespace shtest;

namespace
{

//- Cell-centre coordinate that is mirror-symmetric to the last bit:
//  x(i) = -x(n-1-i) exactly
double symmetricCentre(int i, int n, double halfWidth)
{
    const double d = 2*halfWidth/n;
    const double k = i + 0.5 - 0.5*n;   // exact in binary for these n
    return k*d;
}

//- Fill zb and h from functions of (x, y) at symmetric centres
void setSymmetric
(
    Problem<double>& pb,
    double halfWidth,
    const std::function<double(double, double)>& zb,
    const std::function<double(double, double)>& h
)
{
    const int nx = pb.grid.nx, ny = pb.grid.ny;
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            const double x = symmetricCentre(i, nx, halfWidth);
            const double y = symmetricCentre(j, ny, halfWidth);
            pb.zb[pb.cell(i, j)] = zb(x, y);
            pb.h[pb.cell(i, j)] = h(x, y);
            pb.hu[pb.cell(i, j)] = 0;
            pb.hv[pb.cell(i, j)] = 0;
        }
    }
}


// * * * * * * * * * * * * * * * 1. Lakes at rest  * * * * * * * * * * * * * //

void lakes(Counter& t)
{
    std::printf("\n1. Lakes at rest: h + zb = 0.3 m, delta = 0, walls, 64^2, t = 1 s\n");
    std::printf("%-10s %-14s %12s %12s %12s\n",
        "lake", "earthPressure", "wet cells", "max|v| m/s", "max|dh| m");
    for (const bool shoreline : {false, true})
    {
        for (const bool ap : {false, true})
        {
            ModelInput in;
            in.g = 9.81;
            in.earthPressure = ap
                ? EarthPressureModel::activePassive
                : EarthPressureModel::isotropic;
            in.phiDeg = 30;
            in.coulomb.deltaDeg = 0;
            const int n = 64;
            Problem<double> pb(makeParams<double>(in), n, n, -1, 1, -1, 1);
            for (int s = 0; s < 4; ++s)
            {
                pb.bc.type[s] = BCType::wall;
            }
            const auto bed = [shoreline](double x, double y)
            {
                const double r = std::hypot(x, y);
                return shoreline ? 0.5*r : 0.2*std::exp(-r*r/0.1);
            };
            setSymmetric(pb, 1, bed, [&](double x, double y)
            {
                return std::max(0.0, 0.3 - bed(x, y));
            });
            const std::vector<double> h0 = pb.h;
            CpuSolver<double> s(pb, false);
            s.advanceTo(1.0);
            std::vector<double> h, hu, hv;
            s.getState(h, hu, hv);
            double vmax = 0, dh = 0;
            long wet = 0;
            for (std::size_t c = 0; c < h.size(); ++c)
            {
                dh = std::max(dh, std::fabs(h[c] - h0[c]));
                if (h[c] > 1e-6)
                {
                    ++wet;
                    vmax = std::max(vmax, std::hypot(hu[c], hv[c])/h[c]);
                }
            }
            const char* lake = shoreline ? "shoreline" : "wet";
            const char* K = ap ? "activePassive" : "isotropic";
            std::printf("%-10s %-14s %12ld %12.3g %12.3g\n", lake, K, wet, vmax, dh);
            t.check(vmax <= 1e-12 && dh <= 1e-12,
                std::string(lake) + ", " + K + ": at rest to round-off (|v|, |dh| <= 1e-12)");
            if (!shoreline)
            {
                t.check(wet == n*n, "wet lake: every cell wet");
            }
        }
    }
}


//- A uniform layer, h = 0.3 m at rest, on zeta(x) of eq. (35) with
//  zeta0 = 20 deg, phi = 30, delta = 25 deg, a flat bed, walls, 60 x 28
//  cells on [0, 30] x [-7, 7]; staticRule: the static resistance and the
//  stopping criterion on (the defaults) or off
Problem<double> layerOnVaryingZeta(bool activePassive, bool staticRule)
{
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = activePassive
        ? EarthPressureModel::activePassive : EarthPressureModel::isotropic;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 25;
    in.staticResistance = staticRule;
    in.stoppingCriterion = staticRule;
    Problem<double> pb(makeParams<double>(in), 60, 28, 0, 30, -7, 7);
    for (int s = 0; s < 4; ++s)
    {
        pb.bc.type[s] = BCType::wall;
    }
    pb.setInclination([](double x)
    {
        const double z0 = 20*deg;
        return x <= 17.5 ? z0 : (x < 21.5 ? z0*(1 - (x - 17.5)/4) : 0.0);
    });
    pb.setState([](double, double) { return Primitive{0.3, 0, 0}; });
    return pb;
}

void restOnCurvedBed(Counter& t)
{
    std::printf("\n1b. Rest on a varying reference surface: zeta(x) of eq. (35) with "
                "zeta0 = 20 deg, delta = 25 deg, h = 0.3 m, t = 2 s\n");
    for (const bool ap : {false, true})
    {
        Problem<double> pb = layerOnVaryingZeta(ap, true);
        pb.setTopography([](double x, double y)
        {
            return 0.2*std::exp(-((x - 10)*(x - 10) + y*y)/4);
        });
        const std::vector<double> h0 = pb.h;
        CpuSolver<double> s(pb, false);
        s.advanceTo(2.0);
        std::vector<double> h, hu, hv;
        s.getState(h, hu, hv);
        double mmax = 0, dh = 0;
        for (std::size_t c = 0; c < h.size(); ++c)
        {
            mmax = std::max({mmax, std::fabs(hu[c]), std::fabs(hv[c])});
            dh = std::max(dh, std::fabs(h[c] - h0[c]));
        }
        const char* K = ap ? "activePassive" : "isotropic";
        std::printf("  %-14s max|hU| %.3g, max|dh| %.3g after %ld steps\n", K, mmax, dh, s.steps());
        t.check(mmax == 0 && dh == 0,
            std::string(K) + ": the layer held by its static resistance stays exactly at rest");
    }
}


void slopeAtOpenSides(Counter& t)
{
    std::printf("\n1c. Sloping bed at open sides: zb = -0.1 x, h = 0.5 m, one step\n");
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 0;
    Problem<double> pb(makeParams<double>(in), 20, 6, 0, 10, 0, 3);
    pb.setTopography([](double x, double) { return -0.1*x; });
    pb.setState([](double, double) { return Primitive{0.5, 0, 0}; });
    CpuSolver<double> s(pb, false);
    const double dt = s.stableDt();
    s.step(dt);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    const double expect = 9.81*0.5*0.1*dt;
    double dev = 0;
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        dev = std::max({dev, std::fabs(hu[c] - expect), std::fabs(hv[c])});
    }
    std::printf("  expected hu %.12g, largest deviation over all cells %.3g\n", expect, dev);
    t.check(dev <= 1e-12*expect,
        "every cell, edges included, feels the bed slope: hu = g h (0.1) dt to round-off");
}


//- Whether a run from a state at rest keeps it: the largest speed over
//  the wet cells and change of h after tEnd
struct RestCheck
{
    double vmax = 0;    //!< largest |v| over the cells with h > 1e-6 m
    double dh = 0;      //!< largest |h - h0|
    long wet = 0;
    long steps = 0;
};

RestCheck runRest(Problem<double>& pb, double tEnd)
{
    const std::vector<double> h0 = pb.h;
    CpuSolver<double> s(pb, false);
    s.advanceTo(tEnd);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    RestCheck r;
    r.steps = s.steps();
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        r.dh = std::max(r.dh, std::fabs(h[c] - h0[c]));
        if (h[c] > 1e-6)
        {
            ++r.wet;
            r.vmax = std::max(r.vmax, std::hypot(hu[c], hv[c])/h[c]);
        }
    }
    return r;
}

//- The earth pressure coefficients the scheme gives a cell at rest with
//  no strain (physics/earthPressure.H cellCoeffs)
CellK<double> restingCoeffs(const Params<double>& p)
{
    return cellCoeffs(p.K, p.epsilon*p.g, 0.3, 0.0, 0.0, 0.0, 0.0, true,
        p.staticResistance, 1.0, 1.0);
}

void lakesAtOpenSides(Counter& t)
{
    std::printf("\n1d. Lakes at rest reaching open sides (transmissive on all four), "
                "delta = 0, 64^2 on [-1, 1]^2, t = 1 s\n");
    std::printf("%-34s %-14s %12s %12s %12s\n",
        "lake", "earthPressure", "wet cells", "max|v| m/s", "max|dh| m");
    struct Lake
    {
        const char* name;
        double eta;
        std::function<double(double, double)> zb;
    };
    const Lake lakes[] =
    {
        {"wet: tilted plane + bump, eta 0.4", 0.4, [](double x, double y)
            { return 0.05*(x + y) + 0.2*std::exp(-(x*x + y*y)/0.1); }},
        {"shoreline across the open sides", 0.3, [](double x, double)
            { return 0.3 + 0.3*x; }},
        // the plane turned 135 deg (descending towards (-1, 1)): its
        // shoreline x - y = -0.24 runs diagonally and meets the open sides
        // x = -1 and y = 1 where the edge cell is wet and its inner
        // neighbour dry (grid.H openGhostThickness)
        {"diagonal shoreline, plane 135 deg", 0.25, [](double x, double y)
            { return 0.3 + 0.3*std::sqrt(0.5)*(x - y); }}
    };
    for (const Lake& lake : lakes)
    {
        for (const bool ap : {false, true})
        {
            ModelInput in;
            in.g = 9.81;
            in.earthPressure = ap
                ? EarthPressureModel::activePassive : EarthPressureModel::isotropic;
            in.phiDeg = 30;
            in.coulomb.deltaDeg = 0;
            const int n = 64;
            Problem<double> pb(makeParams<double>(in), n, n, -1, 1, -1, 1);
            setSymmetric(pb, 1, lake.zb, [&](double x, double y)
            {
                return std::max(0.0, lake.eta - lake.zb(x, y));
            });
            const RestCheck r = runRest(pb, 1.0);
            const char* K = ap ? "activePassive" : "isotropic";
            std::printf("%-34s %-14s %12ld %12.3g %12.3g\n", lake.name, K, r.wet, r.vmax, r.dh);
            t.check(r.vmax <= 1e-12 && r.dh <= 1e-12,
                std::string(lake.name) + ", " + K
              + ": at rest to round-off up to the open sides (|v|, |dh| <= 1e-12)");
        }
    }
}

void lakesWithK(Counter& t)
{
    std::printf("\n1e. Lakes at rest with K != 1: active/passive K without the static "
                "resistance (no K = 1 at rest), delta = 0, so K h + zb is constant at "
                "rest; 64^2 on [-1, 1]^2, t = 1 s\n");
    std::printf("%-8s %-12s %10s %10s %12s %12s %12s\n",
        "sides", "bed", "Kx", "Ky", "wet cells", "max|v| m/s", "max|dh| m");
    for (const bool open : {false, true})
    {
        // beds: 0 tilted plane + bump, 1 the bowl, 2 (open sides only) the
        // plane turned 135 deg whose shoreline meets the open sides where
        // the edge cell is wet and its inner neighbour dry
        for (const int bedKind : {0, 1, 2})
        {
            if (bedKind == 2 && !open)
            {
                continue;
            }
            const bool shoreline = bedKind > 0;
            ModelInput in;
            in.g = 9.81;
            in.earthPressure = EarthPressureModel::activePassive;
            in.phiDeg = 30;
            in.coulomb.deltaDeg = 0;
            in.staticResistance = false;
            in.stoppingCriterion = false;
            const Params<double> p = makeParams<double>(in);
            const CellK<double> K = restingCoeffs(p);
            const int n = 64;
            Problem<double> pb(p, n, n, -1, 1, -1, 1);
            if (!open)
            {
                for (int s = 0; s < 4; ++s)
                {
                    pb.bc.type[s] = BCType::wall;
                }
            }
            const auto bed = [bedKind](double x, double y)
            {
                const double r = std::hypot(x, y);
                return bedKind == 2 ? 0.3 + 0.3*std::sqrt(0.5)*(x - y)
                     : bedKind == 1 ? 0.5*r
                     : 0.05*(x + y) + 0.2*std::exp(-r*r/0.1);
            };
            const double eta = bedKind == 2 ? 0.25 : shoreline ? 0.15 : 0.2;
            setSymmetric(pb, 1, bed, [&](double x, double y)
            {
                return std::max(0.0, (eta - bed(x, y))/K.kx);
            });
            const RestCheck r = runRest(pb, 1.0);
            std::printf("%-8s %-12s %10.6f %10.6f %12ld %12.3g %12.3g\n",
                open ? "open" : "walls",
                bedKind == 2 ? "plane 135" : shoreline ? "bowl" : "plane+bump", K.kx, K.ky,
                r.wet, r.vmax, r.dh);
            t.check(std::fabs(K.kx - K.ky) <= 1e-15 && K.kx < 0.5,
                "at rest without static resistance K is the active value, "
                "Kx = Ky = (1 - sin phi)/(1 + sin phi) for delta = 0 (to 1e-15)");
            t.check(r.vmax <= 1e-12 && r.dh <= 1e-12,
                fmt("K = %.4f, ", K.kx) + (open ? "open sides, " : "walls, ")
              + (bedKind == 2 ? "diagonal shoreline" : shoreline ? "shoreline" : "wet")
              + ": K h + zb = const kept at rest to round-off (|v|, |dh| <= 1e-12)");
        }
    }
}

void frictionRestOnCurvedBed(Counter& t)
{
    std::printf("\n1f. Held by friction alone where zeta(x) varies: as 1b, with the "
                "static resistance and the stopping criterion off (a cell at rest is "
                "held by the friction impulse, friction.H), h = 0.3 m, t = 2 s\n");
    for (const bool ap : {false, true})
    {
        Problem<double> pb = layerOnVaryingZeta(ap, false);
        const RestCheck r = runRest(pb, 2.0);
        const char* K = ap ? "activePassive" : "isotropic";
        std::printf("  %-14s max|v| %.3g, max|dh| %.3g after %ld steps\n", K, r.vmax, r.dh, r.steps);
        t.check(r.vmax == 0 && r.dh == 0,
            std::string(K) + ": the layer stays exactly at rest across the change of zeta "
            "(one beta per face: no mass crosses a face between equal states)");
    }
}


// * * * * * * * * * * * * * * 2. Mirror symmetry  * * * * * * * * * * * * * //

void symmetry(Counter& t)
{
    std::printf("\n2. Mirror symmetry: pile in the bowl of section 5.2, 40^2, t = 0.15 s\n");
    const char* names[] = {"minmod", "vanLeer", "MC"};
    const Limiter lims[] = {Limiter::minmod, Limiter::vanLeer, Limiter::MC};
    struct Variant { const char* name; EarthPressureModel K; double phi, delta; };
    const Variant variants[] =
    {
        {"activePassive, phi = delta = 20", EarthPressureModel::activePassive, 20, 20},
        {"activePassive, phi = 30, delta = 20", EarthPressureModel::activePassive, 30, 20},
        {"isotropic, phi = delta = 20", EarthPressureModel::isotropic, 20, 20}
    };
    for (const Variant& var : variants)
    {
        for (int k = 0; k < 3; ++k)
        {
            ModelInput in;
            in.g = 9.81;
            in.earthPressure = var.K;
            in.phiDeg = var.phi;
            in.coulomb.deltaDeg = var.delta;
            in.limiter = lims[k];
            const int n = 40;
            Problem<double> pb(makeParams<double>(in), n, n, -0.3, 0.3, -0.3, 0.3);
            for (int s = 0; s < 4; ++s)
            {
                pb.bc.type[s] = BCType::wall;
            }
            setSymmetric(pb, 0.3,
                [](double x, double y) { return 0.5*std::hypot(x, y); },
                [](double x, double y) { return std::max(0.0, 0.2 - std::hypot(x, y)); });
            CpuSolver<double> s(pb, false);
            s.advanceTo(0.15);
            std::vector<double> h, hu, hv;
            s.getState(h, hu, hv);
            long diffX = 0, diffY = 0, moving = 0;
            for (int j = 0; j < n; ++j)
            {
                for (int i = 0; i < n; ++i)
                {
                    const int c = i + n*j;
                    const int mx = (n - 1 - i) + n*j;
                    const int my = i + n*(n - 1 - j);
                    diffX += h[c] != h[mx] || hu[c] != -hu[mx] || hv[c] != hv[mx];
                    diffY += h[c] != h[my] || hu[c] != hu[my] || hv[c] != -hv[my];
                    moving += hu[c] != 0 || hv[c] != 0;
                }
            }
            std::printf("  %-36s %-8s moving %5ld, differing from the mirror image: x %ld, y %ld\n",
                var.name, names[k], moving, diffX, diffY);
            t.check(moving > 0 && diffX == 0 && diffY == 0,
                std::string(var.name) + ", " + names[k]
              + ": x- and y-mirror symmetric bit for bit while flowing");
        }
    }
}


// * * * * * * * * * * * * * 3. Momentum in a box  * * * * * * * * * * * * * //

void momentum(Counter& t)
{
    std::printf("\n3. Total momentum, closed flat box, active/passive K, no friction\n");
    std::printf("%6s %16s %16s %12s %12s %8s\n",
        "t", "Px", "Py", "Px - P0x", "Py - P0y", "moving");
    {
        ModelInput in;
        in.g = 9.81;
        in.phiDeg = 30;
        in.coulomb.deltaDeg = 0;
        in.staticResistance = false;
        in.stoppingCriterion = false;
        in.hDry = 1e-12;
        const int n = 80;
        const double L = 4;
        Problem<double> pb(makeParams<double>(in), n, n, -L, L, -L, L);
        for (int s = 0; s < 4; ++s)
        {
            pb.bc.type[s] = BCType::wall;
        }
        pb.setState([](double x, double y)
        {
            // Tilted ellipse, swirl plus drift: strains of both signs
            const double a = 0.8*x + 0.6*y + 0.3, b = -0.6*x + 0.8*y - 0.2;
            const double r2 = a*a/0.8 + b*b/0.3;
            const double h = r2 < 1 ? 0.4*(1 - r2) : 0;
            return Primitive{h, h > 0 ? 0.5 - 1.2*y : 0, h > 0 ? 0.3 + 0.9*x : 0};
        });
        const double dA = pb.grid.dx*pb.grid.dy;
        const auto total = [&](Solver<double>& s, double& px, double& py, long& mv,
                               double& scale)
        {
            std::vector<double> h, hu, hv;
            s.getState(h, hu, hv);
            px = py = scale = 0;
            mv = 0;
            for (std::size_t c = 0; c < h.size(); ++c)
            {
                px += hu[c]*dA;
                py += hv[c]*dA;
                scale += (std::fabs(hu[c]) + std::fabs(hv[c]))*dA;
                mv += hu[c] != 0 || hv[c] != 0;
            }
        };
        CpuSolver<double> s(pb, false);
        s.advanceTo(0.5);
        const long long clips0 = s.diagnostics().speedClips;
        double p0x, p0y, sc;
        long mv;
        total(s, p0x, p0y, mv, sc);
        std::printf("%6.2f %16.12f %16.12f %12s %12s %8ld\n", 0.5, p0x, p0y, "", "", mv);
        double worst = 0;
        for (const double tt : {0.625, 0.75, 0.875, 1.0})
        {
            s.advanceTo(tt);
            double px, py;
            total(s, px, py, mv, sc);
            const double ex = px - p0x;
            const double ey = py - p0y;
            worst = std::max(worst, std::max(std::fabs(ex), std::fabs(ey))/sc);
            std::printf("%6.2f %16.12f %16.12f %12.3e %12.3e %8ld\n",
                tt, px, py, ex, ey, mv);
        }
        // Clear of the walls: the walls would add their pressure
        std::vector<double> h, hu, hv;
        s.getState(h, hu, hv);
        double edge = 0;
        for (int k = 0; k < n; ++k)
        {
            edge = std::max({edge, h[k], h[k + n*(n - 1)], h[n*k], h[n - 1 + n*k]});
        }
        const long long clips = s.diagnostics().speedClips - clips0;
        std::printf("  thin cells bounded: %lld before t = 0.5, %lld after; %ld steps\n", clips0, clips, s.steps());
        t.check(edge == 0, "the material stays clear of the walls");
        t.check(worst <= 1e-13,
            fmt("total momentum conserved to %.1e of sum |hU| dA (<= 1e-13)", worst));
    }
}


// * * * * * * * * * * 4. Float and double decisions * * * * * * * * * * * //

//- The coefficients the scheme computes (scheme.H cellEarthPressure) for
//  every cell of a state given in double, evaluated in precision Real
template<class Real>
std::vector<CellK<Real>> schemeCoeffs
(
    const ModelInput& in,
    const Problem<double>& like,
    const std::vector<double>& h,
    const std::vector<double>& hu,
    const std::vector<double>& hv
)
{
    const Grid<double>& gd = like.grid;
    Problem<Real> pb(makeParams<Real>(in), gd.nx, gd.ny,
        gd.x0, gd.x0 + gd.nx*gd.dx, gd.y0, gd.y0 + gd.ny*gd.dy);
    pb.bc = {};
    for (int s = 0; s < 4; ++s)
    {
        pb.bc.type[s] = like.bc.type[s];
    }
    pb.zb.assign(like.zb.begin(), like.zb.end());
    pb.h.assign(h.begin(), h.end());
    pb.hu.assign(hu.begin(), hu.end());
    pb.hv.assign(hv.begin(), hv.end());
    const HostGeometry<Real> geo(pb);
    Model<Real> m;
    m.p = pb.params;
    m.g = pb.grid;
    m.bc = pb.bc;
    m.geo = geo.view();
    std::vector<Real> q[3] = {toPadded(m.g, pb.h), toPadded(m.g, pb.hu), toPadded(m.g, pb.hv)};
    const Fields<Real> U{q[0].data(), q[1].data(), q[2].data()};
    fillGhostCells(m, U);
    std::vector<CellK<Real>> K;
    for (int j = 0; j < m.g.ny; ++j)
    {
        for (int i = 0; i < m.g.nx; ++i)
        {
            K.push_back(cellStencil(m, U, i, j).K);
        }
    }
    return K;
}

void precisions(Counter& t)
{
    std::printf("\n4. Active/passive decisions in float and double: pile in the bowl, "
                "phi = 30, delta = 20 deg, 64^2, state at t = 0.2 s\n");
    ModelInput in;
    in.g = 9.81;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 20;     // Kx act != pass (delta < phi)
    Problem<double> pb = shcases::pileInBowl<double>(in, 64);
    CpuSolver<double> s(pb, false);
    s.advanceTo(0.2);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    const Params<double> pd = makeParams<double>(in);
    const std::vector<CellK<double>> Kd = schemeCoeffs<double>(in, pb, h, hu, hv);
    const std::vector<CellK<float>> Kf = schemeCoeffs<float>(in, pb, h, hu, hv);
    double dKx = 0, dKy = 0;
    long wet = 0, blended = 0;
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        if (h[c] <= 1e-4)
        {
            continue;
        }
        ++wet;
        dKx = std::max(dKx, std::fabs(Kd[c].kx - double(Kf[c].kx)));
        dKy = std::max(dKy, std::fabs(Kd[c].ky - double(Kf[c].ky)));
        blended += Kd[c].kx != pd.K.kx[0] && Kd[c].kx != pd.K.kx[1] && Kd[c].kx != 1;
    }
    std::printf("  Kx act %.6f pass %.6f; %ld wet cells (h > 1e-4 m), %ld inside a band\n",
        pd.K.kx[0], pd.K.kx[1], wet, blended);
    std::printf("  max |Kx(double) - Kx(float)| = %.3g, max |Ky(double) - Ky(float)| = %.3g\n",
        dKx, dKy);
    t.check(wet > 1000 && dKx <= 1e-4 && dKy <= 1e-4,
        "float and double coefficients agree to 1e-4 in every wet cell");
}


// * * * * * * * * * * * * * 5. CFL with the front  * * * * * * * * * * * * //

void frontCfl(Counter& t)
{
    std::printf("\n5. CFL rate (24) next to a dry cell\n");
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 20;
    const int n = 8;
    Problem<double> pb(makeParams<double>(in), n, 1, 0, 8, 0, 1);
    pb.setState([](double x, double) { return Primitive{x < 4 ? 1.0 : 0.0, 0.5, 0}; });
    CpuSolver<double> s(pb, false);
    const double c = std::sqrt(9.81);
    const double expect = (0.5 + 2*c)/1 + c/1;  // cell 3 touches the dry cell 4
    const double rate = s.diagnostics().maxRate;
    std::printf("  dam of 1 m moving at 0.5 m/s: max rate %.12g, expected (|u| + 2c)/dx + c/dy = %.12g\n",
        rate, expect);
    t.check(std::fabs(rate - expect) <= 1e-12*expect,
        "the front cell's rate uses the front speed |u| + 2c");
}

} // namespace


int main()
{
    Counter test;
    std::printf("Numerical properties by construction: lakes at rest, mirror "
                "symmetry, conservation, precision-independent switching\n");
    lakes(test);
    restOnCurvedBed(test);
    slopeAtOpenSides(test);
    lakesAtOpenSides(test);
    lakesWithK(test);
    frictionRestOnCurvedBed(test);
    symmetry(test);
    momentum(test);
    precisions(test);
    frontCfl(test);
    return test.finish();
}

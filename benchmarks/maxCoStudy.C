/*---------------------------------------------------------------------------*\
  The largest stable time step: the verification cases at maxCo 0.4 ... 1.0
  (issue 27 item 3; the tutorials: benchmarks/maxCoTutorials.sh)

  The time step is eq. (24): dt = maxCo / max over cells of the SUM of the
  two directions' wave rates (|u| + c)/dx + (|v| + c)/dy, with |u| + 2c next
  to a dry cell (docs/numerics.md).  Each case below is run on the CPU
  backend in double at every Courant number of -co (default 0.4, 0.5, ...,
  1.0) and one row per run is printed:
    ok      finite state at the end (no NaN/Inf, no exception)
    min h   smallest h of the final state (>= 0: positivity)
    mass    |V - V_ref|/V_ref, V = sum h dA, V_ref the exact volume at the
            end (closed or inflow-free cases: the initial volume)
    steps   time steps; clips: thin cells whose speed was bounded
            (speedBounds, physics/scheme.H limitThinCell)
    errors  against the exact solution, norms named per case:
            RMS = sqrt(sum e^2/N) (the paper's L2), Linf = max|e|,
            L1 = sum |e| dx over the line (cell averages where the exact
            solution is averaged over the cell, else the centre value)
  Cases:
    A  dam break on the incline, section 5.1, Table II (h along y = 0 at
       the cell centres against eqs 31-33, 128x16 and 256x32)
    B  the same started from its exact cell averages at t0 = 0.1 s, run
       to 0.5 s on a 512-cell line (convergence.C 2b): L1 of h over the
       smooth part, where the scheme is second order, and over the line
    C  the spreading parabolic cap (smooth; convergence.C 1), 400 cells:
       L1 of h and hu in the core |xi| <= 0.7
    D  Ritter's frictionless dam break, flat, K = 1 (ritter.C), 400 cells,
       t = 0.1 s: RMS and Linf of h, and the front (h = 0.05 h0) error
    E  static pile, delta = phi = 40 deg, Table III (staticPile.C), 64^2,
       t = 1 s: RMS, Linf of h against the initial state, max |hu|
    F  lake at rest with a shoreline, active/passive K (numericsFidelity.C
       1), 64^2, t = 1 s: max |v|, max |dh|
    G  collapsing pile, delta = phi = 20 deg (collapsingPile.C), 64^2,
       t = 4 s: no exact solution; at rest (max |v| = 0, moving cells),
       max h, cells not mirror-symmetric bit for bit
  Plan coordinates (coordinates plan, the state H = J h, H u, H v; the
  cases of tests/common/planCases.H, run as planTerrainCases.C and
  planScheme.C run them; "min h" is min H, "mass" |V - V0|/V0, V the sum
  of H dX dY):
    H  energy line, mu = 0.4, lambda = 0, isotropic K, to rest
       (planTerrainCases a, 5 m cells): the travel angle of the centre of
       mass minus atan(0.4) [deg] (the test's bound 0.25) and over the
       friction's path, at rest (1/0); the bend: % of the footprint in its
       banks; (i) the channel bend, (ii) the chute into the bowl, (iii) the
       parabolic chute
    I  parabolic cap on a frictionless 30 deg plane turned 30 deg in plan
       (planTerrainCases d), 100^2, t = 3 s, against its similarity
       solution: L1(h - exact)/L1(exact) over the cells, relative errors
       of the centre of mass's travel, its acceleration and the spreading
       (the larger of along and across), the centre of mass across the
       descent over R, the skewness across
    J  dam break on the 40 deg plane turned 30 deg in plan (planScheme g),
       160^2, t = 0.5 s, against eq. (33) in the band along the descent:
       L1(h - exact)/L1(exact), the front (h > h0/100) error in cells
       along the slope; the same along X, 160x16; open sides fed from
       upslope: mass n/a
    K  rest states on the DEM with a bend, a bowl and a kink (planTerrainCases
       b), 50^2, 200 steps (as the test, so the time covered grows with
       maxCo; steps: 200): K1 the three balanced lakes' largest speed over
       the round-off bound 10 N eps sqrt(g h) (at rest: < 1) and the bowl
       lake's largest speed [m/s] (balanced to O(dx^2) only); K2 a layer
       held by friction (delta 30 deg): max |H u|, |H v| and the cells
       whose H changed, both K (the test: 0 and 0), and with delta 20 deg
       whether both K move (1); mass of the held layers
  Thin films and the active/passive switch (slope coordinates):
    L  thin films (thinFilms.C, tests/common/thinFilmCases.H): L1a the
       chute, Coulomb, t = 150 s: moving cells (test: 0), the CFL rate at
       the end over the body's largest (<= 1), the peak speed map over the
       body's (<= 1.05) and over the frictionless fall (<= 1); L1b Voellmy,
       t = 300 s: the largest speed over 1.5 x the stencil's terminal
       speed + 0.1 (<= 1) and the same ratios; L2 section 5.3, 120x56,
       t = 60: the fastest cell with h > 1e-4 over the body's peak speed
       (<= 0.1) and the maps' ratios; mass against the initial volume
    M  the switch (earthPressureSwitch.C, tests/common/switchCases.H): M1
       the compressed smooth flow, minmod, t = 3 s, 200/400/800 cells:
       the spread of TV(u) under refinement, max |TV_n - TV_200|/TV_200
       (test: <= 0.1 at maxCo 0.4), for the three lines (x; y; y with
       delta = phi), active/passive, steps of x at 800 cells, clips of all
       the runs, mass n/a (open); M2 the nearly symmetric collapse, 96^2,
       t = 4 s: the largest |h - its mirror image| and moving cells,
       active/passive (test: <= 1e-10, 0) and isotropic (<= 1e-5, 0);
       steps of the active/passive run
  Where a row joins several runs: ok of all, the smallest min h, the
  largest mass, the steps of the first named, the clips of all.
  Usage: maxCoStudy [-co 0.4,0.6,1.0] [-cases ABCDEFGHIJKLM]
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "exactCap.H"
#include "planCases.H"
#include "switchCases.H"
#include "thinFilmCases.H"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>

using namespace sh;
using namespace shtest;

namespace
{

struct Row
{
    bool ok = true;
    double minH = 0, mass = 0;
    long steps = 0;
    long long clips = 0;
    double wall = 0;
    std::vector<double> errors;
};

//- ok (finite) and min h of a final state, and its steps and clips
Row endRow(const RunEnd& e)
{
    Row r;
    r.steps = e.steps;
    r.clips = e.clips;
    r.minH = 1e300;
    for (std::size_t c = 0; c < e.h.size(); ++c)
    {
        if (!std::isfinite(e.h[c]) || !std::isfinite(e.hu[c]) || !std::isfinite(e.hv[c]))
        {
            r.ok = false;
        }
        r.minH = std::min(r.minH, e.h[c]);
    }
    return r;
}

//- Run a case, timed: run() returns its row; an exception gives ok = NO
template<class Run>
Row timed(Run run)
{
    const auto t0 = std::chrono::steady_clock::now();
    Row r;
    try
    {
        r = run();
    }
    catch (const std::exception& e)
    {
        std::printf("   (exception: %s)\n", e.what());
        r.ok = false;
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

//- Rows of several runs as one: ok of all, the smallest min h, the
//  largest mass, the first's steps, the clips of all
void join(Row& r, const Row& o)
{
    r.ok = r.ok && o.ok;
    r.minH = std::min(r.minH, o.minH);
    r.mass = std::max(r.mass, o.mass);
    r.clips += o.clips;
}

//- Run a problem to tEnd at the problem's cfl; the final state and a row
Row runProblem
(
    Problem<double>& pb,
    double tEnd,
    std::vector<double>& h,
    std::vector<double>& hu,
    std::vector<double>& hv,
    bool hydrostatic = true
)
{
    bool ran = false;
    Row r = timed([&]
    {
        CpuSolver<double> s(pb, hydrostatic);
        s.advanceTo(tEnd);
        RunEnd e;
        e.take(s);
        ran = true;
        h = e.h;
        hu = e.hu;
        hv = e.hv;
        return endRow(e);
    });
    if (!ran)
    {
        h.assign(pb.h.size(), std::nan(""));
        hu = hv = h;
        r.minH = std::nan("");
    }
    return r;
}

double relChange(double v, double v0)
{
    return std::fabs(v - v0)/v0;
}

double sum(const std::vector<double>& v)
{
    double s = 0;
    for (const double x : v) { s += x; }
    return s;
}

void header(const char* title, const std::vector<std::string>& cols)
{
    std::printf("\n%s\n  %5s %3s %10s %9s %6s %6s", title, "maxCo", "ok", "min h",
        "mass", "steps", "clips");
    for (const std::string& c : cols) { std::printf(" %11s", c.c_str()); }
    std::printf(" %7s\n", "wall s");
}

void print(double co, const Row& r)
{
    std::printf("  %5.2f %3s %10.3e", co, r.ok ? "yes" : "NO", r.minH);
    if (std::isnan(r.mass))
    {
        std::printf(" %9s", "n/a");
    }
    else
    {
        std::printf(" %9.2e", r.mass);
    }
    std::printf(" %6ld %6lld", r.steps, r.clips);
    for (const double e : r.errors) { std::printf(" %11.4e", e); }
    std::printf(" %7.2f\n", r.wall);
    std::fflush(stdout);
}


// * * * * * * * * * * * A: dam break, section 5.1  * * * * * * * * * * * * //

const double dbH0 = 10, dbZeta = 40*deg, dbDelta = 24.5*deg, dbG = 9.81, dbT = 0.5;

ModelInput damBreakInput()
{
    ModelInput in;
    in.g = dbG;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 40;
    in.coulomb.deltaDeg = 24.5;
    return in;
}

void caseA(const std::vector<double>& cos)
{
    const int nxs[] = {128, 256};
    const double paperL2[] = {0.073894, 0.0409712};
    const double paperLinf[] = {0.345509, 0.252918};
    for (int k = 0; k < 2; ++k)
    {
        const int nx = nxs[k], ny = nx/8;
        char title[200];
        std::snprintf(title, sizeof title,
            "A. Dam break on the incline (5.1), %dx%d, t = 0.5 s, h along y = 0 "
            "(Table II: RMS %.6g, Linf %.6g); mass against the exact volume",
            nx, ny, paperL2[k], paperLinf[k]);
        header(title, {"RMS h", "Linf h", "L1 h"});
        for (const double co : cos)
        {
            ModelInput in = damBreakInput();
            in.cfl = co;
            const Params<double> p = makeParams<double>(in);
            Problem<double> pb(p, nx, ny, -12.8, 12.8, -1.6, 1.6);
            pb.setInclination([&](double) { return dbZeta; });
            pb.setState([&](double x, double) { return Primitive{x < 0 ? dbH0 : 0, 0, 0}; });
            std::vector<double> h, hu, hv;
            Row r = runProblem(pb, dbT, h, hu, hv);
            const int j = ny/2;
            std::vector<double> num(nx), ex(nx);
            double vEx = 0;
            const double m = dbG*std::cos(dbZeta)*(std::tan(dbDelta) - std::tan(dbZeta));
            const double c0 = std::sqrt(dbG*dbH0*std::cos(dbZeta));
            const auto b = {-c0*dbT - 0.5*m*dbT*dbT, 2*c0*dbT - 0.5*m*dbT*dbT};
            for (int i = 0; i < nx; ++i)
            {
                num[i] = h[pb.cell(i, j)];
                ex[i] = granularDamBreakDepth(pb.grid.xc(i), dbT, dbH0, dbG, dbZeta, dbDelta);
                const double xl = pb.grid.xc(i) - 0.5*pb.grid.dx;
                vEx += cellMean([&](double x)
                    { return granularDamBreakDepth(x, dbT, dbH0, dbG, dbZeta, dbDelta); },
                    xl, xl + pb.grid.dx, b)*pb.grid.dx*3.2;
            }
            const Norms e = errorNorms(num, ex, pb.grid.dx);
            double l1 = 0;
            for (int i = 0; i < nx; ++i) { l1 += std::fabs(num[i] - ex[i])*pb.grid.dx; }
            r.mass = std::fabs(sum(h)*pb.grid.dx*pb.grid.dy - vEx)/vEx;
            r.errors = {e.rms, e.linf, l1};
            print(co, r);
        }
    }
}


// * * * * * * * * * * B: one-dimensional line runs  * * * * * * * * * * * * //

//- nx cells on [xMin, xMax], one row, dy = 8 dx, transmissive (as
//  convergence.C runLine), from the given cell averages
Row runLine
(
    const Params<double>& p,
    int nx,
    double xMin,
    double xMax,
    double zeta,
    const std::vector<double>& h0,
    const std::vector<double>& hu0,
    double tEnd,
    std::vector<double>& h,
    std::vector<double>& hu
)
{
    const double dx = (xMax - xMin)/nx;
    Problem<double> pb(p, nx, 1, xMin, xMax, 0, 8*dx);
    pb.setInclination([&](double) { return zeta; });
    pb.setState([](double, double) { return Primitive{0, 0, 0}; });
    for (int i = 0; i < nx; ++i)
    {
        pb.h[pb.cell(i, 0)] = h0[i];
        pb.hu[pb.cell(i, 0)] = hu0[i];
    }
    std::vector<double> hv;
    return runProblem(pb, tEnd, h, hu, hv, false);
}

void caseB(const std::vector<double>& cos)
{
    const double t0 = 0.1, xMin = -12.8, xMax = 12.8;
    const int n = 512;
    const double dx = (xMax - xMin)/n;
    const GranularDamBreak db{dbH0, dbG, dbZeta, dbDelta};
    const auto xHead = [&](double t) { return db.xHead(t); };
    const auto xFront = [&](double t) { return db.xFront(t); };
    const double band = 0.05*(xFront(dbT) - xHead(dbT));
    const auto hExact = [&](double x, double t) { return db.h(x, t); };
    const auto huExact = [&](double x, double t) { return db.hu(x, t); };
    std::vector<double> hI(n), huI(n), hE(n), huE(n);
    std::vector<char> smooth(n);
    for (int i = 0; i < n; ++i)
    {
        const double xl = xMin + i*dx, xr = xl + dx;
        const auto b0 = {xHead(t0), xFront(t0)};
        const auto b = {xHead(dbT), xFront(dbT)};
        hI[i] = cellMean([&](double x) { return hExact(x, t0); }, xl, xr, b0);
        huI[i] = cellMean([&](double x) { return huExact(x, t0); }, xl, xr, b0);
        hE[i] = cellMean([&](double x) { return hExact(x, dbT); }, xl, xr, b);
        huE[i] = cellMean([&](double x) { return huExact(x, dbT); }, xl, xr, b);
        smooth[i] = (xr < xHead(dbT) - band || xl > xHead(dbT) + band)
                 && (xr < xFront(dbT) - band || xl > xFront(dbT) + band);
    }
    header("B. Dam break (5.1) from its exact cell averages at t0 = 0.1 s to 0.5 s, "
           "512 cells (dy = 8 dx); L1 = sum |e| dx; mass against the exact volume",
        {"L1 h smth", "L1 hu smth", "L1 h all", "L1 hu all"});
    for (const double co : cos)
    {
        ModelInput in = damBreakInput();
        in.cfl = co;
        const Params<double> p = makeParams<double>(in);
        std::vector<double> h, hu;
        Row r = runLine(p, n, xMin, xMax, dbZeta, hI, huI, dbT - t0, h, hu);
        double es = 0, eus = 0, ea = 0, eua = 0;
        for (int i = 0; i < n; ++i)
        {
            const double e = std::fabs(h[i] - hE[i])*dx, eu = std::fabs(hu[i] - huE[i])*dx;
            ea += e;
            eua += eu;
            if (smooth[i]) { es += e; eus += eu; }
        }
        r.mass = std::fabs(sum(h) - sum(hE))/sum(hE);
        r.errors = {es, eus, ea, eua};
        print(co, r);
    }
}

void caseC(const std::vector<double>& cos)
{
    const double g = 9.81, zeta = 35*deg, tEnd = 1, xMin = -6, xMax = 14, xiCore = 0.7;
    const int n = 400;
    const double dx = (xMax - xMin)/n;
    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::activePassive;
    in.phiDeg = 30;
    in.coulomb.deltaDeg = 25;
    const double Kx = makeParams<double>(in).K.kx[0];
    ParabolicCap cap;
    cap.a = g*(std::sin(zeta) - std::tan(in.coulomb.deltaDeg*deg)*std::cos(zeta));
    cap.beta = in.epsilon*g*std::cos(zeta)*Kx;
    cap.uc0 = 3;
    cap.G0 = 5;
    cap.Gdot0 = 1;
    cap.H0 = 1;
    const CapState e0 = cap.at(0, 1), e = cap.at(tEnd, 20000);
    std::vector<double> h0(n), hu0(n), hE(n), huE(n);
    std::vector<char> core(n);
    for (int i = 0; i < n; ++i)
    {
        const double xl = xMin + i*dx, xr = xl + dx;
        const auto b0 = {e0.xc - e0.G, e0.xc + e0.G};
        const auto b = {e.xc - e.G, e.xc + e.G};
        h0[i] = cellMean([&](double x) { return cap.h(e0, x); }, xl, xr, b0);
        hu0[i] = cellMean([&](double x) { return cap.hu(e0, x); }, xl, xr, b0);
        hE[i] = cellMean([&](double x) { return cap.h(e, x); }, xl, xr, b);
        huE[i] = cellMean([&](double x) { return cap.hu(e, x); }, xl, xr, b);
        core[i] = std::fabs(xl - e.xc) <= xiCore*e.G && std::fabs(xr - e.xc) <= xiCore*e.G;
    }
    header("C. Spreading parabolic cap (Savage & Hutter 1989), smooth, 400 cells, t = 1 s; "
           "L1 = sum |e| dx in the core |xi| <= 0.7 and over the line",
        {"L1 h core", "L1 hu core", "L1 h all"});
    for (const double co : cos)
    {
        in.cfl = co;
        const Params<double> p = makeParams<double>(in);
        std::vector<double> h, hu;
        Row r = runLine(p, n, xMin, xMax, zeta, h0, hu0, tEnd, h, hu);
        double ec = 0, euc = 0, ea = 0;
        for (int i = 0; i < n; ++i)
        {
            const double d = std::fabs(h[i] - hE[i])*dx;
            ea += d;
            if (core[i]) { ec += d; euc += std::fabs(hu[i] - huE[i])*dx; }
        }
        r.mass = std::fabs(sum(h) - sum(h0))/sum(h0);
        r.errors = {ec, euc, ea};
        print(co, r);
    }
}

void caseD(const std::vector<double>& cos)
{
    const double tEnd = 0.1, g = 9.81;
    const int n = 400, m = 4;
    const double d = 2.0/n;
    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 35;
    in.coulomb.deltaDeg = 0;
    in.staticResistance = false;
    in.stoppingCriterion = false;
    const double c0 = std::sqrt(g);
    const double level = 0.05, xFront = (2 - std::sqrt(9*level))*c0*tEnd;
    header("D. Ritter's dam break, flat, frictionless, K = 1, h0 = 1 m, 400 cells "
           "(transverse 1.5 dx), t = 0.1 s; errors of h over the line's centres",
        {"RMS h", "Linf h", "front err"});
    for (const double co : cos)
    {
        in.cfl = co;
        Problem<double> pb(makeParams<double>(in), n, m, -1, 1, 0, m*1.5*d);
        pb.setState([](double x, double) { return Primitive{x < 0 ? 1.0 : 0.0, 0, 0}; });
        const double v0 = sum(pb.h);
        std::vector<double> h, hu, hv;
        Row r = runProblem(pb, tEnd, h, hu, hv);
        std::vector<double> line(n), ex(n);
        for (int k = 0; k < n; ++k)
        {
            line[k] = h[pb.cell(k, m/2)];
            ex[k] = ritterDepth(-1 + (k + 0.5)*d, tEnd, 1.0, c0);
        }
        const Norms e = errorNorms(line, ex, d);
        double front = -1;
        for (int k = n - 1; k > 0; --k)
        {
            if (line[k - 1] >= level)
            {
                front = -1 + (k - 0.5)*d + (line[k - 1] - level)/(line[k - 1] - line[k])*d;
                break;
            }
        }
        r.mass = std::fabs(sum(h) - v0)/v0;
        r.errors = {e.rms, e.linf, front - xFront};
        print(co, r);
    }
}

void caseE(const std::vector<double>& cos)
{
    header("E. Static pile, delta = phi = 40 deg (5.2), 64^2, t = 1 s; h against the "
           "initial state over all cells (Table III: RMS 0.00348176, Linf 0.0337154)",
        {"RMS h", "Linf h", "max |hu|"});
    for (const double co : cos)
    {
        ModelInput in;
        in.g = 9.81;
        in.phiDeg = 40;
        in.coulomb.deltaDeg = 40;
        in.cfl = co;
        const int n = 64;
        Problem<double> pb(makeParams<double>(in), n, n, -0.3, 0.3, -0.3, 0.3);
        pb.setTopography([](double x, double y) { return 0.5*std::hypot(x, y); });
        pb.setState([](double x, double y)
        {
            return Primitive{std::max(0.0, 0.2 - std::hypot(x, y)), 0, 0};
        });
        const std::vector<double> h0 = pb.h;
        std::vector<double> h, hu, hv;
        Row r = runProblem(pb, 1.0, h, hu, hv);
        double mmax = 0;
        for (std::size_t c = 0; c < h.size(); ++c)
        {
            mmax = std::max(mmax, std::max(std::fabs(hu[c]), std::fabs(hv[c])));
        }
        const Norms e = errorNorms(h, h0, pb.grid.dx*pb.grid.dy);
        r.mass = std::fabs(sum(h) - sum(h0))/sum(h0);
        r.errors = {e.rms, e.linf, mmax};
        print(co, r);
    }
}

void caseF(const std::vector<double>& cos)
{
    header("F. Lake at rest with a shoreline (h + zb = 0.3 m, zb = r/2), delta = 0, "
           "active/passive, walls, 64^2, t = 1 s", {"max |v|", "max |dh|"});
    for (const double co : cos)
    {
        ModelInput in;
        in.g = 9.81;
        in.earthPressure = EarthPressureModel::activePassive;
        in.phiDeg = 30;
        in.coulomb.deltaDeg = 0;
        in.cfl = co;
        const int n = 64;
        Problem<double> pb(makeParams<double>(in), n, n, -1, 1, -1, 1);
        for (int s = 0; s < 4; ++s) { pb.bc.type[s] = BCType::wall; }
        pb.setTopography([](double x, double y) { return 0.5*std::hypot(x, y); });
        pb.setState([](double x, double y)
        {
            return Primitive{std::max(0.0, 0.3 - 0.5*std::hypot(x, y)), 0, 0};
        });
        const std::vector<double> h0 = pb.h;
        std::vector<double> h, hu, hv;
        Row r = runProblem(pb, 1.0, h, hu, hv, false);
        double vmax = 0, dh = 0;
        for (std::size_t c = 0; c < h.size(); ++c)
        {
            dh = std::max(dh, std::fabs(h[c] - h0[c]));
            if (h[c] > 1e-6) { vmax = std::max(vmax, std::hypot(hu[c], hv[c])/h[c]); }
        }
        r.mass = std::fabs(sum(h) - sum(h0))/sum(h0);
        r.errors = {vmax, dh};
        print(co, r);
    }
}

void caseG(const std::vector<double>& cos)
{
    header("G. Collapsing pile, delta = phi = 20 deg (5.2, Fig. 9; collapsingPile.C), "
           "active/passive, walls, 64^2, t = 4 s (no exact solution: at rest and symmetric)",
        {"max |v|", "moving", "max h", "asymmetric"});
    for (const double co : cos)
    {
        ModelInput in;
        in.g = 9.81;
        in.earthPressure = EarthPressureModel::activePassive;
        in.phiDeg = 20;
        in.coulomb.deltaDeg = 20;
        in.cfl = co;
        const int n = 64;
        Problem<double> pb(makeParams<double>(in), n, n, -0.3, 0.3, -0.3, 0.3);
        for (int s = 0; s < 4; ++s) { pb.bc.type[s] = BCType::wall; }
        const double d = 0.6/n;
        for (int j = 0; j < n; ++j)
        {
            for (int i = 0; i < n; ++i)
            {
                const double x = (i + 0.5 - 0.5*n)*d, y = (j + 0.5 - 0.5*n)*d;
                const double r = std::sqrt(x*x + y*y);
                pb.zb[pb.cell(i, j)] = 0.5*r;
                pb.h[pb.cell(i, j)] = std::max(0.0, 0.2 - r);
            }
        }
        const std::vector<double> h0 = pb.h;
        std::vector<double> h, hu, hv;
        Row r = runProblem(pb, 4.0, h, hu, hv);
        double vmax = 0, hmax = 0;
        long moving = 0, asym = 0;
        for (int j = 0; j < n; ++j)
        {
            for (int i = 0; i < n; ++i)
            {
                const int c = i + n*j;
                const int mx = (n - 1 - i) + n*j, my = i + n*(n - 1 - j);
                asym += h[c] != h[mx] || hu[c] != -hu[mx] || hv[c] != hv[mx]
                     || h[c] != h[my] || hu[c] != hu[my] || hv[c] != -hv[my];
                hmax = std::max(hmax, h[c]);
                if (h[c] > 0)
                {
                    vmax = std::max(vmax, std::hypot(hu[c], hv[c])/h[c]);
                    moving += hu[c] != 0 || hv[c] != 0;
                }
            }
        }
        r.mass = std::fabs(sum(h) - sum(h0))/sum(h0);
        r.errors = {vmax, double(moving), hmax, double(asym)};
        print(co, r);
    }
}


//- One row per maxCo of cos: run(co) returns it, timed (an exception
//  gives ok = NO)
template<class Run>
void rows(const std::vector<double>& cos, Run run)
{
    for (const double co : cos)
    {
        print(co, timed([&] { return run(co); }));
    }
}


// * * * * * * * * * * * * * H-K: plan coordinates  * * * * * * * * * * * * //

void caseH(const std::vector<double>& cos)
{
    const char* names[] = {"(i) channel bend", "(ii) chute into a bowl", "(iii) parabolic chute"};
    for (int k = 0; k < 3; ++k)
    {
        char title[300];
        std::snprintf(title, sizeof title,
            "H. Plan: energy line %s, mu = 0.4, lambda = 0, isotropic K, 5 m cells, to rest "
            "(planTerrainCases a): gamma - atan(0.4) [deg] of the centre of mass (bound 0.25) "
            "and over the friction's path", names[k]);
        std::vector<std::string> cols{"gamma err", "fric err", "at rest", "t rest"};
        if (k == 0) { cols.push_back("in banks %"); }
        header(title, cols);
        rows(cos, [&](double co)
        {
            const Problem<double> pb = k == 0 ? bendRelease(1, co)
                : (k == 1 ? bowlRelease(1, co) : chuteRelease(1, co));
            const Travel t = travel(pb, 200);
            Row row = endRow(t.end);
            row.mass = relChange(t.v1, t.v0);
            row.errors = {t.gamma - gammaTarget, t.gammaFriction - gammaTarget,
                double(t.rest), t.t};
            if (k == 0) { row.errors.push_back(bendFootprint(pb, t.peakH).frac); }
            return row;
        });
    }
}

void caseI(const std::vector<double>& cos)
{
    header("I. Plan: parabolic cap on a frictionless 30 deg plane turned 30 deg in plan, "
           "isotropic K, 100^2, t = 3 s (planTerrainCases d), against the similarity solution: "
           "L1 rel = L1(h - exact)/L1(exact); relative errors of travel, acceleration, "
           "spreading; centre across/R, skewness across",
        {"L1 h rel", "travel", "accel", "spread", "across/R", "skew"});
    rows(cos, [&](double co)
    {
        const CapRun c = runTurnedCap(TurnedCap(), co);
        Row row = endRow(c.end);
        row.mass = relChange(c.m1.volume, c.m0.volume);
        row.errors = {c.l1, (c.travel - c.travelEx)/c.travelEx,
            (c.accel - c.accelEx)/c.accelEx,
            std::max(std::fabs(c.rXi - c.R), std::fabs(c.rEta - c.R))/c.R,
            c.m1.eta/c.R, c.m1.skewEta};
        return row;
    });
}

void caseJ(const std::vector<double>& cos)
{
    for (const bool turned : {true, false})
    {
        header(turned
            ? "J1. Plan: dam break on the 40 deg plane turned 30 deg in plan (planScheme g), "
              "160^2, t = 0.5 s, against eq. (33) over the band along the descent: "
              "L1 rel = L1(h - exact)/L1(exact); front error in cells along the slope; "
              "mass n/a (open sides, fed from upslope)"
            : "J2. Plan: the same dam break along X, 160x16",
            {"L1 h rel", "front err"});
        rows(cos, [&](double co)
        {
            const DamBreak d = turned ? turnedDamBreak(30*deg, 160, 160, 10, 10, co)
                : turnedDamBreak(0, 160, 16, 10, 1, co);
            Row row = endRow(d.end);
            row.mass = std::nan("");
            row.errors = {d.e1, (d.front - d.frontExact)/d.dx};
            return row;
        });
    }
}

void caseK(const std::vector<double>& cos)
{
    header("K1. Plan: lakes at rest (planTerrainCases b1), 50^2, 200 steps: largest speed over "
           "the round-off bound 10 N eps sqrt(g h) of the three balanced lakes (the 12 deg "
           "plane below the features, the whole 25 deg plane, the 12 deg plane's shoreline "
           "meeting the open sides); the bowl lake's largest speed [m/s] (O(dx^2), printed); "
           "the time the 200 steps cover in lake 1 [s]",
        {"lake 1", "lake 2", "lake 3", "bowl [m/s]", "t lake 1"});
    rows(cos, [&](double co)
    {
        Row row;
        bool first = true;
        double t = 0;
        for (const Lake& c : restLakes())
        {
            double hMax = 0;
            const Problem<double> pb = lakeProblem(c, hMax, co);
            const Rest rest = restRun(pb, restSteps);
            Row one = endRow(rest.end);
            one.mass = relChange(rest.v1, rest.v0);
            if (first) { row = one; t = rest.t; } else { join(row, one); }
            first = false;
            row.errors.push_back(rest.maxSpeed/lakeBound(restSteps, hMax));
        }
        const Rest bowl = restRun(bowlLake(co), restSteps);
        Row one = endRow(bowl.end);
        one.mass = relChange(bowl.v1, bowl.v0);
        join(row, one);
        row.errors.push_back(bowl.maxSpeed);
        row.errors.push_back(t);
        return row;
    });
    header("K2. Plan: layer 1 +- 0.2 m held by friction over the DEM (planTerrainCases b2), "
           "delta 30 deg, 200 steps: max |Hu|, |Hv| [m2/s] and cells whose H changed "
           "(test: 0 and 0), active/passive and isotropic K; delta 20 deg: both move (1); "
           "mass of the held layers",
        {"mom ap", "changed ap", "mom iso", "changed iso", "20: moves"});
    rows(cos, [&](double co)
    {
        Row row;
        bool first = true, moves = true;
        std::vector<double> held;
        for (const double delta : {30.0, 20.0})
        {
            for (const EarthPressureModel K :
                 {EarthPressureModel::activePassive, EarthPressureModel::isotropic})
            {
                const Rest rest = restRun(heldLayer(delta, K, co), restSteps);
                Row one = endRow(rest.end);
                // mass of the held layers (delta 20 leaves the open sides)
                one.mass = delta > 25 ? relChange(rest.v1, rest.v0) : 0.0;
                if (first) { row = one; } else { join(row, one); }
                first = false;
                if (delta > 25)
                {
                    held.push_back(rest.maxMomentum);
                    held.push_back(double(rest.changed));
                }
                else
                {
                    moves = moves && (rest.maxMomentum > 0 || rest.changed > 0);
                }
            }
        }
        row.errors = held;
        row.errors.push_back(double(moves));
        return row;
    });
}


// * * * * * * * * * * * * * * L: thin films  * * * * * * * * * * * * * * * //

void caseL(const std::vector<double>& cos)
{
    for (const bool voellmy : {false, true})
    {
        header(voellmy
            ? "L1b. Thin films: chute, Voellmy mu = 0.2, xi = 2000, 200x30, t = 300 s "
              "(thinFilms 1b): largest speed over 1.5 x its stencil's terminal speed + 0.1 "
              "(<= 1); CFL rate at the end over the body's (<= 1); peak speed map over the "
              "body's (<= 1.05) and over the frictionless fall (<= 1); mass against the start"
            : "L1a. Thin films: chute, Coulomb delta = 19 deg, 200x30, t = 150 s (thinFilms 1a): "
              "moving cells (0); CFL rate at the end over the body's (<= 1); peak speed map "
              "over the body's (<= 1.05) and over the frictionless fall (<= 1)",
            {voellmy ? "terminal x" : "moving", "rate/body", "UMax/body", "UMax/fall"});
        rows(cos, [&](double co)
        {
            const ModelInput in = chuteInput(voellmy, co);
            const Problem<double> pb = chuteProblem(in);
            CpuSolver<double> s(pb, false);
            advanceChute(s, voellmy, [](double) {});
            RunEnd e;
            e.take(s);
            Row row = endRow(e);
            row.mass = relChange(sum(e.h), sum(toDouble(pb.h)));
            int at = -1;
            const Speeds u = peakSpeeds(s);
            row.errors =
            {
                voellmy ? terminalExcess(in, e.h, e.hu, e.hv, at)
                    : double(movingCells(e.hu, e.hv)),
                s.diagnostics().maxRate/bodyRate(in, e.h, e.hu, e.hv),
                u.all/u.body,
                u.all/frictionlessFall(in.g, chuteDrop(), chuteHead(in))
            };
            return row;
        });
    }
    header("L2. Thin films: section 5.3, 120x56, t = 60 (thinFilms 2): fastest cell with "
           "h > 1e-4 over the body's peak speed (<= 0.1); peak speed map over the body's "
           "(<= 1.05) and over the frictionless fall (<= 1)",
        {"vmax/body", "UMax/body", "UMax/fall"});
    rows(cos, [&](double co)
    {
        const ModelInput in = filmPlaneInput(co);
        const Problem<double> pb = filmPlaneProblem(in);
        CpuSolver<double> s(pb, false);
        s.advanceTo(filmPlaneEnd);
        RunEnd e;
        e.take(s);
        Row row = endRow(e);
        row.mass = relChange(sum(e.h), sum(toDouble(pb.h)));
        const Speeds u = peakSpeeds(s);
        row.errors = {maxSpeed(e.h, e.hu, e.hv)/u.body, u.all/u.body,
            u.all/frictionlessFall(in.g, filmPlaneDrop(), filmPlaneHead(in))};
        return row;
    });
}


// * * * * * * * * * * * * M: the active/passive switch  * * * * * * * * * * //

void caseM(const std::vector<double>& cos)
{
    header("M1. Switch: compressed smooth flow, minmod, t = 3 s (earthPressureSwitch 1), "
           "active/passive: spread of TV(u) over 200/400/800 cells, max |TV_n - TV_200|/TV_200 "
           "(test at 0.4: <= 0.1), lines x, y, y delta = phi; TV(u) of x at 800 cells; "
           "mass n/a (open)",
        {"spread x", "spread y", "spread y=", "TV x 800"});
    rows(cos, [&](double co)
    {
        Row row;
        bool first = true;
        double tvx = 0;
        std::vector<double> spreads;
        for (const SwitchLine& c : switchLines)
        {
            // 800 cells first: the row's steps are those of x at 800
            double tv[3] = {0, 0, 0};
            int m = 2;
            for (const int n : {800, 200, 400})
            {
                const LineResult l =
                    compressedLine(c.dir, c.phi, c.delta, EarthPressureModel::activePassive, n, co);
                Row one = endRow(l.end);
                if (first) { row = one; tvx = l.tv; } else { join(row, one); }
                first = false;
                tv[m] = l.tv;
                m = (m + 1) % 3;
            }
            const double spread = std::max(std::fabs(tv[1] - tv[0]), std::fabs(tv[2] - tv[0]))/tv[0];
            spreads.push_back(spread);
        }
        row.mass = std::nan("");
        row.errors = spreads;
        row.errors.push_back(tvx);
        return row;
    });
    header("M2. Switch: nearly symmetric collapse, cone in the bowl, delta = phi = 20 deg, "
           "96^2, walls, t = 4 s, centres in floating point (earthPressureSwitch 2): largest "
           "|h - mirror image| [m] and moving cells, active/passive (test: <= 1e-10, 0) and "
           "isotropic (<= 1e-5, 0)",
        {"asym ap", "moving ap", "asym iso", "moving iso"});
    rows(cos, [&](double co)
    {
        const Collapse a = nearlySymmetric(EarthPressureModel::activePassive, co);
        const Collapse i = nearlySymmetric(EarthPressureModel::isotropic, co);
        Row row = endRow(a.end);
        row.mass = relChange(sum(a.end.h), a.v0);
        Row one = endRow(i.end);
        one.mass = relChange(sum(i.end.h), i.v0);
        join(row, one);
        row.errors = {a.final, double(a.moving), i.final, double(i.moving)};
        return row;
    });
}

} // namespace


int main(int argc, char* argv[])
{
    std::vector<double> cos{0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    std::string cases = "ABCDEFGHIJKLM";
    for (int a = 1; a + 1 < argc; a += 2)
    {
        if (!std::strcmp(argv[a], "-co"))
        {
            cos.clear();
            std::stringstream ss(argv[a + 1]);
            std::string item;
            while (std::getline(ss, item, ',')) { cos.push_back(std::atof(item.c_str())); }
        }
        else if (!std::strcmp(argv[a], "-cases"))
        {
            cases = argv[a + 1];
        }
    }
    std::printf("maxCo study: CPU backend, double; Courant number of eq. (24) on the sum "
                "of both directions' rates\n");
    if (cases.find('A') != std::string::npos) { caseA(cos); }
    if (cases.find('B') != std::string::npos) { caseB(cos); }
    if (cases.find('C') != std::string::npos) { caseC(cos); }
    if (cases.find('D') != std::string::npos) { caseD(cos); }
    if (cases.find('E') != std::string::npos) { caseE(cos); }
    if (cases.find('F') != std::string::npos) { caseF(cos); }
    if (cases.find('G') != std::string::npos) { caseG(cos); }
    if (cases.find('H') != std::string::npos) { caseH(cos); }
    if (cases.find('I') != std::string::npos) { caseI(cos); }
    if (cases.find('J') != std::string::npos) { caseJ(cos); }
    if (cases.find('K') != std::string::npos) { caseK(cos); }
    if (cases.find('L') != std::string::npos) { caseL(cos); }
    if (cases.find('M') != std::string::npos) { caseM(cos); }
    return 0;
}

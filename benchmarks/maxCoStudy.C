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
  Usage: maxCoStudy [-co 0.4,0.6,1.0] [-cases ABCDEFG]
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "exactCap.H"

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
    Row r;
    const auto t0 = std::chrono::steady_clock::now();
    try
    {
        CpuSolver<double> s(pb, hydrostatic);
        s.advanceTo(tEnd);
        s.getState(h, hu, hv);
        r.steps = s.steps();
        r.clips = s.diagnostics().speedClips;
    }
    catch (const std::exception& e)
    {
        std::printf("   (exception: %s)\n", e.what());
        r.ok = false;
        h.assign(pb.h.size(), std::nan(""));
        hu = hv = h;
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.minH = 1e300;
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        if (!std::isfinite(h[c]) || !std::isfinite(hu[c]) || !std::isfinite(hv[c]))
        {
            r.ok = false;
        }
        r.minH = std::min(r.minH, h[c]);
    }
    return r;
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
    std::printf("  %5.2f %3s %10.3e %9.2e %6ld %6lld", co, r.ok ? "yes" : "NO",
        r.minH, r.mass, r.steps, r.clips);
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

} // namespace


int main(int argc, char* argv[])
{
    std::vector<double> cos{0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    std::string cases = "ABCDEFG";
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
    return 0;
}

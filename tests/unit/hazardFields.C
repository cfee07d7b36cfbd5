/*---------------------------------------------------------------------------*\
  Hazard maps of the solver (physics/scheme.H updatePeaks): hMax, UMax,
  pMax and tArrival against values computed here, independently, from the
  state after every step

    1. Bit for bit, in double and float, on the cases of gpuCases.H with
       rho = 1500 kg/m^3 and arrivalThreshold 1 % of the initial peak
       thickness: stepping one step at a time (Solver::step with a given dt,
       then advance() with a wall budget of 0 s, which returns after every
       step, to several end times, so that steps ending exactly at tEnd
       are among them), after each step
         hMax = max h,  UMax = max sqrt(u^2 + v^2),
         pMax = max rho (u^2 + v^2)   (u, v as the scheme forms them,
                                       reconstruction.H primitive; over the
                                       steps where h > hDry),
         tArrival = float(the end time of the first step with h >
                    arrivalThreshold), -1 where never;
       the initial state counts at t = 0.
    2. Restart: maps and state handed to a new solver at t1 (Problem::peaks,
       startTime) continue bit for bit as the uninterrupted run's to t2;
       without pMax handed over, UMax still does (pMax then only to
       round-off: printed).
    3. squaredSpeedPeak finds, for random peaks S and densities, a value
       with sqrt == UMax and rho times it == pMax (the restart's input);
       how often UMax^2 alone would miss S (why pMax is read back) is
       printed.
    4. Ritter: a frictionless dam break on a flat bed (h0 = 1 m behind
       x0 = 0, K = 1, g = 9.81, 400 and 800 cells on [-2, 2]) to t = 0.3 s.
       In Ritter's solution h = (2 c0 - x/t)^2/(9 g) ahead of the dam, so
       the depth a reaches x at t_a(x) = x/(2 c0 - 3 sqrt(g a)), the front
       x = 2 c0 t in the limit a -> 0.  tArrival of the cells from x = 0.2 m
       to where a arrives at 0.8 t, for a = 1e-2 m (the default
       arrivalThreshold): within 5 cells of the exact position of that
       depth at tArrival, (2 c0 - 3 sqrt(g a)) tArrival (the numerical
       front lags it by a few cells, the same along the way, the distance
       in metres halving with the cells: checked), for a = 1e-4 m printed
       (the thinnest layer of the numerical front lags more, converging
       slowly).
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "gpuCases.H"

#include <limits>
#include <random>

using namespace sh;
using namespace shtest;

namespace
{

//- The maps computed here from the states after each step
template<class Real>
struct Reference
{
    std::vector<Real> h, speed, pressure;
    std::vector<float> arrival;
    Real rho, threshold, hDry;

    explicit Reference(const Problem<Real>& pb)
    :
        h(pb.nCells(), Real(0)),
        speed(pb.nCells(), Real(0)),
        pressure(pb.nCells(), Real(0)),
        arrival(pb.nCells(), -1.0f),
        rho(pb.params.rho),
        threshold(pb.params.arrivalThreshold),
        hDry(pb.params.hDry)
    {}

    //- The state at time t (after a step or the initial one)
    void update(Solver<Real>& s, double t)
    {
        std::vector<Real> hs, hus, hvs;
        s.getState(hs, hus, hvs);
        for (std::size_t c = 0; c < hs.size(); ++c)
        {
            if (hs[c] > threshold && arrival[c] < 0)
            {
                arrival[c] = float(t);
            }
            h[c] = std::max(h[c], hs[c]);
            if (hs[c] > hDry)
            {
                const CellState<Real> p = primitive(State<Real>{hs[c], hus[c], hvs[c]});
                const Real s2 = p.u*p.u + p.v*p.v;
                speed[c] = std::max(speed[c], std::sqrt(s2));
                pressure[c] = std::max(pressure[c], rho*s2);
            }
        }
    }
};

template<class T>
long differing(const std::vector<T>& a, const std::vector<T>& b)
{
    if (a.size() != b.size())
    {
        return -1;
    }
    long n = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
    {
        n += !(a[k] == b[k]);
    }
    return n;
}

template<class Real>
void independentMaps(Counter& test, const char* name, const Problem<Real>& pb0, double tEnd)
{
    const Problem<Real> pb = shcases::withHazardMaps(pb0);
    const std::string prec = sizeof(Real) == 8 ? "double" : "float";
    CpuSolver<Real> s(pb, true);
    Reference<Real> ref(pb);
    ref.update(s, 0);

    // Steps of a given dt, then advance() one step per call to each end
    long onEnd = 0;
    for (int k = 0; k < 5; ++k)
    {
        s.step(Real(0.5)*s.stableDt());
        ref.update(s, s.time());
    }
    for (int e = 1; e <= 4; ++e)
    {
        const double t = tEnd*e/4;
        while (!s.advance(t, 0.0))
        {
            ref.update(s, s.time());
        }
        ref.update(s, s.time());
        ++onEnd;
    }

    const PeakMaps<Real> m = s.peakMaps();
    long arrived = 0, later = 0, atEnd = 0;
    for (const float a : m.arrival)
    {
        arrived += a >= 0;
        later += a > 0;
        for (int e = 1; e <= 4; ++e)
        {
            atEnd += a == float(tEnd*e/4);
        }
    }
    const long dh = differing(m.h, ref.h);
    const long du = differing(m.speed, ref.speed);
    const long dp = differing(m.pressure, ref.pressure);
    const long da = differing(m.arrival, ref.arrival);
    std::printf("%-15s %-6s %6ld steps, %6d cells: arrived %ld (after t = 0: "
        "%ld, on a step ending at tEnd: %ld); max pMax %.4g Pa; differing "
        "hMax %ld, UMax %ld, pMax %ld, tArrival %ld\n", name, prec.c_str(),
        s.steps(), pb.nCells(), arrived, later, atEnd,
        double(*std::max_element(m.pressure.begin(), m.pressure.end())),
        dh, du, dp, da);
    test.check(dh == 0 && du == 0 && dp == 0 && da == 0 && later > 0,
        std::string(name) + " " + prec + ": hMax, UMax, pMax, tArrival "
        "bit-identical to the maxima and first arrivals over the steps");
}

template<class Real>
void restart(Counter& test, const char* name, const Problem<Real>& pb0, double t1, double t2)
{
    const Problem<Real> pb = shcases::withHazardMaps(pb0);
    const std::string prec = sizeof(Real) == 8 ? "double" : "float";
    // Through t1 too, as a run writing there (its steps end at t1)
    CpuSolver<Real> whole(pb, true);
    whole.advanceTo(t1);
    whole.advanceTo(t2);
    const PeakMaps<Real> a = whole.peakMaps();

    CpuSolver<Real> first(pb, true);
    first.advanceTo(t1);
    long dPressure = 0;
    bool same = true;
    for (const bool withPressure : {true, false})
    {
        Problem<Real> pr = pb;
        pr.startTime = first.time();
        first.getState(pr.h, pr.hu, pr.hv);
        pr.peaks = first.peakMaps();
        if (!withPressure)
        {
            pr.peaks.pressure.clear();
        }
        CpuSolver<Real> second(pr, true);
        second.advanceTo(t2);
        const PeakMaps<Real> b = second.peakMaps();
        std::vector<Real> ha, hb, x, y;
        whole.getState(ha, x, y);
        second.getState(hb, x, y);
        const bool mapsSame = differing(a.h, b.h) == 0
            && differing(a.speed, b.speed) == 0
            && differing(a.arrival, b.arrival) == 0 && ha == hb
            && second.time() == whole.time();
        if (withPressure)
        {
            same = mapsSame && differing(a.pressure, b.pressure) == 0;
        }
        else
        {
            same = same && mapsSame;
            dPressure = differing(a.pressure, b.pressure);
        }
    }
    test.check(same, std::string(name) + " " + prec
      + fmt(": restart at t = %g continues hMax, UMax, pMax, tArrival and "
        "the state bit for bit", t1)
      + fmt(" to t = %g", t2)
      + fmt(" (without pMax handed over: UMax still, %g pMax differ)",
        double(dPressure)));
}

template<class Real>
void recovery(Counter& test)
{
    const std::string prec = sizeof(Real) == 8 ? "double" : "float";
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> logS(-8, 8);
    const Real rhos[] = {Real(1), Real(3), Real(1500), Real(2650.7)};
    long n = 0, found = 0, squareMisses = 0, pressureMisses = 0;
    for (int k = 0; k < 200000; ++k)
    {
        const Real S = Real(std::pow(10.0, logS(rng)));
        const Real rho = rhos[k % 4];
        const Real speed = std::sqrt(S);
        const Real p = rho*S;
        Real r = 0;
        const bool ok = squaredSpeedPeak(speed, p, rho, true, r);
        ++n;
        found += ok && std::sqrt(r) == speed && rho*r == p;
        squareMisses += speed*speed != S;
        pressureMisses += rho*(speed*speed) != p;
    }
    test.check(found == n, prec + fmt(": squaredSpeedPeak recovers a peak "
        "with sqrt == UMax and rho x == pMax for %g random peaks", double(n))
      + fmt(" (UMax^2 alone: %g differ from the peak", double(squareMisses))
      + fmt(", %g give another pMax)", double(pressureMisses)));
}

//- Ritter's depth a reaches x > 0 at x/(2 c0 - 3 sqrt(g a))
void ritterArrival(Counter& test)
{
    const double g = 9.81, h0 = 1, tEnd = 0.3;
    const int m = 4;
    ModelInput in;
    in.g = g;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 35;
    in.coulomb.deltaDeg = 0;
    in.staticResistance = false;
    in.stoppingCriterion = false;
    const double c0 = std::sqrt(g*h0);
    std::printf("\nRitter: h0 = %g m, c0 = %.4f m/s, t = %g s, front at 2 c0 t "
        "= %.3f m; tArrival of the cells from x = 0.2 m to where depth a "
        "arrives at 0.8 t; x_a = (2 c0 - 3 sqrt(g a)) tArrival\n", h0, c0,
        tEnd, 2*c0*tEnd);
    std::printf("%10s %6s %12s %16s %16s %18s %20s\n", "a [m]", "cells",
        "speed of a", "mean x - x_a [m]", "mean (x - x_a)/dx",
        "max |x - x_a|/dx", "max (x - 2c0 t)/dx");
    const double tol = 5;
    for (const double a : {1e-2, 1e-4})
    {
        double lagBefore = 0;
        for (const int n : {400, 800})
        {
            const double dx = 4.0/n;
            in.arrivalThreshold = a;
            Problem<double> pb(makeParams<double>(in), n, m, -2, 2, 0, m*dx);
            pb.setState([&](double x, double)
            {
                return Primitive{x < 0 ? h0 : 0.0, 0, 0};
            });
            CpuSolver<double> s(pb, true);
            s.advanceTo(tEnd);
            const PeakMaps<double> maps = s.peakMaps();
            const double va = 2*c0 - 3*std::sqrt(g*a);
            const double xMax = 0.8*va*tEnd;
            double sum = 0, worst = 0, front = -1e300;
            int count = 0;
            bool all = true;
            for (int i = 0; i < n; ++i)
            {
                const double x = pb.grid.xc(i);
                if (x < 0.2 || x > xMax)
                {
                    continue;
                }
                for (int j = 0; j < m; ++j)
                {
                    const double t = maps.arrival[pb.cell(i, j)];
                    all = all && t > 0;
                    const double e = (x - va*t)/dx;
                    sum += e;
                    worst = std::max(worst, std::fabs(e));
                    front = std::max(front, (x - 2*c0*t)/dx);
                    ++count;
                }
            }
            const double lag = sum/count*dx;
            std::printf("%10g %6d %12.4f %16.4f %16.3f %18.3f %20.3f\n", a, n,
                va, lag, sum/count, worst, front);
            if (a < 1e-3)
            {
                continue;
            }
            test.check(all && worst <= tol, fmt("Ritter, depth a = %g m, ", a)
              + fmt("%g cells: every cell arrived, within ", double(n))
              + fmt("%g cells of the exact arrival", tol)
              + fmt(" (%.3f)", worst));
            if (lagBefore != 0)
            {
                test.check(std::fabs(lag) < 0.75*std::fabs(lagBefore),
                    fmt("Ritter, depth a = %g m: the mean distance to the "
                        "exact arrival converges with the mesh (%.4f m", a,
                        lagBefore) + fmt(" -> %.4f m)", lag));
            }
            lagBefore = lag;
        }
    }
    std::printf("(a = 1e-4 m, printed only: the thinnest depths of the front "
        "lag Ritter's by a distance that falls slowly with the mesh)\n");
}

} // namespace


int main()
{
    Counter test;
    std::printf("Hazard maps against maxima and first arrivals computed from "
        "the state after every step (rho 1500, arrivalThreshold 1 %% of the "
        "initial peak h)\n");
    independentMaps(test, "damBreak", shcases::damBreak<double>(128), 0.2);
    independentMaps(test, "collapsingPile", shcases::collapsingPile<double>(40), 0.4);
    independentMaps(test, "inclinedPlane", shcases::inclinedPlane<double>(2), 4);
    independentMaps(test, "inflowPlane", shcases::inflowPlane<double>(2), 2);
    independentMaps(test, "granularJet", shcases::granularJet<double>(64), 0.2);
    independentMaps(test, "damBreak", shcases::damBreak<float>(128), 0.2);
    independentMaps(test, "collapsingPile", shcases::collapsingPile<float>(40), 0.4);
    independentMaps(test, "inclinedPlane", shcases::inclinedPlane<float>(2), 4);
    std::printf("\nRestart\n");
    restart(test, "inclinedPlane", shcases::inclinedPlane<double>(2), 2, 5);
    restart(test, "collapsingPile", shcases::collapsingPile<double>(40), 0.2, 0.5);
    restart(test, "inclinedPlane", shcases::inclinedPlane<float>(2), 2, 5);
    std::printf("\nThe peak of u^2 + v^2 from UMax and pMax read back\n");
    recovery<double>(test);
    recovery<float>(test);
    ritterArrival(test);
    return test.finish();
}

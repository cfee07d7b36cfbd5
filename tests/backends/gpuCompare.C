/*---------------------------------------------------------------------------*\
  GPU against CPU: the CUDA backend must reproduce the CPU backend

    Usage: gpuCompare damBreak|collapsingPile|lakeAtRest|inclinedPlane|
                      inflowPlane|granularJet|voellmyPile|openLake|
                      outflowCorner|planBumpyDem|planFlatPile|coverPile|
                      planCoverPile|planCoverDem

    planBumpyDem and planFlatPile run in plan coordinates (physics/
    planScheme.H; the CUDA backend's PlanStages kernels), with the same
    checks as the others.

    Runs the case on the CPU backend (OpenMP) and on the CUDA backend, in
    double and in float, and compares the states at several output times.

    Double: no tolerance.  The two backends call the same functions
    (physics/scheme.H) on the same inputs in the same order, with
    IEEE-rounded +, -, *, /, sqrt and no contraction into FMA on either
    side (cuda/cudaSolverImpl.H), and the only reductions are maxima; so
    every value of h, hu, hv must be bit-identical, and so must the number
    of steps, the time, the last time step, the diagnostics and the hazard
    maps hMax, UMax, pMax (rho = 1500) and tArrival (arrivalThreshold 1 %
    of the initial peak h; its time is the step's end time, which the GPU
    keeps on the device: stepKernels.H), counted on host-given steps,
    device-clock steps and steps ending at an output time.

    Float: by default the CUDA backend is IEEE-rounded in float too, and
    the float comparison is bit for bit, as in double.  A build configured
    with SH_CUDA_FLOAT_APPROX=ON compiles the float kernels with the
    hardware's approximate division and square root
    (cuda/cudaSolverFloat.cu).  Approximate, its state differs from
    the CPU's float state by round-off, and the test bounds that difference
    by how far the same flow carries a perturbation of one ulp, measured in
    the same run:
      e_gpu = relL2(float GPU - float CPU),
      e_ulp = relL2(float CPU from h + 1 ulp - float CPU),
    (the second run starts with every wet cell's h one ulp larger), where
    relL2(a - b) = ||a - b||_2 / ||b||_2 over the interior cells, for h and
    for the momentum (hu, hv) as one vector (hv alone is antisymmetric and
    nearly zero in the symmetric cases, so its own relative norm says
    little), must satisfy at every output time
      e_gpu <= 8 e_ulp + 1e-6.
    Why e_ulp: the GPU's approximate operations are ulp-sized
    perturbations fed into the flow at every step; e_ulp is what the flow
    makes of such a perturbation, including the growth that the
    active/passive switch of the inclined plane gives it (by orders of
    magnitude over the run: docs/performance.md).  Why 8: an approximate
    division errs by up to 2 ulp and a square root by about 1, against 0.5
    for IEEE rounding, so 4 times larger perturbations, and a factor 2 for
    their being fed at every step rather than once.  Why 1e-6 (17 ulp of
    float, relative, in the rms): in the smooth dam break errors add up
    step by step without growth, and e_ulp stays near one ulp.  Where the
    reference momentum is zero (the pile at rest), the GPU's must be
    exactly zero too.
    The distance of the CPU's float run from its double run, e_fd, is
    printed for information; it is not the reference: in the inclined
    plane it is large, and e_ulp is of the same size (docs/performance.md):
    the flow, its stopping criterion and the steep but continuous switch
    amplify any perturbation alike, so a bound on e_fd could not catch an
    error below that size.
    Further float checks: the step count within 1 % (+1) of the CPU's (dt
    depends on the rounded wave speeds), output times hit exactly, stableDt
    within 1e-6 relative (a few ulp), the volume within the bound of h; wet
    and moving cells printed.

    The paths through the device clock are all exercised: Solver::step with
    a host-given dt, advanceTo over one and many graph launches, advance()
    returning after its wall-time budget (collapsingPile: a budget of 0 s,
    so one graph per call) and stableDt.

    With the bed's cover (coverPile, planCoverPile, planCoverDem: an
    erodible layer, a resistance patch and an entrainment model; each case
    runs once for every model of physics/entrainmentModels/ but none, at
    the coefficients of gpuCases.H smallScaleCover): also the layer left
    and the eroded depth (Solver::getCover) bit-identical at every output
    time in double (and in an IEEE float build), the diagnostics' layer
    and eroded volumes identical, material taken up (eroded volume > 0 on
    the GPU), the layer, eroded depth and h never negative, and, in the
    closed cases (walls on every side), flowing + erodible volume
    conserved on the GPU: relative change <= 1e-12 in double (the stage's
    two additions per cell and step, each rounding by 1.1e-16 relative,
    over a few thousand steps, and the volumes' sums; the CPU test
    verification/entrainment.C holds its box to 1e-13), <= 1e-5 in float
    (the same count of float roundings, 6e-8 each).

    Without a usable GPU (no CUDA in the build, no device) the test prints
    why and exits with 77, which CTest reports as skipped.
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "gpuCases.H"
#include "cuda/cudaSolver.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>

using namespace sh;
using namespace shtest;

namespace
{

//- Whether the case compared holds material at rest (nothing may arrive)
bool staticCase = false;

//- Float bound: e_gpu <= floatFactor e_ulp + floatFloor (header)
constexpr double floatFactor = 8;
constexpr double floatFloor = 1e-6;

//- A state on the host, as doubles
struct State
{
    std::vector<double> q[3];
};

template<class Real>
State state(Solver<Real>& s)
{
    std::vector<Real> q[3];
    s.getState(q[0], q[1], q[2]);
    State r;
    for (int k = 0; k < 3; ++k)
    {
        r.q[k].assign(q[k].begin(), q[k].end());
    }
    return r;
}

struct Difference
{
    long differing = 0;     //!< values that differ (bit patterns of Real)
    double maxAbs = 0;      //!< max |a - b| over h, hu, hv
    double relL2h = 0;      //!< ||h_a - h_b|| / ||h_b||
    double relL2m = 0;      //!< ||m_a - m_b|| / ||m_b||, m = (hu, hv);
                            //   0 if both zero, inf if only m_b is
    double maxHu = 0;       //!< max |hu|, |hv| of b (non-trivial)
};

//- Whether two arrays hold the same bits
template<class Real>
bool sameBits(const std::vector<Real>& a, const std::vector<Real>& b)
{
    return a.size() == b.size() && (a.empty()
        || std::memcmp(a.data(), b.data(), a.size()*sizeof(Real)) == 0);
}

//- The problem with the initial h of every wet cell one ulp larger (and
//  an impinging jet's thickness scale and speed)
template<class Real>
Problem<Real> ulpUp(Problem<Real> pb)
{
    for (Real& x : pb.h)
    {
        if (x > 0)
        {
            x = std::nextafter(x, std::numeric_limits<Real>::max());
        }
    }
    // A jet re-imposes its state every step, which would wipe the
    // perturbation out there: perturb the jet's data by one ulp instead
    JetParams<Real>& jet = pb.params.jet;
    if (jet.on)
    {
        jet.hCoeff = std::nextafter(jet.hCoeff, std::numeric_limits<Real>::max());
        jet.uJet = std::nextafter(jet.uJet, std::numeric_limits<Real>::max());
    }
    return pb;
}

//- a against the reference b; values compared as doubles (exact for float)
Difference difference(const State& a, const State& b)
{
    Difference d;
    double eh = 0, rh = 0, em = 0, rm = 0;
    for (int k = 0; k < 3; ++k)
    {
        for (std::size_t c = 0; c < b.q[k].size(); ++c)
        {
            const double x = a.q[k][c];
            const double y = b.q[k][c];
            d.differing += x != y;
            d.maxAbs = std::max(d.maxAbs, std::fabs(x - y));
            (k == 0 ? eh : em) += (x - y)*(x - y);
            (k == 0 ? rh : rm) += y*y;
            if (k > 0)
            {
                d.maxHu = std::max(d.maxHu, std::fabs(y));
            }
        }
    }
    const double inf = std::numeric_limits<double>::infinity();
    d.relL2h = rh > 0 ? std::sqrt(eh/rh) : (eh > 0 ? inf : 0);
    d.relL2m = rm > 0 ? std::sqrt(em/rm) : (em > 0 ? inf : 0);
    return d;
}

//- Run cpu and gpu through the output times and compare at each.  Double
//  (or float on an IEEE build): bit for bit.  Approximate float: against
//  the bound of the header (with a third run, the CPU from h + 1 ulp), and
//  cpuDouble the double CPU states at the output times (for e_fd).  Returns the CPU states at the output times and leaves the
//  GPU's final state in gpuFinal.
//  Kept in one piece: the lock-step of the two (three) runs over the output
//  times and the comparison at each share the solvers and the running error
//  tables.
template<class Real>
std::vector<State> compareRun
(
    Counter& test,
    const Problem<Real>& pb,
    const std::vector<double>& times,
    bool wallChunks,
    int fixedSteps,
    const std::vector<State>* cpuDouble,
    State& gpuFinal
)
{
    const bool dbl = sizeof(Real) == 8;
    const std::string prec = dbl ? "double" : "float";
    const bool exact = dbl || !cudaFloatApproximate();
    CpuSolver<Real> cpu(pb, true);
    std::unique_ptr<Solver<Real>> gpu = makeCudaSolver(pb);
    std::unique_ptr<CpuSolver<Real>> cpuUlp;
    if (!exact)
    {
        cpuUlp.reset(new CpuSolver<Real>(ulpUp(pb), true));
    }
    std::printf("\n%s: %s against %s, %dx%d cells\n", prec.c_str(),
        gpu->name().c_str(), cpu.name().c_str(), pb.grid.nx, pb.grid.ny);
    if (exact)
    {
        std::printf("must be bit-identical\n");
    }
    else
    {
        std::printf("bound: e_gpu <= %g e_ulp + %g, of h and of (hu, hv); "
            "e_gpu = relL2(GPU - CPU), e_ulp = relL2(CPU from h + 1 ulp - "
            "CPU), e_fd = relL2(CPU float - CPU double)\n", floatFactor,
            floatFloor);
    }

    // The volumes before the first step, for the balance of the cover
    const Diagnostics d0 = gpu->diagnostics();
    const Real dtCpu = cpu.stableDt();
    double fixedEnd = 0;
    const Real dtGpu = gpu->stableDt();
    const double dtRel = std::fabs(double(dtGpu) - double(dtCpu))/double(dtCpu);
    test.check(exact ? dtCpu == dtGpu : dtRel <= 1e-6,
        prec + (exact ? ": stableDt identical" : ": stableDt within 1e-6")
      + fmt(" (%.17g vs %.17g)", double(dtCpu), double(dtGpu)));
    for (int k = 0; k < fixedSteps; ++k)
    {
        cpu.step(Real(0.5)*dtCpu);
        gpu->step(Real(0.5)*dtCpu);
        if (cpuUlp)
        {
            cpuUlp->step(Real(0.5)*dtCpu);
        }
    }
    fixedEnd = cpu.time();

    if (exact)
    {
        std::printf("%8s %8s %8s %10s %12s %12s %12s %10s %8s\n", "t",
            "steps cpu", "gpu", "differing", "max|diff|", "relL2(h)",
            "relL2(m)", "max|hu|", "launches");
    }
    else
    {
        std::printf("%8s %8s %8s %10s %10s %10s %10s %10s %10s %10s %10s "
            "%8s\n", "t", "steps cpu", "gpu", "e_gpu(h)", "e_ulp(h)",
            "bound(h)", "e_gpu(m)", "e_ulp(m)", "bound(m)", "e_fd(h)",
            "e_fd(m)", "launches");
    }
    const bool covered = pb.params.entrainment.on();
    bool closed = true;
    for (int side = 0; side < 4; ++side)
    {
        closed = closed && pb.bc.type[side] == BCType::wall;
    }
    bool coverSame = true, nonNegative = true;
    double worstBalance = 0;
    bool allSame = true, clocksSame = true, moved = false, within = true;
    bool stepsClose = true, timesSame = true;
    double lastBoundH = 0;
    long chunks = 0;
    std::vector<State> cpuStates;
    for (std::size_t n = 0; n < times.size(); ++n)
    {
        const double t = times[n];
        cpu.advanceTo(t);
        if (wallChunks)
        {
            while (!gpu->advance(t, 0.0))
            {
                ++chunks;
            }
            ++chunks;
        }
        else
        {
            gpu->advanceTo(t);
        }
        cpuStates.push_back(state(cpu));
        const State a = state(*gpu);
        if (covered)
        {
            std::vector<Real> lc, ec, lg, eg;
            cpu.getCover(lc, ec);
            gpu->getCover(lg, eg);
            coverSame = coverSame && !lc.empty() && sameBits(lc, lg)
                && sameBits(ec, eg);
            for (std::size_t c = 0; c < lg.size(); ++c)
            {
                nonNegative = nonNegative && lg[c] >= 0 && eg[c] >= 0
                    && a.q[0][c] >= 0;
            }
            const Diagnostics dn = gpu->diagnostics();
            const double v0 = d0.volume + d0.layerVolume;
            worstBalance = std::max(worstBalance,
                std::fabs(dn.volume + dn.layerVolume - v0)/v0);
        }
        const Difference d = difference(a, cpuStates.back());
        const std::string launches =
            wallChunks ? std::to_string(chunks) : "-";
        moved = moved || d.maxHu > 0;
        clocksSame = clocksSame && cpu.steps() == gpu->steps()
            && cpu.time() == gpu->time() && cpu.lastDt() == gpu->lastDt();
        timesSame = timesSame && cpu.time() == gpu->time();
        stepsClose = stepsClose && std::labs(cpu.steps() - gpu->steps())
            <= 1 + cpu.steps()/100;
        if (exact)
        {
            std::printf("%8.3g %8ld %8ld %10ld %12.3e %12.3e %12.3e %10.3g "
                "%8s\n", t, cpu.steps(), gpu->steps(), d.differing, d.maxAbs,
                d.relL2h, d.relL2m, d.maxHu, launches.c_str());
            allSame = allSame && d.differing == 0 && d.maxAbs == 0;
        }
        else
        {
            cpuUlp->advanceTo(t);
            const Difference up = difference(state(*cpuUlp), cpuStates.back());
            const Difference fd = difference(cpuStates.back(), (*cpuDouble)[n]);
            const double bh = floatFactor*up.relL2h + floatFloor;
            const double bm = floatFactor*up.relL2m + floatFloor;
            lastBoundH = bh;
            // At rest (zero reference momentum) relL2m is 0 only if the GPU
            // is at rest too
            const bool ok = d.relL2h <= bh && d.relL2m <= bm;
            std::printf("%8.3g %8ld %8ld %10.3e %10.3e %10.3e %10.3e %10.3e "
                "%10.3e %10.3e %10.3e %8s%s\n", t, cpu.steps(), gpu->steps(),
                d.relL2h, up.relL2h, bh, d.relL2m, up.relL2m, bm, fd.relL2h,
                fd.relL2m, launches.c_str(), ok ? "" : "  <- over");
            within = within && ok;
        }
    }
    test.check(moved && cpu.steps() > fixedSteps,
        prec + ": the flow moves (non-zero momentum at an output time)");
    if (exact)
    {
        const PeakMaps<Real> mc = cpu.peakMaps();
        const PeakMaps<Real> mg = gpu->peakMaps();
        const double top = mc.speed.empty() ? 0.0
            : double(*std::max_element(mc.speed.begin(), mc.speed.end()));
        test.check(!mc.h.empty() && mc.h == mg.h && mc.speed == mg.speed
            && top > 0, prec + fmt(": peak maps hMax, UMax bit-identical "
            "(max UMax %.4g)", top));
        const double pTop = mc.pressure.empty() ? 0.0
            : double(*std::max_element(mc.pressure.begin(), mc.pressure.end()));
        test.check(mc.pressure == mg.pressure && pTop > 0, prec
            + fmt(": pMax bit-identical (max %.4g Pa)", pTop));
        // Arrivals on host-given steps (before the first output time),
        // on device-clock steps and on steps ending at an output time
        long later = 0, onOutput = 0, early = 0;
        for (const float a : mc.arrival)
        {
            later += a > 0;
            early += a > 0 && a <= float(fixedEnd);
            for (const double t : times)
            {
                onOutput += a == float(t);
            }
        }
        std::vector<std::uint32_t> bc(mc.arrival.size()), bg(mg.arrival.size());
        std::memcpy(bc.data(), mc.arrival.data(), 4*bc.size());
        std::memcpy(bg.data(), mg.arrival.data(), 4*bg.size());
        // A lake at rest has nothing that arrives after t = 0; every other
        // case spreads, so arrivals must have been stamped
        test.check(bc == bg && (staticCase ? later == 0 : later > 0),
            prec + fmt(": tArrival bit-identical (%g cells arrived after t = 0",
            double(later)) + (staticCase ? ", none expected" : "")
          + fmt(", %g on the host-given steps", double(early))
          + fmt(", %g on steps ending at an output time)", double(onOutput)));
        test.check(allSame, prec + ": h, hu, hv bit-identical at every output time");
        test.check(clocksSame, prec + ": steps, time and last dt identical");
        const long long wc = cpu.wetCellUpdates();
        const long long wg = gpu->wetCellUpdates();
        test.check(wc == wg && wc > 0, prec + fmt(": wet cells counted over the "
            "steps identical (%.0f / %.0f)", double(wc), double(wg)));
    }
    else
    {
        test.check(within, prec + fmt(": relL2 of h and of (hu, hv) against "
            "the CPU <= %g x that of one ulp", floatFactor)
          + fmt(" + %g at every output time", floatFloor));
        test.check(timesSame, prec + ": output times hit exactly");
        test.check(stepsClose, prec + fmt(": steps within 1 %% (+1) of the "
            "CPU's (%g", double(cpu.steps()))
          + fmt(" vs %g)", double(gpu->steps())));
    }
    if (wallChunks)
    {
        test.check(chunks > long(times.size()), prec
            + fmt(": advance() returned on its wall budget (%g calls)",
                double(chunks)));
    }

    const Diagnostics dc = cpu.diagnostics();
    const Diagnostics dg = gpu->diagnostics();
    if (exact)
    {
        test.check
        (
            dc.volume == dg.volume && dc.wetCells == dg.wetCells
         && dc.movingCells == dg.movingCells && dc.maxRate == dg.maxRate
         && dc.hMax == dg.hMax,
            prec + fmt(": diagnostics identical (volume %.17g, ", dg.volume)
          + fmt("%g wet cells)", double(dg.wetCells))
        );
    }
    else
    {
        const double dv = std::fabs(dg.volume - dc.volume)/dc.volume;
        const double bh = lastBoundH;
        std::printf("diagnostics cpu / gpu: volume %.9g / %.9g, wet cells "
            "%ld / %ld, moving %ld / %ld, max rate %.7g / %.7g, hMax %.7g / "
            "%.7g\n", dc.volume, dg.volume, dc.wetCells, dg.wetCells,
            dc.movingCells, dg.movingCells, dc.maxRate, dg.maxRate, dc.hMax,
            dg.hMax);
        test.check(dv <= bh, prec + fmt(": volume within the bound of h "
            "(relative difference %.3e", dv) + fmt(" <= %.3e)", bh));
    }
    if (covered)
    {
        const Diagnostics dn = gpu->diagnostics();
        std::printf("cover on the GPU: layer %.9g -> %.9g, eroded %.9g, "
            "flowing %.9g -> %.9g (volumes); worst relative change of "
            "flowing + erodible %.3e%s\n", d0.layerVolume, dn.layerVolume,
            dn.erodedVolume, d0.volume, dn.volume, worstBalance,
            closed ? "" : " (open sides: not conserved)");
        if (exact)
        {
            test.check(coverSame, prec + ": layer left and eroded depth "
                "bit-identical at every output time");
            test.check(dc.layerVolume == dg.layerVolume
                && dc.erodedVolume == dg.erodedVolume, prec
              + fmt(": layer and eroded volumes identical (%.17g", dg.layerVolume)
              + fmt(", %.17g)", dg.erodedVolume));
        }
        test.check(dg.erodedVolume > 0, prec + fmt(": material taken up "
            "(eroded volume %.4g > 0)", dg.erodedVolume));
        test.check(nonNegative, prec + ": layer, eroded depth and h never "
            "negative at the output times");
        if (closed)
        {
            const double bound = dbl ? 1e-12 : 1e-5;
            test.check(worstBalance <= bound, prec + fmt(": closed: flowing "
                "+ erodible volume conserved (%.2e", worstBalance)
              + fmt(" <= %g)", bound));
        }
    }
    gpuFinal = state(*gpu);
    return cpuStates;
}

template<class Problem>
int run
(
    const Problem& makeDouble,
    const std::vector<double>& times,
    bool wallChunks,
    int fixedSteps
)
{
    Counter test;
    State d, f;
    const std::vector<State> cpuDouble = compareRun(test,
        shcases::withHazardMaps(makeDouble(double(0))),
        times, wallChunks, fixedSteps, nullptr, d);
    compareRun(test, shcases::withHazardMaps(makeDouble(float(0))), times,
        wallChunks, fixedSteps,
        &cpuDouble, f);
    const Difference fd = difference(f, d);
    std::printf("\nfloat on the GPU against double on the GPU, at t = %g: "
        "max|diff| %.3e, relL2(h) %.3e, relL2(hu, hv) %.3e (for "
        "information)\n", times.back(), fd.maxAbs, fd.relL2h, fd.relL2m);
    return test.finish();
}

} // namespace


int main(int argc, char** argv)
{
    const std::string which = argc > 1 ? argv[1] : "";
    std::string why;
    if (!cudaAvailable(&why))
    {
        std::printf("gpuCompare %s: SKIPPED: %s\n", which.c_str(), why.c_str());
        return 77;
    }

    if (which == "damBreak")
    {
        std::printf("Dam break, section 5.1, t = 0.5 s\n");
        return run([](auto r) { return shcases::damBreak<decltype(r)>(256); },
            {0.1, 0.25, 0.5}, false, 3);
    }
    if (which == "collapsingPile")
    {
        std::printf("Collapsing pile, section 5.2, to rest at t = 4 s\n");
        return run([](auto r) { return shcases::collapsingPile<decltype(r)>(64); },
            {0.1, 0.5, 1, 2, 4}, true, 0);
    }
    if (which == "lakeAtRest")
    {
        staticCase = true;
        std::printf("Lake at rest with a shoreline, active/passive K, 64x64, t = 1 s\n");
        return run([](auto r) { return shcases::lakeAtRest<decltype(r)>(64); },
            {0.25, 0.5, 1}, false, 0);
    }
    if (which == "inclinedPlane")
    {
        std::printf("Inclined plane, section 5.3, mesh 4x4x(30x14), t = 24\n");
        return run([](auto r) { return shcases::inclinedPlane<decltype(r)>(4); },
            {6, 12, 24}, false, 0);
    }
    if (which == "inflowPlane")
    {
        std::printf("Inclined plane fed by inflow at x = 0, walls at y = -+7, "
            "mesh 2x2x(30x14), t = 12\n");
        return run([](auto r) { return shcases::inflowPlane<decltype(r)>(2); },
            {3, 6, 12}, false, 2);
    }
    if (which == "granularJet")
    {
        std::printf("Granular jet, section 5.4, Pouliquen-Forterre friction, "
            "128x64, t = 0.5 s\n");
        return run([](auto r) { return shcases::granularJet<decltype(r)>(128); },
            {0.1, 0.25, 0.5}, false, 3);
    }
    if (which == "voellmyPile")
    {
        std::printf("Collapsing pile with Voellmy friction, 64x64, t = 2 s\n");
        return run([](auto r) { return shcases::voellmyPile<decltype(r)>(64); },
            {0.1, 0.5, 1, 2}, false, 0);
    }
    if (which == "openLake")
    {
        staticCase = true;
        std::printf("Lake at rest with K != 1, open sides, 97x41, t = 1 s\n");
        return run([](auto r) { return shcases::openLake<decltype(r)>(); },
            {0.25, 0.5, 1}, false, 2);
    }
    if (which == "outflowCorner")
    {
        std::printf("Pile leaving through the corner of open sides, 97x41, t = 2 s\n");
        return run([](auto r) { return shcases::outflowCorner<decltype(r)>(); },
            {0.5, 1, 2}, false, 3);
    }
    if (which == "planBumpyDem")
    {
        std::printf("Plan coordinates: a pile released on a bumpy DEM at 30 deg"
            " running out onto a flat floor, a pile at rest there, 97x41,"
            " t = 3 s\n");
        return run([](auto r) { return shcases::planBumpyDem<decltype(r)>(); },
            {0.5, 1.5, 3}, false, 3);
    }
    if (which == "planFlatPile")
    {
        std::printf("Plan coordinates: a pile collapsing on a flat floor"
            " (constant bed), walls, 64x64, t = 0.6 s\n");
        return run([](auto r) { return shcases::planFlatPile<decltype(r)>(64); },
            {0.1, 0.3, 0.6}, true, 0);
    }
    if (which == "coverPile" || which == "planCoverPile" || which == "planCoverDem")
    {
        int failed = 0;
        forEachEntrainmentModel([&](auto model)
        {
            using M = decltype(model);
            const EntrainmentModel e = entrainmentModelOf(model);
            if (e == EntrainmentModel::NoEntrainment)
            {
                return;
            }
            std::printf("\n==== entrainmentModel %s (shcases::smallScaleCover) ====\n",
                M::name);
            if (which == "coverPile")
            {
                std::printf("Collapsing pile in its bowl (walls) over an "
                    "erodible ring, a resistance patch, 64x64, t = 2 s\n");
                failed += run([e](auto r) { return shcases::coverPile<decltype(r)>(e, 64); },
                    {0.1, 0.5, 1, 2}, true, 2);
            }
            else if (which == "planCoverPile")
            {
                std::printf("Plan coordinates: planFlatPile (walls) over an "
                    "erodible ring, a resistance patch, 64x64, t = 0.6 s\n");
                failed += run([e](auto r) { return shcases::planCoverPile<decltype(r)>(e, 64); },
                    {0.1, 0.3, 0.6}, false, 2);
            }
            else
            {
                std::printf("Plan coordinates: planBumpyDem with an erodible "
                    "run-out and a resistance patch, 97x41, t = 3 s\n");
                failed += run([e](auto r) { return shcases::planCoverDem<decltype(r)>(e); },
                    {0.5, 1.5, 3}, false, 3);
            }
        });
        return failed ? 1 : 0;
    }
    std::fprintf(stderr, "usage: gpuCompare damBreak|collapsingPile|"
        "lakeAtRest|inclinedPlane|inflowPlane|granularJet|voellmyPile|"
        "openLake|outflowCorner|planBumpyDem|planFlatPile|coverPile|"
        "planCoverPile|planCoverDem\n");
    return 2;
}

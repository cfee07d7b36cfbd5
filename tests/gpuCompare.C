/*---------------------------------------------------------------------------*\
  GPU against CPU: the CUDA backend must reproduce the CPU backend

    Usage: gpuCompare damBreak|collapsingPile|inclinedPlane|inflowPlane

    Runs the case on the CPU backend (OpenMP) and on the CUDA backend, in
    double and in float, and compares the states at several output times.

    Tolerance, both precisions: none.  The two backends call the same
    functions (physics/scheme.H) on the same inputs in the same order, with
    IEEE-rounded +, -, *, /, sqrt and no contraction into FMA on either
    side (cuda/cudaSolver.cu), and the only reductions are maxima; so every
    value of h, hu, hv must be bit-identical, and so must the number of
    steps, the time and the last time step.  The test prints the number of
    differing values, max |difference| and the relative L2 norm of the
    difference of h, ||h_gpu - h_cpu||_2 / ||h_cpu||_2, which are all zero
    when it passes.  For information it also prints the distance of the
    float result from the double one (a property of the scheme in float, not
    of the backend).

    The paths through the device clock are all exercised: Solver::step with
    a host-given dt, advanceTo over one and many graph launches, advance()
    returning after its wall-time budget (collapsingPile: a budget of 0 s,
    so one graph per call) and stableDt.

    Without a usable GPU (no CUDA in the build, no device) the test prints
    why and exits with 77, which CTest reports as skipped.
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "gpuCases.H"
#include "cuda/cudaSolver.H"

#include <cstring>
#include <memory>

using namespace sh;
using namespace shtest;

namespace
{

struct Difference
{
    long differing = 0;     //!< values whose bits differ
    double maxAbs = 0;      //!< max |gpu - cpu| over h, hu, hv
    double relL2h = 0;      //!< ||h_gpu - h_cpu|| / ||h_cpu||
    double maxHu = 0;       //!< max |hu| + |hv| of the reference (non-trivial)
};

template<class A, class B>
Difference difference
(
    const std::vector<A> (&gpu)[3],
    const std::vector<B> (&ref)[3]
)
{
    Difference d;
    double e2 = 0, r2 = 0;
    for (int k = 0; k < 3; ++k)
    {
        for (std::size_t c = 0; c < ref[k].size(); ++c)
        {
            const double a = double(gpu[k][c]);
            const double b = double(ref[k][c]);
            if (sizeof(A) == sizeof(B))
            {
                d.differing += std::memcmp(&gpu[k][c], &ref[k][c], sizeof(A)) != 0;
            }
            d.maxAbs = std::max(d.maxAbs, std::fabs(a - b));
            if (k == 0)
            {
                e2 += (a - b)*(a - b);
                r2 += b*b;
            }
            else
            {
                d.maxHu = std::max(d.maxHu, std::fabs(b));
            }
        }
    }
    d.relL2h = r2 > 0 ? std::sqrt(e2/r2) : 0;
    return d;
}

template<class Real>
void state(Solver<Real>& s, std::vector<Real> (&q)[3])
{
    s.getState(q[0], q[1], q[2]);
}

//- Run cpu and gpu through the output times and compare at each; returns
//  the GPU's final state
template<class Real>
void compareRun
(
    Counter& test,
    const Problem<Real>& pb,
    const std::vector<double>& times,
    bool wallChunks,
    int fixedSteps,
    std::vector<Real> (&gpuFinal)[3]
)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    CpuSolver<Real> cpu(pb, true);
    std::unique_ptr<Solver<Real>> gpu = makeCudaSolver(pb);
    std::printf("\n%s: %s against %s, %dx%d cells\n", prec,
        gpu->name().c_str(), cpu.name().c_str(), pb.grid.nx, pb.grid.ny);

    const Real dtCpu = cpu.stableDt();
    const Real dtGpu = gpu->stableDt();
    test.check(dtCpu == dtGpu, std::string(prec) + fmt(": stableDt identical (%.17g", double(dtCpu))
        + fmt(" vs %.17g)", double(dtGpu)));
    for (int k = 0; k < fixedSteps; ++k)
    {
        cpu.step(Real(0.5)*dtCpu);
        gpu->step(Real(0.5)*dtCpu);
    }

    std::printf("%8s %8s %8s %10s %12s %12s %10s %8s\n", "t", "steps cpu",
        "gpu", "differing", "max|diff|", "relL2(h)", "max|hu|", "launches");
    bool allSame = true, clocksSame = true, moved = false;
    long chunks = 0;
    std::vector<Real> a[3], b[3];
    for (const double t : times)
    {
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
        state(cpu, b);
        state(*gpu, a);
        const Difference d = difference(a, b);
        std::printf("%8.3g %8ld %8ld %10ld %12.3e %12.3e %10.3g %8s\n", t,
            cpu.steps(), gpu->steps(), d.differing, d.maxAbs, d.relL2h,
            d.maxHu, wallChunks ? std::to_string(chunks).c_str() : "-");
        allSame = allSame && d.differing == 0 && d.maxAbs == 0;
        clocksSame = clocksSame && cpu.steps() == gpu->steps()
            && cpu.time() == gpu->time() && cpu.lastDt() == gpu->lastDt();
        moved = moved || d.maxHu > 0;
    }
    test.check(moved && cpu.steps() > fixedSteps,
        std::string(prec) + ": the flow moves (non-zero momentum at an output time)");
    test.check(allSame, std::string(prec) + ": h, hu, hv bit-identical at every output time");
    test.check(clocksSame, std::string(prec) + ": steps, time and last dt identical");
    if (wallChunks)
    {
        test.check(chunks > long(times.size()), std::string(prec)
            + fmt(": advance() returned on its wall budget (%g calls)",
                double(chunks)));
    }

    const Diagnostics dc = cpu.diagnostics();
    const Diagnostics dg = gpu->diagnostics();
    test.check
    (
        dc.volume == dg.volume && dc.wetCells == dg.wetCells
     && dc.movingCells == dg.movingCells && dc.maxRate == dg.maxRate
     && dc.hMax == dg.hMax,
        std::string(prec) + fmt(": diagnostics identical (volume %.17g, ", dg.volume)
      + fmt("%g wet cells)", double(dg.wetCells))
    );
    state(*gpu, gpuFinal);
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
    std::vector<double> d[3];
    std::vector<float> f[3];
    compareRun(test, makeDouble(double(0)), times, wallChunks, fixedSteps, d);
    compareRun(test, makeDouble(float(0)), times, wallChunks, fixedSteps, f);
    const Difference fd = difference(f, d);
    std::printf("\nfloat on the GPU against double, at t = %g: max|diff| %.3e, "
        "relL2(h) %.3e (for information)\n", times.back(), fd.maxAbs, fd.relL2h);
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
            {0.5, 1, 2, 4}, true, 0);
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
    std::fprintf(stderr, "usage: gpuCompare "
        "damBreak|collapsingPile|inclinedPlane|inflowPlane\n");
    return 2;
}

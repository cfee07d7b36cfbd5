/*---------------------------------------------------------------------------*\
  Decomposed CPU runs against the whole run, bit for bit

    Usage: mpiexec -np P parallelCpu px py          (P = px py)

    The MPI transport first (tests/common/mpiHaloCheck.H): exchange of ghost
    layers checked against a function of the whole-grid index, the
    reductions, and the refusal of subdomains that do not fit together.

    Then the cases of tests/common/parallelCases.H, each in double and in float,
    as tests/common/parallelCompare.H describes: each rank runs its subdomain
        CpuSolver<Real>(subProblem(whole, splitGrid(nx, ny, px, py, r)),
                        false, &halo)
    and rank 0 compares the parts, bit for bit, with the serial run
    CpuSolver<Real>(whole, false).  The exit code is non-zero on any
    failure, on every rank; an exception calls MPI_Abort.
\*---------------------------------------------------------------------------*/

#include "parallelCompare.H"

#include "cpu/cpuSolver.H"

#include <cstdio>
#include <vector>

using namespace sh;
using namespace shtest;

namespace
{

template<class Real>
Backends<Real> cpuBackends()
{
    Backends<Real> b;
    b.part = [](const Problem<Real>& pb, Halo<Real>* halo)
    {
        return std::unique_ptr<Solver<Real>>
        (
            new CpuSolver<Real>(pb, false, halo)
        );
    };
    b.whole = [](const Problem<Real>& pb)
    {
        return std::unique_ptr<Solver<Real>>(new CpuSolver<Real>(pb, false));
    };
    return b;
}

int run(MpiReport& t, int px, int py)
{
    if (t.root())
    {
        std::printf("\nMPI transport, %d ranks, split %dx%d\n\n", t.size, px, py);
    }
    haloExchangeCheck<double>(t, 13, 11, px, py);
    haloExchangeCheck<float>(t, 13, 11, px, py);
    haloExchangeCheck<double>(t, 200, 180, px, py);
    haloReductionCheck<double>(t, px, py);
    haloReductionCheck<float>(t, px, py);
    haloRefusalChecks(t, px, py);

    std::vector<Row> rows;
    runCases<double>(t, px, py, cpuBackends<double>(), rows);
    runCases<float>(t, px, py, cpuBackends<float>(), rows);
    if (t.root())
    {
        printTable
        (
            rows,
            "Decomposed CPU runs against the serial CPU run"
        );
    }
    return t.finish();
}

} // namespace


int main(int argc, char** argv)
{
    return mpiTestMain(argc, argv, "parallelCpu", run);
}

/*---------------------------------------------------------------------------*\
  Decomposed CUDA runs against the whole run, bit for bit

    Usage: mpiexec -np P parallelGpu px py          (P = px py)

    Each rank takes a GPU, the node-local rank (MPI_Comm_split_type
    SHARED) mod the node's devices, so that 4 ranks share 1 or 2 GPUs, and
    runs its subdomain of each case of tests/common/parallelCases.H on it,
        makeCudaSolver<Real>(subProblem(whole, splitGrid(nx, ny, px, py, r)),
                             &halo)
    as tests/common/parallelCompare.H describes (to the end time through
    advance(), which keeps the clock on the device, first stopped by rank
    0's wall budget; or 40 steps beyond the CFL limit through step()).
    Rank 0 compares the parts bit for bit with the serial run of the whole
    problem:
      double  the CPU backend, CpuSolver<double>(whole, false): the
              reference, which the serial CUDA run equals bit for bit
              (tests/backends/gpuCompare.C)
      float   the CUDA backend, makeCudaSolver<float>(whole): both runs
              execute the same device code on the same inputs, so they
              agree bit for bit in every build, with SH_CUDA_FLOAT_APPROX
              =ON too (which only parts them from the CPU's float)
    Without a usable GPU on every rank it prints "SKIPPED: ..." and exits
    77 on every rank (CTest's SKIP_RETURN_CODE).  The exit code is
    non-zero on any failure, on every rank; an exception calls MPI_Abort.
\*---------------------------------------------------------------------------*/

#include "parallelCompare.H"

#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"

#include <cstdio>
#include <string>
#include <vector>

using namespace sh;
using namespace shtest;

namespace
{

template<class Real>
std::unique_ptr<Solver<Real>> cudaPart(const Problem<Real>& pb, Halo<Real>* halo)
{
    return makeCudaSolver<Real>(pb, halo);
}

template<class Real>
std::unique_ptr<Solver<Real>> cudaWhole(const Problem<Real>& pb)
{
    return makeCudaSolver<Real>(pb);
}

std::unique_ptr<Solver<double>> cpuWhole(const Problem<double>& pb)
{
    return std::unique_ptr<Solver<double>>(new CpuSolver<double>(pb, false));
}

//- The node-local rank of this process (ranks sharing its memory)
int nodeRank()
{
    MPI_Comm node;
    MPI_Comm_split_type
    (
        MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node
    );
    int r = 0;
    MPI_Comm_rank(node, &r);
    MPI_Comm_free(&node);
    return r;
}

int run(MpiReport& t, int px, int py)
{
    // A GPU for this rank, or a reason why none is usable
    const int devices = cudaDeviceCount();
    const int local = nodeRank();
    if (devices > 0)
    {
        cudaSelectDevice(local % devices);
    }
    std::string why;
    const bool usable = cudaAvailable(&why);
    if (!t.allOk(usable))
    {
        if (t.root())
        {
            std::printf
            (
                "SKIPPED: %s\n",
                usable ? "a rank has no usable GPU" : why.c_str()
            );
        }
        return 77;
    }
    const std::string device = cudaDeviceDescription();
    std::printf
    (
        "rank %d: GPU %d of %d (node-local rank %d): %s\n", t.rank,
        local % devices, devices, local, device.c_str()
    );
    std::fflush(stdout);
    MPI_Barrier(MPI_COMM_WORLD);

    Backends<double> inDouble;
    inDouble.part = cudaPart<double>;
    inDouble.whole = cpuWhole;
    Backends<float> inFloat;
    inFloat.part = cudaPart<float>;
    inFloat.whole = cudaWhole<float>;

    std::vector<Row> rows;
    runCases<double>(t, px, py, inDouble, rows);
    runCases<float>(t, px, py, inFloat, rows);
    if (t.root())
    {
        printTable
        (
            rows,
            "Decomposed CUDA runs against the serial CPU run (double) and"
            " the serial CUDA run (float)"
        );
    }
    return t.finish();
}

} // namespace


int main(int argc, char** argv)
{
    return mpiTestMain(argc, argv, "parallelGpu", run);
}

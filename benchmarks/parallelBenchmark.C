/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    Decomposed runs, the rate of a fully wet flow over MPI ranks: the
    peers' dam break of docs/design.md section 4 (1.0 | 0.5 m at x = Lx/2,
    flat bed, 1 m cells, walls, g = 9.81, no friction, K = 1), each rank a
    rectangle of a px x py split (parallel/halo.H splitGrid), its Problem
    built on its own as the application builds it.  One rank runs the
    serial solver (no halo): the baseline of the scaling tables.

    Rate = cells of the whole grid x steps / wall time of the timed
    advance() (the slowest rank's: every rank steps alike), after a warm-up
    of a few steps; wet rate = the wet cells after each step, summed over
    the steps and the ranks, / the same wall time.  Both are printed as
    one markdown table row on rank 0, with the ranks, the split, the
    backend, the precision and the cells per rank.

    Usage: mpirun -np N parallelBenchmark [options]
      -backend cpu|cuda    (default cuda; cpu: OpenMP threads in each rank)
      -precision double|float
      -nx NX -ny NY        the whole grid (strong scaling; default 4320 x
                           2016, the 8.7M cells of the single-GPU tables)
      -weak NX NY          each rank NX x NY cells: the whole grid is
                           px NX x py NY (weak scaling)
      -split PX PY         the split (default: N x 1)
      -steps S             steps timed (about; default 200)
      -header              print the table's header first
\*---------------------------------------------------------------------------*/

#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"
#include "parallel/mpiHalo.H"
#include "host/modelInput.H"

#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace
{

struct Options
{
    std::string backend = "cuda";
    bool dbl = true;
    int nx = 4320;
    int ny = 2016;
    int weakNx = 0;
    int weakNy = 0;
    int px = 0;
    int py = 1;
    int steps = 200;
    bool header = false;
};


Options parse(int argc, char** argv, int size)
{
    Options o;
    for (int a = 1; a < argc; ++a)
    {
        const std::string k = argv[a];
        const auto next = [&]() -> const char*
        {
            if (a + 1 >= argc)
            {
                throw std::invalid_argument(k + " needs a value");
            }
            return argv[++a];
        };
        if (k == "-backend") { o.backend = next(); }
        else if (k == "-precision") { o.dbl = std::string(next()) == "double"; }
        else if (k == "-nx") { o.nx = std::atoi(next()); }
        else if (k == "-ny") { o.ny = std::atoi(next()); }
        else if (k == "-weak")
        {
            o.weakNx = std::atoi(next());
            o.weakNy = std::atoi(next());
        }
        else if (k == "-split")
        {
            o.px = std::atoi(next());
            o.py = std::atoi(next());
        }
        else if (k == "-steps") { o.steps = std::atoi(next()); }
        else if (k == "-header") { o.header = true; }
        else { throw std::invalid_argument("unknown option " + k); }
    }
    if (o.px == 0)
    {
        o.px = size;
        o.py = 1;
    }
    if (o.px*o.py != size)
    {
        throw std::invalid_argument
        (
            "-split " + std::to_string(o.px) + " " + std::to_string(o.py)
          + " does not give the " + std::to_string(size) + " ranks"
        );
    }
    if (o.backend != "cpu" && o.backend != "cuda")
    {
        throw std::invalid_argument("-backend cpu|cuda");
    }
    if (o.weakNx > 0)
    {
        o.nx = o.px*o.weakNx;
        o.ny = o.py*o.weakNy;
    }
    return o;
}


//- The rank's part of the dam break on nx x ny cells of 1 m
template<class Real>
sh::Problem<Real> damBreakPart(const sh::Subdomain& s)
{
    sh::ModelInput in;
    in.g = 9.81;
    in.earthPressure = sh::EarthPressureModel::isotropic;
    in.coulomb.deltaDeg = 0;
    in.phiDeg = 30;
    const double Lx = s.nxWhole;
    const double Ly = s.nyWhole;
    sh::Problem<Real> pb(sh::makeParams<Real>(in), s, 0, Lx, 0, Ly);
    for (int side = 0; side < 4; ++side)
    {
        if (!s.processorSide(side))
        {
            pb.bc.type[side] = sh::BCType::wall;
        }
    }
    pb.setState([Lx](double x, double)
    {
        return sh::Primitive{x < 0.5*Lx ? 1.0 : 0.5, 0, 0};
    });
    return pb;
}


template<class Real>
int run(const Options& o, int rank, int size, int localRank)
{
    const sh::Subdomain s = sh::splitGrid(o.nx, o.ny, o.px, o.py, rank);
    const sh::Problem<Real> pb = damBreakPart<Real>(s);
    std::unique_ptr<sh::Halo<Real>> halo;
    if (size > 1)
    {
        halo.reset(new sh::MpiHalo<Real>(MPI_COMM_WORLD, s));
    }
    std::unique_ptr<sh::Solver<Real>> solver;
    if (o.backend == "cuda")
    {
        const int devices = sh::cudaDeviceCount();
        if (devices < 1)
        {
            throw std::runtime_error("-backend cuda: no usable GPU");
        }
        sh::cudaSelectDevice(localRank % devices);
        solver = sh::makeCudaSolver<Real>(pb, halo.get());
    }
    else
    {
        solver.reset(new sh::CpuSolver<Real>(pb, true, halo.get()));
    }

    // Warm-up: a few steps (module load, graphs, buffers)
    const double dt0 = double(solver->stableDt());
    solver->advance(5*dt0, 1e300);
    MPI_Barrier(MPI_COMM_WORLD);

    using clock = std::chrono::steady_clock;
    const long steps0 = solver->steps();
    const long long wet0 = solver->wetCellUpdates();
    const double tEnd = solver->time() + o.steps*dt0;
    const clock::time_point t0 = clock::now();
    solver->advance(tEnd, 1e300);
    solver->diagnostics();      // the device done
    double wall = std::chrono::duration<double>(clock::now() - t0).count();
    MPI_Allreduce(MPI_IN_PLACE, &wall, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    const long steps = solver->steps() - steps0;
    const long long wet = solver->wetCellUpdates() - wet0;

    const double cells = double(o.nx)*o.ny;
    if (rank == 0)
    {
        if (o.header)
        {
            std::printf
            (
                "| ranks | split | backend | precision | cells | cells/rank"
                " | steps | wall [s] | cell updates/s | wet cell updates/s |\n"
                "|---:|---|---|---|---:|---:|---:|---:|---:|---:|\n"
            );
        }
        std::printf
        (
            "| %d | %dx%d | %s | %s | %.4g | %.4g | %ld | %.4f | %.3e | %.3e |\n",
            size, o.px, o.py, solver->name().c_str(),
            sizeof(Real) == 8 ? "double" : "float", cells, cells/size,
            steps, wall, cells*steps/wall, double(wet)/wall
        );
        std::fflush(stdout);
    }
    return 0;
}

} // namespace


int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1, localRank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm node;
    MPI_Comm_split_type
    (
        MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node
    );
    MPI_Comm_rank(node, &localRank);
    MPI_Comm_free(&node);
    int status = 0;
    try
    {
        const Options o = parse(argc, argv, size);
        status = o.dbl
            ? run<double>(o, rank, size, localRank)
            : run<float>(o, rank, size, localRank);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "parallelBenchmark (rank %d): %s\n", rank, e.what());
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Finalize();
    return status;
}

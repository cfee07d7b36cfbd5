/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    Speed of an ensemble: N variants of the section 5.3 inclined plane
    (tests/common/ensembleCases.H inclinedPlaneMembers: delta, phi, the friction
    law and its coefficients, the initial thickness) on k x k x (30 x 14)
    cells, from t = 0 to tEnd, run as one ensemble (batched:
    makeCudaEnsemble, all members in the same kernels; or makeCpuEnsemble)
    against the same members run one after the other as single runs
    (makeCudaSolver; CpuSolver with OpenMP).  The ensembles' target: 1000
    members on 120 x 56 cells (k = 4) at least 50 times faster batched
    than one after the other on one H200; also 100 members on 480 x 224
    (k = 16).

    Sequential runs take long (each single run of a small mesh is bound by
    the launches, not the GPU): -sequential S runs S of the members, spread
    evenly over them (the first and the last among them, so every friction
    law), and extrapolates their mean time to all members; the table says
    so ('~', "extrapolated from S").  Each of those members is checked
    bit for bit against its member of the batched run (state, hazard maps,
    clock): "batched = sequential" in the table.

    Walls: the time of advance() alone, batched and for each single run
    (the set-up, which a sequential sweep pays once per member, is given
    apart: upload, graphs).  Cell updates/s = sum over members of cells x
    steps / batched wall; wet cell updates/s the same over the cells wet
    after each step (EnsembleSolver::wetCellUpdates).

    Usage: ensembleBenchmark [options]
      -k K                  mesh k x k x (30 x 14) (default 4: 120 x 56)
      -members N            members (default 1000 for k <= 4, else 100)
      -tEnd T               end time (default 24, Table IV's runs)
      -sequential S         members run one after the other (default
                            min(N, 100); all: no extrapolation)
      -backend cuda|cpu     (default cuda)
      -precision double|single   (default double)
      -out FILE             append the table row to FILE (markdown; the
                            header first when FILE is empty or new)
\*---------------------------------------------------------------------------*/

#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"
#include "ensemble/ensembleSolver.H"
#include "ensembleCases.H"
#include "ensembleCompare.H"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace sh;

namespace
{

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

struct Options
{
    int k = 4;
    int members = 0;
    double tEnd = 24;
    int sequential = -1;
    bool cuda = true;
    bool dbl = true;
    std::string out;
};

//- Whether member m is bit for bit its single run (tests/common/ensembleCompare.H)
template<class Real>
bool sameRun(EnsembleSolver<Real>& e, int m, Solver<Real>& s)
{
    return shtest::compareMember(e, m, s).empty();
}

//- A benchmark's one pass in order (cases, batched run, sampled members one
//  by one, exactness, table row): kept in one piece so the timed sections
//  stand next to what they time.
template<class Real>
int run(const Options& o)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "single";
    const int n = o.members;
    const std::vector<Problem<Real>> members =
        shcases::inclinedPlaneMembers<Real>(o.k, n);
    const int nx = members[0].grid.nx;
    const int ny = members[0].grid.ny;
    const long cells = long(nx)*ny;
    std::fprintf(stderr, "== %d members, %s, %d x %d cells, t = 0..%g, %s\n",
        n, prec, nx, ny, o.tEnd, o.cuda ? "cuda" : "cpu");

    if (o.cuda)
    {
        // The context and the module loaded before anything is timed
        std::unique_ptr<Solver<Real>> warm = makeCudaSolver(members[0]);
        warm->stableDt();
    }

    // Batched
    const Clock::time_point t0 = Clock::now();
    std::unique_ptr<EnsembleSolver<Real>> e =
        o.cuda ? makeCudaEnsemble(members) : makeCpuEnsemble(members);
    const Clock::time_point t1 = Clock::now();
    const bool reached = e->advance(o.tEnd, 1e300);
    const Clock::time_point t2 = Clock::now();
    const double batchedSetup = seconds(t0, t1);
    const double batchedWall = seconds(t1, t2);
    double updates = 0;
    long lo = -1;
    long hi = 0;
    for (int m = 0; m < n; ++m)
    {
        updates += double(cells)*double(e->steps(m));
        lo = lo < 0 ? e->steps(m) : std::min(lo, e->steps(m));
        hi = std::max(hi, e->steps(m));
    }
    const double wet = double(e->wetCellUpdates());
    std::fprintf(stderr, "   batched: %s, %.3f s (set-up %.3f s), steps %ld"
        " .. %ld%s\n", e->name().c_str(), batchedWall, batchedSetup, lo, hi,
        reached ? "" : " (tEnd NOT reached)");

    // One after the other: S members spread over all, first and last
    const int S = std::max(1, std::min(n, o.sequential < 0 ? 100 : o.sequential));
    double seqWall = 0;
    double seqSetup = 0;
    int identical = 0;
    std::string single;
    for (int s = 0; s < S; ++s)
    {
        const int m = S == 1 ? 0 : int((long(s)*(n - 1) + (S - 1)/2)/(S - 1));
        const Clock::time_point a = Clock::now();
        std::unique_ptr<Solver<Real>> one = o.cuda
            ? makeCudaSolver(members[m])
            : std::unique_ptr<Solver<Real>>(new CpuSolver<Real>(members[m], true));
        const Clock::time_point b = Clock::now();
        one->advance(o.tEnd, 1e300);
        const Clock::time_point c = Clock::now();
        seqSetup += seconds(a, b);
        seqWall += seconds(b, c);
        single = one->name();
        if (sameRun(*e, m, *one))
        {
            ++identical;
        }
        else
        {
            std::fprintf(stderr, "   member %d: batched != sequential\n", m);
        }
    }
    const bool extrapolated = S < n;
    const double seqAll = seqWall/S*n;
    const double seqSetupAll = seqSetup/S*n;
    std::fprintf(stderr, "   sequential: %s, %d members %.3f s (set-up %.3f"
        " s)%s\n", single.c_str(), S, seqWall, seqSetup,
        extrapolated ? ", extrapolated to all" : "");

    char buf[1024];
    std::snprintf
    (
        buf, sizeof buf,
        "| %s | %d | %d x %d | %s | %g | %ld .. %ld | %.3f | %.3f | %s%.3f%s "
        "| %s%.3f | %s%.1f | %.3e | %.3e | %d of %d |\n",
        o.cuda ? "cuda" : "cpu", n, nx, ny, prec, o.tEnd, lo, hi,
        batchedWall, batchedSetup, extrapolated ? "~" : "", seqAll,
        extrapolated
          ? (" (extrapolated from " + std::to_string(S) + ")").c_str() : "",
        extrapolated ? "~" : "", seqSetupAll,
        extrapolated ? "~" : "", seqAll/batchedWall,
        updates/batchedWall, wet/batchedWall, identical, S
    );
    const std::string header =
        "| backend | members | mesh | precision | t | steps per member "
        "| batched wall [s] | batched set-up [s] | sequential wall [s] "
        "| sequential set-up [s] | speed-up | cell updates/s batched "
        "| wet cell updates/s batched | batched = sequential (bit for bit) |\n"
        "|---|---:|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
    std::printf("%s%s", header.c_str(), buf);
    if (!o.out.empty())
    {
        bool empty = true;
        {
            std::ifstream in(o.out);
            empty = !in || in.peek() == std::ifstream::traits_type::eof();
        }
        std::ofstream f(o.out, std::ios::app);
        if (empty)
        {
            f << header;
        }
        f << buf;
    }
    return reached && identical == S ? 0 : 1;
}

} // namespace


int main(int argc, char** argv)
{
    Options o;
    for (int a = 1; a < argc; ++a)
    {
        const std::string arg = argv[a];
        const char* next = a + 1 < argc ? argv[a + 1] : nullptr;
        auto need = [&]()
        {
            if (!next)
            {
                std::fprintf(stderr, "%s needs a value\n", arg.c_str());
                std::exit(2);
            }
            ++a;
            return std::string(next);
        };
        if (arg == "-k") { o.k = std::atoi(need().c_str()); }
        else if (arg == "-members") { o.members = std::atoi(need().c_str()); }
        else if (arg == "-tEnd") { o.tEnd = std::atof(need().c_str()); }
        else if (arg == "-sequential") { o.sequential = std::atoi(need().c_str()); }
        else if (arg == "-out") { o.out = need(); }
        else if (arg == "-backend")
        {
            const std::string b = need();
            if (b != "cuda" && b != "cpu")
            {
                std::fprintf(stderr, "-backend: cuda or cpu, not %s\n", b.c_str());
                return 2;
            }
            o.cuda = b == "cuda";
        }
        else if (arg == "-precision")
        {
            const std::string p = need();
            if (p != "double" && p != "single")
            {
                std::fprintf(stderr, "-precision: double or single, not %s\n", p.c_str());
                return 2;
            }
            o.dbl = p == "double";
        }
        else
        {
            std::fprintf(stderr, "unknown option %s (see the header of "
                "benchmarks/ensembleBenchmark.C)\n", arg.c_str());
            return 2;
        }
    }
    if (o.k < 1)
    {
        std::fprintf(stderr, "-k: at least 1\n");
        return 2;
    }
    if (o.members <= 0)
    {
        o.members = o.k <= 4 ? 1000 : 100;
    }
    std::string why;
    if (o.cuda && !cudaAvailable(&why))
    {
        std::fprintf(stderr, "ensembleBenchmark: no GPU: %s\n", why.c_str());
        return 77;
    }
    try
    {
        return o.dbl ? run<double>(o) : run<float>(o);
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "ensembleBenchmark: %s\n", e.what());
        return 1;
    }
}

/*---------------------------------------------------------------------------*\
  Ensembles on the CPU backend (ensemble/ensembleSolver.H)

    Members of tests/common/ensembleCases.H (the section 5.3 inclined plane with
    delta, phi, the friction law and its coefficients and the initial
    thickness varied), advanced together to t = 1.5, 3 and 6 (the second
    leg first stopped by a spent wall budget, then continued), against
    single runs of each member's problem advanced to the same end times
    (CpuSolver): h, hu, hv, hMax, speed, pressure, arrival, the time,
    steps and last dt, the diagnostics and speed clips, bit for bit
    (tests/common/ensembleCompare.H).  Members are picked at random
    (the seed is printed), always with the first and the last; both ways
    the CPU backend runs (OpenMP over members when there are at least as
    many members as threads; else member after member), double and float.
    Refused: an empty ensemble, and members with another grid, boundary
    condition, inclination or topography (std::invalid_argument naming
    the member).
\*---------------------------------------------------------------------------*/

#include "cpu/cpuSolver.H"
#include "ensemble/ensembleSolver.H"
#include "ensembleCases.H"
#include "ensembleCompare.H"
#include "testing.H"

#ifdef _OPENMP
#   include <omp.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

using namespace sh;
using shtest::Counter;
using shtest::compareMember;

namespace
{


template<class Real>
void exactness(Counter& t, int nMembers, int threads, unsigned seed)
{
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    const std::vector<Problem<Real>> members =
        shcases::inclinedPlaneMembers<Real>(1, nMembers);
    std::unique_ptr<EnsembleSolver<Real>> e = makeCpuEnsemble(members);
    const double ends[] = {1.5, 3, 6};

    e->advance(ends[0], 1e300);
    // A spent wall budget: advance() returns before the end, then goes on
    const bool early = e->advance(ends[1], 0.0);
    bool reached = e->advance(ends[1], 1e300);
    reached = e->advance(ends[2], 1e300) && reached;

    std::mt19937 rng(seed);
    std::vector<int> picks = {0};
    if (nMembers > 1)
    {
        picks.push_back(nMembers - 1);
    }
    std::uniform_int_distribution<int> pick(0, nMembers - 1);
    while (int(picks.size()) < std::min(nMembers, 6))
    {
        const int m = pick(rng);
        if (std::find(picks.begin(), picks.end(), m) == picks.end())
        {
            picks.push_back(m);
        }
    }
    std::string bad;
    std::printf
    (
        "\n  %s, %d members, %d threads (%s), members compared:",
        prec, nMembers, threads, e->name().c_str()
    );
    long steps = 0;
    for (int m : picks)
    {
        std::printf(" %d", m);
        CpuSolver<Real> single(members[m], true);
        single.advance(ends[0], 1e300);
        single.advance(ends[1], 1e300);
        single.advance(ends[2], 1e300);
        steps += single.steps();
        const std::string b = compareMember(*e, m, single);
        if (!b.empty())
        {
            bad += " member " + std::to_string(m) + ":" + b + ";";
        }
    }
    std::printf(" (%ld steps of theirs)\n", steps);
    t.check
    (
        !early && reached && bad.empty(),
        std::string(prec) + ", " + std::to_string(nMembers) + " members on "
      + std::to_string(threads) + " threads: each member bit for bit its"
        " single run at t = 6 (after a stop by the wall budget)"
      + (bad.empty() ? "" : " -" + bad)
    );
}

void refusals(Counter& t)
{
    const auto refused = [](std::vector<Problem<double>> ms)
    {
        try
        {
            makeCpuEnsemble(ms);
        }
        catch (const std::invalid_argument& e)
        {
            std::printf("    refused: %s\n", e.what());
            return true;
        }
        return false;
    };
    std::vector<Problem<double>> base = shcases::inclinedPlaneMembers<double>(1, 3);
    std::vector<Problem<double>> grid = base;
    grid[2] = shcases::inclinedPlaneMember<double>(2, 2);
    std::vector<Problem<double>> bc = base;
    bc[1].bc.type[yMin] = BCType::wall;
    std::vector<Problem<double>> zeta = base;
    zeta[1].setInclination([](double) { return 0.5; });
    std::vector<Problem<double>> zb = base;
    zb[2].setTopography([](double x, double) { return 0.01*x; });
    t.check
    (
        refused({}) && refused(grid) && refused(bc) && refused(zeta)
     && refused(zb),
        "an empty ensemble and members with another grid, side, inclination"
        " or topography refused"
    );
}

} // namespace


int main(int argc, char* argv[])
{
    const unsigned seed = argc > 1
        ? unsigned(std::stoul(argv[1]))
        : unsigned(std::chrono::system_clock::now().time_since_epoch().count() % 100000);
    std::printf("Ensembles on the CPU backend; members picked with seed %u\n", seed);
    Counter t;
    exactness<double>(t, 13, 2, seed);
    exactness<double>(t, 1, 2, seed);
    exactness<float>(t, 9, 2, seed + 1);
    exactness<double>(t, 5, 1, seed + 2);
    refusals(t);
    return t.finish();
}

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
    The bed's cover (coverExactness): every member of
    shcases::coveredPlaneMembers (an erodible layer across the track and
    a resistance patch; entrainment models none, constantRate at three
    rates and each other model of the list; resistance none or scaled by
    0.5, 1, 2; one member starting with an eroded depth) against its
    single run as above, the erodible layer left and the eroded depth
    too, with the layer and eroded volumes of the diagnostics; that the
    case does what it is for: the constantRate members take material up,
    the layer runs out somewhere, constantRate members of different rates
    end with different layers, and each member with a resistance ends
    elsewhere than its run without.
    Refused: an empty ensemble, and members with another grid, boundary
    condition, inclination or topography (std::invalid_argument naming
    the member); a member with a negative erodible thickness (InputError
    naming hEntrainable and the member).
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
#include <utility>

using namespace sh;
using shtest::Counter;
using shtest::compareMember;

namespace
{


//- The output times of the ensembles and their single runs
constexpr double ends[] = {1.5, 3, 6};

//- members as a CPU ensemble on threads through ends, stopped once by a
//  spent wall budget on the way to ends[1]
template<class Real>
struct StoppedRun
{
    std::unique_ptr<EnsembleSolver<Real>> e;
    bool early;     //!< whether advance() returned at the spent budget
                    //!< before reaching ends[1] (it must not have)
    bool reached;   //!< whether the advances after it reached their ends
};

template<class Real>
StoppedRun<Real> runWithStop
(
    const std::vector<Problem<Real>>& members,
    int threads
)
{
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    StoppedRun<Real> r;
    r.e = makeCpuEnsemble(members);
    r.e->advance(ends[0], 1e300);
    // A spent wall budget: advance() returns before the end, then goes on
    r.early = r.e->advance(ends[1], 0.0);
    r.reached = r.e->advance(ends[1], 1e300);
    r.reached = r.e->advance(ends[2], 1e300) && r.reached;
    return r;
}

//- A single run through ends
template<class Real>
void runSingle(Solver<Real>& s)
{
    for (const double tEnd : ends)
    {
        s.advance(tEnd, 1e300);
    }
}

template<class Real>
void exactness(Counter& t, int nMembers, int threads, unsigned seed)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    const std::vector<Problem<Real>> members =
        shcases::inclinedPlaneMembers<Real>(1, nMembers);
    StoppedRun<Real> run = runWithStop(members, threads);
    EnsembleSolver<Real>* e = run.e.get();
    const bool early = run.early;
    const bool reached = run.reached;

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
        runSingle(single);
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

template<class Real>
void coverExactness(Counter& t, int nMembers, int threads)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    const std::vector<Problem<Real>> members =
        shcases::coveredPlaneMembers<Real>(1, nMembers);
    StoppedRun<Real> run = runWithStop(members, threads);
    EnsembleSolver<Real>* e = run.e.get();
    const bool early = run.early;
    const bool reached = run.reached;
    std::printf
    (
        "\n  bed's cover, %s, %d members, %d threads (%s), every member"
        " compared:\n    member  model          c_res  eroded volume"
        "  layer volume  cells run out\n",
        prec, nMembers, threads, e->name().c_str()
    );

    std::string bad;
    bool rateEntrains = true;
    int runOut = 0;
    int resisting = 0;
    bool resistanceActs = true;
    //- The constantRate members' rates and layers left
    std::vector<std::pair<Real, std::vector<Real>>> layers;
    for (int m = 0; m < nMembers; ++m)
    {
        const Problem<Real>& pb = members[m];
        CpuSolver<Real> single(pb, true);
        runSingle(single);
        const std::string b = compareMember(*e, m, single);
        if (!b.empty())
        {
            bad += " member " + std::to_string(m) + ":" + b + ";";
        }
        const Diagnostics d = e->diagnostics(m);
        std::vector<Real> layer, eroded;
        e->getCover(m, layer, eroded);
        int out = 0;
        for (std::size_t c = 0; c < layer.size(); ++c)
        {
            out += pb.hEntrainable[c] > Real(0) && layer[c] == Real(0);
        }
        runOut += out;
        const EntrainmentModel model = pb.params.entrainment.model;
        if (model == EntrainmentModel::ConstantRate)
        {
            layers.emplace_back(pb.params.entrainment.constantRate.rate, layer);
        }
        if (model == EntrainmentModel::ConstantRate && !(d.erodedVolume > 0))
        {
            rateEntrains = false;
        }
        const double cRes = pb.cResistance.empty() ? 0.0
            : double(*std::max_element(pb.cResistance.begin(), pb.cResistance.end()));
        std::printf
        (
            "    %6d  %-13s %6.3f  %13.6g  %12.6g  %13d\n", m,
            toString(model).c_str(), cRes, d.erodedVolume, d.layerVolume, out
        );
        if (!pb.cResistance.empty())
        {
            // The same member without its resistance
            ++resisting;
            Problem<Real> bare = pb;
            bare.cResistance.clear();
            CpuSolver<Real> without(bare, true);
            runSingle(without);
            std::vector<Real> h, hu, hv, h1, hu1, hv1;
            e->getState(m, h, hu, hv);
            without.getState(h1, hu1, hv1);
            resistanceActs = resistanceActs && !shtest::same(h, h1);
        }
    }
    bool layersDiffer = true;
    int pairs = 0;
    for (std::size_t a = 0; a < layers.size(); ++a)
    {
        for (std::size_t b = a + 1; b < layers.size(); ++b)
        {
            if (layers[a].first != layers[b].first)
            {
                ++pairs;
                layersDiffer = layersDiffer
                 && !shtest::same(layers[a].second, layers[b].second);
            }
        }
    }
    t.check
    (
        !early && reached && bad.empty(),
        std::string("bed's cover, ") + prec + ", "
      + std::to_string(nMembers) + " members on "
      + std::to_string(threads) + " threads: each member bit for bit its"
        " single run at t = 6 (state, layer, eroded depth, maps, clock,"
        " diagnostics)" + (bad.empty() ? "" : " -" + bad)
    );
    t.check
    (
        rateEntrains && runOut > 0 && pairs > 0 && layersDiffer,
        std::string("bed's cover, ") + prec + ": every constantRate member"
        " took material up, the layer ran out in " + std::to_string(runOut)
      + " cells of the members, the layers of the " + std::to_string(pairs)
      + " pairs of constantRate members of different rates differ"
    );
    t.check
    (
        resisting > 0 && resistanceActs,
        std::string("bed's cover, ") + prec + ": each of the "
      + std::to_string(resisting) + " members with a resistance ends"
        " with another h than its run without"
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

    std::vector<Problem<double>> cover = shcases::coveredPlaneMembers<double>(1, 4);
    cover[3].hEntrainable[7] = -0.01;
    std::string what;
    try
    {
        makeCpuEnsemble(cover);
    }
    catch (const InputError& e)
    {
        std::printf("    refused: %s\n", e.what());
        what = e.keyword() + " | " + e.what();
    }
    t.check
    (
        what.find("hEntrainable |") == 0
     && what.find("member 3") != std::string::npos,
        "a member with a negative erodible thickness refused (InputError"
        " naming hEntrainable and member 3)"
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
    coverExactness<double>(t, 12, 2);
    coverExactness<float>(t, 10, 2);
    coverExactness<double>(t, 6, 1);
    refusals(t);
    return t.finish();
}

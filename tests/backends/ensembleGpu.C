/*---------------------------------------------------------------------------*\
  Ensembles on the CUDA backend (cuda/cudaEnsembleImpl.H)

    Members of tests/common/ensembleCases.H (the section 5.3 inclined plane with
    delta, phi, the friction law and its coefficients and the initial
    thickness varied), advanced together in the same kernels to t = 1.5,
    6 and 12 (the second leg with maxDt 0.02, ensemble and singles alike,
    so that it needs more steps than one graph holds: first stopped by a
    spent wall budget, after one graph of steps, then continued; the last advance repeated, which
    must change nothing), against single runs of each member's problem
    advanced to the same end times: h, hu, hv, hMax, speed, pressure,
    arrival, the time, steps and last dt and the diagnostics, bit for bit
    (memcmp), at every end time.  Double against CpuSolver, float against
    single CUDA runs (makeCudaSolver: the same kernels, so bit for bit
    also in a build with SH_CUDA_FLOAT_APPROX=ON).  Members compared:
    the first, the last, a Voellmy one (3), a Pouliquen-Forterre one (5)
    and others picked at random (the seed is printed; give it as the
    first argument to repeat a run).  Ensembles: 23 members on 30 x 14
    cells; 7 members on 60 x 28 launched 3 members at a time (the chunks
    of an ensemble of more than 65535 members: SH_ENSEMBLE_CHUNK); the
    sum of the wet cell updates over all members against the singles'
    where all are run.  Plan coordinates (PlanStages' batched kernels,
    planExactness): three members of tests/common/gpuCases.H planBumpyDem
    with delta and the release's thickness varied, 97 x 41 cells, to
    t = 0.5, 1 and 1.5 (a stop by the wall budget in the second leg),
    each member bit for bit its CpuSolver run (float: unless
    SH_CUDA_FLOAT_APPROX), its single CUDA run and its CPU ensemble's
    member; double in one launch, float 2 members a launch.  The bed's
    cover (coverExactness, the same comparisons, the erodible layer left,
    the eroded depth and their volumes besides): every member of
    tests/common/ensembleCases.H coveredPlaneMembers (13 members: an
    erodible layer and a resistance patch on the inclined plane;
    entrainment none, constantRate at three rates and each other model
    of the list, resistance none or scaled by 0.5, 1, 2) to t = 1.5, 6
    (maxDt 0.02, wall budget) and 12, in one launch and 4 members a
    launch; and the plan members with a cover (planMember covered: a
    layer on the DEM's slope, rates 0.05, 0.1 m/s and none, resistance
    scaled 1, 0, 2).  Refused:
    members with another grid, and a slope-coordinate member among plan
    ones (std::invalid_argument, as the CPU backend).

    Without a usable GPU (no CUDA in the build, no device) the test
    prints why and exits with 77, which CTest reports as skipped.
\*---------------------------------------------------------------------------*/

#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"
#include "ensemble/ensembleSolver.H"
#include "ensembleCompare.H"
#include "ensembleCases.H"
#include "testing.H"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

using namespace sh;
using shtest::Counter;
using shtest::compareMember;

namespace
{


//- The single run a member is compared with: CpuSolver in double, a
//  single CUDA run in float
std::unique_ptr<Solver<double>> singleRun(const Problem<double>& pb)
{
    return std::unique_ptr<Solver<double>>(new CpuSolver<double>(pb, true));
}

std::unique_ptr<Solver<float>> singleRun(const Problem<float>& pb)
{
    return makeCudaSolver(pb);
}

//- Kept in one piece: one test scenario read top to bottom (members,
//  batched and single runs, comparison, table, assertions).
template<class Real>
void exactness(Counter& t, int k, int nMembers, int chunk, unsigned seed)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    const char* against = sizeof(Real) == 8 ? "CpuSolver" : "single CUDA runs";
    if (chunk > 0)
    {
        setenv("SH_ENSEMBLE_CHUNK", std::to_string(chunk).c_str(), 1);
    }
    else
    {
        unsetenv("SH_ENSEMBLE_CHUNK");
    }
    const std::vector<Problem<Real>> members =
        shcases::inclinedPlaneMembers<Real>(k, nMembers);
    std::unique_ptr<EnsembleSolver<Real>> e = makeCudaEnsemble(members);
    unsetenv("SH_ENSEMBLE_CHUNK");

    // The first and the last, a Voellmy and a Pouliquen-Forterre member
    // (ensembleCases.H), then random ones
    std::mt19937 rng(seed);
    std::vector<int> picks;
    for (int m : {0, nMembers - 1, 3, 5})
    {
        if (m < nMembers && std::find(picks.begin(), picks.end(), m) == picks.end())
        {
            picks.push_back(m);
        }
    }
    std::uniform_int_distribution<int> pick(0, nMembers - 1);
    while (int(picks.size()) < std::min(nMembers, 8))
    {
        const int m = pick(rng);
        if (std::find(picks.begin(), picks.end(), m) == picks.end())
        {
            picks.push_back(m);
        }
    }
    const bool everyMember = int(picks.size()) == nMembers;
    std::printf
    (
        "\n  %s, %d members on %d x %d cells (%s), against %s; members"
        " compared:",
        prec, nMembers, members[0].grid.nx, members[0].grid.ny,
        e->name().c_str(), against
    );
    std::vector<std::unique_ptr<Solver<Real>>> singles;
    for (int m : picks)
    {
        std::printf(" %d", m);
        singles.push_back(singleRun(members[m]));
    }
    std::printf("\n");

    // Each end time: the ensemble, then the singles, then the comparison
    const double ends[] = {1.5, 6, 12};
    std::string bad;
    bool early = false;
    bool reached = true;
    for (int leg = 0; leg < 3; ++leg)
    {
        const double tEnd = ends[leg];
        // The second leg with maxDt 0.02 (ensemble and singles alike): at
        // least 225 steps, more than any one graph, so that the spent
        // wall budget surely stops it before tEnd
        const double maxDt = leg == 1 ? 0.02 : 1e30;
        e->setMaxDt(maxDt);
        for (auto& s : singles)
        {
            s->setMaxDt(maxDt);
        }
        if (leg == 1)
        {
            // A spent wall budget: one graph of steps, then on
            early = e->advance(tEnd, 0.0);
            int behind = 0;
            for (int m = 0; m < nMembers; ++m)
            {
                behind += e->time(m) < tEnd;
            }
            std::printf
            (
                "    to t = %g with a wall budget of 0 s: %s, %d of %d"
                " members short of it\n",
                tEnd, early ? "reached (not stopped)" : "stopped early",
                behind, nMembers
            );
        }
        reached = e->advance(tEnd, 1e300) && reached;
        if (leg == 2)
        {
            // Again to the same end: nothing to do
            reached = e->advance(tEnd, 1e300) && reached;
        }
        long steps = 0;
        long lo = -1;
        long hi = 0;
        for (std::size_t s = 0; s < picks.size(); ++s)
        {
            singles[s]->advance(tEnd, 1e300);
            steps += singles[s]->steps();
            const std::string b = compareMember(*e, picks[s], *singles[s]);
            if (!b.empty())
            {
                bad += " t = " + std::to_string(tEnd) + " member "
                  + std::to_string(picks[s]) + ":" + b + ";";
            }
        }
        for (int m = 0; m < nMembers; ++m)
        {
            lo = lo < 0 ? e->steps(m) : std::min(lo, e->steps(m));
            hi = std::max(hi, e->steps(m));
        }
        std::printf
        (
            "    t = %g: compared (%ld steps of theirs; every member's steps"
            " %ld .. %ld)\n", tEnd, steps, lo, hi
        );
    }
    if (everyMember)
    {
        long long wet = 0;
        for (auto& s : singles)
        {
            wet += s->wetCellUpdates();
        }
        if (wet != e->wetCellUpdates())
        {
            bad += " wet cell updates " + std::to_string(e->wetCellUpdates())
              + " against " + std::to_string(wet) + ";";
        }
    }
    t.check
    (
        !early && reached && bad.empty(),
        std::string(prec) + ", " + std::to_string(nMembers) + " members on "
      + std::to_string(members[0].grid.nx) + " x "
      + std::to_string(members[0].grid.ny)
      + (chunk > 0 ? ", " + std::to_string(chunk) + " per launch" : "")
      + ": each member bit for bit its single run at t = 1.5, 6 (maxDt"
        " 0.02, stopped by the wall budget, then on), 12"
      + (everyMember ? ", wet cell updates summed" : "")
      + (bad.empty() ? "" : " -" + bad)
    );
}

//- Member k of the plan-coordinate ensemble: tests/common/gpuCases.H
//  planBumpyDem (a pile released on a bumpy DEM, a small one on its
//  floor, 97 x 41 cells) with the friction angle delta and the release's
//  thickness scaled, hazard maps on
template<class Real>
Problem<Real> planMember(int k, bool covered = false)
{
    const double deltas[] = {24, 20, 27};
    const double scales[] = {1, 1.25, 0.75};
    const double delta = deltas[k % 3];
    const double scale = scales[k % 3];
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::activePassive;
    in.phiDeg = 32;
    in.coulomb.deltaDeg = delta;
    in.rho = 1500;
    in.arrivalThreshold = 0.004;
    // With the cover: constantRate at 0.05, 0.1 m/s and none
    const double rates[] = {0.05, 0.1, 0};
    if (covered && rates[k % 3] > 0)
    {
        in.entrainmentModel = EntrainmentModel::ConstantRate;
        in.constantRate.rate = rates[k % 3];
    }
    Problem<Real> pb = shcases::planProblem<Real>
    (
        in, 97, 41, 0, 9.7, -2.05, 2.05, shcases::planBumpyBed,
        [scale](double x, double y)
        {
            const double r2 = (x - 1.8)*(x - 1.8) + y*y;
            const double q2 = (x - 8.6)*(x - 8.6) + (y + 1.1)*(y + 1.1);
            const double h = r2 < 1.1*1.1
                ? 0.4*(1 - r2/(1.1*1.1))
                : (q2 < 0.5*0.5 ? 0.1*(1 - q2/(0.5*0.5)) : 0.0);
            return Primitive{scale*h, 0, 0};
        }
    );
    pb.bc.type[xMin] = BCType::wall;
    pb.bc.type[yMin] = BCType::wall;
    if (covered)
    {
        // A layer of 0.03 m (per plan area) below x = 6, a resistance
        // patch of 0.5 [1/m] times 1, 0, 2 beyond x = 4
        const double cScale[] = {1, 0, 2};
        const Grid<Real>& g = pb.grid;
        pb.hEntrainable.assign(pb.nCells(), Real(0));
        if (cScale[k % 3] > 0)
        {
            pb.cResistance.assign(pb.nCells(), Real(0));
        }
        for (int j = 0; j < g.ny; ++j)
        {
            for (int i = 0; i < g.nx; ++i)
            {
                const double x = double(g.xc(i));
                if (x > 2.5 && x < 6)
                {
                    pb.hEntrainable[pb.cell(i, j)] = Real(0.03);
                }
                if (cScale[k % 3] > 0 && x > 4)
                {
                    pb.cResistance[pb.cell(i, j)] = Real(0.5*cScale[k % 3]);
                }
            }
        }
    }
    return pb;
}

//- everyMember (below): every member of an ensemble against its single
//  runs at three end times; returns the members' eroded volume at the end
template<class Real>
double everyMember
(
    Counter& t,
    const std::vector<Problem<Real>>& members,
    int chunk,
    const std::string& what,
    const std::string& where,
    const std::array<double, 3>& ends,
    double legDt
);

//- An ensemble in plan coordinates (PlanStages' batched kernels): three
//  members of planMember (delta 24, 20, 27 deg; release x 1, 1.25, 0.75),
//  batched on the GPU, advanced to t = 0.5, 1 and 1.5 (the second leg
//  with maxDt 0.002, so that it needs more steps than one graph holds:
//  first stopped by a spent wall budget, then continued), every member
//  compared at every end time, bit for bit (compareMember: h, hu, hv,
//  hMax, speed, pressure, arrival, t, steps, last dt, diagnostics, speed
//  clips), with its CPU single run (CpuSolver), its single CUDA run
//  (makeCudaSolver) and its member of the CPU ensemble (makeCpuEnsemble);
//  in float against the CPU only where the float kernels are IEEE-rounded
//  (not SH_CUDA_FLOAT_APPROX).  chunk > 0: launched chunk members at a
//  time (SH_ENSEMBLE_CHUNK).
template<class Real>
void planExactness(Counter& t, int chunk)
{
    std::vector<Problem<Real>> members;
    for (int k = 0; k < 3; ++k)
    {
        members.push_back(planMember<Real>(k));
    }
    everyMember
    (
        t, members, chunk, "plan coordinates",
        "members on bumpy DEM", {0.5, 1.0, 1.5}, 0.002
    );
}

//- The bed's cover: coveredPlaneMembers (tests/common/ensembleCases.H)
//  and the plan members with a cover, each member compared as
//  planExactness compares them (the layer left and the eroded depth
//  too: compareMember)
template<class Real>
void coverExactness(Counter& t, int chunk)
{
    const double onPlane = everyMember
    (
        t, shcases::coveredPlaneMembers<Real>(1, 13), chunk,
        "bed's cover", "members on the plane", {1.5, 6, 12}, 0.02
    );
    std::vector<Problem<Real>> plan;
    for (int k = 0; k < 3; ++k)
    {
        plan.push_back(planMember<Real>(k, true));
    }
    const double onDem = everyMember
    (
        t, plan, chunk, "bed's cover in plan coordinates",
        "members on bumpy DEM", {0.5, 1.0, 1.5}, 0.002
    );
    std::printf
    (
        "    eroded volume of all members: %g (plane), %g (DEM)\n",
        onPlane, onDem
    );
    t.check
    (
        onPlane > 0 && onDem > 0,
        std::string("bed's cover, ") + (sizeof(Real) == 8 ? "double" : "float")
      + ": the members take material up, on the plane and on the DEM"
    );
}

//- Every member of an ensemble of members, batched on the GPU and
//  advanced to ends[0], ends[1] (maxDt legDt, first stopped by a spent
//  wall budget) and ends[2], against its single CUDA run and, where the
//  float kernels are IEEE-rounded, its CpuSolver run and its member of
//  the CPU ensemble, bit for bit at each end time (compareMember); the
//  wet cell updates summed against the single CUDA runs'
template<class Real>
double everyMember
(
    Counter& t,
    const std::vector<Problem<Real>>& members,
    int chunk,
    const std::string& what,
    const std::string& where,
    const std::array<double, 3>& ends,
    double legDt
)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    const bool againstCpu = sizeof(Real) == 8 || !cudaFloatApproximate();
    const int nMembers = int(members.size());
    if (chunk > 0)
    {
        setenv("SH_ENSEMBLE_CHUNK", std::to_string(chunk).c_str(), 1);
    }
    else
    {
        unsetenv("SH_ENSEMBLE_CHUNK");
    }
    std::unique_ptr<EnsembleSolver<Real>> e = makeCudaEnsemble(members);
    unsetenv("SH_ENSEMBLE_CHUNK");
    // The CPU's runs: only where the GPU's float is IEEE-rounded
    std::unique_ptr<EnsembleSolver<Real>> cpuEnsemble =
        againstCpu ? makeCpuEnsemble(members) : nullptr;
    std::vector<std::unique_ptr<Solver<Real>>> cpu, gpu;
    for (int m = 0; m < nMembers; ++m)
    {
        if (againstCpu)
        {
            cpu.emplace_back(new CpuSolver<Real>(members[m], true));
        }
        gpu.push_back(makeCudaSolver(members[m]));
    }
    std::printf
    (
        "\n  %s, %s, %d members on %d x %d cells (%s), against"
        " the single CUDA runs%s\n",
        what.c_str(), prec, nMembers, members[0].grid.nx, members[0].grid.ny,
        e->name().c_str(),
        againstCpu ? ", CpuSolver and the CPU ensemble's members" : ""
    );

    std::string bad;
    bool early = false;
    bool reached = true;
    for (int leg = 0; leg < 3; ++leg)
    {
        const double tEnd = ends[leg];
        const double maxDt = leg == 1 ? legDt : 1e30;
        e->setMaxDt(maxDt);
        if (cpuEnsemble) { cpuEnsemble->setMaxDt(maxDt); }
        for (auto& s : cpu) { s->setMaxDt(maxDt); }
        for (auto& s : gpu) { s->setMaxDt(maxDt); }
        if (leg == 1)
        {
            early = e->advance(tEnd, 0.0);
            int behind = 0;
            for (int m = 0; m < nMembers; ++m)
            {
                behind += e->time(m) < tEnd;
            }
            std::printf
            (
                "    to t = %g with a wall budget of 0 s: %s, %d of %d"
                " members short of it\n",
                tEnd, early ? "reached (not stopped)" : "stopped early",
                behind, nMembers
            );
        }
        reached = e->advance(tEnd, 1e300) && reached;
        if (againstCpu)
        {
            cpuEnsemble->advance(tEnd, 1e300);
        }
        const std::string at = " t = " + std::to_string(tEnd) + " member ";
        long lo = -1;
        long hi = 0;
        for (int m = 0; m < nMembers; ++m)
        {
            gpu[m]->advance(tEnd, 1e300);
            std::string b = compareMember(*e, m, *gpu[m]);
            if (!b.empty())
            {
                bad += at + std::to_string(m) + " (single CUDA):" + b + ";";
            }
            if (againstCpu)
            {
                b = compareMember(*e, m, *cpuEnsemble);
                if (!b.empty())
                {
                    bad += at + std::to_string(m) + " (CPU ensemble):" + b
                      + ";";
                }
                cpu[m]->advance(tEnd, 1e300);
                b = compareMember(*e, m, *cpu[m]);
                if (!b.empty())
                {
                    bad += at + std::to_string(m) + " (CpuSolver):" + b + ";";
                }
            }
            lo = lo < 0 ? e->steps(m) : std::min(lo, e->steps(m));
            hi = std::max(hi, e->steps(m));
        }
        std::printf
        (
            "    t = %g: compared (every member's steps %ld .. %ld)\n",
            tEnd, lo, hi
        );
    }
    long long wet = 0;
    for (auto& s : gpu)
    {
        wet += s->wetCellUpdates();
    }
    if (wet != e->wetCellUpdates())
    {
        bad += " wet cell updates " + std::to_string(e->wetCellUpdates())
          + " against " + std::to_string(wet) + ";";
    }
    const auto num = [](double x)
    {
        char b[32];
        std::snprintf(b, sizeof b, "%g", x);
        return std::string(b);
    };
    t.check
    (
        !early && reached && bad.empty(),
        what + ", " + prec + ", " + std::to_string(nMembers) + " " + where
      + " " + std::to_string(members[0].grid.nx) + " x "
      + std::to_string(members[0].grid.ny)
      + (chunk > 0 ? ", " + std::to_string(chunk) + " per launch" : "")
      + ": each member bit for bit its single CUDA run"
      + (againstCpu ? ", CpuSolver run and CPU ensemble member" : "")
      + " at t = " + num(ends[0]) + ", " + num(ends[1]) + " (maxDt "
      + num(legDt) + ", stopped by the wall budget, then on), "
      + num(ends[2]) + ", wet cell updates summed"
      + (bad.empty() ? "" : " -" + bad)
    );
    double eroded = 0;
    for (int m = 0; m < nMembers; ++m)
    {
        eroded += e->diagnostics(m).erodedVolume;
    }
    return eroded;
}

//- A member in slope coordinates among plan ones: refused, as another
//  grid (the bed's geometry and the kernels are member 0's)
void planRefusal(Counter& t)
{
    std::vector<Problem<double>> ms;
    ms.push_back(planMember<double>(0));
    ms.push_back(planMember<double>(1));
    ms[1].params.planTerrain = false;
    bool refused = false;
    try
    {
        makeCudaEnsemble(ms);
    }
    catch (const std::invalid_argument& e)
    {
        std::printf("    refused: %s\n", e.what());
        refused = true;
    }
    t.check(refused, "a slope-coordinate member among plan ones refused");
}

void refusal(Counter& t)
{
    std::vector<Problem<double>> ms = shcases::inclinedPlaneMembers<double>(1, 3);
    ms[2] = shcases::inclinedPlaneMember<double>(2, 2);
    bool refused = false;
    try
    {
        makeCudaEnsemble(ms);
    }
    catch (const std::invalid_argument& e)
    {
        std::printf("    refused: %s\n", e.what());
        refused = true;
    }
    t.check(refused, "members with another grid refused");
}

} // namespace


int main(int argc, char* argv[])
{
    std::string why;
    if (!cudaAvailable(&why))
    {
        std::printf("ensembleGpu: SKIPPED: %s\n", why.c_str());
        return 77;
    }
    const unsigned seed = argc > 1
        ? unsigned(std::stoul(argv[1]))
        : unsigned(std::chrono::system_clock::now().time_since_epoch().count() % 100000);
    std::printf
    (
        "Ensembles on the CUDA backend (%s); members picked with seed %u\n",
        cudaDeviceDescription().c_str(), seed
    );
    Counter t;
    exactness<double>(t, 1, 23, 0, seed);
    exactness<double>(t, 2, 7, 3, seed + 1);
    exactness<double>(t, 1, 1, 0, seed + 2);
    exactness<float>(t, 1, 23, 0, seed + 3);
    exactness<float>(t, 2, 7, 3, seed + 4);
    planExactness<double>(t, 0);
    planExactness<float>(t, 2);
    coverExactness<double>(t, 0);
    coverExactness<double>(t, 4);
    coverExactness<float>(t, 0);
    coverExactness<float>(t, 4);
    refusal(t);
    planRefusal(t);
    return t.finish();
}

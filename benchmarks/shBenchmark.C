/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    Performance of the backends on the inclined plane of section 5.3
    (tests/common/gpuCases.H), in double and float:
      - the meshes of Table IV, k x k x (30 x 14), k = 4, 8, 16, 32, from
        t = 0 to t = 24, against the paper's GPU times (Table IV, 1D) and
        specific times (Table V);
      - a large mesh (k = 144: 4320 x 2016 = 8.7M cells) over a shorter
        time, and the same mesh covered by a flowing layer everywhere
        ("wet"), so that no cell takes the cheap dry path;
      - the wet mesh on bumps of the bed ("wet bumps"): zb = 0.05
        cos(pi x) cos(pi y) in slope coordinates, the plan wet bed's bumps,
        so that the slope mode takes the work of a varying bed (bed-step
        forces, the bed's reconstruction with K) as the plan mode always
        does;
      - its counterpart in plan coordinates ("plan wet",
        docs/generalTerrain.md): the 35 deg plane as a DEM,
        b = -X tan(35 deg) with gentle bumps (so that the bed varies and
        the plan bed-step arrays are used), on [0, 30 cos(35 deg)] x
        [-7, 7] with the same cells (30k x 14k, the slope mesh's cells
        projected), the same layer (thickness 0.5 normal to the bed and
        the cap, at rest: H = J h), to the same time.  A table after the
        main one sets its wet cell updates per second against those of
        the slope wet mesh and of the slope wet bumps, precision by
        precision and backend by backend: slope rate / plan rate is the
        plan mode's cost per wet cell-step relative to the slope mode's
        (target: within 1.3); against the bumps the two modes do the work
        of the same kind of bed.  The slope wet
        mesh follows eq. (35), 35 deg up to x = 17.5 easing to flat; the
        plan one stays at 35 deg, so the flows differ past x = 17.5, the
        cost per wet cell-step little.
    Backends: CPU serial, CPU on all cores (OpenMP), CUDA.  After the table,
    the GPU's float rate over its double rate, mesh by mesh (the float
    CUDA backend uses approximate division and square root when built with
    SH_CUDA_FLOAT_APPROX=ON; its name says which).

    Wet cell updates per second = the cells wet (h > hDry) after each step,
    summed over the steps, / the same wall time: the rate over the cells
    that hold material.
    Cell updates per second = cells x steps / wall time of the time loop
    (Solver::advance; set-up and copies of the state excluded).  A CPU run
    that would take longer than its wall budget stops there (advance()'s
    budget); its s/cell/step is then taken over the steps it made, and its
    time for the whole run is that times cells x the GPU's step count
    (marked '~'; the early, mostly dry steps are cheaper, so this
    underestimates the CPU time).

    Usage: shBenchmark [options]
      -meshes 4,8,16,32     Table IV meshes (0 for none)
      -large K              large mesh K x K x (30 x 14), 0 for none
      -largeTime T          end time of the large runs (default 1)
      -precision both|double|float
      -cpuWall S            wall budget of one CPU run on a Table IV mesh
      -cpuWallLarge S       the same on the large meshes (plan wet too)
      -plan 0|1             the plan wet row and its wet bumps row on the
                            large mesh (default 1)
      -noCpu                GPU only
      -huge K               also the wet mesh K x K x (30 x 14) on the GPU
                            alone (K = 1544: 1.0e9 cells), to t = hugeTime,
                            with the device memory it takes per cell and
                            the longest wait between the host's looks at
                            the run (4 calls of advance() without a wall
                            budget after the timed run)
      -hugeTime T           end time of the huge run (default 1e-3)
      -profile K            three steps on mesh K, for ncu (no timing)
      -profileCase wet|dry|bumps|plan  the case -profile runs (default wet;
                            plan: the plan wet mesh)
      -out FILE             also write the table (markdown) to FILE
\*---------------------------------------------------------------------------*/

#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"
#include "gpuCases.H"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace sh;

namespace
{

//- The problems a row runs: the inclined plane, the same covered by a
//  flowing layer, that layer on the plan bed's bumps (zb) in slope
//  coordinates, and the layer in plan coordinates
enum class Case { dry, wet, wetBumps, planWet };

struct Options
{
    std::vector<int> meshes{4, 8, 16, 32};
    int large = 144;
    double largeTime = 1;
    bool dbl = true;
    bool flt = true;
    double cpuWall = 15;
    double cpuWallLarge = 5;
    bool cpu = true;
    bool plan = true;
    int profile = 0;
    Case profileCase = Case::wet;
    int huge = 0;
    double hugeTime = 1e-3;
    bool checkInterval = false;     //!< set for the huge run
    std::string out;
};

//- Table IV (GPU time, 1D allocation, ms) and Table V (1D, s/cell/step)
struct PaperRow
{
    int k;
    double gpuMs;
    double specific;
};
const PaperRow paper[] = {
    {4, 538.4, 1.1e-7}, {8, 2452, 6.8e-8}, {16, 16169.1, 5.7e-8},
    {32, 122621.7, 5.2e-8}
};

const PaperRow* paperRow(int k)
{
    for (const PaperRow& r : paper)
    {
        if (r.k == k) { return &r; }
    }
    return nullptr;
}

struct Result
{
    std::string precision;
    Case kase = Case::dry;
    std::string mesh;
    long cells = 0;
    std::string backend;
    long steps = 0;
    double tEnd = 0;
    double tReached = 0;
    double wall = 0;        //!< measured
    bool partial = false;
    double fullWall = 0;    //!< whole run (extrapolated if partial)
    double rate = 0;        //!< cell updates / s
    double wetRate = 0;     //!< wet cell updates / s
    double serialWall = 0;  //!< CPU serial, whole run
    bool serialPartial = false;
    const PaperRow* paper = nullptr;
};

std::vector<Result> results;

//- Device memory a run took: cells, bytes, device total
struct MemoryRow
{
    std::string precision;
    std::string mesh;
    long cells;
    double bytes;
    double total;
};
std::vector<MemoryRow> memoryRows;

//- How long the host waits between two looks at the run (a signal, its
//  wall budget, tEnd): the longest of a few advance() calls with no wall
//  budget, each of which returns after one launch of steps
struct CheckRow
{
    std::string precision;
    std::string mesh;
    long cells;
    long steps;         //!< steps made by the timed calls
    double longest;     //!< [s]
    double stepSeconds; //!< mean wall time of one step in them [s]
    long firstSteps;    //!< steps of the solver's first launch
    double firstWait;   //!< its wall time [s] (graph set-up included)
};
std::vector<CheckRow> checkRows;

//- The wet layer's thickness at (x, y) along the plane: 0.5 everywhere,
//  the cap of section 5.3 on top (every cell wet)
double wetLayer(double x, double y)
{
    const double r0 = 1.85;
    const double r2 = (x - 4)*(x - 4) + y*y;
    return 0.5 + (r2 < r0*r0 ? std::sqrt(r0*r0 - r2) : 0.0);
}

template<class Real>
sh::Problem<Real> wetPlane(int k)
{
    sh::Problem<Real> pb = shcases::inclinedPlane<Real>(k);
    pb.setState([](double x, double y)
    {
        return sh::Primitive{wetLayer(x, y), 0, 0};
    });
    return pb;
}

//- The plan wet plane: inclination, and the bumps' height and wavelength
//  (their steepest slope 2 pi a/L = 0.16 against tan(35 deg) = 0.70)
const double planZeta = 35*shcases::deg;
const double bumpA = 0.05;
const double bumpL = 2;

//- Its bed b(X, Y) and slopes (p, q) = grad b
double planWetBed(double X, double Y)
{
    const double w = 2*shcases::pi/bumpL;
    return -X*std::tan(planZeta) + bumpA*std::cos(w*X)*std::cos(w*Y);
}

void planWetSlopes(double X, double Y, double& p, double& q)
{
    const double w = 2*shcases::pi/bumpL;
    p = -std::tan(planZeta) - bumpA*w*std::sin(w*X)*std::cos(w*Y);
    q = -bumpA*w*std::cos(w*X)*std::sin(w*Y);
}

//- The wet mesh in plan coordinates: the slope mesh's cells projected
//  (30k x 14k on [0, 30 cos zeta] x [-7, 7]), the model of section 5.3
//  (inclinedPlane's parameters with Params::planTerrain, the one
//  difference makeParams makes for ModelInput::coordinates plan), the
//  wet layer at rest normal to the bed, held as H = J h; transmissive
//  sides as the slope mesh's
template<class Real>
sh::Problem<Real> wetPlanPlane(int k)
{
    sh::Params<Real> p = shcases::inclinedPlane<Real>(1).params;
    p.planTerrain = true;
    const double cosZeta = std::cos(planZeta);
    sh::Problem<Real> pb(p, 30*k, 14*k, 0, 30*cosZeta, -7, 7);
    pb.setTopography(planWetBed);
    pb.setState([=](double X, double Y)
    {
        double bx = 0, by = 0;
        planWetSlopes(X, Y, bx, by);
        const double J = std::sqrt(1 + bx*bx + by*by);
        return sh::Primitive{J*wetLayer(X/cosZeta, Y), 0, 0};
    });
    return pb;
}

//- The wet plane in slope coordinates on the plan wet bed's bumps: zb =
//  a cos(2 pi x/L) cos(2 pi y/L) along the plane (x, y), so that the
//  slope mode, too, takes the varying bed's work (the bed-step forces and
//  their face arrays, the bed's reconstruction with K): the like-for-like
//  counterpart of the plan wet plane, whose bed always varies
template<class Real>
sh::Problem<Real> wetBumpsPlane(int k)
{
    sh::Problem<Real> pb = wetPlane<Real>(k);
    pb.setTopography([](double x, double y)
    {
        const double w = 2*shcases::pi/bumpL;
        return bumpA*std::cos(w*x)*std::cos(w*y);
    });
    return pb;
}

template<class Real>
sh::Problem<Real> problemOf(int k, Case c)
{
    return c == Case::planWet ? wetPlanPlane<Real>(k)
         : c == Case::wet ? wetPlane<Real>(k)
         : c == Case::wetBumps ? wetBumpsPlane<Real>(k)
         : shcases::inclinedPlane<Real>(k);
}

template<class Real>
Result timeRun
(
    Solver<Real>& s,
    double tEnd,
    double wallBudget,
    long cells
)
{
    using clock = std::chrono::steady_clock;
    const long long wet0 = s.wetCellUpdates();
    const clock::time_point t0 = clock::now();
    const bool reached = s.advance(tEnd, wallBudget);
    const std::chrono::duration<double> dt = clock::now() - t0;
    const long long wet1 = s.wetCellUpdates();
    Result r;
    r.cells = cells;
    r.backend = s.name();
    r.steps = s.steps();
    r.tEnd = tEnd;
    r.tReached = s.time();
    r.wall = dt.count();
    r.partial = !reached;
    r.fullWall = r.wall;
    r.rate = double(cells)*r.steps/r.wall;
    r.wetRate = double(wet1 - wet0)/r.wall;
    return r;
}

std::string meshName(int k, int nx, int ny, Case c)
{
    std::ostringstream os;
    os << k << "x" << k << "x(30x14) = " << nx << "x" << ny;
    if (c == Case::wet) { os << " wet"; }
    if (c == Case::wetBumps) { os << " wet bumps"; }
    if (c == Case::planWet) { os << " plan wet"; }
    return os.str();
}

//- Kept in one piece: the timed runs of one mesh on each backend with the
//  wall-budget handling between them; split, the timers and partial-run
//  state would pass between helpers.
template<class Real>
void runMesh(const Options& o, int k, bool large, Case c, double tLarge)
{
    const char* prec = sizeof(Real) == 8 ? "double" : "float";
    const sh::Problem<Real> pb = problemOf<Real>(k, c);
    const long cells = long(pb.grid.nx)*pb.grid.ny;
    const double tEnd = large ? tLarge : 24;
    const std::string mesh = meshName(k, pb.grid.nx, pb.grid.ny, c);
    std::fprintf(stderr, "== %s %s, t = 0..%g\n", prec, mesh.c_str(), tEnd);

    std::vector<Result> rows;
    long gpuSteps = 0;
    std::string why;
    if (cudaAvailable(&why))
    {
        std::size_t free0 = 0, free1 = 0, total = 0;
        cudaMemoryInfo(&free0, &total);
        std::unique_ptr<Solver<Real>> gpu = makeCudaSolver(pb);
        gpu->stableDt();    // context and module loaded before timing
        if (cudaMemoryInfo(&free1, &total) && large)
        {
            memoryRows.push_back
            (
                {prec, mesh, cells,
                 double(free0) - double(free1), double(total)}
            );
        }
        // The huge run: the wait of the very first launch (no step timed
        // yet), before the timed run, which then starts that many steps on
        double firstWait = 0;
        long firstSteps = 0;
        if (o.checkInterval)
        {
            const std::chrono::steady_clock::time_point t0 =
                std::chrono::steady_clock::now();
            gpu->advance(1e300, 0);
            firstWait = std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - t0
            ).count();
            firstSteps = gpu->steps();
        }
        rows.push_back(timeRun(*gpu, tEnd, 1e300, cells));
        rows.back().steps -= firstSteps;
        rows.back().rate = double(cells)*rows.back().steps/rows.back().wall;
        gpuSteps = rows.back().steps;
        if (o.checkInterval)
        {
            using clock = std::chrono::steady_clock;
            const long steps0 = gpu->steps();
            double longest = 0, all = 0;
            for (int call = 0; call < 4; ++call)
            {
                const clock::time_point t0 = clock::now();
                gpu->advance(1e300, 0);
                const std::chrono::duration<double> d = clock::now() - t0;
                longest = std::max(longest, d.count());
                all += d.count();
            }
            const long made = gpu->steps() - steps0;
            checkRows.push_back
            (
                {prec, mesh, cells, made, longest, made > 0 ? all/made : 0,
                 firstSteps, firstWait}
            );
        }
    }
    else
    {
        std::fprintf(stderr, "   no GPU: %s\n", why.c_str());
    }
    if (o.cpu)
    {
        const double budget = large ? o.cpuWallLarge : o.cpuWall;
        for (const bool parallel : {false, true})
        {
            CpuSolver<Real> cpu(pb, parallel);
            Result r = timeRun(cpu, tEnd, budget, cells);
            if (r.partial && gpuSteps > 0)
            {
                r.fullWall = r.wall/r.steps*gpuSteps;
            }
            rows.push_back(r);
        }
    }
    double serial = 0;
    bool serialPartial = false;
    for (const Result& r : rows)
    {
        if (r.backend == "cpu (serial)")
        {
            serial = r.fullWall;
            serialPartial = r.partial;
        }
    }
    for (Result& r : rows)
    {
        r.precision = prec;
        r.kase = c;
        r.mesh = mesh;
        r.serialWall = serial;
        r.serialPartial = serialPartial;
        r.paper = large ? nullptr : paperRow(k);
        std::fprintf(stderr, "   %-45s %8ld steps, t = %-8.4g %9.4f s%s\n",
            r.backend.c_str(), r.steps, r.tReached, r.wall,
            r.partial ? " (partial)" : "");
        results.push_back(r);
    }
}

//- The plan wet rows against the slope wet rows of the same precision,
//  backend and cells: slope rate / plan rate, the plan mode's cost per wet
//  cell-step relative to the slope mode's, against the target 1.3.  A CPU
//  run stopped by its wall budget gives its rate over the steps it made
//  (marked '~'; every cell is wet from the first step, so those steps
//  are representative).  Empty without plan rows.
std::string planComparison()
{
    const double target = 1.3;
    std::ostringstream rows;
    char buf[512];
    for (const Result& p : results)
    {
        if (p.kase != Case::planWet) { continue; }
        for (const Result& s : results)
        {
            if
            (
                (s.kase != Case::wet && s.kase != Case::wetBumps)
             || s.precision != p.precision
             || s.backend != p.backend || s.cells != p.cells
            )
            {
                continue;
            }
            const double ratio = s.wetRate/p.wetRate;
            const char* approx = s.partial || p.partial ? "~" : "";
            std::snprintf(buf, sizeof buf,
                "| %s | %s | %ld | %s | %ld / %ld | %.3e | %.3e | %s%.3f "
                "| %s |\n",
                p.precision.c_str(), p.backend.c_str(), p.cells,
                s.kase == Case::wet
              ? "wet, zb = 0 (no bed-step work)" : "wet bumps (the plan bed's bumps in zb)",
                s.steps, p.steps, s.wetRate, p.wetRate, approx, ratio,
                ratio <= target ? "yes" : "no");
            rows << buf;
        }
    }
    if (rows.str().empty()) { return ""; }
    std::snprintf(buf, sizeof buf,
        "\nPlan coordinates against slope coordinates, the wet large mesh "
        "(target: the plan mode's cost per wet cell-step within %.1fx the "
        "slope mode's, slope rate / plan rate <= %.1f):\n\n"
        "| precision | backend | cells | slope row | steps slope / plan "
        "| slope wet cell updates/s | plan wet cell updates/s "
        "| slope / plan (plan cost per wet cell-step) | within %.1fx |\n"
        "|---|---|---:|---|---:|---:|---:|---:|---|\n", target, target, target);
    return buf + rows.str();
}

//- Kept in one piece: the whole markdown table, one column after another in
//  print order.
std::string table()
{
    std::ostringstream os;
    char buf[512];
    os << "| precision | mesh | cells | backend | steps | t | wall [s] "
          "| cell updates/s | wet cell updates/s | s/cell/step "
          "| vs CPU serial | vs paper GPU (Table IV/V) |\n";
    os << "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Result& r : results)
    {
        std::string tCol = r.partial
            ? (std::snprintf(buf, sizeof buf, "%.3g of %g", r.tReached, r.tEnd), buf)
            : (std::snprintf(buf, sizeof buf, "%g", r.tEnd), buf);
        std::string wall = r.partial
            ? (std::snprintf(buf, sizeof buf, "%.3f (~%.4g whole)", r.wall, r.fullWall), buf)
            : (std::snprintf(buf, sizeof buf, "%.4g", r.wall), buf);
        std::string vsSerial = "-";
        if (r.serialWall > 0)
        {
            std::snprintf(buf, sizeof buf, "%s%.3g",
                r.partial || r.serialPartial ? "~" : "",
                r.serialWall/r.fullWall);
            vsSerial = buf;
        }
        std::string vsPaper = "-";
        if (r.paper)
        {
            // Table IV time for the whole run; Table V per cell per step
            std::snprintf(buf, sizeof buf, "%s%.3g x (time), %.3g x (s/cell/step)",
                r.partial ? "~" : "", r.paper->gpuMs*1e-3/r.fullWall,
                r.paper->specific*r.rate);
            vsPaper = buf;
        }
        else
        {
            // Against the paper's best specific time, 5.2e-8 s/cell/step
            std::snprintf(buf, sizeof buf, "%.3g x (s/cell/step vs 5.2e-8)",
                5.2e-8*r.rate);
            vsPaper = buf;
        }
        std::snprintf(buf, sizeof buf,
            "| %s | %s | %ld | %s | %ld | %s | %s | %.3e | %.3e | %.3e | %s | %s |\n",
            r.precision.c_str(), r.mesh.c_str(), r.cells, r.backend.c_str(),
            r.steps, tCol.c_str(), wall.c_str(), r.rate, r.wetRate, 1.0/r.rate,
            vsSerial.c_str(), vsPaper.c_str());
        os << buf;
    }

    // The GPU in float against double, mesh by mesh (rates, since the two
    // precisions may take a few steps more or less)
    std::ostringstream ratios;
    for (const Result& f : results)
    {
        if (f.precision != "float" || f.backend.compare(0, 4, "cuda") != 0)
        {
            continue;
        }
        for (const Result& d : results)
        {
            if (d.precision == "double" && d.mesh == f.mesh
             && d.backend.compare(0, 4, "cuda") == 0)
            {
                std::snprintf(buf, sizeof buf,
                    "| %s | %ld / %ld | %.3e | %.3e | %.2f |\n",
                    f.mesh.c_str(), d.steps, f.steps, d.rate, f.rate,
                    f.rate/d.rate);
                ratios << buf;
            }
        }
    }
    if (!memoryRows.empty())
    {
        os << "\nDevice memory of the GPU runs (free memory before the "
              "solver was made less after):\n\n"
              "| precision | mesh | cells | device memory [GB] | bytes/cell "
              "| device total [GB] |\n|---|---|---:|---:|---:|---:|\n";
        for (const MemoryRow& m : memoryRows)
        {
            std::snprintf(buf, sizeof buf, "| %s | %s | %ld | %.2f | %.1f | %.2f |\n",
                m.precision.c_str(), m.mesh.c_str(), m.cells, m.bytes*1e-9,
                m.bytes/double(m.cells), m.total*1e-9);
            os << buf;
        }
    }
    if (!checkRows.empty())
    {
        os << "\nHow often the host looks at a run on the GPU (a signal, "
              "the wall budget, tEnd): the longest of 4 advance() calls "
              "without a wall budget, each one launch of steps:\n\n"
              "| precision | mesh | cells | steps | longest wait [s] "
              "| wall per step [s] | first launch: steps | its wait [s] |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|\n";
        for (const CheckRow& c : checkRows)
        {
            std::snprintf(buf, sizeof buf,
                "| %s | %s | %ld | %ld | %.3f | %.3f | %ld | %.3f |\n",
                c.precision.c_str(), c.mesh.c_str(), c.cells, c.steps,
                c.longest, c.stepSeconds, c.firstSteps, c.firstWait);
            os << buf;
        }
    }
    if (!ratios.str().empty())
    {
        os << "\nGPU, float against double:\n\n"
              "| mesh | steps double / float | cell updates/s double "
              "| float | float / double |\n"
              "|---|---:|---:|---:|---:|\n" << ratios.str();
    }
    os << planComparison();
    return os.str();
}

std::vector<int> parseList(const char* s)
{
    std::vector<int> v;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
    {
        const int k = std::atoi(item.c_str());
        if (k > 0) { v.push_back(k); }
    }
    return v;
}

template<class Real>
int profile(int k, Case c)
{
    const sh::Problem<Real> pb = problemOf<Real>(k, c);
    std::unique_ptr<Solver<Real>> gpu = makeCudaSolver(pb);
    const Real dt = gpu->stableDt();
    for (int n = 0; n < 3; ++n)
    {
        gpu->step(dt);
    }
    std::printf("profiled 3 steps of %s on %dx%d\n", gpu->name().c_str(),
        pb.grid.nx, pb.grid.ny);
    return 0;
}

} // namespace


//- Kept in one piece: the option parsing and the benchmark's sequence as a
//  reader follows it.
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
            return next;
        };
        if (arg == "-meshes") { o.meshes = parseList(need()); }
        else if (arg == "-large") { o.large = std::atoi(need()); }
        else if (arg == "-largeTime") { o.largeTime = std::atof(need()); }
        else if (arg == "-cpuWall") { o.cpuWall = std::atof(need()); }
        else if (arg == "-cpuWallLarge") { o.cpuWallLarge = std::atof(need()); }
        else if (arg == "-noCpu") { o.cpu = false; }
        else if (arg == "-profile") { o.profile = std::atoi(need()); }
        else if (arg == "-huge") { o.huge = std::atoi(need()); }
        else if (arg == "-hugeTime") { o.hugeTime = std::atof(need()); }
        else if (arg == "-out") { o.out = need(); }
        else if (arg == "-plan") { o.plan = std::atoi(need()) != 0; }
        else if (arg == "-profileCase")
        {
            const std::string c = need();
            o.profileCase = c == "dry" ? Case::dry
                          : c == "plan" ? Case::planWet
                          : c == "bumps" ? Case::wetBumps : Case::wet;
        }
        else if (arg == "-precision")
        {
            const std::string p = need();
            if (p != "both" && p != "double" && p != "float")
            {
                std::fprintf(stderr, "-precision: both, double or float, not %s\n", p.c_str());
                return 2;
            }
            o.dbl = p != "float";
            o.flt = p != "double";
        }
        else
        {
            std::fprintf(stderr, "unknown option %s (see the header of "
                "benchmarks/shBenchmark.C)\n", arg.c_str());
            return 2;
        }
    }

    if (o.profile > 0)
    {
        return o.dbl
            ? profile<double>(o.profile, o.profileCase)
            : profile<float>(o.profile, o.profileCase);
    }

    for (const bool dbl : {true, false})
    {
        if ((dbl && !o.dbl) || (!dbl && !o.flt)) { continue; }
        for (const int k : o.meshes)
        {
            dbl ? runMesh<double>(o, k, false, Case::dry, 24)
                : runMesh<float>(o, k, false, Case::dry, 24);
        }
        if (o.large > 0)
        {
            for
            (
                const Case c
              : {Case::dry, Case::wet, Case::wetBumps, Case::planWet}
            )
            {
                if
                (
                    (c == Case::planWet || c == Case::wetBumps) && !o.plan
                )
                {
                    continue;
                }
                dbl ? runMesh<double>(o, o.large, true, c, o.largeTime)
                    : runMesh<float>(o, o.large, true, c, o.largeTime);
            }
        }
        if (o.huge > 0)
        {
            Options gpuOnly = o;
            gpuOnly.cpu = false;
            gpuOnly.checkInterval = true;
            dbl ? runMesh<double>(gpuOnly, o.huge, true, Case::wet, o.hugeTime)
                : runMesh<float>(gpuOnly, o.huge, true, Case::wet, o.hugeTime);
        }
    }

    const std::string t = table();
    std::printf("\n%s", t.c_str());
    if (!o.out.empty())
    {
        std::ofstream f(o.out);
        f << t;
    }
    return 0;
}

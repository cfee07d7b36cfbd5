/*---------------------------------------------------------------------------*\
  Decomposed CPU runs against the whole run, bit for bit (issue 12)

    Usage: mpiexec -np P parallelCpu px py          (P = px py)

    The MPI transport first (tests/mpiHaloCheck.H): exchange of ghost
    layers checked against a function of the whole-grid index, the
    reductions, and the refusal of subdomains that do not fit together.

    Then the cases of tests/parallelCases.H, each in double and in float.
    Every rank builds the same whole problem from its formulas and runs
    its subdomain of the px x py split,
        CpuSolver<Real>(subProblem(whole, splitGrid(nx, ny, px, py, r)),
                        false, &halo)
    with an MpiHalo over MPI_COMM_WORLD, to the case's end time
    (advanceTo).  Rank 0 gathers every rank's interior state (h, hu, hv)
    and hazard maps (hMax, speed, pressure where rho > 0, arrival) into the
    whole grid's layout, each at its subdomain's offset, and runs the
    serial solver CpuSolver<Real>(whole, false) to the same time.

    Checks, for each case and precision:
      - every field bit for bit the serial run's (memcmp; the table shows
        max |difference| and the cells that differ in any field, both 0);
      - on every rank: the number of steps, the time and the last time step
        the serial run's (bits);
      - the collective figures, on every rank: diagnostics() wetCells,
        movingCells, speedClips, hMax and maxRate (sums of integers, and
        maxima: exact) and wetCellUpdates() equal to the serial run's; the
        volume within 1e-12 relative (its sum is taken in another order);
      - the case reaches the cuts: cells within two of a cut whose state
        changed (else the comparison would prove little).
    The first differing cell of a field is printed with both values
    (whole-grid i, j).  The exit code is non-zero on any failure, on every
    rank; an exception calls MPI_Abort.
\*---------------------------------------------------------------------------*/

#include "mpiHaloCheck.H"
#include "parallelCases.H"
#include "testing.H"

#include "cpu/cpuSolver.H"
#include "parallel/halo.H"
#include "parallel/mpiHalo.H"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace sh;
using namespace shtest;

namespace
{

//- Every rank's subdomain, on rank 0
std::vector<Subdomain> gatherSubdomains(const MpiReport& t, const Subdomain& s)
{
    int mine[4] = {s.i0, s.j0, s.nx, s.ny};
    std::vector<int> all(4*std::size_t(t.size));
    MPI_Gather(mine, 4, MPI_INT, all.data(), 4, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<Subdomain> subs;
    if (t.root())
    {
        subs.resize(t.size);
        for (int r = 0; r < t.size; ++r)
        {
            subs[r] = s;
            subs[r].i0 = all[4*r];
            subs[r].j0 = all[4*r + 1];
            subs[r].nx = all[4*r + 2];
            subs[r].ny = all[4*r + 3];
        }
    }
    return subs;
}


//- One field of every rank in the whole grid's layout, on rank 0.  Every
//  rank's array must have its subdomain's nx ny values, or every rank's
//  none (a map not kept): false on rank 0 otherwise.
template<class T>
bool gatherWhole
(
    const MpiReport& t,
    const std::vector<Subdomain>& subs,
    const std::vector<T>& local,
    std::vector<T>& whole
)
{
    const int bytes = int(local.size()*sizeof(T));
    std::vector<int> counts(t.size), displs(t.size);
    MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<char> buf;
    int total = 0;
    if (t.root())
    {
        for (int r = 0; r < t.size; ++r)
        {
            displs[r] = total;
            total += counts[r];
        }
        buf.resize(std::size_t(total) + 1);
    }
    MPI_Gatherv
    (
        local.data(), bytes, MPI_BYTE, buf.data(), counts.data(),
        displs.data(), MPI_BYTE, 0, MPI_COMM_WORLD
    );
    whole.clear();
    if (!t.root())
    {
        return true;
    }
    int present = 0;
    for (int r = 0; r < t.size; ++r)
    {
        const int expected = int(subs[r].nx*subs[r].ny*sizeof(T));
        if (counts[r] == expected)
        {
            ++present;
        }
        else if (counts[r] != 0)
        {
            return false;
        }
    }
    if (present == 0)
    {
        return true;
    }
    if (present != t.size)
    {
        return false;
    }
    const int nxW = subs[0].nxWhole;
    whole.resize(std::size_t(nxW)*subs[0].nyWhole);
    for (int r = 0; r < t.size; ++r)
    {
        const Subdomain& s = subs[r];
        const char* p = buf.data() + displs[r];
        for (int j = 0; j < s.ny; ++j)
        {
            std::memcpy
            (
                &whole[(s.i0) + std::size_t(s.j0 + j)*nxW],
                p + std::size_t(j)*s.nx*sizeof(T),
                s.nx*sizeof(T)
            );
        }
    }
    return true;
}


//- Bits of a and b differ
template<class T>
bool differ(const T& a, const T& b)
{
    return std::memcmp(&a, &b, sizeof(T)) != 0;
}


struct Row
{
    std::string name, prec, split;
    long steps = 0;
    long stepsSerial = 0;
    double maxAbs = 0;
    long cellsDiffering = 0;
    double volumeRel = 0;
    double wallPar = 0, wallSer = 0;
    bool ok = true;
};


//- par against the serial ser, per cell; marks the differing cells and
//  prints the first
template<class T>
void compareField
(
    MpiReport& t,
    Row& row,
    const char* field,
    bool gathered,
    const std::vector<T>& par,
    const std::vector<T>& ser,
    int nxW,
    std::vector<char>& differs
)
{
    std::string what = row.name + ", " + row.prec + ", " + row.split + ": "
      + field;
    if (!gathered || par.size() != ser.size())
    {
        std::printf
        (
            "    %s: %zu values from the subdomains, the serial run %zu\n",
            what.c_str(), par.size(), ser.size()
        );
        row.ok = false;
        t.rootCheck(false, what + " has the serial run's size");
        return;
    }
    long n = 0;
    for (std::size_t k = 0; k < ser.size(); ++k)
    {
        if (differ(par[k], ser[k]))
        {
            const double a = double(par[k]);
            const double b = double(ser[k]);
            const double d = std::fabs(a - b);
            row.maxAbs = std::max
            (
                row.maxAbs,
                d == d ? d : std::numeric_limits<double>::infinity()
            );
            differs[k] = 1;
            if (n++ == 0)
            {
                std::printf
                (
                    "    %s: first difference at whole-grid cell (%d, %d): "
                    "decomposed %.17g, serial %.17g\n",
                    what.c_str(), int(k%nxW), int(k/nxW), a, b
                );
            }
        }
    }
    const bool same = ser.empty()
        || std::memcmp(par.data(), ser.data(), ser.size()*sizeof(T)) == 0;
    if (!same)
    {
        row.ok = false;
        std::printf("    %s: %ld values differ\n", what.c_str(), n);
    }
}


//- Figures every rank reports of its decomposed run
struct Figures
{
    enum { steps, wetCells, movingCells, speedClips, wetUpdates, nLong };
    enum { time, lastDt, volume, maxRate, hMax, nDouble };
    long long l[nLong];
    double d[nDouble];
};

template<class Real>
Figures figures(Solver<Real>& s)
{
    const Diagnostics diag = s.diagnostics();
    Figures f;
    f.l[Figures::steps] = s.steps();
    f.l[Figures::wetCells] = diag.wetCells;
    f.l[Figures::movingCells] = diag.movingCells;
    f.l[Figures::speedClips] = diag.speedClips;
    f.l[Figures::wetUpdates] = s.wetCellUpdates();
    f.d[Figures::time] = s.time();
    f.d[Figures::lastDt] = s.lastDt();
    f.d[Figures::volume] = diag.volume;
    f.d[Figures::maxRate] = diag.maxRate;
    f.d[Figures::hMax] = diag.hMax;
    return f;
}


//- Cells of the whole grid within two cells of a cut of the split whose
//  state the serial run changed
template<class Real>
long changedNearCuts
(
    const std::vector<Subdomain>& subs,
    const Problem<Real>& whole,
    const std::vector<Real>& h,
    const std::vector<Real>& hu,
    const std::vector<Real>& hv
)
{
    const int nxW = whole.grid.nx;
    const int nyW = whole.grid.ny;
    std::vector<char> near(std::size_t(nxW)*nyW, 0);
    for (const Subdomain& s : subs)
    {
        for (int j = 0; j < s.ny; ++j)
        {
            for (int i = 0; i < s.nx; ++i)
            {
                const bool n =
                    (s.processorSide(xMin) && i < 2)
                 || (s.processorSide(xMax) && i >= s.nx - 2)
                 || (s.processorSide(yMin) && j < 2)
                 || (s.processorSide(yMax) && j >= s.ny - 2);
                near[(s.i0 + i) + std::size_t(s.j0 + j)*nxW] = n;
            }
        }
    }
    long changed = 0;
    for (std::size_t k = 0; k < near.size(); ++k)
    {
        changed += near[k]
            && (h[k] != whole.h[k] || hu[k] != whole.hu[k]
             || hv[k] != whole.hv[k]);
    }
    return changed;
}


//- A case's run: to its end time, or (dtScale > 0) 40 steps of dtScale
//  times the stable step, beyond the CFL limit on purpose
template<class Real>
void runCase(Solver<Real>& solver, const shparallel::Case<Real>& c)
{
    if (c.dtScale > 0)
    {
        for (int k = 0; k < 40; ++k)
        {
            solver.step(Real(c.dtScale)*solver.stableDt());
        }
    }
    else
    {
        solver.advanceTo(c.tEnd);
    }
}

template<class Real>
Row compareCase
(
    MpiReport& t,
    const shparallel::Case<Real>& c,
    int px,
    int py
)
{
    using clock = std::chrono::steady_clock;
    Row row;
    row.name = c.name;
    row.prec = sizeof(Real) == 8 ? "double" : "float";
    row.split = std::to_string(px) + "x" + std::to_string(py);
    const std::string tag = row.name + ", " + row.prec + ", " + row.split;

    const Problem<Real> whole = c.make();
    const int nxW = whole.grid.nx;
    const int nyW = whole.grid.ny;
    const Subdomain sub = splitGrid(nxW, nyW, px, py, t.rank);

    // The decomposed run, every rank
    MPI_Barrier(MPI_COMM_WORLD);
    clock::time_point t0 = clock::now();
    MpiHalo<Real> halo(MPI_COMM_WORLD, sub);
    CpuSolver<Real> par(subProblem(whole, sub), false, &halo);
    runCase(par, c);
    const Figures fPar = figures(par);
    MPI_Barrier(MPI_COMM_WORLD);
    row.wallPar = std::chrono::duration<double>(clock::now() - t0).count();

    std::vector<Real> q[3];
    par.getState(q[0], q[1], q[2]);
    const PeakMaps<Real> peaks = par.peakMaps();

    const std::vector<Subdomain> subs = gatherSubdomains(t, sub);
    std::vector<Real> wq[3];
    bool gathered[7];
    for (int k = 0; k < 3; ++k)
    {
        gathered[k] = gatherWhole(t, subs, q[k], wq[k]);
    }
    PeakMaps<Real> wp;
    gathered[3] = gatherWhole(t, subs, peaks.h, wp.h);
    gathered[4] = gatherWhole(t, subs, peaks.speed, wp.speed);
    gathered[5] = gatherWhole(t, subs, peaks.pressure, wp.pressure);
    gathered[6] = gatherWhole(t, subs, peaks.arrival, wp.arrival);

    std::vector<Figures> fAll(t.size);
    {
        std::vector<long long> l(std::size_t(Figures::nLong)*t.size);
        std::vector<double> d(std::size_t(Figures::nDouble)*t.size);
        MPI_Gather
        (
            fPar.l, Figures::nLong, MPI_LONG_LONG, l.data(), Figures::nLong,
            MPI_LONG_LONG, 0, MPI_COMM_WORLD
        );
        MPI_Gather
        (
            fPar.d, Figures::nDouble, MPI_DOUBLE, d.data(), Figures::nDouble,
            MPI_DOUBLE, 0, MPI_COMM_WORLD
        );
        for (int r = 0; t.root() && r < t.size; ++r)
        {
            std::copy_n
            (
                &l[std::size_t(Figures::nLong)*r], int(Figures::nLong),
                fAll[r].l
            );
            std::copy_n
            (
                &d[std::size_t(Figures::nDouble)*r], int(Figures::nDouble),
                fAll[r].d
            );
        }
    }

    if (t.root())
    {
        // The serial run of the whole problem
        t0 = clock::now();
        CpuSolver<Real> ser(whole, false);
        runCase(ser, c);
        const Figures fSer = figures(ser);
        row.wallSer = std::chrono::duration<double>(clock::now() - t0).count();
        std::vector<Real> sq[3];
        ser.getState(sq[0], sq[1], sq[2]);
        const PeakMaps<Real> sp = ser.peakMaps();

        std::vector<char> differs(std::size_t(nxW)*nyW, 0);
        const char* names[3] = {"h", "hu", "hv"};
        for (int k = 0; k < 3; ++k)
        {
            compareField(t, row, names[k], gathered[k], wq[k], sq[k], nxW, differs);
        }
        compareField(t, row, "hMax", gathered[3], wp.h, sp.h, nxW, differs);
        compareField(t, row, "speed", gathered[4], wp.speed, sp.speed, nxW, differs);
        compareField(t, row, "pressure", gathered[5], wp.pressure, sp.pressure, nxW, differs);
        compareField(t, row, "arrival", gathered[6], wp.arrival, sp.arrival, nxW, differs);
        for (const char d : differs)
        {
            row.cellsDiffering += d;
        }
        t.rootCheck
        (
            row.cellsDiffering == 0 && row.ok,
            tag + ": h, hu, hv, hMax, speed, pressure, arrival bit for bit"
        );
        if (whole.params.rho > Real(0))
        {
            t.rootCheck
            (
                !sp.pressure.empty(),
                tag + ": the pressure map is kept (rho > 0)"
            );
        }

        // Figures of every rank
        const char* longNames[] =
            {"steps", "wetCells", "movingCells", "speedClips", "wetCellUpdates"};
        const char* doubleNames[] =
            {"time", "lastDt", "volume", "maxRate", "hMax"};
        bool sameFigures = true;
        for (int r = 0; r < t.size; ++r)
        {
            const Figures& f = fAll[r];
            for (int k = 0; k < Figures::nLong; ++k)
            {
                if (f.l[k] != fSer.l[k])
                {
                    sameFigures = false;
                    std::printf
                    (
                        "    %s: rank %d %s %lld, serial %lld\n",
                        tag.c_str(), r, longNames[k], f.l[k], fSer.l[k]
                    );
                }
            }
            for (int k = 0; k < Figures::nDouble; ++k)
            {
                const double a = f.d[k];
                const double b = fSer.d[k];
                const bool ok = k == Figures::volume
                    ? std::fabs(a - b) <= 1e-12*std::fabs(b)
                    : !differ(a, b);
                if (!ok)
                {
                    sameFigures = false;
                    std::printf
                    (
                        "    %s: rank %d %s %.17g, serial %.17g\n",
                        tag.c_str(), r, doubleNames[k], a, b
                    );
                }
            }
            row.volumeRel = std::max
            (
                row.volumeRel,
                std::fabs(f.d[Figures::volume] - fSer.d[Figures::volume])
               /std::fabs(fSer.d[Figures::volume])
            );
        }
        row.steps = fAll[0].l[Figures::steps];
        row.stepsSerial = fSer.l[Figures::steps];
        row.ok = row.ok && sameFigures;
        t.rootCheck
        (
            sameFigures,
            tag + ": on every rank steps, time, last dt, wetCells, "
            "movingCells, speedClips, hMax, maxRate, wetCellUpdates the "
            "serial run's; volume within 1e-12"
        );

        const long near = changedNearCuts(subs, whole, sq[0], sq[1], sq[2]);
        t.rootCheck
        (
            near > 0 && fSer.l[Figures::steps] > 10,
            tag + ": " + std::to_string(near) + " cells within two of a cut "
            "changed in " + std::to_string(fSer.l[Figures::steps])
          + " steps"
        );
        row.ok = row.ok && near > 0;
    }
    MPI_Barrier(MPI_COMM_WORLD);
    return row;
}


void printTable(const std::vector<Row>& rows)
{
    std::printf
    (
        "\n%-16s %-7s %-6s %6s %6s %12s %9s %10s %8s %8s  %s\n",
        "case", "prec", "split", "steps", "serial", "max|diff|", "differing",
        "volume rel", "wall par", "wall ser", "result"
    );
    for (const Row& r : rows)
    {
        std::printf
        (
            "%-16s %-7s %-6s %6ld %6ld %12.3g %9ld %10.2g %7.3fs %7.3fs  %s\n",
            r.name.c_str(), r.prec.c_str(), r.split.c_str(), r.steps,
            r.stepsSerial, r.maxAbs, r.cellsDiffering, r.volumeRel,
            r.wallPar, r.wallSer, r.ok ? "ok" : "FAIL"
        );
    }
}


template<class Real>
void runCases(MpiReport& t, int px, int py, std::vector<Row>& rows)
{
    for (const shparallel::Case<Real>& c : shparallel::cases<Real>())
    {
        if (t.root())
        {
            const char* prec = sizeof(Real) == 8 ? "double" : "float";
            if (c.dtScale > 0)
            {
                std::printf
                (
                    "\n%s, %s, split %dx%d, 40 steps of %g x the stable"
                    " step\n", c.name.c_str(), prec, px, py, c.dtScale
                );
            }
            else
            {
                std::printf
                (
                    "\n%s, %s, split %dx%d, to t = %g\n", c.name.c_str(),
                    prec, px, py, c.tEnd
                );
            }
        }
        rows.push_back(compareCase(t, c, px, py));
    }
}


int positive(const char* s)
{
    char* end = nullptr;
    const long v = std::strtol(s, &end, 10);
    if (!end || *end || v < 1 || v > 1000)
    {
        throw std::invalid_argument
        (
            std::string("parallelCpu: '") + s + "' is not a number of parts"
        );
    }
    return int(v);
}

} // namespace


int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int code = 1;
    try
    {
        MpiReport t;
        if (argc != 3)
        {
            throw std::invalid_argument
            (
                "usage: mpiexec -np P parallelCpu px py   (P = px py)"
            );
        }
        const int px = positive(argv[1]);
        const int py = positive(argv[2]);
        if (px*py != t.size)
        {
            throw std::invalid_argument
            (
                "parallelCpu: a " + std::to_string(px) + " x "
              + std::to_string(py) + " split needs " + std::to_string(px*py)
              + " ranks, not " + std::to_string(t.size)
            );
        }
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
        runCases<double>(t, px, py, rows);
        runCases<float>(t, px, py, rows);
        if (t.root())
        {
            printTable(rows);
        }
        code = t.finish();
    }
    catch (const std::exception& e)
    {
        std::fprintf(stderr, "parallelCpu: rank %d: %s\n", rank, e.what());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 2);
    }
    MPI_Finalize();
    return code;
}

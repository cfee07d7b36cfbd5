/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    savageHutterFoam

Description
    Transient solver of the Savage-Hutter equations of granular avalanche
    flow over a curved reference surface with basal topography, by Davis's
    predictor-corrector Godunov scheme with MUSCL reconstruction, HLLC flux,
    static resistance, stopping criterion and partial-wet cells (Zhai, Yuan,
    Liu, Zhang 2014).

    The case is read here (mesh, fields h, U and optional zb,
    transportProperties, fvSolution::savageHutter, controlDict); the run
    happens in the solver core (src/savageHutter) on the CPU or the GPU.
    Time steps follow the CFL condition of eq. (24) with maxCo and hit the
    write times exactly.

    Written at write times: h, U, hU (the conserved momentum, read back on
    restart so that a restart continues exactly), zb, regime (0 dry,
    1 at rest, 2 moving), and the hazard maps hMax and UMax: the largest
    thickness and speed of each cell since the start of the run (read back
    on restart, so that they cover the whole simulation).

    Every controlDict entry the run depends on is checked before Time reads
    it (controlSettings); time directories appear complete or not at all
    (timeDirectories); SIGTERM/SIGINT write the state and end the run,
    SIGUSR1 writes it (runSignals); with runTimeModifiable yes, changes to
    endTime, writeControl, writeInterval and stopAt act during the run.

Usage
    savageHutterFoam [-backend auto|cpu|cuda] [-precision double|single]
                     [-logInterval seconds]
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "OFstream.H"
#include "structuredMesh.H"
#include "boundaryConditions.H"
#include "caseInput.H"
#include "controlSettings.H"
#include "timeDirectories.H"
#include "runSignals.H"
#include "host/problem.H"
#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"

#include <chrono>
#include <memory>

namespace
{

using namespace Foam;
using wallClock = std::chrono::steady_clock;

double secondsSince(const wallClock::time_point& t0)
{
    return std::chrono::duration<double>(wallClock::now() - t0).count();
}

std::string hms(const double seconds)
{
    const long s = long(seconds + 0.5);
    char buf[32];
    snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", s/3600, (s/60)%60, s%60);
    return buf;
}


//- Time directory names: Time raises their precision only in its own
//  time loop, which this solver does not use
struct timeNames : public Time
{
    //- A precision whose name of t differs from every name in `taken` and
    //  reads back as t to within a tenth of the distance to `previous`;
    //  raises Time's precision to it (at most 17 digits)
    static void distinguish
    (
        const scalar t,
        const scalar previous,
        const wordList& taken
    )
    {
        const int old = precision_;
        const scalar tol = 0.1*mag(t - previous);
        while (precision_ < 17)
        {
            const word name = timeName(t);
            scalar back = 0;
            if
            (
                !taken.found(name)
             && readScalar(name, back) && mag(back - t) <= tol
            )
            {
                break;
            }
            ++precision_;
        }
        if (precision_ != old)
        {
            WarningInFunction
                << "Increased the timePrecision from " << old << " to "
                << precision_ << " to distinguish the time directory of t = "
                << t << nl << endl;
        }
    }
};


//- The fields of a case and the structured view of its mesh
struct avalancheCase
{
    Time& runTime;
    const fvMesh& mesh;
    structuredMesh smesh;
    caseInput input;
    volScalarField h;
    volVectorField U;
    volScalarField zb;
    volVectorField hU;
    volScalarField regime;
    volScalarField hMax;
    volScalarField UMax;
    FixedList<sideCondition, 4> sides;
    //- Momentum as written at the start time (exact restarts)
    bool hasMomentum;
    //- Peak maps of an earlier part of the run (restart)
    bool hasPeaks;

    static IOobject io(const Time& t, const fvMesh& m, const word& name,
                       IOobject::readOption r)
    {
        return IOobject(name, t.timeName(), m, r, IOobject::AUTO_WRITE);
    }

    static IOobject reading(const Time& t, const fvMesh& m, const word& name)
    {
        Info<< "Reading field " << name << endl;
        return io(t, m, name, IOobject::MUST_READ);
    }

    avalancheCase(Time& t, const fvMesh& m)
    :
        runTime(t),
        mesh(m),
        smesh(m),
        input(m),
        h(reading(t, m, "h"), m),
        U(reading(t, m, "U"), m),
        zb(io(t, m, "zb", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimLength, Zero)),
        hU(io(t, m, "hU", IOobject::READ_IF_PRESENT), m,
            dimensionedVector(dimLength*dimVelocity, Zero)),
        regime(io(t, m, "regime", IOobject::NO_READ), m,
            dimensionedScalar(dimless, Zero)),
        hMax(io(t, m, "hMax", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimLength, Zero)),
        UMax(io(t, m, "UMax", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimVelocity, Zero)),
        sides(readBoundaryConditions(smesh, h, U)),
        hasMomentum(io(t, m, "hU", IOobject::MUST_READ)
            .typeHeaderOk<volVectorField>(true)),
        hasPeaks(io(t, m, "hMax", IOobject::MUST_READ)
            .typeHeaderOk<volScalarField>(true)
         && io(t, m, "UMax", IOobject::MUST_READ)
            .typeHeaderOk<volScalarField>(true))
    {
        Info<< "Mesh: " << smesh.nx() << " x " << smesh.ny()
            << " cells of " << smesh.dx() << " x " << smesh.dy()
            << " m on [" << smesh.xMin() << ", " << smesh.xMax() << "] x ["
            << smesh.yMin() << ", " << smesh.yMax() << "]" << nl;
        for (label s = 0; s < 4; ++s)
        {
            const char* names[3] = {"transmissive", "wall", "inflow"};
            Info<< "    " << structuredMesh::sideNames[s] << ": patch "
                << sides[s].patch << ", " << names[int(sides[s].type)];
            if (sides[s].type == sh::BCType::inflow)
            {
                Info<< " h " << sides[s].h << " U " << sides[s].U;
            }
            Info<< nl;
        }
        if (!io(t, m, "zb", IOobject::MUST_READ)
            .typeHeaderOk<volScalarField>(true))
        {
            Info<< "No field zb: flat bed on the reference surface" << nl;
        }
        checkInitialFields();
        checkMomentum();
        Info<< endl;
    }

    //- hU of a restart is the exact momentum; a U edited after the write
    //  (setFields, setAvalancheFields into the latest time) makes them
    //  disagree, and then U wins
    void checkMomentum()
    {
        if (!hasMomentum)
        {
            return;
        }
        label disagree = 0;
        forAll(h, c)
        {
            const vector hu = h[c]*U[c];
            if
            (
                h[c] > input.model.hDry
             && mag(hU[c] - hu) > 1e-9*(mag(hU[c]) + mag(hu)) + VSMALL
            )
            {
                ++disagree;
            }
        }
        if (disagree)
        {
            WarningInFunction
                << "hU disagrees with h U in " << disagree << " cells (h or U"
                << " edited after the write?): using h U" << nl << endl;
            hasMomentum = false;
        }
        else
        {
            Info<< "Reading field hU: the momentum, exact for the restart"
                << nl;
        }
    }

    void checkInitialFields() const
    {
        forAll(h, c)
        {
            if (!std::isfinite(h[c]) || h[c] < 0)
            {
                FatalIOErrorInFunction(h.objectPath())
                    << "h = " << h[c] << " in cell " << c << " at "
                    << mesh.C()[c] << ": the thickness must be finite and"
                    << " >= 0" << nl << exit(FatalIOError);
            }
            const vector& u = hasMomentum ? hU[c] : U[c];
            if (!std::isfinite(u.x()) || !std::isfinite(u.y()))
            {
                FatalIOErrorInFunction(U.objectPath())
                    << (hasMomentum ? "hU = " : "U = ") << u << " in cell "
                    << c << " is not finite" << nl << exit(FatalIOError);
            }
            if (!std::isfinite(zb[c]))
            {
                FatalIOErrorInFunction(zb.objectPath())
                    << "zb = " << zb[c] << " in cell " << c
                    << " is not finite" << nl << exit(FatalIOError);
            }
        }
    }

    //- The core's problem in precision Real
    template<class Real>
    sh::Problem<Real> problem() const
    {
        sh::Problem<Real> pb
        (
            input.params<Real>(),
            smesh.nx(), smesh.ny(),
            smesh.xMin(), smesh.xMax(), smesh.yMin(), smesh.yMax()
        );
        pb.bc = boundarySpec<Real>(sides);
        try
        {
            const Function1<scalar>& zeta = input.inclination();
            pb.setInclination
            (
                [&zeta](double x) { return degToRad(zeta.value(x)); }
            );
        }
        catch (const sh::InputError& e)
        {
            input.fail(e);
        }
        if (hasPeaks)
        {
            pb.hPeak.resize(h.size());
            pb.speedPeak.resize(h.size());
        }
        forAll(h, c)
        {
            const label k = smesh.gridIndex(c);
            if (hasPeaks)
            {
                pb.hPeak[k] = Real(hMax[c]);
                pb.speedPeak[k] = Real(UMax[c]);
            }
            pb.zb[k] = Real(zb[c]);
            pb.h[k] = Real(h[c]);
            pb.hu[k] = Real(hasMomentum ? hU[c].x() : h[c]*U[c].x());
            pb.hv[k] = Real(hasMomentum ? hU[c].y() : h[c]*U[c].y());
        }
        if (input.hasJet)
        {
            try
            {
                pb.setImpingingJet(input.jet);
            }
            catch (const sh::InputError& e)
            {
                input.fail(e);
            }
        }
        return pb;
    }

    //- Copy a state into the fields; false (fields untouched) when it is
    //  not finite or has a negative thickness
    template<class Real>
    bool store
    (
        const std::vector<Real>& hs,
        const std::vector<Real>& hus,
        const std::vector<Real>& hvs,
        const std::vector<Real>& hPeak,
        const std::vector<Real>& speedPeak
    )
    {
        forAll(hs, k)
        {
            if
            (
                !std::isfinite(double(hs[k])) || hs[k] < 0
             || !std::isfinite(double(hus[k]))
             || !std::isfinite(double(hvs[k]))
            )
            {
                return false;
            }
        }
        const scalar hDry = input.model.hDry;
        forAll(h, c)
        {
            const label k = smesh.gridIndex(c);
            const scalar hc = hs[k];
            const vector m(hus[k], hvs[k], 0);
            h[c] = hc;
            hU[c] = m;
            U[c] = hc > 0 ? m/hc : vector::zero;
            regime[c] =
                hc <= hDry ? 0 : (m.x() != 0 || m.y() != 0 ? 2 : 1);
            hMax[c] = hPeak[k];
            UMax[c] = speedPeak[k];
        }
        h.correctBoundaryConditions();
        U.correctBoundaryConditions();
        hU.correctBoundaryConditions();
        regime.correctBoundaryConditions();
        hMax.correctBoundaryConditions();
        UMax.correctBoundaryConditions();
        return true;
    }

    //- The time of the start directory to full precision: the name holds
    //  timePrecision digits (6: up to 5e-6 relative off, as for a time
    //  written on a signal), uniform/time the value itself, trusted when
    //  its name is the directory's
    void restoreStartTime()
    {
        IOobject timeIO
        (
            "time", runTime.timeName(), "uniform", runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        );
        if (!timeIO.typeHeaderOk<IOdictionary>(true))
        {
            return;
        }
        const IOdictionary timeDict(timeIO);
        scalar value;
        string name;
        if
        (
            timeDict.readIfPresent("value", value)
         && (
                (
                    timeDict.readIfPresent("name", name)
                 && name == runTime.timeName()
                )
             || mag(value - runTime.value()) <= 1e-6*max(mag(value), SMALL)
            )
        )
        {
            runTime.setTime(value, runTime.timeIndex());
        }
    }

    //- Next write time after t on the grid of writeInterval, anchored at 0
    //  when the start time lies on it (as after a restart), else at start.
    //  Rounded to 12 significant digits, so that 3 x 0.1 is the 0.3 a user
    //  writes as endTime and a restart reads from the directory name: runs
    //  that stop at the same time then take the same last step.
    scalar nextWriteTime(const scalar t, const scalar anchor) const
    {
        const scalar w = input.writeInterval;
        const scalar k = std::floor((t - anchor)/w + 1e-6) + 1;
        char buf[32];
        snprintf(buf, sizeof(buf), "%.12g", anchor + k*w);
        return std::strtod(buf, nullptr);
    }
};


//- The case at the start time; an unreadable file is reported by
//  reportUnreadable (with what to remove when it lies in the start time)
autoPtr<avalancheCase> readCase(Time& runTime, const fvMesh& mesh)
{
    const bool ioThrows = FatalIOError.throwExceptions();
    const bool throws = FatalError.throwExceptions();
    autoPtr<avalancheCase> ac;
    try
    {
        ac.reset(new avalancheCase(runTime, mesh));
        ac->restoreStartTime();
    }
    catch (const IOerror& e)
    {
        FatalIOError.throwExceptions(ioThrows);
        FatalError.throwExceptions(throws);
        reportUnreadable(runTime, e);
    }
    catch (const error& e)
    {
        FatalIOError.throwExceptions(ioThrows);
        FatalError.throwExceptions(throws);
        reportUnreadable(runTime, e);
    }
    FatalIOError.throwExceptions(ioThrows);
    FatalError.throwExceptions(throws);
    return ac;
}


template<class Real>
std::unique_ptr<sh::Solver<Real>> selectBackend
(
    const word& backend,
    const sh::Problem<Real>& pb
)
{
    std::string why;
    if (backend == "cuda" || (backend == "auto" && sh::cudaAvailable(&why)))
    {
        try
        {
            return sh::makeCudaSolver<Real>(pb);
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "-backend " << backend << ": the CUDA backend cannot run"
                << " here: " << e.what() << nl
                << "Use -backend cpu." << nl << exit(FatalError);
        }
    }
    if (backend == "auto")
    {
        Info<< "No usable GPU (" << why.c_str() << "): running on the CPU"
            << nl;
    }
    return std::unique_ptr<sh::Solver<Real>>
    (
        new sh::CpuSolver<Real>(pb, true)
    );
}


template<class Real>
void run(avalancheCase& ac, const word& backend, const scalar logInterval)
{
    Time& runTime = ac.runTime;
    const sh::Problem<Real> pb = ac.problem<Real>();
    std::unique_ptr<sh::Solver<Real>> solver = selectBackend(backend, pb);

    const scalar t0 = runTime.value();
    scalar endTime = runTime.endTime().value();
    const scalar w = ac.input.writeInterval;
    // The write times: k writeInterval from the origin of the run that
    // wrote the start time (uniform/writeGrid), so that a restart from a
    // time written on a signal keeps its grid; else from 0 when the start
    // time lies on that grid, else from the start time, as in OpenFOAM
    IOdictionary writeGrid
    (
        IOobject
        (
            "writeGrid", runTime.timeName(), "uniform", runTime,
            IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE
        )
    );
    scalar anchor = mag(t0/w - std::round(t0/w)) < 1e-6 ? 0 : t0;
    if (writeGrid.found("origin"))
    {
        anchor = writeGrid.get<scalar>("origin");
        Info<< "Write times on the grid of the run that wrote "
            << runTime.timeName() << ": " << anchor << " + k " << w << nl;
    }
    writeGrid.set("origin", anchor);
    const label index0 = runTime.timeIndex();
    const double nCells = double(pb.nCells());

    solver->setTime(t0);
    solver->setMaxDt(ac.input.maxDeltaT);
    solver->setInterrupt(&runSignals::pending);
    atomicWriter writer(runTime);

    Info<< "Backend: " << solver->name().c_str() << ", "
        << (sizeof(Real) == 8 ? "double" : "single") << " precision" << nl;

    const sh::Diagnostics d0 = solver->diagnostics();
    Info<< "Initial volume " << d0.volume << " m^3, " << d0.wetCells
        << " wet cells, hMax " << d0.hMax << " m" << nl << nl
        << "Starting time loop" << nl << endl;

    // controlDict functions: they see the states of the write times (the
    // time steps themselves run inside the backend)
    functionObjectList& functions = runTime.functionObjects();
    functions.start();
    if (functions.size())
    {
        Info<< "Function objects: " << functions.size() << ", executed at"
            << " every write time" << nl << endl;
    }

    const wallClock::time_point start = wallClock::now();
    wallClock::time_point lastLog = start;

    auto logProgress = [&]()
    {
        const sh::Diagnostics d = solver->diagnostics();
        const double t = solver->time();
        const double done = (t - t0)/max(endTime - t0, SMALL);
        const double wall = secondsSince(start);
        // The step the state now allows (the last step taken may have been
        // shortened to land on a write time)
        const double dtNow = d.maxRate > 0
            ? min(ac.input.maxDeltaT, ac.input.model.cfl/d.maxRate)
            : solver->lastDt();
        Info<< "Time = " << t << " (" << label(100*done) << "%)"
            << "  deltaT = " << dtNow
            << "  Co = " << dtNow*d.maxRate
            << "  volume = " << d.volume
            << "  wet = " << d.wetCells
            << "  moving = " << d.movingCells
            << "  steps = " << solver->steps()
            << "  ETA "
            << (done > 0 ? hms(wall*(1 - done)/done) : std::string("-")).c_str()
            << endl;
        if (!std::isfinite(d.volume))
        {
            FatalErrorInFunction
                << "The solution is no longer finite at t = " << t
                << "; nothing more is written" << nl << exit(FatalError);
        }
        lastLog = wallClock::now();
    };

    std::vector<Real> hs, hus, hvs, hPeak, speedPeak;
    wordList written(1, runTime.timeName());
    scalar lastWritten = t0;

    // Approach to a steady state: |dh/dt| between consecutive write times,
    // logged, written to postProcessing/steadyState/<t0>/dhdt.dat, and
    // ending the run below fvSolution::savageHutter steadyStateTolerance
    std::vector<Real> hPrev;
    solver->getState(hPrev, hus, hvs);
    const fileName steadyDir =
        runTime.globalPath()/"postProcessing"/"steadyState"/runTime.timeName();
    std::unique_ptr<OFstream> steadyFile;
    bool steady = false;
    auto steadyCheck = [&](const double dt)
    {
        // Over the cells wet (h > hDry) at either time: dry ground does not
        // dilute the measure
        const double hDry = ac.input.model.hDry;
        double sum2 = 0, maxRate = 0;
        long nWet = 0;
        for (std::size_t k = 0; k < hs.size(); ++k)
        {
            if (!(double(hs[k]) > hDry || double(hPrev[k]) > hDry))
            {
                continue;
            }
            const double r = std::fabs(double(hs[k]) - double(hPrev[k]))/dt;
            sum2 += r*r;
            maxRate = std::max(maxRate, r);
            ++nWet;
        }
        const double rms = nWet ? std::sqrt(sum2/nWet) : 0;
        hPrev = hs;
        if (!steadyFile)
        {
            mkDir(steadyDir);
            steadyFile.reset(new OFstream(steadyDir/"dhdt.dat"));
            steadyFile->precision(12);
            *steadyFile
                << "# |dh/dt| between consecutive write times [m/s], over"
                << " the cells wet (h > hDry) at either time" << nl
                << "# Time    RMS    max    wet cells" << nl;
        }
        *steadyFile << solver->time() << tab << rms << tab << maxRate
            << tab << nWet << endl;
        Info<< "Steady-state check: |dh/dt| over " << nWet << " wet cells:"
            << " RMS " << rms << ", max " << maxRate << " m/s";
        const scalar tol = ac.input.steadyStateTolerance;
        if (tol > 0 && rms < tol)
        {
            steady = true;
            Info<< "; RMS < steadyStateTolerance " << tol << ": steady state"
                << " reached at t = " << solver->time();
        }
        Info<< nl;
    };

    auto write = [&]()
    {
        const double dtWrite = solver->time() - lastWritten;
        solver->getState(hs, hus, hvs);
        solver->getPeaks(hPeak, speedPeak);
        if (!ac.store(hs, hus, hvs, hPeak, speedPeak))
        {
            FatalErrorInFunction
                << "The solution at t = " << solver->time() << " is not"
                << " finite or has h < 0; it is not written, and the last"
                << " written time directory holds the last good state" << nl
                << exit(FatalError);
        }
        timeNames::distinguish(solver->time(), lastWritten, written);
        runTime.setTime(solver->time(), index0 + solver->steps());
        runTime.setDeltaT(solver->lastDt(), false);
        writer.write();
        functions.execute();
        written.append(runTime.timeName());
        lastWritten = solver->time();
        if (dtWrite > 0)
        {
            steadyCheck(dtWrite);
        }
    };
    auto logIfDue = [&]()
    {
        if (secondsSince(lastLog) >= logInterval)
        {
            logProgress();
        }
    };

    // SIGTERM/SIGINT: write the state and stop; SIGUSR1: write and go on.
    // True when the run is to stop.
    bool stopped = false;
    std::string stoppedBy;
    auto actOnSignals = [&]() -> bool
    {
        runSignals::pending = 0;
        const bool stop = runSignals::stop;
        Info<< nl << runSignals::name(runSignals::last) << " at t = "
            << solver->time() << ": writing"
            << (stop ? " and stopping" : "") << nl << endl;
        if (solver->time() > lastWritten)
        {
            write();
        }
        if (stop)
        {
            stoppedBy = runSignals::name(runSignals::last);
        }
        return stop;
    };

    // controlDict, with runTimeModifiable yes, read again when it changes:
    // at every write time and every second of wall time
    const double checkInterval = 1;
    const fileName controlDictPath =
        runTime.path()/runTime.system()/"controlDict";
    double controlStamp = highResLastModified(controlDictPath);
    wallClock::time_point lastCheck = wallClock::now();
    bool stopAtNextWrite = false;
    // Next write time of adjustableRunTime/runTime (recomputed once reached
    // or when writeInterval changes)
    scalar nextWrite = -GREAT;

    // Applies endTime, writeControl, writeInterval and stopAt of a changed
    // controlDict (an invalid one is reported and ignored); true when the
    // run is to stop
    auto readControlIfModified = [&]() -> bool
    {
        lastCheck = wallClock::now();
        const double stamp = highResLastModified(controlDictPath);
        if (!ac.input.control.runTimeModifiable || stamp == controlStamp)
        {
            return false;
        }
        controlStamp = stamp;
        controlSettings c;
        const bool ioThrows = FatalIOError.throwExceptions();
        const bool throws = FatalError.throwExceptions();
        bool valid = true;
        try
        {
            c = controlSettings::readFile(controlDictPath, true);
        }
        catch (const error& e)
        {
            valid = false;
            Warning
                << nl << "controlDict changed at t = " << solver->time()
                << " but is invalid; the run goes on as before:" << nl
                << e.message().c_str() << nl << "file: "
                << controlDictPath << nl << endl;
        }
        FatalIOError.throwExceptions(ioThrows);
        FatalError.throwExceptions(throws);
        if (!valid)
        {
            return false;
        }

        controlSettings& now = ac.input.control;
        Info<< nl << "controlDict changed at t = " << solver->time() << ":";
        if (c.endTime != endTime)
        {
            Info<< " endTime " << endTime << " -> " << c.endTime << ";";
            endTime = c.endTime;
            runTime.setEndTime(endTime);
        }
        if
        (
            c.writeControl != ac.input.writeControl
         || c.writeInterval != ac.input.writeInterval
        )
        {
            Info<< " writeControl " << c.writeControl << ", writeInterval "
                << ac.input.writeInterval << " -> " << c.writeInterval
                << ";";
            ac.input.writeControl = c.writeControl;
            ac.input.writeInterval = c.writeInterval;
            nextWrite = -GREAT;
        }
        if (c.stopAt != now.stopAt)
        {
            Info<< " stopAt " << c.stopAt << ";";
        }
        if
        (
            c.deltaT != now.deltaT || c.maxCo != now.maxCo
         || c.maxDeltaT != now.maxDeltaT
         || c.adjustTimeStep != now.adjustTimeStep
         || c.purgeWrite != now.purgeWrite
        )
        {
            Info<< " (deltaT, maxCo, maxDeltaT, adjustTimeStep and"
                << " purgeWrite are read at the next start)";
        }
        Info<< nl << endl;
        now.endTime = c.endTime;
        now.writeControl = c.writeControl;
        now.writeInterval = c.writeInterval;
        now.stopAt = c.stopAt;
        now.runTimeModifiable = c.runTimeModifiable;

        stopAtNextWrite = c.stopAt == "nextWrite";
        if (c.stopAt == "noWriteNow")
        {
            stoppedBy = "stopAt noWriteNow";
            return true;
        }
        if (c.stopAt == "writeNow" || !(solver->time() < endTime))
        {
            stoppedBy = c.stopAt == "writeNow" ? "stopAt writeNow" : "endTime";
            if (solver->time() > lastWritten)
            {
                write();
            }
            return true;
        }
        return false;
    };

    // One pass: advance to the next write time, signal, log or controlDict
    // check, whichever comes first, then act on what was reached
    wallClock::time_point lastWrite = wallClock::now();
    while (solver->time() < endTime && !steady && !stopped)
    {
        const word& writeControl = ac.input.writeControl;
        const scalar w = ac.input.writeInterval;
        const double toLog = logInterval - secondsSince(lastLog);
        const double toCheck = checkInterval - secondsSince(lastCheck);
        bool due = false;
        if (writeControl == "timeStep")
        {
            // Steps driven one by one from here, with the arithmetic of
            // Solver::advance (the GPU then synchronises every step); a
            // write when the time index is a multiple of writeInterval, as
            // in Time
            const label every = max(label(w), label(1));
            do
            {
                double dt = double(solver->stableDt());
                dt = min(dt, ac.input.maxDeltaT);
                const double left = endTime - solver->time();
                const bool last = dt >= left;
                solver->step(Real(last ? left : dt));
                if (last)
                {
                    solver->setTime(endTime);
                }
                logIfDue();
            }
            while
            (
                solver->time() < endTime
             && (index0 + solver->steps()) % every != 0
             && !runSignals::pending
             && secondsSince(lastCheck) < checkInterval
            );
            due =
                !(solver->time() < endTime)
             || (index0 + solver->steps()) % every == 0;
        }
        else if (writeControl == "clockTime" || writeControl == "cpuTime")
        {
            // Every writeInterval seconds of wall time, wherever the run is
            const double toWrite = w - secondsSince(lastWrite);
            const bool reached = solver->advance
            (
                endTime, max(min(min(toLog, toWrite), toCheck), 0.0)
            );
            logIfDue();
            due = reached || secondsSince(lastWrite) >= w;
        }
        else
        {
            // adjustableRunTime, runTime: every write time hit exactly
            if (!(nextWrite > solver->time()))
            {
                nextWrite = ac.nextWriteTime(solver->time(), anchor);
            }
            due = solver->advance
            (
                min(nextWrite, endTime), max(min(toLog, toCheck), 0.0)
            );
            logIfDue();
        }

        if (runSignals::pending)
        {
            // Written wherever the run is, write time or not
            stopped = actOnSignals();
            lastWrite = wallClock::now();
            continue;
        }
        if (due)
        {
            write();
            lastWrite = wallClock::now();
            if (stopAtNextWrite)
            {
                stoppedBy = "stopAt nextWrite";
                stopped = true;
                continue;
            }
        }
        if (due || secondsSince(lastCheck) >= checkInterval)
        {
            stopped = readControlIfModified();
        }
    }

    functions.end();
    if (stopped)
    {
        Info<< nl << "Stopped by " << stoppedBy.c_str() << " at t = "
            << solver->time();
        if (stoppedBy == "stopAt noWriteNow")
        {
            Info<< ", not written (the last time directory: "
                << runTime.timeName() << ")" << nl;
        }
        else
        {
            Info<< ", written to " << runTime.timeName()
                << " (restart: startFrom latestTime)" << nl;
        }
    }

    const double wall = secondsSince(start);
    if (solver->steps() > 0)
    {
        logProgress();
    }
    const double updates = nCells*double(solver->steps());
    Info<< nl << "Time loop: " << solver->steps() << " steps on "
        << label(nCells) << " cells in " << wall << " s wall ("
        << solver->name().c_str() << ")" << nl
        << "Cell updates per second: "
        << (wall > 0 ? updates/wall : 0.0) << nl << endl;
}

} // namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Savage-Hutter granular avalanche solver (Zhai et al. 2014 scheme)"
        " on the CPU or the GPU"
    );
    argList::addOption
    (
        "backend", "auto|cpu|cuda",
        "where the time loop runs; auto: the GPU when one is present"
    );
    argList::addOption
    (
        "precision", "double|single",
        "floating-point precision of the time loop (default double)"
    );
    argList::addOption
    (
        "logInterval", "seconds",
        "wall time between progress lines (default 5)"
    );
    argList::noParallel();

    #include "setRootCase.H"

    const word backend = args.getOrDefault<word>("backend", "auto");
    const word precision = args.getOrDefault<word>("precision", "double");
    const scalar logInterval = args.getOrDefault<scalar>("logInterval", 5);
    if (!wordList({"auto", "cpu", "cuda"}).found(backend))
    {
        FatalErrorInFunction
            << "Unknown -backend " << backend << nl
            << "Valid choices: (auto cpu cuda)" << nl << exit(FatalError);
    }
    if (!wordList({"double", "single"}).found(precision))
    {
        FatalErrorInFunction
            << "Unknown -precision " << precision << nl
            << "Valid choices: (double single)" << nl << exit(FatalError);
    }

    // Before Time reads it: Time misuses some values (a floating-point
    // exception for writeInterval 0)
    const controlSettings control =
        controlSettings::readFile(args.path()/"system"/"controlDict");

    #include "createTime.H"

    if (control.endTime < runTime.value())
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "endTime " << control.endTime << " lies before the start time "
            << runTime.timeName() << " (startFrom " << control.startFrom
            << ")." << nl << "Valid values: endTime >= "
            << runTime.timeName() << nl << exit(FatalIOError);
    }

    #include "createMesh.H"

    autoPtr<avalancheCase> acPtr = readCase(runTime, mesh);
    avalancheCase& ac = acPtr();
    removeIncompleteWrites(runTime);
    runSignals::install();

    // Restarts continue exactly only from states written to full precision
    if
    (
        runTime.writeFormat() == IOstream::ASCII
     && IOstream::defaultPrecision() < 17
    )
    {
        IOstream::defaultPrecision(17);
        Info<< "Writing with 17 significant digits so that restarts"
            << " continue exactly" << nl << endl;
    }

    if (precision == "double")
    {
        run<double>(ac, backend, logInterval);
    }
    else
    {
        run<float>(ac, backend, logInterval);
    }

    Info<< "End\n" << endl;
    return 0;
}


// ************************************************************************* //

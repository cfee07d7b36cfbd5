/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "avalancheRun.H"
#include "anyProcessor.H"
#include "backendSelection.H"
#include "runSignals.H"
#include "startUp.H"

#include <fstream>
#include <sstream>

namespace Foam
{

namespace
{

//- The partials of f(begin, end) over the chunks of 16384 cells of
//  [0, n), the chunks over OpenMP threads: summed in the chunks' order,
//  they give the same sum whatever the number of threads
template<class Partial, class F>
void chunkPartials(const long n, std::vector<Partial>& parts, const F& f)
{
    const long chunk = 16384;
    const long nChunks = (n + chunk - 1)/chunk;
    parts.assign(nChunks, Partial());
    #pragma omp parallel for schedule(static)
    for (long b = 0; b < nChunks; ++b)
    {
        parts[b] = f(b*chunk, std::min(n, (b + 1)*chunk));
    }
}

//- A chunk's share of the steady-state check
struct steadyPartial
{
    double sum2 = 0;
    double maxRate = 0;
    long nWet = 0;
    long nWetNow = 0;
};

} // namespace


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

template<class Real>
avalancheRun<Real>::avalancheRun
(
    avalancheCase& ac,
    const word& backend,
    const scalar logInterval
)
:
    ac_(ac),
    runTime_(ac.runTime),
    logInterval_(logInterval),
    halo_(makeHalo<Real>(ac.smesh)),
    pb_(ac.problem<Real>(halo_.get())),
    solver_(selectBackend(backend, pb_, halo_.get())),
    t0_(runTime_.value()),
    index0_(runTime_.timeIndex()),
    endTime_(runTime_.endTime().value()),
    writeGrid_
    (
        IOobject
        (
            "writeGrid", runTime_.timeName(), "uniform", runTime_,
            IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE
        )
    ),
    origin_(0),
    nextWrite_(-GREAT),
    writer_(runTime_),
    functions_(runTime_.functionObjects()),
    start_(wallClock::now()),
    lastLog_(start_),
    lastWrite_(start_),
    lastCheck_(start_),
    written_(1, runTime_.timeName()),
    lastWritten_(t0_),
    lastRestart_(t0_),
    lastFull_(true),
    kineticPeak_(0),
    steadyDir_
    (
        runTime_.globalPath()/"postProcessing"/"steadyState"
       /runTime_.timeName()
    ),
    steady_(false),
    nextCom_(-GREAT),
    lastCom_(-GREAT),
    stopped_(false),
    stopAtNextWrite_(false),
    controlDictPath_(runTime_.globalPath()/runTime_.system()/"controlDict"),
    controlStamp_(highResLastModified(controlDictPath_))
{
    // A signal while the backend was set up (the GPU's initialisation):
    // nothing is written
    endIfSignalled("setting up the backend");

    readWriteGrid();

    solver_->setTime(t0_);
    solver_->setMaxDt(ac_.input.maxDeltaT);
    solver_->setInterrupt(&runSignals::pending);
    checkFirstStep();

    Info<< "Backend: " << solver_->name().c_str() << ", "
        << (sizeof(Real) == 8 ? "double" : "single") << " precision" << nl;
    if (!writer_.overlapped())
    {
        Info<< "Writes on the solver's thread, not overlapped with the"
            << " steps: " << writer_.whyNotOverlapped().c_str() << nl;
    }

    const sh::Diagnostics d0 = solver_->diagnostics();
    Info<< "Initial volume " << d0.volume << " m^3, " << d0.wetCells
        << " wet cells, hMax " << d0.hMax << " m" << nl;
    if (ac_.input.entraining())
    {
        // The flowing volume plus the layer's is what a closed domain
        // keeps
        Info<< "Erodible volume " << d0.layerVolume << " m^3, eroded so far "
            << d0.erodedVolume << " m^3" << nl;
    }
    Info<< nl << "Starting time loop" << nl << endl;

    functions_.start();
    if (functions_.size())
    {
        Info<< "Function objects: " << functions_.size() << ", executed at"
            << " every write time" << nl << endl;
    }

    solver_->getState(hPrev_, hus_, hvs_);
    // Sized (and their pages touched) now: the first write's copies cost
    // what the later ones do
    hs_ = hPrev_;
    solver_->getPeakMaps(peaks_);
    if (ac_.input.plan())
    {
        openCentreOfMass();
        recordCentreOfMass();
    }
    start_ = lastLog_ = lastWrite_ = lastCheck_ = wallClock::now();
    eta_.start(t0_, 0);
}


// * * * * * * * * * * * * * * * Centre of mass  * * * * * * * * * * * * * //

template<class Real>
void avalancheRun<Real>::openCentreOfMass()
{
    if (!Pstream::master())
    {
        return;
    }
    // A restart keeps the path before its start time (times strictly
    // increasing, as hazardMaps reads them)
    const fileName dir = runTime_.globalPath()/"postProcessing";
    const fileName file = dir/"centreOfMass.dat";
    std::vector<std::string> kept;
    if (isFile(file))
    {
        std::ifstream is(file);
        std::string line;
        while (std::getline(is, line))
        {
            const std::size_t first = line.find_first_not_of(" \t\r");
            if (first == std::string::npos || line[first] == '#')
            {
                continue;
            }
            std::istringstream ls(line);
            double t = 0;
            if (ls >> t && t < t0_ - 1e-12*max(scalar(1), mag(t0_)))
            {
                kept.push_back(line);
            }
        }
    }
    mkDir(dir);
    comFile_.reset(new OFstream(file));
    comFile_->precision(12);
    *comFile_
        << "# Centre of mass of the volume J h dA (H dA) at the cells' bed"
        << " points, the case's plan coordinates (constant/terrainMapping"
        << " maps x, y to the DEM's)" << nl
        << "# time [s]  x [m]  y [m]  z [m]  volume [m^3]" << nl;
    for (const std::string& line : kept)
    {
        *comFile_ << line.c_str() << nl;
    }
    comFile_->flush();
}


template<class Real>
void avalancheRun<Real>::recordCentreOfMass()
{
    const double t = solver_->time();
    if (!(t > lastCom_))
    {
        return;
    }
    lastCom_ = t;
    solver_->getState(comH_, comHu_, comHv_);
    const volVectorField& C = ac_.mesh.C();
    // sum H, sum H x, sum H y, sum H zb
    FixedList<scalar, 4> sums(Zero);
    forAll(C, c)
    {
        const scalar H = comH_[ac_.smesh.gridIndex(c)];
        sums[0] += H;
        sums[1] += H*C[c].x();
        sums[2] += H*C[c].y();
        sums[3] += H*ac_.zb[c];
    }
    for (scalar& s : sums)
    {
        reduce(s, sumOp<scalar>());
    }
    if (comFile_ && sums[0] > 0)
    {
        *comFile_ << t << tab << sums[1]/sums[0] << tab << sums[2]/sums[0]
            << tab << sums[3]/sums[0] << tab
            << sums[0]*ac_.smesh.dx()*ac_.smesh.dy() << endl;
    }
}


// * * * * * * * * * * * * * * * * Stages  * * * * * * * * * * * * * * * * //

template<class Real>
void avalancheRun<Real>::readWriteGrid()
{
    // The write times: k writeInterval from the origin of the run that
    // wrote the start time, so that a restart from a time written on a
    // signal keeps its grid; else from 0 when the start time lies on that
    // grid, else from the start time, as in OpenFOAM
    const scalar w = ac_.input.writeInterval;
    origin_ = ac_.writeOrigin(t0_);
    for (const word& key : writeGrid_.toc())
    {
        if (key != "origin")
        {
            FatalIOErrorInFunction(writeGrid_)
                << "Unknown keyword '" << key << "'." << nl
                << "Valid keywords: (origin)" << nl << exit(FatalIOError);
        }
    }
    if (writeGrid_.found("origin"))
    {
        // The start of the run that wrote the start time: not after it,
        // and not so far before that the grid's k (a count of write
        // intervals, as the steps to endTime) passes maxStepsToEnd
        origin_ = writeGrid_.get<scalar>("origin");
        if (!(origin_ <= t0_ && t0_ - origin_ <= maxStepsToEnd()*w))
        {
            FatalIOErrorInFunction(writeGrid_)
                << "Invalid origin " << origin_ << " of the write times"
                << " origin + k writeInterval (" << w << "): the start of"
                << " the run that wrote " << runTime_.timeName() << "." << nl
                << "Valid values: a time in [" << t0_ - maxStepsToEnd()*w
                << ", " << t0_ << "]; or remove " << writeGrid_.objectPath()
                << " (the write times are then counted from "
                << ac_.writeOrigin(t0_) << ")"
                << nl << exit(FatalIOError);
        }
        Info<< "Write times on the grid of the run that wrote "
            << runTime_.timeName() << ": " << origin_ << " + k " << w << nl;
    }
    writeGrid_.set("origin", origin_);
}


template<class Real>
bool avalancheRun<Real>::advance()
{
    sh::Solver<Real>& solver = *solver_;
    const word& writeControl = ac_.input.writeControl;
    const scalar w = ac_.input.writeInterval;
    const double toLog = logInterval_ - secondsSince(lastLog_);
    const double toCheck = checkInterval() - secondsSince(lastCheck_);
    bool due = false;
    if (writeControl == "timeStep")
    {
        // With the arithmetic of Solver::advance; a write when the time
        // index is a multiple of writeInterval, as in Time
        const label every = max(label(w), label(1));
        do
        {
            double dt = double(solver.stableDt());
            dt = min(dt, ac_.input.maxDeltaT);
            const double left = endTime_ - solver.time();
            const bool last = dt >= left;
            if (last)
            {
                solver.step(Real(left), endTime_);
            }
            else
            {
                solver.step(Real(dt));
            }
            logIfDue();
        }
        while
        (
            solver.time() < endTime_
         && (index0_ + solver.steps()) % every != 0
         && !anyProcessor
            (
                runSignals::pending
             || secondsSince(lastCheck_) >= checkInterval()
            )
        );
        due =
            !(solver.time() < endTime_)
         || (index0_ + solver.steps()) % every == 0;
    }
    else if (writeControl == "clockTime" || writeControl == "cpuTime")
    {
        // Wherever the run is
        const double toWrite = w - secondsSince(lastWrite_);
        const bool reached = solver.advance
        (
            endTime_, max(min(min(toLog, toWrite), toCheck), 0.0)
        );
        logIfDue();
        due = reached || anyProcessor(secondsSince(lastWrite_) >= w);
    }
    else
    {
        if (!(nextWrite_ > solver.time()))
        {
            nextWrite_ = ac_.nextWriteTime(solver.time(), origin_, endTime_);
        }
        // Plan coordinates: also the centre of mass' samples, on their
        // grid from the write times' origin (the same steps after a
        // restart)
        scalar target = nextWrite_;
        if (ac_.input.plan())
        {
            if (!(nextCom_ > solver.time()))
            {
                nextCom_ = ac_.nextComTime(solver.time(), origin_, endTime_);
            }
            target = min(target, nextCom_);
        }
        const bool reached =
            solver.advance(target, max(min(toLog, toCheck), 0.0));
        due = reached && !(solver.time() < nextWrite_);
        if (reached && ac_.input.plan())
        {
            recordCentreOfMass();
        }
        logIfDue();
    }
    if (ac_.input.plan() && writeControl != "adjustableRunTime"
     && writeControl != "runTime")
    {
        recordCentreOfMass();
    }
    return due;
}


template<class Real>
bool avalancheRun<Real>::restartDue(const bool last) const
{
    const scalar every = ac_.input.control.restartInterval;
    return ac_.input.control.writeFields.empty() || last
        || (
               every > 0
            && solver_->time() - lastRestart_ >= every*(1 - 1e-9)
           );
}


template<class Real>
void avalancheRun<Real>::write(const bool restart)
{
    // The time already written, without the restart fields: again, with
    // them (the state has not changed since)
    const bool again = !(solver_->time() > lastWritten_);
    if (again && (lastFull_ || !restart))
    {
        return;
    }
    const wallClock::time_point callStart = wallClock::now();
    const double waited = writer_.waitSeconds();
    // The snapshot, once the write before has filled the fields from it:
    // the copy from the solver and its check while the writer thread may
    // still be writing the time before (they touch neither the fields nor
    // Time, which are its own until it has finished)
    writer_.waitFilled();
    solver_->getState(hs_, hus_, hvs_);
    solver_->getPeakMaps(peaks_);
    solver_->getCover(layer_, eroded_);
    // Not written on any processor unless good on all
    const bool good = ac_.goodState(hs_, hus_, hvs_);
    finishWrite();
    const double dtWrite = solver_->time() - lastWritten_;
    if (!good)
    {
        FatalErrorInFunction
            << "The solution at t = " << solver_->time() << " is not"
            << " finite or has h < 0; it is not written, and the last"
            << " written time directory holds the last good state" << nl
            << exit(FatalError);
    }
    // Before the write: a run that comes to rest here ends with it
    if (dtWrite > 0)
    {
        steadyCheck(dtWrite);
    }
    const bool full = restartDue
    (
        restart || steady_ || stopAtNextWrite_
     || !(solver_->time() < endTime_)
    );
    ac_.selectWrites(full);
    if (!again)
    {
        timeNames::distinguish(solver_->time(), lastWritten_, written_);
    }
    runTime_.setTime(solver_->time(), index0_ + solver_->steps());
    runTime_.setDeltaT(solver_->lastDt(), false);
    // The fields filled from the snapshot in the write (on the writer
    // thread where it overlaps), which then leaves the snapshot alone
    writer_.write
    (
        full,
        [this]()
        {
            ac_.fill(hs_, hus_, hvs_, peaks_);
            ac_.fillCover(layer_, eroded_);
        }
    );
    if (again)
    {
        Info<< "Wrote " << runTime_.timeName() << " again, with the restart"
            << " fields" << nl;
        lastRestart_ = solver_->time();
        lastFull_ = true;
        writeCallSeconds_ += secondsSince(callStart);
        writeCallWaitSeconds_ += writer_.waitSeconds() - waited;
        return;
    }
    // After the write (now, or once the writer thread has finished)
    executePending_ = true;
    if (!writer_.overlapped())
    {
        finishWrite();
    }
    if (ac_.input.plan())
    {
        recordCentreOfMass();
    }
    written_.append(runTime_.timeName());
    lastWritten_ = solver_->time();
    lastWrite_ = wallClock::now();
    lastFull_ = full;
    if (full)
    {
        lastRestart_ = solver_->time();
    }
    writeCallSeconds_ += secondsSince(callStart);
    writeCallWaitSeconds_ += writer_.waitSeconds() - waited;
}


template<class Real>
void avalancheRun<Real>::finishWrite()
{
    writer_.wait();
    if (executePending_)
    {
        executePending_ = false;
        functions_.execute();
    }
}


template<class Real>
void avalancheRun<Real>::steadyCheck(const double dt)
{
    // Dry ground at both times does not dilute the measure; whether any
    // material is left (a cell wet now); hPrev_ becomes the state
    const double hDry = ac_.input.model.hDry;
    const long n = long(hs_.size());
    hPrev_.resize(n);
    std::vector<steadyPartial> parts;
    chunkPartials
    (
        n, parts,
        [&](const long begin, const long end)
        {
            steadyPartial p;
            for (long k = begin; k < end; ++k)
            {
                const double h = hs_[k], h0 = hPrev_[k];
                hPrev_[k] = hs_[k];
                p.nWetNow += h > hDry;
                if (h > hDry || h0 > hDry)
                {
                    const double r = std::fabs(h - h0)/dt;
                    p.sum2 += r*r;
                    p.maxRate = std::max(p.maxRate, r);
                    ++p.nWet;
                }
            }
            return p;
        }
    );
    double sum2 = 0, maxRate = 0;
    long nWet = 0, nWetNow = 0;
    for (const steadyPartial& p : parts)
    {
        sum2 += p.sum2;
        maxRate = std::max(maxRate, p.maxRate);
        nWet += p.nWet;
        nWetNow += p.nWetNow;
    }
    // Over all processors (nothing to reduce in a serial run)
    reduce(sum2, sumOp<double>());
    reduce(maxRate, maxOp<double>());
    reduce(nWet, sumOp<long>());
    reduce(nWetNow, sumOp<long>());
    empty_ = nWetNow == 0;
    const double rms = nWet ? std::sqrt(sum2/nWet) : 0;
    if (!steadyFile_ && Pstream::master())
    {
        mkDir(steadyDir_);
        steadyFile_.reset(new OFstream(steadyDir_/"dhdt.dat"));
        steadyFile_->precision(12);
        *steadyFile_
            << "# |dh/dt| between consecutive write times [m/s], over"
            << " the cells wet (h > hDry) at either time" << nl
            << "# Time    RMS    max    wet cells" << nl;
    }
    if (steadyFile_)
    {
        *steadyFile_ << solver_->time() << tab << rms << tab << maxRate
            << tab << nWet << endl;
    }
    Info<< "Steady-state check: |dh/dt| over " << nWet << " wet cells:"
        << " RMS " << rms << ", max " << maxRate << " m/s";
    const scalar tol = ac_.input.steadyStateTolerance;
    if (tol > 0 && rms < tol)
    {
        steady_ = true;
        if (restBy_.empty())
        {
            std::ostringstream os;
            os << "steadyStateTolerance " << tol;
            restBy_ = os.str();
        }
        Info<< "; RMS < steadyStateTolerance " << tol << ": steady state"
            << " reached at t = " << solver_->time();
    }
    Info<< nl;

    // The flow's kinetic energy, sum h |u|^2/2 dA (per unit density)
    const double fraction = ac_.input.kineticEnergyStop;
    if (fraction > 0)
    {
        // Plan coordinates: H |V|^2/2 per plan area, |V| the 3D speed
        // (the momentum's vertical component p hu + q hv)
        const bool plan = ac_.input.plan();
        std::vector<double> energies;
        chunkPartials
        (
            long(ac_.h.size()), energies,
            [&](const long begin, const long end)
            {
                double e = 0;
                for (long c = begin; c < end; ++c)
                {
                    const label k = ac_.smesh.gridIndex(c);
                    const double h = hs_[k];
                    if (h > hDry)
                    {
                        const double hu = hus_[k], hv = hvs_[k];
                        const double hw =
                            plan ? ac_.planP[c]*hu + ac_.planQ[c]*hv : 0;
                        e += 0.5*((hu*hu + hv*hv) + hw*hw)/h;
                    }
                }
                return e;
            }
        );
        double energy = 0;
        for (const double e : energies)
        {
            energy += e;
        }
        energy *= ac_.smesh.dx()*ac_.smesh.dy();
        reduce(energy, sumOp<double>());
        kineticPeak_ = std::max(kineticPeak_, energy);
        Info<< "Kinetic energy: " << energy << " m^5/s^2 (per unit density),"
            << " peak " << kineticPeak_;
        if (kineticPeak_ > 0 && energy < fraction*kineticPeak_)
        {
            steady_ = true;
            if (restBy_.empty())
            {
                std::ostringstream os;
                os << "kineticEnergyStop " << fraction;
                restBy_ = os.str();
            }
            Info<< "; below kineticEnergyStop " << fraction << " of the"
                << " peak: the flow has stopped at t = " << solver_->time();
        }
        Info<< nl;
    }
}


template<class Real>
bool avalancheRun<Real>::actOnSignals()
{
    runSignals::pending = 0;
    // A signal's write follows a write in flight, complete
    finishWrite();
    const bool stop = anyProcessor(runSignals::stop);
    Info<< nl << runSignals::name(runSignals::last) << " at t = "
        << solver_->time() << ": writing"
        << (stop ? " and stopping" : "") << nl << endl;
    // Wherever the run is, write time or not, with the restart fields
    write(true);
    if (stop)
    {
        stoppedBy_ = runSignals::name(runSignals::last);
    }
    return stop;
}


template<class Real>
void avalancheRun<Real>::logProgress(const bool final)
{
    const sh::Diagnostics d = solver_->diagnostics();
    const double t = solver_->time();
    const double done = (t - t0_)/max(endTime_ - t0_, SMALL);
    // The step the state now allows (the last step taken may have been
    // shortened to land on a write time)
    const double dtNow = d.maxRate > 0
        ? min(ac_.input.maxDeltaT, ac_.input.model.cfl/d.maxRate)
        : solver_->lastDt();
    // The peak speed to 3 digits; the moving volume as the volume
    char speed[32];
    snprintf(speed, sizeof(speed), "%.3g", d.maxSpeed);
    // With an entrainment model: the volume taken up so far
    char eroded[32];
    snprintf(eroded, sizeof(eroded), "%.6g", d.erodedVolume);
    Info<< "Time = " << t << " (" << label(100*done) << "%)"
        << "  deltaT = " << dtNow
        << "  Co = " << dtNow*d.maxRate
        << "  volume = " << d.volume
        << "  wet = " << d.wetCells
        << "  moving = " << d.movingCells
        << "  speedBounds = " << std::to_string(d.speedClips).c_str()
        << "  steps = " << solver_->steps()
        << "  maxSpeed = " << speed
        << "  movingVol = " << d.movingVolume
        << (ac_.input.entraining() ? "  eroded = " : "")
        << (ac_.input.entraining() ? eroded : "")
        << (final ? std::string("  end") : "  ETA "
          + eta_.text(t, double(solver_->steps()), dtNow, endTime_))
           .c_str()
        << endl;
    if (!std::isfinite(d.volume))
    {
        // The last good state's directory complete before the exit
        finishWrite();
        FatalErrorInFunction
            << "The solution is no longer finite at t = " << t
            << "; nothing more is written" << nl << exit(FatalError);
    }
    lastLog_ = wallClock::now();
}


template<class Real>
std::string avalancheRun<Real>::endReason() const
{
    if (stopped_)
    {
        if (stoppedBy_ == "endTime")
        {
            return "endTime (lowered in the controlDict)";
        }
        if (stoppedBy_.compare(0, 7, "stopAt ") == 0)
        {
            return stoppedBy_ + " (controlDict)";
        }
        return stoppedBy_ + " (signal)";
    }
    if (steady_ && empty_)
    {
        // Everything flowed out: nothing is at rest in the domain
        return "no material left in the domain (no cell with h > hDry; "
            + restBy_ + ")";
    }
    if (steady_)
    {
        return "at rest (" + restBy_ + ")";
    }
    return "endTime";
}


template<class Real>
void avalancheRun<Real>::logIfDue()
{
    if (anyProcessor(secondsSince(lastLog_) >= logInterval_))
    {
        logProgress();
    }
}


// * * * * * * * * * * * * * * * * The run * * * * * * * * * * * * * * * * //

template<class Real>
void avalancheRun<Real>::run()
{
    capLogPrecision();
    while (solver_->time() < endTime_ && !steady_ && !stopped_)
    {
        const wallClock::time_point stepStart = wallClock::now();
        const bool due = advance();
        steppingSeconds_ += secondsSince(stepStart);
        if (anyProcessor(runSignals::pending))
        {
            stopped_ = actOnSignals();
            continue;
        }
        if (due)
        {
            write();
            if (stopAtNextWrite_)
            {
                stoppedBy_ = "stopAt nextWrite";
                stopped_ = true;
                continue;
            }
        }
        if (due || anyProcessor(secondsSince(lastCheck_) >= checkInterval()))
        {
            stopped_ = readControlIfModified();
        }
    }

    // The last write complete before the run reports its end
    finishWrite();
    functions_.end();
    if (stopped_)
    {
        Info<< nl << "Stopped by " << stoppedBy_.c_str() << " at t = "
            << solver_->time();
        if (stoppedBy_ == "stopAt noWriteNow")
        {
            Info<< ", not written (the last time directory: "
                << runTime_.timeName() << ")" << nl;
        }
        else
        {
            Info<< ", written to " << runTime_.timeName()
                << " (restart: startFrom latestTime)" << nl;
        }
    }

    const double wall = secondsSince(start_);
    if (solver_->steps() > 0)
    {
        logProgress(true);
    }
    Info<< "End of run at t = " << solver_->time() << " s: "
        << endReason().c_str() << nl;
    // All processors' cells
    const double cells = returnReduce(double(pb_.nCells()), sumOp<double>());
    const double updates = cells*double(solver_->steps());
    Info<< nl << "Time loop: " << solver_->steps() << " steps on "
        << std::to_string((long long)(cells)).c_str() << " cells in "
        << wallSeconds(wall).c_str() << " s wall ("
        << solver_->name().c_str()
        << (Pstream::parRun()
          ? " on each of " + std::to_string(Pstream::nProcs())
          + " processors" : std::string()).c_str()
        << ")" << nl
        << "Cell updates per second: "
        << rate3(wall > 0 ? updates/wall : 0.0).c_str() << nl
        << "Stepping: "
        << rate3(steppingSeconds_ > 0 ? updates/steppingSeconds_ : 0.0).c_str()
        << " cell updates per second ("
        << wallSeconds(steppingSeconds_).c_str()
        << " s wall stepping, without writing)" << nl
        << "Thin cells whose speed was bounded (speedBounds, scheme.H): "
        << std::to_string(solver_->diagnostics().speedClips).c_str()
        << nl;
    // The writes: decomposed, the slowest processor's times and all
    // processors' bytes
    const double writing =
        returnReduce(writer_.writeSeconds(), maxOp<double>());
    const double waited =
        returnReduce(writer_.waitSeconds(), maxOp<double>());
    const double called = returnReduce(writeCallSeconds_, maxOp<double>());
    const double calledWaiting =
        returnReduce(writeCallWaitSeconds_, maxOp<double>());
    const double synced =
        returnReduce(writer_.syncSeconds(), maxOp<double>());
    const double filling =
        returnReduce(writer_.fillSeconds(), maxOp<double>());
    const double bytes = returnReduce(writer_.bytes(), sumOp<double>());
    char mb[32];
    snprintf(mb, sizeof(mb), "%.1f", bytes/1e6);
    // The fields are filled in the write (on the writer thread, or on the
    // solver's where writes do not overlap) but for a decomposed run's
    // overlapped writes, where the solver's thread fills them
    const bool fillInWrite = writer_.fillsOnWriter() || !writer_.overlapped();
    const std::string filled =
        wallSeconds(filling) + " s filling the fields";
    Info<< "Writes: " << writer_.nWrites() << " in "
        << wallSeconds(writing).c_str() << " s "
        << (writer_.overlapped()
          ? "on the writer thread (" + wallSeconds(waited)
          + " s waited for by the solver)"
          : std::string("on the solver's thread")).c_str()
        << ", " << mb << " MB (" << wallSeconds(synced).c_str()
        << " s of it fsync"
        << (fillInWrite ? ", " + filled : std::string()).c_str()
        << "); " << wallSeconds(called).c_str()
        << " s in write on the solver's thread ("
        << wallSeconds(calledWaiting).c_str()
        << " s of it waiting for the write before"
        << (fillInWrite ? std::string() : ", " + filled).c_str()
        << ")" << nl << endl;
}

// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * //

template class avalancheRun<float>;
template class avalancheRun<double>;

} // End namespace Foam

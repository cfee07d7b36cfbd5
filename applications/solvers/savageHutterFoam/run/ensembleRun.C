/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "ensembleRun.H"
#include "backendSelection.H"
#include "runSignals.H"
#include "startUp.H"
#include "wallClock.H"
#include "OFstream.H"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace Foam
{

template<class Real>
fileName ensembleRun<Real>::memberDir(const label k)
{
    return fileName("ensemble")/ensembleInput::memberName(k);
}


template<class Real>
scalar ensembleRun<Real>::restartTime(word& name) const
{
    scalar t = -1;
    for (label k = 0; k < n_; ++k)
    {
        const fileName dir = runTime_.path()/memberDir(k);
        if (!isDir(dir))
        {
            return -1;
        }
        const instantList times = TimePaths::findTimes(dir);
        scalar latest = -1;
        word latestName;
        for (const instant& i : times)
        {
            if (i.value() > latest && isFile(dir/i.name()/"h"))
            {
                latest = i.value();
                latestName = i.name();
            }
        }
        if (latest < 0)
        {
            return -1;
        }
        if (k == 0 || latest < t)
        {
            t = latest;
            name = latestName;
        }
    }
    return t;
}


template<class Real>
scalar ensembleRun<Real>::readMember(const label k, const word& name)
{
    const fileName inst = memberDir(k)/name;
    const fvMesh& mesh = ac_.mesh;
    const auto io = [&](const word& field)
    {
        return IOobject
        (
            field, inst, mesh, IOobject::MUST_READ, IOobject::NO_WRITE,
            false
        );
    };
    ac_.h.primitiveFieldRef() = volScalarField(io("h"), mesh).primitiveField();
    ac_.hU.primitiveFieldRef() = volVectorField(io("hU"), mesh).primitiveField();
    ac_.hMax.primitiveFieldRef() = volScalarField(io("hMax"), mesh).primitiveField();
    ac_.UMax.primitiveFieldRef() = volScalarField(io("UMax"), mesh).primitiveField();
    ac_.tArrival.primitiveFieldRef() =
        volScalarField(io("tArrival"), mesh).primitiveField();
    if (ac_.pMax.valid())
    {
        ac_.pMax->primitiveFieldRef() =
            volScalarField(io("pMax"), mesh).primitiveField();
    }
    if (ac_.input.plan())
    {
        // The volume per plan area and the velocity, as written: the
        // restart continues exactly (avalancheCase::toPlanState)
        ac_.H->primitiveFieldRef() =
            volScalarField(io("H"), mesh).primitiveField();
        ac_.U.primitiveFieldRef() =
            volVectorField(io("U"), mesh).primitiveField();
        ac_.hasVolume = true;
    }
    if (ac_.hEntrainable.valid())
    {
        // The member's cover of that time (written with its state): the
        // layer left and the depth taken up, as a single run's restart
        // reads them
        ac_.hEntrainable->primitiveFieldRef() =
            volScalarField(io("hEntrainable"), mesh).primitiveField();
        ac_.erodedDepth->primitiveFieldRef() =
            volScalarField(io("erodedDepth"), mesh).primitiveField();
        ac_.hasEroded = true;
        if (ac_.HEntrainable.valid())
        {
            // Plan coordinates: both per plan area too, as H, so that the
            // restart continues exactly (avalancheCase::copyCover)
            ac_.HEntrainable->primitiveFieldRef() =
                volScalarField(io("HEntrainable"), mesh).primitiveField();
            ac_.HErodedDepth->primitiveFieldRef() =
                volScalarField(io("HErodedDepth"), mesh).primitiveField();
            ac_.hasPlanCover = true;
        }
    }
    ac_.hasMomentum = true;
    ac_.hasPeaks = true;
    ac_.hasArrival = true;
    ac_.hasPressure = ac_.pMax.valid();
    const IOdictionary timeDict
    (
        IOobject
        (
            "time", inst, "uniform", runTime_, IOobject::MUST_READ,
            IOobject::NO_WRITE, false
        )
    );
    steps0_[k] = timeDict.get<label>("index");
    return timeDict.get<scalar>("value");
}


template<class Real>
sh::Problem<Real> ensembleRun<Real>::memberProblem
(
    const label k,
    const sh::Problem<Real>& base,
    const bool fresh
) const
{
    const ensembleInput::member& m = ens_.members[k];
    sh::Problem<Real> pb = base;
    const sh::JetParams<Real> jet = pb.params.jet;
    try
    {
        pb.params = sh::makeParams<Real>(ens_.memberModel(ac_.input, k));
    }
    catch (const sh::InputError& e)
    {
        FatalErrorInFunction
            << "Member " << k << ": " << e.what() << nl
            << exit(FatalError);
    }
    pb.params.jet = jet;
    if (ens_.variesCResistance)
    {
        // The member's resistance: the case's field times its factor, as
        // its single run reads that product from its 0/cResistance (in
        // the field's precision, then the problem's)
        const scalarField c = memberResistance(k);
        forAll(c, cell)
        {
            pb.cResistance[ac_.smesh.gridIndex(cell)] = Real(c[cell]);
        }
    }
    if (!fresh)
    {
        // A restart: the base holds the member's state (and cover) already
        return pb;
    }
    if (!m.release.empty())
    {
        const volScalarField hr
        (
            IOobject
            (
                m.release, startName_, ac_.mesh,
                IOobject::MUST_READ, IOobject::NO_WRITE, false
            ),
            ac_.mesh
        );
        forAll(hr, c)
        {
            const label i = ac_.smesh.gridIndex(c);
            if (!(hr[c] >= 0 && hr[c] < 1e30))
            {
                FatalErrorInFunction
                    << hr.objectPath() << ": member " << k << ": release field " << m.release
                    << " has h = " << hr[c] << " in cell " << c
                    << nl << "Valid: 0 <= h < 1e30" << nl
                    << exit(FatalError);
            }
            if (ac_.input.plan())
            {
                // h normal to the bed: the volume per plan area J h, as
                // avalancheCase::toPlanState forms it
                const Real H = Real(hr[c])*Real(ac_.planJ[c]);
                pb.h[i] = H;
                pb.hu[i] = H*Real(ac_.U[c].x());
                pb.hv[i] = H*Real(ac_.U[c].y());
                continue;
            }
            pb.h[i] = Real(hr[c]);
            pb.hu[i] = Real(hr[c]*ac_.U[c].x());
            pb.hv[i] = Real(hr[c]*ac_.U[c].y());
        }
    }
    if (m.hScale != 1)
    {
        const Real s = Real(m.hScale);
        for (std::size_t i = 0; i < pb.h.size(); ++i)
        {
            pb.h[i] *= s;
            pb.hu[i] *= s;
            pb.hv[i] *= s;
        }
    }
    return pb;
}


template<class Real>
void ensembleRun<Real>::makeViewable(const fileName& dir) const
{
    mkDir(dir);
    for (const word& d : {word("constant"), word("system")})
    {
        if (!exists(dir/d, false, false))
        {
            ln(fileName("../..")/d, dir/d);
        }
    }
    if (!isFile(dir/(dir.name() + ".foam")))
    {
        OFstream os(dir/(dir.name() + ".foam"));
    }
}


template<class Real>
scalarField ensembleRun<Real>::memberResistance(const label k) const
{
    return cResistance0_*ens_.members[k].cResistanceScale;
}


template<class Real>
void ensembleRun<Real>::writeMembers()
{
    std::vector<Real> h, hu, hv, layer, eroded;
    for (label k = 0; k < n_; ++k)
    {
        solver_->getState(k, h, hu, hv);
        if (!ac_.store(h, hu, hv, solver_->peakMaps(k)))
        {
            FatalErrorInFunction
                << "Member " << k << " (" << ens_.describe(k).c_str()
                << "): the solution at t = " << solver_->time(k)
                << " is not finite or has h < 0; nothing of this time"
                << " is written for it" << nl << exit(FatalError);
        }
        // Its cover: the layer left and the depth taken up (with a
        // model; else the fields as read), its resistance field
        solver_->getCover(k, layer, eroded);
        ac_.fillCover(layer, eroded);
        if (ens_.variesCResistance)
        {
            ac_.cResistance->primitiveFieldRef() = memberResistance(k);
            ac_.cResistance->correctBoundaryConditions();
        }
        runTime_.setTime(solver_->time(k), steps0_[k] + solver_->steps(k));
        writers_[k].write();
    }
}


template<class Real>
void ensembleRun<Real>::restoreKilledWrites() const
{
    for (label k = 0; k <= n_; ++k)
    {
        const fileName dir = k < n_
            ? runTime_.path()/memberDir(k)
            : runTime_.path()/"ensemble"/"statistics";
        restoreReplaced(dir);
        if (isDir(dir/stagingDirName, false))
        {
            WarningInFunction
                << "Removing " << dir/stagingDirName << ": incomplete"
                << " time directories of a run stopped while writing"
                << nl << endl;
            rmDir(dir/stagingDirName);
        }
    }
}


template<class Real>
scalar ensembleRun<Real>::startPoint(word& restartName) const
{
    const scalar tRestart =
        ac_.input.control.startFrom == "latestTime"
      ? restartTime(restartName) : -1;
    // latestTime continues the same ensemble or none: an ensemble/ of
    // another (more members, or members without a common time) is
    // kept and refused
    if
    (
        ac_.input.control.startFrom == "latestTime"
     && isDir(runTime_.path()/memberDir(0))
     && (tRestart < 0 || isDir(runTime_.path()/memberDir(n_)))
    )
    {
        FatalErrorInFunction
            << "ensemble/ holds another ensemble (other members, or no"
            << " time all " << n_ << " members of this ensembleDict"
            << " have): startFrom latestTime cannot continue it" << nl
            << "Remove ensemble/ (or move it away), or start afresh"
            << " with startFrom startTime (which replaces it)" << nl
            << exit(FatalError);
    }
    return tRestart;
}


template<class Real>
void ensembleRun<Real>::setUpMembers
(
    const scalar tRestart,
    const word& restartName
)
{
    if (ens_.variesCResistance)
    {
        // The case's resistance, which each member scales
        cResistance0_ = ac_.cResistance->primitiveField();
    }
    const sh::Problem<Real> base = ac_.problem<Real>();
    const bool restarted = tRestart >= 0;
    problems_.reserve(n_);
    steps0_.assign(n_, 0);
    for (label k = 0; k < n_; ++k)
    {
        if (tRestart >= 0)
        {
            // The same ensemble, or none
            checkSameMember(k);
            const scalar t = readMember(k, restartName);
            runTime_.setTime(t, 0);
            problems_.push_back(memberProblem(k, ac_.problem<Real>(), false));
        }
        else
        {
            problems_.push_back(memberProblem(k, base, true));
        }
        // The release's volume and top (also on a restart)
        if (k == 0)
        {
            surfacePositions(problems_.back());
        }
        const sh::Problem<Real> fresh =
            restarted ? memberProblem(k, base, true) : problems_.back();
        released_.push_back(fresh.volume());
        top_.push_back(releaseTop(fresh));
    }
}


template<class Real>
void ensembleRun<Real>::makeDirectories()
{
    atomicWriter caseWriter(runTime_);
    const label purge = caseWriter.purgeWrite();
    // A fresh start replaces what an earlier ensemble left (its later
    // times would otherwise be taken up by a restart)
    const fileName ensembleDir = runTime_.path()/"ensemble";
    if (!restarted_ && isDir(ensembleDir))
    {
        WarningInFunction
            << "Replacing " << ensembleDir << " of an earlier run (a"
            << " fresh start: startFrom " << ac_.input.control.startFrom
            << (ac_.input.control.startFrom == "latestTime"
                ? ", no time every member of this ensembleDict has"
                : "")
            << ")" << nl << endl;
        rmDir(ensembleDir);
    }
    for (label k = 0; k < n_; ++k)
    {
        makeViewable(runTime_.path()/memberDir(k));
        writers_.append(new atomicWriter(runTime_, memberDir(k), purge));
        // Written by hand: regIOobject::write would put it in the
        // current time directory
        const IOobject io
        (
            "parameters", memberDir(k), runTime_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        );
        OFstream os(runTime_.path()/memberDir(k)/"parameters");
        os.precision(17);
        io.writeHeader(os, word("dictionary"));
        ens_.memberDict(k).write(os, false);
        IOobject::writeEndDivider(os);
    }
    makeViewable(runTime_.path()/"ensemble"/"statistics");
    statsWriter_.reset
    (
        new atomicWriter(runTime_, fileName("ensemble")/"statistics", purge)
    );
}


template<class Real>
ensembleRun<Real>::ensembleRun
(
    avalancheCase& ac,
    const word& backend,
    const scalar logInterval
)
:
    ac_(ac),
    runTime_(ac.runTime),
    ens_(ac.runTime, ac.input),
    logInterval_(logInterval),
    n_(ens_.members.size()),
    startName_(ac.runTime.timeName())
{
    checkOptions();
    if (!ac_.input.control.writeFields.empty())
    {
        WarningInFunction
            << "writeFields (system/controlDict) applies to single runs:"
            << " the ensemble writes every field of its members and"
            << " statistics" << nl << endl;
    }

    // What a run killed while writing left (timeDirectories.H): a
    // directory it was replacing back in place, the incomplete ones
    // removed; before the restart looks for the members' times
    restoreKilledWrites();

    // Restart from the members' latest common time, or start
    word restartName;
    const scalar tRestart = startPoint(restartName);
    setUpMembers(tRestart, restartName);
    restarted_ = tRestart >= 0;
    if (restarted_)
    {
        Info<< "Restart of the ensemble from t = " << restartName
            << " (the latest time every member has)" << nl << endl;
    }

    // The backend
    solver_ = selectEnsembleBackend<Real>(backend, problems_);
    endIfSignalled("setting up the backend");
    solver_->setMaxDt(ac_.input.maxDeltaT);
    solver_->setInterrupt(&runSignals::pending);
    Info<< "Ensemble of " << n_ << " members on "
        << solver_->name().c_str() << nl << endl;

    // The directories: members and statistics, viewable as cases
    makeDirectories();
}


template<class Real>
void ensembleRun<Real>::run()
{
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    const scalar endTime = runTime_.endTime().value();
    scalar t = solver_->time(0);
    const scalar origin = ac_.writeOrigin(t);
    if (!restarted_)
    {
        // A fresh start: the initial states too
        runTime_.setTime(t, 0);
        writeMembers();
        writeStatistics();
    }
    double stepping = 0;
    // The progress of the slowest member, to endTime
    etaEstimate eta;
    eta.start(t, 0);
    const scalar tStart = t;
    // The progress line of the slowest member; final: "end" in place of
    // the ETA (the last line, as a single run's)
    const auto logProgress = [&](const scalar next, const bool final)
    {
        long lo = solver_->steps(0), hi = lo;
        double tMin = solver_->time(0);
        for (label k = 1; k < n_; ++k)
        {
            lo = std::min(lo, solver_->steps(k));
            hi = std::max(hi, solver_->steps(k));
            tMin = std::min(tMin, solver_->time(k));
        }
        const double done = (tMin - tStart)/max(endTime - tStart, SMALL);
        Info<< "Time = " << tMin << " (slowest member, "
            << label(100*done) << "% of endTime " << endTime
            << "), next write " << next
            << ", steps per member " << lo << " .. " << hi
            << (
                   final
                 ? std::string("  end")
                 : "  ETA " + eta.text(tMin, 0, HUGE_VAL, endTime)
               ).c_str()
            << nl;
        return tMin;
    };
    // Plan coordinates: a single run also stops at the samples of its
    // centre of mass (avalancheRun::advance, avalancheCase::nextComTime,
    // on the write times' grid), so every member stops there too: the
    // same steps (nothing is recorded there)
    const bool samples = ac_.input.plan();
    scalar nextCom = -GREAT;
    // Where every member stands: the last stop reached
    scalar tStop = t;
    clock::time_point lastLog = clock::now();
    while (t < endTime)
    {
        // The next write time, on the grid of a single run
        const scalar next = ac_.nextWriteTime(t, origin, endTime);
        const clock::time_point t0 = clock::now();
        bool reached = false;
        while (!reached)
        {
            // The next stop: the write time, or before it a sample
            scalar target = next;
            if (samples)
            {
                // From tStop, as the single run from its clock, which is
                // the last target it reached wherever it computes its
                // next sample
                if (!(nextCom > tStop))
                {
                    nextCom = ac_.nextComTime(tStop, origin, endTime);
                }
                target = min(target, nextCom);
            }
            const bool hit = solver_->advance(target, logInterval_);
            if (hit)
            {
                tStop = target;
            }
            // At a sample before the write time: on to the next stop
            reached = hit && !(target < next);
            if (runSignals::pending)
            {
                runSignals::pending = 0;
                if (runSignals::stop)
                {
                    Info<< nl << runSignals::name(runSignals::last)
                        << ": the ensemble stops; its last write time"
                        << " is its restart point" << nl << endl;
                    const scalar tMin = logProgress(next, true);
                    Info<< "End of run at t = " << tMin << " s: "
                        << runSignals::name(runSignals::last)
                        << " (signal; the last write time " << t
                        << " s is the restart point)" << nl;
                    return;
                }
                Info<< runSignals::name(runSignals::last)
                    << ": an ensemble writes at its write times only"
                    << nl;
            }
            // A progress line where a logInterval passed (one advance's
            // budget) or at the write time; not at every sample
            if
            (
                !hit || reached
             || std::chrono::duration<double>(clock::now() - lastLog).count()
             >= logInterval_
            )
            {
                logProgress(next, reached && next >= endTime);
                lastLog = clock::now();
            }
        }
        stepping +=
            std::chrono::duration<double>(clock::now() - t0).count();
        t = next;
        writeMembers();
        writeStatistics();
        Info<< "Wrote t = " << runTime_.timeName() << ": " << n_
            << " members and the statistics" << nl << endl;
    }
    // As a single run's last line of the time loop (an ensemble has no
    // steady-state stop: each member runs to endTime)
    Info<< "End of run at t = " << t << " s: endTime (every member)" << nl
        << endl;
    writeReport();
    const double cells = double(ac_.h.size());
    label steps = 0;   // in this run
    for (label k = 0; k < n_; ++k)
    {
        steps += solver_->steps(k);
    }
    Info<< "Ensemble: " << n_ << " members, " << steps << " member steps"
        << " in " << stepping << " s of stepping ("
        << std::chrono::duration<double>(clock::now() - start).count()
        << " s wall)" << nl
        << "Cell updates per second: "
        << (stepping > 0 ? cells*double(steps)/stepping : 0) << nl
        << "Wet cell updates per second: "
        << (stepping > 0 ? double(solver_->wetCellUpdates())/stepping : 0)
        << nl << endl;
}


// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * //

template class ensembleRun<float>;
template class ensembleRun<double>;

} // End namespace Foam

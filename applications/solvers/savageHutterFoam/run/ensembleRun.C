/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "ensembleRun.H"
#include "backendSelection.H"
#include "runSignals.H"
#include "startUp.H"
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
        pb.params = sh::makeParams<Real>
        (
            ac_.input.memberModel(ens_.keys, m.values)
        );
    }
    catch (const sh::InputError& e)
    {
        FatalErrorInFunction
            << "Member " << k << ": " << e.what() << nl
            << exit(FatalError);
    }
    pb.params.jet = jet;
    if (!fresh)
    {
        // A restart: the base holds the member's state already
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
void ensembleRun<Real>::writeMembers()
{
    std::vector<Real> h, hu, hv;
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
        runTime_.setTime(solver_->time(k), steps0_[k] + solver_->steps(k));
        writers_[k].write();
    }
}


template<class Real>
void ensembleRun<Real>::peakValues
(
    std::vector<double>& hv,
    std::vector<double>& uv,
    std::vector<double>& pv
) const
{
    const label nc = ac_.h.size();
    const bool pressure = ac_.pMax.valid();
    hv.assign(std::size_t(nc)*n_, 0);
    uv.assign(hv.size(), 0);
    pv.assign(pressure ? hv.size() : 0, 0);
    for (label k = 0; k < n_; ++k)
    {
        const sh::PeakMaps<Real> p = solver_->peakMaps(k);
        forAll(ac_.h, c)
        {
            const label i = ac_.smesh.gridIndex(c);
            const std::size_t at = std::size_t(c)*n_ + k;
            hv[at] = double(p.h[i]);
            uv[at] = double(p.speed[i]);
            if (pressure)
            {
                pv[at] = double(p.pressure[i]);
            }
        }
    }
}


namespace
{

//- A statistic's field name: prefix and x as "%g"
word named(const char* prefix, const scalar x)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%g", prefix, x);
    return word(buf);
}

} // namespace


template<class Real>
label ensembleRun<Real>::addField
(
    PtrList<volScalarField>& fields,
    const word& name,
    const dimensionSet& dims
) const
{
    fields.append
    (
        new volScalarField
        (
            IOobject
            (
                name, runTime_.timeName(), ac_.mesh,
                IOobject::NO_READ, IOobject::AUTO_WRITE
            ),
            ac_.mesh,
            dimensionedScalar(name, dims, 0),
            "zeroGradient"
        )
    );
    return fields.size() - 1;
}


template<class Real>
void ensembleRun<Real>::addExceedances
(
    PtrList<volScalarField>& fields,
    const std::vector<double>& hv
) const
{
    const label nc = ac_.h.size();
    forAll(ens_.thresholds, q)
    {
        const scalar thr = ens_.thresholds[q];
        const label f = addField(fields, named("hMaxExceedance_", thr), dimless);
        for (label c = 0; c < nc; ++c)
        {
            label above = 0;
            for (label k = 0; k < n_; ++k)
            {
                above += hv[std::size_t(c)*n_ + k] > thr;
            }
            fields[f][c] = scalar(above)/n_;
        }
    }
}


template<class Real>
void ensembleRun<Real>::addSummary
(
    PtrList<volScalarField>& fields,
    const std::vector<double>& all,
    const word& name,
    const dimensionSet& dims
) const
{
    const label nc = ac_.h.size();
    std::vector<double> v(n_);
    const label mean = addField(fields, name + "Mean", dims);
    List<label> pct(ens_.percentiles.size());
    forAll(pct, q)
    {
        pct[q] = addField(fields, named((name + "P").c_str(), ens_.percentiles[q]), dims);
    }
    for (label c = 0; c < nc; ++c)
    {
        double sum = 0;
        for (label k = 0; k < n_; ++k)
        {
            v[k] = all[std::size_t(c)*n_ + k];
            sum += v[k];
        }
        fields[mean][c] = sum/n_;
        std::sort(v.begin(), v.end());
        forAll(pct, q)
        {
            const double r = ens_.percentiles[q]/100*(n_ - 1);
            const label lo = std::min(label(std::floor(r)), n_ - 1);
            const label hi = std::min(lo + 1, n_ - 1);
            fields[pct[q]][c] = v[lo] + (r - lo)*(v[hi] - v[lo]);
        }
    }
}


template<class Real>
void ensembleRun<Real>::writeStatistics()
{
    // Per cell the members' values (member fastest)
    std::vector<double> hv, uv, pv;
    peakValues(hv, uv, pv);

    PtrList<volScalarField> fields;
    addExceedances(fields, hv);
    addSummary(fields, hv, "hMax", dimLength);
    addSummary(fields, uv, "UMax", dimVelocity);
    if (ac_.pMax.valid())
    {
        addSummary(fields, pv, "pMax", dimPressure);
    }
    for (volScalarField& f : fields)
    {
        f.correctBoundaryConditions();
    }

    // Only these: the case's own fields are left out of this write
    List<regIOobject*> quiet
    ({
        &ac_.h, &ac_.U, &ac_.hU, &ac_.regime, &ac_.hMax, &ac_.UMax,
        &ac_.tArrival
    });
    if (ac_.pMax.valid())
    {
        quiet.append(ac_.pMax.get());
    }
    for (regIOobject* f : quiet)
    {
        f->writeOpt() = IOobject::NO_WRITE;
    }
    statsWriter_->write();
    for (regIOobject* f : quiet)
    {
        f->writeOpt() = IOobject::AUTO_WRITE;
    }
}


template<class Real>
void ensembleRun<Real>::position
(
    const sh::Problem<Real>& pb,
    const label i,
    const label j,
    double& E,
    double& X
) const
{
    const double zeta = double(pb.zeta[i]);
    const double zb = double(pb.zb[pb.cell(i, j)]);
    E = E0_[i] + zb*std::cos(zeta);
    X = X0_[i] - zb*std::sin(zeta);
}


template<class Real>
void ensembleRun<Real>::surfacePositions(const sh::Problem<Real>& pb)
{
    const label nx = pb.grid.nx;
    const double dx = double(pb.grid.dx);
    E0_.resize(nx);
    X0_.resize(nx);
    double e = 0, x = 0;
    for (label i = 0; i < nx; ++i)
    {
        const double z = double(pb.zeta[i]);
        E0_[i] = e - 0.5*dx*std::sin(z);
        X0_[i] = x + 0.5*dx*std::cos(z);
        e -= dx*std::sin(z);
        x += dx*std::cos(z);
    }
}


template<class Real>
FixedList<double, 3> ensembleRun<Real>::releaseTop(const sh::Problem<Real>& pb) const
{
    FixedList<double, 3> top({-1e300, 0, 0});
    for (label j = 0; j < pb.grid.ny; ++j)
    {
        for (label i = 0; i < pb.grid.nx; ++i)
        {
            double E, X;
            position(pb, i, j, E, X);
            if (double(pb.h[pb.cell(i, j)]) > ens_.runoutThreshold && E > top[0])
            {
                top = {E, X, double(pb.grid.yc(j))};
            }
        }
    }
    return top;
}


template<class Real>
void ensembleRun<Real>::writeReport()
{
    const sh::Problem<Real>& pb0 = problems_[0];
    const label nx = pb0.grid.nx;
    const label ny = pb0.grid.ny;
    const double dx = double(pb0.grid.dx);
    const double dy = double(pb0.grid.dy);
    const double thr = ens_.runoutThreshold;

    OFstream os(runTime_.path()/"ensemble"/"report.dat");
    os.precision(10);
    os  << "# savageHutterFoam -ensemble: " << n_ << " members, t = "
        << runTime_.timeName() << nl
        << "# runout: the cell reached (hMax > " << thr << " m) farthest"
        << " downslope; travel angle from the highest released cell"
        << " (h > " << thr << " m at the start) to it [deg]" << nl
        << "# member";
    for (const word& k : ens_.keys) { os << ' ' << k; }
    if (ens_.variesHScale) { os << " hScale"; }
    if (ens_.variesRelease) { os << " release"; }
    os  << " releasedVolume volume runoutX runoutY travelAngle steps" << nl;
    for (label k = 0; k < n_; ++k)
    {
        const sh::Problem<Real>& pb = problems_[k];
        const sh::PeakMaps<Real> p = solver_->peakMaps(k);
        // Top of the release, runout point
        const double eTop = top_[k][0];
        const double xTop = top_[k][1];
        const double yTop = top_[k][2];
        double xRun = -1e300, eRun = 0, yRun = 0, xcRun = 0;
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                double E, X;
                position(pb, i, j, E, X);
                const label c = pb.cell(i, j);
                if (double(p.h[c]) > thr && X > xRun)
                {
                    xRun = X;
                    eRun = E;
                    yRun = double(pb.grid.yc(j));
                    xcRun = double(pb.grid.xc(i));
                }
            }
        }
        const bool moved = eTop > -1e300 && xRun > -1e300;
        const double d = moved
            ? std::hypot(xRun - xTop, yRun - yTop) : 0;
        const double angle = moved && d > 0
            ? std::atan2(eTop - eRun, d)*180/constant::mathematical::pi
            : 0;
        std::vector<Real> h, hu, hv;
        solver_->getState(k, h, hu, hv);
        double vol = 0;
        for (const Real hc : h) { vol += double(hc); }
        vol *= dx*dy;

        os  << k;
        const ensembleInput::member& m = ens_.members[k];
        for (const scalar v : m.values) { os << ' ' << v; }
        if (ens_.variesHScale) { os << ' ' << m.hScale; }
        if (ens_.variesRelease) { os << ' ' << m.release; }
        os  << ' ' << released_[k] << ' ' << vol << ' '
            << (moved ? xcRun : 0) << ' ' << (moved ? yRun : 0) << ' '
            << angle << ' ' << steps0_[k] + solver_->steps(k) << nl;
    }
    Info<< "Wrote " << os.name() << nl;
}


template<class Real>
void ensembleRun<Real>::checkOptions() const
{
    if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "-ensemble runs serial: not with -parallel" << nl
            << exit(FatalError);
    }
    if (ac_.input.steadyStateTolerance > 0)
    {
        Info<< "Note: steadyStateTolerance is not applied to an"
            << " ensemble: every member runs to endTime" << nl << endl;
    }
    if (ac_.input.kineticEnergyStop > 0)
    {
        Info<< "Note: kineticEnergyStop is not applied to an"
            << " ensemble: every member runs to endTime" << nl << endl;
    }
    const word wc = ac_.input.writeControl;
    if (wc != "adjustableRunTime" && wc != "runTime")
    {
        FatalIOErrorInFunction(runTime_.controlDict())
            << "writeControl " << wc << ": an ensemble writes its"
            << " members at common times." << nl
            << "Valid choices with -ensemble: (adjustableRunTime runTime)"
            << nl << exit(FatalIOError);
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
void ensembleRun<Real>::checkSameMember(const label k) const
{
    const IOdictionary had
    (
        IOobject
        (
            "parameters", memberDir(k), runTime_,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    dictionary now = ens_.memberDict(k);
    OStringStream a, b;
    a.precision(17);
    b.precision(17);
    for (const entry& e : now) { a << e; }
    for (const entry& e : had) { if (e.keyword() != "FoamFile") b << e; }
    if (a.str() != b.str())
    {
        FatalErrorInFunction
            << "ensemble/ holds another ensemble: "
            << memberDir(k) << "/parameters differs from what"
            << " ensembleDict makes of member " << k << nl
            << "Remove ensemble/ (or move it away) to start the"
            << " new ensemble" << nl << exit(FatalError);
    }
}


template<class Real>
void ensembleRun<Real>::setUpMembers
(
    const scalar tRestart,
    const word& restartName
)
{
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
    while (t < endTime)
    {
        // The next write time, on the grid of a single run
        const scalar next = ac_.nextWriteTime(t, origin, endTime);
        const clock::time_point t0 = clock::now();
        bool reached = false;
        while (!reached)
        {
            reached = solver_->advance(next, logInterval_);
            if (runSignals::pending)
            {
                runSignals::pending = 0;
                if (runSignals::stop)
                {
                    Info<< nl << runSignals::name(runSignals::last)
                        << ": the ensemble stops; its last write time"
                        << " is its restart point" << nl << endl;
                    return;
                }
                Info<< runSignals::name(runSignals::last)
                    << ": an ensemble writes at its write times only"
                    << nl;
            }
            long lo = solver_->steps(0), hi = lo;
            double tMin = solver_->time(0);
            for (label k = 1; k < n_; ++k)
            {
                lo = std::min(lo, solver_->steps(k));
                hi = std::max(hi, solver_->steps(k));
                tMin = std::min(tMin, solver_->time(k));
            }
            Info<< "Time = " << tMin << " (slowest member) of " << next
                << ", steps per member " << lo << " .. " << hi << nl;
        }
        stepping +=
            std::chrono::duration<double>(clock::now() - t0).count();
        t = next;
        writeMembers();
        writeStatistics();
        Info<< "Wrote t = " << runTime_.timeName() << ": " << n_
            << " members and the statistics" << nl << endl;
    }
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

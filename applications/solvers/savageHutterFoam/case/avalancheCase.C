/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "avalancheCase.H"
#include "physics/planTerrain.H"

namespace Foam
{

void timeNames::distinguish
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


bool avalancheCase::onAll(const bool here, const char* file)
{
    const bool all = !anyProcessor(!here);
    if (here && !all)
    {
        Pout<< "Restart file " << file << " is missing on other"
            << " processors: not used here either" << endl;
    }
    return all;
}


IOobject avalancheCase::io(const Time& t, const fvMesh& m, const word& name,
                   IOobject::readOption r)
{
    return IOobject(name, t.timeName(), m, r, IOobject::AUTO_WRITE);
}


IOobject avalancheCase::reading(const Time& t, const fvMesh& m, const word& name)
{
    Info<< "Reading field " << name << endl;
    return io(t, m, name, IOobject::MUST_READ);
}


volScalarField* avalancheCase::readIfPresent
(
    const Time& t,
    const fvMesh& m,
    const word& name
)
{
    const bool here =
        io(t, m, name, IOobject::MUST_READ).typeHeaderOk<volScalarField>(true);
    if (!onAll(here, name.c_str()))
    {
        return nullptr;
    }
    return new volScalarField(reading(t, m, name), m);
}


volScalarField* avalancheCase::readOrZero
(
    const Time& t,
    const fvMesh& m,
    const word& name
)
{
    volScalarField* f = readIfPresent(t, m, name);
    if (f)
    {
        return f;
    }
    return new volScalarField
    (
        io(t, m, name, IOobject::NO_READ), m,
        dimensionedScalar(dimLength, Zero)
    );
}


avalancheCase::avalancheCase(Time& t, const fvMesh& m)
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
    pMax
    (
        input.model.rho > 0
      ? new volScalarField
        (
            io(t, m, "pMax", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimPressure, Zero)
        )
      : nullptr
    ),
    tArrival(io(t, m, "tArrival", IOobject::READ_IF_PRESENT), m,
        dimensionedScalar("tArrival", dimTime, -1)),
    sides(),
    hasMomentum(onAll(io(t, m, "hU", IOobject::MUST_READ)
        .typeHeaderOk<volVectorField>(true), "hU")),
    hasPeaks(onAll(io(t, m, "hMax", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true)
     && io(t, m, "UMax", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true), "hMax or UMax")),
    hasPressure(onAll(hasPeaks && pMax.valid()
     && io(t, m, "pMax", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true), "pMax")),
    hasArrival(onAll(hasPeaks
     && io(t, m, "tArrival", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true), "tArrival")),
    hEntrainable(readIfPresent(t, m, "hEntrainable")),
    // With the layer: what it has lost so far (a restart's), else 0
    erodedDepth
    (
        hEntrainable.valid() ? readOrZero(t, m, "erodedDepth") : nullptr
    ),
    cResistance(readIfPresent(t, m, "cResistance")),
    hasEroded(hEntrainable.valid() && onAll(io(t, m, "erodedDepth",
        IOobject::MUST_READ).typeHeaderOk<volScalarField>(true),
        "erodedDepth")),
    HEntrainable
    (
        input.plan() && hEntrainable.valid()
      ? new volScalarField
        (
            io(t, m, "HEntrainable", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimLength, Zero)
        )
      : nullptr
    ),
    HErodedDepth
    (
        HEntrainable.valid()
      ? new volScalarField
        (
            io(t, m, "HErodedDepth", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimLength, Zero)
        )
      : nullptr
    ),
    hasPlanCover(onAll(HEntrainable.valid() && hasEroded
     && io(t, m, "HEntrainable", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true)
     && io(t, m, "HErodedDepth", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true), "HEntrainable or HErodedDepth")),
    H
    (
        input.plan()
      ? new volScalarField
        (
            io(t, m, "H", IOobject::READ_IF_PRESENT), m,
            dimensionedScalar(dimLength, Zero)
        )
      : nullptr
    ),
    hasVolume(onAll(input.plan()
     && io(t, m, "H", IOobject::MUST_READ)
        .typeHeaderOk<volScalarField>(true), "H"))
{}


template<class Real>
void avalancheCase::copyFields(sh::Problem<Real>& pb) const
{
    sh::PeakMaps<Real>& peaks = pb.peaks;
    if (hasPeaks)
    {
        peaks.h.resize(h.size());
        peaks.speed.resize(h.size());
        peaks.pressure.resize(hasPressure ? h.size() : 0);
        peaks.arrival.resize(hasArrival ? h.size() : 0);
    }
    forAll(h, c)
    {
        const label k = smesh.gridIndex(c);
        if (hasPeaks)
        {
            peaks.h[k] = Real(hMax[c]);
            peaks.speed[k] = Real(UMax[c]);
        }
        if (hasPressure)
        {
            peaks.pressure[k] = Real(pMax()[c]);
        }
        if (hasArrival)
        {
            peaks.arrival[k] = float(tArrival[c]);
        }
        pb.zb[k] = Real(zb[c]);
        pb.h[k] = Real(h[c]);
        pb.hu[k] = Real(hasMomentum ? hU[c].x() : h[c]*U[c].x());
        pb.hv[k] = Real(hasMomentum ? hU[c].y() : h[c]*U[c].y());
    }
}


template<class Real>
void avalancheCase::copyCover(sh::Problem<Real>& pb)
{
    // Plan coordinates: the layer per plan area, J times the normal
    // thickness, as H = J h (toPlanState has set planJ); a restart's
    // HEntrainable and HErodedDepth where they agree with it
    const bool plan = input.plan();
    if (hEntrainable.valid())
    {
        const volScalarField& l = hEntrainable();
        const volScalarField& e = erodedDepth();
        if (hasPlanCover)
        {
            const auto differ = [](const scalar a, const scalar b)
            {
                return mag(a - b) > 1e-9*(mag(a) + mag(b)) + VSMALL;
            };
            label off = 0;
            forAll(l, c)
            {
                off +=
                    differ(HEntrainable()[c], planJ[c]*l[c])
                 || differ(HErodedDepth()[c], planJ[c]*e[c]);
            }
            reduce(off, sumOp<label>());
            if (off)
            {
                WarningInFunction
                    << "HEntrainable or HErodedDepth disagrees with J"
                    << " hEntrainable or J erodedDepth in " << off
                    << " cells (hEntrainable or erodedDepth edited after"
                    << " the write?): using J hEntrainable and J"
                    << " erodedDepth" << nl << endl;
                hasPlanCover = false;
            }
            else
            {
                Info<< "Reading fields HEntrainable and HErodedDepth: the"
                    << " layer and the eroded depth per plan area, exact"
                    << " for the restart" << nl;
            }
        }
        pb.hEntrainable.resize(h.size());
        pb.erodedDepth.resize(hasEroded ? h.size() : 0);
        forAll(h, c)
        {
            const label k = smesh.gridIndex(c);
            if (hasPlanCover)
            {
                pb.hEntrainable[k] = Real(HEntrainable()[c]);
                pb.erodedDepth[k] = Real(HErodedDepth()[c]);
                continue;
            }
            // J as toPlanState forms H = J h
            const Real J = plan ? Real(planJ[c]) : Real(1);
            pb.hEntrainable[k] = plan ? Real(l[c])*J : Real(l[c]);
            if (hasEroded)
            {
                pb.erodedDepth[k] = plan ? Real(e[c])*J : Real(e[c]);
            }
        }
        if (HEntrainable.valid() && !hasPlanCover)
        {
            // What the run starts from, written as such until an
            // entrainment model changes it (fillCover)
            scalarField& L = HEntrainable->primitiveFieldRef();
            scalarField& E = HErodedDepth->primitiveFieldRef();
            forAll(h, c)
            {
                const label k = smesh.gridIndex(c);
                L[c] = pb.hEntrainable[k];
                E[c] = hasEroded ? scalar(pb.erodedDepth[k]) : 0;
            }
            HEntrainable->correctBoundaryConditions();
            HErodedDepth->correctBoundaryConditions();
        }
    }
    if (cResistance.valid())
    {
        // A coefficient per bed area: the same in both coordinates
        pb.cResistance.resize(h.size());
        forAll(h, c)
        {
            pb.cResistance[smesh.gridIndex(c)] = Real(cResistance()[c]);
        }
    }
}


template<class Real>
void avalancheCase::fillCover
(
    const std::vector<Real>& layer,
    const std::vector<Real>& eroded
)
{
    if (!hEntrainable.valid() || layer.empty())
    {
        return;
    }
    const bool plan = input.plan();
    const label n = h.size();
    scalar* lp = hEntrainable->primitiveFieldRef().data();
    scalar* ep = erodedDepth->primitiveFieldRef().data();
    const scalar* Jp = plan ? planJ.cdata() : nullptr;
    scalar* Lp = plan ? HEntrainable->primitiveFieldRef().data() : nullptr;
    scalar* Ep = plan ? HErodedDepth->primitiveFieldRef().data() : nullptr;
    #pragma omp parallel for schedule(static)
    for (label c = 0; c < n; ++c)
    {
        const label k = smesh.gridIndex(c);
        lp[c] = layer[k];
        ep[c] = eroded[k];
        if (plan)
        {
            // The scheme's per plan area, and the thickness normal to
            // the bed
            Lp[c] = layer[k];
            Ep[c] = eroded[k];
            lp[c] = scalar(layer[k])/Jp[c];
            ep[c] = scalar(eroded[k])/Jp[c];
        }
    }
    hEntrainable->correctBoundaryConditions();
    erodedDepth->correctBoundaryConditions();
    if (plan)
    {
        HEntrainable->correctBoundaryConditions();
        HErodedDepth->correctBoundaryConditions();
    }
}


template<class Real>
void avalancheCase::toPlanState(sh::Problem<Real>& pb, sh::Halo<Real>* halo)
{
    // The bed's metric as the scheme has it (HostGeometry: centred
    // differences of the padded zb; InputError naming coordinates where
    // the inclination is not 0)
    const sh::HostGeometry<Real> geo(pb, halo);
    const sh::Grid<Real>& g = pb.grid;
    planJ.setSize(h.size());
    planP.setSize(h.size());
    planQ.setSize(h.size());
    std::vector<Real> J(h.size());
    forAll(h, c)
    {
        const label k = smesh.gridIndex(c);
        const int pc = g.idx(int(k % g.nx), int(k/g.nx));
        const sh::PlanMetric<Real> m = sh::planMetric
        (
            geo.planP[pc], geo.planQ[pc], geo.planBxx[pc], geo.planBxy[pc],
            geo.planByy[pc]
        );
        J[c] = m.J;
        planJ[c] = m.J;
        planP[c] = m.p;
        planQ[c] = m.q;
    }

    // A restart's H and hU continue exactly, unless h or U were edited
    // after the write (they then disagree, and h and U win)
    auto differ = [](const scalar a, const scalar b)
    {
        return mag(a - b) > 1e-9*(mag(a) + mag(b)) + VSMALL;
    };
    label volumeOff = 0, momentumOff = 0;
    forAll(h, c)
    {
        const scalar Hc = hasVolume ? H()[c] : J[c]*h[c];
        if (h[c] <= input.model.hDry)
        {
            continue;
        }
        volumeOff += hasVolume && differ(Hc, J[c]*h[c]);
        momentumOff += hasMomentum
         && (differ(hU[c].x(), Hc*U[c].x()) || differ(hU[c].y(), Hc*U[c].y()));
    }
    reduce(volumeOff, sumOp<label>());
    reduce(momentumOff, sumOp<label>());
    if (volumeOff)
    {
        WarningInFunction
            << "H (the volume per plan area) disagrees with J h in "
            << volumeOff << " cells (h edited after the write?): using J h"
            << " and J h U" << nl << endl;
        hasVolume = false;
        hasMomentum = false;
    }
    else if (momentumOff)
    {
        WarningInFunction
            << "hU disagrees with H U in " << momentumOff << " cells (U"
            << " edited after the write?): using H U" << nl << endl;
        hasMomentum = false;
    }
    else if (hasVolume && hasMomentum)
    {
        Info<< "Reading fields H and hU: the volume and momentum per plan"
            << " area, exact for the restart" << nl;
    }
    forAll(h, c)
    {
        const label k = smesh.gridIndex(c);
        // H = J h as the scheme forms it (planVolume)
        const Real Hc = hasVolume ? Real(H()[c]) : Real(h[c])*J[c];
        pb.h[k] = Hc;
        pb.hu[k] = hasMomentum ? Real(hU[c].x()) : Hc*Real(U[c].x());
        pb.hv[k] = hasMomentum ? Real(hU[c].y()) : Hc*Real(U[c].y());
    }
}


template<class Real>
sh::Problem<Real> avalancheCase::problem(sh::Halo<Real>* halo)
{
    if (sizeof(Real) < sizeof(double))
    {
        checkSinglePrecision();
    }
    // A decomposed run's part, with the whole grid's spacing and
    // origin (structuredMesh: reduced to the serial run's)
    sh::Problem<Real> pb = smesh.decomposed()
      ? sh::Problem<Real>
        (
            input.params<Real>(), smesh.subdomain(),
            smesh.xMin(), smesh.xMax(), smesh.yMin(), smesh.yMax()
        )
      : sh::Problem<Real>
        (
            input.params<Real>(),
            smesh.nx(), smesh.ny(),
            smesh.xMin(), smesh.xMax(), smesh.yMin(), smesh.yMax()
        );
    pb.bc = boundarySpec<Real>(sides);
    try
    {
        const caseInput& in = input;
        pb.setInclination
        (
            [&in](double x) { return degToRad(in.inclinationAt(x)); }
        );
    }
    catch (const sh::InputError& e)
    {
        input.fail(e);
    }
    pb.startTime = runTime.value();
    copyFields(pb);
    if (input.plan())
    {
        try
        {
            toPlanState(pb, halo);
        }
        catch (const sh::InputError& e)
        {
            input.fail(e);
        }
    }
    copyCover(pb);
    if (hasPressure)
    {
        reportPressureRestart(pb);
    }
    if (input.hasJet)
    {
        try
        {
            // On a part the circle may lie elsewhere: the parts
            // together must hold one of its cells
            const label cells = pb.setImpingingJet(input.jet);
            if (returnReduce(cells, sumOp<label>()) == 0)
            {
                throw sh::Problem<Real>::noJetCells(input.jet);
            }
        }
        catch (const sh::InputError& e)
        {
            input.fail(e);
        }
    }
    return pb;
}


template<class Real>
void avalancheCase::reportPressureRestart(const sh::Problem<Real>& pb) const
{
    label ignored = 0;
    const sh::PeakMaps<Real>& peaks = pb.peaks;
    for (std::size_t k = 0; k < peaks.speed.size(); ++k)
    {
        Real S = 0;
        ignored += !sh::squaredSpeedPeak
        (
            peaks.speed[k], peaks.pressure[k], pb.params.rho, true, S
        );
    }
    reduce(ignored, sumOp<label>());
    if (ignored)
    {
        WarningInFunction
            << "pMax of " << runTime.timeName() << " is not rho UMax^2"
            << " with rho = " << input.model.rho << " in " << ignored
            << " cells (rho changed, or another -precision): there pMax"
            << " continues from rho UMax^2" << nl << endl;
    }
}


template<class Real>
bool avalancheCase::goodState
(
    const std::vector<Real>& hs,
    const std::vector<Real>& hus,
    const std::vector<Real>& hvs
) const
{
    // Good on every processor, or on none: the fields' boundary
    // conditions exchange across processor patches
    const long n = long(hs.size());
    long bad = 0;
    #pragma omp parallel for reduction(+:bad) schedule(static)
    for (long k = 0; k < n; ++k)
    {
        bad +=
            !std::isfinite(double(hs[k])) || hs[k] < 0
         || !std::isfinite(double(hus[k]))
         || !std::isfinite(double(hvs[k]));
    }
    return !anyProcessor(bad != 0);
}


template<class Real>
void avalancheCase::fill
(
    const std::vector<Real>& hs,
    const std::vector<Real>& hus,
    const std::vector<Real>& hvs,
    const sh::PeakMaps<Real>& peaks
)
{
    const scalar hDry = input.model.hDry;
    const bool plan = input.plan();
    const label n = h.size();
    scalar* hp = h.primitiveFieldRef().data();
    vector* hUp = hU.primitiveFieldRef().data();
    vector* Up = U.primitiveFieldRef().data();
    scalar* regimep = regime.primitiveFieldRef().data();
    scalar* hMaxp = hMax.primitiveFieldRef().data();
    scalar* UMaxp = UMax.primitiveFieldRef().data();
    scalar* tArrivalp = tArrival.primitiveFieldRef().data();
    scalar* pMaxp = pMax.valid() ? pMax->primitiveFieldRef().data() : nullptr;
    scalar* Hp = plan ? H->primitiveFieldRef().data() : nullptr;
    const scalar* Jp = plan ? planJ.cdata() : nullptr;
    const scalar* Pp = plan ? planP.cdata() : nullptr;
    const scalar* Qp = plan ? planQ.cdata() : nullptr;
    #pragma omp parallel for schedule(static)
    for (label c = 0; c < n; ++c)
    {
        const label k = smesh.gridIndex(c);
        const scalar hc = hs[k];
        const vector m(hus[k], hvs[k], 0);
        hp[c] = hc;
        hUp[c] = m;
        Up[c] = hc > 0 ? m/hc : vector::zero;
        if (plan)
        {
            // hc is H: the normal thickness H/J, the velocity along the
            // bed with its vertical component
            Hp[c] = hc;
            hp[c] = hc/Jp[c];
            // (+ 0: a zero as +0, whatever the slopes' signs: OpenFOAM
            // writes a field of equal values as uniform, with the first
            // one's sign of zero for all)
            Up[c].z() = (Pp[c]*Up[c].x() + Qp[c]*Up[c].y()) + 0.0;
        }
        regimep[c] =
            hc <= hDry ? 0 : (m.x() != 0 || m.y() != 0 ? 2 : 1);
        hMaxp[c] = peaks.h[k];
        UMaxp[c] = peaks.speed[k];
        tArrivalp[c] = peaks.arrival[k];
        if (pMaxp)
        {
            pMaxp[c] = peaks.pressure[k];
        }
    }
    h.correctBoundaryConditions();
    U.correctBoundaryConditions();
    hU.correctBoundaryConditions();
    regime.correctBoundaryConditions();
    hMax.correctBoundaryConditions();
    UMax.correctBoundaryConditions();
    tArrival.correctBoundaryConditions();
    if (pMax.valid())
    {
        pMax->correctBoundaryConditions();
    }
    if (H.valid())
    {
        H->correctBoundaryConditions();
    }
}


template<class Real>
bool avalancheCase::store
(
    const std::vector<Real>& hs,
    const std::vector<Real>& hus,
    const std::vector<Real>& hvs,
    const sh::PeakMaps<Real>& peaks
)
{
    if (!goodState(hs, hus, hvs))
    {
        return false;
    }
    fill(hs, hus, hvs, peaks);
    return true;
}


void avalancheCase::selectWrites(const bool restart)
{
    const wordList& chosen = input.control.writeFields;
    const wordList& needed = controlSettings::restartFields();
    auto set = [&](regIOobject& f)
    {
        const bool written =
            chosen.empty() || chosen.found(f.name())
         || (restart && needed.found(f.name()));
        f.writeOpt() = written ? IOobject::AUTO_WRITE : IOobject::NO_WRITE;
    };
    set(h);
    set(U);
    set(zb);
    set(hU);
    set(regime);
    set(hMax);
    set(UMax);
    set(tArrival);
    if (pMax.valid())
    {
        set(pMax());
    }
    if (H.valid())
    {
        set(H());
    }
    if (hEntrainable.valid())
    {
        set(hEntrainable());
        set(erodedDepth());
    }
    if (HEntrainable.valid())
    {
        set(HEntrainable());
        set(HErodedDepth());
    }
    if (cResistance.valid())
    {
        set(cResistance());
    }
}


void avalancheCase::restoreStartTime()
{
    IOobject timeIO
    (
        "time", runTime.timeName(), "uniform", runTime,
        IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
    );
    if (timeIO.typeHeaderOk<IOdictionary>(true))
    {
        startTimeDict.reset(new IOdictionary(timeIO));
    }
}


scalar avalancheCase::writeOrigin(const scalar t0) const
{
    const scalar w = input.writeInterval;
    return mag(t0/w - std::round(t0/w)) < 1e-6 ? 0 : t0;
}


scalar avalancheCase::nextWriteTime
(
    const scalar t, const scalar anchor, const scalar endTime
) const
{
    return nextGridTime(t, anchor, input.writeInterval, endTime);
}


scalar avalancheCase::nextComTime
(
    const scalar t, const scalar anchor, const scalar endTime
) const
{
    return nextGridTime
    (
        t, anchor, input.writeInterval/comSamples(), endTime
    );
}


scalar avalancheCase::nextGridTime
(
    const scalar t, const scalar anchor, const scalar interval,
    const scalar endTime
)
{
    const scalar k = std::floor((t - anchor)/interval + 1e-6) + 1;
    char buf[32];
    snprintf(buf, sizeof(buf), "%.12g", anchor + k*interval);
    return min(scalar(std::strtod(buf, nullptr)), endTime);
}


autoPtr<avalancheCase> readCase(Time& runTime, const fvMesh& mesh)
{
    avalancheCase::checkStartFiles(runTime, mesh);
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
    ac->check();
    return ac;
}


// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * //

#define makeCaseMembers(Real)                                                 \
    template sh::Problem<Real> avalancheCase::problem<Real>                   \
    (                                                                         \
        sh::Halo<Real>*                                                       \
    );                                                                        \
    template void avalancheCase::toPlanState<Real>                            \
    (                                                                         \
        sh::Problem<Real>&, sh::Halo<Real>*                                   \
    );                                                                        \
    template void avalancheCase::copyCover<Real>                              \
    (                                                                         \
        sh::Problem<Real>&                                                    \
    );                                                                        \
    template void avalancheCase::fillCover<Real>                              \
    (                                                                         \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&                                              \
    );                                                                        \
    template void avalancheCase::reportPressureRestart<Real>                  \
    (                                                                         \
        const sh::Problem<Real>&                                              \
    ) const;                                                                  \
    template bool avalancheCase::goodState<Real>                              \
    (                                                                         \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&                                              \
    ) const;                                                                  \
    template void avalancheCase::fill<Real>                                   \
    (                                                                         \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&,                                             \
        const sh::PeakMaps<Real>&                                             \
    );                                                                        \
    template bool avalancheCase::store<Real>                                  \
    (                                                                         \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&,                                             \
        const std::vector<Real>&,                                             \
        const sh::PeakMaps<Real>&                                             \
    );

makeCaseMembers(float)
makeCaseMembers(double)

} // End namespace Foam

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "avalancheCase.H"

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
        .typeHeaderOk<volScalarField>(true), "tArrival"))
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
sh::Problem<Real> avalancheCase::problem() const
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
bool avalancheCase::store
(
    const std::vector<Real>& hs,
    const std::vector<Real>& hus,
    const std::vector<Real>& hvs,
    const sh::PeakMaps<Real>& peaks
)
{
    // Good on every processor, or stored on none: the fields'
    // boundary conditions exchange across processor patches
    bool good = true;
    forAll(hs, k)
    {
        if
        (
            !std::isfinite(double(hs[k])) || hs[k] < 0
         || !std::isfinite(double(hus[k]))
         || !std::isfinite(double(hvs[k]))
        )
        {
            good = false;
            break;
        }
    }
    if (anyProcessor(!good))
    {
        return false;
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
        hMax[c] = peaks.h[k];
        UMax[c] = peaks.speed[k];
        tArrival[c] = peaks.arrival[k];
        if (pMax.valid())
        {
            pMax()[c] = peaks.pressure[k];
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
    return true;
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
    const scalar w = input.writeInterval;
    const scalar k = std::floor((t - anchor)/w + 1e-6) + 1;
    char buf[32];
    snprintf(buf, sizeof(buf), "%.12g", anchor + k*w);
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
    template sh::Problem<Real> avalancheCase::problem<Real>() const;          \
    template void avalancheCase::reportPressureRestart<Real>                  \
    (                                                                         \
        const sh::Problem<Real>&                                              \
    ) const;                                                                  \
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

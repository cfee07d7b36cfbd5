/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The plausibility checks of a run's start (avalancheRun): the controls
    against the number of steps they would take, the initial state's
    fastest signal and time step, with the inputs that make them named.
\*---------------------------------------------------------------------------*/

#include "avalancheRun.H"
#include "OStringStream.H"

namespace Foam
{


// * * * * * * * * * * * * * * * * Stages  * * * * * * * * * * * * * * * * //

template<class Real>
std::string avalancheRun<Real>::stepsProblem
(
    const double t,
    const double endTime,
    const word& writeControl,
    const double w,
    const double firstWrite
) const
{
    const caseInput& in = ac_.input;
    const bool onGrid =
        writeControl == "adjustableRunTime" || writeControl == "runTime";
    const char* dtKey = in.adjustTimeStep ? "maxDeltaT" : "deltaT";
    const double dtMax = in.maxDeltaT;
    const double dt = onGrid ? min(dtMax, w) : dtMax;
    const double span = endTime - t;
    const double steps = span/dt;
    OStringStream os;
    os.precision(8);
    // A step below the resolution of the time in double: t + dt == t
    const bool stalls =
        !(steps > maxStepsToEnd()) && span > 0 && !(endTime - dt < endTime);
    if (steps > maxStepsToEnd() || stalls)
    {
        const bool byWrites = onGrid && w < dtMax;
        const double least =
            max(span/maxStepsToEnd(), stalls ? 1e-15*mag(endTime) : 0.0);
        os  << "endTime " << endTime << " lies " << steps << " steps of at"
            << " most " << dt << " s (" << (byWrites ? "writeInterval" : dtKey)
            << (byWrites ? ": the steps of " + writeControl + " writes land"
                " on every write time" : std::string()).c_str()
            << ") from t = " << t;
        if (stalls)
        {
            os  << ", a step below the resolution of endTime in double:"
                << " the time would not advance." << nl;
        }
        else
        {
            os  << ", more than 1e10: the run would never end (1e10 steps"
                << " take more than two days even on a 16 x 2 mesh; the"
                << " first write time may lie at most 1e8 steps away)." << nl;
        }
        os  << "Valid values: " << (byWrites ? "writeInterval" : dtKey)
            << " >= " << least;
        if (byWrites && dtMax < GREAT)
        {
            os  << " (and " << dtKey << " >= " << least << ")";
        }
        os  << ", or endTime <= " << t + maxStepsToEnd()*dt;
        return os.str();
    }
    const double first = min(firstWrite, endTime) - t;
    if (onGrid && first/dtMax > maxStepsToFirstWrite())
    {
        os  << "The first write time " << t + first << " lies "
            << first/dtMax << " steps of at most " << dtKey << " "
            << dtMax << " s from t = " << t << ", more than 1e8: the run"
            << " would seem to hang."
            << nl << "Valid values: " << dtKey << " >= "
            << first/maxStepsToFirstWrite() << ", or a writeInterval <= "
            << maxStepsToFirstWrite()*dtMax;
    }
    return os.str();
}


template<class Real>
void avalancheRun<Real>::checkFirstStep()
{
    const word& writeControl = ac_.input.writeControl;
    const bool onGrid =
        writeControl == "adjustableRunTime" || writeControl == "runTime";
    const double firstWrite =
        onGrid ? double(ac_.nextWriteTime(t0_, origin_, endTime_)) : endTime_;
    const std::string controls = stepsProblem
    (
        t0_, endTime_, writeControl, ac_.input.writeInterval, firstWrite
    );
    if (!controls.empty())
    {
        FatalIOErrorInFunction(runTime_.controlDict())
            << controls.c_str() << nl << exit(FatalIOError);
    }

    // The fastest signal of eq. (24), front speed |u| + 2c, and the
    // largest wave speed c, over the cells and the inflows
    signal fastest, widest;
    scanSignals(fastest, widest);
    if (widest.c > maxInputSpeed)
    {
        // U itself is bounded as it is read (avalancheCase)
        FatalErrorInFunction
            << "The wave speed c = sqrt(epsilon g cos(zeta) K h) of the"
            << " initial state exceeds the speed of light, "
            << label(maxInputSpeed) << " m/s: no granular flow comes near"
            << " it." << nl << "The largest, c = " << widest.c << " m/s, is ";
        describe(widest);
        FatalError
            << "Check these inputs." << nl << exit(FatalError);
    }

    const double dtCfl = double(solver_->stableDt());
    const double dt = min
    (
        min(dtCfl, double(ac_.input.maxDeltaT)),
        onGrid ? double(ac_.input.writeInterval) : GREAT
    );
    const double toFirst = (min(firstWrite, endTime_) - t0_)/dt;
    const double toEnd = (endTime_ - t0_)/dt;
    const bool hangs = onGrid && toFirst > maxStepsToFirstWrite();
    if (!hangs && !(toEnd > maxStepsToEnd()))
    {
        return;
    }

    // The controls passed: the state's CFL step is the bound
    FatalErrorInFunction
        << "The initial state allows time steps of only " << dt << " s: ";
    if (hangs)
    {
        FatalError
            << "the first write time " << min(firstWrite, endTime_)
            << " lies " << toFirst << " steps away (more than 1e8), and the"
            << " run would seem to hang." << nl;
    }
    else
    {
        FatalError
            << "endTime " << endTime_ << " lies " << toEnd << " steps away"
            << " (more than 1e10), and the run would never end." << nl;
    }
    FatalError << "The fastest signal, |U| + 2c = "
        << mag(vector(fastest.u, fastest.v, 0)) + 2*fastest.c << " m/s, is ";
    describe(fastest);
    FatalError
        << "Check these inputs; if they are meant, "
        << (hangs ? "write more often (writeInterval " : "end sooner (endTime ")
        << (hangs ? ac_.input.writeInterval : endTime_) << ")." << nl
        << exit(FatalError);
}


template<class Real>
void avalancheRun<Real>::scanSignals(signal& fastest, signal& widest) const
{
    const sh::Grid<Real>& g = pb_.grid;
    const sh::Params<Real>& p = pb_.params;
    const double K = max(double(p.K.kxMax), double(p.K.kyMax));
    const auto consider = [&]
    (
        double h, double hu, double hv, double zeta,
        label i, label j, label side
    )
    {
        if (!(h > 0))
        {
            return;
        }
        signal s;
        s.h = h;
        s.u = hu/h;
        s.v = hv/h;
        s.zeta = zeta;
        s.c = std::sqrt
        (
            double(p.epsilon)*double(p.g)*std::cos(zeta)*K*h
        );
        s.rate =
            (mag(s.u) + 2*s.c)/double(g.dx) + (mag(s.v) + 2*s.c)/double(g.dy);
        s.i = i;
        s.j = j;
        s.side = side;
        if (s.rate > fastest.rate)
        {
            fastest = s;
        }
        if (s.c > widest.c)
        {
            widest = s;
        }
    };
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            const int c = pb_.cell(i, j);
            consider
            (
                pb_.h[c], pb_.hu[c], pb_.hv[c], double(pb_.zeta[i]), i, j, -1
            );
        }
    }
    for (label side = 0; side < 4; ++side)
    {
        if (pb_.bc.type[side] == sh::BCType::inflow)
        {
            const sh::State<Real>& q = pb_.bc.inflow[side];
            const double z = double(pb_.zeta[side == 1 ? g.nx - 1 : 0]);
            consider(q.h, q.hu, q.hv, z, -1, -1, side);
        }
    }
}


template<class Real>
void avalancheRun<Real>::describe(const signal& s) const
{
    const sh::Grid<Real>& g = pb_.grid;
    const sh::Params<Real>& p = pb_.params;
    const double K = max(double(p.K.kxMax), double(p.K.kyMax));
    sh::State<Real> jq;
    if (s.side >= 0)
    {
        FatalError
            << "the inflow on side " << structuredMesh::sideNames[s.side]
            << " (patch " << ac_.sides[s.side].patch << ", boundaryField"
            << " of " << ac_.h.objectPath() << " and "
            << ac_.U.objectPath() << ")";
    }
    else if
    (
        ac_.input.hasJet && sh::jetState(p.jet, g, int(s.i), int(s.j), jq)
    )
    {
        FatalError
            << "in cell (" << s.i + g.i0 << ", " << s.j + g.j0 << "), where the"
            << " impinging jet of fvOptions imposes its state (R "
            << ac_.input.jet.R << ", R_imp " << ac_.input.jet.rImp
            << ", u_jet " << ac_.input.jet.uJet << ")";
    }
    else
    {
        FatalError
            << "in cell (" << s.i + g.i0 << ", " << s.j + g.j0 << ") at ("
            << g.xc(int(s.i)) << " " << g.yc(int(s.j)) << "), fields "
            << ac_.h.objectPath() << " and " << ac_.U.objectPath();
    }
    FatalError
        << ":" << nl << "    h = " << s.h << " m, U = (" << s.u << " "
        << s.v << ") m/s, c = sqrt(epsilon g cos(zeta) K h) = " << s.c
        << " m/s with epsilon = " << p.epsilon << ", g = " << p.g
        << " (transportProperties), zeta = " << radToDeg(s.zeta)
        << " deg, K = " << K << nl
        << "mostly through "
        << (mag(s.u) + mag(s.v) > 4*s.c ? "the speed |U|" : "the wave speed c")
        << "; cell size " << g.dx << " x " << g.dy << " m, maxCo "
        << p.cfl << nl;
}

// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * //

template std::string avalancheRun<float>::stepsProblem
(
    double, double, const word&, double, double
) const;
template void avalancheRun<float>::checkFirstStep();
template void avalancheRun<float>::scanSignals
(
    avalancheRun<float>::signal&, avalancheRun<float>::signal&
) const;
template void avalancheRun<float>::describe
(
    const avalancheRun<float>::signal&
) const;
template std::string avalancheRun<double>::stepsProblem
(
    double, double, const word&, double, double
) const;
template void avalancheRun<double>::checkFirstStep();
template void avalancheRun<double>::scanSignals
(
    avalancheRun<double>::signal&, avalancheRun<double>::signal&
) const;
template void avalancheRun<double>::describe
(
    const avalancheRun<double>::signal&
) const;

} // End namespace Foam

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The checks of an ensemble run (ensembleRun): its options against what an
    ensemble does, and a restart's member against the ensemble's case.
\*---------------------------------------------------------------------------*/

#include "ensembleRun.H"

namespace Foam
{

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

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



// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * * //

template class ensembleRun<float>;
template class ensembleRun<double>;

} // End namespace Foam

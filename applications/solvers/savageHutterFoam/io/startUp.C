/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "startUp.H"
#include "anyProcessor.H"
#include "runSignals.H"
#include "timeDirectories.H"
#include "host/modelInput.H"

namespace Foam
{

void runOptions::declare()
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
    argList::addBoolOption
    (
        "ensemble",
        "run the members of system/ensembleDict together (ensemble/)"
    );
    argList::addBoolOption
    (
        "listFrictionLaws",
        "list the friction laws, their coefficients and rules, and exit"
    );
    argList::addBoolOption
    (
        "listEntrainmentModels",
        "list the entrainment models, their coefficients and rules, and exit"
    );
}


runOptions runOptions::read(const argList& args)
{
    runOptions o;
    o.backend = args.getOrDefault<word>("backend", "auto");
    o.precision = args.getOrDefault<word>("precision", "double");
    o.logInterval = args.getOrDefault<scalar>("logInterval", 5);
    o.ensemble = args.found("ensemble");
    if (!wordList({"auto", "cpu", "cuda"}).found(o.backend))
    {
        FatalErrorInFunction
            << "Unknown -backend " << o.backend << nl
            << "Valid choices: (auto cpu cuda)" << nl << exit(FatalError);
    }
    if (!wordList({"double", "single"}).found(o.precision))
    {
        FatalErrorInFunction
            << "Unknown -precision " << o.precision << nl
            << "Valid choices: (double single)" << nl << exit(FatalError);
    }
    return o;
}


bool listFrictionLaws(const argList& args)
{
    if (!args.found("listFrictionLaws"))
    {
        return false;
    }
    Info<< sh::describeFrictionLaws().c_str() << nl << "End" << nl << endl;
    return true;
}


bool listEntrainmentModels(const argList& args)
{
    if (!args.found("listEntrainmentModels"))
    {
        return false;
    }
    Info<< sh::describeEntrainmentModels().c_str() << nl << "End" << nl
        << endl;
    return true;
}


controlSettings prepareStart(const argList& args)
{
    #ifndef SH_HAVE_MPI
    if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "This savageHutterFoam was built without MPI: no decomposed"
            << " runs (install libopenmpi-dev, bin/installDependencies, and"
            << " build again)" << nl << exit(FatalError);
    }
    #endif
    const controlSettings control =
        controlSettings::readFile(args.globalPath()/"system"/"controlDict");
    restoreReplaced(args.path());
    if (control.startFrom == "latestTime")
    {
        removeUnsharedTimes(args.path());
    }
    return control;
}


void capLogPrecision()
{
    if (Sout.precision() > logPrecision())
    {
        Sout.precision(logPrecision());
    }
}


void checkEndTime(const Time& runTime, const controlSettings& control)
{
    capLogPrecision();
    if (control.endTime < runTime.value())
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "endTime " << control.endTime << " lies before the start time "
            << runTime.timeName() << " (startFrom " << control.startFrom
            << ")." << nl << "Valid values: endTime >= "
            << runTime.timeName() << nl << exit(FatalIOError);
    }
}


void setWritePrecision(const Time& runTime)
{
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
}


void endIfSignalled(const char* stage)
{
    if (anyProcessor(runSignals::stop))
    {
        Info<< nl << runSignals::name(runSignals::last)
            << " during start-up (" << stage << "): the run ends before"
            << " its first step; nothing written" << nl << endl
            << "End" << nl << endl;
        UPstream::exit(0);
    }
}

} // End namespace Foam

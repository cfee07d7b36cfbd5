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
    1 at rest, 2 moving), and the hazard maps hMax and UMax, the largest
    thickness and speed of each cell since the start of the run, pMax
    (with rho in transportProperties), the largest rho |u|^2 [Pa], and
    tArrival, the first time h exceeded arrivalThreshold (-1 where never):
    updated every step, read back on restart, so that they cover the whole
    simulation.

    Every controlDict entry the run depends on is checked before Time reads
    it (controlSettings); time directories appear complete or not at all
    (timeDirectories); SIGTERM/SIGINT write the state and end the run,
    SIGUSR1 writes it (runSignals); with runTimeModifiable yes, changes to
    endTime, writeControl, writeInterval and stopAt act during the run.

Usage
    savageHutterFoam [-backend auto|cpu|cuda] [-precision double|single]
                     [-logInterval seconds] [-parallel] [-ensemble]

    -ensemble: the members of system/ensembleDict (design.md section 6)
    run together, each written under ensemble/member<k>/, the statistics
    across members under ensemble/statistics/ (ensembleRun.H).

    Decomposed (decomposePar with method simple, hierarchical or manual
    into rectangles of the block): mpirun -np N savageHutterFoam -parallel,
    one GPU per processor with -backend cuda; results bit for bit the
    serial run's.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "avalancheCase.H"
#include "avalancheRun.H"
#include "ensembleRun.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

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
    argList::addBoolOption
    (
        "ensemble",
        "run the members of system/ensembleDict together (ensemble/)"
    );

    #include "setRootCase.H"

    #ifndef SH_HAVE_MPI
    if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "This savageHutterFoam was built without MPI: no decomposed"
            << " runs (install libopenmpi-dev, bin/installDependencies, and"
            << " build again)" << nl << exit(FatalError);
    }
    #endif

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
        controlSettings::readFile(args.globalPath()/"system"/"controlDict");

    // A time directory a killed run was replacing, back before Time looks
    // for the latest time
    restoreReplaced(args.path());

    if (control.startFrom == "latestTime")
    {
        removeUnsharedTimes(args.path());
    }

    #include "createTime.H"

    if (control.endTime < runTime.value())
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "endTime " << control.endTime << " lies before the start time "
            << runTime.timeName() << " (startFrom " << control.startFrom
            << ")." << nl << "Valid values: endTime >= "
            << runTime.timeName() << nl << exit(FatalIOError);
    }

    // The block of blockMeshDict, before the mesh is read (a scale beyond
    // 1e30 writes points the mesh reader refuses without naming it)
    structuredMesh::readBlockCounts(runTime);

    #include "createMesh.H"

    autoPtr<avalancheCase> acPtr = readCase(runTime, mesh);
    avalancheCase& ac = acPtr();
    removeIncompleteWrites(runTime);
    checkWritable(runTime);
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

    if (args.found("ensemble"))
    {
        if (precision == "double")
        {
            ensembleRun<double>(ac, backend, logInterval).run();
        }
        else
        {
            ensembleRun<float>(ac, backend, logInterval).run();
        }
    }
    else if (precision == "double")
    {
        avalancheRun<double>(ac, backend, logInterval).run();
    }
    else
    {
        avalancheRun<float>(ac, backend, logInterval).run();
    }

    Info<< "End\n" << endl;
    return 0;
}


// ************************************************************************* //

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

    The case is read here (mesh, fields h, U and optional zb, hEntrainable,
    cResistance, transportProperties, fvSolution::savageHutter,
    controlDict); the run
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
    simulation.  With the bed's cover (docs/design.md section 7:
    entrainmentModel in transportProperties, 0/hEntrainable, 0/cResistance)
    also hEntrainable (the erodible layer left), erodedDepth (the depth
    taken up so far) and cResistance, and in plan coordinates HEntrainable
    and HErodedDepth (per plan area, for exact restarts).

    Every controlDict entry the run depends on is checked before Time reads
    it (controlSettings); time directories appear complete or not at all
    (timeDirectories); SIGTERM/SIGINT write the state and end the run,
    SIGUSR1 writes it (runSignals); with runTimeModifiable yes, changes to
    endTime, writeControl, writeInterval and stopAt act during the run.

Usage
    savageHutterFoam [-backend auto|cpu|cuda] [-precision double|single]
                     [-logInterval seconds] [-parallel] [-ensemble]
    savageHutterFoam -listFrictionLaws
    savageHutterFoam -listEntrainmentModels

    -listFrictionLaws, -listEntrainmentModels: the friction laws and the
    entrainment models of this build with their coefficients, defaults and
    rules (no case needed).

    -ensemble: the members of system/ensembleDict (docs/design.md section 6)
    run together, each written under ensemble/member<k>/, the statistics
    across members under ensemble/statistics/ (run/ensembleRun.H).

    Decomposed (decomposePar with method simple, hierarchical or manual
    into rectangles of the block): mpirun -np N savageHutterFoam -parallel,
    one GPU per processor with -backend cuda; results bit for bit the
    serial run's.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "startUp.H"
#include "runSignals.H"
#include "timeDirectories.H"
#include "avalancheCase.H"
#include "avalancheRun.H"
#include "ensembleRun.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- The run, single or ensemble, in precision Real
template<class Real>
void run(Foam::avalancheCase& ac, const Foam::runOptions& options)
{
    if (options.ensemble)
    {
        Foam::ensembleRun<Real>(ac, options.backend, options.logInterval).run();
    }
    else
    {
        Foam::avalancheRun<Real>(ac, options.backend, options.logInterval).run();
    }
}


int main(int argc, char *argv[])
{
    // First thing: a signal during start-up ends the run cleanly
    runSignals::install();
    runOptions::declare();
    #include "setRootCase.H"
    runSignals::install();   // again: argList sets OpenFOAM's own
    if (listFrictionLaws(args) || listEntrainmentModels(args))
    {
        return 0;
    }
    const runOptions options = runOptions::read(args);
    const controlSettings control = prepareStart(args);
    endIfSignalled("checking the case's time directories");

    #include "createTime.H"
    runSignals::install();   // and after Time, whatever it set
    checkEndTime(runTime, control);
    // The block of blockMeshDict, before the mesh is read (a scale beyond
    // 1e30 writes points the mesh reader refuses without naming it)
    structuredMesh::readBlockCounts(runTime);
    endIfSignalled("reading the controls");

    #include "createMesh.H"
    endIfSignalled("reading the mesh");

    autoPtr<avalancheCase> ac = readCase(runTime, mesh);
    removeIncompleteWrites(runTime);
    checkWritable(runTime);
    setWritePrecision(runTime);
    endIfSignalled("reading the fields");

    if (options.precision == "double")
    {
        run<double>(ac(), options);
    }
    else
    {
        run<float>(ac(), options);
    }

    Info<< "End\n" << endl;
    return 0;
}


// ************************************************************************* //

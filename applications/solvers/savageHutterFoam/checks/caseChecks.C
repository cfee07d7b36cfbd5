/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The checks of a case against the contract (avalancheCase): the files of
    the start time directory, the fields' dimensions and values, the
    restart's momentum, hazard maps and uniform/time, the ranges a float
    holds in single precision.  Errors name the file, the keyword and the
    valid values.
\*---------------------------------------------------------------------------*/

#include "avalancheCase.H"

namespace Foam
{

template<class FieldType>
void avalancheCase::checkFile
(
    const Time& t,
    const fvMesh& m,
    const word& name,
    const bool required
)
{
    IOobject fio(io(t, m, name, IOobject::MUST_READ));
    const fileName path = fio.objectPath();
    if (!isFile(path))
    {
        if (required)
        {
            reportUnreadableFile(t, path, "is missing (no such file)");
        }
        return;
    }
    if (!fio.typeHeaderOk<FieldType>(false))
    {
        reportUnreadableFile
        (
            t, path, "cannot be read: no FoamFile header (empty, cut"
            " short or not an OpenFOAM file)"
        );
    }
    if (fio.headerClassName() != FieldType::typeName)
    {
        reportUnreadableFile
        (
            t, path, "is of class " + fio.headerClassName()
          + ", not " + FieldType::typeName
        );
    }
}


void avalancheCase::checkStartFiles(const Time& t, const fvMesh& m)
{
    if (!isDir(t.timePath()))
    {
        // No such directory: caseInput names startTime
        return;
    }
    // A write time of writeFields without the restart fields: name the
    // latest time that has them
    const fileName hPath = io(t, m, "h", IOobject::MUST_READ).objectPath();
    if (!isFile(hPath))
    {
        word latest;
        for (const instant& i : t.times())
        {
            if (i.value() < t.value() && isFile(t.path()/i.name()/"h"))
            {
                latest = i.name();
            }
        }
        if (!latest.empty())
        {
            reportUnreadableFile
            (
                t, hPath, "is missing: time " + t.timeName() + " holds the"
                " fields of writeFields (system/controlDict) only, not the"
                " restart fields. The latest time with them is " + latest
              + ": restart from it with 'startFrom startTime; startTime "
              + latest + ";' in system/controlDict"
            );
        }
    }
    checkFile<volScalarField>(t, m, "h", true);
    checkFile<volVectorField>(t, m, "U", true);
    checkFile<volScalarField>(t, m, "zb", false);
    checkFile<volVectorField>(t, m, "hU", false);
    checkFile<volScalarField>(t, m, "H", false);
    checkFile<volScalarField>(t, m, "hMax", false);
    checkFile<volScalarField>(t, m, "UMax", false);
    checkFile<volScalarField>(t, m, "pMax", false);
    checkFile<volScalarField>(t, m, "tArrival", false);
    checkFile<volScalarField>(t, m, "hEntrainable", false);
    checkFile<volScalarField>(t, m, "erodedDepth", false);
    checkFile<volScalarField>(t, m, "cResistance", false);
    checkFile<volScalarField>(t, m, "HEntrainable", false);
    checkFile<volScalarField>(t, m, "HErodedDepth", false);
    for (const word name : {"time", "writeGrid"})
    {
        IOobject uio
        (
            name, t.timeName(), "uniform", t,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        );
        if
        (
            isFile(uio.objectPath())
         && !uio.typeHeaderOk<IOdictionary>(false)
        )
        {
            reportUnreadableFile
            (
                t, uio.objectPath(), "cannot be read: no FoamFile header"
                " (empty, cut short or not an OpenFOAM file)"
            );
        }
    }
}


void avalancheCase::check()
{
    sides = readBoundaryConditions(smesh, h, U);
    Info<< "Mesh: " << smesh.nxWhole() << " x " << smesh.nyWhole()
        << " cells of " << smesh.dx() << " x " << smesh.dy()
        << " m on [" << smesh.xMin() << ", " << smesh.xMax() << "] x ["
        << smesh.yMin() << ", " << smesh.yMax() << "]" << nl;
    if (Pstream::parRun())
    {
        Info<< "Decomposed into " << Pstream::nProcs() << " rectangles;"
            << " processor 0: " << smesh.nx() << " x " << smesh.ny()
            << " cells from (" << smesh.i0() << ", " << smesh.j0()
            << "), its sides:" << nl;
    }
    for (label s = 0; s < 4; ++s)
    {
        const char* names[4] =
            {"transmissive", "wall", "inflow", "the neighbour's cells"};
        Info<< "    " << structuredMesh::sideNames[s] << ": patch "
            << sides[s].patch << ", " << names[int(sides[s].type)];
        if (sides[s].type == sh::BCType::inflow)
        {
            Info<< " h " << sides[s].h << " U " << sides[s].U;
        }
        Info<< nl;
    }
    if (!isFile(zb.objectPath()))
    {
        Info<< "No field zb: flat bed on the reference surface" << nl;
    }
    if
    (
        !hasPeaks
     && (isFile(hMax.objectPath()) || isFile(UMax.objectPath()))
    )
    {
        WarningInFunction
            << "Only one of hMax and UMax in " << runTime.timeName()
            << ": the peak maps start again from the start time's state"
            << nl << endl;
    }
    // The start time to full precision first: a restart's tArrival is
    // checked against it, not against its directory's rounded name
    checkStartTime();
    checkInitialFields();
    checkCover();
    checkMomentum();
    checkHazardMaps();
    Info<< endl;
}


void avalancheCase::checkHazardMaps() const
{
    const word now = runTime.timeName();
    if (hasPressure)
    {
        checkDimensions(pMax(), pMax().dimensions(), dimPressure, "Pa");
    }
    if (hasArrival)
    {
        checkDimensions(tArrival, tArrival.dimensions(), dimTime, "s");
    }
    if (!hasPeaks)
    {
        return;
    }
    if (pMax.valid() && !hasPressure)
    {
        Info<< "No pMax in " << now << ": pMax continues from rho UMax^2"
            << nl;
    }
    if (!pMax.valid() && isFile(runTime.timePath()/"pMax"))
    {
        Info<< "pMax in " << now << " is not continued: no rho in"
            << " transportProperties" << nl;
    }
    const scalar threshold = input.model.arrivalThreshold;
    label above = 0, disagree = 0;
    forAll(hMax, c)
    {
        const bool reached = hMax[c] > threshold;
        above += reached;
        disagree += hasArrival && reached != (tArrival[c] >= 0);
    }
    if (disagree)
    {
        FatalIOErrorInFunction(tArrival.objectPath())
            << "tArrival disagrees with hMax (" << hMax.objectPath()
            << ") in " << disagree << " cells:"
            << " it is set where hMax exceeds arrivalThreshold "
            << threshold << " m (transportProperties), and only there;"
            << " it was written with another arrivalThreshold, or one of"
            << " the two files was changed." << nl
            << "Set arrivalThreshold back, or remove tArrival (the cells"
            << " whose hMax exceeds the threshold then take the start"
            << " time as arrival time):" << nl
            << "    rm " << tArrival.objectPath() << nl
            << exit(FatalIOError);
    }
    if (!hasArrival && above)
    {
        WarningInFunction
            << "No tArrival in " << now << ": the " << above << " cells"
            << " whose hMax exceeds arrivalThreshold " << threshold
            << " m take the start time " << now << " as arrival time"
            << " (an upper bound)" << nl << endl;
    }
}


void avalancheCase::checkMomentum()
{
    // Plan coordinates: hU is H U, compared where H is known
    // (toPlanState)
    if (!hasMomentum || input.plan())
    {
        return;
    }
    label disagree = 0;
    forAll(h, c)
    {
        const vector hu = h[c]*U[c];
        if
        (
            h[c] > input.model.hDry
         && mag(hU[c] - hu) > 1e-9*(mag(hU[c]) + mag(hu)) + VSMALL
        )
        {
            ++disagree;
        }
    }
    if (disagree)
    {
        WarningInFunction
            << "hU disagrees with h U in " << disagree << " cells (h or U"
            << " edited after the write?): using h U" << nl << endl;
        hasMomentum = false;
    }
    else
    {
        Info<< "Reading field hU: the momentum, exact for the restart"
            << nl;
    }
}


void avalancheCase::checkDimensions
(
    const regIOobject& f,
    const dimensionSet& dims,
    const dimensionSet& expected,
    const char* unit
)
{
    if (dims != expected)
    {
        FatalIOErrorInFunction(f.objectPath())
            << "dimensions " << dims << " of " << f.name() << ": must be "
            << expected << " (" << unit << ")" << nl
            << exit(FatalIOError);
    }
}


void avalancheCase::checkCell(const label c) const
{
    // Magnitudes beyond 1e30 overflow in the scheme's squares; speeds
    // are bounded by maxInputSpeed (boundaryConditions.H)
    const scalar big = 1e30;
    if (!(h[c] >= 0 && h[c] <= big))
    {
        FatalIOErrorInFunction(h.objectPath())
            << "h = " << h[c] << " in cell " << c << " at "
            << mesh.C()[c] << ": the thickness must be finite,"
            << " >= 0 and at most 1e30" << nl << exit(FatalIOError);
    }
    if (hasVolume && !(H()[c] >= 0 && H()[c] <= big))
    {
        FatalIOErrorInFunction(H().objectPath())
            << "H = " << H()[c] << " in cell " << c << " at "
            << mesh.C()[c] << ": the volume per plan area must be finite,"
            << " >= 0 and at most 1e30" << nl << exit(FatalIOError);
    }
    if
    (
        !(
            mag(U[c].x()) <= big && mag(U[c].y()) <= big
         && mag(U[c].z()) <= big
         )
     || !(mag(U[c]) <= maxInputSpeed)
    )
    {
        FatalIOErrorInFunction(U.objectPath())
            << "U = " << U[c] << " in cell " << c << " at "
            << mesh.C()[c] << ": must be finite, of magnitude at"
            << " most " << label(maxInputSpeed)
            << " m/s (the speed of light)" << nl
            << exit(FatalIOError);
    }
    if (hasMomentum)
    {
        // The speed |hU|/h of a cell with h > 0 (a cell with h = 0
        // has no velocity, physics/reconstruction.H)
        const vector& m = hU[c];
        if
        (
            !(
                mag(m.x()) <= big && mag(m.y()) <= big
             && mag(m.z()) <= big
             )
         || !(mag(m) <= maxInputSpeed*h[c] || h[c] == 0)
        )
        {
            FatalIOErrorInFunction(hU.objectPath())
                << "hU = " << m << " in cell " << c << " with h = "
                << h[c] << ": must be finite, the speed |hU|/h at"
                << " most " << label(maxInputSpeed)
                << " m/s (the speed of light)" << nl
                << exit(FatalIOError);
        }
    }
    if (!(mag(zb[c]) <= big))
    {
        FatalIOErrorInFunction(zb.objectPath())
            << "zb = " << zb[c] << " in cell " << c
            << ": must be finite, of magnitude at most 1e30" << nl
            << exit(FatalIOError);
    }
}


void avalancheCase::checkInitialFields() const
{
    checkDimensions(h, h.dimensions(), dimLength, "m");
    checkDimensions(U, U.dimensions(), dimVelocity, "m/s");
    checkDimensions(zb, zb.dimensions(), dimLength, "m");
    if (isFile(hU.objectPath()))
    {
        checkDimensions
        (
            hU, hU.dimensions(), dimLength*dimVelocity, "m^2/s"
        );
    }
    if (hasVolume)
    {
        checkDimensions(H(), H().dimensions(), dimLength, "m");
    }
    if (isFile(hMax.objectPath()))
    {
        checkDimensions(hMax, hMax.dimensions(), dimLength, "m");
    }
    if (isFile(UMax.objectPath()))
    {
        checkDimensions(UMax, UMax.dimensions(), dimVelocity, "m/s");
    }
    // Cell by cell, each cell's h, U, hU and zb
    forAll(h, c)
    {
        checkCell(c);
    }
    if (hasPeaks)
    {
        checkPeaks(hMax, "the largest thickness");
        checkPeaks(UMax, "the largest speed");
    }
    if (hasPressure)
    {
        checkPeaks(pMax(), "the largest pressure");
    }
    if (hasArrival)
    {
        checkArrival();
    }
}


void avalancheCase::checkCover() const
{
    const word now = runTime.timeName();
    const dictionary& tp = input.transportProperties();
    if (input.entraining() && !hEntrainable.valid())
    {
        // A model with nothing to take up is a field forgotten (or
        // misnamed): refused rather than run as if without the model
        const entry* e = tp.findEntry("entrainmentModel", keyType::LITERAL);
        FatalIOErrorInFunction(tp)
            << "entrainmentModel "
            << sh::toString(input.model.entrainmentModel).c_str();
        if (e)
        {
            FatalIOError << " at line " << e->startLineNumber();
        }
        FatalIOError
            << " needs the erodible layer, the field hEntrainable [m], in"
            << " the start time " << now << ": there is no "
            << (runTime.timePath()/"hEntrainable") << nl
            << "Write it with setAvalancheFields (hEntrainable in"
            << " system/setAvalancheFieldsDict) or terrainToCase (an"
            << " entrainment entry in system/terrainDict), or set"
            << " entrainmentModel none";
        if (runTime.value() > 0)
        {
            // A later time: written without the layer (by a run without
            // it, or with writeFields between restart times)
            FatalIOError
                << "; or restart from a time that holds hEntrainable";
        }
        FatalIOError << nl << exit(FatalIOError);
    }
    if (!hEntrainable.valid() && isFile(runTime.timePath()/"erodedDepth"))
    {
        Info<< "erodedDepth in " << now << " is not used: no hEntrainable"
            << " there" << nl;
    }

    // Every cell finite, >= 0 and at most 1e30
    const auto nonNegative = [this]
    (
        const volScalarField& f,
        const dimensionSet& dims,
        const char* unit,
        const char* meaning
    )
    {
        checkDimensions(f, f.dimensions(), dims, unit);
        forAll(f, c)
        {
            if (!(f[c] >= 0 && f[c] <= 1e30))
            {
                FatalIOErrorInFunction(f.objectPath())
                    << f.name() << " = " << f[c] << " in cell " << c
                    << " at " << mesh.C()[c] << ": " << meaning << nl
                    << "Valid range: [0, 1e30] " << unit << nl
                    << exit(FatalIOError);
            }
        }
    };
    if (hEntrainable.valid())
    {
        nonNegative
        (
            hEntrainable(), dimLength, "m",
            "the erodible thickness left (normal to the bed) must be finite"
            " and not negative"
        );
        if (hasEroded)
        {
            nonNegative
            (
                erodedDepth(), dimLength, "m",
                "the thickness taken up so far must be finite and not"
                " negative"
            );
        }
        if (hasPlanCover)
        {
            nonNegative
            (
                HEntrainable(), dimLength, "m",
                "the erodible layer left per plan area must be finite and"
                " not negative"
            );
            nonNegative
            (
                HErodedDepth(), dimLength, "m",
                "the eroded depth per plan area must be finite and not"
                " negative"
            );
        }
        if (!hasEroded && input.entraining() && runTime.value() > 0)
        {
            // Not the continuation of the run that wrote this time: its
            // maps and report count erosion from here, and a model whose
            // depth depends on what was taken up (frontal) erodes again
            WarningInFunction
                << "No erodedDepth in " << now << ": the eroded depth is"
                << " counted from " << now << ", so this is not an exact"
                << " restart (entrainmentModel "
                << sh::toString(input.model.entrainmentModel).c_str()
                << (
                       input.model.entrainmentModel
                    == sh::EntrainmentModel::FrontalEntrainment
                     ? " erodes again down to the depth of the flow's load,"
                       " whatever was taken up before"
                     : ""
                   )
                << "); restart from a time that holds erodedDepth for one"
                << nl;
        }
        // Plan coordinates: the layer per plan area as the run held it is
        // HEntrainable, HErodedDepth; without them the restart starts from
        // J hEntrainable, which the written digits need not give back
        if
        (
            input.plan() && input.entraining() && runTime.value() > 0
         && !hasPlanCover
         && (
                !isFile(runTime.timePath()/"HEntrainable")
             || !isFile(runTime.timePath()/"HErodedDepth")
            )
        )
        {
            WarningInFunction
                << "No HEntrainable or HErodedDepth in " << now << ": the"
                << " layer and eroded depth per plan area start from J"
                << " hEntrainable and J erodedDepth, so this is not an exact"
                << " restart; restart from a time that holds them for one"
                << nl;
        }
        const scalar layer =
            returnReduce(max(hEntrainable().primitiveField()), maxOp<scalar>());
        Info<< "Erodible layer hEntrainable: largest " << layer << " m"
            << (
                   input.entraining()
                 ? string(", taken up by entrainmentModel ")
                 + sh::toString(input.model.entrainmentModel)
                 : string(", not taken up (entrainmentModel none)")
               ).c_str() << nl;
    }
    if
    (
        !cResistance.valid() && runTime.value() > 0
     && isFile(runTime.path()/"0"/"cResistance")
    )
    {
        // The fields are read from the start time: one written without
        // the resistance (its file removed, or a run that had none) runs
        // without it, which 0/ would not
        WarningInFunction
            << "No cResistance in " << now << " but one in "
            << (runTime.path()/"0") << ": this run has no resistance; copy"
            << " it to " << now << " to keep it" << nl;
    }
    if (cResistance.valid())
    {
        nonNegative
        (
            cResistance(), dimless/dimLength, "1/m",
            "the resistance coefficient must be finite and not negative"
        );
        Info<< "Resistance cResistance: largest "
            << returnReduce(max(cResistance().primitiveField()), maxOp<scalar>())
            << " 1/m (an extra drag c_res |u|^2)" << nl;
    }
}


void avalancheCase::checkArrival() const
{
    const scalar now = runTime.value();
    const scalar latest = now + 1e-6*mag(now);
    forAll(tArrival, c)
    {
        const scalar t = tArrival[c];
        if (!(t == -1 || (t >= 0 && t <= latest)))
        {
            FatalIOErrorInFunction(tArrival.objectPath())
                << "tArrival = " << t << " in cell " << c << ": must be"
                << " -1 (not reached) or an arrival time from 0 to the"
                << " start time " << runTime.timeName() << nl
                << exit(FatalIOError);
        }
    }
}


void avalancheCase::checkSinglePrecision() const
{
    const scalar big = 1e9;
    const auto bounded = [big]
    (
        const volScalarField& f, const char* what
    )
    {
        forAll(f, c)
        {
            if (!(mag(f[c]) <= big))
            {
                FatalIOErrorInFunction(f.objectPath())
                    << f.name() << " = " << f[c] << " in cell " << c
                    << ": " << what << " must be of magnitude at most"
                    << " 1e9 with -precision single (a float's squares"
                    << " overflow beyond); -precision double takes up"
                    << " to 1e30" << nl << exit(FatalIOError);
            }
        }
    };
    bounded(h, "the thickness");
    bounded(zb, "the bed");
    if (hEntrainable.valid())
    {
        bounded(hEntrainable(), "the erodible thickness");
        bounded(erodedDepth(), "the eroded depth");
    }
    if (cResistance.valid())
    {
        bounded(cResistance(), "the resistance coefficient");
    }
    forAll(sides, s)
    {
        if (!(sides[s].h <= big))
        {
            FatalIOErrorInFunction(h.objectPath())
                << "Patch " << sides[s].patch << ": inflow thickness h = "
                << sides[s].h << " must be at most 1e9 with -precision"
                << " single (a float's squares overflow beyond);"
                << " -precision double takes up to 1e30" << nl
                << exit(FatalIOError);
        }
    }
}


void avalancheCase::checkPeaks(const volScalarField& f, const char* meaning)
{
    forAll(f, c)
    {
        if (!(f[c] >= 0 && f[c] <= 1e30))
        {
            FatalIOErrorInFunction(f.objectPath())
                << f.name() << " = " << f[c] << " in cell " << c << ": "
                << meaning << " of the cell so far must be finite, >= 0"
                << " and at most 1e30" << nl << exit(FatalIOError);
        }
    }
}


void avalancheCase::checkStartTime()
{
    if (!startTimeDict.valid())
    {
        return;
    }
    const IOdictionary& d = startTimeDict();
    const wordList valid({"value", "name", "index", "deltaT", "deltaT0"});
    for (const word& key : d.toc())
    {
        if (!valid.found(key))
        {
            FatalIOErrorInFunction(d)
                << "Unknown keyword '" << key << "'." << nl
                << "Valid keywords: " << flatOutput(valid)
                << " (as OpenFOAM's Time writes them)" << nl
                << exit(FatalIOError);
        }
    }
    label index = 0;
    if (d.readIfPresent("index", index) && index < 0)
    {
        FatalIOErrorInFunction(d)
            << "Invalid index " << index << ": the number of time steps"
            << " of the run that wrote it." << nl
            << "Valid values: an integer >= 0" << nl
            << exit(FatalIOError);
    }
    for (const word key : {"deltaT", "deltaT0"})
    {
        scalar dt = 0;
        if (d.readIfPresent(key, dt) && !(dt > 0 && dt <= 1e30))
        {
            FatalIOErrorInFunction(d)
                << "Invalid " << key << " " << dt << ": a time step of"
                << " the run that wrote it." << nl
                << "Valid values: a number in (0, 1e30]" << nl
                << exit(FatalIOError);
        }
    }
    scalar value = 0;
    if (d.readIfPresent("value", value))
    {
        // Time's own test of the value against the directory's name
        if (Time::timeName(value) != runTime.timeName())
        {
            FatalIOErrorInFunction(d)
                << "Invalid value " << value << ": a time named "
                << Time::timeName(value) << ", not "
                << runTime.timeName() << " as its directory." << nl
                << "Valid values: a time whose name is "
                << runTime.timeName() << "; or remove "
                << d.objectPath() << " (the start time is then "
                << runTime.timeName() << " as named)" << nl
                << exit(FatalIOError);
        }
        runTime.setTime(value, runTime.timeIndex());
    }
}

} // End namespace Foam

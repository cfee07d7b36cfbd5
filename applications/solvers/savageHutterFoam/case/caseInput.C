/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "caseInput.H"
#include "boundaryConditions.H"
#include "Switch.H"
#include "IStringStream.H"
#include "unitConversion.H"

#include <cstdlib>

namespace Foam
{

namespace
{

//- A name from a fixed set; missing or unknown: error listing the choices
word readChoice
(
    const dictionary& dict,
    const word& keyword,
    const std::vector<std::string>& names
)
{
    wordList valid(names.size());
    forAll(valid, i)
    {
        valid[i] = names[i];
    }
    if (!dict.found(keyword, keyType::LITERAL))
    {
        FatalIOErrorInFunction(dict)
            << "Missing keyword '" << keyword << "'." << nl
            << "Valid choices: " << flatOutput(valid) << nl
            << exit(FatalIOError);
    }
    const word name = dict.get<word>(keyword);
    if (!valid.found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown " << keyword << " '" << name << "'." << nl
            << "Valid choices: " << flatOutput(valid) << nl
            << exit(FatalIOError);
    }
    return name;
}

const wordList solverKeywords
({
    "limiter", "stoppingCriterion", "staticResistance", "hDry", "holdResting",
    "steadyStateTolerance", "kineticEnergyStop"
});

const wordList transportKeywords
({
    "g", "coordinates", "epsilon", "lambda", "inclination", "earthPressure",
    "phi", "frictionModel", "rho", "arrivalThreshold", "entrainmentModel"
});

//- Calls f with OpenFOAM's fatal errors thrown as exceptions (the throw
//  modes restored after), an error caught going to onError (which must
//  not return): Function1's own errors name neither the file nor the
//  keyword
template<class F, class OnError>
void catchFatalErrors(const F& f, const OnError& onError)
{
    const bool ioThrows = FatalIOError.throwExceptions();
    const bool throws = FatalError.throwExceptions();
    try
    {
        f();
    }
    catch (const error& e)
    {
        FatalIOError.throwExceptions(ioThrows);
        FatalError.throwExceptions(throws);
        onError(e);
    }
    FatalIOError.throwExceptions(ioThrows);
    FatalError.throwExceptions(throws);
}

} // namespace


caseInput::caseInput(const fvMesh& mesh)
:
    mesh_(mesh),
    transportProperties_
    (
        IOobject
        (
            "transportProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    solverDict_(mesh.solutionDict().subDict("savageHutter")),
    jetDict_(nullptr),
    hasJet(false),
    steadyStateTolerance(0),
    kineticEnergyStop(0),
    adjustTimeStep(false),
    deltaT(0),
    maxDeltaT(GREAT),
    writeInterval(0)
{
    const dictionary& tp = transportProperties_;
    Info<< "Reading transportProperties" << nl;

    // A misspelt keyword (lamda, epsilom) must not fall back to a default;
    // <anything>Coeffs sub-dictionaries are models' coefficients
    for (const word& key : tp.toc())
    {
        const bool coeffs =
            key.size() > 6 && key.compare(key.size() - 6, 6, "Coeffs") == 0;
        if (!transportKeywords.found(key) && !coeffs && key != "FoamFile")
        {
            FatalIOErrorInFunction(tp)
                << "Unknown keyword '" << key << "'." << nl
                << "Valid keywords: " << flatOutput(transportKeywords)
                << " and <model>Coeffs sub-dictionaries" << nl
                << exit(FatalIOError);
        }
    }

    model.g = tp.get<scalar>("g");
    model.epsilon = tp.getOrDefault<scalar>("epsilon", 1);
    model.lambda = tp.getOrDefault<scalar>("lambda", 1);
    // slope (the paper's coordinates along and across an inclined
    // reference surface) or plan (the DEM's plan grid, the whole relief in
    // zb: docs/generalTerrain.md)
    model.coordinates = tp.found("coordinates", keyType::LITERAL)
      ? sh::parseCoordinates
        (
            readChoice(tp, "coordinates", sh::coordinatesNames())
        )
      : sh::Coordinates::slope;
    readInclination(tp);

    model.earthPressure = sh::parseEarthPressure
    (
        readChoice(tp, "earthPressure", sh::earthPressureNames())
    );
    model.phiDeg = tp.get<scalar>("phi");
    readHazardSettings(tp);

    friction_ = frictionModel::New(tp);
    friction_->set(model);
    entrainment_ = entrainmentModel::New(tp);
    entrainment_->set(model);

    Info<< "    g             " << model.g << nl
        << "    epsilon       " << model.epsilon << nl
        << "    lambda        " << model.lambda << nl
        << "    coordinates   " << sh::toString(model.coordinates).c_str()
        << (plan() ? " (the DEM's plan grid: h normal to the bed, U the"
            " velocity along it)" : "") << nl
        << "    inclination   " << inclination->type() << nl
        << "    earthPressure "
        << sh::toString(model.earthPressure).c_str() << nl
        << "    phi           " << model.phiDeg << " deg" << nl
        << "    frictionModel " << friction_->type() << " { "
        << friction_->summary().c_str() << " }" << nl
        << "    entrainmentModel " << entrainment_->type();
    if (entrainment_->on())
    {
        Info<< " { " << entrainment_->summary().c_str() << " }" << nl;
    }
    else
    {
        Info<< " (off: the released volume is all that flows)" << nl;
    }

    readSources();

    readSolverSettings();
    readTimeControl();
}


void caseInput::readSolverSettings()
{
    // fvSolution::savageHutter: a misspelt keyword must not fall back
    Info<< "Reading fvSolution::savageHutter" << nl;
    for (const word& key : solverDict_.toc())
    {
        if (!solverKeywords.found(key))
        {
            FatalIOErrorInFunction(solverDict_)
                << "Unknown keyword '" << key << "' in savageHutter." << nl
                << "Valid keywords: " << flatOutput(solverKeywords) << nl
                << exit(FatalIOError);
        }
    }
    model.limiter = sh::parseLimiter
    (
        readChoice(solverDict_, "limiter", sh::limiterNames())
    );
    model.stoppingCriterion =
        solverDict_.getOrDefault<Switch>("stoppingCriterion", true);
    model.staticResistance =
        solverDict_.getOrDefault<Switch>("staticResistance", true);
    model.holdResting = solverDict_.getOrDefault<Switch>("holdResting", true);
    model.hDry = solverDict_.getOrDefault<scalar>("hDry", 1e-6);
    steadyStateTolerance =
        solverDict_.getOrDefault<scalar>("steadyStateTolerance", 0);
    if (!(steadyStateTolerance >= 0))
    {
        FatalIOErrorInFunction(solverDict_)
            << "steadyStateTolerance must not be negative (0: off), got "
            << steadyStateTolerance << nl << exit(FatalIOError);
    }
    kineticEnergyStop =
        solverDict_.getOrDefault<scalar>("kineticEnergyStop", 0);
    if (!(kineticEnergyStop >= 0 && kineticEnergyStop < 1))
    {
        FatalIOErrorInFunction(solverDict_)
            << "kineticEnergyStop is a fraction of the run's peak kinetic"
            << " energy, 0 <= kineticEnergyStop < 1 (0: off), got "
            << kineticEnergyStop << nl << exit(FatalIOError);
    }

    auto onOff = [](const bool b) { return b ? "on" : "off"; };
    Info<< "    limiter           " << sh::toString(model.limiter).c_str()
        << nl
        << "    stoppingCriterion " << onOff(model.stoppingCriterion) << nl
        << "    staticResistance  " << onOff(model.staticResistance) << nl
        << "    holdResting       " << onOff(model.holdResting) << nl
        << "    hDry              " << model.hDry << nl
        << "    steadyStateTolerance " << steadyStateTolerance
        << (steadyStateTolerance > 0 ? " m/s (RMS of |dh/dt| over wet cells)" : " (off)") << nl
        << "    kineticEnergyStop " << kineticEnergyStop
        << (kineticEnergyStop > 0 ? " (of the peak kinetic energy)" : " (off)") << nl;
}


void caseInput::readTimeControl()
{
    const Time& runTime = mesh_.time();
    // controlDict: the CFL number of eq. (24) and the output times
    control = controlSettings::read(runTime.controlDict());
    // startFrom startTime names the directory to read: say so when it is
    // not there (rather than a missing file <startTime>/h)
    if
    (
        control.startFrom == "startTime"
     && !isDir(runTime.timePath())
    )
    {
        const entry* e =
            runTime.controlDict().findEntry("startTime", keyType::LITERAL);
        FatalIOErrorInFunction(runTime.controlDict())
            << "startTime " << runTime.timeName().c_str();
        if (e)
        {
            FatalIOError << " at line " << e->startLineNumber();
        }
        FatalIOError
            << " (startFrom startTime): no time directory "
            << runTime.timePath().c_str() << nl
            << "Valid values: the time of an existing time directory,"
            << " or startFrom latestTime" << nl << exit(FatalIOError);
    }
    adjustTimeStep = control.adjustTimeStep;
    deltaT = control.deltaT;
    maxDeltaT = control.maxDeltaT;
    // Fixed deltaT: still never beyond the stability limit Co = 1
    model.cfl = adjustTimeStep ? control.maxCo : 1;
    if (!adjustTimeStep)
    {
        maxDeltaT = deltaT;
    }
    writeControl = control.writeControl;
    writeInterval = control.writeInterval;

    if (adjustTimeStep)
    {
        Info<< "Time step: adjustTimeStep yes, maxCo " << model.cfl
            << ", maxDeltaT " << maxDeltaT << nl;
    }
    else
    {
        Info<< "Time step: adjustTimeStep no, deltaT " << deltaT
            << " (reduced where the Courant number would exceed 1)" << nl;
    }
    Info<< "Output: " << writeControl << ", writeInterval "
        << writeInterval << nl;
    readFieldSelection();
    Info<< endl;
}


namespace
{

bool planCoverName(const word& name)
{
    return name == "HEntrainable" || name == "HErodedDepth";
}

} // namespace


void caseInput::readFieldSelection()
{
    const wordList& chosen = control.writeFields;
    if (chosen.empty())
    {
        return;
    }
    // The fields of this case: pMax needs rho, H is plan coordinates',
    // the cover's are the start time's (erodedDepth goes with
    // hEntrainable)
    const fileName startDir = mesh_.time().timePath();
    const bool layer = returnReduce
    (
        isFile(startDir/"hEntrainable"), orOp<bool>()
    );
    const bool resistance = returnReduce
    (
        isFile(startDir/"cResistance"), orOp<bool>()
    );
    wordList valid;
    for (const word& name : controlSettings::writableFields())
    {
        const bool cover = name == "hEntrainable" || name == "erodedDepth";
        const bool planCover = planCoverName(name);
        if
        (
            (name != "pMax" || model.rho > 0) && (name != "H" || plan())
         && (!cover || layer) && (name != "cResistance" || resistance)
         && (!planCover || (layer && plan()))
        )
        {
            valid.append(name);
        }
    }
    for (const word& name : chosen)
    {
        if (!valid.found(name))
        {
            const dictionary& cd = mesh_.time().controlDict();
            const entry* e = cd.findEntry("writeFields", keyType::LITERAL);
            FatalIOErrorInFunction(cd)
                << "writeFields at line " << e->startLineNumber()
                << " names " << name << ", which this case does not have ("
                << (
                       name == "pMax"
                     ? "the peak pressure needs rho in"
                       " constant/transportProperties"
                     : name == "H"
                     ? "H, the volume per plan area, is written in"
                       " coordinates plan"
                     : name == "cResistance"
                     ? "no field cResistance in the start time"
                     : planCoverName(name)
                     ? "HEntrainable and HErodedDepth, the layer and the"
                       " eroded depth per plan area, are written in"
                       " coordinates plan with the field hEntrainable in"
                       " the start time"
                     : "hEntrainable and erodedDepth need the field"
                       " hEntrainable in the start time"
                   ) << ")." << nl
                << "Valid choices: " << valid << nl << exit(FatalIOError);
        }
    }
    wordList restart;
    for (const word& name : controlSettings::restartFields())
    {
        if (valid.found(name))
        {
            restart.append(name);
        }
    }
    Info<< "Fields written: " << chosen << " at every write time, and the"
        << " restart fields " << restart;
    if (control.restartInterval > 0)
    {
        Info<< " every restartInterval " << control.restartInterval
            << " s and";
    }
    Info<< " at the last write time (restartInterval "
        << (control.restartInterval > 0 ? "set" : "0: only there") << ")"
        << nl;
}


void caseInput::readInclination(const dictionary& tp)
{
    if (plan() && !tp.found("inclination"))
    {
        // The whole relief is zb; an inclination given must be 0
        // (HostGeometry::planMetrics names coordinates otherwise)
        IStringStream is("inclination constant 0;");
        const dictionary zero(is);
        inclination = Function1<scalar>::New("inclination", zero);
        return;
    }
    if (!tp.found("inclination"))
    {
        FatalIOErrorInFunction(tp)
            << "Missing keyword 'inclination': the angle zeta(x) of the"
            << " reference surface in degrees, a Function1 of x, e.g."
            << nl << "    inclination constant 35;" << nl
            << "    inclination table ((0 35) (17.5 35) (21.5 0) (30 0));"
            << nl << exit(FatalIOError);
    }
    // An empty or unsorted table: Function1's "out-of-order value"
    catchFatalErrors
    (
        [&]() { inclination = Function1<scalar>::New("inclination", tp); },
        [this](const error& e) { failInclination(e); }
    );
}


void caseInput::readHazardSettings(const dictionary& tp)
{
    // rho: only for the peak pressure of the hazard maps (docs/design.md,
    // section 5)
    if (tp.found("rho"))
    {
        const scalar rho = tp.get<scalar>("rho");
        if (!(rho > 0 && rho <= 1e30))
        {
            FatalIOErrorInFunction(tp)
                << "rho = " << rho << ": the density [kg/m^3] must be"
                << " positive and at most 1e30" << nl << exit(FatalIOError);
        }
        model.rho = rho;
        Info<< "    rho           " << rho << " kg/m^3 (peak pressure pMax)"
            << nl;
    }
    // The arrival time's threshold, validated with the model (makeParams)
    model.arrivalThreshold =
        tp.getOrDefault<scalar>("arrivalThreshold", 0.01);
    Info<< "    arrivalThreshold " << model.arrivalThreshold
        << " m (arrival time tArrival)" << nl;
}


namespace
{

const wordList jetKeywords({"centre", "R", "R_imp", "u_jet"});

//- The keywords of impingingJet entry e (src: its dictionary, c: where its
//  coefficients are, src itself or its coeffsName sub-dictionary): none
//  unknown, every one of jetKeywords in c
void checkJetKeywords
(
    const entry& e,
    const dictionary& src,
    const dictionary& c,
    const word& type,
    const word& coeffsName
)
{
    const wordList entryKeywords({"type", "active", "selectionMode"});
    for (const word& key : src.toc())
    {
        const bool ok =
            entryKeywords.found(key) || key == coeffsName
         || (&c == &src && jetKeywords.found(key));
        if (!ok)
        {
            FatalIOErrorInFunction(src)
                << "Unknown keyword '" << key << "' of " << type << "."
                << nl << "Valid keywords: " << flatOutput(entryKeywords)
                << " and " << flatOutput(jetKeywords) << " (directly or"
                << " in " << type << "Coeffs)" << nl
                << exit(FatalIOError);
        }
    }
    if (&c != &src)
    {
        for (const word& key : c.toc())
        {
            if (!jetKeywords.found(key))
            {
                FatalIOErrorInFunction(c)
                    << "Unknown keyword '" << key << "' of " << type
                    << "." << nl << "Valid keywords: "
                    << flatOutput(jetKeywords) << nl
                    << exit(FatalIOError);
            }
        }
    }
    for (const word& key : jetKeywords)
    {
        if (!c.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(c)
                << "Missing keyword '" << key << "' of " << e.keyword()
                << " (" << type << ")." << nl << "The coefficients "
                << flatOutput(jetKeywords) << " go directly in "
                << e.keyword() << " or in its " << coeffsName
                << " { ... }" << nl << exit(FatalIOError);
        }
    }
}

//- The coefficients of the active source entry e of this type, checked:
//  in <type>Coeffs or in the entry itself, as fvOptions takes them
const dictionary& jetCoeffs(const entry& e, const word& type)
{
    const dictionary& src = e.dict();
    // As fvOptions: coefficients in <type>Coeffs or in the entry
    const word coeffsName = type + "Coeffs";
    const entry* ce = src.findEntry(coeffsName, keyType::LITERAL);
    if (ce && !ce->isDict())
    {
        FatalIOErrorInFunction(src)
            << coeffsName << " of " << e.keyword() << " is not a"
            << " sub-dictionary." << nl << "Valid forms: the"
            << " coefficients in " << coeffsName << " { ... } or in "
            << e.keyword() << " itself" << nl << exit(FatalIOError);
    }
    const dictionary& c = src.optionalSubDict(coeffsName);
    // fvOptions' cell selection: the jet selects the cells within
    // R_imp of its centre itself
    if (src.found("selectionMode", keyType::LITERAL))
    {
        const word mode = src.get<word>("selectionMode");
        if (mode != "all")
        {
            FatalIOErrorInFunction(src)
                << "Invalid selectionMode " << mode << " of "
                << e.keyword() << ": the impinging jet imposes its"
                << " state on the cells within R_imp of its centre."
                << nl << "Valid choices: (all)" << nl
                << exit(FatalIOError);
        }
    }
    checkJetKeywords(e, src, c, type, coeffsName);
    return c;
}

} // namespace


bool caseInput::openSources()
{
    const Time& runTime = mesh_.time();
    IOobject inSystem
    (
        "fvOptions", runTime.system(), mesh_,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
    IOobject inConstant
    (
        "fvOptions", runTime.constant(), mesh_,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
    const bool sys = inSystem.typeHeaderOk<IOdictionary>(true);
    const bool con = inConstant.typeHeaderOk<IOdictionary>(true);
    if (sys && con)
    {
        FatalErrorInFunction
            << "Both system/fvOptions and constant/fvOptions exist: keep one"
            << nl << exit(FatalError);
    }
    if (!sys && !con)
    {
        return false;
    }
    fvOptions_.reset(new IOdictionary(sys ? inSystem : inConstant));
    return true;
}


void caseInput::readSources()
{
    if (!openSources())
    {
        return;
    }
    const dictionary& opts = fvOptions_();
    Info<< "Reading " << opts.name() << nl;

    const wordList validTypes({"impingingJet"});
    for (const entry& e : opts)
    {
        if (e.keyword() == "FoamFile")
        {
            continue;
        }
        if (!e.isDict())
        {
            FatalIOErrorInFunction(opts)
                << "Entry '" << e.keyword() << "' is not a source"
                << " dictionary, e.g." << nl
                << "    jet { type impingingJet; centre (0 0 0); R 7.5e-3;"
                << " R_imp 15e-3; u_jet 0.99; }" << nl
                << exit(FatalIOError);
        }
        const dictionary& src = e.dict();
        const word type = src.get<word>("type");
        if (!validTypes.found(type))
        {
            FatalIOErrorInFunction(src)
                << "Unknown source type '" << type << "' of "
                << e.keyword() << "." << nl
                << "Valid types: " << flatOutput(validTypes) << nl
                << exit(FatalIOError);
        }
        if (!src.getOrDefault<Switch>("active", true))
        {
            Info<< "    " << e.keyword() << ": " << type << ", inactive" << nl;
            continue;
        }
        if (jetDict_)
        {
            FatalIOErrorInFunction(src)
                << "More than one active impingingJet: " << e.keyword()
                << " and " << jetDict_->dictName() << nl
                << exit(FatalIOError);
        }
        readJet(e.keyword(), jetCoeffs(e, type));
    }
}


void caseInput::readJet(const word& name, const dictionary& c)
{
    jetDict_ = &c;
    const vector centre = c.get<vector>("centre");
    jet.xc = centre.x();
    jet.yc = centre.y();
    jet.R = c.get<scalar>("R");
    jet.rImp = c.get<scalar>("R_imp");
    jet.uJet = c.get<scalar>("u_jet");
    if (!(jet.uJet <= maxInputSpeed))
    {
        FatalIOErrorInFunction(c)
            << "u_jet " << jet.uJet << ": the jet's speed must be at"
            << " most " << label(maxInputSpeed)
            << " m/s (the speed of light)" << nl << exit(FatalIOError);
    }
    jet.zeta = degToRad(inclinationAt(jet.xc));
    hasJet = true;
    Info<< "    " << name << ": impingingJet at " << centre
        << ", R " << jet.R << ", R_imp " << jet.rImp << ", u_jet "
        << jet.uJet << ", zeta " << radToDeg(jet.zeta) << " deg" << nl;
}


const dictionary& caseInput::dictOf(const std::string& keyword) const
{
    if (friction_.valid() && friction_->owns(keyword))
    {
        return friction_->coeffs();
    }
    if (entrainment_.valid() && entrainment_->owns(keyword))
    {
        return entrainment_->coeffs();
    }
    if (jetDict_ && (keyword == "centre" || keyword == "R"
     || keyword == "R_imp" || keyword == "u_jet"))
    {
        return *jetDict_;
    }
    if (solverKeywords.found(word(keyword)))
    {
        return solverDict_;
    }
    if (keyword == "maxCo")
    {
        return mesh_.time().controlDict();
    }
    return transportProperties_;
}


scalar caseInput::inclinationAt(const scalar x) const
{
    scalar zeta = 0;
    catchFatalErrors
    (
        [&]() { zeta = inclination->value(x); },
        [this](const error& e) { failInclination(e); }
    );
    if (!(mag(zeta) < 90))
    {
        FatalIOErrorInFunction(transportProperties_)
            << "Invalid inclination: zeta(x = " << x << ") = " << zeta
            << " deg: the inclination must lie in (-90, 90) degrees" << nl
            << exit(FatalIOError);
    }
    return zeta;
}


void caseInput::failInclination(const error& e) const
{
    FatalIOErrorInFunction(transportProperties_)
        << "Invalid inclination: " << e.message().c_str() << nl
        << "Valid: a Function1 of x giving zeta in degrees, in (-90, 90)"
        << " over the mesh, e.g." << nl
        << "    inclination constant 35;" << nl
        << "    inclination table ((0 35) (17.5 35) (21.5 0) (30 0));"
        << "  (x strictly ascending)" << nl << exit(FatalIOError);
    std::abort();
}


wordList caseInput::memberKeywords() const
{
    wordList keys({"phi", "epsilon", "lambda"});
    const word coeffs = friction_->type() + "Coeffs";
    for (const word& k : friction_->coeffs().sortedToc())
    {
        keys.append(coeffs + "/" + k);
    }
    return keys;
}


sh::ModelInput caseInput::memberModel
(
    const wordList& keys,
    const scalarList& values
) const
{
    dictionary tp(transportProperties_);
    forAll(keys, k)
    {
        const auto slash = keys[k].find('/');
        if (slash == std::string::npos)
        {
            tp.set(keyType(keys[k]), values[k]);
        }
        else
        {
            tp.subDict(word(keys[k].substr(0, slash)))
                .set(keyType(word(keys[k].substr(slash + 1))), values[k]);
        }
    }
    sh::ModelInput m = model;
    m.epsilon = tp.getOrDefault<scalar>("epsilon", 1);
    m.lambda = tp.getOrDefault<scalar>("lambda", 1);
    m.phiDeg = tp.get<scalar>("phi");
    frictionModel::New(tp)->set(m);
    // What makeParams refuses (delta > phi, ...), as an InputError
    sh::makeParams<double>(m);
    return m;
}


void caseInput::fail(const sh::InputError& e) const
{
    // An entrainment model's coefficient: its valid range too
    const bool entrainmentCoeff =
        (!friction_.valid() || !friction_->owns(e.keyword()))
     && entrainment_.valid() && entrainment_->owns(e.keyword());
    FatalIOErrorInFunction(dictOf(e.keyword()))
        << "Invalid " << e.keyword() << ": " << e.what() << nl;
    if (entrainmentCoeff)
    {
        FatalIOError
            << "Valid range: "
            << entrainment_->validRange(e.keyword()).c_str() << nl;
    }
    FatalIOError << exit(FatalIOError);
    std::abort();
}

} // End namespace Foam

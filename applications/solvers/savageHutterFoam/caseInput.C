/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "caseInput.H"
#include "Switch.H"

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
    "limiter", "stoppingCriterion", "staticResistance", "hDry", "holdResting"
});

const wordList transportKeywords
({
    "g", "epsilon", "lambda", "inclination", "earthPressure", "phi",
    "frictionModel"
});

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
    if (!tp.found("inclination"))
    {
        FatalIOErrorInFunction(tp)
            << "Missing keyword 'inclination': the angle zeta(x) of the"
            << " reference surface in degrees, a Function1 of x, e.g."
            << nl << "    inclination constant 35;" << nl
            << "    inclination table ((0 35) (17.5 35) (21.5 0) (30 0));"
            << nl << exit(FatalIOError);
    }
    inclination = Function1<scalar>::New("inclination", tp);

    model.earthPressure = sh::parseEarthPressure
    (
        readChoice(tp, "earthPressure", sh::earthPressureNames())
    );
    model.phiDeg = tp.get<scalar>("phi");

    const word friction =
        readChoice(tp, "frictionModel", sh::frictionLawNames());
    model.frictionLaw = sh::parseFrictionLaw(friction);
    const dictionary& coeffs = tp.subDict(friction + "Coeffs");
    model.deltaDeg = coeffs.get<scalar>("delta");

    Info<< "    g             " << model.g << nl
        << "    epsilon       " << model.epsilon << nl
        << "    lambda        " << model.lambda << nl
        << "    inclination   " << inclination->type() << nl
        << "    earthPressure "
        << sh::toString(model.earthPressure).c_str() << nl
        << "    phi           " << model.phiDeg << " deg" << nl
        << "    frictionModel " << friction << " { delta "
        << model.deltaDeg << " deg }" << nl;

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

    auto onOff = [](const bool b) { return b ? "on" : "off"; };
    Info<< "    limiter           " << sh::toString(model.limiter).c_str()
        << nl
        << "    stoppingCriterion " << onOff(model.stoppingCriterion) << nl
        << "    staticResistance  " << onOff(model.staticResistance) << nl
        << "    holdResting       " << onOff(model.holdResting) << nl
        << "    hDry              " << model.hDry << nl;

    // controlDict: the CFL number of eq. (24) and the output times
    const dictionary& cd = mesh.time().controlDict();
    adjustTimeStep = cd.getOrDefault<Switch>("adjustTimeStep", false);
    deltaT = cd.get<scalar>("deltaT");
    maxDeltaT = cd.getOrDefault<scalar>("maxDeltaT", GREAT);
    if (adjustTimeStep)
    {
        model.cfl = cd.getOrDefault<scalar>("maxCo", 1);
    }
    else
    {
        // Fixed deltaT, still never beyond the stability limit Co = 1
        model.cfl = 1;
        maxDeltaT = deltaT;
    }
    if (!(deltaT > 0) || !(maxDeltaT > 0))
    {
        FatalIOErrorInFunction(cd)
            << "deltaT and maxDeltaT must be positive, got deltaT = "
            << deltaT << ", maxDeltaT = " << maxDeltaT << nl
            << exit(FatalIOError);
    }

    writeControl = cd.get<word>("writeControl");
    const wordList validWrite
    ({
        "adjustableRunTime", "runTime", "timeStep", "clockTime", "cpuTime"
    });
    if (!validWrite.found(writeControl))
    {
        FatalIOErrorInFunction(cd)
            << "Unknown writeControl " << writeControl << nl
            << "Valid choices: " << flatOutput(validWrite) << nl
            << exit(FatalIOError);
    }
    writeInterval = cd.get<scalar>("writeInterval");
    if
    (
        !(writeInterval > 0)
     || (writeControl == "timeStep" && writeInterval < 1)
    )
    {
        FatalIOErrorInFunction(cd)
            << "writeInterval must be positive (at least 1 with writeControl"
            << " timeStep), got " << writeInterval << nl
            << exit(FatalIOError);
    }

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
        << writeInterval << nl << endl;
}


const dictionary& caseInput::dictOf(const std::string& keyword) const
{
    if (keyword == "delta")
    {
        return transportProperties_.subDict
        (
            sh::toString(model.frictionLaw) + "Coeffs"
        );
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


void caseInput::fail(const sh::InputError& e) const
{
    FatalIOErrorInFunction(dictOf(e.keyword()))
        << "Invalid " << e.keyword() << ": " << e.what() << nl
        << exit(FatalIOError);
    std::abort();
}

} // End namespace Foam

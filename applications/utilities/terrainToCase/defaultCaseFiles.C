/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "defaultCaseFiles.H"
#include "IStringStream.H"
#include "OSspecific.H"

#include "terrainFiles.H"

namespace Foam
{

namespace
{

std::string header(const char* location, const char* object)
{
    return std::string
    (
        "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        "  savageHutterFoam: written by terrainToCase with its defaults; edit freely\n"
        "  (docs/userGuide.md lists every keyword and its range)\n"
        "\\*---------------------------------------------------------------------------*/\n"
        "FoamFile\n"
        "{\n"
        "    version     2.0;\n"
        "    format      ascii;\n"
        "    class       dictionary;\n"
        "    location    \""
    ) + location + "\";\n    object      " + object + ";\n}\n\n";
}

const char* const footer =
    "\n// ************************************************************************* //\n";

//- The entries of the default controlDict: 10 minutes of flow at most,
//  ended earlier at rest (fvSolution's steadyStateTolerance), a write every
//  10 s
const char* const controlEntries =
    "application     savageHutterFoam;\n"
    "startFrom       latestTime;\n"
    "startTime       0;\n"
    "stopAt          endTime;\n"
    "endTime         600;        // [s]; the run ends earlier at rest"
    " (fvSolution: steadyStateTolerance)\n"
    "deltaT          1e-2;       // [s] the first step; then maxCo decides\n"
    "adjustTimeStep  yes;\n"
    "maxCo           0.4;        // Courant number of the paper's eq. (24)\n"
    "writeControl    adjustableRunTime;\n"
    "writeInterval   10;         // [s]\n"
    "purgeWrite      0;\n"
    "writeFormat     binary;\n"
    "writePrecision  8;\n"
    "writeCompression off;\n"
    "timeFormat      general;\n"
    "timePrecision   6;\n"
    "runTimeModifiable false;\n";

const char* const schemesEntries =
    "// savageHutterFoam discretises with its own Godunov scheme (fvSolution's\n"
    "// savageHutter dictionary); OpenFOAM's mesh needs this file to exist.\n"
    "ddtSchemes      { default none; }\n"
    "gradSchemes     { default none; }\n"
    "divSchemes      { default none; }\n"
    "laplacianSchemes { default none; }\n"
    "interpolationSchemes { default linear; }\n"
    "snGradSchemes   { default none; }\n";

const char* const solutionEntries =
    "savageHutter\n"
    "{\n"
    "    limiter           minmod;     // minmod | vanLeer | MC\n"
    "    stoppingCriterion on;         // eq. (27) of the paper\n"
    "    staticResistance  on;         // eqs (25)-(26)\n"
    "    hDry              1e-6;       // [m] partial-wet threshold, eq. (29)\n"
    "    steadyStateTolerance 1e-4;    // [m/s] the run ends when the flow"
    " is at rest\n"
    "}\n";

//- Writes `text` to path/rel unless the file is there; reports it
void writeIfMissing
(
    const fileName& path, const char* rel, const std::string& text,
    const char* what
)
{
    const fileName f = path/rel;
    if (isFile(f))
    {
        return;
    }
    terrainFiles::writeText(f, text);
    Info<< "Wrote " << rel << " (" << what << "; it was missing)" << nl;
}

} // End anonymous namespace


dictionary defaultControlDict()
{
    IStringStream is(controlEntries);
    return dictionary(is);
}


std::string defaultTransportProperties(bool plan)
{
    std::string s = header("constant", "transportProperties");
    s +=
        "g               9.81;       // [m/s^2]\n"
        "epsilon         1;          // aspect ratio (1: dimensional terrain"
        " cases)\n"
        "lambda          1;          // curvature term of the normal load"
        " (0: none)\n";
    s += plan
        ? "coordinates     plan;       // the DEM's plan grid (set by"
          " terrainToCase)\n"
        : "inclination     constant 0; // terrainToCase writes the table"
          " along its axis\n";
    s +=
        "earthPressure   activePassive;  // activePassive | isotropic\n"
        "phi             35;         // [deg] internal friction angle\n"
        "rho             1500;       // [kg/m^3] density: the peak pressure"
        " map pMax\n"
        "arrivalThreshold 0.01;      // [m] thickness of the arrival time"
        " map tArrival\n"
        "frictionModel   Coulomb;    // Coulomb | Voellmy |"
        " PouliquenForterre\n"
        "CoulombCoeffs\n"
        "{\n"
        "    delta       20;         // [deg] basal friction angle,"
        " <= phi\n"
        "}\n"
        "VoellmyCoeffs\n"
        "{\n"
        "    mu          0.2;        // friction coefficient\n"
        "    xi          2000;       // [m/s^2] turbulence coefficient\n"
        "}\n";
    return s + footer;
}


void writeMissingCaseFiles(const fileName& path)
{
    writeIfMissing
    (
        path, "system/controlDict",
        header("system", "controlDict") + controlEntries + footer,
        "endTime 600 s or at rest, a write every 10 s"
    );
    writeIfMissing
    (
        path, "system/fvSchemes",
        header("system", "fvSchemes") + schemesEntries + footer,
        "none of its schemes is used"
    );
    writeIfMissing
    (
        path, "system/fvSolution",
        header("system", "fvSolution") + solutionEntries + footer,
        "the paper's scheme: minmod, eqs (25)-(27), at rest below 1e-4 m/s"
    );
}

} // End namespace Foam

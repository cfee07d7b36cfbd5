/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "terrainCase.H"
#include "timeSelector.H"
#include "vector2D.H"

namespace Foam
{

IOobject fieldIO(const fvMesh& mesh, const word& instance, const word& name)
{
    return IOobject
    (
        name, instance, mesh, IOobject::MUST_READ, IOobject::NO_WRITE
    );
}


instantList numericTimes(const Time& runTime)
{
    instantList numeric;
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant())
        {
            numeric.append(t);
        }
    }
    if (numeric.empty())
    {
        FatalErrorInFunction
            << "No time directory in " << runTime.path() << nl
            << exit(FatalError);
    }
    return numeric;
}


instantList selectedTimes
(
    const Time& runTime, const argList& args, const instantList& numeric
)
{
    instantList selected;
    for
    (
        const instant& t
      : timeSelector::select(runTime.times(), args, runTime.constant())
    )
    {
        if (t.name() != runTime.constant())
        {
            selected.append(t);
        }
    }
    if (selected.empty())
    {
        FatalErrorInFunction
            << "No time selected in " << runTime.path() << "; times: "
            << flatOutput(numeric) << nl << exit(FatalError);
    }
    return selected;
}


IOobject terrainMappingIO(const Time& runTime)
{
    return IOobject
    (
        "terrainMapping", runTime.constant(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
}


IOobject transportPropertiesIO(const Time& runTime)
{
    return IOobject
    (
        "transportProperties", runTime.constant(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
}


terrain::referenceSurface mappingSurface(const dictionary& mapDict)
{
    const List<vector2D> table = mapDict.get<List<vector2D>>("inclination");
    std::vector<double> xT, zT;
    for (const vector2D& p : table)
    {
        xT.push_back(p.x());
        zT.push_back(p.y());
    }
    const vector o = mapDict.get<vector>("origin");
    const vector2D t = mapDict.get<vector2D>("tangent");
    return terrain::referenceSurface
    (
        {o.x(), o.y(), o.z()}, t.x(), t.y(), xT, zT
    );
}



bool planMode(const dictionary& mapDict, const dictionary& tp)
{
    const word mode = mapDict.getOrDefault<word>("mode", "axis");
    if (mode != "axis" && mode != "plan")
    {
        FatalIOErrorInFunction(mapDict)
            << "keyword 'mode' = " << mode << ": unknown mapping mode (plan,"
            << " or axis, the default without 'mode')" << nl
            << "Nothing written." << nl << exit(FatalIOError);
    }
    if (mode == "plan" && tp.getOrDefault<word>("coordinates", "") != "plan")
    {
        FatalIOErrorInFunction(tp)
            << "keyword 'coordinates': " << mapDict.name()
            << " is of the plan mode, so 'coordinates plan;' is expected"
            << " here (terrainToCase writes it; it has "
            << (tp.found("coordinates") ? "another value" : "none") << ")"
            << nl << "Nothing written." << nl << exit(FatalIOError);
    }
    return mode == "plan";
}


planGrid mappingPlan(const dictionary& mapDict)
{
    const vector2D o = mapDict.get<vector2D>("origin");
    const vector2D ax = mapDict.get<vector2D>("xAxis");
    const vector2D ay = mapDict.get<vector2D>("yAxis");
    planGrid g;
    g.origin = {o.x(), o.y()};
    g.xAxis = {ax.x(), ax.y()};
    g.yAxis = {ay.x(), ay.y()};
    g.cellSize = mapDict.get<scalar>("cellSize");
    g.nx = mapDict.get<label>("nx");
    g.ny = mapDict.get<label>("ny");
    const scalar cross = ax.x()*ay.y() - ax.y()*ay.x();
    if
    (
        !(g.cellSize > 0) || g.nx < 1 || g.ny < 1
     || !(mag(mag(ax) - 1) < 1e-9) || !(mag(cross - 1) < 1e-9)
    )
    {
        FatalIOErrorInFunction(mapDict)
            << "keywords 'xAxis', 'yAxis', 'cellSize', 'nx', 'ny': not a plan"
            << " grid (unit xAxis, yAxis it turned by +90 deg, cellSize > 0,"
            << " nx, ny >= 1)" << nl << "Nothing written." << nl
            << exit(FatalIOError);
    }
    return g;
}

} // End namespace Foam

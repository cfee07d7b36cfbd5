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

} // End namespace Foam

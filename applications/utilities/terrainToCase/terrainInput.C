/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "terrainInput.H"
#include "OSspecific.H"
#include "FlatOutput.H"

namespace Foam
{

const wordList terrainKeywords
({
    "dem", "axis", "halfWidth", "cellSize", "profileSmoothing", "extent",
    "release", "entrainment", "resistance"
});

const wordList releaseKeywords
({
    "polygon", "file", "raster", "thickness", "thicknessDirection"
});

const wordList resistanceKeywords
({
    "polygon", "file", "raster", "cResistance"
});


void checkKeywords
(
    const dictionary& d, const wordList& valid, const std::string& what
)
{
    for (const word& key : d.toc())
    {
        if (!valid.found(key) && key != "FoamFile")
        {
            FatalIOErrorInFunction(d)
                << "Unknown keyword '" << key << "' in " << what.c_str()
                << "." << nl
                << "Valid keywords: " << flatOutput(valid) << nl
                << exit(FatalIOError);
        }
    }
}


scalar readPositive(const dictionary& d, const word& key, bool zeroOk)
{
    const scalar v = d.get<scalar>(key);
    if (!(zeroOk ? v >= 0 : v > 0) || !(v < 1e30))
    {
        FatalIOErrorInFunction(d)
            << "keyword '" << key << "' = " << v << ": must be "
            << (zeroOk ? "finite and >= 0" : "finite and > 0") << nl
            << exit(FatalIOError);
    }
    return v;
}


fileName caseFile(const Time& runTime, const dictionary& d, const word& key)
{
    fileName f = d.get<fileName>(key);
    f.expand();
    if (!f.isAbsolute())
    {
        f = runTime.path()/f;
    }
    if (!isFile(f))
    {
        FatalIOErrorInFunction(d)
            << "keyword '" << key << "': file " << f << " not found" << nl
            << exit(FatalIOError);
    }
    return f;
}


chuteAxis readAxis(const dictionary& dict)
{
    if (dict.found("extent"))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'extent' belongs to the plan mode (a terrainDict"
            << " without 'axis'): with 'axis' the mesh spans the axis and"
            << " +-halfWidth.  Remove 'extent' or 'axis'" << nl
            << exit(FatalIOError);
    }
    chuteAxis a;
    a.points = dict.get<List<vector2D>>("axis");
    if (a.points.size() != 2)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'axis': two points ((X0 Y0) (X1 Y1)), top to"
            << " bottom, expected; got " << a.points.size() << nl
            << exit(FatalIOError);
    }
    a.P0 = a.points[0];
    a.length = mag(a.points[1] - a.points[0]);
    if (!(a.length > 0) || !(a.length < 1e30))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'axis': its points " << a.points[0] << " and "
            << a.points[1] << " must differ (length " << a.length << ")" << nl
            << exit(FatalIOError);
    }
    a.t = (a.points[1] - a.points[0])/a.length;
    a.halfWidth = readPositive(dict, "halfWidth");
    a.cellSize = readPositive(dict, "cellSize");
    a.smoothing = readPositive(dict, "profileSmoothing", true);
    return a;
}

} // End namespace Foam

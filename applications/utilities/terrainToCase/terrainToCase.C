/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    terrainToCase

Description
    Makes a savageHutterFoam case from a digital elevation model and
    release areas, as system/terrainDict describes them (docs/design.md
    section 5):

        dem             "constant/dem.tif";   // .asc or .tif, elevation [m]
        axis            ((X0 Y0) (X1 Y1));    // chute axis, top to bottom
        halfWidth       250;                  // [m] y in [-halfWidth, halfWidth]
        cellSize        5;                    // [m] square cells
        profileSmoothing 25;                  // [m] 0 = none
        release
        {
            release1
            {
                polygon     ((X Y) (X Y) ...);    // or file "constant/release.shp";
                thickness   1.0;                  // [m]
                thicknessDirection normal;        // normal | vertical
            }
            release2
            {
                raster      "constant/release.tif";  // thickness [m] per pixel
                thicknessDirection vertical;     // (no 'thickness' keyword)
            }
        }

    The DEM's grid may be north-up or rotated (any affine geotransform).
    Polygon vertices in the dictionary are in the DEM's coordinates; a
    shapefile's (its .prj) and a release raster's coordinate reference
    system, when both it and the DEM's are given and differ, is transformed
    to the DEM's (OGR, traditional GIS axis order: a vertex at a time, so
    a polygon's edges are straight in the DEM's plan); when only one of
    the two is given, a warning, and the coordinates are taken as the
    DEM's.

    The reference profile is the DEM's elevation along the axis (the
    thalweg), its slope fitted by a local linear regression over
    profileSmoothing on either side (biweight weights; a straight profile
    stays exactly straight, ends included), zeta = atan(-dZ/dS).  x is the
    arc length along that profile from the axis' first point, y the
    horizontal distance across it (to the left looking downslope), z the
    distance along the profile's normal (referenceSurface.H).

    Writes
        system/blockMeshDict         nx x ny square cells of cellSize, x in
                                     [0, nx cellSize], y symmetric; patches
                                     upslope (wall), downslope and sides
                                     (outflow), frontAndBack (empty)
        constant/transportProperties its inclination entry replaced by the
                                     table of zeta(x) (the rest kept)
        0/zb                         the DEM's offset from the reference
                                     surface along its normal
        0/h                          the releases' thickness normal to the
                                     reference surface, each cell by the
                                     area of it the polygons cover, or the
                                     area-weighted mean of the release
                                     raster's pixels over it
                                     (rasterRelease.H: conservative, exact
                                     on a plane DEM); vertical thickness d
                                     becomes d cos(theta), theta the DEM's
                                     slope there
        0/U                          zero
        constant/terrainMapping      what maps (x, y, z) back to the DEM's
                                     world coordinates (hazardMaps reads it)

    Warns, with figures, where |grad zb| is large (the shallow-flow model's
    bed is the reference surface; a steep zb strains it).  Every input is
    checked before anything is written: a missing DEM, an unknown raster
    format, a DEM with an infinite elevation, an axis of zero length or
    leaving the DEM, a mesh over nodata or off the DEM, a normal from the
    reference surface (along which zb is measured) leaving the DEM or
    meeting nodata before it meets the terrain, a release outside the mesh,
    too few DEM values around a cell for the slope a vertical thickness
    needs, a release raster that cannot be read, with a negative, NaN or
    infinite thickness, without a thickness > 0 or without overlap with the
    mesh, a coordinate transformation that cannot be built stop it with
    FOAM FATAL IO ERROR naming the file and the keyword, and nothing is
    written.  A release raster reaching beyond the mesh is a warning with
    the volume left out.

Usage
    terrainToCase [-dict file]

    then blockMesh and savageHutterFoam; hazardMaps afterwards.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "vector2D.H"
#include "OSspecific.H"

#include "gdalIO.H"
#include "referenceSurface.H"
#include "polygonClip.H"
#include "rasterRelease.H"
#include "terrainFiles.H"

#include <fstream>
#include <iomanip>
#include <sstream>

using namespace Foam;

namespace
{

const wordList terrainKeywords
({
    "dem", "axis", "halfWidth", "cellSize", "profileSmoothing", "release"
});

const wordList releaseKeywords
({
    "polygon", "file", "raster", "thickness", "thicknessDirection"
});

void checkKeywords
(
    const dictionary& d, const wordList& valid, const word& what
)
{
    for (const word& key : d.toc())
    {
        if (!valid.found(key) && key != "FoamFile")
        {
            FatalIOErrorInFunction(d)
                << "Unknown keyword '" << key << "' in " << what << "." << nl
                << "Valid keywords: " << flatOutput(valid) << nl
                << exit(FatalIOError);
        }
    }
}

scalar readPositive(const dictionary& d, const word& key, bool zeroOk = false)
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

//- A file named by a keyword, relative to the case directory
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

//- Slopes dZ/dS of the profile at its samples and Z at the first one: a
//  local linear fit with biweight weights over +-L (L = 0: differences)
void fitProfile
(
    const std::vector<double>& Z, double dS, double L,
    std::vector<double>& slope, double& Z0
)
{
    const label n = label(Z.size());
    slope.assign(Z.size(), 0);
    if (L < 1.5*dS)
    {
        for (label k = 0; k < n; ++k)
        {
            const label a = max(k - 1, label(0));
            const label b = min(k + 1, n - 1);
            slope[k] = (Z[b] - Z[a])/((b - a)*dS);
        }
        Z0 = Z[0];
        return;
    }
    const label w = label(std::ceil(L/dS));
    for (label k = 0; k < n; ++k)
    {
        double sw = 0, su = 0, sz = 0, suu = 0, suz = 0;
        for (label m = max(k - w, label(0)); m <= min(k + w, n - 1); ++m)
        {
            const double u = (m - k)*dS;
            const double r = u/L;
            if (std::fabs(r) >= 1)
            {
                continue;
            }
            const double wt = sqr(1 - r*r);
            sw += wt;
            su += wt*u;
            sz += wt*Z[m];
            suu += wt*u*u;
            suz += wt*u*Z[m];
        }
        const double det = sw*suu - su*su;
        slope[k] = (sw*suz - su*sz)/det;
        if (k == 0)
        {
            Z0 = (suu*sz - su*suz)/det;
        }
    }
}

struct release
{
    word name;
    std::vector<terrain::Polygon> polygons;   // world (X, Y) of the DEM
    terrain::Raster raster;                   // or a thickness raster
    fileName rasterFile;
    std::unique_ptr<terrain::crsTransform> rasterToDem;
    scalar thickness = 0;
    bool vertical = false;
    const dictionary* dict = nullptr;
    word shapeKey;                            // polygon, file or raster
};

//- A crsTransform from a file's system to the DEM's, its warning and
//  what it does announced; FatalIOError naming the keyword when none
std::unique_ptr<terrain::crsTransform> toDemSystem
(
    const std::string& wkt, const std::string& demWkt, const fileName& file,
    const dictionary& d, const word& key, const word& releaseName
)
{
    std::unique_ptr<terrain::crsTransform> t;
    try
    {
        t.reset(new terrain::crsTransform(wkt, demWkt, file));
    }
    catch (const terrain::gdalError& err)
    {
        FatalIOErrorInFunction(d)
            << "keyword '" << key << "' of release " << releaseName << ": "
            << err.what() << nl << exit(FatalIOError);
    }
    if (!t->warning().empty())
    {
        WarningInFunction
            << "release " << releaseName << ": " << t->warning().c_str()
            << nl << endl;
    }
    if (!t->identity())
    {
        Info<< "    release " << releaseName << ": " << file
            << " transformed " << t->description().c_str() << nl;
    }
    return t;
}

//- The release raster's values as thickness: finite and >= 0 where not
//  nodata (nodata and 0: no release)
void checkThicknessRaster
(
    const terrain::Raster& r, const fileName& file, const dictionary& d,
    const word& releaseName
)
{
    const bool nanIsNodata = r.hasNodata && std::isnan(r.nodata);
    for (int j = 0; j < r.ny; ++j)
    {
        for (int i = 0; i < r.nx; ++i)
        {
            const double v = r.at(i, j);
            const bool bad =
                std::isnan(v) ? !nanIsNodata
              : r.valid(v) && (v < 0 || !(v < 1e30));
            if (bad)
            {
                const std::array<double, 2> P = r.point(i + 0.5, j + 0.5);
                FatalIOErrorInFunction(d)
                    << "keyword 'raster' of release " << releaseName << ": "
                    << file << " holds the thickness " << v << " at pixel ("
                    << i << ", " << j << ") (X = " << P[0] << ", Y = " << P[1]
                    << "): thickness must be finite and >= 0 (nodata and 0:"
                    << " no release)" << nl << exit(FatalIOError);
            }
        }
    }
}

} // namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Make a savageHutterFoam case (mesh, inclination table, zb, h, U)"
        " from a DEM and release areas in system/terrainDict"
    );
    argList::addOption("dict", "file", "alternative dictionary");
    argList::noParallel();
    argList::noFunctionObjects();

    #include "setRootCase.H"
    #include "createTime.H"

    const fileName dictFile =
        args.getOrDefault<fileName>("dict", runTime.system()/"terrainDict");
    Info<< "Reading " << dictFile << nl << endl;
    const IOdictionary dict
    (
        IOobject(dictFile, runTime, IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    checkKeywords(dict, terrainKeywords, "terrainDict");

    // -- The DEM ------------------------------------------------------------
    const fileName demName = dict.get<fileName>("dem");
    try
    {
        terrain::rasterDriver(demName);
    }
    catch (const terrain::gdalError& e)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'dem': " << e.what() << nl << exit(FatalIOError);
    }
    const fileName demFile = caseFile(runTime, dict, "dem");
    terrain::Raster dem;
    try
    {
        dem = terrain::readRaster(demFile);
    }
    catch (const terrain::gdalError& e)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'dem': " << e.what() << nl << exit(FatalIOError);
    }
    // Elevations finite where not nodata (NaN pixels count as nodata)
    for (int j = 0; j < dem.ny; ++j)
    {
        for (int i = 0; i < dem.nx; ++i)
        {
            const double v = dem.at(i, j);
            if (dem.valid(v) && !std::isfinite(v))
            {
                const std::array<double, 2> P = dem.point(i + 0.5, j + 0.5);
                FatalIOErrorInFunction(dict)
                    << "keyword 'dem': " << demFile << " holds the elevation "
                    << v << " at pixel (" << i << ", " << j << ") (X = "
                    << P[0] << ", Y = " << P[1] << "): elevations must be"
                    << " finite (nodata: the raster's nodata value or NaN)"
                    << nl << exit(FatalIOError);
            }
        }
    }
    const double pixel = dem.pixelSize();
    const std::array<double, 4> demBox = dem.bounds();
    const double demX0 = demBox[0], demX1 = demBox[1];
    const double demY0 = demBox[2], demY1 = demBox[3];
    // Where the DEM has values: between its outermost pixel centres
    const std::array<double, 4> valueBox = dem.sampledBounds();
    std::ostringstream valueExtent;
    valueExtent
        << "its values (bilinear between pixel centres) reach X in ["
        << valueBox[0] << ", " << valueBox[1] << "], Y in [" << valueBox[2]
        << ", " << valueBox[3] << "]"
        << (dem.northUp() ? "" : " (rotated; their bounding box)")
        << ", half a pixel inside its outline";
    Info<< "DEM " << demFile << ": " << dem.nx << " x " << dem.ny
        << " pixels of " << std::hypot(dem.gt[1], dem.gt[4]) << " x "
        << std::hypot(dem.gt[2], dem.gt[5]) << " m, "
        << (dem.northUp() ? "" : "rotated grid, bounding box ")
        << "X in [" << demX0 << ", " << demX1 << "], Y in ["
        << demY0 << ", " << demY1 << "]" << nl;
    const auto elevation = [&dem](double X, double Y)
    {
        return dem.value(X, Y);
    };

    // -- Axis and mesh size -------------------------------------------------
    const List<vector2D> axis = dict.get<List<vector2D>>("axis");
    if (axis.size() != 2)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'axis': two points ((X0 Y0) (X1 Y1)), top to"
            << " bottom, expected; got " << axis.size() << nl
            << exit(FatalIOError);
    }
    const vector2D P0 = axis[0];
    const scalar L = mag(axis[1] - axis[0]);
    if (!(L > 0) || !(L < 1e30))
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'axis': its points " << axis[0] << " and " << axis[1]
            << " must differ (length " << L << ")" << nl
            << exit(FatalIOError);
    }
    const vector2D t = (axis[1] - axis[0])/L;
    const scalar halfWidth = readPositive(dict, "halfWidth");
    const scalar cellSize = readPositive(dict, "cellSize");
    const scalar smoothing = readPositive(dict, "profileSmoothing", true);

    // -- The thalweg profile and the inclination table ----------------------
    const label nS = max(label(2), label(std::ceil(2*L/cellSize)) + 1);
    const double dS = L/(nS - 1);
    std::vector<double> Zraw(nS);
    for (label k = 0; k < nS; ++k)
    {
        const vector2D P = P0 + (k*dS)*t;
        Zraw[k] = dem.value(P.x(), P.y());
        if (!std::isfinite(Zraw[k]))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'axis': the axis from " << axis[0] << " to "
                << axis[1] << " leaves the DEM"
                << " or crosses nodata at " << P << " (distance " << k*dS
                << " m from its first point); the DEM " << demFile
                << (dem.northUp() ? "" : " (rotated; its bounding box)")
                << " covers X in [" << demX0 << ", " << demX1
                << "], Y in [" << demY0 << ", " << demY1 << "]" << nl
                << exit(FatalIOError);
        }
    }
    std::vector<double> slope;
    double Z0 = 0;
    fitProfile(Zraw, dS, smoothing, slope, Z0);
    std::vector<double> zetaDeg(nS), xTable(nS, 0.0);
    for (label k = 0; k < nS; ++k)
    {
        zetaDeg[k] = radToDeg(std::atan(-slope[k]));
    }
    // Table points where the profile has advanced dS in plan
    for (label k = 1; k < nS; ++k)
    {
        const double z0 = degToRad(zetaDeg[k - 1]);
        const double z1 = degToRad(zetaDeg[k]);
        double dx = dS/std::cos(0.5*(z0 + z1));
        for (int it = 0; it < 20; ++it)
        {
            dx *= dS/terrain::referenceSurface::planAdvance(z0, z1, dx);
        }
        xTable[k] = xTable[k - 1] + dx;
    }
    const terrain::referenceSurface surface
    (
        {P0.x(), P0.y(), Z0}, t.x(), t.y(), xTable, zetaDeg
    );
    const label nx = label(std::floor(surface.xEnd()/cellSize*(1 + 1e-12)));
    const label ny = max(label(1), label(std::round(2*halfWidth/cellSize)));
    if (nx < 1)
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'axis': the profile along the axis is "
            << surface.xEnd() << " m long, shorter than one cell"
            << " (cellSize " << cellSize << ")" << nl << exit(FatalIOError);
    }
    const scalar xMax = nx*cellSize;
    const scalar yMax = 0.5*ny*cellSize;
    Info<< "Axis " << axis << ": " << L << " m in plan, profile "
        << surface.xEnd() << " m long, zeta from "
        << *std::min_element(zetaDeg.begin(), zetaDeg.end()) << " to "
        << *std::max_element(zetaDeg.begin(), zetaDeg.end()) << " deg" << nl
        << "Mesh: " << nx << " x " << ny << " cells of " << cellSize
        << " m, x in [0, " << xMax << "], y in [" << -yMax << ", " << yMax
        << "]" << nl;

    // -- zb at the cell centres ---------------------------------------------
    // FatalIOError for the cell at (x, y) where offset() found no zb, with
    // zNoValue, the offset along the normal of the point with no DEM value
    const auto zbFailure = [&](double x, double y, double zNoValue)
    {
        const terrain::vec3 W = surface.world(x, y, 0);
        if (zNoValue == 0)
        {
            const bool inside = dem.sampled(W[0], W[1]);
            FatalIOErrorInFunction(dict)
                << "keyword '" << (inside ? "dem" : "halfWidth")
                << "': the mesh cell at x = " << x << ", y = " << y
                << " (world X = " << W[0] << ", Y = " << W[1] << ") "
                << (inside
                    ? "lies over a nodata hole of the DEM "
                    : "lies outside the DEM ")
                << demFile << "; " << valueExtent.str().c_str() << nl
                << "(the mesh spans the axis' profile and +-halfWidth)"
                << nl << exit(FatalIOError);
        }
        if (!std::isfinite(zNoValue))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'dem': the offset of the DEM " << demFile
                << " from the reference surface along its normal at x = "
                << x << ", y = " << y << " (world X = " << W[0] << ", Y = "
                << W[1] << ") was not found: the secant iteration did not"
                << " converge there" << nl << exit(FatalIOError);
        }
        const terrain::vec3 E = surface.world(x, y, zNoValue);
        if (dem.sampled(E[0], E[1]))
        {
            FatalIOErrorInFunction(dict)
                << "keyword 'dem': the normal from the reference surface at"
                << " x = " << x << ", y = " << y << " (world X = " << W[0]
                << ", Y = " << W[1] << ") meets a nodata hole of the DEM "
                << demFile << " at X = " << E[0] << ", Y = " << E[1]
                << " (" << zNoValue << " m along it) before it meets the"
                << " terrain: fill the DEM's nodata there" << nl
                << exit(FatalIOError);
        }
        // The normal runs along the axis in plan (N = (sin zeta t, cos
        // zeta)); the terrain's vertical distance from the reference
        // surface here and on the axis at this x
        const double gap = W[2] - dem.value(W[0], W[1]);
        const terrain::vec3 A = surface.world(x, 0, 0);
        const double gapAxis = A[2] - dem.value(A[0], A[1]);
        const double along =
            (E[0] - W[0])*surface.tX() + (E[1] - W[1])*surface.tY();
        const bool back = along < 0;
        // (both gaps finite: offset() and the axis' check sampled them);
        // in mm
        const auto mm = [](double v) { return std::round(1000*v)/1000; };
        std::ostringstream gapText;
        if (std::isfinite(gap))
        {
            gapText << "The terrain lies " << mm(std::fabs(gap)) << " m "
                << (mm(gap) >= 0 ? "below" : "above")
                << " the reference surface there (vertically";
            if (std::isfinite(gapAxis))
            {
                gapText << ", " << mm(std::fabs(gapAxis)) << " m "
                    << (mm(gapAxis) >= 0 ? "below" : "above")
                    << " it on the axis at this x";
            }
            gapText << "), and the";
        }
        else
        {
            gapText << "The";
        }
        FatalIOErrorInFunction(dict)
            << "keyword 'dem': the normal from the reference surface at"
            << " x = " << x << ", y = " << y << " (world X = " << W[0]
            << ", Y = " << W[1] << ") leaves the DEM " << demFile
            << " at X = " << E[0] << ", Y = " << E[1] << " (" << zNoValue
            << " m along it, " << std::fabs(along) << " m in plan towards"
            << " the axis' " << (back ? "first" : "last") << " point)"
            << " without meeting the terrain; "
            << valueExtent.str().c_str() << "." << nl
            << gapText.str().c_str()
            << " normal, along which zb is measured, runs along the axis in"
            << " plan.  A DEM reaching further beyond the axis' "
            << (back ? "first" : "last") << " point, an axis that "
            << (back ? "begins" : "ends") << " further inside the DEM, or"
            << " less departure of the terrain from the reference surface"
            << " there (a smaller halfWidth where it comes from the terrain"
            << " across the axis, a smaller profileSmoothing where it comes"
            << " from the profile along it) keep the normal on the DEM."
            << nl << exit(FatalIOError);
    };
    const label nCells = nx*ny;
    scalarField zb(nCells);
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const double x = (i + 0.5)*cellSize;
            const double y = -yMax + (j + 0.5)*cellSize;
            double zNoValue = 0;
            const double z = surface.offset(x, y, elevation, &zNoValue);
            if (!std::isfinite(z))
            {
                zbFailure(x, y, zNoValue);
            }
            zb[i + nx*j] = z;
        }
    }

    // Steepness of zb: the model's bed slope is zeta; zb's own slope is
    // taken as small (shallowness)
    scalar gradMax = 0;
    label cellMax = 0;
    label nSteep = 0;
    const scalar steep = 0.5;
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label c = i + nx*j;
            const label im = max(i - 1, label(0)), ip = min(i + 1, nx - 1);
            const label jm = max(j - 1, label(0)), jp = min(j + 1, ny - 1);
            const scalar gx = ip > im
              ? (zb[ip + nx*j] - zb[im + nx*j])/((ip - im)*cellSize) : 0;
            const scalar gy = jp > jm
              ? (zb[i + nx*jp] - zb[i + nx*jm])/((jp - jm)*cellSize) : 0;
            const scalar g = std::sqrt(gx*gx + gy*gy);
            nSteep += (g > steep);
            if (g > gradMax)
            {
                gradMax = g;
                cellMax = c;
            }
        }
    }
    {
        const double x = (cellMax % nx + 0.5)*cellSize;
        const double y = -yMax + (cellMax/nx + 0.5)*cellSize;
        const terrain::vec3 W = surface.world(x, y, zb[cellMax]);
        Info<< "zb in [" << gMin(zb) << ", " << gMax(zb) << "] m; largest"
            << " |grad zb| " << gradMax << " (" << radToDeg(std::atan(gradMax))
            << " deg) at x = " << x << ", y = " << y << " (X = " << W[0]
            << ", Y = " << W[1] << ", Z = " << W[2] << ")" << nl;
        if (nSteep)
        {
            WarningInFunction
                << nSteep << " of " << nCells << " cells have |grad zb| > "
                << steep << " (" << radToDeg(std::atan(steep)) << " deg),"
                << " the largest " << gradMax << " ("
                << radToDeg(std::atan(gradMax)) << " deg) at x = " << x
                << ", y = " << y << " (X = " << W[0] << ", Y = " << W[1]
                << "): there the terrain departs from the reference surface"
                << " more steeply than the shallow-flow model assumes"
                << " (a straighter axis, more profileSmoothing or a smaller"
                << " halfWidth help)" << nl << endl;
        }
    }

    // -- Releases -----------------------------------------------------------
    if (!dict.isDict("release") || dict.subDict("release").empty())
    {
        FatalIOErrorInFunction(dict)
            << "keyword 'release': a dictionary of one or more release"
            << " entries { polygon ((X Y) ...); thickness 1;"
            << " thicknessDirection normal; } expected" << nl
            << exit(FatalIOError);
    }
    const dictionary& releaseDict = dict.subDict("release");
    std::vector<release> releases;
    for (const entry& e : releaseDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(releaseDict)
                << "keyword 'release': entry '" << e.keyword()
                << "' is not a dictionary { polygon ...; thickness ...; }"
                << nl << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        checkKeywords(d, releaseKeywords, "release " + e.keyword());
        release r;
        r.name = e.keyword();
        r.dict = &d;
        wordList shapes;
        for (const word& key : {"polygon", "file", "raster"})
        {
            if (d.found(key))
            {
                shapes.append(key);
            }
        }
        if (shapes.size() != 1)
        {
            std::string given = shapes.empty() ? " none" : " several:";
            for (const word& key : shapes)
            {
                given += " '" + key + "'";
            }
            FatalIOErrorInFunction(d)
                << "release " << r.name << ": give one of 'polygon' ((X Y)"
                << " ...), 'file' (a shapefile) or 'raster' (a thickness"
                << " raster), not" << given.c_str() << nl
                << exit(FatalIOError);
        }
        r.shapeKey = shapes[0];
        if (r.shapeKey == "polygon")
        {
            const List<vector2D> pts = d.get<List<vector2D>>("polygon");
            if (pts.size() < 3)
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'polygon' of release " << r.name
                    << ": at least 3 vertices expected, got " << pts.size()
                    << nl << exit(FatalIOError);
            }
            terrain::Ring ring;
            for (const vector2D& p : pts)
            {
                ring.push_back({p.x(), p.y()});
            }
            r.polygons.push_back({ring});
        }
        else if (r.shapeKey == "file")
        {
            const fileName f = caseFile(runTime, d, "file");
            std::string wkt;
            try
            {
                r.polygons = terrain::readPolygons(f, wkt);
            }
            catch (const terrain::gdalError& err)
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'file' of release " << r.name << ": "
                    << err.what() << nl << exit(FatalIOError);
            }
            const auto tr = toDemSystem(wkt, dem.wkt, f, d, "file", r.name);
            try
            {
                for (terrain::Polygon& poly : r.polygons)
                {
                    for (terrain::Ring& ring : poly)
                    {
                        tr->apply(ring);
                    }
                }
            }
            catch (const terrain::gdalError& err)
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'file' of release " << r.name << ": "
                    << err.what() << nl << exit(FatalIOError);
            }
        }
        else
        {
            try
            {
                terrain::rasterDriver(d.get<fileName>("raster"));
            }
            catch (const terrain::gdalError& err)
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'raster' of release " << r.name << ": "
                    << err.what() << nl << exit(FatalIOError);
            }
            r.rasterFile = caseFile(runTime, d, "raster");
            try
            {
                r.raster = terrain::readRaster(r.rasterFile);
            }
            catch (const terrain::gdalError& err)
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'raster' of release " << r.name << ": "
                    << err.what() << nl << exit(FatalIOError);
            }
            checkThicknessRaster(r.raster, r.rasterFile, d, r.name);
            if (d.found("thickness"))
            {
                FatalIOErrorInFunction(d)
                    << "keyword 'thickness' of release " << r.name
                    << ": a release raster gives the thickness itself;"
                    << " remove 'thickness' (or scale the raster)" << nl
                    << exit(FatalIOError);
            }
            r.rasterToDem = toDemSystem
            (
                r.raster.wkt, dem.wkt, r.rasterFile, d, "raster", r.name
            );
        }
        if (r.shapeKey != "raster")
        {
            r.thickness = readPositive(d, "thickness");
        }
        const word dir = d.get<word>("thicknessDirection");
        if (dir != "normal" && dir != "vertical")
        {
            FatalIOErrorInFunction(d)
                << "keyword 'thicknessDirection' of release " << r.name
                << ": unknown '" << dir << "'. Valid choices: (normal"
                << " vertical)" << nl << exit(FatalIOError);
        }
        r.vertical = (dir == "vertical");
        releases.push_back(std::move(r));
    }

    // Cos of the DEM's slope at a cell's bed point (vertical thickness of
    // release r): central differences over a pixel, one-sided where one
    // side has no value (the DEM's edge, nodata); FatalIOError where
    // neither has
    const auto cosSlope = [&](label c, const release& r)
    {
        const double x = (c % nx + 0.5)*cellSize;
        const double y = -yMax + (c/nx + 0.5)*cellSize;
        const terrain::vec3 W = surface.world(x, y, zb[c]);
        const double d = pixel;
        const double Zc = dem.value(W[0], W[1]);
        const auto slope = [&](double dX, double dY)
        {
            const double zp = dem.value(W[0] + dX, W[1] + dY);
            const double zm = dem.value(W[0] - dX, W[1] - dY);
            if (std::isfinite(zp) && std::isfinite(zm))
            {
                return (zp - zm)/(2*d);
            }
            if (std::isfinite(zp) && std::isfinite(Zc))
            {
                return (zp - Zc)/d;
            }
            if (std::isfinite(zm) && std::isfinite(Zc))
            {
                return (Zc - zm)/d;
            }
            return std::numeric_limits<double>::quiet_NaN();
        };
        const double gx = slope(d, 0);
        const double gy = slope(0, d);
        if (!(std::isfinite(gx) && std::isfinite(gy)))
        {
            FatalIOErrorInFunction(*r.dict)
                << "keyword 'thicknessDirection' of release " << r.name
                << ": the DEM " << demFile << " has too few values around"
                << " the bed point (X = " << W[0] << ", Y = " << W[1]
                << ") of the mesh cell at x = " << x << ", y = " << y
                << " for its slope there (a pixel either side in X and in"
                << " Y: nodata or the DEM's edge), which a vertical"
                << " thickness needs; " << valueExtent.str().c_str() << nl
                << exit(FatalIOError);
        }
        return 1/std::sqrt(1 + gx*gx + gy*gy);
    };

    scalarField h(nCells, Zero);
    scalar releasedVolume = 0;
    const scalar cellArea = cellSize*cellSize;
    for (const release& r : releases)
    {
        scalarField frac(nCells, Zero);
        for (const terrain::Polygon& poly : r.polygons)
        {
            forAll(poly, ringi)
            {
                // Densified and mapped to (x, y): edges straight in plan
                // stay close to straight on the mesh
                const terrain::Ring& ring = poly[ringi];
                std::vector<terrain::point2> xy;
                const label n = label(ring.size());
                for (label k = 0; k < n; ++k)
                {
                    const auto& a = ring[k];
                    const auto& b = ring[(k + 1) % n];
                    const double len =
                        std::hypot(b[0] - a[0], b[1] - a[1]);
                    const label m =
                        max(label(1), label(std::ceil(4*len/cellSize)));
                    for (label s = 0; s < m; ++s)
                    {
                        const double f = double(s)/m;
                        const double X = a[0] + f*(b[0] - a[0]);
                        const double Y = a[1] + f*(b[1] - a[1]);
                        const double Z = dem.value(X, Y);
                        double x = 0, y = 0, z = 0;
                        const bool onDem = std::isfinite(Z);
                        const bool ok =
                            onDem && surface.local({X, Y, Z}, x, y, z);
                        if
                        (
                            !ok || x < -1e-9*xMax || x > xMax*(1 + 1e-9)
                         || std::fabs(y) > yMax*(1 + 1e-9)
                        )
                        {
                            std::ostringstream why;
                            if (!onDem)
                            {
                                why << (dem.sampled(X, Y)
                                    ? "over a nodata hole of the DEM \""
                                    : "outside the DEM \"")
                                    << demFile.c_str() << "\"; "
                                    << valueExtent.str();
                            }
                            else if (!ok)
                            {
                                why << "where its foot on the reference"
                                    << " surface was not found (the Newton"
                                    << " iteration did not converge)";
                            }
                            else
                            {
                                why << "(x = " << x << ", y = " << y
                                    << ") outside the mesh, x in [0, "
                                    << xMax << "], y in [" << -yMax << ", "
                                    << yMax << "]";
                            }
                            FatalIOErrorInFunction(*r.dict)
                                << "keyword '" << r.shapeKey
                                << "' of release " << r.name
                                << ": the release outline passes (X = "
                                << X << ", Y = " << Y << ") "
                                << why.str().c_str()
                                << nl << exit(FatalIOError);
                        }
                        xy.push_back({x, y});
                    }
                }
                const double sign = ringi == 0 ? 1 : -1;
                double bx0 = GREAT, bx1 = -GREAT, by0 = GREAT, by1 = -GREAT;
                for (const auto& p : xy)
                {
                    bx0 = std::min(bx0, p[0]);
                    bx1 = std::max(bx1, p[0]);
                    by0 = std::min(by0, p[1]);
                    by1 = std::max(by1, p[1]);
                }
                const label i0 = max(label(0), label(std::floor(bx0/cellSize)));
                const label i1 = min(nx - 1, label(std::floor(bx1/cellSize)));
                const label j0 =
                    max(label(0), label(std::floor((by0 + yMax)/cellSize)));
                const label j1 =
                    min(ny - 1, label(std::floor((by1 + yMax)/cellSize)));
                for (label j = j0; j <= j1; ++j)
                {
                    for (label i = i0; i <= i1; ++i)
                    {
                        const double a = terrain::clippedArea
                        (
                            xy, i*cellSize, (i + 1)*cellSize,
                            -yMax + j*cellSize, -yMax + (j + 1)*cellSize
                        );
                        frac[i + nx*j] += sign*a/cellArea;
                    }
                }
            }
        }
        // The thickness in each cell, normal or vertical as given
        scalarField d(nCells, Zero);
        forAll(frac, c)
        {
            // Overlapping polygons of one release count once
            d[c] = r.thickness*min(max(frac[c], scalar(0)), scalar(1));
        }
        terrain::rasterRelease mapped;
        if (r.shapeKey == "raster")
        {
            try
            {
                mapped = terrain::mapRasterRelease
                (
                    r.raster, *r.rasterToDem, dem, surface,
                    {nx, ny, cellSize, yMax}
                );
            }
            catch (const terrain::gdalError& err)
            {
                FatalIOErrorInFunction(*r.dict)
                    << "keyword 'raster' of release " << r.name << ": "
                    << err.what() << nl << exit(FatalIOError);
            }
            if (!mapped.nPixels)
            {
                FatalIOErrorInFunction(*r.dict)
                    << "keyword 'raster' of release " << r.name << ": "
                    << r.rasterFile << " holds no thickness > 0" << nl
                    << exit(FatalIOError);
            }
            forAll(d, c)
            {
                d[c] = mapped.h[c];
            }
        }
        scalar volume = 0;
        forAll(d, c)
        {
            if (d[c] > 0)
            {
                const scalar hc = d[c]*(r.vertical ? cosSlope(c, r) : 1);
                h[c] += hc;
                volume += hc*cellArea;
            }
        }
        if (!(volume > 0))
        {
            FatalIOErrorInFunction(*r.dict)
                << "keyword '" << r.shapeKey << "' of release " << r.name
                << ": the release "
                << (r.shapeKey == "raster" ? r.rasterFile + " " : "")
                << "covers no area of the mesh" << nl
                << exit(FatalIOError);
        }
        if (r.shapeKey == "raster")
        {
            Info<< "    raster " << r.rasterFile << ": " << mapped.nPixels
                << " pixels of thickness in [" << mapped.dMin << ", "
                << mapped.dMax << "] m, sum of thickness x pixel area in"
                << " the DEM's plan " << mapped.planVolume << " m^3; "
                << mapped.subdivisions << " x " << mapped.subdivisions
                << " sub-pixels" << nl;
            if (mapped.nOutside || mapped.nOffDem)
            {
                WarningInFunction
                    << "release " << r.name << ": " << mapped.nOutside
                    << " of the " << mapped.nPixels << " pixels of "
                    << r.rasterFile << " with thickness > 0 reach outside"
                    << " the mesh (" << mapped.outsideVolume << " m^3 of"
                    << " thickness x area there is dropped), "
                    << mapped.nOffDem << " reach off the DEM (dropped)"
                    << nl << endl;
            }
            Info<< "Release " << r.name << ": raster, thickness "
                << (r.vertical ? "vertical" : "normal") << ", volume "
                << volume << " m^3" << nl;
        }
        else
        {
            Info<< "Release " << r.name << ": " << r.polygons.size()
                << " polygon(s), thickness " << r.thickness << " m "
                << (r.vertical ? "vertical" : "normal") << ", volume "
                << volume << " m^3" << nl;
        }
        releasedVolume += volume;
    }
    Info<< "Released volume " << releasedVolume << " m^3" << nl << endl;

    // -- Everything checked: write ------------------------------------------
    const fileName tpFile = runTime.path()/"constant"/"transportProperties";
    if (!isFile(tpFile))
    {
        FatalIOErrorInFunction(dict)
            << "constant/transportProperties not found: terrainToCase sets"
            << " its 'inclination' entry and keeps the rest (g, phi,"
            << " frictionModel, ...), which must be there" << nl
            << exit(FatalIOError);
    }
    const std::string tpText = terrainFiles::readText(tpFile);

    std::vector<double> xMesh(xTable), zMesh(zetaDeg);
    terrainFiles::writeBlockMeshDict
    (
        runTime.path()/"system"/"blockMeshDict", nx, ny, xMax, yMax
    );
    terrainFiles::writeText
    (
        tpFile,
        terrainFiles::setInclination(tpText, xTable, zetaDeg, dict.name())
    );
    mkDir(runTime.path()/"0");
    terrainFiles::writeScalarField
    (
        runTime.path()/"0"/"zb", "zb", "[0 1 0 0 0 0 0]", zb, "zeroGradient"
    );
    terrainFiles::writeScalarField
    (
        runTime.path()/"0"/"h", "h", "[0 1 0 0 0 0 0]", h, "zeroGradient"
    );
    terrainFiles::writeVelocityField(runTime.path()/"0"/"U");

    terrainFiles::mapping m;
    m.dem = demName;
    m.axis[0] = {axis[0].x(), axis[0].y()};
    m.axis[1] = {axis[1].x(), axis[1].y()};
    m.origin = {P0.x(), P0.y(), Z0};
    m.tangent = {t.x(), t.y()};
    m.cellSize = cellSize;
    m.nx = nx;
    m.ny = ny;
    m.yMax = yMax;
    m.x = xTable;
    m.zetaDeg = zetaDeg;
    m.releasedVolume = releasedVolume;
    terrainFiles::writeMapping(runTime.path()/"constant"/"terrainMapping", m);

    Info<< "Wrote system/blockMeshDict, constant/transportProperties"
        << " (inclination), 0/zb, 0/h, 0/U, constant/terrainMapping" << nl
        << "Next: blockMesh, then savageHutterFoam" << nl << nl
        << "End\n" << endl;
    return 0;
}

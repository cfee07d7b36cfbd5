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
        entrainment                           // optional: 0/hEntrainable
        {
            bed1
            {
                polygon     ((X Y) ...);      // or file, or raster
                thickness   0.5;              // [m] erodible thickness
                thicknessDirection vertical;  // normal | vertical
            }
        }
        resistance                            // optional: 0/cResistance
        {
            forest1
            {
                polygon     ((X Y) ...);      // or file, or raster
                cResistance 0.01;             // [1/m] drag c |u|^2
            }
        }

    entrainment and resistance (docs/design.md section 7) are read and
    mapped as release is (a polygon's value times the fraction of each
    cell it covers, a raster's area-weighted mean, the areas of one
    dictionary summed, the same refusals); the erodible thickness is
    normal to the bed like h (vertical: d cos(theta)), cResistance is
    mapped as given.

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
        0/hEntrainable, 0/cResistance
                                     where terrainDict has entrainment,
                                     resistance: as 0/h (zeroGradient
                                     patches); without the entry an
                                     existing file is left (a warning)
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

    Without axis (the plan mode, docs/design.md section 5b,
    docs/terrainMapping.md): the case on the DEM's own plan grid,

        dem             "constant/dem.tif";
        cellSize        10;                   // [m] square plan cells
        extent          ((X0 Y0) (X1 Y1));    // optional; default the DEM's
        release         { ... as above ... }

    x along the DEM's columns, y to the left of x (a north-up DEM: x east,
    y north), from the grid's lower-left corner; extent, a rectangle on the
    DEM's axes, is clipped to the DEM's outline (one wholly outside it is
    an error), the rows and columns along the edges whose cell centres lie
    where the DEM has no values (half a pixel along its outline) are left
    out, and nodata under a cell centre is an error with the count of such
    cells (an extent can leave them out).  halfWidth and profileSmoothing
    belong to the axis mode: an error without axis (as extent is with
    it).  Writes system/blockMeshDict (nx x ny cells, patches xMin, xMax,
    yMin, yMax open: zeroGradient h and U), 0/zb the DEM's elevation at
    the cell centres (bilinear), 0/h the releases' thickness normal to the
    bed (a vertical thickness d becomes d cos(theta), cos(theta) =
    1/sqrt(1 + |grad zb|^2) of zb's centred differences), 0/U zero,
    coordinates plan in constant/transportProperties (its inclination
    entry removed, the rest kept) and constant/terrainMapping with mode
    plan and the affine map X = origin + x xAxis + y yAxis.  The log:
    the grid, its extent, zb's and the slope's range, the released volume
    sum h J A (J = 1/cos(theta)).  planGrid and planRelease are its stages.

    Stage by stage, each in its own file: terrainInput (terrainDict's
    keywords, the axis and the mesh's size), terrainDem (the DEM),
    thalwegProfile (the profile along the axis, the inclination table and
    the mesh over it), bedElevation (zb and its steepness), releaseInput
    (the release, entrainment and resistance entries), releaseThickness
    (h, hEntrainable, cResistance) and caseFiles (writing).

Usage
    terrainToCase [-dict file]

    then blockMesh and savageHutterFoam; hazardMaps afterwards.
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"

#include "terrainInput.H"
#include "terrainDem.H"
#include "thalwegProfile.H"
#include "bedElevation.H"
#include "releaseInput.H"
#include "releaseThickness.H"
#include "caseFiles.H"
#include "planRelease.H"
#include "defaultCaseFiles.H"

using namespace Foam;


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Make a savageHutterFoam case from a DEM and release areas in"
        " system/terrainDict: blockMeshDict, 0/zb, 0/h, 0/U,"
        " constant/terrainMapping, the inclination table or coordinates"
        " plan in constant/transportProperties, and, where the case has"
        " none, controlDict, fvSchemes, fvSolution and transportProperties"
        " with defaults.\n"
        "terrainDict keywords (a commented sample: etc/caseDicts/terrainDict;"
        " docs/userGuide.md):\n"
        "  dem               \"<file>.asc|.tif\"  vertical elevation [m]\n"
        "  cellSize          > 0 [m]  square cells\n"
        "  extent            ((X0 Y0) (X1 Y1))  plan mode, optional\n"
        "  axis              ((X0 Y0) (X1 Y1))  axis mode, top to bottom\n"
        "  halfWidth         > 0 [m]  axis mode\n"
        "  profileSmoothing  >= 0 [m]  axis mode\n"
        "  release           { <name> { ... } ... }, each entry with one of\n"
        "      polygon ((X Y) ...);  file \"<.shp>\";  raster \"<.asc|.tif>\";\n"
        "      thickness > 0 [m] (not with raster);\n"
        "      thicknessDirection vertical | normal;\n"
        "  entrainment       { <name> { ... } ... }  optional: 0/hEntrainable\n"
        "      entries as release's (the thickness erodible);\n"
        "  resistance        { <name> { ... } ... }  optional: 0/cResistance\n"
        "      polygon, file or raster;  cResistance > 0 [1/m] (not with"
        " raster);"
    );
    argList::addOption("dict", "file", "alternative dictionary");
    argList::noParallel();
    argList::noFunctionObjects();

    #include "setRootCase.H"

    // A case of terrainDict and constant/ inputs alone has no controlDict
    // yet: the Time is made of the default one, written with the case
    Info<< "Create time\n" << endl;
    autoPtr<Time> timePtr
    (
        isFile(args.path()/"system"/"controlDict")
      ? new Time(Time::controlDictName, args)
      : new Time(defaultControlDict(), args.rootPath(), args.caseName())
    );
    Time& runTime = timePtr();

    const fileName dictFile =
        args.getOrDefault<fileName>("dict", runTime.system()/"terrainDict");
    Info<< "Reading " << dictFile << nl << endl;
    const IOdictionary dict
    (
        IOobject(dictFile, runTime, IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    checkKeywords(dict, terrainKeywords, "terrainDict");

    // Each stage checks what it reads: nothing is written before the last
    const terrainDem dem = readDem(runTime, dict);
    if (!dict.found("axis"))
    {
        // The plan mode: the DEM's own plan grid
        const planGrid grid = readPlanGrid(dict, dem);
        const planBed bed = bedOnPlan(dict, dem, grid);
        const auto onPlan = [&](const word& kind)
        {
            return planReleaseThickness
            (
                readAreas(runTime, dict, dem, kind), dem, grid, bed
            );
        };
        caseLayers layers;
        layers.h = onPlan("release");
        layers.hEntrainable = onPlan("entrainment");
        layers.cResistance = onPlan("resistance");

        writePlanCaseFiles(runTime, dict, dem, grid, bed, layers);

        Info<< "End\n" << endl;
        return 0;
    }
    const chuteAxis axis = readAxis(dict);
    const thalwegProfile profile = readProfile(dict, dem, axis);
    const chuteGrid grid = gridOnProfile(dict, axis, profile);
    const scalarField zb = bedElevation(dict, dem, profile, grid);
    reportBedSlope(zb, profile, grid);
    const auto onMesh = [&](const word& kind)
    {
        return releaseThickness
        (
            readAreas(runTime, dict, dem, kind), dem, profile, grid, zb
        );
    };
    caseLayers layers;
    layers.h = onMesh("release");
    layers.hEntrainable = onMesh("entrainment");
    layers.cResistance = onMesh("resistance");

    writeCaseFiles(runTime, dict, dem, axis, profile, grid, zb, layers);

    Info<< "End\n" << endl;
    return 0;
}

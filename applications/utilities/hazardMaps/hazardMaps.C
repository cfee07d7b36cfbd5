/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    hazardMaps

Description
    Hazard maps of a terrain case (made by terrainToCase) on the DEM's grid
    and georeference, and a report of volumes, runout and travel angles.
    Run in the case directory after savageHutterFoam; reads
    constant/terrainMapping and, at each chosen time (default the latest),
    hMax, UMax, pMax, tArrival, h and zb (and erodedDepth and
    hEntrainable where written) as savageHutterFoam wrote them.
    pMax is the solver's field (rho |u|^2 peaked every step; written when
    constant/transportProperties has rho); without it, rho UMax^2 from the
    rho of transportProperties (the same to round-off: the peak of |u|^2
    is the square of the peak of |u|); with neither, no pMax map (the log
    says "pMax skipped: no rho in ... and no field pMax in <time>"), the
    others written.  A run of an older version without tArrival gets no
    arrival-time map (said so).

    Writes postProcessing/hazardMaps/<time>/ for each time:
        hMax, UMax, pMax, deposit (h at that time), tArrival
                        as .asc and .tif: each DEM pixel takes the value of
                        the mesh cell that holds the foot of its normal on
                        the reference surface; nodata (-9999) outside the
                        mesh and where hMax <= threshold (outside the
                        flow), in deposit where h <= threshold (the
                        deposit masked by itself), in tArrival where the
                        material never
                        arrived (-1: h never exceeded arrivalThreshold);
                        a rotated DEM's as .tif alone (ESRI ASCII grids are
                        north-up)
        erodedDepth, hEntrainable
                        where that time has them (a run with entrainment,
                        docs/design.md section 7): the thickness eroded so
                        far, nodata where it is 0, and the erodible layer
                        left, every cell of the mesh a value
        report.dat      lines "key value", each after its comment line
                        "# key [unit] meaning":
            releasedVolume  sum of h dA at the first time directory [m^3]
            entrainedVolume sum of erodedDepth dA at that time [m^3],
                            where the run has an erodible layer
                            (erodedDepth or hEntrainable at that time, or
                            hEntrainable at the first): 0 without
                            erodedDepth; no line without a layer
            depositVolume   sum of h dA at that time [m^3] (all the
                            material in the domain, moving or at rest:
                            the final flowing volume at the last time)
            runoutX/Y/Z     world position of the bed in the cell furthest
                            along the axis with hMax > threshold (of that
                            row of cells, the one with the largest hMax)
            travelAngle     [deg] atan(drop / horizontal distance) from the
                            highest released point to the runout point
            comTravelAngle  [deg] the same between the centres of mass of
                            the release and of the material at that time
            outflowVolume   releasedVolume + entrainedVolume -
                            depositVolume [m^3]
            reachesBoundary 1 if a cell of the mesh's outermost ring has
                            hMax > threshold (the flow reached the domain's
                            edge; the log warns), else 0
                            (runoutDefinition.H: shared with the ensemble's
                            report)
    Every chosen time is checked (hMax, UMax, h) before anything is
    written.  bin/plotHazardMaps draws the maps as a PNG.

    The plan mode (constant/terrainMapping with mode plan, made by
    terrainToCase without axis; transportProperties with coordinates plan):
    the rasters lie on the case's own plan grid, a pixel a cell, with the
    georeference of the mapping's origin, xAxis, yAxis and cellSize and the
    DEM's coordinate reference system (a grid rotated against north as .tif
    alone); hMax and deposit are the thickness h normal to the bed.  The
    report (planReport.H) holds the keys above, the volumes sums of J h A
    (J = sqrt(1 + |grad zb|^2); entrainedVolume of J erodedDepth A), the runout point the footprint's cell
    horizontally furthest from the highest released point, comTravelAngle
    measured along the centre of mass' path, and adds comPathLength.  A
    mapping of another mode, or a plan mapping without coordinates plan,
    is an error.

    -statistics: instead, the statistics of an ensemble (savageHutterFoam
    -ensemble, ensemble/statistics/<time>/: hMaxExceedance_<thr>,
    hMaxMean, hMaxP<p>, UMax..., pMax...) as rasters in
    postProcessing/hazardMaps/ensemble/<time>/, each pixel the value of its
    cell, nodata outside the mesh only (a probability of 0 is a value).
    The latest time of ensemble/statistics, or the one -time names.

    Stage by stage: hazardInput (the options, the times, the terrain
    mapping, rho, the checks), hazardRasters (pixels to cells, the maps,
    the ensemble's statistics), runoutReport (report.dat) and planReport
    (the plan mode's report.dat).

Usage
    hazardMaps [-time <ranges> | -latestTime] [-threshold 0.01]
        -time 10,20, -time '10:30' (OpenFOAM's time ranges; a single value
        picks the nearest time), -latestTime; default: the latest time
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"

#include "hazardInput.H"
#include "hazardRasters.H"
#include "runoutReport.H"
#include "planReport.H"

using namespace Foam;


int main(int argc, char *argv[])
{
    declareOptions();

    #include "setRootCase.H"
    #include "createTime.H"

    // Everything is read and checked before anything is written
    const scalar threshold = readThreshold(args);
    const bool statistics = args.found("statistics");
    const word statsTime = statistics ? statisticsTime(args) : word::null;
    const hazardTimes times = selectTimes(runTime, args, statistics);
    runTime.setTime(times.chosen.first(), 0);

    #include "createMesh.H"

    const hazardTerrain mapping = readTerrain(runTime, mesh);
    const densityInput density = readDensity(runTime);
    const volScalarField h0(fieldIO(mesh, times.first, "h"), mesh);
    checkTimes(mesh, times, h0, density, threshold, statistics);
    if (mapping.plan && !statistics)
    {
        checkComPath(mesh, times);
    }
    const labelList pixelCell = pixelCells(mesh, mapping);

    if (statistics)
    {
        writeStatistics(args, mesh, mapping.mapGrid(), pixelCell, statsTime);
    }
    else
    {
        for (const instant& ti : times.chosen)
        {
            const word now = ti.name();
            Info<< "Time " << now << nl;
            const hazardFields fields(mesh, now, times.first, density);
            const fileName outDir =
                runTime.path()/"postProcessing"/"hazardMaps"/now;
            writeMaps
            (
                outDir, fields, mapping.mapGrid(), pixelCell, threshold
            );
            if (mapping.plan)
            {
                writePlanReport
                (
                    outDir, ti, threshold, mapping, times, h0, fields
                );
            }
            else
            {
                writeReport(outDir, now, threshold, mapping, h0, fields);
            }
        }
    }
    Info<< "End\n" << endl;
    return 0;
}

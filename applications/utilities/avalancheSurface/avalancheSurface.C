/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    avalancheSurface

Description
    The results of a case as 3D surfaces for ParaView, at their world
    positions: the bed and the flow surface (the bed + h along the normal of
    the reference surface), one pair of VTK XML PolyData files per time and
    a .series file over the times, so that an avalanche is seen on its
    slope.  Run in the case directory after savageHutterFoam.

    The reference surface (applications/utilities/terrain/referenceSurface.H,
    the code terrainToCase and hazardMaps use):
      - with constant/terrainMapping (a terrain case): its origin, tangent
        and inclination table; positions in the DEM's world (X, Y, Z);
      - without it (the analytic cases): the inclination zeta(x) of
        constant/transportProperties, read as the solver reads it (a
        Function1: constant, table, ...), the profile (X(x), Z(x)) with
        dX/dx = cos zeta, dZ/dx = -sin zeta, X = Z = 0 at x = 0, y = Y.
        A table is taken point by point (integrated exactly on each of its
        segments); any other Function1 is sampled 8 times per cell along x
        and taken linear between the samples.
    The bed of a cell is its centre at offset zb along the normal (zb of
    that time when written there, else of the first time, else 0); the flow
    surface is at offset zb + h.

    The plan mode (constant/terrainMapping with mode plan, transportProperties
    with coordinates plan; planSurface.H): the bed of a cell is (X, Y, zb),
    X, Y its centre in the world by the mapping's origin and axes, and the
    flow surface bed + h n, n = (-grad zb, 1)/J the bed's unit normal (h is
    normal to the bed); U's x and y along the grid's axes in plan, its
    vertical component tangent to the bed.

    The points are the cell centres of the structured grid (nx x ny cells of
    one block: the surface stops half a cell inside the mesh's edges), the
    polygons quads between neighbouring centres (lines when the grid is one
    cell wide).  Point data: h, U (world components with terrainMapping or
    a curved reference surface: u_x along the profile's tangent, u_y across
    it), magU, zb, and where written hMax, UMax, pMax (or rho UMax^2 with
    rho in transportProperties) and tArrival.

    Writes postProcessing/avalancheSurface/:
        surface_<time>.vtp, bed_<time>.vtp
        surface.vtp.series, bed.vtp.series  (JSON, the .vtp files of every
                        time directory the case has, sorted by time)

    Every selected time is checked (h and U present) before anything is
    written.

    Stage by stage: surfaceInput (the options, the times, the structured
    grid, the reference surface or the plan grid, rho, the checks; with
    terrainCase of ../terrain, which hazardMaps shares), surfacePoints (a
    time's bed, flow surface and point data), planSurface (the same in the
    plan mode) and vtkPolyData (the .vtp and .series files).

Usage
    avalancheSurface [-time <ranges> | -latestTime | -noZero]
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"

#include "surfaceInput.H"
#include "surfacePoints.H"
#include "planSurface.H"
#include "vtkPolyData.H"

using namespace Foam;


int main(int argc, char *argv[])
{
    declareOptions();

    #include "setRootCase.H"
    #include "createTime.H"

    // Everything is read and checked before anything is written
    const surfaceTimes times = selectTimes(runTime, args);
    runTime.setTime(times.chosen.first(), 0);

    #include "createMesh.H"

    const structuredGrid grid = readGrid(mesh);
    const IOdictionary tp(transportPropertiesIO(runTime));
    const surfaceGeometry geometry = readGeometry(runTime, grid, tp);
    const scalar rho = readDensity(tp);
    checkTimes(mesh, times.chosen);
    const pointFrame frame =
        geometry.plan
      ? pointFrame()
      : pointFrames(mesh, grid, geometry.surface);

    const fileName outDir = runTime.path()/"postProcessing"/"avalancheSurface";
    mkDir(outDir);
    const word firstTime = times.numeric.first().name();
    for (const instant& t : times.chosen)
    {
        runTime.setTime(t, 0);
        if (geometry.plan)
        {
            writePlanTime
            (
                outDir, mesh, grid, geometry.grid, t.name(), firstTime, rho
            );
        }
        else
        {
            writeTime
            (
                outDir, mesh, grid, geometry.surface, frame, t.name(),
                firstTime, rho
            );
        }
    }

    writeSeries(outDir, "surface", times.numeric);
    writeSeries(outDir, "bed", times.numeric);
    Info<< nl << "End\n" << endl;
    return 0;
}

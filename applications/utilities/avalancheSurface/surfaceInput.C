/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "surfaceInput.H"
#include "timeSelector.H"
#include "IOdictionary.H"
#include "boundBox.H"
#include "Function1.H"
#include "TableBase.H"

#include <algorithm>
#include <cmath>

namespace Foam
{

namespace
{

//- Sorted distinct values of v (values closer than tol merged); index of
//  each value in the result
std::vector<double> distinct
(
    const std::vector<double>& v, double tol, std::vector<label>& index
)
{
    std::vector<double> s(v);
    std::sort(s.begin(), s.end());
    std::vector<double> u;
    for (const double a : s)
    {
        if (u.empty() || a - u.back() > tol)
        {
            u.push_back(a);
        }
    }
    index.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
    {
        auto it = std::lower_bound(u.begin(), u.end(), v[k] - tol);
        index[k] = label(it - u.begin());
    }
    return u;
}


//- The grid of constant/terrainMapping (mapDict) is the mesh's
void checkMappingGrid(const dictionary& mapDict, const structuredGrid& grid)
{
    const label mnx = mapDict.get<label>("nx");
    const label mny = mapDict.get<label>("ny");
    if (mnx != grid.nx || mny != grid.ny)
    {
        FatalIOErrorInFunction(mapDict)
            << "nx " << mnx << " x ny " << mny << " cells, but the mesh"
            << " has " << grid.nx << " x " << grid.ny
            << ": run blockMesh after terrainToCase" << nl
            << exit(FatalIOError);
    }
}


//- The geometry of constant/terrainMapping (mapDict; tp the
//  transportProperties a plan mapping needs), whose grid must be the
//  mesh's
surfaceGeometry mappedGeometry
(
    const dictionary& mapDict, const dictionary& tp,
    const structuredGrid& grid
)
{
    surfaceGeometry g;
    g.plan = planMode(mapDict, tp);
    if (g.plan)
    {
        g.grid = mappingPlan(mapDict);
    }
    else
    {
        g.surface = mappingSurface(mapDict);
    }
    checkMappingGrid(mapDict, grid);
    Info<< (g.plan ? "Plan grid" : "Reference surface")
        << ": constant/terrainMapping (world X, Y, Z)" << nl;
    return g;
}


//- The table (xT, zT) of the inclination zeta: a table's own points,
//  else samples, 8 per cell between the grid's edges
void inclinationTable
(
    const Function1<scalar>& zeta, const structuredGrid& grid,
    std::vector<double>& xT, std::vector<double>& zT
)
{
    const auto* table =
        dynamic_cast<const Function1Types::TableBase<scalar>*>(&zeta);
    if (table)
    {
        const scalarField tx(table->x());
        const scalarField tz(table->y());
        xT.assign(tx.begin(), tx.end());
        zT.assign(tz.begin(), tz.end());
        return;
    }
    const std::vector<double>& xs = grid.xs;
    const label nx = grid.nx;
    const double x0 = xs.front() - 0.5*(nx > 1 ? xs[1] - xs[0] : 1);
    const double x1 = xs.back() + 0.5*(nx > 1 ? xs[nx-1] - xs[nx-2] : 1);
    const label n = 8*nx;
    for (label k = 0; k <= n; ++k)
    {
        const double x = x0 + (x1 - x0)*k/n;
        xT.push_back(x);
        zT.push_back(zeta.value(x));
    }
}


//- The reference surface of the inclination of transportProperties (tp):
//  X = Y = Z = 0 at x = 0, y = 0, X along the profile
terrain::referenceSurface inclinationSurface
(
    const dictionary& tp, const structuredGrid& grid
)
{
    if (!tp.found("inclination"))
    {
        FatalIOErrorInFunction(tp)
            << "Missing keyword 'inclination' (and no"
            << " constant/terrainMapping): the angle zeta(x) [deg] of"
            << " the reference surface" << nl << exit(FatalIOError);
    }
    const autoPtr<Function1<scalar>> zeta =
        Function1<scalar>::New("inclination", tp);
    std::vector<double> xT, zT;
    inclinationTable(zeta(), grid, xT, zT);
    for (std::size_t k = 0; k < zT.size(); ++k)
    {
        if (!std::isfinite(zT[k]) || (k > 0 && !(xT[k] > xT[k-1])))
        {
            FatalIOErrorInFunction(tp)
                << "keyword 'inclination': zeta(" << xT[k] << ") = "
                << zT[k] << ": x must increase and zeta be finite" << nl
                << exit(FatalIOError);
        }
    }
    // World X = Y = Z = 0 at x = 0, y = 0
    const terrain::referenceSurface s0({0, 0, 0}, 1, 0, xT, zT);
    const terrain::vec3 w0 = s0.world(0, 0, 0);
    const terrain::referenceSurface surface
    (
        {-w0[0], -w0[1], -w0[2]}, 1, 0, xT, zT
    );
    Info<< "Reference surface: inclination " << zeta->type()
        << " of transportProperties (X along the profile, Y = y, Z up)"
        << nl;
    return surface;
}

} // End anonymous namespace


void declareOptions()
{
    argList::addNote
    (
        "The bed and the flow surface (bed + h along the normal) at their"
        " world positions as VTK PolyData (.vtp) per time, and .series"
        " files for ParaView"
    );
    timeSelector::addOptions(false, false);
    argList::noParallel();
    argList::noFunctionObjects();
}


surfaceTimes selectTimes(const Time& runTime, const argList& args)
{
    surfaceTimes times;
    times.numeric = numericTimes(runTime);
    times.chosen = selectedTimes(runTime, args, times.numeric);
    return times;
}


structuredGrid readGrid(const fvMesh& mesh)
{
    const volVectorField& C = mesh.C();
    std::vector<double> cx(C.size()), cy(C.size());
    forAll(C, c)
    {
        cx[c] = C[c].x();
        cy[c] = C[c].y();
    }
    const boundBox& bb = mesh.bounds();
    const double tol = 1e-9*(1 + mag(bb.max()) + mag(bb.min()));
    std::vector<label> ic, jc;
    structuredGrid grid;
    grid.xs = distinct(cx, tol, ic);
    grid.ys = distinct(cy, tol, jc);
    grid.nx = label(grid.xs.size());
    grid.ny = label(grid.ys.size());
    const label nx = grid.nx, ny = grid.ny;
    grid.pointCell = labelList(nx*ny, -1);
    forAll(C, c)
    {
        grid.pointCell[ic[c] + nx*jc[c]] = c;
    }
    if (nx*ny != mesh.nCells() || grid.pointCell.found(-1))
    {
        FatalErrorInFunction
            << "The mesh is not one structured block of nx x ny cells (its "
            << mesh.nCells() << " cell centres have " << nx
            << " distinct x and " << ny << " distinct y)" << nl
            << exit(FatalError);
    }
    return grid;
}


surfaceGeometry readGeometry
(
    const Time& runTime, const structuredGrid& grid, const dictionary& tp
)
{
    IOobject mapIO(terrainMappingIO(runTime));
    if (mapIO.typeHeaderOk<IOdictionary>(true))
    {
        const IOdictionary mapDict(mapIO);
        return mappedGeometry(mapDict, tp, grid);
    }
    surfaceGeometry g;
    g.surface = inclinationSurface(tp, grid);
    return g;
}


scalar readDensity(const dictionary& tp)
{
    scalar rho = -1;
    if (tp.found("rho"))
    {
        rho = tp.get<scalar>("rho");
        if (!(rho > 0) || !(rho < 1e30))
        {
            FatalIOErrorInFunction(tp)
                << "keyword 'rho' = " << rho << ": must be > 0" << nl
                << exit(FatalIOError);
        }
    }
    return rho;
}


void checkTimes(const fvMesh& mesh, const instantList& chosen)
{
    for (const instant& t : chosen)
    {
        if (!hasField<volScalarField>(mesh, t.name(), "h"))
        {
            FatalErrorInFunction
                << "No field h in " << mesh.time().path()/t.name() << nl
                << "The surface needs h and U at every time it converts;"
                << " a case that writes only some fields (writeFields in"
                << " system/controlDict) has them at its restart times:"
                << " choose those with -time <ranges> or -latestTime" << nl
                << exit(FatalError);
        }
        if (!hasField<volVectorField>(mesh, t.name(), "U"))
        {
            FatalErrorInFunction
                << "No field U in " << mesh.time().path()/t.name() << nl
                << "The surface needs h and U at every time it converts;"
                << " a case that writes only some fields (writeFields in"
                << " system/controlDict) has them at its restart times:"
                << " choose those with -time <ranges> or -latestTime" << nl
                << exit(FatalError);
        }
    }
}

} // End namespace Foam

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "surfacePoints.H"
#include "vtkPolyData.H"

#include <cmath>
#include <map>

namespace Foam
{

pointBed bedOffsets
(
    const fvMesh& mesh, const structuredGrid& grid, const word& now,
    const word& firstTime
)
{
    const label nP = grid.nx*grid.ny;
    pointBed bed{std::vector<double>(nP, 0), "0 (no zb)"};
    for (const word& inst : {now, firstTime})
    {
        if (hasField<volScalarField>(mesh, inst, "zb"))
        {
            const volScalarField f(fieldIO(mesh, inst, "zb"), mesh);
            for (label p = 0; p < nP; ++p)
            {
                bed.zb[p] = f[grid.pointCell[p]];
            }
            bed.from = "time " + inst;
            break;
        }
    }
    return bed;
}


std::map<word, std::vector<double>> peakMaps
(
    const fvMesh& mesh, const structuredGrid& grid, const word& now,
    scalar rho
)
{
    const label nP = grid.nx*grid.ny;
    std::map<word, std::vector<double>> extra;
    for (const word& name : {"hMax", "UMax", "pMax", "tArrival"})
    {
        if (hasField<volScalarField>(mesh, now, name))
        {
            const volScalarField f(fieldIO(mesh, now, name), mesh);
            std::vector<double>& v = extra[name];
            v.resize(nP);
            for (label p = 0; p < nP; ++p)
            {
                v[p] = f[grid.pointCell[p]];
            }
        }
    }
    if (!extra.count("pMax") && extra.count("UMax") && rho > 0)
    {
        std::vector<double>& v = extra["pMax"];
        for (const double u : extra["UMax"])
        {
            v.push_back(rho*u*u);
        }
    }
    return extra;
}


pointFrame pointFrames
(
    const fvMesh& mesh, const structuredGrid& grid,
    const terrain::referenceSurface& surface
)
{
    const volVectorField& C = mesh.C();
    const label nP = grid.nx*grid.ny;
    pointFrame frame;
    frame.T.resize(nP);
    frame.N2.resize(nP);
    for (label p = 0; p < nP; ++p)
    {
        double zeta, S, Z, b;
        surface.profile(C[grid.pointCell[p]].x(), zeta, S, Z, b);
        const double tX = surface.tX(), tY = surface.tY();
        frame.T[p] = {std::cos(zeta)*tX, std::cos(zeta)*tY, -std::sin(zeta)};
        frame.N2[p] = {-tY, tX, 0};
    }
    return frame;
}


void writeTime
(
    const fileName& outDir, const fvMesh& mesh, const structuredGrid& grid,
    const terrain::referenceSurface& surface, const pointFrame& frame,
    const word& now, const word& firstTime, scalar rho
)
{
    const volVectorField& C = mesh.C();
    const label nP = grid.nx*grid.ny;
    const volScalarField h(fieldIO(mesh, now, "h"), mesh);
    const volVectorField U(fieldIO(mesh, now, "U"), mesh);
    const pointBed offsets = bedOffsets(mesh, grid, now, firstTime);
    const std::vector<double>& zb = offsets.zb;

    timePoints tp(nP);
    for (label p = 0; p < nP; ++p)
    {
        const label c = grid.pointCell[p];
        tp.bed[p] = surface.world(C[c].x(), C[c].y(), zb[p]);
        tp.top[p] = surface.world(C[c].x(), C[c].y(), zb[p] + h[c]);
        for (int k = 0; k < 3; ++k)
        {
            tp.U[p][k] = U[c].x()*frame.T[p][k] + U[c].y()*frame.N2[p][k];
        }
    }
    writePoints(outDir, mesh, grid, now, rho, offsets, h, U, tp);
}


void writePoints
(
    const fileName& outDir, const fvMesh& mesh, const structuredGrid& grid,
    const word& now, scalar rho, const pointBed& offsets,
    const volScalarField& h, const volVectorField& U, const timePoints& tp
)
{
    const label nx = grid.nx, ny = grid.ny, nP = nx*ny;
    std::vector<double> hp(nP), magU(nP);
    for (label p = 0; p < nP; ++p)
    {
        const label c = grid.pointCell[p];
        hp[p] = h[c];
        magU[p] = mag(U[c]);
    }
    scalarPointData scalars{{"h", &hp}, {"magU", &magU}, {"zb", &offsets.zb}};
    const std::map<word, std::vector<double>> extra =
        peakMaps(mesh, grid, now, rho);
    for (const auto& e : extra)
    {
        scalars.push_back({e.first, &e.second});
    }
    const vectorPointData vectors{{"U", &tp.U}};

    writeVtp(outDir/("surface_" + now + ".vtp"), nx, ny, tp.top, scalars,
        vectors);
    writeVtp(outDir/("bed_" + now + ".vtp"), nx, ny, tp.bed, scalars,
        vectors);
    Info<< "Time " << now << ": " << nx << " x " << ny << " points,"
        << " zb of " << offsets.from << ", h max " << gMax(h) << ", data";
    for (const auto& s : scalars)
    {
        Info<< ' ' << s.first;
    }
    Info<< " U" << nl;
}

} // End namespace Foam

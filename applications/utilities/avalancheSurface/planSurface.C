/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "planSurface.H"
#include "zbGradient.H"

#include <cmath>

namespace Foam
{

void writePlanTime
(
    const fileName& outDir, const fvMesh& mesh, const structuredGrid& grid,
    const planGrid& plan, const word& now, const word& firstTime,
    scalar rho
)
{
    const volVectorField& C = mesh.C();
    const label nx = grid.nx, ny = grid.ny;
    const volScalarField h(fieldIO(mesh, now, "h"), mesh);
    const volVectorField U(fieldIO(mesh, now, "U"), mesh);
    const pointBed offsets = bedOffsets(mesh, grid, now, firstTime);
    scalarField zb(label(offsets.zb.size()));
    forAll(zb, p)
    {
        zb[p] = offsets.zb[p];
    }
    const std::array<double, 2>& ax = plan.xAxis;
    const std::array<double, 2>& ay = plan.yAxis;

    timePoints tp(nx*ny);
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label p = i + nx*j, c = grid.pointCell[p];
            const vector2D G = zbGradient(zb, nx, ny, plan.cellSize, i, j);
            const double J = std::sqrt(1 + G.x()*G.x() + G.y()*G.y());
            const std::array<double, 2> W = plan.world(C[c].x(), C[c].y());
            // n = (-grad zb, 1)/J, its plan part along x and y turned to
            // the world's directions
            const terrain::vec3 n
            {
                -(G.x()*ax[0] + G.y()*ay[0])/J,
                -(G.x()*ax[1] + G.y()*ay[1])/J,
                1/J
            };
            tp.bed[p] = {W[0], W[1], zb[p]};
            for (int k = 0; k < 3; ++k)
            {
                tp.top[p][k] = tp.bed[p][k] + h[c]*n[k];
            }
            const scalar ux = U[c].x(), uy = U[c].y();
            tp.U[p] =
            {
                ux*ax[0] + uy*ay[0], ux*ax[1] + uy*ay[1],
                G.x()*ux + G.y()*uy
            };
        }
    }
    writePoints(outDir, mesh, grid, now, rho, offsets, h, U, tp);
}

} // End namespace Foam

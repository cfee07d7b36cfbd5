/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    Compiles every pointwise stage of physics/scheme.H as device code, for
    float and double.  Built whenever nvcc is present, so a change to the
    physics that nvcc cannot compile fails the build on any machine, with or
    without a GPU.
\*---------------------------------------------------------------------------*/

#include "physics/scheme.H"

namespace sh
{

template<class Real>
__global__ void allStagesKernel
(
    Model<Real> m,
    Fields<Real> U,
    Fields<Real> Uh,
    FaceFields<Real> Fx,
    FaceFields<Real> Fy,
    Real* theta,
    Fields<Real> Unew,
    Real dt,
    Real* rate
)
{
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    const int j = blockIdx.y*blockDim.y + threadIdx.y;
    if (i >= m.g.nx || j >= m.g.ny)
    {
        return;
    }
    fillGhostCell(m, U, xMin, -1, j);
    predictorCell(m, U, Uh, dt, i, j);
    // Not a solver: every stage once, so that each is compiled
    const FaceFlux<Real> fx = fluxX(m, Uh, i, j);
    const FaceFlux<Real> fy = fluxY(m, Uh, i, j);
    Fx.bedLow[m.g.idx(i, j)] = fx.bedLow;
    Fx.bedHigh[m.g.idx(i, j)] = fx.bedHigh;
    Fy.bedLow[m.g.idx(i, j)] = fy.bedLow;
    Fy.bedHigh[m.g.idx(i, j)] = fy.bedHigh;
    theta[m.g.idx(i, j)] = drainFactor(m, U, Fx, Fy, dt, i, j);
    correctorCell(m, U, Uh, Fx, Fy, theta, Unew, dt, i, j);
    partialWetCell(m, Unew, i, j);
    rate[m.g.idx(i, j)] = cellWaveRate(m, U, i, j);
    if (i == 0 && j == 0)
    {
        rate[0] += activePassiveCoeffs<Real>(Real(0.6), Real(0.4)).kxMax
                 + isotropicCoeffs<Real>().kyMax;
    }
}

template __global__ void allStagesKernel<double>
(
    Model<double>, Fields<double>, Fields<double>, FaceFields<double>,
    FaceFields<double>, double*, Fields<double>, double, double*
);
template __global__ void allStagesKernel<float>
(
    Model<float>, Fields<float>, Fields<float>, FaceFields<float>,
    FaceFields<float>, float*, Fields<float>, float, float*
);

} // namespace sh

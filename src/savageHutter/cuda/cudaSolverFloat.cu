/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The CUDA backend in single precision (kernels and driver in
    cudaSolverImpl.H, the ensembles' driver in cudaEnsembleImpl.H, the
    same code as in double).

    Compiled apart from double so that it can take other flags without
    changing a bit of the double backend.  By default it is IEEE-rounded
    and bit-identical to the CPU's float run, as double is.
    SH_CUDA_FLOAT_APPROX=ON (CMakeLists.txt) gives it the hardware's
    approximate division and square root (-prec-div=false
    -prec-sqrt=false): an IEEE-rounded float division is a multi-
    instruction sequence with a slow-path branch, an approximate one a
    reciprocal and a multiplication.  The float state then differs from
    the CPU's float state by round-off; tests/backends/gpuCompare.C states and
    checks the tolerance.  Since the kernels divide little (the
    reciprocals of dx and dy formed once, one reciprocal of h per cell and
    stage) the approximate build gains little (docs/performance.md).
\*---------------------------------------------------------------------------*/

#include "cudaEnsembleImpl.H"

namespace sh
{

bool cudaFloatApproximate()
{
#ifdef SH_CUDA_APPROX_DIV_SQRT
    return true;
#else
    return false;
#endif
}

template std::unique_ptr<Solver<float>> makeCudaSolver
(
    const Problem<float>&, Halo<float>*
);
template std::unique_ptr<EnsembleSolver<float>> makeCudaEnsemble
(
    const std::vector<Problem<float>>&
);

} // namespace sh

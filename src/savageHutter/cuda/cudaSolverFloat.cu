/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The CUDA backend in single precision (kernels and driver in
    cudaSolverImpl.H, the same code as in double).

    Compiled apart from double so that it can take the hardware's
    approximate division and square root (-prec-div=false -prec-sqrt=false,
    CMakeLists.txt) without changing a bit of the double backend: the step
    is bound by instruction issue, and an IEEE-rounded float division is a
    multi-instruction sequence with a slow-path branch, an approximate one
    a reciprocal and a multiplication (docs/performance.md).  The float
    state then differs from the CPU's float state by round-off;
    tests/gpuCompare.C states and checks the tolerance.  SH_CUDA_FLOAT_IEEE=ON
    compiles it with IEEE-rounded division and square root instead, and it
    is then bit-identical to the CPU as double is.
\*---------------------------------------------------------------------------*/

#include "cudaSolverImpl.H"

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

template std::unique_ptr<Solver<float>> makeCudaSolver(const Problem<float>&);

} // namespace sh

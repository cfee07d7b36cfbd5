/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The CUDA backend in double precision (kernels and driver in
    cudaSolverImpl.H), and cudaAvailable().

    Compiled with IEEE correctly rounded division and square root (nvcc's
    default) and --fmad=false (CMakeLists.txt), like the CPU backend, so
    that the two give bit-identical states (tests/gpuCompare.C).
\*---------------------------------------------------------------------------*/

#include "cudaSolverImpl.H"

namespace sh
{

bool cudaAvailable(std::string* why)
{
    int n = 0;
    const cudaError_t e = cudaGetDeviceCount(&n);
    if (e != cudaSuccess || n == 0)
    {
        if (why)
        {
            *why = e != cudaSuccess
                ? std::string("no usable CUDA device: ") + cudaGetErrorName(e)
                  + " (" + cudaGetErrorString(e) + ")"
                : std::string("no CUDA device found");
        }
        cudaGetLastError();
        return false;
    }
    // A kernel image for this device (the build's architectures)
    cudaFuncAttributes attr;
    const cudaError_t k = cudaFuncGetAttributes(&attr, rateKernel<double>);
    if (k != cudaSuccess)
    {
        if (why)
        {
            *why = std::string("the CUDA build has no kernels for this "
                "device: ") + cudaGetErrorName(k) + " ("
              + cudaGetErrorString(k) + ")";
        }
        cudaGetLastError();
        return false;
    }
    return true;
}

template std::unique_ptr<Solver<double>> makeCudaSolver(const Problem<double>&);

} // namespace sh

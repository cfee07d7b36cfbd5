/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The CUDA backend in double precision (kernels and driver in
    cudaSolverImpl.H, the ensembles' driver in cudaEnsembleImpl.H),
    cudaAvailable() and cudaMemoryInfo().

    Compiled with IEEE correctly rounded division and square root (nvcc's
    default) and --fmad=false (CMakeLists.txt), like the CPU backend, so
    that the two give bit-identical states (tests/backends/gpuCompare.C).
\*---------------------------------------------------------------------------*/

#include "cudaEnsembleImpl.H"

namespace sh
{

std::string cudaDeviceDescription(int* fp32PerFp64)
{
    int dev = 0;
    cudaDeviceProp p;
    if
    (
        cudaGetDevice(&dev) != cudaSuccess
     || cudaGetDeviceProperties(&p, dev) != cudaSuccess
    )
    {
        cudaGetLastError();
        return std::string();
    }
    int ratio = 0;
    if
    (
        cudaDeviceGetAttribute
        (
            &ratio, cudaDevAttrSingleToDoublePrecisionPerfRatio, dev
        ) != cudaSuccess
    )
    {
        cudaGetLastError();
        ratio = 0;
    }
    if (fp32PerFp64)
    {
        *fp32PerFp64 = ratio;
    }
    return std::string(p.name) + ", compute capability "
        + std::to_string(p.major) + "." + std::to_string(p.minor) + ", "
        + std::to_string((p.totalGlobalMem + (1u << 29))>>30) + " GiB"
        + (ratio > 0 ? ", FP32:FP64 " + std::to_string(ratio) + ":1" : "");
}


bool cudaMemoryInfo(std::size_t* freeBytes, std::size_t* totalBytes)
{
    std::size_t f = 0;
    std::size_t t = 0;
    if (cudaMemGetInfo(&f, &t) != cudaSuccess)
    {
        cudaGetLastError();
        return false;
    }
    *freeBytes = f;
    *totalBytes = t;
    return true;
}


int cudaDeviceCount()
{
    int n = 0;
    if (cudaGetDeviceCount(&n) != cudaSuccess)
    {
        cudaGetLastError();
        return 0;
    }
    return n;
}


void cudaSelectDevice(int device)
{
    SH_CUDA_CHECK(cudaSetDevice(device));
}


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

template std::unique_ptr<Solver<double>> makeCudaSolver
(
    const Problem<double>&, Halo<double>*
);
template std::unique_ptr<EnsembleSolver<double>> makeCudaEnsemble
(
    const std::vector<Problem<double>>&
);

} // namespace sh

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The CUDA entry points of a build without nvcc: no device can be used,
    and asking for the backend says so.
\*---------------------------------------------------------------------------*/

#include "cudaSolver.H"
#include "../ensemble/ensembleSolver.H"

#include <stdexcept>

namespace sh
{

namespace
{

const char* const notBuilt =
    "this build of savageHutter has no CUDA backend (it was configured "
    "with SH_CUDA=OFF or without nvcc; reconfigure with nvcc on the PATH "
    "or in /usr/local/cuda)";

} // namespace


bool cudaAvailable(std::string* why)
{
    if (why)
    {
        *why = notBuilt;
    }
    return false;
}


std::string cudaDeviceDescription(int*)
{
    return std::string();
}


bool cudaMemoryInfo(std::size_t*, std::size_t*)
{
    return false;
}


bool cudaFloatApproximate()
{
    return false;
}


int cudaDeviceCount()
{
    return 0;
}


void cudaSelectDevice(int)
{
    throw std::runtime_error(std::string("CUDA backend: ") + notBuilt);
}


template<class Real>
std::unique_ptr<Solver<Real>> makeCudaSolver(const Problem<Real>&, Halo<Real>*)
{
    throw std::runtime_error(std::string("CUDA backend: ") + notBuilt);
}

template std::unique_ptr<Solver<double>> makeCudaSolver
(
    const Problem<double>&, Halo<double>*
);
template std::unique_ptr<Solver<float>> makeCudaSolver
(
    const Problem<float>&, Halo<float>*
);


template<class Real>
std::unique_ptr<EnsembleSolver<Real>> makeCudaEnsemble
(
    const std::vector<Problem<Real>>&
)
{
    throw std::runtime_error(std::string("CUDA backend: ") + notBuilt);
}

template std::unique_ptr<EnsembleSolver<double>> makeCudaEnsemble
(
    const std::vector<Problem<double>>&
);
template std::unique_ptr<EnsembleSolver<float>> makeCudaEnsemble
(
    const std::vector<Problem<float>>&
);

} // namespace sh

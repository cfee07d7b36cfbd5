/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "backendSelection.H"
#include "anyProcessor.H"
#include "cpu/cpuSolver.H"
#include "cuda/cudaSolver.H"
#ifdef SH_HAVE_MPI
#include "parallel/mpiHalo.H"
#endif

namespace Foam
{

template<class Real>
std::unique_ptr<sh::Halo<Real>> makeHalo(const structuredMesh& smesh)
{
    if (!Pstream::parRun())
    {
        return nullptr;
    }
    #ifdef SH_HAVE_MPI
    try
    {
        return std::unique_ptr<sh::Halo<Real>>
        (
            new sh::MpiHalo<Real>(MPI_COMM_WORLD, smesh.subdomain())
        );
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "The decomposition cannot run: " << e.what() << nl
            << smesh.refusedSplit().c_str() << exit(FatalError);
    }
    #else
    (void)smesh;
    #endif
    return nullptr;
}


int nodeLocalRank()
{
    int local = 0;
    #ifdef SH_HAVE_MPI
    if (Pstream::parRun())
    {
        MPI_Comm node;
        if
        (
            MPI_Comm_split_type
            (
                MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL,
                &node
            ) != MPI_SUCCESS
         || MPI_Comm_rank(node, &local) != MPI_SUCCESS
         || MPI_Comm_free(&node) != MPI_SUCCESS
        )
        {
            FatalErrorInFunction
                << "MPI_Comm_split_type (the processors of this node)"
                << " failed" << nl << exit(FatalError);
        }
    }
    #endif
    return local;
}


template<class Real>
bool useCudaBackend(const word& backend, const bool decomposed, std::string& why)
{
    // Decomposed: a GPU per processor, by its rank on the node (the
    // collective call made by every processor alike)
    const int local = nodeLocalRank();
    const int devices = sh::cudaDeviceCount();
    if (devices > 0 && backend != "cpu")
    {
        try
        {
            sh::cudaSelectDevice(local % devices);
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "-backend " << backend << ": " << e.what() << nl
                << exit(FatalError);
        }
    }
    // auto: the GPU when every processor has one (they must all take
    // the same backend: the two exchange in different orders)
    bool useCuda = backend == "cuda";
    if (backend == "auto")
    {
        const bool here = sh::cudaAvailable(&why);
        useCuda = !anyProcessor(!here);
        if (here && !useCuda)
        {
            why = "not every processor has a usable GPU";
        }
    }
    if (useCuda)
    {
        int fp32PerFp64 = 0;
        const std::string gpu = sh::cudaDeviceDescription(&fp32PerFp64);
        if (!gpu.empty())
        {
            Info<< "GPU: " << gpu.c_str();
            if (decomposed)
            {
                Info<< " (processor 0; each processor the GPU of its rank"
                    << " on the node mod " << devices << ")";
            }
            // Flushed: a log watched during start-up sees it
            Info<< endl;
            if (sizeof(Real) == 8 && fp32PerFp64 >= 16)
            {
                Info<< "    This GPU computes in double precision at 1/"
                    << fp32PerFp64 << " of its single-precision rate:"
                    << " -precision single runs many times faster" << nl;
            }
        }
    }
    else if (backend == "auto")
    {
        Info<< "No usable GPU (" << why.c_str() << "): running on the CPU"
            << nl;
    }
    return useCuda;
}


template<class Real>
std::unique_ptr<sh::Solver<Real>> selectBackend
(
    const word& backend,
    const sh::Problem<Real>& pb,
    sh::Halo<Real>* halo
)
{
    std::string why;
    if (useCudaBackend<Real>(backend, halo != nullptr, why))
    {
        try
        {
            return sh::makeCudaSolver<Real>(pb, halo);
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "-backend " << backend << ": the CUDA backend cannot run"
                << " here: " << e.what() << nl
                << "Use -backend cpu." << nl << exit(FatalError);
        }
    }
    return std::unique_ptr<sh::Solver<Real>>
    (
        new sh::CpuSolver<Real>(pb, true, halo)
    );
}


template<class Real>
std::unique_ptr<sh::EnsembleSolver<Real>> selectEnsembleBackend
(
    const word& backend,
    const std::vector<sh::Problem<Real>>& members
)
{
    std::string why;
    // Slope and plan coordinates alike: the batched CUDA backend steps
    // both (cudaEnsembleImpl.H, the kernels of the case's stages)
    const bool useCuda = useCudaBackend<Real>(backend, false, why);
    try
    {
        return useCuda
          ? sh::makeCudaEnsemble<Real>(members)
          : sh::makeCpuEnsemble<Real>(members);
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "-backend " << backend << ": " << e.what() << nl
            << (useCuda ? "Use -backend cpu.\n" : "") << exit(FatalError);
    }
    return nullptr;
}


#define makeBackendSelection(Real)                                            \
    template std::unique_ptr<sh::Halo<Real>> makeHalo<Real>                   \
    (                                                                         \
        const structuredMesh&                                                 \
    );                                                                        \
    template bool useCudaBackend<Real>(const word&, bool, std::string&);      \
    template std::unique_ptr<sh::Solver<Real>> selectBackend<Real>            \
    (                                                                         \
        const word&, const sh::Problem<Real>&, sh::Halo<Real>*                \
    );                                                                        \
    template std::unique_ptr<sh::EnsembleSolver<Real>>                        \
    selectEnsembleBackend<Real>                                               \
    (                                                                         \
        const word&, const std::vector<sh::Problem<Real>>&                    \
    );

makeBackendSelection(float)
makeBackendSelection(double)

} // End namespace Foam

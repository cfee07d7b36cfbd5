/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    CUDA backend: the stages of physics/scheme.H run over the grid by
    kernels, one thread per cell (or face), on structure-of-arrays device
    arrays with the padded layout of physics/grid.H.

    One time step is five kernels; each boundary between them is a data
    dependency on neighbouring cells that another block writes:
      1. predictor      eq. (14) -> U^{n+1/2}, and its ghost cells; reads
                        the step's dt off the device (below)
      2. face fluxes    MUSCL + HLLC of every face, one thread per face,
                        stored once per face
      3. drain factor   theta of each cell from its four faces' mass flux
      4. corrector      eq. (17) with sources, (26) and (27) -> U^{n+1}
      5. finish         partial-wet cells (29), ghost cells of U^{n+1}, the
                        wave rate of eq. (24) for the next step (block max,
                        then one atomicMax per block), the clock
    The thread that finishes a cell writes the ghost cells that mirror it
    (calling fillGhostCell in the order the CPU fills sides), so no
    separate ghost launches are needed.

    Fluxes are stored, not recomputed per cell: theta of a cell needs all
    four of its faces, and the corrector needs theta of its neighbours, so
    recomputing would cost four flux evaluations per face instead of one,
    and the flux is already most of the work (docs/performance.md has the
    profiler's figures).

    Empty regions: a tile of cells whose neighbourhood holds no material
    now and held none in the state the step overwrites is skipped by every
    kernel (the arrays already hold what the stages would write), and a
    face with no material on its stencil gets its exact zero flux without
    the HLLC solver (decideSkip, emptyFace).  An avalanche covers a few
    per cent of its domain for much of its run.

    Time step on the device: kernel 5 of step n leaves max(rate) of U^{n+1}
    in one of two slots (by step parity); kernel 1 of step n+1 turns it into
    dt with exactly the arithmetic of Solver::advance (dt = min(cfl/rate,
    maxDt), dt = tEnd - t on the step that would pass tEnd, t = tEnd after
    it), block (0, 0) stores dt for kernels 2-5, and kernel 5 advances the
    clock, kept in double.  A step that finds t >= tEnd does nothing, so a
    CUDA graph of a fixed number of steps can overrun tEnd harmlessly.  The
    host only synchronises between graph launches, to see whether tEnd or
    its wall-time budget is reached.

    Round-off: every stage runs the same function on the same inputs in the
    same order as the CPU backend, divisions and square roots are IEEE
    correctly rounded on both sides, and this file is compiled with
    --fmad=false (CMakeLists.txt) because the host compiler (x86-64, no
    -mfma) contracts no a*b + c either (measured on an H100: no loss of
    speed).  Reductions are maxima, which do not depend on order.  So the
    GPU state is bit-identical to the CPU state in double and in float
    (tests/gpuCompare.C checks it).
\*---------------------------------------------------------------------------*/

#include "cudaSolver.H"
#include "../physics/scheme.H"

#include <cuda_runtime.h>

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

//- Check a CUDA runtime call; throws std::runtime_error naming the call,
//  the file and the line
#define SH_CUDA_CHECK(call) ::sh::cudaCheck((call), #call, __FILE__, __LINE__)

//- Check a kernel launch (configuration errors; faults surface at the next
//  synchronising call)
#define SH_CUDA_CHECK_LAUNCH(name) \
    ::sh::cudaCheck(cudaGetLastError(), name, __FILE__, __LINE__)

namespace sh
{

void cudaCheck(cudaError_t e, const char* what, const char* file, int line)
{
    if (e != cudaSuccess)
    {
        throw std::runtime_error
        (
            std::string("CUDA error at ") + file + ":" + std::to_string(line)
          + ": " + what + ": " + cudaGetErrorName(e) + " ("
          + cudaGetErrorString(e) + ")"
        );
    }
}

namespace
{

// * * * * * * * * * * * * * * Device helpers  * * * * * * * * * * * * * * //

//- Unsigned integer of the width of Real.  For non-negative reals the
//  order of the bit patterns is the order of the values, so a max of rates
//  is an integer atomicMax.
template<class Real> struct Bits;

template<>
struct Bits<double>
{
    using type = unsigned long long;
    static __host__ __device__ type of(double x)
    {
#ifdef __CUDA_ARCH__
        return __double_as_longlong(x);
#else
        type b;
        std::memcpy(&b, &x, sizeof b);
        return b;
#endif
    }
    static __host__ __device__ double real(type b)
    {
#ifdef __CUDA_ARCH__
        return __longlong_as_double(b);
#else
        double x;
        std::memcpy(&x, &b, sizeof x);
        return x;
#endif
    }
    static __host__ __device__ double maxValue() { return DBL_MAX; }
};

template<>
struct Bits<float>
{
    using type = unsigned int;
    static __host__ __device__ type of(float x)
    {
#ifdef __CUDA_ARCH__
        return __float_as_uint(x);
#else
        type b;
        std::memcpy(&b, &x, sizeof b);
        return b;
#endif
    }
    static __host__ __device__ float real(type b)
    {
#ifdef __CUDA_ARCH__
        return __uint_as_float(b);
#else
        float x;
        std::memcpy(&x, &b, sizeof x);
        return x;
#endif
    }
    static __host__ __device__ float maxValue() { return FLT_MAX; }
};


//- The clock and the time step, in device memory
template<class Real>
struct StepControl
{
    using B = typename Bits<Real>::type;

    double t;           //!< time, advanced by kernel 5
    double tEnd;        //!< end of the current advance()
    double maxDt;       //!< Solver::maxDt_
    double dt;          //!< this step's dt (before rounding to Real)
    double lastDt;
    long long steps;
    int active;         //!< whether this step runs (t < tEnd)
    int last;           //!< whether this step ends at tEnd
    int stateBuf;       //!< state buffer the last active step wrote
    B rate[2];          //!< max wave rate, eq. (24), by step parity
    B inflowRate;       //!< the inflow sides' rate, where each max starts
};


//- Threads of a block, cells of a tile (SH_BLOCK_X/Y: for measurements).
//  32 x 8 against 32 x 4: +13 % (double) and +35 % (float) on the 8.7M-cell
//  inclined plane, where tiles are skipped, -1 % on a wet flow
#ifndef SH_BLOCK_X
#   define SH_BLOCK_X 32
#endif
#ifndef SH_BLOCK_Y
#   define SH_BLOCK_Y 8
#endif
constexpr int blockX = SH_BLOCK_X;
constexpr int blockY = SH_BLOCK_Y;

__device__ inline bool firstThread()
{
    return blockIdx.x == 0 && blockIdx.y == 0
        && threadIdx.x == 0 && threadIdx.y == 0;
}

//- atomicMax of the block's largest v into target; every thread of the
//  block must call it
template<class B>
__device__ void blockMax(B v, B* target)
{
    for (int o = 16; o > 0; o >>= 1)
    {
        const B w = __shfl_down_sync(0xffffffffu, v, o);
        v = w > v ? w : v;
    }
    __shared__ B warpMax[32];
    const int tid = threadIdx.x + threadIdx.y*blockDim.x;
    const int nWarps = (blockDim.x*blockDim.y + 31)/32;
    if ((tid & 31) == 0)
    {
        warpMax[tid >> 5] = v;
    }
    __syncthreads();
    if (tid < 32)
    {
        v = tid < nWarps ? warpMax[tid] : B(0);
        for (int o = 16; o > 0; o >>= 1)
        {
            const B w = __shfl_down_sync(0xffffffffu, v, o);
            v = w > v ? w : v;
        }
        if (tid == 0)
        {
            atomicMax(target, v);
        }
    }
}

//- Empty tiles.  The grid of cells is cut into tiles of blockX x blockY
//  cells, one block of the cell kernels each.  A tile is occupied when a
//  cell of it has a non-zero bit in h, hu or hv.  In a step from state
//  buffer b to b^1, what the kernels write for a tile (U^{n+1/2}, its face
//  fluxes, theta, U^{n+1} and the ghost cells they mirror) depends on U^n
//  within 6 cells (predictor 1, MUSCL + HLLC 2, theta 1, the corrector's
//  neighbours' theta 1, partial-wet cells 1).  Where U^n is empty there,
//  every stage gives exactly its empty value: U^{n+1/2} = U^{n+1} = +0
//  (h = max(0, +0) and momenta set to 0), fluxes +0 (emptyFace), theta = 1.
//  If also U^{n-1}, the state in buffer b^1 that the step overwrites and
//  the input of the step that wrote the arrays, is empty there, all the
//  arrays already hold those values: the tile is skipped.  The bounds are
//  within dependenceRadius cells: skipTilesX, skipTilesY tiles.
constexpr int dependenceRadius = 6;
constexpr int skipTilesX = (dependenceRadius + blockX - 1)/blockX;
constexpr int skipTilesY = (dependenceRadius + blockY - 1)/blockY;

//- Whether a state has a non-zero bit (-0 counts as occupied)
template<class Real>
__host__ __device__ bool occupied(Real h, Real hu, Real hv)
{
    return (Bits<Real>::of(h) | Bits<Real>::of(hu) | Bits<Real>::of(hv)) != 0;
}

//- Whether this block's tile is skipped this step (every thread of the
//  block calls it; one store of the decision for the other kernels)
__device__ bool decideSkip
(
    const int* occNow,
    const int* occBefore,
    int* skip,
    bool skipping
)
{
    const int nTx = gridDim.x;
    const int nTy = gridDim.y;
    const int tid = threadIdx.x + threadIdx.y*blockDim.x;
    const int w = 2*skipTilesX + 1;
    const int nb = w*(2*skipTilesY + 1);
    int busy = 0;
    if (tid < 2*nb)
    {
        const int k = tid % nb;
        const int tx = int(blockIdx.x) + k % w - skipTilesX;
        const int ty = int(blockIdx.y) + k / w - skipTilesY;
        if (tx >= 0 && tx < nTx && ty >= 0 && ty < nTy)
        {
            const int t = tx + ty*nTx;
            busy = tid < nb ? occNow[t] : occBefore[t];
        }
    }
    const bool skipped = skipping && !__syncthreads_or(busy);
    if (threadIdx.x == 0 && threadIdx.y == 0)
    {
        skip[blockIdx.x + blockIdx.y*nTx] = skipped;
    }
    return skipped;
}

//- Ghost cells that mirror interior cell (i, j), filled from its final
//  value in the order of CpuSolver::fillGhosts: x-sides, then y-sides of
//  the cell and of its x-ghosts (the corners)
template<class Real>
__device__ void mirrorGhosts
(
    const Model<Real>& m,
    const Fields<Real>& U,
    int i,
    int j
)
{
    const int ng = Grid<Real>::ng;
    const int nx = m.g.nx;
    const int ny = m.g.ny;
    int xg[2], xs[2], nxg = 0;
    int yg[2], ys[2], nyg = 0;
    if (i < ng) { xg[nxg] = -1 - i; xs[nxg++] = xMin; }
    if (i >= nx - ng) { xg[nxg] = 2*nx - 1 - i; xs[nxg++] = xMax; }
    if (j < ng) { yg[nyg] = -1 - j; ys[nyg++] = yMin; }
    if (j >= ny - ng) { yg[nyg] = 2*ny - 1 - j; ys[nyg++] = yMax; }

    for (int a = 0; a < nxg; ++a)
    {
        fillGhostCell(m, U, xs[a], xg[a], j);
    }
    for (int b = 0; b < nyg; ++b)
    {
        fillGhostCell(m, U, ys[b], i, yg[b]);
        for (int a = 0; a < nxg; ++a)
        {
            fillGhostCell(m, U, ys[b], xg[a], yg[b]);
        }
    }
}


// * * * * * * * * * * * * * * * * Kernels * * * * * * * * * * * * * * * * //

//- Kernel 1: the step's dt, then the predictor (14) and its ghost cells.
//  fixedDt > 0: a step of that size with the clock kept by the host
//  (Solver::step).
template<class Real>
__global__ void predictorKernel
(
    Model<Real> m,
    Fields<Real> U,
    Fields<Real> Uh,
    StepControl<Real>* ctrl,
    int parity,
    Real fixedDt,
    const int* occNow,
    const int* occBefore,
    int* skip,
    bool skipping
)
{
    Real dt;
    if (fixedDt > Real(0))
    {
        dt = fixedDt;
        if (firstThread())
        {
            ctrl->dt = double(fixedDt);
            ctrl->last = 0;
            ctrl->active = 1;
        }
    }
    else
    {
        // Solver::advance's arithmetic, in the same types
        const double t = ctrl->t;
        const double tEnd = ctrl->tEnd;
        if (!(t < tEnd))
        {
            if (firstThread())
            {
                ctrl->active = 0;
            }
            return;
        }
        const Real rate = Bits<Real>::real(ctrl->rate[parity]);
        const Real stable =
            rate > Real(0) ? m.p.cfl/rate : Bits<Real>::maxValue();
        double d = double(stable);
        if (d > ctrl->maxDt)
        {
            d = ctrl->maxDt;
        }
        const double left = tEnd - t;
        const bool last = d >= left;
        if (last)
        {
            d = left;
        }
        dt = Real(d);
        if (firstThread())
        {
            ctrl->dt = d;
            ctrl->last = last;
            ctrl->active = 1;
        }
    }

    if (decideSkip(occNow, occBefore, skip, skipping))
    {
        return;
    }
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    const int j = blockIdx.y*blockDim.y + threadIdx.y;
    if (i < m.g.nx && j < m.g.ny)
    {
        predictorCell(m, U, Uh, dt, i, j);
        mirrorGhosts(m, Uh, i, j);
    }
}


//- Whether the face between cells c and c + step (step 1: x-face, stride:
//  y-face) lies in an empty region: U^{n+1/2} has h == 0 on the whole
//  stencil of its MUSCL reconstruction (c - step .. c + 2 step) and no
//  momentum in its two cells.  fluxX/fluxY then give exactly +0 in every
//  component: both reconstructed sides are dry (limited differences of
//  zeros are 0), so hllcFlux returns 0 and holdResting leaves it; both
//  cells are at rest, so K = 1 on both sides and on the face (selectK),
//  and pLow = pHigh = (1 - 1) bn h^2/2 = +0.  The avalanche covers a few
//  per cent of the inclined plane, so this skips most of the work there;
//  tests/gpuCompare.C checks that the results stay bit-identical.
template<class Real>
__device__ bool emptyFace(const Fields<Real>& Uh, int c, int step)
{
    return Uh.h[c - step] == Real(0) && Uh.h[c] == Real(0)
        && Uh.h[c + step] == Real(0) && Uh.h[c + 2*step] == Real(0)
        && Uh.hu[c] == Real(0) && Uh.hv[c] == Real(0)
        && Uh.hu[c + step] == Real(0) && Uh.hv[c + step] == Real(0);
}

template<class Real>
__device__ void storeFace
(
    const FaceFields<Real>& F,
    int c,
    const FaceFlux<Real>& f
)
{
    F.h[c] = f.F.h;
    F.hu[c] = f.F.hu;
    F.hv[c] = f.F.hv;
    F.pLow[c] = f.pLow;
    F.pHigh[c] = f.pHigh;
}

//- Kernel 2: x-faces (blockIdx.z = 0) i+1/2 for i = -1..nx-1, rows
//  0..ny-1, and y-faces (blockIdx.z = 1) j+1/2 for j = -1..ny-1, columns
//  0..nx-1, stored by the low cell.  One thread per face: half the
//  dependent chain of a thread doing both, which is what a small mesh
//  waits for.
template<class Real>
__global__ void fluxKernel
(
    Model<Real> m,
    Fields<Real> Uh,
    FaceFields<Real> Fx,
    FaceFields<Real> Fy,
    const StepControl<Real>* ctrl,
    const int* skip,
    int nTx
)
{
    if (!ctrl->active)
    {
        return;
    }
    const int i = int(blockIdx.x*blockDim.x + threadIdx.x) - 1;
    const int j = int(blockIdx.y*blockDim.y + threadIdx.y) - 1;
    if (i >= m.g.nx || j >= m.g.ny)
    {
        return;
    }
    // The tile of the face's low cell (the boundary tile for i or j = -1)
    if (skip[(i < 0 ? 0 : i)/blockX + (j < 0 ? 0 : j)/blockY*nTx])
    {
        return;
    }
    const int c = m.g.idx(i, j);
    if (blockIdx.z == 0)
    {
        if (j < 0)
        {
            return;
        }
        if (emptyFace(Uh, c, 1))
        {
            storeFace(Fx, c, {{Real(0), Real(0), Real(0)}, Real(0), Real(0)});
        }
        else
        {
            storeFace(Fx, c, fluxX(m, Uh, i, j));
        }
    }
    else
    {
        if (i < 0)
        {
            return;
        }
        if (emptyFace(Uh, c, m.g.stride()))
        {
            storeFace(Fy, c, {{Real(0), Real(0), Real(0)}, Real(0), Real(0)});
        }
        else
        {
            storeFace(Fy, c, fluxY(m, Uh, i, j));
        }
    }
}


//- Kernel 3: drain factor theta of each cell
template<class Real>
__global__ void drainKernel
(
    Model<Real> m,
    Fields<Real> U,
    FaceFields<Real> Fx,
    FaceFields<Real> Fy,
    Real* theta,
    const StepControl<Real>* ctrl,
    const int* skip
)
{
    if (!ctrl->active || skip[blockIdx.x + blockIdx.y*gridDim.x])
    {
        return;
    }
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    const int j = blockIdx.y*blockDim.y + threadIdx.y;
    if (i < m.g.nx && j < m.g.ny)
    {
        const Real dt = Real(ctrl->dt);
        theta[m.g.idx(i, j)] = drainFactor(m, U, Fx, Fy, dt, i, j);
    }
}


//- Kernel 4: corrector.  At most 64 registers (74 unbounded in double:
//  35 % occupancy): +5 % on the wet double step for 24 B of spills
template<class Real>
__launch_bounds__(blockX*blockY, 1024/(blockX*blockY))
__global__ void correctorKernel
(
    Model<Real> m,
    Fields<Real> U,
    Fields<Real> Uh,
    FaceFields<Real> Fx,
    FaceFields<Real> Fy,
    const Real* theta,
    Fields<Real> Unew,
    const StepControl<Real>* ctrl,
    const int* skip
)
{
    if (!ctrl->active || skip[blockIdx.x + blockIdx.y*gridDim.x])
    {
        return;
    }
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    const int j = blockIdx.y*blockDim.y + threadIdx.y;
    if (i < m.g.nx && j < m.g.ny)
    {
        const Real dt = Real(ctrl->dt);
        correctorCell(m, U, Uh, Fx, Fy, theta, Unew, dt, i, j);
    }
}


//- Kernel 5: partial-wet cells (in place: reads only wet cells, writes
//  only partial-wet ones), ghost cells, the next step's wave rate and, if
//  the device keeps the clock, the clock
template<class Real>
__global__ void finishKernel
(
    Model<Real> m,
    Fields<Real> Unew,
    StepControl<Real>* ctrl,
    int parity,
    int newBuf,
    bool deviceClock,
    const int* skip,
    int* occNew
)
{
    using B = typename Bits<Real>::type;
    if (!ctrl->active)
    {
        return;
    }
    const int tile = blockIdx.x + blockIdx.y*gridDim.x;
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    const int j = blockIdx.y*blockDim.y + threadIdx.y;
    B rate = 0;
    int busy = 0;
    const bool skipped = skip[tile];
    if (!skipped && i < m.g.nx && j < m.g.ny)
    {
        partialWetCell(m, Unew, i, j);
        mirrorGhosts(m, Unew, i, j);
        const int c = m.g.idx(i, j);
        busy = occupied(Unew.h[c], Unew.hu[c], Unew.hv[c]);
        rate = Bits<Real>::of(cellWaveRate(m, Unew, i, j));
    }
    // A skipped tile stays empty; the condition is uniform over the block
    if (skipped)
    {
        if (threadIdx.x == 0 && threadIdx.y == 0)
        {
            occNew[tile] = 0;
        }
    }
    else
    {
        busy = __syncthreads_or(busy);
        if (threadIdx.x == 0 && threadIdx.y == 0)
        {
            occNew[tile] = busy;
        }
        blockMax(rate, &ctrl->rate[parity ^ 1]);
    }

    if (firstThread())
    {
        // Slot `parity` was read by this step's kernel 1; it collects the
        // step after next
        ctrl->rate[parity] = ctrl->inflowRate;
        if (deviceClock)
        {
            const double dt = double(Real(ctrl->dt));
            ctrl->t = ctrl->last ? ctrl->tEnd : ctrl->t + dt;
            ctrl->lastDt = dt;
            ++ctrl->steps;
        }
        ctrl->stateBuf = newBuf;
    }
}


//- max of eq. (24)'s rate over the cells, into ctrl->rate[slot]
template<class Real>
__global__ void rateKernel
(
    Model<Real> m,
    Fields<Real> U,
    StepControl<Real>* ctrl,
    int slot
)
{
    using B = typename Bits<Real>::type;
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    const int j = blockIdx.y*blockDim.y + threadIdx.y;
    B rate = 0;
    if (i < m.g.nx && j < m.g.ny)
    {
        rate = Bits<Real>::of(cellWaveRate(m, U, i, j));
    }
    blockMax(rate, &ctrl->rate[slot]);
}


// * * * * * * * * * * * * * * * Device memory * * * * * * * * * * * * * * //

//- An owned device array
template<class T>
class DeviceArray
{
    T* p_ = nullptr;
    std::size_t n_ = 0;

public:
    DeviceArray() = default;
    DeviceArray(const DeviceArray&) = delete;
    DeviceArray& operator=(const DeviceArray&) = delete;
    ~DeviceArray() { if (p_) { cudaFree(p_); } }

    void allocate(std::size_t n)
    {
        SH_CUDA_CHECK(cudaMalloc(&p_, n*sizeof(T)));
        n_ = n;
    }
    void upload(const std::vector<T>& v)
    {
        SH_CUDA_CHECK
        (
            cudaMemcpy(p_, v.data(), v.size()*sizeof(T), cudaMemcpyHostToDevice)
        );
    }
    void download(std::vector<T>& v) const
    {
        v.resize(n_);
        SH_CUDA_CHECK
        (
            cudaMemcpy(v.data(), p_, n_*sizeof(T), cudaMemcpyDeviceToHost)
        );
    }
    T* get() const { return p_; }
};


// * * * * * * * * * * * * * * * * The solver  * * * * * * * * * * * * * * //

template<class Real>
class CudaSolver : public Solver<Real>
{
    using Control = StepControl<Real>;
    using B = typename Bits<Real>::type;

    //- Steps in the large and the small graph (even: each ends with the
    //  state back in the buffer it started from)
    static constexpr int bigGraph = 128;
    static constexpr int smallGraph = 8;

    std::string deviceName_;
    cudaStream_t stream_ = nullptr;

    Grid<Real> grid_;
    HostGeometry<Real> hostGeometry_;
    Model<Real> hostModel_;     //!< host copy, for host-side reductions
    Model<Real> model_;         //!< device geometry pointers

    DeviceArray<Real> cosZeta_, sinZeta_, kappa_, dzbdx_, dzbdy_;
    DeviceArray<Real> state_[2][3];
    DeviceArray<Real> half_[3];
    DeviceArray<Real> fx_[5], fy_[5];
    DeviceArray<Real> theta_;
    DeviceArray<Control> ctrl_;

    //- Occupied tiles of the state in each buffer, skipped tiles of the
    //  step in progress
    DeviceArray<int> occ_[2];
    DeviceArray<int> skip_;
    bool skipping_ = true;

    int cur_ = 0;               //!< state buffer holding U^n
    B inflowBits_;

    //- Instantiated graphs [size][start buffer]
    cudaGraphExec_t graphs_[2][2] = {{nullptr, nullptr}, {nullptr, nullptr}};

    dim3 cells_, faces_, block_;

    Fields<Real> fields(int b) const
    {
        return {state_[b][0].get(), state_[b][1].get(), state_[b][2].get()};
    }
    Fields<Real> half() const
    {
        return {half_[0].get(), half_[1].get(), half_[2].get()};
    }
    static FaceFields<Real> faces(const DeviceArray<Real>* f)
    {
        return {f[0].get(), f[1].get(), f[2].get(), f[3].get(), f[4].get()};
    }

    //- Launch a kernel of a step on the stream
    template<class... Params, class... Args>
    void launch
    (
        const char* name,
        void (*kernel)(Params...),
        dim3 grid,
        Args... args
    )
    {
        cudaLaunchConfig_t cfg = {};
        cfg.gridDim = grid;
        cfg.blockDim = block_;
        cfg.dynamicSmemBytes = 0;
        cfg.stream = stream_;
        cfg.attrs = nullptr;
        cfg.numAttrs = 0;
        cudaCheck(cudaLaunchKernelEx(&cfg, kernel, args...), name, __FILE__, __LINE__);
    }

    //- The five kernels of one step from buffer `from` to the other one
    void launchStep(int from, int parity, Real fixedDt)
    {
        const Fields<Real> U = fields(from);
        const Fields<Real> Un = fields(from ^ 1);
        const Fields<Real> Uh = half();
        const FaceFields<Real> Fx = faces(fx_);
        const FaceFields<Real> Fy = faces(fy_);
        Control* c = ctrl_.get();
        Real* theta = theta_.get();
        const int newBuf = from ^ 1;
        const bool deviceClock = fixedDt <= Real(0);

        const int* occNow = occ_[from].get();
        const int* occBefore = occ_[from ^ 1].get();
        int* skip = skip_.get();
        const int* skipped = skip;
        const Control* cc = c;

        launch("predictorKernel", predictorKernel<Real>, cells_,
            model_, U, Uh, c, parity, fixedDt, occNow, occBefore, skip,
            skipping_);
        launch("fluxKernel", fluxKernel<Real>, faces_,
            model_, Uh, Fx, Fy, cc, skipped, int(cells_.x));
        launch("drainKernel", drainKernel<Real>, cells_,
            model_, U, Fx, Fy, theta, cc, skipped);
        launch("correctorKernel", correctorKernel<Real>, cells_,
            model_, U, Uh, Fx, Fy, static_cast<const Real*>(theta), Un, cc,
            skipped);
        launch("finishKernel", finishKernel<Real>, cells_,
            model_, Un, c, parity, newBuf, deviceClock, skipped,
            occ_[newBuf].get());
    }

    cudaGraphExec_t graph(int size, int start)
    {
        cudaGraphExec_t& g = graphs_[size][start];
        if (!g)
        {
            const int n = size == 0 ? bigGraph : smallGraph;
            cudaGraph_t captured;
            SH_CUDA_CHECK
            (
                cudaStreamBeginCapture(stream_, cudaStreamCaptureModeThreadLocal)
            );
            for (int k = 0; k < n; ++k)
            {
                launchStep(start ^ (k & 1), k & 1, Real(0));
            }
            SH_CUDA_CHECK(cudaStreamEndCapture(stream_, &captured));
            SH_CUDA_CHECK(cudaGraphInstantiate(&g, captured, 0));
            SH_CUDA_CHECK(cudaGraphDestroy(captured));
        }
        return g;
    }

    //- ctrl->rate[slot] = max(inflow rate, rate of buffer cur_)
    void launchRate(int slot)
    {
        SH_CUDA_CHECK
        (
            cudaMemcpyAsync
            (
                &ctrl_.get()->rate[slot], &inflowBits_, sizeof(B),
                cudaMemcpyHostToDevice, stream_
            )
        );
        rateKernel<Real><<<cells_, block_, 0, stream_>>>
            (model_, fields(cur_), ctrl_.get(), slot);
        SH_CUDA_CHECK_LAUNCH("rateKernel");
    }

    Control readControl()
    {
        Control c;
        SH_CUDA_CHECK
        (
            cudaMemcpyAsync
            (
                &c, ctrl_.get(), sizeof c, cudaMemcpyDeviceToHost, stream_
            )
        );
        SH_CUDA_CHECK(cudaStreamSynchronize(stream_));
        return c;
    }

    void advanceStep(Real dt) override
    {
        launchStep(cur_, 0, dt);
        SH_CUDA_CHECK(cudaStreamSynchronize(stream_));
        cur_ ^= 1;
    }

    //- Padded arrays of the current state on the host
    void downloadPadded(std::vector<Real> (&q)[3]) const
    {
        SH_CUDA_CHECK(cudaStreamSynchronize(stream_));
        for (int k = 0; k < 3; ++k)
        {
            state_[cur_][k].download(q[k]);
        }
    }

public:
    explicit CudaSolver(const Problem<Real>& pb)
    :
        grid_(pb.grid),
        hostGeometry_(pb)
    {
        const Grid<Real>& g = pb.grid;
        if (g.nx < Grid<Real>::ng || g.ny < Grid<Real>::ng)
        {
            throw std::runtime_error
            (
                "CUDA backend: the grid needs at least "
              + std::to_string(Grid<Real>::ng) + " cells in each direction"
            );
        }
        int dev = 0;
        SH_CUDA_CHECK(cudaGetDevice(&dev));
        cudaDeviceProp prop;
        SH_CUDA_CHECK(cudaGetDeviceProperties(&prop, dev));
        deviceName_ = prop.name;
        SH_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, cudaStreamNonBlocking));

        hostModel_.p = pb.params;
        hostModel_.g = g;
        hostModel_.bc = pb.bc;
        hostModel_.geo = hostGeometry_.view();

        const std::size_t nc = g.stride();
        const std::size_t n = g.size();
        cosZeta_.allocate(nc);
        sinZeta_.allocate(nc);
        kappa_.allocate(nc);
        dzbdx_.allocate(n);
        dzbdy_.allocate(n);
        cosZeta_.upload(hostGeometry_.cosZeta);
        sinZeta_.upload(hostGeometry_.sinZeta);
        kappa_.upload(hostGeometry_.kappa);
        dzbdx_.upload(hostGeometry_.dzbdx);
        dzbdy_.upload(hostGeometry_.dzbdy);
        model_ = hostModel_;
        model_.geo =
        {
            cosZeta_.get(), sinZeta_.get(), kappa_.get(),
            dzbdx_.get(), dzbdy_.get()
        };

        // Initial state with its ghost cells, filled on the host as the
        // CPU backend fills them
        std::vector<Real> q[3];
        for (int k = 0; k < 3; ++k)
        {
            q[k].assign(n, Real(0));
        }
        for (int j = 0; j < g.ny; ++j)
        {
            for (int i = 0; i < g.nx; ++i)
            {
                const int c = g.idx(i, j);
                const int k = pb.cell(i, j);
                q[0][c] = pb.h[k];
                q[1][c] = pb.hu[k];
                q[2][c] = pb.hv[k];
            }
        }
        const Fields<Real> U{q[0].data(), q[1].data(), q[2].data()};
        const int ng = Grid<Real>::ng;
        for (int j = 0; j < g.ny; ++j)
        {
            for (int k = 1; k <= ng; ++k)
            {
                fillGhostCell(hostModel_, U, xMin, -k, j);
                fillGhostCell(hostModel_, U, xMax, g.nx - 1 + k, j);
            }
        }
        for (int k = 1; k <= ng; ++k)
        {
            for (int i = -ng; i < g.nx + ng; ++i)
            {
                fillGhostCell(hostModel_, U, yMin, i, -k);
                fillGhostCell(hostModel_, U, yMax, i, g.ny - 1 + k);
            }
        }
        for (int b = 0; b < 2; ++b)
        {
            for (int k = 0; k < 3; ++k)
            {
                state_[b][k].allocate(n);
                state_[b][k].upload(q[k]);
            }
        }

        // Theta is 1 outside the interior (never written), as on the CPU
        const std::vector<Real> zero(n, Real(0));
        for (int k = 0; k < 3; ++k)
        {
            half_[k].allocate(n);
            half_[k].upload(zero);
        }
        for (int k = 0; k < 5; ++k)
        {
            fx_[k].allocate(n);
            fx_[k].upload(zero);
            fy_[k].allocate(n);
            fy_[k].upload(zero);
        }
        theta_.allocate(n);
        theta_.upload(std::vector<Real>(n, Real(1)));

        inflowBits_ = Bits<Real>::of(inflowWaveRate(hostModel_));
        Control c{};
        c.inflowRate = inflowBits_;
        c.rate[0] = c.rate[1] = inflowBits_;
        ctrl_.allocate(1);
        ctrl_.upload(std::vector<Control>(1, c));

        block_ = dim3(blockX, blockY);
        cells_ = dim3((g.nx + blockX - 1)/blockX, (g.ny + blockY - 1)/blockY);
        faces_ = dim3
        (
            (g.nx + 1 + blockX - 1)/blockX, (g.ny + 1 + blockY - 1)/blockY, 2
        );

        // Occupied tiles of the initial state, for both buffers.  Inflow
        // sides impose states that need not be empty: no skipping then.
        const int nTiles = int(cells_.x*cells_.y);
        std::vector<int> occ(nTiles, 0);
        for (int j = 0; j < g.ny; ++j)
        {
            for (int i = 0; i < g.nx; ++i)
            {
                const int c = g.idx(i, j);
                if (occupied(q[0][c], q[1][c], q[2][c]))
                {
                    occ[i/blockX + (j/blockY)*cells_.x] = 1;
                }
            }
        }
        for (int b = 0; b < 2; ++b)
        {
            occ_[b].allocate(nTiles);
            occ_[b].upload(occ);
        }
        skip_.allocate(nTiles);
        skip_.upload(std::vector<int>(nTiles, 0));
        for (int s = 0; s < 4; ++s)
        {
            skipping_ = skipping_ && pb.bc.type[s] != BCType::inflow;
        }

        // Graphs of the first advance() built now, not in its time loop
        graph(0, cur_);
        graph(1, cur_);
    }

    ~CudaSolver() override
    {
        for (auto& gs : graphs_)
        {
            for (cudaGraphExec_t g : gs)
            {
                if (g) { cudaGraphExecDestroy(g); }
            }
        }
        if (stream_) { cudaStreamDestroy(stream_); }
    }

    std::string name() const override
    {
        return std::string("cuda (") + deviceName_ + ", "
            + (sizeof(Real) == 8 ? "double" : "float") + ")";
    }

    Real stableDt() override
    {
        launchRate(0);
        const Real rate = Bits<Real>::real(readControl().rate[0]);
        return rate > Real(0) ? hostModel_.p.cfl/rate : Bits<Real>::maxValue();
    }

    bool advance(double tEnd, double wallSeconds) override
    {
        using clock = std::chrono::steady_clock;
        const clock::time_point start = clock::now();
        if (!(this->time_ < tEnd))
        {
            return true;
        }

        // The clock to the device; rate slot 0 for the first step
        Control c = readControl();
        c.t = this->time_;
        c.tEnd = tEnd;
        c.maxDt = this->maxDt_;
        c.steps = this->steps_;
        c.lastDt = this->lastDt_;
        c.active = 1;
        c.stateBuf = cur_;
        c.rate[1] = inflowBits_;
        SH_CUDA_CHECK
        (
            cudaMemcpyAsync
            (
                ctrl_.get(), &c, sizeof c, cudaMemcpyHostToDevice, stream_
            )
        );
        launchRate(0);

        bool reached = false;
        while (true)
        {
            // The small graph once the remaining steps are few, so that
            // little of the last launch runs as no-op steps
            const double dtGuess = this->lastDt_ > 0 ? this->lastDt_ : 0;
            const bool few =
                dtGuess > 0 && (tEnd - this->time_) < 1.5*bigGraph*dtGuess;
            SH_CUDA_CHECK
            (
                cudaGraphLaunch(graph(few ? 1 : 0, cur_), stream_)
            );
            c = readControl();
            this->time_ = c.t;
            this->steps_ = c.steps;
            this->lastDt_ = c.lastDt;
            cur_ = c.stateBuf;
            if (!(c.t < tEnd))
            {
                reached = true;
                break;
            }
            const std::chrono::duration<double> used = clock::now() - start;
            if (used.count() >= wallSeconds)
            {
                break;
            }
        }
        return reached;
    }

    Diagnostics diagnostics() override
    {
        std::vector<Real> q[3];
        downloadPadded(q);
        const Fields<Real> U{q[0].data(), q[1].data(), q[2].data()};
        const Grid<Real>& g = grid_;
        Diagnostics d;
        double sumH = 0;
        for (int j = 0; j < g.ny; ++j)
        {
            for (int i = 0; i < g.nx; ++i)
            {
                const int c = g.idx(i, j);
                const Real h = U.h[c];
                sumH += double(h);
                d.hMax = std::max(d.hMax, double(h));
                d.maxRate = std::max
                (
                    d.maxRate,
                    double(cellWaveRate(hostModel_, U, i, j))
                );
                if (h > hostModel_.p.hDry)
                {
                    ++d.wetCells;
                    if (U.hu[c] != Real(0) || U.hv[c] != Real(0))
                    {
                        ++d.movingCells;
                    }
                }
            }
        }
        d.volume = sumH*double(g.dx)*double(g.dy);
        return d;
    }

    void getState
    (
        std::vector<Real>& h,
        std::vector<Real>& hu,
        std::vector<Real>& hv
    ) override
    {
        std::vector<Real> q[3];
        downloadPadded(q);
        const Grid<Real>& g = grid_;
        const std::size_t n = std::size_t(g.nx)*g.ny;
        h.resize(n);
        hu.resize(n);
        hv.resize(n);
        for (int j = 0; j < g.ny; ++j)
        {
            for (int i = 0; i < g.nx; ++i)
            {
                const int c = g.idx(i, j);
                const std::size_t k = i + std::size_t(j)*g.nx;
                h[k] = q[0][c];
                hu[k] = q[1][c];
                hv[k] = q[2][c];
            }
        }
    }
};

} // namespace


// * * * * * * * * * * * * * * * Entry points  * * * * * * * * * * * * * * //

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


template<class Real>
std::unique_ptr<Solver<Real>> makeCudaSolver(const Problem<Real>& problem)
{
    std::string why;
    if (!cudaAvailable(&why))
    {
        throw std::runtime_error("CUDA backend: " + why);
    }
    return std::unique_ptr<Solver<Real>>(new CudaSolver<Real>(problem));
}

template std::unique_ptr<Solver<double>> makeCudaSolver(const Problem<double>&);
template std::unique_ptr<Solver<float>> makeCudaSolver(const Problem<float>&);

} // namespace sh

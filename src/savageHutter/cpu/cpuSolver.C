#include "cpuSolver.H"
#include "../host/padded.H"

#include <algorithm>
#include <limits>

#ifdef _OPENMP
#   include <omp.h>
#endif

namespace sh
{

template<class Real>
CpuSolver<Real>::CpuSolver(const Problem<Real>& pb, bool parallel)
:
    geometry_(pb),
    parallel_(parallel),
    peaks_(pb)
{
    this->time_ = pb.startTime;
    model_.p = pb.params;
    model_.g = pb.grid;
    model_.bc = pb.bc;
    model_.geo = geometry_.view();

    const Grid<Real>& g = pb.grid;
    const std::size_t n = g.size();
    U_.resize(n);
    Uh_.resize(n);
    Unew_.resize(n);
    Fx_.resize(n, !geometry_.constantBed());
    Fy_.resize(n, !geometry_.constantBed());

    U_.h = toPadded(g, pb.h);
    U_.hu = toPadded(g, pb.hu);
    U_.hv = toPadded(g, pb.hv);
    Unew_ = U_;
}


template<class Real>
std::string CpuSolver<Real>::name() const
{
    return parallel_
        ? "cpu (OpenMP, " + std::to_string(nThreads()) + " threads)"
        : "cpu (serial)";
}


template<class Real>
int CpuSolver<Real>::nThreads() const
{
#ifdef _OPENMP
    return parallel_ ? omp_get_max_threads() : 1;
#else
    return 1;
#endif
}


template<class Real>
Real CpuSolver<Real>::stableDt()
{
    const Grid<Real>& g = model_.g;
    const Fields<Real> U = U_.view();
    Real rate = inflowWaveRate(model_);

    #pragma omp parallel for if(parallel_) reduction(max:rate) schedule(static)
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            rate = shMax(rate, cellWaveRate(model_, U, i, j));
        }
    }
    return rate > Real(0)
        ? model_.p.cfl/rate
        : std::numeric_limits<Real>::max();
}


template<class Real>
void CpuSolver<Real>::advanceStep(Real dt, double tNew)
{
    const Grid<Real>& g = model_.g;
    const Model<Real>& m = model_;
    const Fields<Real> U = U_.view();
    const Fields<Real> Uh = Uh_.view();
    const Fields<Real> Un = Unew_.view();
    const FaceFields<Real> Fx = Fx_.view();
    const FaceFields<Real> Fy = Fy_.view();
    const int nx = g.nx;
    const int ny = g.ny;

    fillGhostCells(m, U);

    #pragma omp parallel for if(parallel_) schedule(static)
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            predictorCell(m, U, Uh, dt, i, j);
        }
    }

    fillGhostCells(m, Uh);

    // Each x-face i+1/2 for i = -1..nx-1 of rows 0..ny-1, each y-face
    // j+1/2 for j = -1..ny-1 of columns 0..nx-1, from the reconstructions
    // of their two cells, each cell reconstructed once (two rows kept):
    // every thread takes a band of y-face rows, reconstructing one row
    // more than its band
    #pragma omp parallel if(parallel_)
    {
        int t = 0;
        int nt = 1;
#ifdef _OPENMP
        t = omp_get_thread_num();
        nt = omp_get_num_threads();
#endif
        const long rows = ny + 1;
        const int ja = -1 + int(rows*t/nt);
        const int jb = -1 + int(rows*(t + 1)/nt);
        std::vector<CellFaces<Real>> lo(nx + 2), hi(nx + 2);
        // Row j, cells -1..nx of an interior row, 0..nx-1 of a ghost row
        const auto reconstructRow = [&](int j, std::vector<CellFaces<Real>>& r)
        {
            const bool inner = j >= 0 && j < ny;
            for (int i = inner ? -1 : 0; i < (inner ? nx + 1 : nx); ++i)
            {
                r[i + 1] = reconstructCell(m, Uh, i, j);
            }
        };
        if (ja < jb)
        {
            reconstructRow(ja, lo);
        }
        for (int j = ja; j < jb; ++j)
        {
            if (j >= 0)
            {
                for (int i = -1; i < nx; ++i)
                {
                    storeFaceFlux(Fx, g.idx(i, j), fluxX(m, lo[i + 1], lo[i + 2]));
                }
            }
            reconstructRow(j + 1, hi);
            for (int i = 0; i < nx; ++i)
            {
                storeFaceFlux(Fy, g.idx(i, j), fluxY(m, lo[i + 1], hi[i + 1]));
            }
            std::swap(lo, hi);
        }
    }

    long long clips = 0;
    #pragma omp parallel for if(parallel_) reduction(+:clips) schedule(static)
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            clips += correctorCell(m, U, Uh, Fx, Fy, Un, dt, i, j);
        }
    }
    speedClips_ += clips;

    const PeakFields<Real> P = peaks_.view();
    long long wet = 0;
    #pragma omp parallel for if(parallel_) reduction(+:wet) schedule(static)
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            partialWetCell(m, Un, i, j);
            updatePeaks(m, Un, P, tNew, i, j);
            wet += Un.h[g.idx(i, j)] > m.p.hDry ? 1 : 0;
        }
    }
    wetUpdates_ += wet;

    std::swap(U_, Unew_);
}


template<class Real>
void CpuSolver<Real>::getState
(
    std::vector<Real>& h,
    std::vector<Real>& hu,
    std::vector<Real>& hv
)
{
    toInterior(model_.g, U_.h.data(), h);
    toInterior(model_.g, U_.hu.data(), hu);
    toInterior(model_.g, U_.hv.data(), hv);
}


template<class Real>
PeakMaps<Real> CpuSolver<Real>::peakMaps()
{
    return HostPeaks<Real>::maps
    (
        model_.g, model_.p, peaks_.h.data(), peaks_.speed2.data(),
        peaks_.arrival.data()
    );
}


template<class Real>
Diagnostics CpuSolver<Real>::diagnostics()
{
    Diagnostics d = diagnosticsOf(model_, U_.view());
    d.speedClips = speedClips_;
    return d;
}


template class CpuSolver<double>;
template class CpuSolver<float>;

} // namespace sh

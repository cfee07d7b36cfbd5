#include "cpuSolver.H"
#include "../host/padded.H"

#include <algorithm>
#include <limits>
#include <string>

#ifdef _OPENMP
#   include <omp.h>
#endif

namespace sh
{

namespace
{

template<class Real>
const Problem<Real>& checkedSubdomain(const Problem<Real>& pb, Halo<Real>* halo)
{
    checkSubdomain(pb, halo, "CpuSolver");
    return pb;
}

} // namespace


template<class Real>
CpuSolver<Real>::CpuSolver
(
    const Problem<Real>& pb,
    bool parallel,
    Halo<Real>* halo
)
:
    geometry_(checkedSubdomain(pb, halo), halo),
    parallel_(parallel),
    peaks_(pb, &geometry_),
    cover_(pb),
    halo_(halo)
{
    this->time_ = pb.startTime;
    model_.p = pb.params;
    model_.g = pb.grid;
    model_.bc = pb.bc;
    model_.geo = geometry_.view();
    model_.plan = geometry_.planView();
    model_.cover = cover_.view();

    const Grid<Real>& g = pb.grid;
    if (halo_)
    {
        ghostTheta_.assign(g.size(), Real(1));
        model_.ghostTheta = ghostTheta_.data();
    }
    const std::size_t n = g.size();
    U_.resize(n);
    Uh_.resize(n);
    Unew_.resize(n);
    const bool plan = pb.params.planTerrain;
    Fx_.resize(n, !geometry_.constantBed(), plan);
    Fy_.resize(n, !geometry_.constantBed(), plan);

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
void CpuSolver<Real>::fillStateGhosts()
{
    if (!ghostsFilled_)
    {
        fillGhostCells(model_, U_.view(), halo_);
        ghostsFilled_ = true;
    }
}


template<class Real>
bool CpuSolver<Real>::agreeToStop(bool stop)
{
    return halo_ ? halo_->anyAll(stop) : stop;
}


template<class Real>
Real CpuSolver<Real>::stableDt()
{
    const Grid<Real>& g = model_.g;
    const Fields<Real> U = U_.view();
    // The wave rate of a cell looks at its neighbours' h and, for the
    // active/passive switch (scheme.H switchRate), their velocities
    fillStateGhosts();
    Real rate = inflowWaveRate(model_);
    const bool plan = model_.p.planTerrain;

    #pragma omp parallel for if(parallel_) reduction(max:rate) schedule(static)
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            rate = shMax
            (
                rate,
                plan ? PlanStages::waveRate(model_, U, i, j)
                  : SlopeStages::waveRate(model_, U, i, j)
            );
        }
    }
    if (halo_)
    {
        rate = halo_->maxAll(rate);
    }
    return rate > Real(0)
        ? model_.p.cfl/rate
        : std::numeric_limits<Real>::max();
}


template<class Real>
void CpuSolver<Real>::exchangeDrainFactors(Real dt)
{
    // theta of the cells along the processor sides, for the neighbours'
    // corrector (scheme.H drainFactorAt)
    const Model<Real>& m = model_;
    const Grid<Real>& g = m.g;
    const Fields<Real> U = U_.view();
    const FaceFields<Real> Fx = Fx_.view();
    const FaceFields<Real> Fy = Fy_.view();
    const auto processor = [&m](int side)
    {
        return m.bc.type[side] == BCType::processor;
    };
    for (int j = 0; j < g.ny; ++j)
    {
        const bool row = (j == 0 && processor(yMin))
            || (j == g.ny - 1 && processor(yMax));
        for (int i = 0; i < g.nx; ++i)
        {
            if
            (
                row || (i == 0 && processor(xMin))
             || (i == g.nx - 1 && processor(xMax))
            )
            {
                ghostTheta_[g.idx(i, j)] = drainFactor(m, U, Fx, Fy, dt, i, j);
            }
        }
    }
    Real* theta[1] = {ghostTheta_.data()};
    exchangeGhostCells(*halo_, theta, 1, 1);
}


template<class Real>
template<class Stages>
void CpuSolver<Real>::computeFluxes()
{
    using Faces = typename Stages::template Faces<Real>;
    const Grid<Real>& g = model_.g;
    const Model<Real>& m = model_;
    const Fields<Real> Uh = Uh_.view();
    const auto Fx = Fx_.template viewFor<Stages>();
    const auto Fy = Fy_.template viewFor<Stages>();
    const int nx = g.nx;
    const int ny = g.ny;

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
        std::vector<Faces> lo(nx + 2), hi(nx + 2);
        // Row j, cells -1..nx of an interior row, 0..nx-1 of a ghost row
        const auto reconstructRow = [&](int j, std::vector<Faces>& r)
        {
            const bool inner = j >= 0 && j < ny;
            for (int i = inner ? -1 : 0; i < (inner ? nx + 1 : nx); ++i)
            {
                r[i + 1] = Stages::reconstruct(m, Uh, i, j);
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
                    Stages::store
                    (
                        Fx, g.idx(i, j), Stages::flux(m, lo[i + 1], lo[i + 2], false)
                    );
                }
            }
            reconstructRow(j + 1, hi);
            for (int i = 0; i < nx; ++i)
            {
                Stages::store
                (
                    Fy, g.idx(i, j), Stages::flux(m, lo[i + 1], hi[i + 1], true)
                );
            }
            std::swap(lo, hi);
        }
    }
}


template<class Real>
void CpuSolver<Real>::advanceStep(Real dt, double tNew)
{
    const bool entraining = cover_.entraining();
    if (model_.p.planTerrain)
    {
        if (entraining) { stepWith<Entraining<PlanStages>>(dt, tNew); }
        else { stepWith<PlanStages>(dt, tNew); }
    }
    else
    {
        if (entraining) { stepWith<Entraining<SlopeStages>>(dt, tNew); }
        else { stepWith<SlopeStages>(dt, tNew); }
    }
}


template<class Real>
template<class Stages>
void CpuSolver<Real>::stepWith(Real dt, double tNew)
{
    const Grid<Real>& g = model_.g;
    const Model<Real>& m = model_;
    const Fields<Real> U = U_.view();
    const Fields<Real> Uh = Uh_.view();
    const Fields<Real> Un = Unew_.view();
    const auto Fx = Fx_.template viewFor<Stages>();
    const auto Fy = Fy_.template viewFor<Stages>();
    const int nx = g.nx;
    const int ny = g.ny;

    fillStateGhosts();

    #pragma omp parallel for if(parallel_) schedule(static)
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            Stages::predictor(m, U, Uh, dt, i, j);
        }
    }

    fillGhostCells(m, Uh, halo_);

    computeFluxes<Stages>();

    if (halo_)
    {
        exchangeDrainFactors(dt);
    }

    long long clips = 0;
    #pragma omp parallel for if(parallel_) reduction(+:clips) schedule(static)
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            clips += Stages::corrector(m, U, Uh, Fx, Fy, Un, dt, i, j);
        }
    }
    speedClips_ += clips;

    if (halo_)
    {
        // Partial-wet cells take the velocity of a wet neighbour
        Real* state[3] = {Un.h, Un.hu, Un.hv};
        exchangeGhostCells(*halo_, state, 3, 1);
    }

    const PeakFields<Real> P = peaks_.view();
    long long wet = 0;
    #pragma omp parallel for if(parallel_) reduction(+:wet) schedule(static)
    for (int j = 0; j < ny; ++j)
    {
        for (int i = 0; i < nx; ++i)
        {
            partialWetCell(m, Un, i, j);
            Stages::peaks(m, Un, P, tNew, i, j);
            wet += Un.h[g.idx(i, j)] > m.p.hDry ? 1 : 0;
        }
    }
    wetUpdates_ += wet;

    std::swap(U_, Unew_);
    ghostsFilled_ = false;
}


template<class Real>
long long CpuSolver<Real>::wetCellUpdates()
{
    return halo_ ? halo_->sumAll(wetUpdates_) : wetUpdates_;
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
void CpuSolver<Real>::getCover
(
    std::vector<Real>& hEntrainable,
    std::vector<Real>& erodedDepth
)
{
    if (!cover_.entraining())
    {
        hEntrainable.clear();
        erodedDepth.clear();
        return;
    }
    toInterior(model_.g, cover_.layer.data(), hEntrainable);
    toInterior(model_.g, cover_.eroded.data(), erodedDepth);
}


template<class Real>
PeakMaps<Real> CpuSolver<Real>::peakMaps()
{
    PeakMaps<Real> maps;
    getPeakMaps(maps);
    return maps;
}


template<class Real>
void CpuSolver<Real>::getPeakMaps(PeakMaps<Real>& maps)
{
    HostPeaks<Real>::maps
    (
        model_.g, model_.p, peaks_.h.data(), peaks_.speed2.data(),
        peaks_.arrival.data(), maps
    );
}


template<class Real>
Diagnostics CpuSolver<Real>::diagnostics()
{
    // The wave rate of a cell looks at its neighbours
    fillStateGhosts();
    Diagnostics d = diagnosticsOf(model_, U_.view());
    d.speedClips = speedClips_;
    HostCover<Real>::addVolumes
    (
        model_.g, model_.cover.layer, model_.cover.eroded, d
    );
    return halo_ ? reducedDiagnostics(*halo_, d) : d;
}


template class CpuSolver<double>;
template class CpuSolver<float>;

} // namespace sh

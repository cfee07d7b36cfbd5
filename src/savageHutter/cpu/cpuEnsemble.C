/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The CPU backend of an ensemble (ensemble/ensembleSolver.H): a CpuSolver
    per member.  With at least as many members as OpenMP threads, the
    members are shared among the threads (each member's loops serial);
    with fewer, members run one after the other, each with OpenMP over
    its rows.  A CpuSolver's result does not depend on its thread count,
    so both give every member its single run's numbers.  Each CpuSolver
    has its member's cover (erodible layer, eroded depth, resistance) and
    entrainment model, as a single run of the member's problem.
\*---------------------------------------------------------------------------*/

#include "cpuSolver.H"
#include "../ensemble/ensembleSolver.H"

#ifdef _OPENMP
#   include <omp.h>
#endif

#include <atomic>
#include <chrono>

namespace sh
{

namespace
{

template<class Real>
class CpuEnsemble : public EnsembleSolver<Real>
{
    std::vector<std::unique_ptr<CpuSolver<Real>>> members_;
    bool overMembers_;

    static int threads()
    {
#ifdef _OPENMP
        return omp_get_max_threads();
#else
        return 1;
#endif
    }

public:
    explicit CpuEnsemble(const std::vector<Problem<Real>>& members)
    :
        overMembers_(int(members.size()) >= threads() && threads() > 1)
    {
        checkEnsemble(members);
        members_.reserve(members.size());
        for (const Problem<Real>& pb : members)
        {
            members_.emplace_back(new CpuSolver<Real>(pb, !overMembers_));
        }
    }

    std::string name() const override
    {
        return overMembers_
            ? "cpu (OpenMP over members, " + std::to_string(threads())
              + " threads)"
            : members_[0]->name();
    }

    int size() const override { return int(members_.size()); }

    bool advance(double tEnd, double wallSeconds) override
    {
        const int n = size();
        for (auto& s : members_)
        {
            s->setMaxDt(this->maxDt_);
            s->setInterrupt(this->interrupt_);
        }
        // Each member's advance() keeps to the wall budget from the start
        // of this call; a member not started when it is spent waits for
        // the next call
        using clock = std::chrono::steady_clock;
        const clock::time_point start = clock::now();
        std::atomic<int> short_(0);
        const auto one = [&](int m)
        {
            const std::chrono::duration<double> used = clock::now() - start;
            const double left = wallSeconds - used.count();
            if ((left <= 0 || this->interrupted()) && members_[m]->time() < tEnd)
            {
                ++short_;
                return;
            }
            if (!members_[m]->advance(tEnd, left))
            {
                ++short_;
            }
        };
        if (overMembers_)
        {
            #pragma omp parallel for schedule(dynamic, 1)
            for (int m = 0; m < n; ++m)
            {
                one(m);
            }
        }
        else
        {
            for (int m = 0; m < n; ++m)
            {
                one(m);
            }
        }
        return short_ == 0;
    }

    double time(int m) const override { return members_.at(m)->time(); }
    long steps(int m) const override { return members_.at(m)->steps(); }
    double lastDt(int m) const override { return members_.at(m)->lastDt(); }

    void getState
    (
        int m,
        std::vector<Real>& h,
        std::vector<Real>& hu,
        std::vector<Real>& hv
    ) override
    {
        members_.at(m)->getState(h, hu, hv);
    }

    void getCover
    (
        int m,
        std::vector<Real>& hEntrainable,
        std::vector<Real>& erodedDepth
    ) override
    {
        members_.at(m)->getCover(hEntrainable, erodedDepth);
    }

    PeakMaps<Real> peakMaps(int m) override
    {
        return members_.at(m)->peakMaps();
    }

    Diagnostics diagnostics(int m) override
    {
        return members_.at(m)->diagnostics();
    }

    long long wetCellUpdates() override
    {
        long long n = 0;
        for (auto& s : members_)
        {
            n += s->wetCellUpdates();
        }
        return n;
    }
};

} // namespace


template<class Real>
std::unique_ptr<EnsembleSolver<Real>> makeCpuEnsemble
(
    const std::vector<Problem<Real>>& members
)
{
    return std::unique_ptr<EnsembleSolver<Real>>
    (
        new CpuEnsemble<Real>(members)
    );
}

template std::unique_ptr<EnsembleSolver<double>>
makeCpuEnsemble(const std::vector<Problem<double>>&);
template std::unique_ptr<EnsembleSolver<float>>
makeCpuEnsemble(const std::vector<Problem<float>>&);

} // namespace sh

#include "ensembleSolver.H"

#include <cstring>
#include <stdexcept>

namespace sh
{

namespace
{

template<class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b)
{
    return a.size() == b.size()
        && (a.empty() || std::memcmp(a.data(), b.data(), a.size()*sizeof(T)) == 0);
}

template<class Real>
bool sameBits(const Real& a, const Real& b)
{
    return std::memcmp(&a, &b, sizeof(Real)) == 0;
}

} // namespace


template<class Real>
void checkEnsemble(const std::vector<Problem<Real>>& members)
{
    if (members.empty())
    {
        throw std::invalid_argument("ensemble: no members");
    }
    const Problem<Real>& first = members[0];
    if (first.isPart())
    {
        throw std::invalid_argument
        (
            "ensemble: member 0 is a part of a decomposed grid (ensembles"
            " run serial)"
        );
    }
    // Each member's cover as its single run checks it (the backends build
    // the same arrays again, member by member)
    for (std::size_t k = 0; k < members.size(); ++k)
    {
        const Problem<Real>& m = members[k];
        if
        (
            m.hEntrainable.empty() && m.erodedDepth.empty()
         && m.cResistance.empty()
        )
        {
            continue;
        }
        try
        {
            const HostCover<Real> cover(m);
        }
        catch (const InputError& e)
        {
            // what() is "<keyword>: <message>"
            const std::string what = e.what();
            const std::size_t lead = e.keyword().size() + 2;
            throw InputError
            (
                e.keyword(),
                "member " + std::to_string(k) + ": "
              + (what.size() >= lead ? what.substr(lead) : what)
            );
        }
    }
    for (std::size_t k = 1; k < members.size(); ++k)
    {
        const Problem<Real>& m = members[k];
        std::string what;
        const Grid<Real>& a = first.grid;
        const Grid<Real>& b = m.grid;
        if
        (
            a.nx != b.nx || a.ny != b.ny || !sameBits(a.dx, b.dx)
         || !sameBits(a.dy, b.dy) || !sameBits(a.x0, b.x0)
         || !sameBits(a.y0, b.y0) || m.isPart()
        )
        {
            what = "grid";
        }
        else if (std::memcmp(&first.bc, &m.bc, sizeof(first.bc)) != 0)
        {
            what = "boundary conditions";
        }
        else if (!sameBits(first.zeta, m.zeta) || !sameBits(first.kappa, m.kappa))
        {
            what = "reference surface (inclination)";
        }
        else if (!sameBits(first.zb, m.zb))
        {
            what = "topography zb";
        }
        else if (first.params.planTerrain != m.params.planTerrain)
        {
            // The bed's geometry (and on the CUDA backend the kernels)
            // is member 0's
            what = "coordinates (slope or plan)";
        }
        else if (first.startTime != m.startTime)
        {
            what = "start time";
        }
        if (!what.empty())
        {
            throw std::invalid_argument
            (
                "ensemble: member " + std::to_string(k) + " has a different "
              + what + " from member 0 (members differ only in their"
                " parameters, initial state and hazard maps)"
            );
        }
    }
}

template void checkEnsemble(const std::vector<Problem<double>>&);
template void checkEnsemble(const std::vector<Problem<float>>&);

} // namespace sh

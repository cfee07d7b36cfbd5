#include "decomposition.H"

#include <stdexcept>
#include <string>

namespace sh
{

template<class Real>
Problem<Real> subProblem(const Problem<Real>& whole, const Subdomain& s)
{
    const Grid<Real>& G = whole.grid;
    if
    (
        s.nxWhole != G.nx || s.nyWhole != G.ny || G.i0 != 0 || G.j0 != 0
     || s.nx < Grid<Real>::ng || s.ny < Grid<Real>::ng
     || s.i0 < 0 || s.j0 < 0 || s.i0 + s.nx > G.nx || s.j0 + s.ny > G.ny
    )
    {
        throw std::invalid_argument
        (
            "subProblem: subdomain of " + std::to_string(s.nx) + " x "
          + std::to_string(s.ny) + " cells at (" + std::to_string(s.i0)
          + ", " + std::to_string(s.j0) + ") does not fit a whole grid of "
          + std::to_string(G.nx) + " x " + std::to_string(G.ny) + " cells"
        );
    }
    Problem<Real> p = whole;
    p.grid.nx = s.nx;
    p.grid.ny = s.ny;
    p.grid.i0 = s.i0;
    p.grid.j0 = s.j0;
    for (int side = 0; side < 4; ++side)
    {
        if (s.processorSide(side))
        {
            p.bc.type[side] = BCType::processor;
            p.bc.inflow[side] = State<Real>{};
        }
    }

    p.zeta.assign(whole.zeta.begin() + s.i0, whole.zeta.begin() + s.i0 + s.nx);
    p.kappa.assign
    (
        whole.kappa.begin() + s.i0, whole.kappa.begin() + s.i0 + s.nx
    );
    const auto cut = [&](const auto& w, auto& out)
    {
        out.resize(std::size_t(s.nx)*s.ny);
        for (int j = 0; j < s.ny; ++j)
        {
            for (int i = 0; i < s.nx; ++i)
            {
                out[i + std::size_t(j)*s.nx] =
                    w[(s.i0 + i) + std::size_t(s.j0 + j)*G.nx];
            }
        }
    };
    cut(whole.zb, p.zb);
    cut(whole.h, p.h);
    cut(whole.hu, p.hu);
    cut(whole.hv, p.hv);
    const auto cutIfGiven = [&](const auto& w, auto& out)
    {
        if (w.empty())
        {
            return;
        }
        if (w.size() != std::size_t(G.nx)*G.ny)
        {
            throw std::invalid_argument
            (
                "subProblem: a map of the whole problem (hazard map or bed"
                " cover) has "
                + std::to_string(w.size()) + " cells, the grid "
                + std::to_string(std::size_t(G.nx)*G.ny)
            );
        }
        cut(w, out);
    };
    cutIfGiven(whole.peaks.h, p.peaks.h);
    cutIfGiven(whole.peaks.speed, p.peaks.speed);
    cutIfGiven(whole.peaks.pressure, p.peaks.pressure);
    cutIfGiven(whole.peaks.arrival, p.peaks.arrival);
    cutIfGiven(whole.hEntrainable, p.hEntrainable);
    cutIfGiven(whole.erodedDepth, p.erodedDepth);
    cutIfGiven(whole.cResistance, p.cResistance);

    // The jet's first test in local indices (an empty range where its
    // cells lie elsewhere is harmless: the circle test decides)
    JetParams<Real>& jet = p.params.jet;
    jet.iMin -= s.i0;
    jet.iMax -= s.i0;
    jet.jMin -= s.j0;
    jet.jMax -= s.j0;
    return p;
}

template Problem<double> subProblem(const Problem<double>&, const Subdomain&);
template Problem<float> subProblem(const Problem<float>&, const Subdomain&);

template<class Real>
void checkSubdomain
(
    const Problem<Real>& pb,
    Halo<Real>* halo,
    const std::string& backend
)
{
    if (!halo)
    {
        for (int side = 0; side < 4; ++side)
        {
            if (pb.bc.type[side] == BCType::processor)
            {
                throw std::invalid_argument
                (
                    backend + ": the problem has a processor side (a"
                    " subdomain) but no halo to exchange with its"
                    " neighbours"
                );
            }
        }
        return;
    }
    const Subdomain& s = halo->subdomain();
    bool ok =
        s.nx == pb.grid.nx && s.ny == pb.grid.ny
     && s.i0 == pb.grid.i0 && s.j0 == pb.grid.j0
     && s.nx >= Grid<Real>::ng && s.ny >= Grid<Real>::ng;
    for (int side = 0; side < 4; ++side)
    {
        ok = ok
         && s.processorSide(side) == (pb.bc.type[side] == BCType::processor);
    }
    if (halo->anyAll(!ok))
    {
        throw std::invalid_argument
        (
            backend + ": the problem's grid (" + std::to_string(pb.grid.nx)
          + " x " + std::to_string(pb.grid.ny) + " cells at ("
          + std::to_string(pb.grid.i0) + ", " + std::to_string(pb.grid.j0)
          + ")) or its processor sides are not the halo's subdomain"
          + (ok ? std::string(" on another rank") : std::string())
        );
    }
}

template void checkSubdomain
(
    const Problem<double>&, Halo<double>*, const std::string&
);
template void checkSubdomain
(
    const Problem<float>&, Halo<float>*, const std::string&
);

} // namespace sh

#include "problem.H"
#include "modelInput.H"
#include "padded.H"

#include <cmath>
#include <stdexcept>

namespace sh
{

template<class Real>
Problem<Real>::Problem
(
    const Params<Real>& p,
    int nx,
    int ny,
    double xMin,
    double xMax,
    double yMin,
    double yMax
)
:
    params(p)
{
    if (nx < 1 || ny < 1 || !(xMax > xMin) || !(yMax > yMin))
    {
        throw std::invalid_argument("Problem: empty or inverted grid");
    }
    grid.nx = nx;
    grid.ny = ny;
    grid.dx = Real((xMax - xMin)/nx);
    grid.dy = Real((yMax - yMin)/ny);
    grid.x0 = Real(xMin);
    grid.y0 = Real(yMin);
    zeta.assign(nx, Real(0));
    kappa.assign(nx, Real(0));
    zb.assign(std::size_t(nx)*ny, Real(0));
    h.assign(std::size_t(nx)*ny, Real(0));
    hu.assign(std::size_t(nx)*ny, Real(0));
    hv.assign(std::size_t(nx)*ny, Real(0));
}


template<class Real>
void Problem<Real>::setInclination(const std::function<double(double)>& z)
{
    const double dx = grid.dx;
    for (int i = 0; i < grid.nx; ++i)
    {
        const double x = double(grid.x0) + (i + 0.5)*dx;
        const double zx = z(x);
        if (!(std::fabs(zx) < 0.5*3.14159265358979323846))
        {
            throw InputError
            (
                "inclination",
                "zeta(x = " + std::to_string(x) + ") = "
              + std::to_string(zx*180/3.14159265358979323846)
              + " deg: the inclination must lie in (-90, 90) degrees"
            );
        }
        zeta[i] = Real(zx);
        kappa[i] = Real(-(z(x + 0.5*dx) - z(x - 0.5*dx))/dx);
    }
}


template<class Real>
void Problem<Real>::setTopography(const std::function<double(double, double)>& f)
{
    for (int j = 0; j < grid.ny; ++j)
    {
        for (int i = 0; i < grid.nx; ++i)
        {
            zb[cell(i, j)] = Real(f(grid.xc(i), grid.yc(j)));
        }
    }
}


template<class Real>
void Problem<Real>::setState
(
    const std::function<Primitive(double, double)>& f
)
{
    for (int j = 0; j < grid.ny; ++j)
    {
        for (int i = 0; i < grid.nx; ++i)
        {
            const Primitive s = f(grid.xc(i), grid.yc(j));
            const int c = cell(i, j);
            h[c] = Real(s.h);
            hu[c] = Real(s.h*s.u);
            hv[c] = Real(s.h*s.v);
        }
    }
}


template<class Real>
double Problem<Real>::volume() const
{
    double v = 0;
    for (const Real x : h)
    {
        v += double(x);
    }
    return v*double(grid.dx)*double(grid.dy);
}


template<class Real>
HostGeometry<Real>::HostGeometry(const Problem<Real>& pb)
{
    const Grid<Real>& g = pb.grid;
    const int ng = Grid<Real>::ng;
    const int nc = g.stride();
    cosZeta.resize(nc);
    sinZeta.resize(nc);
    kappa.resize(nc);
    for (int k = 0; k < nc; ++k)
    {
        // Ghost columns mirror the interior, like the state
        int i = k - ng;
        if (i < 0) { i = -1 - i; }
        if (i >= g.nx) { i = 2*g.nx - 1 - i; }
        cosZeta[k] = Real(std::cos(double(pb.zeta[i])));
        sinZeta[k] = Real(std::sin(double(pb.zeta[i])));
        kappa[k] = pb.kappa[i];
    }

    // Topography gradient: centred inside, one-sided on the edges
    dzbdx.assign(g.size(), Real(0));
    dzbdy.assign(g.size(), Real(0));
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            const int il = i > 0 ? i - 1 : i;
            const int ih = i < g.nx - 1 ? i + 1 : i;
            const int jl = j > 0 ? j - 1 : j;
            const int jh = j < g.ny - 1 ? j + 1 : j;
            const int c = g.idx(i, j);
            if (ih > il)
            {
                dzbdx[c] = (pb.zb[pb.cell(ih, j)] - pb.zb[pb.cell(il, j)])
                          /(Real(ih - il)*g.dx);
            }
            if (jh > jl)
            {
                dzbdy[c] = (pb.zb[pb.cell(i, jh)] - pb.zb[pb.cell(i, jl)])
                          /(Real(jh - jl)*g.dy);
            }
        }
    }
}

template<class Real>
HostPeaks<Real>::HostPeaks(const Problem<Real>& pb)
{
    const Grid<Real>& g = pb.grid;
    const bool given = pb.hPeak.size() == std::size_t(pb.nCells())
                    && pb.speedPeak.size() == std::size_t(pb.nCells());
    h = given ? toPadded(g, pb.hPeak) : std::vector<Real>(g.size(), Real(0));
    speed =
        given ? toPadded(g, pb.speedPeak) : std::vector<Real>(g.size(), Real(0));

    // Raised to the initial state, as the backends hold it
    std::vector<Real> q[3] =
        {toPadded(g, pb.h), toPadded(g, pb.hu), toPadded(g, pb.hv)};
    Model<Real> m;
    m.p = pb.params;
    m.g = g;
    const Fields<Real> U{q[0].data(), q[1].data(), q[2].data()};
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            updatePeaks(m, U, h.data(), speed.data(), i, j);
        }
    }
}


template struct Problem<double>;
template struct Problem<float>;
template struct HostGeometry<double>;
template struct HostGeometry<float>;
template struct HostPeaks<double>;
template struct HostPeaks<float>;

} // namespace sh

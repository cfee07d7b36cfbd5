#include "problem.H"
#include "modelInput.H"
#include "padded.H"
#include "../parallel/halo.H"
#include "../physics/planTerrain.H"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace sh
{

namespace
{

//- The interior index (0..n-1) a ghost index k mirrors, as the state's
//  ghost cells do (grid.H): -1 <- 0, -2 <- 1, n <- n-1, ..., reflected
//  again while outside, so that a grid one cell wide mirrors that cell
//  into both ghost layers
int mirrored(int k, int n)
{
    while (k < 0 || k >= n)
    {
        k = k < 0 ? -1 - k : 2*n - 1 - k;
    }
    return k;
}

//- Cells are indexed with int (physics/grid.H), ghost layers included:
//  nx x ny cells (`what` names them) must stay below 2^31 with them
template<class Real>
void checkIndexable(int nx, int ny, const std::string& what)
{
    const long long padded =
        (long long)(nx + 2*Grid<Real>::ng)*(ny + 2*Grid<Real>::ng);
    if (padded > 2147483647LL)
    {
        throw std::invalid_argument
        (
            "Problem: " + what + std::to_string(nx) + " x "
          + std::to_string(ny) + " cells is more than the 2^31 - 1 cells"
            " (with two ghost layers) that the grid's int indices reach"
        );
    }
}

//- The whole grid of nx x ny cells on the bounds: its spacing (and
//  reciprocals), origin and counts, formed alike for a whole problem and
//  for a part of it
template<class Real>
void setWholeGrid
(
    Problem<Real>& pb,
    int nx,
    int ny,
    double xMin,
    double xMax,
    double yMin,
    double yMax
)
{
    if (nx < 1 || ny < 1 || !(xMax > xMin) || !(yMax > yMin))
    {
        throw std::invalid_argument("Problem: empty or inverted grid");
    }
    Grid<Real>& g = pb.grid;
    pb.wholeNx = nx;
    pb.wholeNy = ny;
    g.nx = nx;
    g.ny = ny;
    g.dx = Real((xMax - xMin)/nx);
    g.dy = Real((yMax - yMin)/ny);
    g.rdx = Real(1)/g.dx;
    g.rdy = Real(1)/g.dy;
    g.x0 = Real(xMin);
    g.y0 = Real(yMin);
}

//- Columns and cells of the problem's grid, zero
template<class Real>
void allocateArrays(Problem<Real>& pb)
{
    const int nx = pb.grid.nx;
    const std::size_t n = std::size_t(nx)*pb.grid.ny;
    pb.zeta.assign(nx, Real(0));
    pb.kappa.assign(nx, Real(0));
    pb.zb.assign(n, Real(0));
    pb.h.assign(n, Real(0));
    pb.hu.assign(n, Real(0));
    pb.hv.assign(n, Real(0));
}


//- InputError where the jet's input is not finite and bounded, its radii
//  not positive, its speed negative or its stagnation point outside the
//  whole mesh [x0, x1] x [y0, y1]
void checkJetInput
(
    const JetInput& in, double x0, double y0, double x1, double y1
)
{
    const auto num = numberString;
    // Beyond 1e30 the jet's state (R^2, R_imp^2, h u_jet) overflows, as
    // every other input (modelInput.C)
    const auto bounded = [&num](const char* keyword, double x)
    {
        if (!(std::fabs(x) <= 1e30))
        {
            throw InputError
            (
                keyword,
                "must be a finite number of magnitude at most 1e30, got "
              + num(x)
            );
        }
    };
    bounded("centre", in.xc);
    bounded("centre", in.yc);
    bounded("R", in.R);
    bounded("R_imp", in.rImp);
    bounded("u_jet", in.uJet);
    if (!(in.R > 0 && std::isfinite(in.R)))
    {
        throw InputError("R", "jet radius must be positive, got " + num(in.R));
    }
    if (!(in.rImp > 0 && std::isfinite(in.rImp)))
    {
        throw InputError
        (
            "R_imp",
            "radius of the imposed region must be positive, got "
          + num(in.rImp)
        );
    }
    if (!(in.uJet >= 0 && std::isfinite(in.uJet)))
    {
        throw InputError
        (
            "u_jet", "jet speed must not be negative, got " + num(in.uJet)
        );
    }
    if (!(in.xc >= x0 && in.xc <= x1 && in.yc >= y0 && in.yc <= y1))
    {
        throw InputError
        (
            "centre",
            "stagnation point (" + num(in.xc) + " " + num(in.yc)
          + ") lies outside the mesh [" + num(x0) + ", " + num(x1) + "] x ["
          + num(y0) + ", " + num(y1) + "]"
        );
    }
}

} // namespace

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
    setWholeGrid(*this, nx, ny, xMin, xMax, yMin, yMax);
    checkIndexable<Real>(nx, ny, "");
    allocateArrays(*this);
}


template<class Real>
Problem<Real>::Problem
(
    const Params<Real>& p,
    const Subdomain& s,
    double xMin,
    double xMax,
    double yMin,
    double yMax
)
:
    params(p)
{
    // The whole grid's spacing and origin; the part's cells only (the
    // whole grid's arrays are never held)
    setWholeGrid(*this, s.nxWhole, s.nyWhole, xMin, xMax, yMin, yMax);
    if
    (
        s.nx < 1 || s.ny < 1 || s.i0 < 0 || s.j0 < 0
     || s.i0 + s.nx > s.nxWhole || s.j0 + s.ny > s.nyWhole
    )
    {
        throw std::invalid_argument
        (
            "Problem: part of " + std::to_string(s.nx) + " x "
          + std::to_string(s.ny) + " cells at (" + std::to_string(s.i0)
          + ", " + std::to_string(s.j0) + ") of a whole grid of "
          + std::to_string(s.nxWhole) + " x " + std::to_string(s.nyWhole)
        );
    }
    grid.nx = s.nx;
    grid.ny = s.ny;
    grid.i0 = s.i0;
    grid.j0 = s.j0;
    checkIndexable<Real>(s.nx, s.ny, "a part of ");
    for (int side = 0; side < 4; ++side)
    {
        if (s.processorSide(side))
        {
            bc.type[side] = BCType::processor;
        }
    }
    allocateArrays(*this);
}


template<class Real>
void Problem<Real>::setInclination(const std::function<double(double)>& z)
{
    const double pi = 3.14159265358979323846;
    const double dx = grid.dx;
    // zeta at the cell centres and, for the curvature, at the faces: a
    // table may pass 90 degrees between two centres
    const auto angle = [&z, pi](double x)
    {
        const double zx = z(x);
        if (!(std::fabs(zx) < 0.5*pi))
        {
            throw InputError
            (
                "inclination",
                "zeta(x = " + numberString(x) + ") = "
              + numberString(zx*180/pi)
              + " deg: the inclination must lie in (-90, 90) degrees"
            );
        }
        return zx;
    };
    for (int i = 0; i < grid.nx; ++i)
    {
        const double x = double(grid.x0) + (grid.i0 + i + 0.5)*dx;
        const double zx = angle(x);
        zeta[i] = Real(zx);
        kappa[i] = Real(-(angle(x + 0.5*dx) - angle(x - 0.5*dx))/dx);
    }
}


template<class Real>
InputError Problem<Real>::noJetCells(const JetInput& in)
{
    return InputError
    (
        "R_imp",
        "no cell centre lies within R_imp = " + numberString(in.rImp)
      + " of the stagnation point: refine the mesh or enlarge R_imp"
    );
}


template<class Real>
int Problem<Real>::setImpingingJet(const JetInput& in)
{
    const double x0 = grid.x0;
    const double y0 = grid.y0;
    const double x1 = x0 + wholeNx*double(grid.dx);
    const double y1 = y0 + wholeNy*double(grid.dy);
    checkJetInput(in, x0, y0, x1, y1);
    const auto num = numberString;

    JetParams<Real> j;
    j.on = 1;
    j.xc = Real(in.xc);
    j.yc = Real(in.yc);
    j.rImp2 = Real(in.rImp*in.rImp);
    const double cz = std::cos(in.zeta);
    j.hCoeff = Real(0.5*in.R*in.R*cz*cz*cz);
    j.sinZeta = Real(std::sin(in.zeta));
    j.uJet = Real(in.uJet);
    const auto clampI = [](double v, int n)
    {
        return v < 0 ? 0 : (v > n - 1 ? n - 1 : int(v));
    };
    // The whole grid's ranges, in this grid's indices
    j.iMin = clampI(std::floor((in.xc - in.rImp - x0)/grid.dx) - 1, wholeNx)
      - grid.i0;
    j.iMax = clampI(std::ceil((in.xc + in.rImp - x0)/grid.dx) + 1, wholeNx)
      - grid.i0;
    j.jMin = clampI(std::floor((in.yc - in.rImp - y0)/grid.dy) - 1, wholeNy)
      - grid.j0;
    j.jMax = clampI(std::ceil((in.yc + in.rImp - y0)/grid.dy) + 1, wholeNy)
      - grid.j0;

    // h of eq. (38) grows as 1/r: a cell centre next to the stagnation
    // point would get an arbitrarily thick, fast cell
    const double iNear = std::floor((in.xc - x0)/grid.dx);
    const double jNear = std::floor((in.yc - y0)/grid.dy);
    const double dxNear = std::fabs(in.xc - (x0 + (iNear + 0.5)*grid.dx));
    const double dyNear = std::fabs(in.yc - (y0 + (jNear + 0.5)*grid.dy));
    if (std::hypot(dxNear, dyNear) < 0.25*std::min(double(grid.dx), double(grid.dy)))
    {
        throw InputError
        (
            "centre",
            "stagnation point (" + num(in.xc) + " " + num(in.yc)
          + ") lies within a quarter cell of the centre of cell ("
          + num(iNear) + ", " + num(jNear) + "), where h of eq. (38), which"
            " grows as 1/r, is unbounded; put it on a mesh point or a face"
        );
    }

    // The state the backends will impose, computed by the same function
    params.jet = j;
    const int cells = imposeJet();
    if (cells == 0 && !isPart())
    {
        params.jet = JetParams<Real>();
        throw noJetCells(in);
    }
    return cells;
}


template<class Real>
int Problem<Real>::imposeJet()
{
    const JetParams<Real>& j = params.jet;
    if (!j.on)
    {
        return 0;
    }
    // The jet's cells of this grid (on a subdomain, parallel/halo.H, its
    // ranges are the whole grid's shifted and may reach beyond it)
    int inside = 0;
    const int jLo = std::max(j.jMin, 0);
    const int jHi = std::min(j.jMax, grid.ny - 1);
    const int iLo = std::max(j.iMin, 0);
    const int iHi = std::min(j.iMax, grid.nx - 1);
    for (int jj = jLo; jj <= jHi; ++jj)
    {
        for (int i = iLo; i <= iHi; ++i)
        {
            State<Real> q;
            if (!jetState(j, grid, i, jj, q))
            {
                continue;
            }
            // The bound of every initial field (avalancheCase.H): beyond
            // it the scheme's squares overflow
            if (!(std::fabs(double(q.h)) <= 1e30))
            {
                throw InputError
                (
                    "R",
                    "the jet's h of eq. (38), R^2 cos^3(zeta)/(2 r (1 -"
                    " sin(zeta) cos(theta))^2), is " + numberString(q.h)
                  + " in cell (" + std::to_string(i) + ", "
                  + std::to_string(jj) + "), beyond 1e30: R too large, or"
                    " the stagnation point (centre) too close to the cell"
                    " centre"
                );
            }
            if
            (
                !(std::fabs(double(q.hu)) <= 1e30)
             || !(std::fabs(double(q.hv)) <= 1e30)
            )
            {
                throw InputError
                (
                    "u_jet",
                    "the jet's momentum h u_jet is " + numberString(q.hu)
                  + ", " + numberString(q.hv) + " in cell ("
                  + std::to_string(i) + ", " + std::to_string(jj)
                  + "), beyond 1e30"
                );
            }
            const int c = cell(i, jj);
            h[c] = q.h;
            hu[c] = q.hu;
            hv[c] = q.hv;
            ++inside;
        }
    }
    return inside;
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
    // The jet's cells keep its state (a backend may skip empty tiles)
    imposeJet();
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
HostGeometry<Real>::HostGeometry(const Problem<Real>& pb, Halo<Real>* halo)
{
    padColumns(pb, halo);
    padBed(pb, halo);
    if (pb.params.planTerrain)
    {
        planMetrics(pb);
    }
}


template<class Real>
void HostGeometry<Real>::planMetrics(const Problem<Real>& pb)
{
    for (int i = 0; i < pb.grid.nx; ++i)
    {
        if (pb.zeta[i] != Real(0) || pb.kappa[i] != Real(0))
        {
            throw InputError
            (
                "coordinates",
                "plan coordinates take the whole relief from zb: the"
                " inclination must be 0 (zeta = " + numberString(pb.zeta[i])
              + " rad in column " + std::to_string(i) + ")"
            );
        }
    }
    const Grid<Real>& g = pb.grid;
    const int ng = Grid<Real>::ng;
    const int sy = g.stride();
    for (std::vector<Real>* a : {&planP, &planQ, &planBxx, &planBxy, &planByy})
    {
        a->assign(g.size(), Real(0));
    }
    // Sums of mirrored pairs first, so that a transposed or mirrored bed
    // gives the transposed or mirrored values bit for bit
    const double rx = 0.5*double(g.rdx), ry = 0.5*double(g.rdy);
    const double rxx = double(g.rdx)*double(g.rdx);
    const double ryy = double(g.rdy)*double(g.rdy);
    const double rxy = rx*ry;
    for (int j = 1 - ng; j < g.ny + ng - 1; ++j)
    {
        for (int i = 1 - ng; i < g.nx + ng - 1; ++i)
        {
            const int c = g.idx(i, j);
            const double z = zb[c];
            const double w = zb[c - 1], e = zb[c + 1];
            const double s = zb[c - sy], n = zb[c + sy];
            planP[c] = Real((e - w)*rx);
            planQ[c] = Real((n - s)*ry);
            planBxx[c] = Real(((e + w) - 2*z)*rxx);
            planByy[c] = Real(((n + s) - 2*z)*ryy);
            planBxy[c] = Real
            (
                ((double(zb[c + 1 + sy]) + double(zb[c - 1 - sy]))
               - (double(zb[c + 1 - sy]) + double(zb[c - 1 + sy])))*rxy
            );
        }
    }
    // The outer ghost layer: its inner neighbour's values (no stage reads
    // the bed's derivatives there)
    for (int j = -ng; j < g.ny + ng; ++j)
    {
        for (int i = -ng; i < g.nx + ng; ++i)
        {
            const int ii = std::min(std::max(i, 1 - ng), g.nx + ng - 2);
            const int jj = std::min(std::max(j, 1 - ng), g.ny + ng - 2);
            const int c = g.idx(i, j), k = g.idx(ii, jj);
            planP[c] = planP[k];
            planQ[c] = planQ[k];
            planBxx[c] = planBxx[k];
            planBxy[c] = planBxy[k];
            planByy[c] = planByy[k];
        }
    }
    // The metric's scalars, by the function the stages used to form them
    // with: the same values, once
    for (std::vector<Real>* a : {&planJ, &planRJ, &planRJ2, &planRJ1})
    {
        a->assign(g.size(), Real(0));
    }
    for (int c = 0; c < g.size(); ++c)
    {
        const PlanMetric<Real> pm =
            planMetric(planP[c], planQ[c], Real(0), Real(0), Real(0));
        planJ[c] = pm.J;
        planRJ[c] = pm.rJ;
        planRJ2[c] = pm.rJ2;
        planRJ1[c] = pm.rJ1;
    }
}


template<class Real>
void HostGeometry<Real>::padColumns(const Problem<Real>& pb, Halo<Real>* halo)
{
    const Grid<Real>& g = pb.grid;
    const int ng = Grid<Real>::ng;
    const int nc = g.stride();
    const auto physical = [&pb](int side)
    {
        return pb.bc.type[side] != BCType::processor;
    };
    cosZeta.resize(nc);
    sinZeta.resize(nc);
    kappa.resize(nc);
    for (int k = 0; k < nc; ++k)
    {
        // Ghost columns mirror the interior, like the state
        const int i = mirrored(k - ng, g.nx);
        cosZeta[k] = Real(std::cos(double(pb.zeta[i])));
        sinZeta[k] = Real(std::sin(double(pb.zeta[i])));
        kappa[k] = pb.kappa[i];
    }
    if (halo)
    {
        // The neighbours' columns, through padded arrays of the column
        // values (every row alike)
        std::vector<Real> a[3];
        std::vector<Real>* column[3] = {&cosZeta, &sinZeta, &kappa};
        Real* arrays[3];
        for (int n = 0; n < 3; ++n)
        {
            a[n].resize(g.size());
            for (int j = -ng; j < g.ny + ng; ++j)
            {
                for (int i = -ng; i < g.nx + ng; ++i)
                {
                    a[n][g.idx(i, j)] = (*column[n])[i + ng];
                }
            }
            arrays[n] = a[n].data();
        }
        halo->exchange(0, arrays, 3, ng);
        for (int n = 0; n < 3; ++n)
        {
            std::vector<Real>& c = *column[n];
            for (int k = 1; k <= ng; ++k)
            {
                if (!physical(xMin)) { c[ng - k] = a[n][g.idx(-k, 0)]; }
                if (!physical(xMax))
                {
                    c[g.nx - 1 + k + ng] = a[n][g.idx(g.nx - 1 + k, 0)];
                }
            }
        }
    }

}


template<class Real>
void HostGeometry<Real>::padBed(const Problem<Real>& pb, Halo<Real>* halo)
{
    const Grid<Real>& g = pb.grid;
    const int ng = Grid<Real>::ng;
    const auto physical = [&pb](int side)
    {
        return pb.bc.type[side] != BCType::processor;
    };

    // Topography on the padded grid.  Beyond a wall the ghost cells mirror
    // the interior (ghost -1 <- cell 0, ghost -2 <- cell 1), as the
    // state's do, so that a lake at rest meets a wall at rest; beyond an
    // open side (transmissive, inflow) the bed continues linearly, so that
    // the cells next to it feel its slope (a mirrored bed would give them
    // a flat reconstructed bed, physics/reconstruction.H).  x-sides first, then
    // y-sides over whole padded rows (the corners); beyond a processor
    // side, the neighbour's cells, in the same order.
    zb.assign(g.size(), Real(0));
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            zb[g.idx(i, j)] = pb.zb[pb.cell(i, j)];
        }
    }
    const auto ghostBed = [&](int side, int n, int k, auto at)
    {
        // k = -1, -2 (low side) or n, n + 1 (high side); at(m): the bed of
        // interior index m along the side's direction
        const int m = mirrored(k, n);
        if (pb.bc.type[side] == BCType::wall || n < 2)
        {
            return at(m);
        }
        const int e = k < 0 ? 0 : n - 1;        // the edge cell
        const int e1 = k < 0 ? 1 : n - 2;       // its inner neighbour
        const Real d = Real(k < 0 ? -k : k - (n - 1));
        return at(e) + d*(at(e) - at(e1));
    };
    Real* bed[1] = {zb.data()};
    for (int j = 0; j < g.ny; ++j)
    {
        const auto row = [&](int m) { return zb[g.idx(m, j)]; };
        for (int k = 1; k <= ng; ++k)
        {
            if (physical(xMin))
            {
                zb[g.idx(-k, j)] = ghostBed(xMin, g.nx, -k, row);
            }
            if (physical(xMax))
            {
                zb[g.idx(g.nx - 1 + k, j)] =
                    ghostBed(xMax, g.nx, g.nx - 1 + k, row);
            }
        }
    }
    if (halo)
    {
        halo->exchange(0, bed, 1, ng);
    }
    for (int i = -ng; i < g.nx + ng; ++i)
    {
        const auto col = [&](int m) { return zb[g.idx(i, m)]; };
        for (int k = 1; k <= ng; ++k)
        {
            if (physical(yMin))
            {
                zb[g.idx(i, -k)] = ghostBed(yMin, g.ny, -k, col);
            }
            if (physical(yMax))
            {
                zb[g.idx(i, g.ny - 1 + k)] =
                    ghostBed(yMax, g.ny, g.ny - 1 + k, col);
            }
        }
    }
    if (halo)
    {
        halo->exchange(1, bed, 1, ng);
    }
}

template<class Real>
bool squaredSpeedPeak
(
    const Real speed,
    const Real pressure,
    const Real rho,
    const bool hasPressure,
    Real& S
)
{
    const Real inf = std::numeric_limits<Real>::infinity();
    const auto fits = [speed](Real s) { return std::sqrt(s) == speed; };

    // One S with sqrt(S) == speed: speed^2 (in binary floating point
    // sqrt(speed^2) == speed, barring overflow), else its neighbours
    Real s = speed*speed;
    for (int k = 0; k < 4 && !fits(s); ++k)
    {
        s = std::nextafter(s, std::sqrt(s) < speed ? inf : Real(0));
    }
    if (!fits(s))
    {
        S = speed*speed;
        return false;
    }
    // The interval of such S (a few values)
    Real lo = s, hi = s;
    for (int k = 0; k < 16 && lo > Real(0) && fits(std::nextafter(lo, Real(0))); ++k)
    {
        lo = std::nextafter(lo, Real(0));
    }
    for (int k = 0; k < 16 && fits(std::nextafter(hi, inf)); ++k)
    {
        hi = std::nextafter(hi, inf);
    }
    S = s;
    if (!hasPressure || !(rho > Real(0)))
    {
        return false;
    }
    for (Real x = lo; x <= hi; x = std::nextafter(x, inf))
    {
        if (rho*x == pressure)
        {
            S = x;
            return true;
        }
    }
    S = std::min(std::max(Real(pressure/rho), lo), hi);
    return false;
}


template<class Real>
HostPeaks<Real>::HostPeaks
(
    const Problem<Real>& pb,
    const HostGeometry<Real>* geo
)
{
    if (pb.params.planTerrain && !geo)
    {
        throw std::invalid_argument
        (
            "HostPeaks: plan mode needs the problem's geometry"
        );
    }
    const Grid<Real>& g = pb.grid;
    const std::size_t n = std::size_t(pb.nCells());
    const PeakMaps<Real>& in = pb.peaks;
    const bool given = in.h.size() == n && in.speed.size() == n;
    const bool withPressure = given && in.pressure.size() == n;
    const bool withArrival = given && in.arrival.size() == n;
    const Real rho = pb.params.rho;
    h.assign(g.size(), Real(0));
    speed2.assign(g.size(), Real(0));
    arrival.assign(g.size(), -1.0f);
    for (int j = 0; j < g.ny && given; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            const int k = pb.cell(i, j);
            const int c = g.idx(i, j);
            h[c] = in.h[k];
            Real S = 0;
            const bool matched = squaredSpeedPeak
            (
                in.speed[k], withPressure ? in.pressure[k] : Real(0), rho,
                withPressure, S
            );
            pressuresIgnored += withPressure && rho > Real(0) && !matched;
            speed2[c] = S;
            if (withArrival)
            {
                arrival[c] = in.arrival[k];
            }
            if (h[c] > pb.params.arrivalThreshold && !(arrival[c] >= 0))
            {
                arrival[c] = float(pb.startTime);
                ++arrivalsSet;
            }
        }
    }

    // Raised to the initial state, as the backends hold it
    std::vector<Real> q[3] =
        {toPadded(g, pb.h), toPadded(g, pb.hu), toPadded(g, pb.hv)};
    Model<Real> m;
    m.p = pb.params;
    m.g = g;
    if (geo)
    {
        m.geo = geo->view();
        m.plan = geo->planView();
    }
    const Fields<Real> U{q[0].data(), q[1].data(), q[2].data()};
    const PeakFields<Real> P = view();
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            if (m.p.planTerrain)
            {
                PlanStages::peaks(m, U, P, pb.startTime, i, j);
            }
            else
            {
                SlopeStages::peaks(m, U, P, pb.startTime, i, j);
            }
        }
    }
}


template<class Real>
PeakMaps<Real> HostPeaks<Real>::maps
(
    const Grid<Real>& g,
    const Params<Real>& p,
    const Real* hPad,
    const Real* speed2Pad,
    const float* arrivalPad
)
{
    PeakMaps<Real> r;
    maps(g, p, hPad, speed2Pad, arrivalPad, r);
    return r;
}


template<class Real>
void HostPeaks<Real>::maps
(
    const Grid<Real>& g,
    const Params<Real>& p,
    const Real* hPad,
    const Real* speed2Pad,
    const float* arrivalPad,
    PeakMaps<Real>& r
)
{
    toInterior(g, hPad, r.h);
    toInterior(g, speed2Pad, r.speed);
    toInterior(g, arrivalPad, r.arrival);
    const long n = long(r.speed.size());
    const bool pressure = p.rho > Real(0);
    r.pressure.resize(pressure ? r.speed.size() : 0);
    #pragma omp parallel for schedule(static)
    for (long k = 0; k < n; ++k)
    {
        if (pressure)
        {
            r.pressure[k] = p.rho*r.speed[k];
        }
        r.speed[k] = std::sqrt(r.speed[k]);
    }
}


// * * * * * * * * * * * * * * * * HostCover * * * * * * * * * * * * * * * //

namespace
{

//- A cover array of the problem on the padded grid (zero in the ghost
//  cells and everywhere where the problem gives none); InputError
//  (keyword) on a wrong size or a value negative or beyond 1e30
template<class Real>
void padCover
(
    const Problem<Real>& pb,
    const std::vector<Real>& in,
    const char* keyword,
    std::vector<Real>& out
)
{
    const Grid<Real>& g = pb.grid;
    out.assign(g.size(), Real(0));
    if (in.empty())
    {
        return;
    }
    if (in.size() != std::size_t(pb.nCells()))
    {
        throw InputError
        (
            keyword,
            "has " + std::to_string(in.size()) + " values for "
          + std::to_string(pb.nCells()) + " cells"
        );
    }
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            const Real v = in[pb.cell(i, j)];
            if (!(v >= Real(0) && v <= Real(1e30)))
            {
                throw InputError
                (
                    keyword,
                    "must be >= 0 and at most 1e30, got "
                  + numberString(double(v)) + " in cell ("
                  + std::to_string(g.i0 + i) + ", "
                  + std::to_string(g.j0 + j) + ")"
                );
            }
            out[g.idx(i, j)] = v;
        }
    }
}

} // namespace


template<class Real>
HostCover<Real>::HostCover(const Problem<Real>& pb)
{
    std::vector<Real> l, e;
    padCover(pb, pb.hEntrainable, "hEntrainable", l);
    padCover(pb, pb.erodedDepth, "erodedDepth", e);
    if (pb.params.entrainment.on())
    {
        layer.swap(l);
        eroded.swap(e);
    }
    if (!pb.cResistance.empty())
    {
        padCover(pb, pb.cResistance, "cResistance", cResistance);
    }
}


template<class Real>
void HostCover<Real>::addVolumes
(
    const Grid<Real>& g,
    const Real* layer,
    const Real* eroded,
    Diagnostics& d
)
{
    double sl = 0, se = 0;
    for (int j = 0; j < g.ny; ++j)
    {
        for (int i = 0; i < g.nx; ++i)
        {
            const int c = g.idx(i, j);
            sl += layer ? double(layer[c]) : 0.0;
            se += eroded ? double(eroded[c]) : 0.0;
        }
    }
    d.layerVolume = sl*double(g.dx)*double(g.dy);
    d.erodedVolume = se*double(g.dx)*double(g.dy);
}


template struct Problem<double>;
template struct Problem<float>;
template<class Real>
bool HostGeometry<Real>::constantBed() const
{
    for (const Real z : zb)
    {
        if (!(z == zb[0]))
        {
            return false;
        }
    }
    return true;
}


template struct HostGeometry<double>;
template struct HostGeometry<float>;
template struct HostPeaks<double>;
template struct HostPeaks<float>;
template struct HostCover<double>;
template struct HostCover<float>;
template bool squaredSpeedPeak(double, double, double, bool, double&);
template bool squaredSpeedPeak(float, float, float, bool, float&);

} // namespace sh

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    What an ensemble run writes besides its members' fields (ensembleRun):
    the statistics over the members (peaks, exceedance probabilities, the
    summary) and ensemble/report.dat.
\*---------------------------------------------------------------------------*/

#include "ensembleRun.H"
#include "OFstream.H"
#include "IOdictionary.H"

// The runout definition hazardMaps' report uses, and the terrain cases'
// reference surface (plain C++ headers of the utilities)
#include "../../../utilities/hazardMaps/runoutDefinition.H"
#include "../../../utilities/terrain/referenceSurface.H"
#include "../../../utilities/terrain/planFrame.H"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace Foam
{

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

template<class Real>
void ensembleRun<Real>::peakValues
(
    std::vector<double>& hv,
    std::vector<double>& uv,
    std::vector<double>& pv
) const
{
    const label nc = ac_.h.size();
    const bool pressure = ac_.pMax.valid();
    hv.assign(std::size_t(nc)*n_, 0);
    uv.assign(hv.size(), 0);
    pv.assign(pressure ? hv.size() : 0, 0);
    for (label k = 0; k < n_; ++k)
    {
        const sh::PeakMaps<Real> p = solver_->peakMaps(k);
        forAll(ac_.h, c)
        {
            const label i = ac_.smesh.gridIndex(c);
            const std::size_t at = std::size_t(c)*n_ + k;
            hv[at] = double(p.h[i]);
            uv[at] = double(p.speed[i]);
            if (pressure)
            {
                pv[at] = double(p.pressure[i]);
            }
        }
    }
}


namespace
{

//- A statistic's field name: prefix and x as "%g"
word named(const char* prefix, const scalar x)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%g", prefix, x);
    return word(buf);
}

} // namespace


template<class Real>
label ensembleRun<Real>::addField
(
    PtrList<volScalarField>& fields,
    const word& name,
    const dimensionSet& dims
) const
{
    fields.append
    (
        new volScalarField
        (
            IOobject
            (
                name, runTime_.timeName(), ac_.mesh,
                IOobject::NO_READ, IOobject::AUTO_WRITE
            ),
            ac_.mesh,
            dimensionedScalar(name, dims, 0),
            "zeroGradient"
        )
    );
    return fields.size() - 1;
}


template<class Real>
void ensembleRun<Real>::addExceedances
(
    PtrList<volScalarField>& fields,
    const std::vector<double>& hv
) const
{
    const label nc = ac_.h.size();
    forAll(ens_.thresholds, q)
    {
        const scalar thr = ens_.thresholds[q];
        const label f = addField(fields, named("hMaxExceedance_", thr), dimless);
        for (label c = 0; c < nc; ++c)
        {
            label above = 0;
            for (label k = 0; k < n_; ++k)
            {
                above += hv[std::size_t(c)*n_ + k] > thr;
            }
            fields[f][c] = scalar(above)/n_;
        }
    }
}


template<class Real>
void ensembleRun<Real>::addSummary
(
    PtrList<volScalarField>& fields,
    const std::vector<double>& all,
    const word& name,
    const dimensionSet& dims
) const
{
    const label nc = ac_.h.size();
    std::vector<double> v(n_);
    const label mean = addField(fields, name + "Mean", dims);
    List<label> pct(ens_.percentiles.size());
    forAll(pct, q)
    {
        pct[q] = addField(fields, named((name + "P").c_str(), ens_.percentiles[q]), dims);
    }
    for (label c = 0; c < nc; ++c)
    {
        double sum = 0;
        for (label k = 0; k < n_; ++k)
        {
            v[k] = all[std::size_t(c)*n_ + k];
            sum += v[k];
        }
        fields[mean][c] = sum/n_;
        std::sort(v.begin(), v.end());
        forAll(pct, q)
        {
            const double r = ens_.percentiles[q]/100*(n_ - 1);
            const label lo = std::min(label(std::floor(r)), n_ - 1);
            const label hi = std::min(lo + 1, n_ - 1);
            fields[pct[q]][c] = v[lo] + (r - lo)*(v[hi] - v[lo]);
        }
    }
}


template<class Real>
void ensembleRun<Real>::writeStatistics()
{
    // Per cell the members' values (member fastest)
    std::vector<double> hv, uv, pv;
    peakValues(hv, uv, pv);

    PtrList<volScalarField> fields;
    addExceedances(fields, hv);
    addSummary(fields, hv, "hMax", dimLength);
    addSummary(fields, uv, "UMax", dimVelocity);
    if (ac_.pMax.valid())
    {
        addSummary(fields, pv, "pMax", dimPressure);
    }
    for (volScalarField& f : fields)
    {
        f.correctBoundaryConditions();
    }

    // Only these: the case's own fields are left out of this write
    List<regIOobject*> quiet
    ({
        &ac_.h, &ac_.U, &ac_.hU, &ac_.regime, &ac_.hMax, &ac_.UMax,
        &ac_.tArrival
    });
    if (ac_.pMax.valid())
    {
        quiet.append(ac_.pMax.get());
    }
    for (regIOobject* f : quiet)
    {
        f->writeOpt() = IOobject::NO_WRITE;
    }
    statsWriter_->write();
    for (regIOobject* f : quiet)
    {
        f->writeOpt() = IOobject::AUTO_WRITE;
    }
}


template<class Real>
void ensembleRun<Real>::position
(
    const sh::Problem<Real>& pb,
    const label i,
    const label j,
    double& E,
    double& X
) const
{
    const double zeta = double(pb.zeta[i]);
    const double zb = double(pb.zb[pb.cell(i, j)]);
    E = E0_[i] + zb*std::cos(zeta);
    X = X0_[i] - zb*std::sin(zeta);
}


template<class Real>
void ensembleRun<Real>::surfacePositions(const sh::Problem<Real>& pb)
{
    const label nx = pb.grid.nx;
    const double dx = double(pb.grid.dx);
    E0_.resize(nx);
    X0_.resize(nx);
    double e = 0, x = 0;
    for (label i = 0; i < nx; ++i)
    {
        const double z = double(pb.zeta[i]);
        E0_[i] = e - 0.5*dx*std::sin(z);
        X0_[i] = x + 0.5*dx*std::cos(z);
        e -= dx*std::sin(z);
        x += dx*std::cos(z);
    }
}


namespace
{

//- The world position of a cell's bed, as hazardMaps places it: on a
//  terrain case of the axis mode the reference surface of
//  constant/terrainMapping; in plan coordinates (coordinates plan) the
//  plan grid's map (origin, xAxis, yAxis of constant/terrainMapping where
//  the case has one, else the case's own x, y) and zb; elsewhere the
//  unfolded inclination (X, y, E)
struct bedWorld
{
    bool terrain = false;
    bool plan = false;
    terrain::referenceSurface surface;
    planGrid grid{{0, 0}, {1, 0}, {0, 1}, 0, 0, 0};

    bedWorld(const Time& runTime, const bool planCoordinates)
    :
        plan(planCoordinates)
    {
        IOobject io
        (
            "terrainMapping", "constant", runTime,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
        );
        if (!io.typeHeaderOk<IOdictionary>(true))
        {
            return;
        }
        const IOdictionary dict(io);
        if (plan)
        {
            if (dict.getOrDefault<word>("mode", "axis") == "plan")
            {
                const vector2D o = dict.get<vector2D>("origin");
                const vector2D ax = dict.get<vector2D>("xAxis");
                const vector2D ay = dict.get<vector2D>("yAxis");
                grid.origin = {o.x(), o.y()};
                grid.xAxis = {ax.x(), ax.y()};
                grid.yAxis = {ay.x(), ay.y()};
                terrain = true;
            }
            return;
        }
        if (dict.getOrDefault<word>("mode", "axis") != "axis")
        {
            return;
        }
        const List<vector2D> table =
            dict.get<List<vector2D>>("inclination");
        std::vector<double> xT, zT;
        for (const vector2D& p : table)
        {
            xT.push_back(p.x());
            zT.push_back(p.y());
        }
        const vector o = dict.get<vector>("origin");
        const vector2D t = dict.get<vector2D>("tangent");
        surface = terrain::referenceSurface
        (
            {o.x(), o.y(), o.z()}, t.x(), t.y(), xT, zT
        );
        terrain = true;
    }
};


const bedWorld& worldOf(const Time& runTime, const bool plan)
{
    static const bedWorld w(runTime, plan);
    return w;
}


//- The world point of cell c's bed (bedWorld), position(i, j, E, X) the
//  unfolded inclination's elevation and horizontal position
template<class Real, class Position>
runoutDefinition::vec3 bedPoint
(
    const bedWorld& bw,
    const avalancheCase& ac,
    const sh::Problem<Real>& pb,
    const long c,
    const Position& position
)
{
    const point& P = ac.mesh.C()[c];
    const label g = ac.smesh.gridIndex(c);
    const double zb = double(pb.zb[g]);
    if (bw.plan)
    {
        const std::array<double, 2> W = bw.grid.world(P.x(), P.y());
        return {W[0], W[1], zb};
    }
    if (bw.terrain)
    {
        return bw.surface.world(P.x(), P.y(), zb);
    }
    double E, X;
    position(g % pb.grid.nx, g/pb.grid.nx, E, X);
    return {X, P.y(), E};
}

} // namespace


template<class Real>
FixedList<double, 3> ensembleRun<Real>::releaseTop(const sh::Problem<Real>& pb) const
{
    // The world point of the highest released bed (runoutDefinition.H),
    // Z = -1e300 when nothing is released
    const bedWorld& bw = worldOf(runTime_, ac_.input.plan());
    const volVectorField& C = ac_.mesh.C();
    const label nx = pb.grid.nx;
    const auto world = [&](long c)
    {
        return bedPoint(bw, ac_, pb, c, [&](label i, label j, double& E, double& X)
        {
            position(pb, i, j, E, X);
        });
    };
    const runoutDefinition::result r = runoutDefinition::runoutOf
    (
        ac_.h.size(), 0, 1, nx, pb.grid.ny,
        [&](long c) { return C[c].x(); },
        [](long) { return 0.0; },
        [&](long c) { return double(pb.h[ac_.smesh.gridIndex(c)]); },
        [](long) { return 1L; },
        [](long) { return 1L; },
        world
    );
    FixedList<double, 3> top({0, 0, -1e300});
    if (r.released)
    {
        top = {r.top[0], r.top[1], r.top[2]};
    }
    return top;
}


template<class Real>
void ensembleRun<Real>::writeReport()
{
    const sh::Problem<Real>& pb0 = problems_[0];
    const label nx = pb0.grid.nx;
    const label ny = pb0.grid.ny;
    const double dx = double(pb0.grid.dx);
    const double dy = double(pb0.grid.dy);
    const double thr = ens_.runoutThreshold;
    const bedWorld& bw = worldOf(runTime_, ac_.input.plan());
    const volVectorField& C = ac_.mesh.C();

    OFstream os(runTime_.path()/"ensemble"/"report.dat");
    os.precision(10);
    os  << "# savageHutterFoam -ensemble: " << n_ << " members, t = "
        << runTime_.timeName() << nl
        << "# the definitions of hazardMaps' report (runoutDefinition.H),"
        << " threshold runoutThreshold " << thr << " m on hMax: runout"
        << " point the bed of the cell with hMax > threshold "
        << (
               bw.plan
             ? "horizontally furthest from the highest released bed"
             : "furthest along the slope (x; of those the largest hMax)"
           )
        << "; travel angle atan(drop / horizontal distance) from the"
        << " highest released bed (h > 0 at the start) to it [deg]" << nl
        << "# coordinates: "
        << (
               bw.plan
             ? (
                   bw.terrain
                 ? "world (the plan grid of constant/terrainMapping: X ="
                   " origin + x xAxis + y yAxis, Z = zb), as hazardMaps"
                   " writes them"
                 : "the case's plan coordinates (x, y, Z = zb; no"
                   " constant/terrainMapping)"
               )
             : bw.terrain
             ? "world (constant/terrainMapping), as hazardMaps writes them"
             : "X horizontal along the unfolded inclination, Y = y,"
               " Z elevation"
           ) << nl
        << "# units (the case's; m unless g says otherwise): releasedVolume, volume [m^3]; runoutX, runoutY,"
        << " runoutZ [m]; travelAngle [deg]; reachesBoundary 1 if a cell of"
        << " the mesh's outermost ring has hMax > threshold, else 0";
    // With an entrainment model (the case's, every member's): the volume
    // each member has taken up from its erodible layer, sum of its eroded
    // depth dA (hazardMaps' entrainedVolume)
    const bool entraining = pb0.params.entrainment.on();
    if (entraining)
    {
        os  << "; entrainedVolume [m^3] the eroded depth's volume, so that"
            << " releasedVolume + entrainedVolume = volume + what left"
            << " through open sides";
    }
    os  << nl << "# member";
    for (const word& k : ens_.keys) { os << ' ' << k; }
    if (ens_.variesHScale) { os << " hScale"; }
    if (ens_.variesCResistance) { os << " cResistanceScale"; }
    if (ens_.variesRelease) { os << " release"; }
    os  << " releasedVolume volume runoutX runoutY travelAngle steps"
        << " runoutZ reachesBoundary" << (entraining ? " entrainedVolume" : "")
        << nl;
    for (label k = 0; k < n_; ++k)
    {
        const sh::Problem<Real>& pb = problems_[k];
        const sh::PeakMaps<Real> p = solver_->peakMaps(k);
        const auto world = [&](long c)
        {
            return bedPoint(bw, ac_, pb, c, [&](label i, label j, double& E, double& X)
        {
            position(pb, i, j, E, X);
        });
        };
        const runoutDefinition::vec3 top{top_[k][0], top_[k][1], top_[k][2]};
        const auto hMaxOf = [&](long c)
        {
            return double(p.h[ac_.smesh.gridIndex(c)]);
        };
        const auto iOf = [&](long c)
        {
            return long(ac_.smesh.gridIndex(c) % nx);
        };
        const auto jOf = [&](long c)
        {
            return long(ac_.smesh.gridIndex(c)/nx);
        };
        runoutDefinition::result r;
        if (bw.plan)
        {
            // Horizontally furthest from the member's top of the release
            r.released = top[2] > -1e300;
            r.top = top;
            runoutDefinition::planRunoutFrom
            (
                r, ac_.h.size(), thr, nx, ny, hMaxOf, iOf, jOf, world
            );
        }
        else
        {
            r = runoutDefinition::runoutOf
            (
                ac_.h.size(), thr, dx, nx, ny,
                [&](long c) { return C[c].x(); },
                hMaxOf, [](long) { return 0.0; }, iOf, jOf, world
            );
        }
        const bool moved = top[2] > -1e300 && r.reached;
        const double angle =
            moved ? runoutDefinition::travelAngle(top, r.point) : 0;
        std::vector<Real> h, hu, hv;
        solver_->getState(k, h, hu, hv);
        double vol = 0;
        for (const Real hc : h) { vol += double(hc); }
        vol *= dx*dy;

        os  << k;
        const ensembleInput::member& m = ens_.members[k];
        for (const scalar v : m.values) { os << ' ' << v; }
        if (ens_.variesHScale) { os << ' ' << m.hScale; }
        if (ens_.variesCResistance) { os << ' ' << m.cResistanceScale; }
        if (ens_.variesRelease) { os << ' ' << m.release; }
        // Volumes to 10 significant digits; the runout point and the
        // angle to the digits of hazardMaps' report (15 in plan
        // coordinates, whose world coordinates may be large)
        const int digits = bw.plan ? 15 : 10;
        os  << ' ' << released_[k] << ' ' << vol << ' ';
        os.precision(digits);
        os  << (moved ? r.point[0] : 0) << ' '
            << (moved ? r.point[1] : 0) << ' '
            << angle << ' ' << steps0_[k] + solver_->steps(k) << ' '
            << (moved ? r.point[2] : 0) << ' '
            << (r.reachesBoundary ? 1 : 0);
        os.precision(10);
        if (entraining)
        {
            std::vector<Real> layer, eroded;
            solver_->getCover(k, layer, eroded);
            double taken = 0;
            for (const Real e : eroded) { taken += double(e); }
            os  << ' ' << taken*dx*dy;
        }
        os  << nl;
    }
    Info<< "Wrote " << os.name() << nl;
}



// * * * * * * * * * * * * * * Instantiations  * * * * * * * * * * * * * * * //

template class ensembleRun<float>;
template class ensembleRun<double>;

} // End namespace Foam

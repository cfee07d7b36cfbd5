/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "planReport.H"
#include "runoutReport.H"
#include "zbGradient.H"
#include "OFstream.H"
#include "unitConversion.H"

#include <cmath>
#include <fstream>
#include <sstream>

namespace Foam
{

namespace
{

//- J = sqrt(1 + |grad zb|^2) per mesh cell, the gradient on the plan grid
scalarField bedMetric
(
    const fvMesh& mesh, const hazardTerrain& t, const volScalarField& zb
)
{
    const labelList cellOf = gridCells(mesh, t);
    scalarField zg(cellOf.size(), 0);
    forAll(cellOf, k)
    {
        zg[k] = zb[cellOf[k]];
    }
    scalarField J(mesh.nCells(), 1);
    for (label j = 0; j < t.ny; ++j)
    {
        for (label i = 0; i < t.nx; ++i)
        {
            const vector2D G = zbGradient(zg, t.nx, t.ny, t.cellSize, i, j);
            J[cellOf[i + t.nx*j]] = std::sqrt(1 + G.x()*G.x() + G.y()*G.y());
        }
    }
    return J;
}


//- The world bed point (X, Y, zb) of a cell centre C
terrain::vec3 bedPoint(const planGrid& g, const point& C, scalar zb)
{
    const std::array<double, 2> W = g.world(C.x(), C.y());
    return {W[0], W[1], zb};
}


//- The volume sum J h A and its centre (at the bed points)
struct massCentre
{
    scalar volume = 0;
    terrain::vec3 W{0, 0, 0};
};

massCentre centreOf
(
    const hazardTerrain& t, const scalarField& J, const volScalarField& h,
    const volScalarField& zb
)
{
    const volVectorField& C = h.mesh().C();
    const scalar A = t.cellSize*t.cellSize;
    massCentre m;
    forAll(C, c)
    {
        const scalar v = J[c]*h[c]*A;
        const terrain::vec3 P = bedPoint(t.grid, C[c], zb[c]);
        m.volume += v;
        for (int k = 0; k < 3; ++k)
        {
            m.W[k] += v*P[k];
        }
    }
    for (int k = 0; k < 3; ++k)
    {
        m.W[k] = m.volume > 0 ? m.W[k]/m.volume : 0;
    }
    return m;
}


fileName comFile(const fvMesh& mesh)
{
    return mesh.time().path()/"postProcessing"/"centreOfMass.dat";
}


//- Whether time a is not after time b (to round-off of the names)
bool notAfter(scalar a, scalar b)
{
    return a <= b + 1e-12*max(scalar(1), mag(b));
}


//- The points of postProcessing/centreOfMass.dat: (time, x, y, z)
typedef std::array<double, 4> comSample;

std::vector<comSample> readComFile(const fileName& file)
{
    std::ifstream is(file);
    std::vector<comSample> s;
    std::string line;
    for (label n = 1; std::getline(is, line); ++n)
    {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
        {
            continue;
        }
        std::istringstream ls(line);
        comSample p;
        const bool read = bool(ls >> p[0] >> p[1] >> p[2] >> p[3]);
        if
        (
            !read || !std::isfinite(p[0]) || !std::isfinite(p[1])
         || !std::isfinite(p[2]) || !std::isfinite(p[3])
         || (!s.empty() && !(p[0] > s.back()[0]))
        )
        {
            FatalErrorInFunction
                << file << " line " << n << ": " << line << " is not"
                << " 'time x y z' (finite numbers, times increasing)" << nl
                << "Nothing written." << nl << exit(FatalError);
        }
        s.push_back(p);
    }
    if (s.empty())
    {
        FatalErrorInFunction
            << file << ": no line 'time x y z'" << nl
            << "Nothing written." << nl << exit(FatalError);
    }
    return s;
}


//- The centre of mass' path up to time now and where it comes from
struct comPath
{
    std::vector<terrain::vec3> points;
    std::string from;
};

comPath comPathOf
(
    const hazardTerrain& t, const hazardTimes& times, const instant& now,
    const scalarField& J, const volScalarField& zb
)
{
    const fvMesh& mesh = zb.mesh();
    comPath path;
    if (isFile(comFile(mesh)))
    {
        for (const comSample& p : readComFile(comFile(mesh)))
        {
            if (notAfter(p[0], now.value()))
            {
                path.points.push_back({p[1], p[2], p[3]});
            }
        }
        path.from = "postProcessing/centreOfMass.dat";
        return path;
    }
    for (const instant& ti : times.numeric)
    {
        if (notAfter(ti.value(), now.value()))
        {
            const volScalarField h(fieldIO(mesh, ti.name(), "h"), mesh);
            const massCentre m = centreOf(t, J, h, zb);
            if (m.volume > 0)
            {
                path.points.push_back(m.W);
            }
        }
    }
    path.from = "the time directories";
    return path;
}


//- The horizontal length of a polyline
scalar pathLength(const std::vector<terrain::vec3>& p)
{
    scalar s = 0;
    for (std::size_t k = 1; k < p.size(); ++k)
    {
        s += std::hypot(p[k][0] - p[k-1][0], p[k][1] - p[k-1][1]);
    }
    return s;
}


//- The highest released point and the runout point: the bed point of the
//  cell with hMax > threshold horizontally furthest from it, and whether
//  the flow reaches the grid's outermost ring (runoutDefinition.H's plan
//  definition, shared with savageHutterFoam -ensemble's report)
struct planRunout
{
    terrain::vec3 top{0, 0, -GREAT};
    terrain::vec3 point{0, 0, 0};
    bool reachesBoundary = false;
};

planRunout runoutOf
(
    scalar threshold, const hazardTerrain& t, const volScalarField& h0,
    const hazardFields& fields
)
{
    const volVectorField& C = h0.mesh().C();
    const volScalarField& zb = fields.zb;
    const scalar cs = t.cellSize;
    const runoutDefinition::result def = runoutDefinition::planRunoutOf
    (
        C.size(), threshold, t.nx, t.ny,
        [&](long c) { return fields.hMax[c]; },
        [&](long c) { return h0[c]; },
        [&](long c) { return long(std::floor(C[c].x()/cs)); },
        [&](long c) { return long(std::floor(C[c].y()/cs)); },
        [&](long c) { return bedPoint(t.grid, C[c], zb[c]); }
    );
    planRunout r;
    if (def.released)
    {
        r.top = def.top;
    }
    r.point = def.point;
    r.reachesBoundary = def.reachesBoundary;
    return r;
}

} // End anonymous namespace


void checkComPath(const fvMesh& mesh, const hazardTimes& times)
{
    const instant& last = times.chosen.last();
    if (isFile(comFile(mesh)))
    {
        const scalar start = readComFile(comFile(mesh)).front()[0];
        if (!notAfter(start, times.chosen.first().value()))
        {
            FatalErrorInFunction
                << comFile(mesh) << " starts at time " << start
                << ", after the chosen time " << times.chosen.first().name()
                << ": no centre of mass' path up to it" << nl
                << "Nothing written." << nl << exit(FatalError);
        }
        return;
    }
    for (const instant& ti : times.numeric)
    {
        if
        (
            notAfter(ti.value(), last.value())
         && !hasField(mesh, ti.name(), "h")
        )
        {
            FatalErrorInFunction
                << "No field h in " << mesh.time().path()/ti.name()
                << ": the centre of mass' path (comPathLength,"
                << " comTravelAngle) needs h at every time directory up to "
                << last.name() << ", or " << comFile(mesh) << nl
                << "Nothing written." << nl << exit(FatalError);
        }
    }
}


void writePlanReport
(
    const fileName& outDir, const instant& now, scalar threshold,
    const hazardTerrain& mapping, const hazardTimes& times,
    const volScalarField& h0, const hazardFields& fields
)
{
    const scalarField J = bedMetric(h0.mesh(), mapping, fields.zb);
    const scalar released = centreOf(mapping, J, h0, fields.zb).volume;
    const scalar deposit = centreOf(mapping, J, fields.h, fields.zb).volume;
    scalar entrained = 0;
    forAll(fields.erodedDepth, c)
    {
        entrained += J[c]*fields.erodedDepth[c]*mapping.cellSize
            *mapping.cellSize;
    }
    const planRunout r = runoutOf(threshold, mapping, h0, fields);
    const comPath path = comPathOf(mapping, times, now, J, fields.zb);
    const scalar s = pathLength(path.points);
    const std::vector<terrain::vec3>& P = path.points;
    const scalar dz = P.empty() ? 0 : P.front()[2] - P.back()[2];
    const scalar comAngle = radToDeg(std::atan2(dz, s));
    const scalar alpha = travelAngle(r.top, r.point);
    warnRunoutAbove(r.top, r.point);

    const bool atBoundary = r.reachesBoundary;

    OFstream report(outDir/"report.dat");
    report.precision(15);
    report
        << "# hazardMaps: time " << now.name() << ", threshold "
        << threshold << " m on hMax; plan mode: volumes sum J h A,"
        << " J = sqrt(1 + |grad zb|^2)" << nl
        << "# lines 'key value'; each key's unit and meaning on the"
        << " comment line above it" << nl;
    const scalar outflow = outflowVolume(released, entrained, deposit);
    writeVolumeKey(report, "releasedVolume", "m^3",
        "sum of J h A at the first time directory", released);
    reportEntrained(report, "sum of J erodedDepth A at that time (0"
        " without the field erodedDepth)", fields, now.name(), entrained);
    writeVolumeKey(report, "depositVolume", "m^3",
        "sum of J h A at that time (in the domain)", deposit);
    writeKey(report, "runoutX", "m", "world X of the runout point (the bed"
        " of the cell with hMax > threshold horizontally furthest from the"
        " highest released point)", r.point[0]);
    writeKey(report, "runoutY", "m", "world Y of the runout point",
        r.point[1]);
    writeKey(report, "runoutZ", "m", "elevation of the runout point",
        r.point[2]);
    writeKey(report, "travelAngle", "deg", "atan(drop / horizontal"
        " distance), highest released point to the runout point", alpha);
    writeKey(report, "comTravelAngle", "deg", "atan(dz / s) along the"
        " centre of mass' path", comAngle);
    writeVolumeKey
    (
        report, "outflowVolume", "m^3", outflowWhat(fields), outflow
    );
    writeKey(report, "comPathLength", "m", "s, the horizontal length of"
        " the centre of mass' path", s);
    writeKey(report, "reachesBoundary", "1", "1 if a cell of the grid's"
        " outermost ring has hMax > threshold (the flow reached the"
        " domain's edge), else 0", atBoundary ? 1 : 0);
    if (atBoundary)
    {
        Info<< "    Warning: the flow reaches the domain's boundary"
            << " (reachesBoundary 1; outflowVolume "
            << volumeText(outflow).c_str() << " m^3)" << nl;
    }
    Info<< "    Released volume " << volumeText(released).c_str()
        << " m^3, at time " << now.name() << " "
        << volumeText(deposit).c_str() << " m^3 in the domain, "
        << volumeText(outflow).c_str() << " m^3 left it" << nl
        << "    Runout point (" << r.point[0] << " " << r.point[1] << " "
        << r.point[2] << "), travel angle " << alpha << " deg" << nl
        << "    Centre of mass: path of " << path.points.size()
        << " points from " << path.from << ", length " << s
        << " m, drop " << dz << " m, travel angle " << comAngle << " deg"
        << nl << "    Wrote " << outDir << nl << endl;
}

} // End namespace Foam

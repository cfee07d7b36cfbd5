/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    avalancheSurface

Description
    The results of a case as 3D surfaces for ParaView, at their world
    positions: the bed and the flow surface (the bed + h along the normal of
    the reference surface), one pair of VTK XML PolyData files per time and
    a .series file over the times, so that an avalanche is seen on its
    slope.  Run in the case directory after savageHutterFoam.

    The reference surface (applications/utilities/terrain/referenceSurface.H,
    the code terrainToCase and hazardMaps use):
      - with constant/terrainMapping (a terrain case): its origin, tangent
        and inclination table; positions in the DEM's world (X, Y, Z);
      - without it (the analytic cases): the inclination zeta(x) of
        constant/transportProperties, read as the solver reads it (a
        Function1: constant, table, ...), the profile (X(x), Z(x)) with
        dX/dx = cos zeta, dZ/dx = -sin zeta, X = Z = 0 at x = 0, y = Y.
        A table is taken point by point (integrated exactly on each of its
        segments); any other Function1 is sampled 8 times per cell along x
        and taken linear between the samples.
    The bed of a cell is its centre at offset zb along the normal (zb of
    that time when written there, else of the first time, else 0); the flow
    surface is at offset zb + h.

    The points are the cell centres of the structured grid (nx x ny cells of
    one block: the surface stops half a cell inside the mesh's edges), the
    polygons quads between neighbouring centres (lines when the grid is one
    cell wide).  Point data: h, U (world components with terrainMapping or
    a curved reference surface: u_x along the profile's tangent, u_y across
    it), magU, zb, and where written hMax, UMax, pMax (or rho UMax^2 with
    rho in transportProperties) and tArrival.

    Writes postProcessing/avalancheSurface/:
        surface_<time>.vtp, bed_<time>.vtp
        surface.vtp.series, bed.vtp.series  (JSON, the .vtp files of every
                        time directory the case has, sorted by time)

    Every selected time is checked (h and U present) before anything is
    written.

Usage
    avalancheSurface [-time <ranges> | -latestTime | -noZero]
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "vector2D.H"
#include "OSspecific.H"
#include "timeSelector.H"
#include "Function1.H"
#include "TableBase.H"

#include "referenceSurface.H"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

using namespace Foam;

namespace
{

const word outName = "avalancheSurface";

IOobject fieldIO(const fvMesh& mesh, const word& instance, const word& name)
{
    return IOobject
    (
        name, instance, mesh, IOobject::MUST_READ, IOobject::NO_WRITE
    );
}

template<class FieldType>
bool hasField(const fvMesh& mesh, const word& instance, const word& name)
{
    return fieldIO(mesh, instance, name).typeHeaderOk<FieldType>(true);
}

//- Sorted distinct values of v (values closer than tol merged); index of
//  each value in the result
std::vector<double> distinct
(
    const std::vector<double>& v, double tol, std::vector<label>& index
)
{
    std::vector<double> s(v);
    std::sort(s.begin(), s.end());
    std::vector<double> u;
    for (const double a : s)
    {
        if (u.empty() || a - u.back() > tol)
        {
            u.push_back(a);
        }
    }
    index.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
    {
        auto it = std::lower_bound(u.begin(), u.end(), v[k] - tol);
        index[k] = label(it - u.begin());
    }
    return u;
}

//- base64 of bytes (RFC 4648, padded)
std::string base64(const std::vector<unsigned char>& b)
{
    static const char* abc =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string s;
    s.reserve(4*(b.size() + 2)/3);
    for (std::size_t k = 0; k < b.size(); k += 3)
    {
        const unsigned v =
            (unsigned(b[k]) << 16)
          | (k + 1 < b.size() ? unsigned(b[k + 1]) << 8 : 0u)
          | (k + 2 < b.size() ? unsigned(b[k + 2]) : 0u);
        s += abc[(v >> 18) & 63];
        s += abc[(v >> 12) & 63];
        s += k + 1 < b.size() ? abc[(v >> 6) & 63] : '=';
        s += k + 2 < b.size() ? abc[v & 63] : '=';
    }
    return s;
}

//- A DataArray of VTK's binary format: base64 of (UInt32 byte count,
//  values), in the machine's byte order (declared in the file's header)
template<class T>
void dataArray
(
    std::ostream& os, const char* type, const std::string& name, int nComp,
    const std::vector<T>& v
)
{
    static_assert(sizeof(std::uint32_t) == 4, "UInt32 header");
    const std::uint32_t n = std::uint32_t(v.size()*sizeof(T));
    std::vector<unsigned char> b(4 + n);
    std::memcpy(b.data(), &n, 4);
    if (n)
    {
        std::memcpy(b.data() + 4, v.data(), n);
    }
    os << "<DataArray type=\"" << type << "\"";
    if (!name.empty())
    {
        os << " Name=\"" << name << "\"";
    }
    if (nComp > 1)
    {
        os << " NumberOfComponents=\"" << nComp << "\"";
    }
    os << " format=\"binary\">\n" << base64(b) << "\n</DataArray>\n";
}

std::vector<float> toFloat(const std::vector<double>& v)
{
    return std::vector<float>(v.begin(), v.end());
}

std::vector<float> toFloat(const std::vector<terrain::vec3>& v)
{
    std::vector<float> f;
    f.reserve(3*v.size());
    for (const terrain::vec3& a : v)
    {
        f.insert(f.end(), {float(a[0]), float(a[1]), float(a[2])});
    }
    return f;
}


//- Write text to path through path.tmp and a rename, so that a reader
//  never sees a half-written file
void writeReplacing(const fileName& path, const std::string& text)
{
    const fileName tmp = path + ".tmp";
    {
        std::ofstream f(tmp);
        f << text;
        f.flush();
        if (!f)
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << nl << exit(FatalError);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << path << nl
            << exit(FatalError);
    }
}

//- A .vtp file: points (Float64), quads (or lines) over the nx x ny grid
//  of points, point data (Float32), VTK XML binary (base64)
void writeVtp
(
    const fileName& path,
    label nx, label ny,
    const std::vector<terrain::vec3>& pts,
    const std::vector<std::pair<word, const std::vector<double>*>>& scalars,
    const std::vector<std::pair<word, const std::vector<terrain::vec3>*>>&
        vectors
)
{
    const bool lines = nx == 1 || ny == 1;
    std::vector<std::int64_t> conn, offs;
    if (lines)
    {
        for (label k = 0; k < label(pts.size()); ++k)
        {
            conn.push_back(k);
        }
        offs.push_back(std::int64_t(pts.size()));
    }
    else
    {
        for (label j = 0; j + 1 < ny; ++j)
        {
            for (label i = 0; i + 1 < nx; ++i)
            {
                const std::int64_t p = i + nx*j;
                conn.insert(conn.end(), {p, p + 1, p + 1 + nx, p + nx});
                offs.push_back(std::int64_t(conn.size()));
            }
        }
    }
    const label nPoly = label(offs.size());

    std::ostringstream os;
    os  << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"PolyData\" version=\"0.1\""
        << " byte_order=\""
        << (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
            ? "LittleEndian" : "BigEndian")
        << "\" header_type=\"UInt32\">\n"
           "<PolyData>\n"
        << "<Piece NumberOfPoints=\"" << pts.size() << "\" NumberOfVerts=\"0\""
        << " NumberOfLines=\"" << (lines ? nPoly : 0) << "\""
        << " NumberOfStrips=\"0\""
        << " NumberOfPolys=\"" << (lines ? 0 : nPoly) << "\">\n"
        << "<PointData Scalars=\"h\" Vectors=\"U\">\n";
    for (const auto& s : scalars)
    {
        dataArray(os, "Float32", s.first, 1, toFloat(*s.second));
    }
    for (const auto& v : vectors)
    {
        dataArray(os, "Float32", v.first, 3, toFloat(*v.second));
    }
    os  << "</PointData>\n<Points>\n";
    std::vector<double> xyz;
    xyz.reserve(3*pts.size());
    for (const terrain::vec3& a : pts)
    {
        xyz.insert(xyz.end(), {a[0], a[1], a[2]});
    }
    dataArray(os, "Float64", "Points", 3, xyz);
    os << "</Points>\n";
    const char* block = lines ? "Lines" : "Polys";
    os << '<' << block << ">\n";
    dataArray(os, "Int64", "connectivity", 1, conn);
    dataArray(os, "Int64", "offsets", 1, offs);
    os << "</" << block << ">\n"
       << "</Piece>\n</PolyData>\n</VTKFile>\n";

    writeReplacing(path, os.str());
}

//- <dir>/<base>.vtp.series: the <base>_<time>.vtp files of dir whose time
//  is a time directory of the case
void writeSeries
(
    const fileName& dir, const word& base, const instantList& caseTimes
)
{
    std::map<scalar, word> files;
    const word prefix = base + "_";
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        if (f.ext() != "vtp" || f.substr(0, prefix.size()) != prefix)
        {
            continue;
        }
        const word tName = f.lessExt().substr(prefix.size());
        for (const instant& t : caseTimes)
        {
            if (t.name() == tName)
            {
                files[t.value()] = f;
            }
        }
    }
    std::ostringstream os;
    os << std::setprecision(17);
    os << "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [\n";
    label k = 0;
    for (const auto& f : files)
    {
        os << "    { \"name\" : \"" << f.second << "\", \"time\" : "
           << f.first << " }" << (++k < label(files.size()) ? ",\n" : "\n");
    }
    os << "  ]\n}\n";
    const fileName path = dir/(base + ".vtp.series");
    writeReplacing(path, os.str());
    Info<< "Wrote " << path << " (" << files.size() << " times)" << nl;
}

} // namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The bed and the flow surface (bed + h along the normal) at their"
        " world positions as VTK PolyData (.vtp) per time, and .series"
        " files for ParaView"
    );
    timeSelector::addOptions(false, false);
    argList::noParallel();
    argList::noFunctionObjects();

    #include "setRootCase.H"
    #include "createTime.H"

    // Numeric time directories (times() also lists constant)
    instantList caseTimes;
    for (const instant& t : runTime.times())
    {
        if (t.name() != runTime.constant())
        {
            caseTimes.append(t);
        }
    }
    if (caseTimes.empty())
    {
        FatalErrorInFunction
            << "No time directory in " << runTime.path() << nl
            << exit(FatalError);
    }
    const instantList selected
    (
        timeSelector::select(runTime.times(), args, runTime.constant())
    );
    instantList timeDirs;
    for (const instant& t : selected)
    {
        if (t.name() != runTime.constant())
        {
            timeDirs.append(t);
        }
    }
    if (timeDirs.empty())
    {
        FatalErrorInFunction
            << "No time selected in " << runTime.path() << "; times: "
            << flatOutput(caseTimes) << nl << exit(FatalError);
    }
    runTime.setTime(timeDirs.first(), 0);

    #include "createMesh.H"

    // -- The structured grid: cell c is point (i, j) --------------------------
    const volVectorField& C = mesh.C();
    std::vector<double> cx(C.size()), cy(C.size());
    forAll(C, c)
    {
        cx[c] = C[c].x();
        cy[c] = C[c].y();
    }
    const boundBox& bb = mesh.bounds();
    const double tol = 1e-9*(1 + mag(bb.max()) + mag(bb.min()));
    std::vector<label> ic, jc;
    const std::vector<double> xs = distinct(cx, tol, ic);
    const std::vector<double> ys = distinct(cy, tol, jc);
    const label nx = label(xs.size()), ny = label(ys.size());
    labelList pointCell(nx*ny, -1);
    forAll(C, c)
    {
        pointCell[ic[c] + nx*jc[c]] = c;
    }
    if (nx*ny != mesh.nCells() || pointCell.found(-1))
    {
        FatalErrorInFunction
            << "The mesh is not one structured block of nx x ny cells (its "
            << mesh.nCells() << " cell centres have " << nx
            << " distinct x and " << ny << " distinct y)" << nl
            << exit(FatalError);
    }

    // -- The reference surface ------------------------------------------------
    const IOdictionary tp
    (
        IOobject
        (
            "transportProperties", runTime.constant(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    terrain::referenceSurface surface;
    IOobject mapIO
    (
        "terrainMapping", runTime.constant(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
    const bool terrainCase = mapIO.typeHeaderOk<IOdictionary>(true);
    if (terrainCase)
    {
        const IOdictionary mapDict(mapIO);
        const List<vector2D> table =
            mapDict.get<List<vector2D>>("inclination");
        std::vector<double> xT, zT;
        for (const vector2D& p : table)
        {
            xT.push_back(p.x());
            zT.push_back(p.y());
        }
        const vector o = mapDict.get<vector>("origin");
        const vector2D t = mapDict.get<vector2D>("tangent");
        const label mnx = mapDict.get<label>("nx");
        const label mny = mapDict.get<label>("ny");
        if (mnx != nx || mny != ny)
        {
            FatalIOErrorInFunction(mapDict)
                << "nx " << mnx << " x ny " << mny << " cells, but the mesh"
                << " has " << nx << " x " << ny
                << ": run blockMesh after terrainToCase" << nl
                << exit(FatalIOError);
        }
        surface = terrain::referenceSurface
        (
            {o.x(), o.y(), o.z()}, t.x(), t.y(), xT, zT
        );
        Info<< "Reference surface: constant/terrainMapping (world X, Y, Z)"
            << nl;
    }
    else
    {
        if (!tp.found("inclination"))
        {
            FatalIOErrorInFunction(tp)
                << "Missing keyword 'inclination' (and no"
                << " constant/terrainMapping): the angle zeta(x) [deg] of"
                << " the reference surface" << nl << exit(FatalIOError);
        }
        const autoPtr<Function1<scalar>> zeta =
            Function1<scalar>::New("inclination", tp);
        std::vector<double> xT, zT;
        const auto* table =
            dynamic_cast<const Function1Types::TableBase<scalar>*>
            (zeta.get());
        if (table)
        {
            const scalarField tx(table->x());
            const scalarField tz(table->y());
            xT.assign(tx.begin(), tx.end());
            zT.assign(tz.begin(), tz.end());
        }
        else
        {
            // Samples: 8 per cell between the grid's edges
            const double x0 = xs.front() - 0.5*(nx > 1 ? xs[1] - xs[0] : 1);
            const double x1 = xs.back() + 0.5*(nx > 1 ? xs[nx-1] - xs[nx-2] : 1);
            const label n = 8*nx;
            for (label k = 0; k <= n; ++k)
            {
                const double x = x0 + (x1 - x0)*k/n;
                xT.push_back(x);
                zT.push_back(zeta->value(x));
            }
        }
        for (std::size_t k = 0; k < zT.size(); ++k)
        {
            if (!std::isfinite(zT[k]) || (k > 0 && !(xT[k] > xT[k-1])))
            {
                FatalIOErrorInFunction(tp)
                    << "keyword 'inclination': zeta(" << xT[k] << ") = "
                    << zT[k] << ": x must increase and zeta be finite" << nl
                    << exit(FatalIOError);
            }
        }
        // World X = Y = Z = 0 at x = 0, y = 0
        const terrain::referenceSurface s0({0, 0, 0}, 1, 0, xT, zT);
        const terrain::vec3 w0 = s0.world(0, 0, 0);
        surface = terrain::referenceSurface
        (
            {-w0[0], -w0[1], -w0[2]}, 1, 0, xT, zT
        );
        Info<< "Reference surface: inclination " << zeta->type()
            << " of transportProperties (X along the profile, Y = y, Z up)"
            << nl;
    }
    scalar rho = -1;
    if (tp.found("rho"))
    {
        rho = tp.get<scalar>("rho");
        if (!(rho > 0) || !(rho < 1e30))
        {
            FatalIOErrorInFunction(tp)
                << "keyword 'rho' = " << rho << ": must be > 0" << nl
                << exit(FatalIOError);
        }
    }

    // -- Check every selected time before writing anything ----------------------
    for (const instant& t : timeDirs)
    {
        if (!hasField<volScalarField>(mesh, t.name(), "h"))
        {
            FatalErrorInFunction
                << "No field h in " << runTime.path()/t.name() << nl
                << exit(FatalError);
        }
        if (!hasField<volVectorField>(mesh, t.name(), "U"))
        {
            FatalErrorInFunction
                << "No field U in " << runTime.path()/t.name() << nl
                << exit(FatalError);
        }
    }

    // Per point: zeta and the directions of the profile
    const label nP = nx*ny;
    std::vector<terrain::vec3> T(nP), N2(nP);
    for (label p = 0; p < nP; ++p)
    {
        double zeta, S, Z, b;
        surface.profile(C[pointCell[p]].x(), zeta, S, Z, b);
        const double tX = surface.tX(), tY = surface.tY();
        T[p] = {std::cos(zeta)*tX, std::cos(zeta)*tY, -std::sin(zeta)};
        N2[p] = {-tY, tX, 0};
    }

    const fileName outDir = runTime.path()/"postProcessing"/outName;
    mkDir(outDir);
    const word firstTime = caseTimes.first().name();

    for (const instant& t : timeDirs)
    {
        runTime.setTime(t, 0);
        const word now = t.name();
        const volScalarField h(fieldIO(mesh, now, "h"), mesh);
        const volVectorField U(fieldIO(mesh, now, "U"), mesh);
        std::vector<double> zb(nP, 0);
        word zbFrom = "0 (no zb)";
        for (const word& inst : {now, firstTime})
        {
            if (hasField<volScalarField>(mesh, inst, "zb"))
            {
                const volScalarField f(fieldIO(mesh, inst, "zb"), mesh);
                for (label p = 0; p < nP; ++p)
                {
                    zb[p] = f[pointCell[p]];
                }
                zbFrom = "time " + inst;
                break;
            }
        }

        std::vector<terrain::vec3> bed(nP), top(nP), Uw(nP);
        std::vector<double> hp(nP), magU(nP);
        for (label p = 0; p < nP; ++p)
        {
            const label c = pointCell[p];
            bed[p] = surface.world(C[c].x(), C[c].y(), zb[p]);
            top[p] = surface.world(C[c].x(), C[c].y(), zb[p] + h[c]);
            hp[p] = h[c];
            for (int k = 0; k < 3; ++k)
            {
                Uw[p][k] = U[c].x()*T[p][k] + U[c].y()*N2[p][k];
            }
            magU[p] = mag(U[c]);
        }

        std::vector<std::pair<word, const std::vector<double>*>> scalars
        {
            {"h", &hp}, {"magU", &magU}, {"zb", &zb}
        };
        std::map<word, std::vector<double>> extra;
        for (const word& name : {"hMax", "UMax", "pMax", "tArrival"})
        {
            if (hasField<volScalarField>(mesh, now, name))
            {
                const volScalarField f(fieldIO(mesh, now, name), mesh);
                std::vector<double>& v = extra[name];
                v.resize(nP);
                for (label p = 0; p < nP; ++p)
                {
                    v[p] = f[pointCell[p]];
                }
            }
        }
        if (!extra.count("pMax") && extra.count("UMax") && rho > 0)
        {
            std::vector<double>& v = extra["pMax"];
            for (const double u : extra["UMax"])
            {
                v.push_back(rho*u*u);
            }
        }
        for (const auto& e : extra)
        {
            scalars.push_back({e.first, &e.second});
        }
        const std::vector<std::pair<word, const std::vector<terrain::vec3>*>>
            vectors{{"U", &Uw}};

        writeVtp(outDir/("surface_" + now + ".vtp"), nx, ny, top, scalars,
            vectors);
        writeVtp(outDir/("bed_" + now + ".vtp"), nx, ny, bed, scalars,
            vectors);
        Info<< "Time " << now << ": " << nx << " x " << ny << " points,"
            << " zb of " << zbFrom << ", h max " << gMax(h) << ", data";
        for (const auto& s : scalars)
        {
            Info<< ' ' << s.first;
        }
        Info<< " U" << nl;
    }

    writeSeries(outDir, "surface", caseTimes);
    writeSeries(outDir, "bed", caseTimes);
    Info<< nl << "End\n" << endl;
    return 0;
}

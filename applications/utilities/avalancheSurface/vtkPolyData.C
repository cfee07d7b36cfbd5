/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "vtkPolyData.H"
#include "OSspecific.H"
#include "error.H"

#include <cstdint>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace Foam
{

namespace
{

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

} // End anonymous namespace


//- A .vtp file: points (Float64), quads (or lines) over the nx x ny grid
//  of points, point data (Float32), VTK XML binary (base64)
void writeVtp
(
    const fileName& path, label nx, label ny,
    const std::vector<terrain::vec3>& pts,
    const scalarPointData& scalars, const vectorPointData& vectors
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

} // End namespace Foam

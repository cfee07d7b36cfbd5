/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "terrainFiles.H"

namespace terrainFiles
{

namespace
{

//- Where entry key of a dictionary's text is: the start of its line
//  (returned; npos when no line starts with it), of the key (first) and
//  just past its ';' outside parentheses, comments skipped (end)
std::size_t findEntry
(
    const std::string& text, const std::string& key, std::size_t& first,
    std::size_t& end
)
{
    const std::size_t n = key.size();
    std::size_t pos = 0;
    while (pos < text.size())
    {
        std::size_t eol = text.find('\n', pos);
        if (eol == std::string::npos)
        {
            eol = text.size();
        }
        first = text.find_first_not_of(" \t", pos);
        if
        (
            first < eol && text.compare(first, n, key) == 0
         && (first + n == text.size()
          || std::string(" \t(\n").find(text[first + n]) != std::string::npos)
        )
        {
            int depth = 0;
            std::size_t k = first + n;
            for (; k < text.size(); ++k)
            {
                const char c = text[k];
                if (c == '/' && k + 1 < text.size() && text[k + 1] == '/')
                {
                    k = text.find('\n', k);
                    if (k == std::string::npos) { k = text.size(); break; }
                }
                else if (c == '(') { ++depth; }
                else if (c == ')') { --depth; }
                else if (c == ';' && depth <= 0) { break; }
            }
            end = k < text.size() ? k + 1 : k;
            return pos;
        }
        pos = eol + 1;
    }
    return std::string::npos;
}

} // End anonymous namespace


std::string readText(const std::string& path)
{
    std::ifstream is(path);
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
}


void writeText(const std::string& path, const std::string& text)
{
    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp);
        os << text;
        os.flush();
        if (!os)
        {
            throw std::runtime_error("cannot write " + tmp);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        throw std::runtime_error("cannot rename " + tmp + " to " + path);
    }
}


std::string header
(
    const std::string& cls, const std::string& location,
    const std::string& object
)
{
    std::ostringstream os;
    os  << "/*--------------------------------*- C++ -*----------------------------------*\\\n"
        << "  savageHutterFoam: written by terrainToCase\n"
        << "\\*---------------------------------------------------------------------------*/\n"
        << "FoamFile\n{\n"
        << "    version     2.0;\n"
        << "    format      ascii;\n"
        << "    class       " << cls << ";\n"
        << "    location    \"" << location << "\";\n"
        << "    object      " << object << ";\n}\n"
        << "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n";
    return os.str();
}


std::ostringstream numbers()
{
    std::ostringstream os;
    os << std::setprecision(17);
    return os;
}


void writeBlock
(
    const std::string& path, long nx, long ny, double xMax, double y0,
    double y1, const std::string& comment, const std::string& patches
)
{
    std::ostringstream os = numbers();
    os  << header("dictionary", "system", "blockMeshDict")
        << comment
        << "nx  " << nx << ";\nny  " << ny << ";\n\n"
        << "vertices\n(\n"
        << "    (0 " << y0 << " 0) (" << xMax << " " << y0 << " 0) ("
        << xMax << " " << y1 << " 0) (0 " << y1 << " 0)\n"
        << "    (0 " << y0 << " 1) (" << xMax << " " << y0 << " 1) ("
        << xMax << " " << y1 << " 1) (0 " << y1 << " 1)\n);\n\n"
        << "blocks\n(\n"
        << "    hex (0 1 2 3 4 5 6 7) ($nx $ny 1) simpleGrading (1 1 1)\n"
        << ");\n\n"
        << patches
        << "    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }\n"
        << ");\n\n"
        << "// ************************************************************************* //\n";
    writeText(path, os.str());
}


void writeBlockMeshDict
(
    const std::string& path, long nx, long ny, double xMax, double yMax
)
{
    writeBlock
    (
        path, nx, ny, xMax, -yMax, yMax,
        "// x: arc length along the reference profile, y: across it\n"
        "// (constant/terrainMapping maps them to the DEM's coordinates)\n",
        "boundary\n(\n"
        "    upslope      { type wall;  faces ((0 4 7 3)); }\n"
        "    downslope    { type patch; faces ((1 2 6 5)); }\n"
        "    sides        { type patch; faces ((0 1 5 4) (3 7 6 2)); }\n"
    );
}


std::string inclinationEntry
(
    const std::vector<double>& x, const std::vector<double>& zetaDeg,
    const std::string& source
)
{
    std::ostringstream os = numbers();
    os << "// zeta(x) [deg] of the thalweg profile: terrainToCase, " << source
       << "\ninclination     table\n(\n";
    for (std::size_t k = 0; k < x.size(); ++k)
    {
        os << "    (" << x[k] << " " << zetaDeg[k] << ")\n";
    }
    os << ");";
    return os.str();
}


std::string setInclination
(
    const std::string& text,
    const std::vector<double>& x, const std::vector<double>& zetaDeg,
    const std::string& source
)
{
    const std::string entry = inclinationEntry(x, zetaDeg, source);
    std::size_t first = 0, end = 0;
    if (findEntry(text, "inclination", first, end) != std::string::npos)
    {
        return text.substr(0, first) + entry + text.substr(end);
    }
    // No entry: before the closing banner, or at the end
    std::size_t banner = text.rfind("// ****");
    if (banner == std::string::npos)
    {
        return text + "\n" + entry + "\n";
    }
    return text.substr(0, banner) + entry + "\n\n" + text.substr(banner);
}


void writeVelocityField(const std::string& path)
{
    std::ostringstream os = numbers();
    os  << header("volVectorField", "0", "U")
        << "dimensions      [0 1 -1 0 0 0 0];\n\n"
        << "internalField   uniform (0 0 0);\n\n"
        << "boundaryField\n{\n"
        << "    upslope      { type slip; }           // a wall\n"
        << "    downslope    { type zeroGradient; }   // outflow\n"
        << "    sides        { type zeroGradient; }\n"
        << "    frontAndBack { type empty; }\n}\n\n"
        << "// ************************************************************************* //\n";
    writeText(path, os.str());
}


void writeMapping(const std::string& path, const mapping& m)
{
    std::ostringstream os = numbers();
    os  << header("dictionary", "constant", "terrainMapping")
        << "// World position of mesh point (x, y, z), z along the normal:\n"
        << "//   W = origin + (S(x) + z sin zeta) t + y n,  Z = Z0 + Z(x) + z cos zeta\n"
        << "// t = tangent, n = (-t_Y t_X), dS/dx = cos zeta, dZ/dx = -sin zeta,\n"
        << "// zeta(x) the inclination table (linear in x)\n"
        << "dem             \"" << m.dem << "\";\n"
        << "axis            ((" << m.axis[0][0] << " " << m.axis[0][1] << ") ("
        << m.axis[1][0] << " " << m.axis[1][1] << "));\n"
        << "origin          (" << m.origin[0] << " " << m.origin[1] << " "
        << m.origin[2] << ");\n"
        << "tangent         (" << m.tangent[0] << " " << m.tangent[1] << ");\n"
        << "cellSize        " << m.cellSize << ";\n"
        << "nx              " << m.nx << ";\n"
        << "ny              " << m.ny << ";\n"
        << "xMin            0;\n"
        << "xMax            " << m.nx*m.cellSize << ";\n"
        << "yMin            " << -m.yMax << ";\n"
        << "yMax            " << m.yMax << ";\n"
        << "releasedVolume  " << m.releasedVolume << ";\n"
        << "inclination\n(\n";
    for (std::size_t k = 0; k < m.x.size(); ++k)
    {
        os << "    (" << m.x[k] << " " << m.zetaDeg[k] << ")\n";
    }
    os  << ");\n\n"
        << "// ************************************************************************* //\n";
    writeText(path, os.str());
}


std::size_t entrySpan
(
    const std::string& text, const std::string& key, std::size_t& end
)
{
    std::size_t first = 0;
    const std::size_t pos = findEntry(text, key, first, end);
    if (pos != std::string::npos)
    {
        // The rest of the line: blanks and a comment
        std::size_t r = text.find_first_not_of(" \t", end);
        if (r != std::string::npos && text.compare(r, 2, "//") == 0)
        {
            r = text.find('\n', r);
        }
        if (r == std::string::npos)
        {
            end = text.size();
        }
        else if (text[r] == '\n')
        {
            end = r + 1;
        }
    }
    return pos;
}


std::string setPlanCoordinates
(
    const std::string& text, bool& hadInclination
)
{
    const std::string entry =
        "coordinates     plan;                   // terrainToCase: the"
        " DEM's plan grid\n";
    std::string t = text;
    std::size_t end = 0;
    std::size_t inclination = entrySpan(t, "inclination", end);
    hadInclination = inclination != std::string::npos;
    if (hadInclination)
    {
        t.erase(inclination, end - inclination);
    }
    std::size_t coordinates = entrySpan(t, "coordinates", end);
    if (coordinates != std::string::npos)
    {
        return t.substr(0, coordinates) + entry + t.substr(end);
    }
    if (hadInclination)
    {
        return t.substr(0, inclination) + entry + t.substr(inclination);
    }
    // No entry: before the closing banner, or at the end
    const std::size_t banner = t.rfind("// ****");
    if (banner == std::string::npos)
    {
        return t + "\n" + entry;
    }
    return t.substr(0, banner) + entry + "\n" + t.substr(banner);
}


const std::vector<std::string>& planPatches()
{
    static const std::vector<std::string> p{"xMin", "xMax", "yMin", "yMax"};
    return p;
}


void writePlanBlockMeshDict
(
    const std::string& path, long nx, long ny, double xMax, double yMax
)
{
    writeBlock
    (
        path, nx, ny, xMax, 0, yMax,
        "// Plan mode: x, y horizontal on the DEM's grid, from its lower-left\n"
        "// corner (constant/terrainMapping maps them to the DEM's coordinates)\n",
        "// Every side open (transmissive: zeroGradient h and U)\n"
        "boundary\n(\n"
        "    xMin         { type patch; faces ((0 4 7 3)); }\n"
        "    xMax         { type patch; faces ((1 2 6 5)); }\n"
        "    yMin         { type patch; faces ((0 1 5 4)); }\n"
        "    yMax         { type patch; faces ((3 7 6 2)); }\n"
    );
}


void writePlanMapping(const std::string& path, const planMapping& m)
{
    std::ostringstream os = numbers();
    os  << header("dictionary", "constant", "terrainMapping")
        << "// Plan mode (no axis): world position of mesh point (x, y),\n"
        << "//   X = origin + x xAxis + y yAxis,  Z = zb (vertical elevation)\n"
        << "// x, y horizontal on the DEM's grid (docs/terrainMapping.md)\n"
        << "mode            plan;\n"
        << "dem             \"" << m.dem << "\";\n"
        << "origin          (" << m.origin[0] << " " << m.origin[1] << ");\n"
        << "xAxis           (" << m.xAxis[0] << " " << m.xAxis[1] << ");\n"
        << "yAxis           (" << m.yAxis[0] << " " << m.yAxis[1] << ");\n"
        << "cellSize        " << m.cellSize << ";\n"
        << "nx              " << m.nx << ";\n"
        << "ny              " << m.ny << ";\n"
        << "xMin            0;\n"
        << "xMax            " << m.nx*m.cellSize << ";\n"
        << "yMin            0;\n"
        << "yMax            " << m.ny*m.cellSize << ";\n"
        << "releasedVolume  " << m.releasedVolume << ";\n\n"
        << "// ************************************************************************* //\n";
    writeText(path, os.str());
}


} // namespace terrainFiles

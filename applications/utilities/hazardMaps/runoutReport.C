/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "runoutReport.H"
#include "OFstream.H"
#include "unitConversion.H"

#include <cstdio>

namespace Foam
{

namespace
{

//- The world position of cell c's bed
terrain::vec3 bedPoint
(
    const terrain::referenceSurface& s, const point& C, scalar zb
)
{
    return s.world(C.x(), C.y(), zb);
}


struct runout
{
    scalar released = 0;
    scalar entrained = 0;
    scalar deposit = 0;

    //- The highest released point, the centres of mass of the release and
    //  of the material now, and the runout point
    terrain::vec3 top{0, 0, -GREAT};
    terrain::vec3 com0{0, 0, 0};
    terrain::vec3 com1{0, 0, 0};
    terrain::vec3 point{0, 0, 0};
    runoutDefinition::result def;
};


runout runoutOf
(
    scalar threshold, const hazardTerrain& mapping,
    const volScalarField& h0, const hazardFields& fields
)
{
    const volVectorField& C = h0.mesh().C();
    const volScalarField& hMax = fields.hMax;
    const volScalarField& h = fields.h;
    const volScalarField& zb = fields.zb;
    const scalar cellSize = mapping.cellSize;
    const scalar cellArea = cellSize*cellSize;
    runout r;
    forAll(C, c)
    {
        const terrain::vec3 W = bedPoint(mapping.surface, C[c], zb[c]);
        r.released += h0[c]*cellArea;
        r.deposit += h[c]*cellArea;
        for (int k = 0; k < 3; ++k)
        {
            r.com0[k] += h0[c]*W[k];
            r.com1[k] += h[c]*W[k];
        }
    }
    for (const scalar e : fields.erodedDepth)
    {
        r.entrained += e*cellArea;
    }
    for (int k = 0; k < 3; ++k)
    {
        r.com0[k] /= r.released/cellArea;
        r.com1[k] /= r.deposit > 0 ? r.deposit/cellArea : 1;
    }
    // The runout point and the top of the release: runoutDefinition.H,
    // shared with savageHutterFoam -ensemble's report
    r.def = runoutDefinition::runoutOf
    (
        C.size(), threshold, cellSize, mapping.nx, mapping.ny,
        [&](long c) { return C[c].x(); },
        [&](long c) { return hMax[c]; },
        [&](long c) { return h0[c]; },
        [&](long c) { return long(std::floor(C[c].x()/cellSize)); },
        [&](long c)
        {
            return long(std::floor((C[c].y() - mapping.yMin)/cellSize));
        },
        [&](long c) { return bedPoint(mapping.surface, C[c], zb[c]); }
    );
    r.top = r.def.top;
    r.point = r.def.point;
    return r;
}

} // End anonymous namespace


scalar travelAngle(const terrain::vec3& a, const terrain::vec3& b)
{
    return runoutDefinition::travelAngle(a, b);
}


void warnRunoutAbove(const terrain::vec3& top, const terrain::vec3& point)
{
    if (!(top[2] > -0.5*GREAT) || !(point[2] > top[2]))
    {
        // Nothing released, or the runout below the release
        return;
    }
    WarningInFunction
        << "The runout point (" << point[0] << ", " << point[1] << ", "
        << point[2] << ") lies " << point[2] - top[2] << " m above the"
        << " highest released point (" << top[0] << ", " << top[1] << ", "
        << top[2] << "): the release is below its runout (travelAngle "
        << travelAngle(top, point) << " deg < 0). Is the axis of"
        << " system/terrainDict drawn uphill, or the release placed where"
        << " the flow ends?" << nl << endl;
}


void writeKey
(
    Ostream& os, const char* key, const char* unit, const char* what,
    const scalar value
)
{
    os  << "# " << key << " [" << unit << "] " << what << nl
        << key << ' ' << value << nl;
}


void writeVolumeKey
(
    Ostream& os, const char* key, const char* unit, const char* what,
    const scalar value
)
{
    const label digits = os.precision(10);
    writeKey(os, key, unit, what, value);
    os.precision(digits);
}


std::string volumeText(const scalar v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", double(v));
    return buf;
}


scalar outflowVolume
(
    const scalar released, const scalar entrained, const scalar deposit
)
{
    // The balance released + entrained = deposit + outflow
    const scalar in = released + entrained;
    const scalar out = in - deposit;
    return mag(out) < 1e-9*mag(in) ? 0 : out;
}


const char* outflowWhat(const hazardFields& fields)
{
    // A run without an erodible layer keeps the report it always had
    return fields.erodible
      ? "releasedVolume + entrainedVolume - depositVolume: what left the"
        " domain (0 where its magnitude is below 1e-9 of releasedVolume +"
        " entrainedVolume, the round-off of the sums)"
      : "releasedVolume - depositVolume: what left the domain (0 where its"
        " magnitude is below 1e-9 of releasedVolume, the round-off of the"
        " two sums)";
}


void reportEntrained
(
    Ostream& report, const char* what, const hazardFields& fields,
    const word& now, const scalar entrained
)
{
    if (!fields.erodible)
    {
        return;
    }
    writeVolumeKey(report, "entrainedVolume", "m^3", what, entrained);
    if (fields.erodedDepth.size())
    {
        Info<< "    Entrained volume " << volumeText(entrained).c_str()
            << " m^3 (erodedDepth at time " << now << ")" << nl;
    }
    else
    {
        Info<< "    No field erodedDepth at time " << now << " (the run"
            << " has an erodible layer, hEntrainable): entrainedVolume 0"
            << nl;
    }
}


void writeReport
(
    const fileName& outDir, const word& now, scalar threshold,
    const hazardTerrain& mapping, const volScalarField& h0,
    const hazardFields& fields
)
{
    const runout r = runoutOf(threshold, mapping, h0, fields);
    const scalar alpha = travelAngle(r.top, r.point);
    const scalar comAlpha = travelAngle(r.com0, r.com1);
    if (r.def.released && r.def.reached)
    {
        warnRunoutAbove(r.top, r.point);
    }
    OFstream report(outDir/"report.dat");
    report.precision(10);
    report
        << "# hazardMaps: time " << now << ", threshold "
        << threshold << " m on hMax; world coordinates of the DEM" << nl
        << "# lines 'key value'; each key's unit and meaning on the"
        << " comment line above it" << nl;
    const scalar outflow = outflowVolume(r.released, r.entrained, r.deposit);
    writeVolumeKey(report, "releasedVolume", "m^3",
        "sum of h dA at the first time directory", r.released);
    reportEntrained(report, "sum of erodedDepth dA at that time (0"
        " without the field erodedDepth)", fields, now, r.entrained);
    writeVolumeKey(report, "depositVolume", "m^3",
        "sum of h dA at that time (in the domain)", r.deposit);
    writeKey(report, "runoutX", "m", "world X of the runout point (the"
        " bed of the cell with hMax > threshold furthest along the axis)",
        r.point[0]);
    writeKey(report, "runoutY", "m", "world Y of the runout point",
        r.point[1]);
    writeKey(report, "runoutZ", "m", "elevation of the runout point",
        r.point[2]);
    writeKey(report, "travelAngle", "deg", "atan(drop / horizontal"
        " distance), highest released point to the runout point", alpha);
    writeKey(report, "comTravelAngle", "deg", "the same between the"
        " centres of mass of the release and of the material at that time",
        comAlpha);
    writeVolumeKey
    (
        report, "outflowVolume", "m^3", outflowWhat(fields), outflow
    );
    writeKey(report, "reachesBoundary", "1", "1 if a cell of the mesh's"
        " outermost ring has hMax > threshold (the flow reached the"
        " domain's edge: the runout may be cut off), else 0",
        r.def.reachesBoundary ? 1 : 0);
    Info<< "    Released volume " << volumeText(r.released).c_str()
        << " m^3, at time " << now << " "
        << volumeText(r.deposit).c_str() << " m^3" << nl
        << "    Runout point (" << r.point[0] << " " << r.point[1] << " "
        << r.point[2] << "), travel angle " << alpha
        << " deg, centre of mass " << comAlpha << " deg" << nl;
    if (r.def.reachesBoundary)
    {
        Info<< "    Warning: the flow reaches the domain's boundary"
            << " (reachesBoundary 1; " << volumeText(outflow).c_str()
            << " m^3 left it): the runout may lie beyond the mesh" << nl;
    }
    Info<< "    Wrote " << outDir << nl << endl;
}

} // End namespace Foam

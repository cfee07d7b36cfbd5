/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "runoutReport.H"
#include "OFstream.H"
#include "unitConversion.H"

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
    scalar deposit = 0;

    //- The highest released point, the centres of mass of the release and
    //  of the material now, and the runout point
    terrain::vec3 top{0, 0, -GREAT};
    terrain::vec3 com0{0, 0, 0};
    terrain::vec3 com1{0, 0, 0};
    terrain::vec3 point{0, 0, 0};
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
    label runoutCell = -1;
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
        if (h0[c] > 0 && W[2] > r.top[2])
        {
            r.top = W;
        }
        if (hMax[c] > threshold)
        {
            if
            (
                runoutCell < 0
             || C[c].x() > C[runoutCell].x() + 0.5*cellSize
             || (
                    C[c].x() > C[runoutCell].x() - 0.5*cellSize
                 && hMax[c] > hMax[runoutCell]
                )
            )
            {
                runoutCell = c;
            }
        }
    }
    for (int k = 0; k < 3; ++k)
    {
        r.com0[k] /= r.released/cellArea;
        r.com1[k] /= r.deposit > 0 ? r.deposit/cellArea : 1;
    }
    r.point = bedPoint(mapping.surface, C[runoutCell], zb[runoutCell]);
    return r;
}

} // End anonymous namespace


scalar travelAngle(const terrain::vec3& a, const terrain::vec3& b)
{
    const scalar dist = std::hypot(b[0] - a[0], b[1] - a[1]);
    return radToDeg(std::atan2(a[2] - b[2], dist));
}


void writeReport
(
    const fileName& outDir, const word& now, scalar threshold,
    const hazardTerrain& mapping, const volScalarField& h0,
    const hazardFields& fields
)
{
    const runout r = runoutOf(threshold, mapping, h0, fields);
    OFstream report(outDir/"report.dat");
    report.precision(10);
    report
        << "# hazardMaps: time " << now << ", threshold "
        << threshold << " m on hMax" << nl
        << "releasedVolume " << r.released << nl
        << "depositVolume " << r.deposit << nl
        << "runoutX " << r.point[0] << nl
        << "runoutY " << r.point[1] << nl
        << "runoutZ " << r.point[2] << nl
        << "travelAngle " << travelAngle(r.top, r.point) << nl
        << "comTravelAngle " << travelAngle(r.com0, r.com1) << nl;
    Info<< "    Released volume " << r.released << " m^3, at time "
        << now << " " << r.deposit << " m^3" << nl
        << "    Runout point (" << r.point[0] << " " << r.point[1] << " "
        << r.point[2] << "), travel angle " << travelAngle(r.top, r.point)
        << " deg, centre of mass " << travelAngle(r.com0, r.com1) << " deg"
        << nl << "    Wrote " << outDir << nl << endl;
}

} // End namespace Foam

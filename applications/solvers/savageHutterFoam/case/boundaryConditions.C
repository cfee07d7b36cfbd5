/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "boundaryConditions.H"

namespace Foam
{

namespace
{

const char* supported =
    "Supported (h / U):\n"
    "    zeroGradient  / zeroGradient   transmissive outflow\n"
    "    zeroGradient  / slip           reflective wall\n"
    "    symmetryPlane / symmetryPlane  (or symmetry) mirror, as a wall\n"
    "    fixedValue    / fixedValue     inflow of a uniform (h, U)\n"
    "    empty         / empty          only across a direction one cell"
    " wide (1D)";

//- A fixedValue inflow's state (h, U) into c: finite, h >= 0, |U| at most
//  maxInputSpeed, uniform along the patch
void readInflow
(
    sideCondition& c,
    const fvPatchScalarField& hp,
    const fvPatchVectorField& Up,
    const volScalarField& h,
    const volVectorField& U
)
{
    // The bound of the initial fields (avalancheCase.H): beyond it the
    // scheme's squares overflow (and mag() of such a U here)
    const scalar big = 1e30;
    forAll(hp, facei)
    {
        if (!(hp[facei] >= 0 && hp[facei] <= big))
        {
            FatalIOErrorInFunction(h.objectPath())
                << "Patch " << c.patch << ": inflow thickness h = "
                << hp[facei] << " at face " << facei << " must be"
                << " finite, >= 0 and at most 1e30" << nl
                << exit(FatalIOError);
        }
        const vector& u = Up[facei];
        if
        (
            !(mag(u.x()) <= big && mag(u.y()) <= big && mag(u.z()) <= big)
         || !(mag(u) <= maxInputSpeed)
        )
        {
            FatalIOErrorInFunction(U.objectPath())
                << "Patch " << c.patch << ": inflow velocity U = " << u
                << " at face " << facei << " must be finite, of"
                << " magnitude at most " << label(maxInputSpeed)
                << " m/s (the speed of light)" << nl
                << exit(FatalIOError);
        }
    }
    c.h = hp[0];
    c.U = Up[0];
    forAll(hp, facei)
    {
        if
        (
            mag(hp[facei] - c.h) > 1e-12*(1 + mag(c.h))
         || mag(Up[facei] - c.U) > 1e-12*(1 + mag(c.U))
        )
        {
            FatalIOErrorInFunction(h.objectPath())
                << "Patch " << c.patch << ": fixedValue inflow must be"
                << " uniform along the patch; face " << facei
                << " has h = " << hp[facei] << ", U = " << Up[facei]
                << ", face 0 h = " << c.h << ", U = " << c.U << nl
                << exit(FatalIOError);
        }
    }
}

//- The condition of patch patchi on side `side` from the types of h and U
sideCondition classify
(
    const structuredMesh& smesh,
    const label side,
    const label patchi,
    const volScalarField& h,
    const volVectorField& U
)
{
    const fvPatchScalarField& hp = h.boundaryField()[patchi];
    const fvPatchVectorField& Up = U.boundaryField()[patchi];
    const word& ht = hp.type();
    const word& Ut = Up.type();

    sideCondition c;
    c.patch = hp.patch().name();

    const bool oneCellAcross =
        (side < 2 && smesh.nxWhole() == 1)
     || (side >= 2 && smesh.nyWhole() == 1);

    if (ht == "zeroGradient" && Ut == "zeroGradient")
    {
        c.type = sh::BCType::transmissive;
    }
    else if (ht == "zeroGradient" && Ut == "slip")
    {
        c.type = sh::BCType::wall;
    }
    else if
    (
        (ht == "symmetryPlane" || ht == "symmetry")
     && (Ut == "symmetryPlane" || Ut == "symmetry")
    )
    {
        c.type = sh::BCType::wall;
    }
    else if (ht == "empty" && Ut == "empty" && oneCellAcross)
    {
        c.type = sh::BCType::wall;
    }
    else if (ht == "fixedValue" && Ut == "fixedValue")
    {
        c.type = sh::BCType::inflow;
        if (hp.empty())
        {
            return c;
        }
        readInflow(c, hp, Up, h, U);
    }
    else
    {
        FatalIOErrorInFunction(U.objectPath())
            << "Patch " << c.patch << " (side "
            << structuredMesh::sideNames[side] << "): unsupported boundary"
            << " condition " << ht << " on h with " << Ut << " on U." << nl
            << supported << nl << exit(FatalIOError);
    }
    return c;
}

} // namespace


FixedList<sideCondition, 4> readBoundaryConditions
(
    const structuredMesh& smesh,
    const volScalarField& h,
    const volVectorField& U
)
{
    FixedList<sideCondition, 4> sides;
    for (label s = 0; s < 4; ++s)
    {
        // A part's side inside the whole grid: the neighbour's cells
        if (smesh.neighbour(s) >= 0)
        {
            sides[s].type = sh::BCType::processor;
            sides[s].patch = "processor" + Foam::name(smesh.neighbour(s));
            continue;
        }
        const labelList& patches = smesh.sidePatches(s);
        if (patches.empty())
        {
            FatalErrorInFunction
                << "No patch covers side " << structuredMesh::sideNames[s]
                << " of the mesh" << nl << exit(FatalError);
        }
        sides[s] = classify(smesh, s, patches[0], h, U);
        for (label k = 1; k < patches.size(); ++k)
        {
            const sideCondition other = classify(smesh, s, patches[k], h, U);
            if
            (
                other.type != sides[s].type
             || mag(other.h - sides[s].h) > 1e-12*(1 + mag(sides[s].h))
             || mag(other.U - sides[s].U) > 1e-12*(1 + mag(sides[s].U))
            )
            {
                FatalIOErrorInFunction(U.objectPath())
                    << "Side " << structuredMesh::sideNames[s]
                    << " has patches " << sides[s].patch << " and "
                    << other.patch << " with different conditions; one"
                    << " condition per side of the block is supported."
                    << nl << exit(FatalIOError);
            }
        }
    }
    // Decomposed: a side of the whole grid is one condition over all the
    // processors along it, as in the serial run (each saw its own part)
    if (Pstream::parRun())
    {
        for (label s = 0; s < 4; ++s)
        {
            const bool on = smesh.neighbour(s) < 0;
            const sideCondition& c = sides[s];
            const scalar values[5] =
                {scalar(int(c.type)), c.h, c.U.x(), c.U.y(), c.U.z()};
            bool same = true;
            for (const scalar v : values)
            {
                const scalar lo = returnReduce(on ? v : VGREAT, minOp<scalar>());
                const scalar hi = returnReduce(on ? v : -VGREAT, maxOp<scalar>());
                same = same && hi - lo <= 1e-12*(1 + max(mag(lo), mag(hi)));
            }
            if (!same)
            {
                FatalIOErrorInFunction(U.objectPath())
                    << "Side " << structuredMesh::sideNames[s] << " of the"
                    << " block has different conditions on different"
                    << " processors' parts (this one: patch " << c.patch
                    << "); one condition per side of the block is"
                    << " supported." << nl << exit(FatalIOError);
            }
        }
    }
    return sides;
}

} // End namespace Foam

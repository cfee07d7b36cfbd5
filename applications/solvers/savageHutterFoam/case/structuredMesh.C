/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "structuredMesh.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "IFstream.H"
#include "boundBox.H"
#include "volFields.H"
#include "OStringStream.H"

namespace Foam
{

const wordList structuredMesh::sideNames({"xMin", "xMax", "yMin", "yMax"});

namespace
{

// Relative tolerance of "equal" lengths: blockMesh writes points with
// writePrecision digits, so widths of one uniform block agree to ~1e-6
const scalar lengthTol = 1e-5;

bool close(const scalar a, const scalar b, const scalar scale)
{
    return mag(a - b) <= lengthTol*scale;
}

//- What savageHutterFoam needs of blockMeshDict, for the messages
const char* const blockNeeds =
    "savageHutterFoam needs one hex block of nx ny 1 uniform cells,"
    " nx and ny positive integers:\n"
    "    blocks ( hex (0 1 2 3 4 5 6 7) (nx ny 1)"
    " simpleGrading (1 1 1) );\n"
    "then blockMesh again";

//- The mesh's coordinates, as blockMesh scales them (it ignores a factor
//  <= 0): beyond 1e30 the scheme's products overflow
void checkScale(const dictionary& dict, const fileName& file)
{
    for (const word key : {"convertToMeters", "scale"})
    {
        if (dict.found(key, keyType::LITERAL))
        {
            const scalar s = dict.get<scalar>(key);
            if (!(mag(s) <= 1e30))
            {
                FatalIOErrorInFunction(dict)
                    << "Invalid " << key << " " << s << " in " << file
                    << ": must be a finite number of magnitude at most"
                    << " 1e30" << nl << exit(FatalIOError);
            }
        }
    }
}

//- The cell counts of the hex block whose keyword hex is token `hex` of
//  blocks: positive integers, one cell in z
labelVector hexCounts
(
    const ITstream& blocks,
    const label hex,
    const dictionary& dict,
    const fileName& file
)
{
    labelVector n(labelVector::zero);
    const auto punct = [&blocks](label i, token::punctuationToken p)
    {
        return i < blocks.size() && blocks[i].isPunctuation()
            && blocks[i].pToken() == p;
    };
    // hex (8 vertices) [zone name] (nx ny nz) grading
    label k = hex + 1;
    bool ok = punct(k, token::BEGIN_LIST);
    while (ok && ++k < blocks.size() && !punct(k, token::END_LIST))
    {}
    ok = ok && k < blocks.size();
    ++k;
    if
    (
        ok && k < blocks.size() && blocks[k].isWord()
     && !blocks[k].wordToken().endsWith("Grading")
    )
    {
        ++k;
    }
    ok = ok && punct(k, token::BEGIN_LIST) && punct(k + 4, token::END_LIST);
    OStringStream counts;
    bool valid = ok;
    if (ok)
    {
        counts << "(";
        for (label d = 0; d < 3; ++d)
        {
            const token& t = blocks[k + 1 + d];
            counts << (d ? " " : "") << t;
            if (t.isLabel() && t.labelToken() >= 1)
            {
                n[d] = t.labelToken();
            }
            else
            {
                valid = false;
            }
        }
        counts << ")";
    }
    if (!valid)
    {
        FatalIOErrorInFunction(dict)
            << "Invalid cell counts "
            << (ok ? counts.str().c_str() : "(not found)")
            << " of the hex block in blocks of " << file << "." << nl
            << blockNeeds << nl << exit(FatalIOError);
    }
    if (n[2] != 1)
    {
        FatalIOErrorInFunction(dict)
            << "3D mesh: the hex block in blocks of " << file
            << " has " << n[2] << " cells in z, cell counts "
            << counts.str().c_str() << ".  savageHutterFoam needs"
            << " exactly one cell in z (blockMesh: nx ny 1)." << nl
            << exit(FatalIOError);
    }
    return n;
}

//- Every face along x, y or z: a block aligned with the axes
void checkAxisAligned(const fvMesh& mesh)
{
    const vectorField& Sf = mesh.faceAreas();
    forAll(Sf, facei)
    {
        const vector n = Sf[facei]/mag(Sf[facei]);
        if (cmptMax(cmptMag(n)) < 1 - lengthTol)
        {
            FatalErrorInFunction
                << "Face " << facei << " has normal " << n << ", not along"
                << " x, y or z.  The block must be aligned with the axes:"
                << " x downslope, y cross-slope, one cell in z." << nl
                << exit(FatalError);
        }
    }
}

//- The widths in x and y of every cell, one uniform hexahedron per
//  (i, j), full depth (span: the mesh's); the largest of all processors
//  into wxMax, wyMax
void uniformWidths
(
    const fvMesh& mesh,
    const vector& span,
    scalar& wxMax,
    scalar& wyMax
)
{
    const pointField& pts = mesh.points();
    const labelListList& cellPoints = mesh.cellPoints();
    scalar wxMin = VGREAT, wyMin = VGREAT;
    wxMax = 0;
    wyMax = 0;
    forAll(cellPoints, c)
    {
        const labelList& cp = cellPoints[c];
        if (cp.size() != 8 || mesh.cells()[c].size() != 6)
        {
            FatalErrorInFunction
                << "Cell " << c << " is not a hexahedron.  savageHutterFoam"
                << " needs one blockMesh hex block of nx ny 1 cells." << nl
                << exit(FatalError);
        }
        const boundBox cb(pts, cp, false);
        const vector w = cb.span();
        if (!close(w.z(), span.z(), span.z()))
        {
            FatalErrorInFunction
                << "3D mesh: cell " << c << " spans " << w.z() << " of the"
                << " depth " << span.z() << " in z.  savageHutterFoam needs"
                << " exactly one cell in z (blockMesh: nx ny 1)." << nl
                << exit(FatalError);
        }
        wxMin = min(wxMin, w.x());
        wxMax = max(wxMax, w.x());
        wyMin = min(wyMin, w.y());
        wyMax = max(wyMax, w.y());
    }

    reduce(wxMin, minOp<scalar>());
    reduce(wxMax, maxOp<scalar>());
    reduce(wyMin, minOp<scalar>());
    reduce(wyMax, maxOp<scalar>());
    if (!close(wxMin, wxMax, wxMax) || !close(wyMin, wyMax, wyMax))
    {
        FatalErrorInFunction
            << "Graded or non-uniform mesh: cell widths range over"
            << " [" << wxMin << ", " << wxMax << "] in x and"
            << " [" << wyMin << ", " << wyMax << "] in y."
            << "  savageHutterFoam needs uniform spacing"
            << " (blockMesh: simpleGrading (1 1 1))." << nl
            << exit(FatalError);
    }
}

} // namespace


labelVector structuredMesh::readBlockCounts(const Time& runTime)
{
    const fileName dictFiles[2] =
    {
        runTime.system()/"blockMeshDict",
        runTime.constant()/"polyMesh"/"blockMeshDict"
    };
    for (const fileName& rel : dictFiles)
    {
        // The case's own (a processor directory of a decomposed case has
        // none: the undecomposed case's)
        const fileName file(runTime.globalPath()/rel);
        if (!isFile(file))
        {
            continue;
        }
        IFstream is(file);
        const dictionary dict(is);
        checkScale(dict, file);

        if (!dict.found("blocks", keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "No blocks in " << file << "." << nl << blockNeeds << nl
                << exit(FatalIOError);
        }
        ITstream& blocks = dict.lookup("blocks");
        label nHex = 0;
        labelVector n(labelVector::zero);
        forAll(blocks, i)
        {
            if (!blocks[i].isWord() || blocks[i].wordToken() != "hex")
            {
                continue;
            }
            ++nHex;
            n = hexCounts(blocks, i, dict, file);
        }
        if (nHex != 1)
        {
            FatalIOErrorInFunction(dict)
                << "blockMeshDict " << file << " has " << nHex
                << " blocks in blocks.  " << blockNeeds << nl
                << exit(FatalIOError);
        }
        return n;
    }
    return labelVector::zero;
}


void structuredMesh::checkCellCount
(
    const fvMesh& mesh,
    const label nCellsWhole
) const
{
    const bool parallel = Pstream::parRun();
    if (mesh.nCells() == 0)
    {
        FatalErrorInFunction << "The mesh has no cells" << nl
            << (parallel ? refusedSplit() : std::string()).c_str()
            << exit(FatalError);
    }

    // A mesh that blockMesh did not make from the blockMeshDict there is
    // (an edit of the cell counts after which blockMesh failed or was not
    // run again)
    const labelVector n = readBlockCounts(mesh.time());
    const scalar nBlock = scalar(n.x())*n.y()*n.z();
    if (nBlock > 0 && nBlock != nCellsWhole)
    {
        FatalErrorInFunction
            << "The mesh in constant/polyMesh has " << nCellsWhole
            << " cells" << (parallel ? " (all processors)" : "") << ","
            << " but blocks of system/blockMeshDict give " << n.x() << " x "
            << n.y() << " x " << n.z() << " = " << nBlock << ": the"
            << " mesh was not made from it (blockMesh failed, or was not run"
            << " again after an edit).  Run blockMesh." << nl
            << exit(FatalError);
    }
}


void structuredMesh::setGrid
(
    const fvMesh& mesh,
    const boundBox& bb,
    const label nCellsWhole
)
{
    const label nCells = mesh.nCells();
    const vector span = bb.span();
    // The whole grid's box: the same points as the serial run's, reduced
    const vector wholeMin
    (
        returnReduce(bb.min().x(), minOp<scalar>()),
        returnReduce(bb.min().y(), minOp<scalar>()),
        0
    );
    const vector wholeMax
    (
        returnReduce(bb.max().x(), maxOp<scalar>()),
        returnReduce(bb.max().y(), maxOp<scalar>()),
        0
    );
    scalar wxMax, wyMax;
    uniformWidths(mesh, span, wxMax, wyMax);

    // The whole grid as the serial run forms it (span / count)
    const scalar wholeSpanX = wholeMax.x() - wholeMin.x();
    const scalar wholeSpanY = wholeMax.y() - wholeMin.y();
    nxWhole_ = label(wholeSpanX/wxMax + 0.5);
    nyWhole_ = label(wholeSpanY/wyMax + 0.5);
    dx_ = wholeSpanX/nxWhole_;
    dy_ = wholeSpanY/nyWhole_;
    xMin_ = wholeMin.x();
    yMin_ = wholeMin.y();
    xMax_ = wholeMax.x();
    yMax_ = wholeMax.y();
    nx_ = label(span.x()/dx_ + 0.5);
    ny_ = label(span.y()/dy_ + 0.5);
    i0_ = label((bb.min().x() - xMin_)/dx_ + 0.5);
    j0_ = label((bb.min().y() - yMin_)/dy_ + 0.5);

    if (nxWhole_*nyWhole_ != nCellsWhole)
    {
        FatalErrorInFunction
            << "The mesh is not one rectangular block: " << nCellsWhole
            << " cells in a bounding box of " << nxWhole_ << " x "
            << nyWhole_ << " cells of " << dx_ << " x " << dy_ << " m."
            << "  Several blocks or a non-rectangular domain are not"
            << " supported." << nl << exit(FatalError);
    }
    if (nx_*ny_ != nCells)
    {
        FatalErrorInFunction
            << "Processor " << Pstream::myProcNo() << " holds " << nCells
            << " cells in a bounding box of " << nx_ << " x " << ny_
            << " cells at (" << i0_ << ", " << j0_ << ") of the " << nxWhole_
            << " x " << nyWhole_ << " block: its part is not a rectangle."
            << nl << refusedSplit().c_str() << exit(FatalError);
    }
}


void structuredMesh::mapCells(const fvMesh& mesh, const boundBox& bb)
{
    const label nCells = mesh.nCells();
    const vector span = bb.span();
    // Axis-aligned boxes, each grid cell exactly once
    const vectorField& C = mesh.C().primitiveField();
    gridIndex_.setSize(nCells);
    labelList meshCell(nCells, -1);
    const scalarField& V = mesh.V().field();
    const scalar vCell = dx_*dy_*span.z();
    forAll(C, c)
    {
        if (!close(V[c], vCell, vCell))
        {
            FatalErrorInFunction
                << "Cell " << c << " is not an axis-aligned box of "
                << dx_ << " x " << dy_ << " x " << span.z()
                << " (volume " << V[c] << " instead of " << vCell << ")."
                << "  x must be the downslope and y the cross-slope"
                << " direction of the block." << nl
                << exit(FatalError);
        }
        const label i =
            min(label((C[c].x() - bb.min().x())/dx_), nx_ - 1);
        const label j =
            min(label((C[c].y() - bb.min().y())/dy_), ny_ - 1);
        const label k = i + nx_*j;
        if (meshCell[k] >= 0)
        {
            FatalErrorInFunction
                << "Cells " << meshCell[k] << " and " << c << " both lie in"
                << " grid cell (" << i << ", " << j << ") of the " << nx_
                << " x " << ny_ << " block: the mesh is not one uniform"
                << " block." << nl << exit(FatalError);
        }
        meshCell[k] = c;
        gridIndex_[c] = k;
    }
}


void structuredMesh::findSidePatches
(
    const fvMesh& mesh,
    List<FixedList<label, 4>>& procFaces
)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    List<DynamicList<label>> onSide(4);
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const bool isEmpty = isA<emptyPolyPatch>(pp);
        const bool isProc = isA<processorPolyPatch>(pp);
        const vectorField nf(pp.faceNormals());
        bool sides[4] = {false, false, false, false};
        forAll(nf, facei)
        {
            const vector& n = nf[facei];
            if (mag(n.z()) > 1 - lengthTol)
            {
                if (!isEmpty)
                {
                    FatalErrorInFunction
                        << "Patch " << pp.name() << " of type " << pp.type()
                        << " holds front/back faces; those must be in an"
                        << " empty patch (2D mesh)." << nl
                        << exit(FatalError);
                }
                continue;
            }
            // Along x or y: checked for every face above
            const label s = mag(n.x()) > mag(n.y())
                ? (n.x() < 0 ? 0 : 1)
                : (n.y() < 0 ? 2 : 3);
            if (isProc)
            {
                ++procFaces[patchi][s];
            }
            else
            {
                sides[s] = true;
            }
        }
        for (label s = 0; s < 4; ++s)
        {
            if (sides[s])
            {
                onSide[s].append(patchi);
            }
        }
    }
    for (label s = 0; s < 4; ++s)
    {
        sidePatches_[s].transfer(onSide[s]);
    }
}


void structuredMesh::findNeighbours
(
    const fvMesh& mesh,
    const List<FixedList<label, 4>>& procFaces
)
{
    // Processor patches: each one whole side of this rectangle, toward a
    // side of the part that lies inside the whole grid
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    forAll(patches, patchi)
    {
        if (!isA<processorPolyPatch>(patches[patchi]))
        {
            continue;
        }
        const processorPolyPatch& pp =
            refCast<const processorPolyPatch>(patches[patchi]);
        for (label s = 0; s < 4; ++s)
        {
            const label faces = procFaces[patchi][s];
            if (faces == 0)
            {
                continue;
            }
            const label along = s < 2 ? ny_ : nx_;
            if (faces != pp.size() || faces != along || neighbour_[s] >= 0)
            {
                FatalErrorInFunction
                    << "Processor " << Pstream::myProcNo() << " ("
                    << nx_ << " x " << ny_ << " cells at (" << i0_ << ", "
                    << j0_ << ")): its patch " << pp.name() << " toward"
                    << " processor " << pp.neighbProcNo() << " holds "
                    << faces << " of its " << pp.size() << " faces on side "
                    << sideNames[s] << ", which is " << along << " cells"
                    << " long: neighbours do not share whole sides." << nl
                    << refusedSplit().c_str() << exit(FatalError);
            }
            neighbour_[s] = pp.neighbProcNo();
        }
    }
    const FixedList<bool, 4> onEdge
    ({
        i0_ == 0, i0_ + nx_ == nxWhole_, j0_ == 0, j0_ + ny_ == nyWhole_
    });
    for (label s = 0; s < 4; ++s)
    {
        if ((neighbour_[s] < 0) != onEdge[s])
        {
            FatalErrorInFunction
                << "Processor " << Pstream::myProcNo() << " (" << nx_
                << " x " << ny_ << " cells at (" << i0_ << ", " << j0_
                << ")): its side " << sideNames[s] << " lies "
                << (onEdge[s] ? "on" : "inside") << " the whole block but"
                << " is " << (neighbour_[s] < 0 ? "not " : "")
                << "a processor patch." << nl << refusedSplit().c_str()
                << exit(FatalError);
        }
    }
}


structuredMesh::structuredMesh(const fvMesh& mesh)
:
    nx_(0),
    ny_(0),
    dx_(0),
    dy_(0),
    xMin_(0),
    yMin_(0),
    xMax_(0),
    yMax_(0),
    nxWhole_(0),
    nyWhole_(0),
    i0_(0),
    j0_(0),
    neighbour_(-1),
    sidePatches_(4)
{
    const label nCellsWhole = returnReduce(mesh.nCells(), sumOp<label>());
    checkCellCount(mesh, nCellsWhole);
    checkAxisAligned(mesh);

    // The grid from the bounding box and the cell widths, each mesh cell
    // mapped to its grid cell
    const boundBox bb(mesh.points(), false);
    setGrid(mesh, bb, nCellsWhole);
    mapCells(mesh, bb);

    // Boundary faces: front/back in empty patches, the rest on the sides;
    // the faces of each processor patch on each side give the neighbours
    List<FixedList<label, 4>> procFaces
    (
        mesh.boundaryMesh().size(), FixedList<label, 4>(0)
    );
    findSidePatches(mesh, procFaces);
    findNeighbours(mesh, procFaces);
}


std::string structuredMesh::refusedSplit() const
{
    return
        "savageHutterFoam runs decomposed only when each processor holds a"
        " rectangle of the block and neighbours share whole sides: in"
        " system/decomposeParDict, method simple or hierarchical with n"
        " (nx ny 1) that divide the block's cell counts"
      + std::string
        (
            nxWhole_ > 0
          ? " (here " + std::to_string(nxWhole_) + " x "
          + std::to_string(nyWhole_) + ")"
          : std::string()
        )
      + ", or method manual with such a split; then decomposePar -force\n";
}


sh::Subdomain structuredMesh::subdomain() const
{
    sh::Subdomain s;
    s.nxWhole = int(nxWhole_);
    s.nyWhole = int(nyWhole_);
    s.i0 = int(i0_);
    s.j0 = int(j0_);
    s.nx = int(nx_);
    s.ny = int(ny_);
    for (label side = 0; side < 4; ++side)
    {
        s.neighbour[side] = int(neighbour_[side]);
    }
    return s;
}

} // End namespace Foam

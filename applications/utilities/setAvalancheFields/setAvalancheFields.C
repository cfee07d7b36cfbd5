/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Application
    setAvalancheFields

Description
    Sets the initial thickness h, velocity U and basal topography zb of a
    savageHutterFoam case from shapes named in system/setAvalancheFieldsDict,
    the release shapes and beds of avalanche test cases that setFields
    cannot express.  Each field is the sum of its shapes evaluated at the
    cell centres (x, y); fields not listed are left as they are.  Every
    number of a shape and every value set must be finite and at most 1e30
    in magnitude (as savageHutterFoam requires), h >= 0, and a keyword a
    shape does not have is an error (never a silent default); on any error
    nothing is written.  Boundary
    conditions of existing fields are kept; a missing 0/zb is created with
    zeroGradient patches.

    The erodible layer and the resistance areas (docs/design.md section
    7) take the scalar shapes too: hEntrainable, the thickness [m] that
    may be entrained (normal to the bed, as h), and cResistance, the
    resistance coefficient [1/m] of the extra drag c_res |u|^2; both
    must come out >= 0, and each, when listed, is created with
    zeroGradient patches where the case has none.

    Shapes (centre, min, max, gradient, origin are (x y) pairs):

        hemisphere { centre (4 0); radius 1.85; }       sqrt(R^2 - r^2)
        cone       { centre (0 0); radius 0.2; height 0.2; }  H (1 - r/R)
        paraboloid { centre (0 0); radius 1; height 1; }  H (1 - r^2/R^2)
        box        { min (-1 -1); max (0 1); value 10; }   value inside
        damBreak   { position 0; upstream 10; downstream 0; }
                                        upstream for x < position, else
                                        downstream
        plane      { origin (0 0); value 0; gradient (0.1 0); }
                                        value + gradient . (x - origin)
        bowl       { centre (0 0); slope 0.5; }         slope r (eq. 34)
        gaussian   { centre (0 0); amplitude 1; width 0.5; }
                                        A exp(-r^2/(2 w^2))
        channel    { axis 0; curvature 0.1; }
                                        curvature (y - axis)^2 / 2

    U takes box and damBreak shapes with vector values, e.g.
        box { min (0 -1); max (1 1); value (1 0 0); }

    Example system/setAvalancheFieldsDict:

        h  ( hemisphere { centre (4 0); radius 1.85; } );
        zb ( bowl { centre (0 0); slope 0.5; } );
        hEntrainable ( box { min (8 -2); max (20 2); value 0.3; } );
        cResistance  ( box { min (20 -2); max (25 2); value 0.01; } );

Usage
    setAvalancheFields [-dict file]
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "vector2D.H"

using namespace Foam;

namespace
{

const wordList scalarShapes
({
    "hemisphere", "cone", "paraboloid", "box", "damBreak", "plane", "bowl",
    "gaussian", "channel"
});

const wordList vectorShapes({"box", "damBreak"});

//- The keywords of each shape (a misspelt one must not fall back to a
//  default)
wordList shapeKeywords(const word& type)
{
    if (type == "hemisphere") return {"centre", "radius"};
    if (type == "cone" || type == "paraboloid")
    {
        return {"centre", "radius", "height"};
    }
    if (type == "box") return {"min", "max", "value"};
    if (type == "damBreak") return {"position", "upstream", "downstream"};
    if (type == "plane") return {"origin", "value", "gradient"};
    if (type == "bowl") return {"centre", "slope"};
    if (type == "gaussian") return {"centre", "amplitude", "width"};
    if (type == "channel") return {"axis", "curvature"};
    return wordList();
}

vector2D xy(const point& p)
{
    return vector2D(p.x(), p.y());
}

//- Magnitudes beyond this are refused, as savageHutterFoam refuses them in
//  its initial fields (its squares and products would overflow)
const scalar bound = 1e30;

bool bounded(const scalar v)
{
    return mag(v) <= bound;
}

bool bounded(const vector2D& v)
{
    return bounded(v.x()) && bounded(v.y());
}

bool bounded(const vector& v)
{
    return bounded(v.x()) && bounded(v.y()) && bounded(v.z());
}

//- An entry of a shape: a finite number (or vector) of magnitude at most
//  1e30, else FatalIOError naming the keyword
template<class Type>
Type get(const dictionary& d, const word& key)
{
    const Type v = d.get<Type>(key);
    if (!bounded(v))
    {
        FatalIOErrorInFunction(d)
            << "Invalid " << key << " " << v << ": must be finite, of"
            << " magnitude at most " << bound << nl << exit(FatalIOError);
    }
    return v;
}

template<class Type>
Type getOrDefault(const dictionary& d, const word& key, const Type& deflt)
{
    return d.found(key, keyType::LITERAL) ? get<Type>(d, key) : deflt;
}

scalar positive(const dictionary& d, const word& key)
{
    const scalar v = get<scalar>(d, key);
    if (!(v > 0))
    {
        FatalIOErrorInFunction(d)
            << key << " must be positive, got " << v << nl
            << exit(FatalIOError);
    }
    return v;
}

//- Whether p lies in a box or on the upstream side of a dam, and then the
//  value the shape takes there (for Type = scalar or vector)
template<class Type>
bool region(const word& type, const dictionary& d, const point& p, Type& v)
{
    if (type == "box")
    {
        const vector2D lo = get<vector2D>(d, "min");
        const vector2D hi = get<vector2D>(d, "max");
        v = get<Type>(d, "value");
        return p.x() >= lo.x() && p.x() <= hi.x()
            && p.y() >= lo.y() && p.y() <= hi.y();
    }
    // damBreak
    const bool up = p.x() < get<scalar>(d, "position");
    v = get<Type>(d, up ? "upstream" : "downstream");
    return true;
}

scalar scalarShape(const word& type, const dictionary& d, const point& p)
{
    if (type == "box" || type == "damBreak")
    {
        scalar v = 0;
        return region(type, d, p, v) ? v : 0;
    }
    if (type == "plane")
    {
        const vector2D o = getOrDefault<vector2D>(d, "origin", vector2D::zero);
        const vector2D g = get<vector2D>(d, "gradient");
        return getOrDefault<scalar>(d, "value", 0) + (g & (xy(p) - o));
    }
    if (type == "channel")
    {
        const scalar y = p.y() - getOrDefault<scalar>(d, "axis", 0);
        return 0.5*get<scalar>(d, "curvature")*y*y;
    }

    const vector2D c = get<vector2D>(d, "centre");
    const scalar r = mag(xy(p) - c);
    if (type == "bowl")
    {
        return get<scalar>(d, "slope")*r;
    }
    if (type == "gaussian")
    {
        const scalar w = positive(d, "width");
        return get<scalar>(d, "amplitude")*Foam::exp(-0.5*sqr(r/w));
    }
    const scalar R = positive(d, "radius");
    if (r >= R)
    {
        return 0;
    }
    if (type == "hemisphere")
    {
        return Foam::sqrt(R*R - r*r);
    }
    if (type == "cone")
    {
        return positive(d, "height")*(1 - r/R);
    }
    // paraboloid
    return positive(d, "height")*(1 - sqr(r/R));
}

//- The shapes listed under name, each checked against the valid types
PtrList<entry> shapes
(
    const dictionary& dict,
    const word& name,
    const wordList& valid
)
{
    // A list of shape dictionaries, name ( shape { ... } ... ): anything
    // else is refused here, before the list reader meets it
    const entry* e = dict.findEntry(name, keyType::LITERAL);
    bool isList =
        e && e->isStream() && e->stream().size()
     && e->stream()[0].isPunctuation()
     && e->stream()[0].pToken() == token::BEGIN_LIST;
    if (isList)
    {
        // Each element a word followed by a { ... } dictionary
        const ITstream& is = e->stream();
        const auto punct = [&](label i, token::punctuationToken p)
        {
            return i < is.size() && is[i].isPunctuation()
                && is[i].pToken() == p;
        };
        label i = 1;
        while (isList && !punct(i, token::END_LIST))
        {
            isList = i + 1 < is.size() && is[i].isWord()
                  && punct(i + 1, token::BEGIN_BLOCK);
            label depth = 0;
            for (i += 1; isList && i < is.size(); ++i)
            {
                depth += punct(i, token::BEGIN_BLOCK);
                depth -= punct(i, token::END_BLOCK);
                if (depth == 0)
                {
                    ++i;
                    break;
                }
            }
            isList = isList && depth == 0 && i < is.size();
        }
    }
    if (!isList)
    {
        FatalIOErrorInFunction(dict)
            << "Invalid " << name << ": it must be a list of shapes, "
            << name << " ( <shape> { ... } ... );" << nl
            << "Valid shapes for " << name << ": " << flatOutput(valid) << nl
            << exit(FatalIOError);
    }
    PtrList<entry> list(dict.lookup(name));
    forAll(list, k)
    {
        if (!list[k].isDict() || !valid.found(list[k].keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown shape '" << list[k].keyword() << "' in " << name
                << "." << nl << "Valid shapes for " << name << ": "
                << flatOutput(valid) << nl << exit(FatalIOError);
        }
        const wordList keys(shapeKeywords(list[k].keyword()));
        for (const word& key : list[k].dict().toc())
        {
            if (!keys.found(key))
            {
                FatalIOErrorInFunction(list[k].dict())
                    << "Unknown keyword '" << key << "' of the "
                    << list[k].keyword() << " in " << name << "." << nl
                    << "Valid keywords: " << flatOutput(keys) << nl
                    << exit(FatalIOError);
            }
        }
    }
    return list;
}

//- A shape's value at p: scalars from every shape, vectors from regions
template<class Type>
Type shapeValue(const word& type, const dictionary& d, const point& p);

template<>
scalar shapeValue<scalar>(const word& type, const dictionary& d, const point& p)
{
    return scalarShape(type, d, p);
}

template<>
vector shapeValue<vector>(const word& type, const dictionary& d, const point& p)
{
    vector v(Zero);
    return region(type, d, p, v) ? v : vector(Zero);
}

//- Field `name` as the sum of its shapes at the cell centres
template<class Type>
void setField
(
    const dictionary& dict,
    const word& name,
    const wordList& valid,
    GeometricField<Type, fvPatchField, volMesh>& f,
    const volVectorField::Internal& C
)
{
    const PtrList<entry> list(shapes(dict, name, valid));
    f.primitiveFieldRef() = Zero;
    forAll(list, k)
    {
        const word& type = list[k].keyword();
        const dictionary& d = list[k].dict();
        Info<< "    " << name << ": " << type << " " << d << endl;
        forAll(C, c)
        {
            f[c] += shapeValue<Type>(type, d, C[c]);
        }
    }
    forAll(f, c)
    {
        if (!bounded(f[c]))
        {
            FatalIOErrorInFunction(dict)
                << "The shapes of " << name << " give " << name << " = "
                << f[c] << " in cell " << c << " at " << C[c] << ", beyond "
                << bound << " in magnitude; check their entries:" << nl
                << dict.findEntry(name, keyType::LITERAL)->stream() << nl
                << exit(FatalIOError);
        }
    }
    f.correctBoundaryConditions();
}

IOobject fieldIO(const fvMesh& mesh, const word& name)
{
    return IOobject
    (
        name, mesh.time().timeName(), mesh,
        IOobject::MUST_READ, IOobject::NO_WRITE
    );
}

//- setAvalancheFields' note and options: -dict; serial
void declareOptions()
{
    argList::addNote
    (
        "Set h, U, zb, hEntrainable and cResistance of a savageHutterFoam"
        " case from the shapes in system/setAvalancheFieldsDict"
    );
    argList::addOption("dict", "file", "alternative dictionary");
    argList::noParallel();
}

//- The dictionary of the shapes: system/setAvalancheFieldsDict, or the
//  file -dict names
IOobject shapesDictIO(const argList& args, const Time& runTime)
{
    const fileName dictFile =
        args.getOrDefault<fileName>
        (
            "dict", runTime.system()/"setAvalancheFieldsDict"
        );
    Info<< "Reading " << dictFile << nl << endl;
    return IOobject
    (
        dictFile, runTime, IOobject::MUST_READ, IOobject::NO_WRITE
    );
}

const wordList validEntries({"h", "U", "zb", "hEntrainable", "cResistance"});

//- The dictionary has the entries validEntries lists only
void checkEntries(const dictionary& dict)
{
    for (const word& key : dict.toc())
    {
        if (!validEntries.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << key << "'; valid entries: "
                << flatOutput(validEntries) << nl << exit(FatalIOError);
        }
    }
}

//- FatalIOError naming the field, the value and the cell where the shapes
//  of f give a negative value (h, hEntrainable, cResistance)
void checkNonNegative
(
    const dictionary& dict, const autoPtr<volScalarField>& f,
    const volVectorField::Internal& C
)
{
    if (!f.valid())
    {
        return;
    }
    const word& name = f().name();
    forAll(f(), c)
    {
        if (f()[c] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "The shapes of " << name << " give " << name << " = "
                << f()[c] << " < 0 in cell " << c << " at " << C[c]
                << " (" << name << " must be >= 0); check their entries:"
                << nl << dict.findEntry(name, keyType::LITERAL)->stream()
                << nl << exit(FatalIOError);
        }
    }
}

//- h of its shapes, which must give h >= 0; none where dict has no h
autoPtr<volScalarField> thicknessField
(
    const dictionary& dict, const fvMesh& mesh,
    const volVectorField::Internal& C
)
{
    autoPtr<volScalarField> h;
    if (dict.found("h"))
    {
        h.reset(new volScalarField(fieldIO(mesh, "h"), mesh));
        setField(dict, "h", scalarShapes, h(), C);
        checkNonNegative(dict, h, C);
    }
    return h;
}

//- U of its shapes; none where dict has no U
autoPtr<volVectorField> velocityField
(
    const dictionary& dict, const fvMesh& mesh,
    const volVectorField::Internal& C
)
{
    autoPtr<volVectorField> U;
    if (dict.found("U"))
    {
        U.reset(new volVectorField(fieldIO(mesh, "U"), mesh));
        setField(dict, "U", vectorShapes, U(), C);
    }
    return U;
}

//- Scalar field `name` of its shapes (zb, hEntrainable, cResistance),
//  created with zeroGradient patches and dimensions dims where the case
//  has none; none where dict does not list it
autoPtr<volScalarField> optionalField
(
    const dictionary& dict, const fvMesh& mesh,
    const volVectorField::Internal& C, const word& name,
    const dimensionSet& dims
)
{
    autoPtr<volScalarField> f;
    if (dict.found(name))
    {
        IOobject io(fieldIO(mesh, name));
        if (io.typeHeaderOk<volScalarField>(true))
        {
            f.reset(new volScalarField(io, mesh));
        }
        else
        {
            io.readOpt() = IOobject::NO_READ;
            f.reset
            (
                new volScalarField
                (
                    io, mesh, dimensionedScalar(dims, Zero), "zeroGradient"
                )
            );
        }
        setField(dict, name, scalarShapes, f(), C);
    }
    return f;
}

//- A thickness field's volume, the sum of f dA [m^3] (in plan coordinates
//  the volume on the bed is the sum of J f dA: savageHutterFoam's log)
scalar volumeOf(const fvMesh& mesh, const volScalarField& f)
{
    return gSum(f.primitiveField()*mesh.V()/(mesh.bounds().span().z()));
}

//- Write f where it was set, with what the log says of it
void writeField
(
    const autoPtr<volScalarField>& f, const fvMesh& mesh, bool thickness,
    const char* unit
)
{
    if (!f.valid())
    {
        return;
    }
    Info<< "Writing " << f().name();
    if (thickness)
    {
        Info<< ": volume " << volumeOf(mesh, f()) << " m^3";
    }
    else
    {
        Info<< ": range [" << gMin(f().primitiveField()) << ", "
            << gMax(f().primitiveField()) << "] " << unit;
    }
    Info<< nl << endl;
    f().write();
}

} // namespace


int main(int argc, char *argv[])
{
    declareOptions();

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const IOdictionary dict(shapesDictIO(args, runTime));
    checkEntries(dict);

    // Every field first, then the writes: a shape refused in one field
    // leaves all of them as they were
    const volVectorField::Internal& C = mesh.C();
    const autoPtr<volScalarField> h = thicknessField(dict, mesh, C);
    const autoPtr<volVectorField> U = velocityField(dict, mesh, C);
    const autoPtr<volScalarField> zb =
        optionalField(dict, mesh, C, "zb", dimLength);
    const autoPtr<volScalarField> hEntrainable =
        optionalField(dict, mesh, C, "hEntrainable", dimLength);
    checkNonNegative(dict, hEntrainable, C);
    const autoPtr<volScalarField> cResistance =
        optionalField(dict, mesh, C, "cResistance", dimless/dimLength);
    checkNonNegative(dict, cResistance, C);

    writeField(h, mesh, true, "m");
    if (U.valid())
    {
        Info<< "Writing U" << nl << endl;
        U().write();
    }
    writeField(zb, mesh, false, "m");
    writeField(hEntrainable, mesh, true, "m");
    writeField(cResistance, mesh, false, "1/m");

    Info<< "End\n" << endl;
    return 0;
}

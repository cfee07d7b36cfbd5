/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "ensembleInput.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "Tuple2.H"
#include "DynamicList.H"
#include "mathematicalConstants.H"
#include "physics/entrainment.H"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace Foam
{

namespace
{

const wordList ensembleKeywords
({
    "parameters", "combine", "samples", "seed", "thresholds", "percentiles",
    "runoutThreshold"
});

//- Most members an ensemble may have
const label maxMembers = 100000;

//- A uniform value in [0, 1) from the top 53 bits of one draw
double unit(std::mt19937_64& rng)
{
    return double(rng() >> 11)*(1.0/9007199254740992.0);
}

//- One parameter as ensembleDict gives it
struct parameter
{
    word name;
    bool words = false;         //!< release: names of fields
    word distribution;          //!< uniform, normal, or empty: a list
    scalarList values;          //!< the list, or (a b) / (mean sd)
    wordList names;
};

//- The number of values (or fields) a parameter lists
label count(const parameter& p)
{
    return p.words ? p.names.size() : p.values.size();
}

//- No ensembleDict: say what one looks like
void requireDict(const Time& runTime)
{
    const fileName path = runTime.path()/runTime.system()/"ensembleDict";
    if (!isFile(path))
    {
        FatalErrorInFunction
            << "savageHutterFoam -ensemble needs " << path << ", e.g." << nl
            << "    parameters" << nl << "    {" << nl
            << "        \"CoulombCoeffs/delta\"  (20 22 24);" << nl
            << "        hScale                 (0.5 1 2);" << nl
            << "    }" << nl << "    combine product;   // or list" << nl
            << "(docs/design.md section 6)" << nl << exit(FatalError);
    }
}

//- Every keyword known, and a sub-dictionary parameters
void checkKeywords(const dictionary& dict)
{
    for (const word& key : dict.toc())
    {
        if (!ensembleKeywords.found(key) && key != "FoamFile")
        {
            FatalIOErrorInFunction(dict)
                << "Unknown keyword '" << key << "'." << nl
                << "Valid keywords: " << flatOutput(ensembleKeywords) << nl
                << exit(FatalIOError);
        }
    }
    if (!dict.isDict("parameters"))
    {
        FatalIOErrorInFunction(dict)
            << "Missing sub-dictionary 'parameters' { <name> <values>; ... }"
            << nl << exit(FatalIOError);
    }
}

//- samples (sampled: ensembleDict has samples), or combine product or
//  list; a seed only with samples, and not samples and combine both
word readMode(const dictionary& dict, const bool sampled)
{
    if (!sampled && dict.found("seed"))
    {
        FatalIOErrorInFunction(dict)
            << "seed without samples: a seed draws 'samples N' members from"
            << " ranges; with listed values (combine) there is nothing to draw"
            << nl << exit(FatalIOError);
    }
    if (sampled && dict.found("combine"))
    {
        FatalIOErrorInFunction(dict)
            << "Give either 'samples N; seed S;' (values drawn from ranges)"
            << " or 'combine product|list;' (values listed), not both" << nl
            << exit(FatalIOError);
    }
    const word mode = sampled ? word("samples") : dict.getOrDefault<word>("combine", "product");
    if (!wordList({"product", "list", "samples"}).found(mode) || mode == "samples" && !sampled)
    {
        FatalIOErrorInFunction(dict)
            << "Unknown combine '" << mode << "'." << nl
            << "Valid choices: (product list)" << nl << exit(FatalIOError);
    }
    return mode;
}

//- The entries of parameters in the order listed, each with the
//  dictionary that holds it: a keyword path such as "CoulombCoeffs/delta"
//  reads as the entry delta of a sub-dictionary CoulombCoeffs (so does
//  CoulombCoeffs { delta (...); }), which gathers every path into it where
//  the first appeared: their lines in the file give back the order they
//  were written in
DynamicList<Tuple2<word, const dictionary*>> entriesInOrder
(
    const dictionary& pd
)
{
    DynamicList<Tuple2<word, const dictionary*>> entries;
    DynamicList<label> lines;
    for (const word& name : pd.toc())
    {
        if (pd.isDict(name))
        {
            const dictionary& sub = pd.subDict(name);
            for (const word& key : sub.toc())
            {
                entries.append({name + "/" + key, &sub});
                lines.append(sub.findEntry(key, keyType::LITERAL)->startLineNumber());
            }
        }
        else
        {
            entries.append({name, &pd});
            lines.append(pd.findEntry(name, keyType::LITERAL)->startLineNumber());
        }
    }
    labelList order(entries.size());
    forAll(order, i)
    {
        order[i] = i;
    }
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b) { return lines[a] < lines[b]; }
    );
    DynamicList<Tuple2<word, const dictionary*>> sorted;
    for (const label i : order)
    {
        sorted.append(entries[i]);
    }
    return sorted;
}

//- A parameter given by a distribution (p.distribution, read from is):
//  its range, uniform (a b) or normal (mean sd); only with samples, and
//  not for release
void readRange
(
    parameter& p,
    ITstream& is,
    const dictionary& in,
    const bool sampled
)
{
    const word& name = p.name;
    if (!sampled || p.words)
    {
        FatalIOErrorInFunction(in)
            << "Parameter '" << name << "': a distribution ("
            << p.distribution << ") "
            << (p.words
                ? "for release: give the fields as a list"
                : "needs 'samples N; seed S;' (with combine, list the"
                  " values)")
            << nl << exit(FatalIOError);
    }
    if (p.distribution != "uniform" && p.distribution != "normal")
    {
        FatalIOErrorInFunction(in)
            << "Parameter '" << name << "': unknown distribution '"
            << p.distribution << "'." << nl
            << "Valid choices: (uniform normal)" << nl
            << exit(FatalIOError);
    }
    p.values = scalarList(is);
    const bool uniform = p.distribution == "uniform";
    if
    (
        p.values.size() != 2
     || !std::isfinite(p.values[0]) || !std::isfinite(p.values[1])
     || (uniform ? !(p.values[0] <= p.values[1]) : !(p.values[1] >= 0))
    )
    {
        FatalIOErrorInFunction(in)
            << "Parameter '" << name << "': " << p.distribution
            << " " << p.values << " is not a range." << nl
            << "Valid: " << (uniform ? "uniform (a b) with a <= b"
                : "normal (mean sd) with sd >= 0") << ", finite"
            << nl << exit(FatalIOError);
    }
}

//- A parameter given by a list (read from is): its values, finite, or
//  for release the names of fields; values only with combine
void readList
(
    parameter& p,
    ITstream& is,
    const dictionary& in,
    const bool sampled
)
{
    const word& name = p.name;
    if (p.words)
    {
        p.names = wordList(is);
    }
    else
    {
        p.values = scalarList(is);
    }
    const label n = p.words ? p.names.size() : p.values.size();
    if (n == 0)
    {
        FatalIOErrorInFunction(in)
            << "Parameter '" << name << "' has no values" << nl
            << exit(FatalIOError);
    }
    if (sampled && !p.words)
    {
        FatalIOErrorInFunction(in)
            << "Parameter '" << name << "': with samples, give a"
            << " range, uniform (a b) or normal (mean sd)" << nl
            << exit(FatalIOError);
    }
    for (const scalar v : p.values)
    {
        if (!std::isfinite(v))
        {
            FatalIOErrorInFunction(in)
                << "Parameter '" << name << "': " << v
                << " is not a finite number" << nl
                << exit(FatalIOError);
        }
    }
}

//- The parameter `name` of dictionary `in` (an entry of parameters or of
//  a sub-dictionary of it): a valid name, then a range or a list
parameter readParameter
(
    const word& name,
    const dictionary& in,
    const bool sampled,
    const wordList& allValid
)
{
    const word key = name.substr(name.rfind('/') + 1);
    if (!allValid.found(name) || in.isDict(key))
    {
        FatalIOErrorInFunction(in)
            << "Unknown parameter '" << name << "'." << nl
            << "Valid parameters: " << flatOutput(allValid)
            << " (the coefficients of the frictionModel and of the"
            << " entrainmentModel selected in transportProperties)" << nl
            << exit(FatalIOError);
    }
    parameter p;
    p.name = name;
    p.words = name == "release";
    ITstream& is = in.lookup(key);
    token first(is);
    if (first.isWord())
    {
        p.distribution = first.wordToken();
        readRange(p, is, in, sampled);
    }
    else
    {
        is.putBack(first);
        readList(p, is, in, sampled);
    }
    return p;
}

//- The number of members: samples (with a seed), as many as each
//  parameter has values (combine list) or their product (combine
//  product); from 1 to maxMembers
label memberCount
(
    const dictionary& dict,
    const List<parameter>& params,
    const bool sampled,
    const word& mode
)
{
    label n = 1;
    if (sampled)
    {
        n = dict.get<label>("samples");
        if (!dict.found("seed"))
        {
            FatalIOErrorInFunction(dict)
                << "samples needs a seed (an integer), e.g. seed 1;" << nl
                << exit(FatalIOError);
        }
    }
    else if (mode == "list")
    {
        n = count(params[0]);
        for (const parameter& p : params)
        {
            if (count(p) != n)
            {
                FatalIOErrorInFunction(dict)
                    << "combine list: every parameter needs as many values;"
                    << " '" << params[0].name << "' has " << n << ", '"
                    << p.name << "' " << count(p) << nl << exit(FatalIOError);
            }
        }
    }
    else
    {
        for (const parameter& p : params)
        {
            n *= count(p);
            if (n > maxMembers)
            {
                break;
            }
        }
    }
    if (n < 1 || n > maxMembers)
    {
        FatalIOErrorInFunction(dict)
            << "The ensemble would have " << n << " members." << nl
            << "Valid: 1 to " << maxMembers << nl << exit(FatalIOError);
    }
    return n;
}

//- What member k of n sets (m.values: nKeys, one for each parameter
//  that is neither hScale nor release): drawn from rng, parameter by
//  parameter (samples), or picked, the k-th value of each (combine list)
//  or the last parameter varying fastest (combine product)
void pickMember
(
    ensembleInput::member& m,
    const label k,
    const label n,
    const List<parameter>& params,
    const label nKeys,
    const bool sampled,
    const word& mode,
    std::mt19937_64& rng
)
{
    m.values.resize(nKeys);
    label index = k;
    label stride = n;
    label key = 0;
    forAll(params, q)
    {
        const parameter& p = params[q];
        label pick = 0;
        scalar value = 0;
        if (sampled)
        {
            if (p.words)
            {
                pick = min(label(unit(rng)*p.names.size()), p.names.size() - 1);
            }
            else if (p.distribution == "uniform")
            {
                value = p.values[0] + (p.values[1] - p.values[0])*unit(rng);
            }
            else
            {
                // Box-Muller: u1 in (0, 1]
                const double u1 = 1.0 - unit(rng);
                const double u2 = unit(rng);
                value = p.values[0] + p.values[1]
                   *std::sqrt(-2.0*std::log(u1))
                   *std::cos(2.0*constant::mathematical::pi*u2);
            }
        }
        else
        {
            if (mode == "list")
            {
                pick = k;
            }
            else
            {
                // The last parameter varying fastest
                stride /= count(p);
                pick = index/stride;
                index -= pick*stride;
            }
            if (!p.words)
            {
                value = p.values[pick];
            }
        }
        if (p.words)
        {
            m.release = p.names[pick];
        }
        else if (p.name == "hScale")
        {
            m.hScale = value;
        }
        else if (p.name == "cResistanceScale")
        {
            m.cResistanceScale = value;
        }
        else
        {
            m.values[key++] = value;
        }
    }
}

//- thresholds or percentiles (key: which) name the statistics' fields by
//  "%g" of each value: no two may give the same name
void checkDistinct
(
    const dictionary& dict,
    const scalarList& v,
    const char* key
)
{
    wordList names;
    for (const scalar x : v)
    {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%g", x);
        if (names.found(buf))
        {
            FatalIOErrorInFunction(dict)
                << key << " " << v << ": " << buf << " twice (values"
                << " name the statistics' fields by 6 significant"
                << " digits: each must differ in those)" << nl
                << exit(FatalIOError);
        }
        names.append(buf);
    }
}

} // namespace


ensembleInput::ensembleInput(const Time& runTime, const caseInput& input)
:
    thresholds({0.01, 0.1, 1}),
    percentiles({5, 50, 95})
{
    requireDict(runTime);
    const IOdictionary dict
    (
        IOobject
        (
            "ensembleDict", runTime.system(), runTime,
            IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    Info<< "Reading ensembleDict" << nl;
    checkKeywords(dict);
    const dictionary& pd = dict.subDict("parameters");
    const bool sampled = dict.found("samples");
    mode = readMode(dict, sampled);

    // The parameters, in the order listed
    wordList allValid(input.memberKeywords());
    for (const word& key : entrainmentKeywords(input))
    {
        if (!allValid.found(key))
        {
            allValid.append(key);
        }
    }
    allValid.append("hScale");
    allValid.append("cResistanceScale");
    allValid.append("release");
    List<parameter> params;
    wordList listed;
    for (const auto& en : entriesInOrder(pd))
    {
        const parameter p =
            readParameter(en.first(), *en.second(), sampled, allValid);
        listed.append(p.name);
        if (p.words)
        {
            variesRelease = true;
        }
        else if (p.name == "hScale")
        {
            variesHScale = true;
        }
        else if (p.name == "cResistanceScale")
        {
            variesCResistance = true;
        }
        else
        {
            keys.append(p.name);
        }
        params.append(p);
    }
    if (params.empty())
    {
        FatalIOErrorInFunction(pd)
            << "No parameters to vary." << nl
            << "Valid parameters: " << flatOutput(allValid) << nl
            << exit(FatalIOError);
    }

    // The members, each checked as the case is
    const label n = memberCount(dict, params, sampled, mode);
    std::mt19937_64 rng(sampled ? std::uint64_t(dict.get<label>("seed")) : 0u);
    members.resize(n);
    forAll(members, k)
    {
        pickMember(members[k], k, n, params, keys.size(), sampled, mode, rng);
        checkMember(k, runTime, input, dict);
    }

    // Statistics and the report
    readStatistics(dict);

    Info<< "    " << n << " members (" << mode << ") of "
        << flatOutput(listed) << nl
        << "    thresholds " << flatOutput(thresholds) << " m, percentiles "
        << flatOutput(percentiles) << ", runoutThreshold " << runoutThreshold
        << " m" << nl << endl;
}


void ensembleInput::checkMember
(
    const label k,
    const Time& runTime,
    const caseInput& input,
    const dictionary& dict
) const
{
    const member& m = members[k];
    if (!(m.hScale > 0 && m.hScale <= 1e6))
    {
        FatalIOErrorInFunction(dict)
            << "Member " << k << " (" << describe(k).c_str() << "): hScale "
            << m.hScale << " must be positive (at most 1e6)" << nl
            << exit(FatalIOError);
    }
    if (variesCResistance)
    {
        if (!(m.cResistanceScale >= 0 && m.cResistanceScale <= 1e6))
        {
            FatalIOErrorInFunction(dict)
                << "Member " << k << " (" << describe(k).c_str() << "):"
                << " cResistanceScale " << m.cResistanceScale
                << " must be >= 0 (at most 1e6)" << nl
                << exit(FatalIOError);
        }
        const fileName field = runTime.path()/runTime.timeName()/"cResistance";
        if (!isFile(field))
        {
            FatalIOErrorInFunction(dict)
                << "cResistanceScale: a factor on the resistance field "
                << field << ", which the case does not have" << nl
                << "Valid: cResistanceScale with a 0/cResistance (e.g. from"
                << " setAvalancheFields or terrainToCase)" << nl
                << exit(FatalIOError);
        }
    }
    if
    (
        !m.release.empty()
     && !isFile(runTime.path()/runTime.timeName()/m.release)
    )
    {
        FatalIOErrorInFunction(dict)
            << "Member " << k << ": release field " << m.release
            << " not found: " << runTime.path()/runTime.timeName()/m.release
            << nl << "Valid: the name of a thickness field in the start"
            << " time directory, e.g. h.release1" << nl << exit(FatalIOError);
    }
    std::string why;
    const bool ioThrows = FatalIOError.throwExceptions();
    const bool throws = FatalError.throwExceptions();
    try
    {
        memberModel(input, k);
    }
    catch (const sh::InputError& e)
    {
        why = e.what();
    }
    catch (const error& e)
    {
        why = e.message();
    }
    FatalIOError.throwExceptions(ioThrows);
    FatalError.throwExceptions(throws);
    if (!why.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Member " << k << " (" << describe(k).c_str() << ") is not a"
            << " valid case: " << why.c_str() << nl << exit(FatalIOError);
    }
}


void ensembleInput::readStatistics(const dictionary& dict)
{
    thresholds = dict.getOrDefault<scalarList>("thresholds", thresholds);
    percentiles = dict.getOrDefault<scalarList>("percentiles", percentiles);
    runoutThreshold =
        dict.getOrDefault<scalar>("runoutThreshold", runoutThreshold);
    for (const scalar t : thresholds)
    {
        if (!(t > 0 && t < 1e30))
        {
            FatalIOErrorInFunction(dict)
                << "thresholds " << thresholds << ": each a thickness > 0 [m]"
                << nl << exit(FatalIOError);
        }
    }
    for (const scalar p : percentiles)
    {
        if (!(p >= 0 && p <= 100))
        {
            FatalIOErrorInFunction(dict)
                << "percentiles " << percentiles << ": each in [0, 100]" << nl
                << exit(FatalIOError);
        }
    }
    checkDistinct(dict, thresholds, "thresholds");
    checkDistinct(dict, percentiles, "percentiles");
    if (!(runoutThreshold > 0 && runoutThreshold < 1e30))
    {
        FatalIOErrorInFunction(dict)
            << "runoutThreshold " << runoutThreshold << " must be > 0 [m]"
            << nl << exit(FatalIOError);
    }
}


word ensembleInput::memberName(const label k)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "member%04ld", long(k));
    return buf;
}


dictionary ensembleInput::memberDict(const label k) const
{
    const member& m = members[k];
    dictionary d;
    d.add("member", k);
    // A keyword path as the sub-dictionary it names (as transportProperties
    // and ensembleDict read it): CoulombCoeffs { delta 24; }
    forAll(keys, q)
    {
        const auto slash = keys[q].find('/');
        if (slash == std::string::npos)
        {
            d.add(keys[q], m.values[q]);
        }
        else
        {
            d.subDictOrAdd(word(keys[q].substr(0, slash)))
                .add(word(keys[q].substr(slash + 1)), m.values[q]);
        }
    }
    d.add("hScale", m.hScale);
    if (variesCResistance)
    {
        d.add("cResistanceScale", m.cResistanceScale);
    }
    if (!m.release.empty())
    {
        d.add("release", m.release);
    }
    return d;
}


string ensembleInput::describe(const label k) const
{
    const member& m = members[k];
    OStringStream os;
    os.precision(17);
    forAll(keys, q)
    {
        os << (q ? " " : "") << keys[q] << " " << m.values[q];
    }
    if (variesHScale)
    {
        os << (keys.size() ? " " : "") << "hScale " << m.hScale;
    }
    if (variesCResistance)
    {
        os << (keys.size() || variesHScale ? " " : "") << "cResistanceScale "
            << m.cResistanceScale;
    }
    if (variesRelease)
    {
        os << " release " << m.release;
    }
    return os.str();
}


wordList ensembleInput::entrainmentKeywords(const caseInput& input)
{
    wordList keys;
    const sh::EntrainmentModel selected = input.model.entrainmentModel;
    if (selected == sh::EntrainmentModel::NoEntrainment)
    {
        return keys;
    }
    sh::forEachEntrainmentModel([&](auto model)
    {
        using Model = decltype(model);
        if (sh::entrainmentModelOf(model) == selected)
        {
            const word coeffs = word(Model::name) + "Coeffs";
            for (const auto& c : Model::coefficients)
            {
                keys.append(coeffs + "/" + c.keyword);
            }
        }
    });
    return keys;
}


sh::ModelInput ensembleInput::memberModel
(
    const caseInput& input,
    const label k
) const
{
    const member& m = members[k];
    const wordList entrainment = entrainmentKeywords(input);
    wordList otherKeys;
    scalarList otherValues;
    forAll(keys, q)
    {
        if (!entrainment.found(keys[q]))
        {
            otherKeys.append(keys[q]);
            otherValues.append(m.values[q]);
        }
    }
    sh::ModelInput in = input.memberModel(otherKeys, otherValues);
    if (otherKeys.size() == keys.size())
    {
        return in;
    }
    // The entrainment model's coefficients, by its coefficient table
    const sh::EntrainmentModel selected = in.entrainmentModel;
    sh::forEachEntrainmentModel([&](auto model)
    {
        using Model = decltype(model);
        if (sh::entrainmentModelOf(model) != selected)
        {
            return;
        }
        const word coeffs = word(Model::name) + "Coeffs/";
        for (const auto& c : Model::coefficients)
        {
            const label q = keys.find(coeffs + c.keyword);
            if (q >= 0)
            {
                in.of(model).*(c.value) = m.values[q];
            }
        }
    });
    // What makeParams refuses (a negative rate, ...), as an InputError
    sh::makeParams<double>(in);
    return in;
}

} // End namespace Foam

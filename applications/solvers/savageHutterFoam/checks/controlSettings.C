/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "controlSettings.H"
#include "IFstream.H"
#include "OStringStream.H"
#include "Switch.H"

#include <cmath>
#include <limits>

namespace Foam
{

namespace
{

//- An interval of valid values and how a message states it
struct range
{
    scalar lo;
    scalar hi;
    bool loOpen;
    bool hiOpen;
    //- Integers only
    bool integer;

    bool contains(const scalar v) const
    {
        return std::isfinite(v)
            && (loOpen ? v > lo : v >= lo)
            && (hiOpen ? v < hi : v <= hi)
            && (!integer || v == std::floor(v));
    }

    std::string str() const
    {
        const bool whole = integer;
        auto bound = [whole](const scalar b) -> std::string
        {
            if (std::isinf(b))
            {
                return b > 0 ? "inf" : "-inf";
            }
            if (whole)
            {
                return std::to_string((long long)(b));
            }
            OStringStream os;
            os << b;
            return os.str();
        };
        return std::string(integer ? "an integer in " : "a finite number in ")
            + (loOpen ? "(" : "[") + bound(lo) + ", " + bound(hi)
            + (hiOpen ? ")" : "]");
    }
};

const scalar inf = std::numeric_limits<scalar>::infinity();

//- The tokens of an entry as written, for messages
std::string asWritten(const entry& e)
{
    if (e.isDict())
    {
        return "a dictionary";
    }
    OStringStream os;
    const ITstream& is = e.stream();
    forAll(is, i)
    {
        os << (i ? " " : "") << is[i];
    }
    return "'" + os.str() + "'";
}

//- The value of a number entry, or of `deflt` when it is absent (required
//  when deflt is null)
scalar number
(
    const dictionary& cd,
    const word& key,
    const range& r,
    const scalar* deflt,
    const std::string& meaning
)
{
    const entry* e = cd.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        if (deflt)
        {
            return *deflt;
        }
        FatalIOErrorInFunction(cd)
            << "Missing keyword '" << key << "' (" << meaning.c_str() << ")."
            << nl
            << "Valid values: " << r.str().c_str() << nl
            << exit(FatalIOError);
    }
    scalar v = std::numeric_limits<scalar>::quiet_NaN();
    bool isNumber = false;
    if (e->isStream())
    {
        const ITstream& is = e->stream();
        isNumber = is.size() == 1 && is[0].isNumber();
        if (isNumber)
        {
            v = is[0].number();
        }
    }
    if (!isNumber || !r.contains(v))
    {
        FatalIOErrorInFunction(cd)
            << "Invalid " << key << " " << asWritten(*e).c_str()
            << " at line " << e->startLineNumber() << " ("
            << meaning.c_str() << ")." << nl
            << "Valid values: " << r.str().c_str() << nl
            << exit(FatalIOError);
    }
    return v;
}

//- "(a b c)"
std::string choices(const wordList& valid)
{
    std::string s = "(";
    forAll(valid, i)
    {
        s += (i ? " " : "") + valid[i];
    }
    return s + ")";
}

//- A name from a fixed set, or `deflt` when absent (required when empty)
word choice
(
    const dictionary& cd,
    const word& key,
    const wordList& valid,
    const word& deflt
)
{
    const entry* e = cd.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        if (!deflt.empty())
        {
            return deflt;
        }
        FatalIOErrorInFunction(cd)
            << "Missing keyword '" << key << "'." << nl
            << "Valid choices: " << choices(valid).c_str() << nl
            << exit(FatalIOError);
    }
    const bool isWord =
        e->isStream() && e->stream().size() == 1 && e->stream()[0].isWord();
    if (!isWord || !valid.found(e->stream()[0].wordToken()))
    {
        FatalIOErrorInFunction(cd)
            << "Invalid " << key << " " << asWritten(*e).c_str()
            << " at line " << e->startLineNumber() << "." << nl
            << "Valid choices: " << choices(valid).c_str() << nl
            << exit(FatalIOError);
    }
    return e->stream()[0].wordToken();
}

//- A switch (yes/no, on/off, true/false, ...), or `deflt` when absent
bool onOff(const dictionary& cd, const word& key, const bool deflt)
{
    const entry* e = cd.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return deflt;
    }
    if (e->isStream() && e->stream().size() == 1)
    {
        const token& t = e->stream()[0];
        if (t.isWord())
        {
            const Switch sw(t.wordToken(), true);
            if (sw.valid())
            {
                return bool(sw);
            }
        }
        else if (t.isLabel() && (t.labelToken() == 0 || t.labelToken() == 1))
        {
            return t.labelToken() == 1;
        }
    }
    FatalIOErrorInFunction(cd)
        << "Invalid " << key << " " << asWritten(*e).c_str() << " at line "
        << e->startLineNumber() << "." << nl
        << "Valid choices: yes | no (on | off, true | false)" << nl
        << exit(FatalIOError);
    return deflt;
}

//- Times beyond 1e30 overflow the progress arithmetic (fractions, ETA)
const range anyTime{-1e30, 1e30, true, true, false};

const range positive{0, inf, true, true, false};

//- startFrom, startTime, stopAt, endTime
void readStartStop(const dictionary& cd, controlSettings& c)
{
    c.startFrom = choice
    (
        cd, "startFrom", {"firstTime", "startTime", "latestTime"},
        "latestTime"
    );
    const scalar zero = 0;
    c.startTime = number
    (
        cd, "startTime", anyTime, c.startFrom == "startTime" ? nullptr : &zero,
        "the time to start from with startFrom startTime"
    );

    c.stopAt = choice
    (
        cd, "stopAt", {"endTime", "writeNow", "noWriteNow", "nextWrite"},
        "endTime"
    );
    c.endTime = number(cd, "endTime", anyTime, nullptr, "the time to stop at");
}

//- deltaT, adjustTimeStep, maxCo, maxDeltaT
void readTimeStep(const dictionary& cd, controlSettings& c)
{
    c.deltaT = number
    (
        cd, "deltaT", positive, nullptr,
        "the time step, or the first one with adjustTimeStep yes"
    );
    c.adjustTimeStep = onOff(cd, "adjustTimeStep", false);
    const scalar one = 1;
    c.maxCo = number
    (
        cd, "maxCo", range{0, 1, true, false, false}, &one,
        "the Courant number of eq. (24) with adjustTimeStep yes"
    );
    const scalar great = GREAT;
    c.maxDeltaT = number
    (
        cd, "maxDeltaT", positive, &great, "the largest time step"
    );
}

//- writeControl, writeInterval, purgeWrite
void readWrites(const dictionary& cd, controlSettings& c)
{
    c.writeControl = choice
    (
        cd, "writeControl",
        {"adjustableRunTime", "runTime", "timeStep", "clockTime", "cpuTime"},
        word::null
    );
    // timeStep: a whole number of steps that OpenFOAM's label (32 bits)
    // holds: Time writes when timeIndex % label(writeInterval) is 0, and
    // beyond labelMax the conversion is undefined (here it gave a write
    // every step).  clockTime, cpuTime: at least a second, since Time
    // counts write times as label(elapsed seconds/writeInterval), which
    // overflows after labelMax intervals (68 years at 1 s, 25 days at
    // 1 ms); a shorter interval also writes a directory nearly every step
    const bool wall =
        c.writeControl == "clockTime" || c.writeControl == "cpuTime";
    c.writeInterval = number
    (
        cd, "writeInterval",
        c.writeControl == "timeStep"
      ? range{1, scalar(labelMax), false, false, true}
      : wall ? range{1, inf, false, true, false} : positive,
        nullptr,
        c.writeControl == "timeStep"
      ? std::string("time steps between writes with writeControl timeStep,"
        " a label")
      : wall
      ? "seconds of wall or CPU time between writes with writeControl "
        + c.writeControl + ": OpenFOAM's Time counts them as the 32-bit"
        " label elapsed/writeInterval, and below 1 s a directory would be"
        " written nearly every step"
      : std::string("time between writes")
    );
    const scalar zero = 0;
    c.purgeWrite = label
    (
        number
        (
            cd, "purgeWrite", range{0, labelMax, false, false, true}, &zero,
            "the number of time directories kept, 0: all"
        )
    );
}

//- writeFields, restartInterval
void readFieldSelection(const dictionary& cd, controlSettings& c)
{
    const wordList& valid = controlSettings::writableFields();
    c.writeFields.clear();
    const entry* e = cd.findEntry("writeFields", keyType::LITERAL);
    if (e)
    {
        // (name name ...): the words between a pair of brackets
        bool ok = e->isStream();
        wordList names;
        if (ok)
        {
            const ITstream& is = e->stream();
            const label n = is.size();
            ok = n >= 2 && is[0].isPunctuation()
              && is[0].pToken() == token::BEGIN_LIST
              && is[n - 1].isPunctuation()
              && is[n - 1].pToken() == token::END_LIST;
            for (label i = 1; ok && i < n - 1; ++i)
            {
                ok = is[i].isWord();
                if (ok)
                {
                    names.append(is[i].wordToken());
                }
            }
        }
        word bad;
        forAll(names, i)
        {
            if (!valid.found(names[i]) && bad.empty())
            {
                bad = names[i];
            }
            if (names.find(names[i]) != i && bad.empty())
            {
                bad = names[i] + " (twice)";
            }
        }
        if (!ok || names.empty() || !bad.empty())
        {
            FatalIOErrorInFunction(cd)
                << "Invalid writeFields " << asWritten(*e).c_str()
                << " at line " << e->startLineNumber()
                << (bad.empty() ? std::string() : ": " + bad).c_str()
                << " (the fields written at every write time, a list of"
                << " names; leave the entry out to write all of them)."
                << nl << "Valid choices: " << choices(valid).c_str() << nl
                << exit(FatalIOError);
        }
        c.writeFields = names;
    }
    const scalar zero = 0;
    c.restartInterval = number
    (
        cd, "restartInterval", range{0, inf, false, true, false}, &zero,
        "the simulated time between the write times that also hold the"
        " restart fields when writeFields is set; 0: the last write time"
        " only"
    );
}

//- The entries of the written files' format, checked only
void checkFormat(const dictionary& cd)
{
    // 17 significant digits tell every double apart: more only print
    // the binary expansion's noise (in field files and directory names)
    const scalar six = 6;
    number
    (
        cd, "writePrecision", range{1, 17, false, false, true}, &six,
        "significant digits of written numbers"
    );
    number
    (
        cd, "timePrecision", range{1, 17, false, false, true}, &six,
        "significant digits of time directory names"
    );
    choice(cd, "writeFormat", {"ascii", "binary"}, "ascii");
    choice
    (
        cd, "writeCompression",
        {"on", "off", "yes", "no", "true", "false", "compressed",
         "uncompressed"},
        "off"
    );
    choice(cd, "timeFormat", {"general", "fixed", "scientific"}, "general");
}

} // namespace


const wordList& controlSettings::writableFields()
{
    static const wordList names
    ({
        "h", "U", "hU", "H", "zb", "regime", "hMax", "UMax", "pMax",
        "tArrival", "hEntrainable", "erodedDepth", "cResistance",
        "HEntrainable", "HErodedDepth"
    });
    return names;
}


const wordList& controlSettings::restartFields()
{
    static const wordList names
    ({
        "h", "U", "hU", "H", "zb", "hMax", "UMax", "pMax", "tArrival",
        "hEntrainable", "erodedDepth", "cResistance", "HEntrainable",
        "HErodedDepth"
    });
    return names;
}


controlSettings controlSettings::read
(
    const dictionary& cd,
    const bool running
)
{
    controlSettings c;

    readStartStop(cd, c);
    readTimeStep(cd, c);
    readWrites(cd, c);
    readFieldSelection(cd, c);
    checkFormat(cd);
    c.runTimeModifiable = onOff(cd, "runTimeModifiable", false);

    if (c.stopAt != "endTime" && !running)
    {
        const entry* e = cd.findEntry("stopAt", keyType::LITERAL);
        FatalIOErrorInFunction(cd)
            << "stopAt " << c.stopAt << " at line " << e->startLineNumber()
            << ": a run starts with stopAt endTime (" << c.stopAt
            << " is a request to a running solver, made by editing the"
            << " controlDict with runTimeModifiable yes)." << nl
            << "Valid choices at the start of a run: (endTime)" << nl
            << exit(FatalIOError);
    }

    return c;
}


controlSettings controlSettings::readFile
(
    const fileName& path,
    const bool running
)
{
    IFstream is(path);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot read " << path << nl << exit(FatalError);
    }
    const dictionary cd(is);
    return read(cd, running);
}

} // End namespace Foam

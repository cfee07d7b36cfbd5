#include "modelInput.H"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace sh
{

namespace
{

constexpr double degToRad = degreesToRadians;

std::string joined(const std::vector<std::string>& names)
{
    std::string s;
    for (const std::string& n : names)
    {
        s += (s.empty() ? "" : " ") + n;
    }
    return s;
}

template<class Enum>
Enum parseName
(
    const std::vector<std::string>& names,
    const std::string& name,
    const std::string& keyword,
    const char* what
)
{
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        if (names[k] == name)
        {
            return Enum(k);
        }
    }
    throw InputError
    (
        keyword,
        "unknown " + std::string(what) + " '" + name
      + "'; valid choices: " + joined(names)
    );
}

std::string str(double x)
{
    return numberString(x);
}

void requireFinite(const std::string& keyword, double x)
{
    // Beyond 1e30 the scheme's squares and products of such inputs
    // overflow (a floating-point exception where OpenFOAM traps them)
    if (!(std::fabs(x) <= 1e30))
    {
        throw InputError
        (
            keyword,
            "must be a finite number of magnitude at most 1e30, got " + str(x)
        );
    }
}

void requireAngle(const std::string& keyword, double deg, const char* what)
{
    if (!(deg >= 0 && deg < 90))
    {
        throw InputError
        (
            keyword,
            std::string(what) + " must lie in [0, 90) degrees, got " + str(deg)
        );
    }
}

void requirePositive(const std::string& keyword, double x, const char* what)
{
    if (!(x > 0))
    {
        throw InputError
        (
            keyword, std::string(what) + " must be positive, got " + str(x)
        );
    }
}

void requireNonNegative(const std::string& keyword, double x, const char* what)
{
    if (!(x >= 0))
    {
        throw InputError
        (
            keyword, std::string(what) + " must not be negative, got " + str(x)
        );
    }
}

//- A coefficient within its bound
void requireBound(const char* keyword, double x, Bound bound, const char* what)
{
    switch (bound)
    {
        case Bound::angle: requireAngle(keyword, x, what); break;
        case Bound::positive: requirePositive(keyword, x, what); break;
        case Bound::nonNegative: requireNonNegative(keyword, x, what); break;
        case Bound::finite: break;
    }
}

const char* boundText(Bound bound)
{
    switch (bound)
    {
        case Bound::angle: return "[0, 90)";
        case Bound::positive: return "> 0";
        case Bound::nonNegative: return ">= 0";
        case Bound::finite: return "finite";
    }
    return "";
}

//- Calls f(Law()) for the selected law
template<class F>
void withFrictionLaw(FrictionLaw law, F&& f)
{
    forEachFrictionLaw
    (
        [&](auto l)
        {
            if (frictionLawOf(l) == law)
            {
                f(l);
            }
        }
    );
}

//- The coefficients of the selected law (only those: another law's
//  defaults are not the user's input): each within its bound, then the
//  law's rules between them
void checkFrictionLaw(const ModelInput& in)
{
    withFrictionLaw
    (
        in.frictionLaw,
        [&](auto law)
        {
            using Law = decltype(law);
            const typename Law::Input& li = in.of(law);
            for (const auto& c : Law::coefficients)
            {
                requireBound(c.keyword, li.*c.value, c.bound, c.what);
            }
            Law::validate(li);
        }
    );
}

//- Calls f(Model()) for the selected entrainment model
template<class F>
void withEntrainmentModel(EntrainmentModel selected, F&& f)
{
    forEachEntrainmentModel
    (
        [&](auto model)
        {
            if (entrainmentModelOf(model) == selected)
            {
                f(model);
            }
        }
    );
}

//- The coefficients of the selected entrainment model: each within its
//  bound, then the model's rules
void checkEntrainmentModel(const ModelInput& in)
{
    withEntrainmentModel
    (
        in.entrainmentModel,
        [&](auto model)
        {
            using M = decltype(model);
            const typename M::Input& mi = in.of(model);
            for (const auto& c : M::coefficients)
            {
                requireBound(c.keyword, mi.*c.value, c.bound, c.what);
            }
            M::validate(mi);
        }
    );
}

//- The basal friction angle of the selected law for earthPressure
//  activePassive: its keyword and value [deg], or why there is none
struct BasalFrictionAngle
{
    const char* keyword = nullptr;
    double deg = 0;
    const char* whyNot = nullptr;
};

BasalFrictionAngle basalFrictionAngle(const ModelInput& in)
{
    BasalFrictionAngle a;
    withFrictionLaw
    (
        in.frictionLaw,
        [&](auto law)
        {
            using Law = decltype(law);
            const FrictionAngle& angle = Law::frictionAngle;
            if (angle.kind == FrictionAngle::none)
            {
                a.whyNot = angle.whyNot;
                return;
            }
            for (const auto& c : Law::coefficients)
            {
                if (std::string(c.keyword) == angle.keyword)
                {
                    const double x = in.of(law).*c.value;
                    a.keyword = angle.keyword;
                    a.deg = angle.kind == FrictionAngle::degrees
                        ? x
                        : std::atan(x)/degToRad;
                }
            }
        }
    );
    return a;
}

//- A number as the listing writes it: the shortest form that reads back
//  as the same double
std::string exactString(double x)
{
    for (int digits = 6; digits < 17; ++digits)
    {
        std::ostringstream os;
        os << std::setprecision(digits) << x;
        if (std::stod(os.str()) == x)
        {
            return os.str();
        }
    }
    std::ostringstream os;
    os << std::setprecision(17) << x;
    return os.str();
}

} // namespace


const std::vector<std::string>& limiterNames()
{
    static const std::vector<std::string> n{"minmod", "vanLeer", "MC"};
    return n;
}

const std::vector<std::string>& earthPressureNames()
{
    static const std::vector<std::string> n{"activePassive", "isotropic"};
    return n;
}

const std::vector<std::string>& frictionLawNames()
{
    static const std::vector<std::string> n = []()
    {
        std::vector<std::string> names;
        forEachFrictionLaw
        (
            [&](auto law) { names.push_back(decltype(law)::name); }
        );
        return names;
    }();
    return n;
}

const std::vector<std::string>& entrainmentModelNames()
{
    static const std::vector<std::string> n = []()
    {
        std::vector<std::string> names;
        forEachEntrainmentModel
        (
            [&](auto model) { names.push_back(decltype(model)::name); }
        );
        return names;
    }();
    return n;
}

EntrainmentModel parseEntrainmentModel
(
    const std::string& name,
    const std::string& keyword
)
{
    return parseName<EntrainmentModel>
    (
        entrainmentModelNames(), name, keyword, "entrainment model"
    );
}

std::string toString(EntrainmentModel x)
{
    return entrainmentModelNames().at(int(x));
}

const std::vector<std::string>& coordinatesNames()
{
    static const std::vector<std::string> n{"slope", "plan"};
    return n;
}

Coordinates parseCoordinates(const std::string& name, const std::string& keyword)
{
    return parseName<Coordinates>(coordinatesNames(), name, keyword, "coordinates");
}

Limiter parseLimiter(const std::string& name, const std::string& keyword)
{
    return parseName<Limiter>(limiterNames(), name, keyword, "limiter");
}

EarthPressureModel parseEarthPressure
(
    const std::string& name,
    const std::string& keyword
)
{
    return parseName<EarthPressureModel>
    (
        earthPressureNames(), name, keyword, "earth pressure model"
    );
}

FrictionLaw parseFrictionLaw(const std::string& name, const std::string& keyword)
{
    return parseName<FrictionLaw>
    (
        frictionLawNames(), name, keyword, "friction model"
    );
}

std::string toString(Limiter x) { return limiterNames().at(int(x)); }
std::string toString(EarthPressureModel x) { return earthPressureNames().at(int(x)); }
std::string toString(FrictionLaw x) { return frictionLawNames().at(int(x)); }
std::string toString(Coordinates x) { return coordinatesNames().at(int(x)); }


namespace
{

//- Every number of the input finite and at most 1e30 in magnitude (the
//  coefficients of every law: another law's are not checked further)
void requireFiniteInput(const ModelInput& in)
{
    requireFinite("g", in.g);
    requireFinite("epsilon", in.epsilon);
    requireFinite("lambda", in.lambda);
    requireFinite("phi", in.phiDeg);
    forEachFrictionLaw
    (
        [&](auto law)
        {
            for (const auto& c : decltype(law)::coefficients)
            {
                requireFinite(c.keyword, in.of(law).*c.value);
            }
        }
    );
    forEachEntrainmentModel
    (
        [&](auto model)
        {
            for (const auto& c : decltype(model)::coefficients)
            {
                requireFinite(c.keyword, in.of(model).*c.value);
            }
        }
    );
    requireFinite("hDry", in.hDry);
    requireFinite("maxCo", in.cfl);
    requireFinite("arrivalThreshold", in.arrivalThreshold);
    requireFinite("rho", in.rho);
}

//- g, epsilon and phi in range, and the coefficients of the selected
//  friction law
void checkModel(const ModelInput& in)
{
    if (in.g <= 0)
    {
        throw InputError("g", "gravity must be positive, got " + str(in.g));
    }
    if (in.epsilon <= 0)
    {
        throw InputError
        (
            "epsilon", "aspect ratio must be positive, got " + str(in.epsilon)
        );
    }
    if (!(in.phiDeg > 0 && in.phiDeg < 90))
    {
        throw InputError
        (
            "phi",
            "internal friction angle must lie in (0, 90) degrees, got "
          + str(in.phiDeg)
        );
    }
    checkFrictionLaw(in);
    checkEntrainmentModel(in);
}

//- The basal friction angle [deg] of the active/passive coefficients: the
//  selected law's, which earthPressure activePassive needs (eqs 7-8) and
//  which must not exceed phi there
double checkedBasalFrictionAngle(const ModelInput& in)
{
    const BasalFrictionAngle angle = basalFrictionAngle(in);
    if (in.earthPressure == EarthPressureModel::activePassive)
    {
        if (!angle.keyword)
        {
            throw InputError
            (
                "earthPressure",
                "activePassive needs one basal friction angle (eqs 7-8),"
                " which frictionModel " + toString(in.frictionLaw)
              + " does not have (" + angle.whyNot + "). Use earthPressure"
                " isotropic (K = 1)"
            );
        }
        if (angle.deg > in.phiDeg)
        {
            throw InputError
            (
                angle.keyword,
                "basal friction angle delta = " + str(angle.deg)
              + " deg exceeds the internal friction angle phi = "
              + str(in.phiDeg) + " deg: the active/passive earth pressure"
                " coefficients (eqs 7-8) are then complex. Use delta <= phi,"
                " or earthPressure isotropic"
            );
        }
    }
    return angle.deg;
}

//- hDry, maxCo, arrivalThreshold and rho in range
void checkNumericsAndMaps(const ModelInput& in)
{
    if (in.hDry <= 0)
    {
        throw InputError
        (
            "hDry", "partial-wet threshold must be positive, got " + str(in.hDry)
        );
    }
    if (!(in.cfl > 0 && in.cfl <= 1))
    {
        throw InputError
        (
            "maxCo", "Courant number must lie in (0, 1], got " + str(in.cfl)
        );
    }

    if (!(in.arrivalThreshold > 0))
    {
        throw InputError
        (
            "arrivalThreshold",
            "the thickness above which material has arrived (tArrival) must"
            " lie in (0, 1e30] m, got " + str(in.arrivalThreshold)
        );
    }
    if (!(in.rho >= 0))
    {
        throw InputError
        (
            "rho",
            "the density must lie in (0, 1e30] kg/m^3 (0: no pressure map),"
            " got " + str(in.rho)
        );
    }
}

//- The earth pressure coefficients of the input (phi, delta [rad]) in Real
template<class Real>
void setEarthPressure
(
    const ModelInput& in, double phi, double delta,
    EarthPressureCoeffs<Real>& pK
)
{
    const EarthPressureCoeffs<double> K =
        in.earthPressure == EarthPressureModel::activePassive
      ? activePassiveCoeffs<double>(phi, delta)
      : isotropicCoeffs<double>();
    for (int a = 0; a < 2; ++a)
    {
        pK.kx[a] = Real(K.kx[a]);
        for (int b = 0; b < 2; ++b)
        {
            pK.ky[a][b] = Real(K.ky[a][b]);
        }
    }
    pK.kxMax = Real(K.kxMax);
    pK.kyMax = Real(K.kyMax);
    pK.dKx = Real(K.dKx);
    pK.dKy = Real(K.dKy);
}

} // namespace


//- The checks, in the order of their errors, then the conversion
template<class Real>
Params<Real> makeParams(const ModelInput& in)
{
    requireFiniteInput(in);
    checkModel(in);
    const double deltaDeg = checkedBasalFrictionAngle(in);
    checkNumericsAndMaps(in);

    const double phi = in.phiDeg*degToRad;
    const double delta = deltaDeg*degToRad;

    Params<Real> p;
    p.g = Real(in.g);
    p.epsilon = Real(in.epsilon);
    p.lambda = Real(in.lambda);
    p.tanPhi = Real(std::tan(phi));

    setEarthPressure(in, phi, delta, p.K);

    p.friction = FrictionParams<Real>();
    p.friction.law = in.frictionLaw;
    const FrictionContext context{in.g, in.epsilon};
    forEachFrictionLaw
    (
        [&](auto law)
        {
            p.friction.of(law) =
                decltype(law)::template params<Real>(in.of(law), context);
        }
    );
    p.jet = JetParams<Real>();
    p.limiter = in.limiter;
    p.stoppingCriterion = in.stoppingCriterion;
    p.staticResistance = in.staticResistance;
    p.holdResting = in.holdResting;
    p.hDry = Real(in.hDry);
    p.cfl = Real(in.cfl);
    p.arrivalThreshold = Real(in.arrivalThreshold);
    p.rho = Real(in.rho);
    p.planTerrain = in.coordinates == Coordinates::plan;
    p.entrainment = EntrainmentParams<Real>();
    p.entrainment.model = in.entrainmentModel;
    const EntrainmentContext ec{in.g, in.epsilon};
    forEachEntrainmentModel
    (
        [&](auto model)
        {
            p.entrainment.of(model) =
                decltype(model)::template params<Real>(in.of(model), ec);
        }
    );
    return p;
}

std::string frictionCoeffsExample(FrictionLaw selected)
{
    std::string s = "{";
    withFrictionLaw
    (
        selected,
        [&](auto law)
        {
            using Law = decltype(law);
            const typename Law::Input defaults{};
            for (const auto& c : Law::coefficients)
            {
                if (c.required)
                {
                    s += std::string(" ") + c.keyword + " "
                       + exactString(defaults.*c.value) + ";";
                }
            }
        }
    );
    return s + " }";
}


//- One line of a model's listing: keyword, its value in Input (the
//  default of an optional coefficient, an example of a required one),
//  required or optional, unit, bound, what it is
template<class Input>
void coefficientRow
(
    std::ostream& os,
    const Coefficient<Input>& c,
    const Input& defaults
)
{
    os  << "    coefficient " << std::left
        << std::setw(8) << c.keyword << " "
        << std::setw(8) << exactString(defaults.*c.value) << " "
        << std::setw(8) << (c.required ? "required" : "optional")
        << " " << std::setw(5) << (*c.unit ? c.unit : "-")
        << " " << std::setw(7) << boundText(c.bound)
        << " " << c.what << "\n";
}


std::string describeFrictionLaws()
{
    std::ostringstream os;
    os  << "Friction laws: frictionModel <name> and <name>Coeffs { ... } in\n"
        << "constant/transportProperties; the law's header is\n"
        << "src/savageHutter/physics/frictionLaws/<name>.H (adding a law:\n"
        << "docs/frictionLaws.md).  Per law: its coefficients (keyword, the\n"
        << "default of an optional one or an example of a required one,"
        << " required or\noptional, unit, bound (every number at most 1e30"
        << " in magnitude), what it\nis), the coefficient that earthPressure"
        << " activePassive takes the basal\nfriction angle from, and its"
        << " edge cases: a coefficient's value\naccepted or rejected, with"
        << " earthPressure isotropic or with\nactivePassive and phi 30.\n";
    forEachFrictionLaw
    (
        [&](auto law)
        {
            using Law = decltype(law);
            const typename Law::Input defaults{};
            os  << "\nfrictionModel " << Law::name << "\n"
                << "    " << Law::description << "\n";
            for (const auto& c : Law::coefficients)
            {
                coefficientRow(os, c, defaults);
            }
            if (Law::frictionAngle.kind != FrictionAngle::none)
            {
                os  << "    activePassive " << Law::frictionAngle.keyword
                    << (
                           Law::frictionAngle.kind == FrictionAngle::degrees
                         ? " (the angle itself)\n"
                         : " (delta = atan of it)\n"
                       );
            }
            else
            {
                os  << "    activePassive none: " << Law::frictionAngle.whyNot
                    << "\n";
            }
            for (const EdgeCase& e : Law::edgeCases)
            {
                os  << "    edge " << std::left << std::setw(12) << e.name
                    << " " << std::setw(8) << e.keyword << " "
                    << std::setw(8) << exactString(e.value) << " "
                    << (e.accepted ? "accepted" : "rejected") << " "
                    << (e.activePassive ? "activePassive" : "isotropic")
                    << "\n";
            }
        }
    );
    return os.str();
}


std::string entrainmentCoeffsExample(EntrainmentModel selected)
{
    std::string s = "{";
    withEntrainmentModel
    (
        selected,
        [&](auto model)
        {
            using M = decltype(model);
            const typename M::Input defaults{};
            for (const auto& c : M::coefficients)
            {
                if (c.required)
                {
                    s += std::string(" ") + c.keyword + " "
                       + exactString(defaults.*c.value) + ";";
                }
            }
        }
    );
    return s + " }";
}


std::string describeEntrainmentModels()
{
    std::ostringstream os;
    os  << "Entrainment models: entrainmentModel <name> and <name>Coeffs"
        << " { ... } in\nconstant/transportProperties (none: off); the"
        << " erodible layer is the\nfield 0/hEntrainable [m], the"
        << " resistance 0/cResistance [1/m]; the\nmodel's header is"
        << " src/savageHutter/physics/entrainmentModels/<name>.H.\n"
        << "Per model: its coefficients (keyword, the default of an"
        << " optional one or\nan example of a required one, required or"
        << " optional, unit, bound\n(every number at most 1e30 in"
        << " magnitude), what it is) and its edge cases.\n";
    forEachEntrainmentModel
    (
        [&](auto model)
        {
            using M = decltype(model);
            const typename M::Input defaults{};
            os  << "\nentrainmentModel " << M::name << "\n"
                << "    " << M::description << "\n";
            for (const auto& c : M::coefficients)
            {
                coefficientRow(os, c, defaults);
            }
            for (const EntrainmentEdgeCase& e : M::edgeCases)
            {
                os  << "    edge " << std::left << std::setw(12) << e.name
                    << " " << std::setw(8) << e.keyword << " "
                    << std::setw(8) << exactString(e.value) << " "
                    << (e.accepted ? "accepted" : "rejected") << "\n";
            }
        }
    );
    return os.str();
}


template Params<double> makeParams<double>(const ModelInput&);
template Params<float> makeParams<float>(const ModelInput&);

} // namespace sh

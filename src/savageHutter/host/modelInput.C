#include "modelInput.H"

#include <cmath>
#include <sstream>

namespace sh
{

namespace
{

constexpr double degToRad = 3.14159265358979323846/180.0;

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
    std::ostringstream os;
    os << x;
    return os.str();
}

void requireFinite(const std::string& keyword, double x)
{
    if (!std::isfinite(x))
    {
        throw InputError(keyword, "must be a finite number, got " + str(x));
    }
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
    static const std::vector<std::string> n{"Coulomb"};
    return n;
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


template<class Real>
Params<Real> makeParams(const ModelInput& in)
{
    requireFinite("g", in.g);
    requireFinite("epsilon", in.epsilon);
    requireFinite("lambda", in.lambda);
    requireFinite("phi", in.phiDeg);
    requireFinite("delta", in.deltaDeg);
    requireFinite("hDry", in.hDry);
    requireFinite("maxCo", in.cfl);

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
    if (!(in.deltaDeg >= 0 && in.deltaDeg < 90))
    {
        throw InputError
        (
            "delta",
            "basal friction angle must lie in [0, 90) degrees, got "
          + str(in.deltaDeg)
        );
    }
    if
    (
        in.earthPressure == EarthPressureModel::activePassive
     && in.deltaDeg > in.phiDeg
    )
    {
        throw InputError
        (
            "delta",
            "basal friction angle delta = " + str(in.deltaDeg)
          + " deg exceeds the internal friction angle phi = "
          + str(in.phiDeg) + " deg: the active/passive earth pressure"
            " coefficients (eqs 7-8) are then complex. Use delta <= phi,"
            " or earthPressure isotropic"
        );
    }
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

    const double phi = in.phiDeg*degToRad;
    const double delta = in.deltaDeg*degToRad;

    Params<Real> p;
    p.g = Real(in.g);
    p.epsilon = Real(in.epsilon);
    p.lambda = Real(in.lambda);
    p.tanPhi = Real(std::tan(phi));

    const EarthPressureCoeffs<double> K =
        in.earthPressure == EarthPressureModel::activePassive
      ? activePassiveCoeffs<double>(phi, delta)
      : isotropicCoeffs<double>();
    for (int a = 0; a < 2; ++a)
    {
        p.K.kx[a] = Real(K.kx[a]);
        for (int b = 0; b < 2; ++b)
        {
            p.K.ky[a][b] = Real(K.ky[a][b]);
        }
    }
    p.K.kxMax = Real(K.kxMax);
    p.K.kyMax = Real(K.kyMax);

    p.friction.law = in.frictionLaw;
    p.friction.tanDelta = Real(std::tan(delta));
    p.limiter = in.limiter;
    p.stoppingCriterion = in.stoppingCriterion;
    p.staticResistance = in.staticResistance;
    p.holdResting = in.holdResting;
    p.hDry = Real(in.hDry);
    p.cfl = Real(in.cfl);
    return p;
}

template Params<double> makeParams<double>(const ModelInput&);
template Params<float> makeParams<float>(const ModelInput&);

} // namespace sh

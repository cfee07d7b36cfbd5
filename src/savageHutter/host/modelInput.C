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

//- The coefficients of the selected law (only those: another law's
//  defaults are not the user's input)
void checkFrictionLaw(const ModelInput& in)
{
    switch (in.frictionLaw)
    {
        case FrictionLaw::Coulomb:
            requireAngle("delta", in.deltaDeg, "basal friction angle");
            break;

        case FrictionLaw::PouliquenForterre:
        {
            const ModelInput::PouliquenForterreInput& pf =
                in.pouliquenForterre;
            requireAngle("zeta1", pf.zeta1Deg, "friction angle zeta1");
            requireAngle("zeta2", pf.zeta2Deg, "friction angle zeta2");
            requireAngle("zeta3", pf.zeta3Deg, "friction angle zeta3");
            if (!(pf.zeta1Deg < pf.zeta2Deg))
            {
                throw InputError
                (
                    "zeta1",
                    "zeta1 = " + str(pf.zeta1Deg) + " deg must be below"
                    " zeta2 = " + str(pf.zeta2Deg) + " deg: mu_stop (eq. 40)"
                    " falls from tan(zeta2) at h = 0 to tan(zeta1) in deep"
                    " flows"
                );
            }
            if (pf.zeta3Deg < pf.zeta1Deg)
            {
                throw InputError
                (
                    "zeta3",
                    "zeta3 = " + str(pf.zeta3Deg) + " deg must not be below"
                    " zeta1 = " + str(pf.zeta1Deg) + " deg: the static"
                    " coefficient mu_start (eq. 41) would fall below the"
                    " dynamic mu_stop (eq. 40) in deep layers"
                );
            }
            requirePositive("L", pf.L, "length scale L");
            requirePositive("beta", pf.beta, "Froude number coefficient beta");
            requirePositive("gamma", pf.gamma, "exponent gamma");
            break;
        }

        case FrictionLaw::Voellmy:
            if (!(in.voellmy.mu >= 0))
            {
                throw InputError
                (
                    "mu",
                    "friction coefficient mu must not be negative, got "
                  + str(in.voellmy.mu)
                );
            }
            requirePositive("xi", in.voellmy.xi, "turbulence coefficient xi");
            break;
    }
}

} // namespace


std::string numberString(double x)
{
    std::ostringstream os;
    os << x;
    return os.str();
}


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
    static const std::vector<std::string> n
    {
        "Coulomb", "PouliquenForterre", "Voellmy"
    };
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
    const ModelInput::PouliquenForterreInput& pf = in.pouliquenForterre;
    requireFinite("zeta1", pf.zeta1Deg);
    requireFinite("zeta2", pf.zeta2Deg);
    requireFinite("zeta3", pf.zeta3Deg);
    requireFinite("L", pf.L);
    requireFinite("beta", pf.beta);
    requireFinite("gamma", pf.gamma);
    requireFinite("mu", in.voellmy.mu);
    requireFinite("xi", in.voellmy.xi);
    requireFinite("hDry", in.hDry);
    requireFinite("maxCo", in.cfl);
    requireFinite("arrivalThreshold", in.arrivalThreshold);
    requireFinite("rho", in.rho);

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

    // The basal friction angle of the active/passive coefficients
    double deltaDeg = in.deltaDeg;
    std::string deltaKeyword = "delta";
    if (in.frictionLaw == FrictionLaw::Voellmy)
    {
        deltaDeg = std::atan(in.voellmy.mu)/degToRad;
        deltaKeyword = "mu";
    }
    if (in.earthPressure == EarthPressureModel::activePassive)
    {
        if (in.frictionLaw == FrictionLaw::PouliquenForterre)
        {
            throw InputError
            (
                "earthPressure",
                "activePassive needs one basal friction angle (eqs 7-8),"
                " which frictionModel PouliquenForterre does not have (its"
                " mu varies with h and Fr). Use earthPressure isotropic"
                " (K = 1, as Johnson & Gray 2011 and Zhai et al. 2014 do)"
            );
        }
        if (deltaDeg > in.phiDeg)
        {
            throw InputError
            (
                deltaKeyword,
                "basal friction angle delta = " + str(deltaDeg)
              + " deg exceeds the internal friction angle phi = "
              + str(in.phiDeg) + " deg: the active/passive earth pressure"
                " coefficients (eqs 7-8) are then complex. Use delta <= phi,"
                " or earthPressure isotropic"
            );
        }
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

    const double phi = in.phiDeg*degToRad;
    const double delta = deltaDeg*degToRad;

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
    p.K.dKx = Real(K.dKx);
    p.K.dKy = Real(K.dKy);

    p.friction = FrictionParams<Real>();
    p.friction.law = in.frictionLaw;
    p.friction.coulomb.tanDelta = Real(std::tan(in.deltaDeg*degToRad));
    {
        PouliquenForterreParams<Real>& f = p.friction.pouliquenForterre;
        const double t1 = std::tan(pf.zeta1Deg*degToRad);
        f.tanZeta1 = Real(t1);
        f.tanZeta3 = Real(std::tan(pf.zeta3Deg*degToRad));
        f.dTan = Real(std::tan(pf.zeta2Deg*degToRad) - t1);
        f.L = Real(pf.L);
        f.beta = Real(pf.beta);
        f.gamma = Real(pf.gamma);
        f.epsG = Real(in.epsilon*in.g);
    }
    p.friction.voellmy.mu = Real(in.voellmy.mu);
    p.friction.voellmy.gOverXi = Real(in.g/in.voellmy.xi);
    p.jet = JetParams<Real>();
    p.limiter = in.limiter;
    p.stoppingCriterion = in.stoppingCriterion;
    p.staticResistance = in.staticResistance;
    p.holdResting = in.holdResting;
    p.hDry = Real(in.hDry);
    p.cfl = Real(in.cfl);
    p.arrivalThreshold = Real(in.arrivalThreshold);
    p.rho = Real(in.rho);
    return p;
}

template Params<double> makeParams<double>(const ModelInput&);
template Params<float> makeParams<float>(const ModelInput&);

} // namespace sh

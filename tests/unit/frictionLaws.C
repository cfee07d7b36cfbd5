/*---------------------------------------------------------------------------*\
  The friction laws (physics/frictionLaws): the portable exp/log/pow they
  use; every law of the list (frictionLawList.H), from its header alone:
  its name selects it, its worked examples (double and float), the
  dispatch of FrictionParams against the law's own functions, material at
  rest as strong as staticMu, finite and non-negative mu and drag, each
  coefficient outside its bound rejected naming its keyword, its edge
  cases, earthPressure activePassive with its friction angle or refused
  without one, and in the scheme a uniform layer at rest that holds below
  its static friction and starts to flow above it; a law without examples
  fails; then each law against further hand-computed values, the
  rejection of bad coefficients, and uniform layers on an incline against
  their exact steady states:

    Pouliquen-Forterre (Zhai et al. 2014 eqs 39-43): a layer of depth
      h > h_stop(zeta) relaxes to the speed |v| = Fr sqrt(eps g h cos zeta)
      with Fr = beta h/h_stop, h_stop = -L ln((tan zeta - tan zeta1)/
      (tan zeta2 - tan zeta1)); a layer below h_stop at rest stays at rest,
      and one set moving stops; between h_stop and h_start (where
      mu_start(h_start) = tan zeta) a layer at rest holds while a moving
      one keeps flowing: the hysteresis.
    Voellmy: g sin zeta = mu g cos zeta + g |v|^2/(xi h), so
      |v| = sqrt(xi h (sin zeta - mu cos zeta)).

  A uniform layer with transmissive sides stays uniform (every face flux is
  the same), so these are the law's own ODE, integrated by the scheme.
  Hand-computed values: Python, double precision, from the printed
  equations (15 significant digits).
\*---------------------------------------------------------------------------*/

#include "testing.H"
#include "physics/portableMath.H"

#include <functional>
#include <limits>

using namespace sh;
using namespace shtest;

namespace
{

constexpr double ulp = 2.220446049250313e-16;

bool relClose(double a, double b, double tol)
{
    return std::fabs(a - b) <= tol*std::fabs(b);
}

void portableMath(Counter& t)
{
    std::printf("\nPortable exp, log, pow against the C library (max error in ulp)\n");
    double eExp = 0, eLog = 0, ePow = 0;
    for (int k = -4000; k <= 4000; ++k)
    {
        const double x = k*0.0173;            // [-69.2, 69.2]
        eExp = std::max(eExp, std::fabs(shExp(x) - std::exp(x))/std::exp(x));
        const double y = std::exp(k*0.011) + 1e-3*k*k;
        eLog = std::max
        (
            eLog,
            std::fabs(shLog(y) - std::log(y))
           /std::max(std::fabs(std::log(y)), 1e-300)
        );
        const double b = 1e-6 + std::fabs(k)*1e-3;
        for (const double p : {1e-3, 0.5, 2.7})
        {
            ePow = std::max
            (
                ePow, std::fabs(shPow(b, p) - std::pow(b, p))/std::pow(b, p)
            );
        }
    }
    std::printf("  exp %.2f  log %.2f  pow %.2f\n", eExp/ulp, eLog/ulp, ePow/ulp);
    t.check(eExp < 4*ulp, "exp within 4 ulp on [-69, 69]");
    t.check(eLog < 4*ulp, "log within 4 ulp on [1e-19, 1e19]");
    t.check(ePow < 8*ulp, "pow within 8 ulp");
    t.check
    (
        shExp(-800.0) == 0 && shPow(0.0, 1e-3) == 0 && shPow(0.0, 0.0) == 1
     && shLog(1.0) == 0 && std::isnan(shLog(-1.0)),
        "limits: exp(-800) = 0, 0^0.001 = 0, 0^0 = 1, log 1 = 0, log(-1) NaN"
    );
    float ef = 0;
    for (int k = -800; k <= 800; ++k)
    {
        const float x = float(k)*0.0173f;
        ef = std::max(ef, std::fabs(shExp(x) - std::exp(x))/std::exp(x));
    }
    std::printf("  float exp: %.2f float ulp\n", ef/1.1920929e-7f);
    t.check(ef < 4*1.1920929e-7f, "float exp within 4 float ulp");
}


ModelInput pfInput()
{
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::isotropic;
    in.phiDeg = 35;
    in.frictionLaw = FrictionLaw::PouliquenForterre;
    return in;                  // coefficients: the paper's (modelInput.H)
}

void handValues(Counter& t)
{
    std::printf("\nFurther hand-computed values (zeta = 26.7 deg, g = 9.81)\n");
    const double cz = std::cos(26.7*deg);
    const Params<double> p = makeParams<double>(pfInput());
    const FrictionParams<double>& f = p.friction;

    t.check
    (
        relClose(staticFrictionCoefficient(f, 0.01), 0.486802133743683, 1e-13)
     && relClose(PouliquenForterre::muStop(f.pouliquenForterre, 0.01), 0.423507610246661, 1e-13),
        "mu_start(0.01) = 0.48680213374368, mu_stop(0.01) = 0.42350761024666"
    );

    // A subnormal layer at rest: eps g h cos(zeta) underflows to 0 (g = 0.1)
    ModelInput weak = pfInput();
    weak.g = 0.1;
    const double muTiny =
        frictionCoefficient(makeParams<double>(weak).friction, {4.9e-324, 0.0, cz});
    const Params<float> pfl = makeParams<float>(weak);
    const float muTinyF = frictionCoefficient(pfl.friction, {1.4e-45f, 0.0f, float(cz)});
    t.check
    (
        std::isfinite(muTiny) && std::isfinite(muTinyF)
     && relClose(muTiny, 0.617984955319308, 1e-13),
        "subnormal h at rest: mu_start(0), no 0/0 (double 4.9e-324, float 1.4e-45)"
    );

    // Continuity at Fr = beta: both branches give mu_stop(h)
    const double h = 0.007;
    const double c = std::sqrt(9.81*h*cz);
    const double below = frictionCoefficient(f, {h, 0.136*c*(1 - 1e-12), cz});
    const double above = frictionCoefficient(f, {h, 0.136*c, cz});
    std::printf("  at Fr = beta: %.15f (below) %.15f (at)\n", below, above);
    t.check(relClose(below, above, 1e-12), "mu continuous at Fr = beta");

    ModelInput co;
    co.coulomb.deltaDeg = 24.5;
    const Params<double> pc = makeParams<double>(co);
    t.check
    (
        relClose(frictionCoefficient(pc.friction, {0.3, 2.0, cz}), 0.455726255532585, 1e-14)
     && frictionDrag(pc.friction, 2.0) == 0,
        "Coulomb: mu = tan(24.5 deg) = 0.455726255532585, no drag"
    );

    ModelInput vo;
    vo.frictionLaw = FrictionLaw::Voellmy;
    vo.voellmy.mu = 0.2;
    vo.voellmy.xi = 500;
    const Params<double> pv = makeParams<double>(vo);
    t.check
    (
        frictionCoefficient(pv.friction, {0.3, 2.0, cz}) == 0.2
     && staticFrictionCoefficient(pv.friction, 0.3) == 0.2
     && relClose(frictionDrag(pv.friction, 2.0), 9.81*4/500, 1e-15),
        "Voellmy: mu = 0.2, drag g|v|^2/xi = 0.07848 at 2 m/s"
    );
}


void rejects
(
    Counter& t,
    const char* what,
    const std::function<void(ModelInput&)>& edit,
    const std::string& keyword
)
{
    ModelInput in = pfInput();
    edit(in);
    try
    {
        makeParams<double>(in);
        t.check(false, std::string(what) + " rejected");
    }
    catch (const InputError& e)
    {
        std::printf("    %s\n", e.what());
        t.check(e.keyword() == keyword, std::string(what) + " rejected, naming " + keyword);
    }
}

void badCoefficients(Counter& t)
{
    std::printf("\nBad coefficients are rejected\n");
    typedef ModelInput M;
    rejects(t, "L < 0", [](M& in) { in.pouliquenForterre.L = -6e-3; }, "L");
    rejects(t, "L = 0", [](M& in) { in.pouliquenForterre.L = 0; }, "L");
    rejects(t, "zeta1 > zeta2", [](M& in) { in.pouliquenForterre.zeta1Deg = 32; }, "zeta1");
    rejects(t, "zeta1 = zeta2", [](M& in) { in.pouliquenForterre.zeta1Deg = 30.7; }, "zeta1");
    rejects(t, "zeta3 < zeta1", [](M& in) { in.pouliquenForterre.zeta3Deg = 20; }, "zeta3");
    rejects(t, "zeta2 = 90", [](M& in) { in.pouliquenForterre.zeta2Deg = 90; }, "zeta2");
    rejects(t, "zeta1 < 0", [](M& in) { in.pouliquenForterre.zeta1Deg = -1; }, "zeta1");
    rejects(t, "beta = 0", [](M& in) { in.pouliquenForterre.beta = 0; }, "beta");
    rejects(t, "gamma < 0", [](M& in) { in.pouliquenForterre.gamma = -1e-3; }, "gamma");
    rejects(t, "L NaN", [](M& in) { in.pouliquenForterre.L = std::nan(""); }, "L");
    rejects(t, "PouliquenForterre with activePassive K",
        [](M& in) { in.earthPressure = EarthPressureModel::activePassive; }, "earthPressure");
    rejects(t, "Voellmy xi = 0",
        [](M& in) { in.frictionLaw = FrictionLaw::Voellmy; in.voellmy.xi = 0; }, "xi");
    rejects(t, "Voellmy mu < 0",
        [](M& in) { in.frictionLaw = FrictionLaw::Voellmy; in.voellmy.mu = -0.1; }, "mu");
    rejects(t, "Voellmy atan(mu) > phi with activePassive", [](M& in)
    {
        in.frictionLaw = FrictionLaw::Voellmy;
        in.voellmy.mu = 0.8;
        in.earthPressure = EarthPressureModel::activePassive;
    }, "mu");

    // Another law's coefficients are not checked: they are not the input
    ModelInput in = pfInput();
    in.coulomb.deltaDeg = -5;
    bool ok = true;
    try { makeParams<double>(in); } catch (const InputError&) { ok = false; }
    t.check(ok, "PouliquenForterre ignores Coulomb's delta");

    try
    {
        parseFrictionLaw("Manning");
        t.check(false, "unknown friction law rejected");
    }
    catch (const InputError& e)
    {
        std::printf("    %s\n", e.what());
        bool all = true;
        for (const std::string& name : frictionLawNames())
        {
            all = all && std::string(e.what()).find(" " + name) != std::string::npos;
        }
        t.check(all, "unknown friction law rejected, listing the valid ones");
    }
}


//- A uniform layer of depth h0 and speed u0 on an incline zetaDeg, 4x4
//  cells with transmissive sides, integrated to tEnd with dt <= 1e-3
struct Layer
{
    double u;
    double v;
    double hChange;
    bool atRest;
    bool uniform;
};

Layer uniformLayer(const ModelInput& in, double zetaDeg, double h0, double u0, double tEnd)
{
    Problem<double> pb(makeParams<double>(in), 4, 4, 0, 1, 0, 1);
    pb.setInclination([&](double) { return zetaDeg*deg; });
    pb.setState([&](double, double) { return Primitive{h0, u0, 0}; });
    CpuSolver<double> s(pb, false);
    s.setMaxDt(1e-3);
    s.advanceTo(tEnd);
    std::vector<double> h, hu, hv;
    s.getState(h, hu, hv);
    Layer r{hu[5]/h[5], hv[5]/h[5], std::fabs(h[5] - h0), true, true};
    for (std::size_t c = 0; c < h.size(); ++c)
    {
        r.atRest = r.atRest && hu[c] == 0 && hv[c] == 0;
        r.uniform = r.uniform && h[c] == h[5] && hu[c] == hu[5] && hv[c] == hv[5];
    }
    return r;
}

//- The input of a law at the defaults of its header, earthPressure
//  isotropic (activePassive: with phi = 30 deg)
template<class Law>
ModelInput lawInput(bool activePassive = false)
{
    ModelInput in;
    in.g = 9.81;
    in.epsilon = 1;
    in.phiDeg = 30;
    in.earthPressure = activePassive
        ? EarthPressureModel::activePassive
        : EarthPressureModel::isotropic;
    in.frictionLaw = frictionLawOf(Law());
    return in;
}

//- The keyword of the InputError that makeParams throws on in; "" where
//  it accepts in
std::string rejection(const ModelInput& in)
{
    try
    {
        makeParams<double>(in);
        makeParams<float>(in);
    }
    catch (const InputError& e)
    {
        return e.keyword();
    }
    return "";
}

//- Tolerance 1e-13 relative, and absolute where the value is 0
bool close(double a, double b, double tol)
{
    return b == 0 ? std::fabs(a) <= tol : relClose(a, b, tol);
}

//- The worked examples of the header against the law (double 1e-13,
//  float 1e-5); how many it gives
template<class Law>
int checkExamples
(
    Counter& t, const Params<double>& p, const Params<float>& pf
)
{
    const std::string name = Law::name;
    int nExamples = 0;
    std::printf("  %8s %8s %6s %18s %18s %12s\n", "h", "|v|", "zeta", "mu", "example", "drag");
    for (const FrictionExample& e : Law::examples)
    {
        const double cz = std::cos(e.zetaDeg*deg);
        const double mu = frictionCoefficient(p.friction, {e.h, e.speed, cz});
        const double drag = frictionDrag(p.friction, e.speed);
        const float muF = frictionCoefficient
        (
            pf.friction, {float(e.h), float(e.speed), float(cz)}
        );
        const float dragF = frictionDrag(pf.friction, float(e.speed));
        std::printf
        (
            "  %8g %8g %6g %18.15f %18.15f %12.6g\n",
            e.h, e.speed, e.zetaDeg, mu, e.mu, drag
        );
        t.check
        (
            close(mu, e.mu, 1e-13) && close(drag, e.drag, 1e-13)
         && close(muF, e.mu, 1e-5) && close(dragF, e.drag, 1e-5),
            name + ": " + e.what + " (double 1e-13, float 1e-5)"
        );
        ++nExamples;
    }
    return nExamples;
}

//- The dispatch of FrictionParams to the law's functions, the strength at
//  rest, finite non-negative values
template<class Law>
void checkDispatch
(
    Counter& t, const Params<double>& p, const Params<float>& pf
)
{
    const std::string name = Law::name;
    const LawParams<Law, double>& lp = p.friction.of(Law());
    bool dispatch = true;
    bool rest = true;
    bool finite = true;
    for (const double h : {0.0, 1e-300, 1e-3, 0.01, 1.0, 100.0})
    {
        for (const double speed : {0.0, 1e-6, 0.1, 1.0, 30.0})
        {
            for (const double zetaDeg : {0.0, 30.0, 60.0})
            {
                const FrictionState<double> s{h, speed, std::cos(zetaDeg*deg)};
                const double mu = frictionCoefficient(p.friction, s);
                dispatch = dispatch && mu == Law::mu(lp, s);
                finite = finite && std::isfinite(mu) && mu >= 0;
                const float muF = frictionCoefficient
                (
                    pf.friction, {float(h), float(speed), float(s.cosZeta)}
                );
                finite = finite && std::isfinite(muF) && muF >= 0;
                if (speed == 0)
                {
                    rest = rest && mu == staticFrictionCoefficient(p.friction, h);
                }
            }
        }
        dispatch = dispatch
         && staticFrictionCoefficient(p.friction, h) == Law::staticMu(lp, h);
    }
    const double k = dragCoefficient(p.friction);
    dispatch = dispatch && k == Law::dragCoefficient(lp);
    finite = finite && std::isfinite(k) && k >= 0;
    t.check(dispatch, name + ": FrictionParams dispatches to the law's mu, staticMu and dragCoefficient");
    t.check(rest, name + ": material at rest has the strength staticMu (mu at speed 0)");
    t.check(finite, name + ": mu and the drag coefficient finite and >= 0 (h 0 to 100, |v| 0 to 30, zeta 0 to 60 deg)");
}

//- Each coefficient outside its bound, and not finite, rejected naming it
template<class Law>
void checkBounds(Counter& t, const ModelInput& in)
{
    const std::string name = Law::name;
    for (const auto& c : Law::coefficients)
    {
        std::vector<double> bad{std::nan(""), 1e31, -1e31};
        switch (c.bound)
        {
            case Bound::angle: bad.insert(bad.end(), {-1, 90, 120}); break;
            case Bound::positive: bad.insert(bad.end(), {0, -1}); break;
            case Bound::nonNegative: bad.insert(bad.end(), {-1e-3}); break;
            case Bound::finite: break;
        }
        bool all = true;
        for (const double v : bad)
        {
            ModelInput bent = in;
            bent.of(Law()).*c.value = v;
            const std::string k = rejection(bent);
            if (k != c.keyword)
            {
                std::printf("    %s = %g: %s\n", c.keyword, v, k.empty() ? "accepted" : ("rejected naming " + k).c_str());
            }
            all = all && k == c.keyword;
        }
        t.check(all, name + ": " + c.keyword + " outside its bound or not finite rejected, naming " + c.keyword);
    }
}

//- The edge cases of the header
template<class Law>
void checkEdgeCases(Counter& t)
{
    const std::string name = Law::name;
    for (const EdgeCase& e : Law::edgeCases)
    {
        ModelInput edge = lawInput<Law>(e.activePassive);
        bool known = false;
        for (const auto& c : Law::coefficients)
        {
            if (std::string(c.keyword) == e.keyword)
            {
                edge.of(Law()).*c.value = e.value;
                known = true;
            }
        }
        const std::string k = rejection(edge);
        t.check
        (
            known && (e.accepted ? k.empty() : k == e.keyword),
            name + ": " + e.name + ", " + e.keyword + " = " + numberString(e.value)
          + (e.activePassive ? " with activePassive, phi 30" : "")
          + (e.accepted ? ", accepted" : ", rejected naming " + std::string(e.keyword))
        );
    }
}

//- earthPressure activePassive: with the law's friction angle, or refused
//  without one
template<class Law>
void checkActivePassive(Counter& t)
{
    const std::string name = Law::name;
    ModelInput ap = lawInput<Law>(true);
    ap.phiDeg = 89;
    if (Law::frictionAngle.kind != FrictionAngle::none)
    {
        bool known = false;
        for (const auto& c : Law::coefficients)
        {
            known = known || std::string(c.keyword) == Law::frictionAngle.keyword;
        }
        t.check
        (
            known && rejection(ap).empty(),
            name + ": activePassive (phi 89) takes its friction angle from its coefficient "
          + Law::frictionAngle.keyword
        );
    }
    else
    {
        t.check(rejection(ap) == "earthPressure", name + ": no friction angle, activePassive refused naming earthPressure");
    }
}

//- The scheme: a uniform layer at rest on a slope below and above its
//  static friction (4x4 cells, transmissive sides)
template<class Law>
void checkStaticFriction
(
    Counter& t, const ModelInput& in, const Params<double>& p
)
{
    const std::string name = Law::name;
    const double h0 = 0.01;
    const double muS = staticFrictionCoefficient(p.friction, h0);
    const double holdDeg = std::atan(0.9*muS)/deg;
    const double flowDeg = std::atan(1.1*muS + 0.02)/deg;
    const Layer holds = uniformLayer(in, holdDeg, h0, 0.0, 1.0);
    const Layer flows = uniformLayer(in, flowDeg, h0, 0.0, 0.05);
    std::printf("  static mu(h = %g) = %.6f: at %.3f deg u = %g, at %.3f deg u = %g\n", h0, muS, holdDeg, holds.u, flowDeg, flows.u);
    t.check(holds.atRest && holds.uniform, name + ": a layer at rest below its static friction holds exactly");
    t.check(!flows.atRest && flows.u > 0 && std::isfinite(flows.u) && flows.uniform, name + ": above it the layer starts to flow downslope");
}

//- Every check of one law, from its header alone
template<class Law>
void checkLaw(Counter& t, int& exercised)
{
    const std::string name = Law::name;
    const FrictionLaw law = frictionLawOf(Law());
    std::printf("\n%s: %s\n", Law::name, Law::description);

    t.check
    (
        parseFrictionLaw(name) == law && toString(law) == name,
        name + ": its name selects it"
    );

    const ModelInput in = lawInput<Law>();
    const std::string defaultsRejected = rejection(in);
    t.check(defaultsRejected.empty(), name + ": its defaults are valid input");
    if (!defaultsRejected.empty())
    {
        return;
    }
    const Params<double> p = makeParams<double>(in);
    const Params<float> pf = makeParams<float>(in);

    const int nExamples = checkExamples<Law>(t, p, pf);
    checkDispatch<Law>(t, p, pf);
    checkBounds<Law>(t, in);
    checkEdgeCases<Law>(t);
    checkActivePassive<Law>(t);
    checkStaticFriction<Law>(t, in, p);

    t.check(nExamples > 0, name + ": its header gives worked examples");
    if (nExamples > 0)
    {
        ++exercised;
    }
}

void everyLaw(Counter& t)
{
    std::printf("\nEvery law of the list (physics/frictionLaws/frictionLawList.H)\n");
    int exercised = 0;
    forEachFrictionLaw([&](auto law) { checkLaw<decltype(law)>(t, exercised); });
    std::printf("\n");
    t.check
    (
        exercised == nFrictionLaws
     && int(frictionLawNames().size()) == nFrictionLaws,
        fmt("all %g laws of the list exercised", nFrictionLaws)
    );
}


void pouliquenForterreLayers(Counter& t)
{
    std::printf("\nPouliquen-Forterre: uniform layers on a 26.7 deg incline\n");
    const ModelInput in = pfInput();
    const double zeta = 26.7*deg;
    const double t1 = std::tan(21*deg), t2 = std::tan(30.7*deg), t3 = std::tan(22.2*deg);
    const double L = 6e-3, beta = 0.136;
    const double hStop = -L*std::log((std::tan(zeta) - t1)/(t2 - t1));
    const double hStart = L*((t2 - t1)/(std::tan(zeta) - t3) - 1);
    std::printf("  h_stop = %.6f m, h_start = %.6f m\n", hStop, hStart);

    std::printf("  %8s %8s %6s %14s %14s %10s\n", "h [m]", "u0", "t", "u", "exact", "rel. err");
    for (const double h0 : {0.01, 0.02, 0.005})
    {
        const double u0 = h0 < hStart ? 0.1 : 0.0;
        const double exact = beta*h0/hStop*std::sqrt(9.81*h0*std::cos(zeta));
        // Relaxation time 1/(g cos zeta dmu/du), dmu/du = (tan zeta -
        // tan zeta1) h_stop/(L u): 0.2 s (h = 1 cm) to 0.6 s (2 cm)
        const Layer r = uniformLayer(in, 26.7, h0, u0, 20.0);
        const double err = std::fabs(r.u - exact)/exact;
        std::printf("  %8g %8g %6g %14.10f %14.10f %10.2e\n", h0, u0, 20.0, r.u, exact, err);
        t.check
        (
            err < 1e-8 && r.v == 0 && r.hChange == 0 && r.uniform,
            fmt("h = %g m relaxes to the steady speed beta h/h_stop sqrt(g h cos zeta) (rel. 1e-8)", h0)
        );
    }

    const Layer below = uniformLayer(in, 26.7, 0.002, 0.0, 2.0);
    t.check(below.atRest && below.uniform, "h = 2 mm < h_stop at rest stays exactly at rest");
    const Layer stops = uniformLayer(in, 26.7, 0.002, 0.05, 2.0);
    std::printf("  h = 2 mm set moving at 0.05 m/s: u = %g after 2 s\n", stops.u);
    t.check(stops.atRest, "h = 2 mm < h_stop set moving comes to rest");
    const Layer holds = uniformLayer(in, 26.7, 0.005, 0.0, 2.0);
    t.check(holds.atRest, "h = 5 mm (h_stop < h < h_start) at rest holds: hysteresis");
    const Layer starts = uniformLayer(in, 26.7, 0.008, 0.0, 0.05);
    t.check(!starts.atRest && starts.u > 0, "h = 8 mm > h_start at rest starts to flow");
}

void voellmyLayer(Counter& t)
{
    std::printf("\nVoellmy: uniform layer on a 35 deg incline, mu = 0.3, xi = 500\n");
    ModelInput in;
    in.g = 9.81;
    in.earthPressure = EarthPressureModel::isotropic;
    in.frictionLaw = FrictionLaw::Voellmy;
    in.voellmy.mu = 0.3;
    in.voellmy.xi = 500;
    const double zeta = 35*deg;
    const double h0 = 0.5;
    const double exact = std::sqrt(500*h0*(std::sin(zeta) - 0.3*std::cos(zeta)));
    // Relaxation time xi h/(2 g u) ~ 1.4 s
    const Layer r = uniformLayer(in, 35, h0, 0.0, 60.0);
    const double err = std::fabs(r.u - exact)/exact;
    std::printf("  u = %.10f, exact %.10f, rel. err %.2e\n", r.u, exact, err);
    t.check(err < 1e-8 && r.uniform, "relaxes to sqrt(xi h (sin zeta - mu cos zeta)) (rel. 1e-8)");
    const Layer rest = uniformLayer(in, 15, h0, 0.0, 1.0);
    t.check(rest.atRest, "tan(15 deg) < mu: stays at rest");
}

} // namespace


int main()
{
    Counter t;
    portableMath(t);
    everyLaw(t);
    handValues(t);
    badCoefficients(t);
    pouliquenForterreLayers(t);
    voellmyLayer(t);
    return t.finish();
}

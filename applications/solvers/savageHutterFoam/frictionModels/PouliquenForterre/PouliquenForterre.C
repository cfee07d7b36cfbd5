/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "PouliquenForterre.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionModels
{

addFrictionModel(PouliquenForterre);

const wordList PouliquenForterre::keywords({"zeta1", "zeta2", "zeta3", "L", "beta", "gamma"});


PouliquenForterre::PouliquenForterre(const dictionary& coeffs)
:
    frictionModel(coeffs)
{
    checkKeywords(keywords);
}


void PouliquenForterre::set(sh::ModelInput& in) const
{
    in.frictionLaw = sh::FrictionLaw::PouliquenForterre;
    sh::ModelInput::PouliquenForterreInput& pf = in.pouliquenForterre;
    pf.zeta1Deg = coeff("zeta1");
    pf.zeta2Deg = coeff("zeta2");
    pf.zeta3Deg = coeff("zeta3");
    pf.L = coeff("L");
    pf.beta = coeff("beta");
    pf.gamma = coeff("gamma");
}


string PouliquenForterre::summary() const
{
    OStringStream os;
    os  << "zeta1 " << coeff("zeta1") << " deg, zeta2 " << coeff("zeta2")
        << " deg, zeta3 " << coeff("zeta3") << " deg, L " << coeff("L")
        << ", beta " << coeff("beta") << ", gamma " << coeff("gamma");
    return os.str();
}

} // End namespace frictionModels
} // End namespace Foam

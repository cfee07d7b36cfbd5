/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "Voellmy.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionModels
{

addFrictionModel(Voellmy);

const wordList Voellmy::keywords({"mu", "xi"});


Voellmy::Voellmy(const dictionary& coeffs)
:
    frictionModel(coeffs)
{
    checkKeywords(keywords);
}


void Voellmy::set(sh::ModelInput& in) const
{
    in.frictionLaw = sh::FrictionLaw::Voellmy;
    in.voellmy.mu = coeff("mu");
    in.voellmy.xi = coeff("xi");
}


string Voellmy::summary() const
{
    OStringStream os;
    os  << "mu " << coeff("mu") << ", xi " << coeff("xi") << " m/s^2";
    return os.str();
}

} // End namespace frictionModels
} // End namespace Foam

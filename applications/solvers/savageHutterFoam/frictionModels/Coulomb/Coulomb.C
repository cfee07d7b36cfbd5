/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "Coulomb.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace frictionModels
{

addFrictionModel(Coulomb);

const wordList Coulomb::keywords({"delta"});


Coulomb::Coulomb(const dictionary& coeffs)
:
    frictionModel(coeffs)
{
    checkKeywords(keywords);
}


void Coulomb::set(sh::ModelInput& in) const
{
    in.frictionLaw = sh::FrictionLaw::Coulomb;
    in.deltaDeg = coeff("delta");
}


string Coulomb::summary() const
{
    OStringStream os;
    os  << "delta " << coeff("delta") << " deg";
    return os.str();
}

} // End namespace frictionModels
} // End namespace Foam

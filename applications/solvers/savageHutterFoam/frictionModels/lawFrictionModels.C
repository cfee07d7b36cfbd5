/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The run-time selection table of frictionModel: a lawFrictionModel per
    entry of the list of laws (src/savageHutter/physics/frictionLaws/
    frictionLawList.H), under the law's name.
\*---------------------------------------------------------------------------*/

#include "lawFrictionModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

#define SH_FRICTION_LAW(Law, member)                                          \
    frictionModel::adddictionaryConstructorToTable<lawFrictionModel<sh::Law>> \
        add##Law##FrictionModelToTable_(word(sh::Law::name));
#include "physics/frictionLaws/frictionLawList.H"
#undef SH_FRICTION_LAW

} // End namespace Foam

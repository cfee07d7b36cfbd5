/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The run-time selection table of entrainmentModel: a
    coefficientEntrainmentModel per entry of the list of models
    (src/savageHutter/physics/entrainmentModels/entrainmentModelList.H),
    under the model's name.
\*---------------------------------------------------------------------------*/

#include "coefficientEntrainmentModel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

#define SH_ENTRAINMENT_MODEL(Model, member)                                   \
    entrainmentModel::adddictionaryConstructorToTable                         \
    <                                                                         \
        coefficientEntrainmentModel<sh::Model>                                \
    > add##Model##EntrainmentModelToTable_(word(sh::Model::name));
#include "physics/entrainmentModels/entrainmentModelList.H"
#undef SH_ENTRAINMENT_MODEL

} // End namespace Foam

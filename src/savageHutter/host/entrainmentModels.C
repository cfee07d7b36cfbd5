/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The definitions of the entrainment models' static constexpr members,
    once for the library and for every model of the list
    (physics/entrainmentModels/entrainmentModelList.H), as
    frictionLaws.C does for the friction laws.
\*---------------------------------------------------------------------------*/

#include "../physics/entrainment.H"

namespace sh
{

#define SH_ENTRAINMENT_MODEL(Model, member)                                   \
    constexpr const char* Model::name;                                        \
    constexpr const char* Model::description;                                 \
    constexpr decltype(Model::coefficients) Model::coefficients;              \
    constexpr decltype(Model::examples) Model::examples;                      \
    constexpr decltype(Model::edgeCases) Model::edgeCases;
#include "../physics/entrainmentModels/entrainmentModelList.H"
#undef SH_ENTRAINMENT_MODEL

} // namespace sh

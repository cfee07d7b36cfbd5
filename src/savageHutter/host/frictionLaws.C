/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver

Description
    The definitions of the friction laws' static constexpr members, once
    for the library and for every law of the list (physics/frictionLaws/
    frictionLawList.H): C++14 wants a definition of a static data member
    that is bound to a reference (a range-for over Law::coefficients, a
    const char* member passed by reference).
\*---------------------------------------------------------------------------*/

#include "../physics/friction.H"

namespace sh
{

#define SH_FRICTION_LAW(Law, member)                                          \
    constexpr const char* Law::name;                                          \
    constexpr const char* Law::description;                                   \
    constexpr Coefficient<Law::Input> Law::coefficients[];                   \
    constexpr FrictionAngle Law::frictionAngle;                               \
    constexpr FrictionExample Law::examples[];                                \
    constexpr EdgeCase Law::edgeCases[];
#include "../physics/frictionLaws/frictionLawList.H"
#undef SH_FRICTION_LAW

} // namespace sh

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "frictionModel.H"
#include "FlatOutput.H"
#include "wordList.H"

namespace Foam
{

defineTypeNameAndDebug(frictionModel, 0);
defineRunTimeSelectionTable(frictionModel, dictionary);


frictionModel::frictionModel(const dictionary& coeffs)
:
    modelCoefficients(coeffs)
{}


autoPtr<frictionModel> frictionModel::New(const dictionary& tp)
{
    // Build the table on first use
    const wordList valid(dictionaryConstructorTablePtr_->sortedToc());

    if (!tp.found("frictionModel", keyType::LITERAL))
    {
        FatalIOErrorInFunction(tp)
            << "Missing keyword 'frictionModel'." << nl
            << "Valid choices: " << flatOutput(valid) << nl
            << exit(FatalIOError);
    }
    const word name = tp.get<word>("frictionModel");

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(tp)
            << "Unknown frictionModel '" << name << "'." << nl
            << "Valid choices: " << flatOutput(valid) << nl
            << exit(FatalIOError);
    }

    const word coeffsName = name + "Coeffs";
    if (!tp.isDict(coeffsName))
    {
        FatalIOErrorInFunction(tp)
            << "frictionModel " << name << " needs the sub-dictionary '"
            << coeffsName << "' with its coefficients, e.g." << nl
            << "    " << coeffsName << " "
            << sh::frictionCoeffsExample(sh::parseFrictionLaw(name)).c_str()
            << nl << "(see src/savageHutter/physics/frictionLaws/" << name
            << ".H, or savageHutterFoam -listFrictionLaws)" << nl
            << exit(FatalIOError);
    }
    return autoPtr<frictionModel>(cstrIter()(tp.subDict(coeffsName)));
}

} // End namespace Foam

/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "entrainmentModel.H"
#include "FlatOutput.H"
#include "wordList.H"

namespace Foam
{

defineTypeNameAndDebug(entrainmentModel, 0);
defineRunTimeSelectionTable(entrainmentModel, dictionary);


namespace
{

//- Whether the model of this name has a coefficient the case must give
bool needsCoeffs(const word& name)
{
    bool needs = false;
    sh::forEachEntrainmentModel
    (
        [&](auto model)
        {
            using M = decltype(model);
            if (name == M::name)
            {
                for (const auto& c : M::coefficients)
                {
                    needs = needs || c.required;
                }
            }
        }
    );
    return needs;
}

} // namespace


entrainmentModel::entrainmentModel(const dictionary& coeffs)
:
    modelCoefficients(coeffs)
{}


autoPtr<entrainmentModel> entrainmentModel::New(const dictionary& tp)
{
    // Build the table on first use
    const wordList valid(dictionaryConstructorTablePtr_->sortedToc());

    // Absent: none, the released volume all that flows
    const word name =
        tp.found("entrainmentModel", keyType::LITERAL)
      ? tp.get<word>("entrainmentModel")
      : word(sh::NoEntrainment::name);

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(name);
    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(tp)
            << "Unknown entrainmentModel '" << name << "'." << nl
            << "Valid choices: " << flatOutput(valid) << nl
            << "(see savageHutterFoam -listEntrainmentModels)" << nl
            << exit(FatalIOError);
    }

    const word coeffsName = name + "Coeffs";
    const entry* ce = tp.findEntry(coeffsName, keyType::LITERAL);
    if (ce && !ce->isDict())
    {
        FatalIOErrorInFunction(tp)
            << coeffsName << " is not a sub-dictionary." << nl
            << "Valid form: " << coeffsName << " "
            << sh::entrainmentCoeffsExample
               (
                   sh::parseEntrainmentModel(name)
               ).c_str()
            << nl << exit(FatalIOError);
    }
    if (!ce)
    {
        if (needsCoeffs(name))
        {
            FatalIOErrorInFunction(tp)
                << "entrainmentModel " << name << " needs the"
                << " sub-dictionary '" << coeffsName << "' with its"
                << " coefficients, e.g." << nl
                << "    " << coeffsName << " "
                << sh::entrainmentCoeffsExample
                   (
                       sh::parseEntrainmentModel(name)
                   ).c_str()
                << nl << "(see src/savageHutter/physics/entrainmentModels/"
                << name << ".H, or savageHutterFoam -listEntrainmentModels)"
                << nl << exit(FatalIOError);
        }
        // None to give: an empty one, named as the case's would be
        dictionary empty;
        empty.name() = tp.name() + '/' + coeffsName;
        return autoPtr<entrainmentModel>(cstrIter()(empty));
    }
    return autoPtr<entrainmentModel>(cstrIter()(ce->dict()));
}

} // End namespace Foam

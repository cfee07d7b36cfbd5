/*---------------------------------------------------------------------------*\
  savageHutterFoam: Savage-Hutter granular avalanche solver
\*---------------------------------------------------------------------------*/

#include "modelCoefficients.H"
#include "FlatOutput.H"

namespace Foam
{

modelCoefficients::modelCoefficients(const dictionary& coeffs)
:
    coeffs_(coeffs)
{}


scalar modelCoefficients::coeff(const word& key) const
{
    if (!coeffs_.found(key, keyType::LITERAL))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Missing coefficient '" << key << "' in "
            << coeffs_.dictName() << nl << exit(FatalIOError);
    }
    return coeffs_.get<scalar>(key);
}


void modelCoefficients::checkKeywords
(
    const wordList& valid,
    const wordList& required,
    const string& seeAlso
) const
{
    // seeAlso on a line of its own, or nothing
    const std::string seeAlsoLine =
        seeAlso.empty() ? std::string() : seeAlso + '\n';
    for (const word& key : coeffs_.toc())
    {
        if (!valid.found(key))
        {
            FatalIOErrorInFunction(coeffs_)
                << "Unknown coefficient '" << key << "' in "
                << coeffs_.dictName() << "." << nl
                << "Valid coefficients: " << flatOutput(valid) << nl
                << seeAlsoLine.c_str() << exit(FatalIOError);
        }
    }
    for (const word& key : required)
    {
        coeff(key);
    }
}


string modelCoefficients::boundText(const sh::Bound bound)
{
    switch (bound)
    {
        case sh::Bound::angle: return "in [0, 90)";
        case sh::Bound::positive: return "> 0";
        case sh::Bound::nonNegative: return ">= 0";
        case sh::Bound::finite: return "finite";
    }
    return string();
}

} // End namespace Foam

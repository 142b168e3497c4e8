/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "elasticConstants.H"
#include "dictionaryChecks.H"
#include <cmath>

Foam::meshless::elasticConstants::elasticConstants(const dictionary& dict)
:
    E_(0),
    nu_(readInOpenRange(dict, "nu", -1, 0.5))
{
    const wordList moduli({"E", "K", "G"});
    label nGiven = 0;
    for (const word& m : moduli) nGiven += dict.found(m);
    if (nGiven != 1)
    {
        FatalIOErrorInFunction(dict)
            << (nGiven ? "More than one" : "None") << " of the moduli "
            << moduli << " given: expected exactly one, with 'nu'"
            << exit(FatalIOError);
    }

    if (dict.found("E"))
    {
        E_ = readPositive(dict, "E");
    }
    else if (dict.found("K"))
    {
        E_ = 3*readPositive(dict, "K")*(1 - 2*nu_);
    }
    else
    {
        E_ = 2*readPositive(dict, "G")*(1 + nu_);
    }
}


Foam::scalar Foam::meshless::elasticConstants::waveSpeed(const scalar rho) const
{
    return std::sqrt(M()/rho);
}

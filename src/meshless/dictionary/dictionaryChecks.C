/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "dictionaryChecks.H"
#include "IOstreams.H"

Foam::scalar Foam::meshless::readPositive
(
    const dictionary& dict,
    const word& keyword
)
{
    const scalar v = dict.get<scalar>(keyword);
    if (!(v > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << keyword << "' is " << v
            << ": expected a value > 0" << exit(FatalIOError);
    }
    return v;
}


Foam::scalar Foam::meshless::readPositiveOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    return dict.found(keyword) ? readPositive(dict, keyword) : deflt;
}


Foam::scalar Foam::meshless::readNonNegative
(
    const dictionary& dict,
    const word& keyword
)
{
    const scalar v = dict.get<scalar>(keyword);
    if (!(v >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << keyword << "' is " << v
            << ": expected a value >= 0" << exit(FatalIOError);
    }
    return v;
}


Foam::scalar Foam::meshless::readNonNegativeOrDefault
(
    const dictionary& dict,
    const word& keyword,
    const scalar deflt
)
{
    return dict.found(keyword) ? readNonNegative(dict, keyword) : deflt;
}


void Foam::meshless::checkRenamed
(
    const dictionary& dict,
    const std::initializer_list<std::pair<const char*, const char*>> renamed
)
{
    for (const auto& r : renamed)
    {
        if (dict.found(r.first, keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << r.first << "' was renamed: expected '"
                << r.second << "' (the same meaning)" << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::meshless::readInOpenRange
(
    const dictionary& dict,
    const word& keyword,
    const scalar lower,
    const scalar upper
)
{
    const scalar v = dict.get<scalar>(keyword);
    if (!(v > lower && v < upper))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << keyword << "' is " << v
            << ": expected a value in (" << lower << ", " << upper << ")"
            << exit(FatalIOError);
    }
    return v;
}


Foam::label Foam::meshless::readPositiveLabel
(
    const dictionary& dict,
    const word& keyword
)
{
    const label v = dict.get<label>(keyword);
    if (v < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << keyword << "' is " << v
            << ": expected an integer > 0" << exit(FatalIOError);
    }
    return v;
}


Foam::label Foam::meshless::readLabelInRange
(
    const dictionary& dict,
    const word& keyword,
    const label lower,
    const label upper
)
{
    const label v = dict.get<label>(keyword);
    if (v < lower || v > upper)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << keyword << "' is " << v
            << ": expected an integer in [" << lower << ", " << upper << "]"
            << exit(FatalIOError);
    }
    return v;
}

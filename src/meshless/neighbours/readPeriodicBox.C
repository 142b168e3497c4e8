/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "readPeriodicBox.H"
#include "wordList.H"
#include "scalarList.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::meshless::periodicBox Foam::meshless::readPeriodicBox
(
    const dictionary& dict,
    const label dim
)
{
    periodicBox box;
    const dictionary* pd = dict.findDict("periodic");
    if (!pd)
    {
        if (dict.found("periodic"))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'periodic': expected a dictionary of directions,"
                << " e.g. periodic { x (0 1); }" << exit(FatalIOError);
        }
        return box;
    }

    const wordList names(dim == 2 ? wordList{"x", "y"} : wordList{"x", "y", "z"});
    for (const entry& e : *pd)
    {
        const word& key = e.keyword();
        const label d = names.find(key);
        if (d < 0)
        {
            FatalIOErrorInFunction(*pd)
                << "Unknown periodic direction '" << key << "' in 'periodic'"
                << " (" << dim << "D scene): expected one of " << names
                << exit(FatalIOError);
        }
        scalarList bounds;
        if (e.isStream())
        {
            ITstream& is = e.stream();
            is >> bounds;
        }
        if (bounds.size() != 2)
        {
            FatalIOErrorInFunction(*pd)
                << "Periodic direction '" << key << "': expected its bounds"
                << " (min max) in m, e.g. " << key << " (0 1);"
                << exit(FatalIOError);
        }
        if (!(bounds[1] > bounds[0]))
        {
            FatalIOErrorInFunction(*pd)
                << "Periodic direction '" << key << "' (" << bounds[0] << " "
                << bounds[1] << "): expected max > min" << exit(FatalIOError);
        }
        box.set(d, bounds[0], bounds[1]);
    }
    return box;
}

// ************************************************************************* //

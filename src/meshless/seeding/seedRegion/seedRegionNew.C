/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "seedRegion.H"
#include "surfaceRegion.H"
#include "searchableSurface.H"
#include "FlatOutput.H"

Foam::autoPtr<Foam::meshless::seedRegion> Foam::meshless::seedRegion::New
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    const word regionType(dict.get<word>("type"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(regionType);
    if (cstrIter.found())
    {
        return cstrIter()(dict, mesh);
    }

    if (searchableSurface::dictConstructorTablePtr_->found(regionType))
    {
        return autoPtr<seedRegion>(new surfaceRegion(dict, mesh));
    }

    FatalIOErrorInFunction(dict)
        << "Entry 'type' is " << regionType << ": expected a region type "
        << flatOutput(dictionaryConstructorTablePtr_->sortedToc())
        << " or a closed searchable surface "
        << flatOutput(searchableSurface::dictConstructorTablePtr_->sortedToc())
        << exit(FatalIOError);

    return nullptr;
}

// ************************************************************************* //

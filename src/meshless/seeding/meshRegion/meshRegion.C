/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshRegion.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(meshRegion, 0);
    addToRunTimeSelectionTable(seedRegion, meshRegion, dictionary);
}
}


Foam::meshless::meshRegion::meshRegion
(
    const dictionary&,
    const polyMesh& mesh
)
:
    mesh_(mesh)
{}


Foam::boundBox Foam::meshless::meshRegion::bounds() const
{
    return mesh_.bounds();
}


void Foam::meshless::meshRegion::inside
(
    const pointField& points,
    const labelUList& cells,
    boolList& in
) const
{
    in.setSize(points.size());
    forAll(points, i)
    {
        in[i] = cells[i] >= 0;
    }
}

// ************************************************************************* //

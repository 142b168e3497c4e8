/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cellZoneRegion.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(cellZoneRegion, 0);
    addToRunTimeSelectionTable(seedRegion, cellZoneRegion, dictionary);
}
}


Foam::meshless::cellZoneRegion::cellZoneRegion
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    mesh_(mesh),
    zoneID_(-1),
    bounds_(boundBox::invertedBox)
{
    const word zone(dict.get<word>("zone"));
    zoneID_ = mesh.cellZones().findZoneID(zone);
    if (zoneID_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'zone': no cellZone " << zone << " in the mesh;"
            << " expected one of " << mesh.cellZones().names()
            << exit(FatalIOError);
    }

    for (const label celli : mesh.cellZones()[zoneID_])
    {
        for (const label pointi : mesh.cellPoints()[celli])
        {
            bounds_.add(mesh.points()[pointi]);
        }
    }
}


Foam::boundBox Foam::meshless::cellZoneRegion::bounds() const
{
    return bounds_;
}


void Foam::meshless::cellZoneRegion::inside
(
    const pointField& points,
    const labelUList& cells,
    boolList& in
) const
{
    // The zone's own lookup: a cell may belong to several zones
    const cellZone& zone = mesh_.cellZones()[zoneID_];
    in.setSize(points.size());
    forAll(points, i)
    {
        in[i] = cells[i] >= 0 && zone.whichCell(cells[i]) >= 0;
    }
}

// ************************************************************************* //

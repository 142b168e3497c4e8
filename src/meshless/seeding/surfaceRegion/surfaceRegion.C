/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "surfaceRegion.H"
#include "Time.H"
#include "OSspecific.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(surfaceRegion, 0);
}
}


Foam::meshless::surfaceRegion::surfaceRegion
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    const word surfaceType(dict.get<word>("type"));

    // Surface files live where snappyHexMesh looks for them; checked here
    // so that a wrong name is an error naming the keyword
    if (dict.found("file"))
    {
        fileName file(dict.get<fileName>("file"));
        file.expand();
        if (!file.isAbsolute())
        {
            file = mesh.time().constant()/"triSurface"/file;
        }
        if (!isFile(file))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'file': no surface file " << file
                << ": expected a closed surface in constant/triSurface"
                << exit(FatalIOError);
        }
    }

    // Not registered: several bodies may use surfaces of one name
    surface_ = searchableSurface::New
    (
        surfaceType,
        IOobject
        (
            dict.dictName(),
            mesh.time().constant(),
            "triSurface",
            mesh.time(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        ),
        dict
    );

    if (!surface_->hasVolumeType())
    {
        FatalIOErrorInFunction(dict)
            << "Surface of type " << surfaceType << " encloses no volume:"
            << " expected a closed surface (box, sphere, cylinder, a closed"
            << " triSurfaceMesh, ...)" << exit(FatalIOError);
    }
    if (surface_->outsideVolumeType() != volumeType::OUTSIDE)
    {
        FatalIOErrorInFunction(dict)
            << "Surface of type " << surfaceType << ": a point outside its"
            << " bounds is " << volumeType::names[surface_->outsideVolumeType()]
            << ": expected OUTSIDE (are its normals pointing inward?)"
            << exit(FatalIOError);
    }
}


Foam::boundBox Foam::meshless::surfaceRegion::bounds() const
{
    return surface_->bounds();
}


void Foam::meshless::surfaceRegion::inside
(
    const pointField& points,
    const labelUList&,
    boolList& in
) const
{
    List<volumeType> types;
    surface_->getVolumeType(points, types);
    in.setSize(points.size());
    forAll(points, i)
    {
        in[i] = types[i] == volumeType::INSIDE;
    }
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "wallLayers.H"
#include "dictionaryChecks.H"
#include "emptyPolyPatch.H"
#include "indexedOctree.H"
#include "treeDataFace.H"
#include "Random.H"
#include "HashSet.H"
#include "FlatOutput.H"

namespace
{

//- Octree over mesh faces, for nearest-point queries
Foam::autoPtr<Foam::indexedOctree<Foam::treeDataFace>> faceTree
(
    const Foam::polyMesh& mesh,
    const Foam::labelList& faces
)
{
    using namespace Foam;

    boundBox bb(boundBox::invertedBox);
    for (const label facei : faces)
    {
        for (const label pointi : mesh.faces()[facei])
        {
            bb.add(mesh.points()[pointi]);
        }
    }

    // Slightly enlarged so that no face lies on the octree's boundary (and
    // a 2D mesh's one-cell thickness is no degenerate box)
    Random rndGen(123456);
    const treeBoundBox treeBb(treeBoundBox(bb).extend(rndGen, 1e-4));

    return autoPtr<indexedOctree<treeDataFace>>::New
    (
        treeDataFace(false, mesh, faces),
        treeBb,
        8,      // maxLevel
        10,     // leaf size
        3.0     // duplicity
    );
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::wallLayers::wallLayers
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    mesh_(mesh),
    patchIDs_(),
    nLayers_(readPositiveLabel(dict, "layers"))
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();

    // Empty patches (the front and back of a 2D mesh) are never walls
    DynamicList<word> candidates;
    for (const polyPatch& pp : patches)
    {
        if (!isA<emptyPolyPatch>(pp)) candidates.append(pp.name());
    }

    const wordRes names(dict.get<wordRes>("patches"));
    if (names.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'patches' is empty: expected wall patch names from "
            << flatOutput(candidates) << exit(FatalIOError);
    }

    labelHashSet chosen;
    for (const wordRe& name : names)
    {
        bool matched = false;
        for (const polyPatch& pp : patches)
        {
            if (!isA<emptyPolyPatch>(pp) && name.match(pp.name()))
            {
                chosen.insert(pp.index());
                matched = true;
            }
        }
        if (!matched)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'patches': " << name << " matches no patch;"
                << " expected names from " << flatOutput(candidates)
                << exit(FatalIOError);
        }
    }
    patchIDs_ = chosen.sortedToc();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::labelList Foam::meshless::wallLayers::patchFaces(const bool chosen) const
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const labelHashSet isChosen(patchIDs_);

    DynamicList<label> faces;
    for (const polyPatch& pp : patches)
    {
        if (isA<emptyPolyPatch>(pp) || isChosen.found(pp.index()) != chosen)
        {
            continue;
        }
        forAll(pp, i)
        {
            faces.append(pp.start() + i);
        }
    }
    return labelList(std::move(faces));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::wallLayers::seed
(
    const seedLattice& lattice,
    const meshSearch& search,
    DynamicList<point>& points,
    DynamicList<vector>& normals,
    DynamicList<scalar>& distances
) const
{
    const scalar dx = lattice.spacing();
    const scalar reach = nLayers_*dx;

    // Round-off allowances: a point at exactly N dx is kept, and an open
    // patch as near as the wall (to round-off) takes a point in front
    const scalar tol = 1e-9*dx;

    const labelList wallFaces(patchFaces(true));
    const labelList otherFaces(patchFaces(false));
    if (wallFaces.empty())
    {
        return;
    }
    const auto wallTree = faceTree(mesh_, wallFaces);
    autoPtr<indexedOctree<treeDataFace>> otherTree;
    if (otherFaces.size())
    {
        otherTree = faceTree(mesh_, otherFaces);
    }

    // The lattice over the walls' box grown by the layers' reach
    boundBox bb(wallTree->bb());
    bb.min() -= vector::uniform(reach);
    bb.max() += vector::uniform(reach);
    const tmp<pointField> tcandidates(lattice.points(bb));
    const pointField& candidates = tcandidates();

    const vectorField& areas = mesh_.faceAreas();

    for (const point& p : candidates)
    {
        const pointIndexHit wallHit =
            wallTree->findNearest(p, sqr(reach + tol));
        if (!wallHit.hit()) continue;

        const point& xw = wallHit.hitPoint();
        const vector r(p - xw);
        const scalar d = mag(r);
        const label facei = wallFaces[wallHit.index()];
        const vector nf(areas[facei]/mag(areas[facei]));

        // In front of the wall's plane and no nearer to it than to an open
        // patch: beyond that patch (ties too: at an acute rim the points
        // over the opening are as near to the rim as to the wall)
        if
        (
            (r & nf) < -tol
         && otherTree
         && otherTree->findNearest(p, sqr(d + 1e3*tol)).hit()
        )
        {
            continue;
        }

        if (search.findCell(p) >= 0) continue;

        points.append(p);
        normals.append(d > tol ? r/d : nf);
        distances.append(d);
    }
}

// ************************************************************************* //

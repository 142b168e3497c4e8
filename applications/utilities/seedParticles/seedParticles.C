/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    seedParticles

Group
    grpPreProcessingUtilities

Description
    Samples the blockMesh geometry into particles: for each body of
    system/seedParticlesDict, the points of a lattice of the body's spacing
    that lie in the mesh and in the body's region, or, for a wall body, the
    layers of lattice points behind chosen patches. Writes each body as a
    lagrangian cloud at the start time with its volume, mass and density per
    particle (and a wall body's normal and wallDistance), and prints per
    body the count, volume, mass and bounding box.

    Every body is seeded on the lattice x = min(mesh bounds) + (i + offset)dx
    (see seedLattice): bodies of one spacing and offset line up, so the wall
    layers continue the fluid's lattice across the wall.

    A body seeded in a region may ask for a 'relaxation' (see
    particleRelaxation): a random shift, then iterations that even out its
    kernel sums among the other bodies' particles (fixed) and within its
    region, across the scene's periodic directions (the 'periodic' entry of
    constant/particleProperties). A flow that stretches a lattice (a
    Taylor-Green vortex) starts from relaxed particles.

    All bodies are seeded before anything is written: a bad body leaves
    nothing on disk.

    The case's dimension is the mesh's: a mesh one cell thick with empty
    front and back patches (normal z) gives 2D particles in its mid-plane.

Usage
    \verbatim
    bodies
    {
        water
        {
            spacing   0.001;         // lattice spacing [m]
            density   1000;          // [kg/m^3]
            offset    (0.5 0.5 0.5); // lattice offset / spacing (default)
            region    { type cellZone; zone water; }
            // region { type mesh; }                         // all cells
            // region { type box; min (0 0 0); max (1 1 1); }
            // region { type sphere; centre (0 0 0); radius 0.1; }
            // region { type cylinder; point1 (0 0 -1); point2 (0 0 1);
            //          radius 0.1; }                        // a 2D disk
            // region { type triSurfaceMesh; file "gate.stl"; }
            //                         // closed, in constant/triSurface
            // region                 // union | intersection | difference
            // {                      // (difference: first minus the rest)
            //     type    difference;
            //     regions ( { type mesh; } { type box; min (..); max (..); } );
            // }
            // ...or any other closed searchable surface type

            // relaxation { iterations 300; }  // optional: see
            //                                  // particleRelaxation
        }

        // A wall body seeded in a region (a gate plate of ghost particles)
        // takes a uniform 'normal', out of the wall into the fluid
        gate
        {
            spacing   0.001;
            density   1000;
            region    { type cellZone; zone gate; }
            normal    (-1 0 0);
        }

        // Wall particles: 'patches' and 'layers' instead of 'region'
        walls
        {
            spacing   0.001;         // the fluid's: the lattices line up
            density   1000;
            patches   (walls);       // patch names or regular expressions
            layers    3;             // layers*spacing >= kernel support
        }
    }
    \endverbatim

See also
    Foam::meshless::seedLattice
    Foam::meshless::seedRegion
    Foam::meshless::wallLayers

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "meshSearch.H"
#include "particleSet.H"
#include "lagrangianIO.H"
#include "dictionaryChecks.H"
#include "seedLattice.H"
#include "seedRegion.H"
#include "wallLayers.H"
#include "particleRelaxation.H"
#include "readPeriodicBox.H"
#include <memory>
#include <vector>

using namespace Foam::meshless;

namespace
{

//- The lattice points of a region that lie in the mesh
void seedInRegion
(
    const dictionary& dict,
    const polyMesh& mesh,
    const meshSearch& search,
    const seedLattice& lattice,
    DynamicList<point>& pts
)
{
    const autoPtr<seedRegion> region
    (
        seedRegion::New(dict.subDict("region"), mesh)
    );

    // The region's box clipped to the mesh
    const boundBox& meshBb = mesh.bounds();
    boundBox bb(region->bounds());
    bb.min() = max(bb.min(), meshBb.min());
    bb.max() = min(bb.max(), meshBb.max());

    const tmp<pointField> tcandidates(lattice.points(bb));
    const pointField& candidates = tcandidates();
    labelList cells(candidates.size());
    forAll(candidates, i)
    {
        cells[i] = search.findCell(candidates[i]);
    }
    boolList in;
    region->inside(candidates, cells, in);

    forAll(candidates, i)
    {
        if (cells[i] >= 0 && in[i]) pts.append(candidates[i]);
    }
}


//- A body has either a region or wall patches
void checkBodyKind(const word& body, const dictionary& dict)
{
    const bool region = dict.found("region");
    const bool walls = dict.found("patches");
    if (region && walls)
    {
        FatalIOErrorInFunction(dict)
            << "Body " << body << " has both 'region' and 'patches':"
            << " expected either 'region' (particles in the mesh) or"
            << " 'patches' with 'layers' (wall particles behind patches)"
            << exit(FatalIOError);
    }
    if (!region && !walls)
    {
        FatalIOErrorInFunction(dict)
            << "Body " << body << " has neither 'region' nor 'patches':"
            << " expected 'region' (particles in the mesh) or 'patches'"
            << " with 'layers' (wall particles behind patches)"
            << exit(FatalIOError);
    }
    if (!region && dict.found("relaxation"))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << body << ": entry 'relaxation' belongs to bodies"
            << " seeded in a region: expected wall layers ('patches') to keep"
            << " their lattice" << exit(FatalIOError);
    }
    if (region && dict.found("layers"))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << body << ": entry 'layers' belongs to wall bodies:"
            << " expected 'patches' instead of 'region' with it"
            << exit(FatalIOError);
    }
    if (walls && dict.found("normal"))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << body << ": entry 'normal' belongs to bodies seeded"
            << " in a region: wall layers take theirs from their patches"
            << exit(FatalIOError);
    }
}

//- A region's uniform wall normal ('normal', optional): a unit vector
//  out of the wall into the fluid, or zero when absent
vector regionNormal(const word& body, const dictionary& dict, const label dim)
{
    if (!dict.found("normal")) return Zero;
    const vector n(dict.get<vector>("normal"));
    const scalar len = mag(n);
    if (len < SMALL || (dim == 2 && mag(n.z()) > SMALL*len))
    {
        FatalIOErrorInFunction(dict)
            << "Body " << body << ": entry 'normal' is " << n
            << ": expected a non-zero vector"
            << (dim == 2 ? " in the 2D case's plane (z = 0)" : "")
            << exit(FatalIOError);
    }
    return n/len;
}

//- The scene's periodic directions (constant/particleProperties' 'periodic'
//  entry), none when the file is absent
periodicBox scenePeriodic(const Time& runTime, const polyMesh& mesh)
{
    IOobject io
    (
        "particleProperties",
        runTime.constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE
    );
    if (!io.typeHeaderOk<IOdictionary>(true)) return periodicBox();
    const IOdictionary scene(io);
    return readPeriodicBox(scene, mesh.nSolutionD());
}


//- Relax the particles of body k among the other bodies' (fixed)
void relaxBody
(
    const label k,
    const dictionary& dict,
    std::vector<std::unique_ptr<particleSet>>& sets,
    const polyMesh& mesh,
    const meshSearch& search,
    const periodicBox& periodic,
    const scalar zPlane
)
{
    particleSet& set = *sets[k];
    const label dim = set.dim();
    const scalar dx = readPositive(dict, "spacing");
    particleRelaxation relaxation(dict.subDict("relaxation"), dim, dx, periodic);

    std::vector<double> x(set.positions().data(), set.positions().data() + size_t(set.size())*dim);
    std::vector<double> xFixed;
    std::vector<double> VFixed;
    forAll(sets, o)
    {
        if (o == k) continue;
        const particleSet& other = *sets[o];
        const particleField& xo = other.positions();
        const particleField& Vo = other.field("volume");
        for (label i = 0; i < other.size(); ++i)
        {
            for (label d = 0; d < dim; ++d) xFixed.push_back(xo(i, d));
            VFixed.push_back(Vo(i, 0));
        }
    }

    const autoPtr<seedRegion> region
    (
        seedRegion::New(dict.subDict("region"), mesh)
    );
    pointField pts;
    labelList cells;
    boolList in;
    auto inside = [&](const double* xt, const label n, std::vector<char>& ok)
    {
        pts.setSize(n);
        cells.setSize(n);
        forAll(pts, i)
        {
            point p(0, 0, zPlane);
            for (label d = 0; d < dim; ++d) p[d] = xt[size_t(i)*dim + d];
            pts[i] = p;
            cells[i] = search.findCell(p);
        }
        region->inside(pts, cells, in);
        for (label i = 0; i < n; ++i) ok[i] = cells[i] >= 0 && in[i];
    };

    const scalar V = set.field("volume")(0, 0);
    relaxation.relax(x, V, xFixed, VFixed, inside);
    std::copy(x.begin(), x.end(), set.positions().data());

    Info<< "Body " << set.name() << " relaxed" << nl
        << "    iterations   " << relaxation.iterationsDone() << nl
        << "    residual     " << relaxation.initialResidual() << " -> "
        << relaxation.finalResidual()
        << " (max h|Gamma|, Gamma = -2 sum grad W V)" << nl
        << "    refused      " << relaxation.refused()
        << " moves out of the region" << nl << endl;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Sample the mesh into particles as described by"
        " system/seedParticlesDict"
    );
    // Seeded once on the whole case; decomposePar then splits the clouds
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    IOdictionary seedDict
    (
        IOobject
        (
            "seedParticlesDict",
            runTime.system(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    // Dimension and 2D plane from the mesh
    const label dim = mesh.nSolutionD();
    if (dim == 2 && mesh.solutionD()[vector::Z] != -1)
    {
        FatalErrorInFunction
            << "2D meshes must have their empty direction along z"
            << exit(FatalError);
    }
    if (dim != 2 && dim != 3)
    {
        FatalErrorInFunction
            << "The mesh solves in " << dim << " directions: expected 2 or 3"
            << exit(FatalError);
    }
    const boundBox& meshBb = mesh.bounds();
    const scalar zPlane = 0.5*(meshBb.min().z() + meshBb.max().z());

    meshSearch search(mesh);

    const dictionary& bodiesDict = seedDict.subDict("bodies");
    if (bodiesDict.empty())
    {
        FatalIOErrorInFunction(bodiesDict)
            << "No body in 'bodies': expected at least one" << exit(FatalIOError);
    }

    Info<< "Seeding " << dim << "D particles" << nl << endl;

    // Seed every body first, write only when all succeeded: a bad body
    // leaves nothing half-written on disk
    std::vector<std::unique_ptr<particleSet>> sets;

    for (const entry& e : bodiesDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(bodiesDict)
                << "Entry '" << e.keyword() << "' in 'bodies':"
                << " expected a body dictionary" << exit(FatalIOError);
        }
        const word body(e.keyword());
        const dictionary& dict = e.dict();
        const scalar dx = readPositive(dict, "spacing");
        const scalar rho = readPositive(dict, "density");
        const vector offset =
            dict.getOrDefault<vector>("offset", vector(0.5, 0.5, 0.5));
        checkBodyKind(body, dict);
        const vector uniformNormal(regionNormal(body, dict, dim));
        const seedLattice lattice(meshBb.min(), dx, offset, dim, zPlane);

        DynamicList<point> pts;
        DynamicList<vector> normals;
        DynamicList<scalar> distances;
        autoPtr<wallLayers> walls;
        if (dict.found("region"))
        {
            seedInRegion(dict, mesh, search, lattice, pts);
        }
        else
        {
            walls.reset(new wallLayers(dict, mesh));
            walls->seed(lattice, search, pts, normals, distances);
        }

        if (pts.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Body " << body << ": "
                << (walls ? "its patches yield" : "its region yields")
                << " no particle at spacing " << dx
                << " (mesh bounds " << meshBb << "): expected "
                << (walls ? "patches" : "a region")
                << " holding at least one lattice point inside the mesh"
                << exit(FatalIOError);
        }

        sets.emplace_back(new particleSet(body, dim));
        particleSet& set = *sets.back();
        set.resize(pts.size());
        particleField& x = set.positions();
        forAll(pts, i)
        {
            for (label d = 0; d < dim; ++d) x(i, d) = pts[i][d];
        }
        const scalar V = lattice.cellVolume();
        set.addField("volume", particleField::kind::scalar).fill(V);
        set.addField("mass", particleField::kind::scalar).fill(rho*V);
        set.addField("rho", particleField::kind::scalar).fill(rho);
        if (walls)
        {
            particleField& n =
                set.addField("normal", particleField::kind::vector);
            particleField& d =
                set.addField("wallDistance", particleField::kind::scalar);
            forAll(pts, i)
            {
                for (label c = 0; c < dim; ++c) n(i, c) = normals[i][c];
                d(i, 0) = distances[i];
            }
        }
        else if (mag(uniformNormal) > 0)
        {
            particleField& n =
                set.addField("normal", particleField::kind::vector);
            forAll(pts, i)
            {
                for (label c = 0; c < dim; ++c) n(i, c) = uniformNormal[c];
            }
        }

        boundBox pbb(pts, false);
        Info<< "Body " << body << nl
            << "    particles    " << set.size() << nl
            << "    spacing      " << dx << nl
            << "    volume       " << V*set.size()
            << (dim == 2 ? " m^2 (per unit depth)" : " m^3") << nl
            << "    mass         " << rho*V*set.size()
            << (dim == 2 ? " kg/m" : " kg") << nl
            << "    bounding box " << pbb << nl;
        if (walls)
        {
            const wordList patchNames(mesh.boundaryMesh().names());
            Info<< "    wall layers  " << walls->nLayers() << " behind "
                << wordList(patchNames, walls->patchIDs()) << nl
                << "    distance     " << min(distances) << " .. "
                << max(distances) << nl;
        }
        Info<< endl;
    }

    // Relax the bodies that ask for it, in order, each among the others
    {
        label k = 0;
        bool any = false;
        for (const entry& e : bodiesDict) any = any || e.dict().found("relaxation");
        const periodicBox periodic
        (
            any ? scenePeriodic(runTime, mesh) : periodicBox()
        );
        for (const entry& e : bodiesDict)
        {
            if (e.dict().found("relaxation"))
            {
                relaxBody(k, e.dict(), sets, mesh, search, periodic, zPlane);
            }
            ++k;
        }
    }

    const lagrangianIO::meshLocator locator(mesh);
    for (const auto& set : sets)
    {
        lagrangianIO::write
        (
            *set,
            runTime,
            runTime.timeName(),
            zPlane,
            locator.locate(*set, zPlane)
        );
        Info<< "Written " << set->name() << " to "
            << (runTime.timeName()/lagrangianIO::cloudLocal(set->name())).c_str()
            << nl;
    }
    Info<< endl;

    Info<< "End" << nl << endl;
    return 0;
}

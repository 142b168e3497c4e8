/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    seedParticles

Group
    grpPreProcessingUtilities

Description
    Samples the blockMesh geometry into particles: for each body of
    system/seedParticlesDict, a lattice of the body's spacing over its
    region, keeping the lattice points that OpenFOAM's cell search finds in
    the mesh (and in the region). Writes each body as a lagrangian cloud at
    the start time with its volume, mass and density per particle, and
    prints per body the count, volume, mass and bounding box.

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
            region    { type cellZone; zone water; }
            // region { type mesh; }                         // all cells
            // region { type box; min (0 0 0); max (1 1 1); }
            offset    (0.5 0.5 0.5); // lattice offset / spacing (default)
        }
    }
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "meshSearch.H"
#include "particleSet.H"
#include "lagrangianIO.H"
#include "dictionaryChecks.H"
#include <memory>
#include <vector>

using namespace Foam::meshless;

namespace
{

//- Bounding box of the region and a test of its cells
struct seedRegion
{
    boundBox bb;
    label zoneID = -1;      // cellZone, or -1 for any cell
    bool box = false;
};


seedRegion readRegion(const dictionary& dict, const polyMesh& mesh)
{
    seedRegion r;
    const word type(dict.get<word>("type"));
    if (type == "mesh")
    {
        r.bb = mesh.bounds();
    }
    else if (type == "cellZone")
    {
        const word zone(dict.get<word>("zone"));
        r.zoneID = mesh.cellZones().findZoneID(zone);
        if (r.zoneID < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'zone': no cellZone " << zone << " in the mesh;"
                << " expected one of " << mesh.cellZones().names()
                << exit(FatalIOError);
        }
        r.bb = boundBox::invertedBox;
        for (const label celli : mesh.cellZones()[r.zoneID])
        {
            for (const label pointi : mesh.cellPoints()[celli])
            {
                r.bb.add(mesh.points()[pointi]);
            }
        }
    }
    else if (type == "box")
    {
        r.bb = boundBox(dict.get<point>("min"), dict.get<point>("max"));
        r.box = true;
        if (r.bb.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Box " << r.bb << ": expected min < max in every direction"
                << exit(FatalIOError);
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'type' is " << type
            << ": expected one of (mesh cellZone box)" << exit(FatalIOError);
    }
    return r;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Sample the mesh into particles as described by"
        " system/seedParticlesDict"
    );
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
        const seedRegion region = readRegion(dict.subDict("region"), mesh);

        // Lattice over the region's box, clipped to the mesh
        boundBox bb(region.bb);
        bb.min() = max(bb.min(), meshBb.min());
        bb.max() = min(bb.max(), meshBb.max());

        label n[3] = {1, 1, 1};
        for (label d = 0; d < dim; ++d)
        {
            n[d] = label(std::floor((bb.max()[d] - bb.min()[d])/dx - offset[d]))
                 + 1;
            n[d] = std::max(n[d], label(0));
        }

        DynamicList<point> pts;
        for (label k = 0; k < n[2]; ++k)
        for (label j = 0; j < n[1]; ++j)
        for (label i = 0; i < n[0]; ++i)
        {
            point p
            (
                bb.min().x() + (i + offset.x())*dx,
                bb.min().y() + (j + offset.y())*dx,
                dim == 3 ? bb.min().z() + (k + offset.z())*dx : zPlane
            );
            if (region.box && !region.bb.contains(p)) continue;
            const label celli = search.findCell(p);
            if (celli < 0) continue;
            if
            (
                region.zoneID >= 0
             && mesh.cellZones().whichZone(celli) != region.zoneID
            )
            {
                continue;
            }
            pts.append(p);
        }

        if (pts.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Body " << body << ": its region yields no particle at"
                << " spacing " << dx << " (region bounds " << region.bb
                << ", mesh bounds " << meshBb << ")" << exit(FatalIOError);
        }

        sets.emplace_back(new particleSet(body, dim));
        particleSet& set = *sets.back();
        set.resize(pts.size());
        particleField& x = set.positions();
        forAll(pts, i)
        {
            for (label d = 0; d < dim; ++d) x(i, d) = pts[i][d];
        }
        const scalar V = dim == 2 ? dx*dx : dx*dx*dx;
        set.addField("volume", particleField::kind::scalar).fill(V);
        set.addField("mass", particleField::kind::scalar).fill(rho*V);
        set.addField("rho", particleField::kind::scalar).fill(rho);

        boundBox pbb(pts, false);
        Info<< "Body " << body << nl
            << "    particles    " << set.size() << nl
            << "    spacing      " << dx << nl
            << "    volume       " << V*set.size()
            << (dim == 2 ? " m^2 (per unit depth)" : " m^3") << nl
            << "    mass         " << rho*V*set.size()
            << (dim == 2 ? " kg/m" : " kg") << nl
            << "    bounding box " << pbb << nl
            << endl;
    }

    for (const auto& set : sets)
    {
        lagrangianIO::write(*set, runTime, runTime.timeName(), zPlane);
        Info<< "Written " << set->name() << " to "
            << (runTime.timeName()/lagrangianIO::cloudLocal(set->name())).c_str()
            << nl;
    }
    Info<< endl;

    Info<< "End" << nl << endl;
    return 0;
}

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "solidConstraints.H"
#include "seedRegion.H"
#include "meshSearch.H"

const Foam::Enum<Foam::meshless::solidConstraints::kind>
Foam::meshless::solidConstraints::kindNames
({
    { kind::clamped, "clamped" },
    { kind::displacement, "displacement" },
    { kind::load, "load" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::solidConstraints::solidConstraints
(
    const dictionary& bodyDict,
    particleSet& particles,
    const particleField& X0,
    const polyMesh& mesh
)
:
    index_
    (
        &particles.addScratchField
        (
            "constraintIndex",
            particleField::kind::scalar
        )
    ),
    dim_(particles.dim())
{
    const label n = particles.size();
    index_->fill(-1);

    const dictionary* dictPtr = bodyDict.findDict("constraints");
    if (!dictPtr) return;
    const dictionary& constraintsDict = *dictPtr;

    // Reference positions as points (the regions are tested there)
    pointField pts(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        for (label c = 0; c < dim_; ++c) pts[i][c] = X0(i, c);
    }
    // A 2D body lies in a plane of the mesh: test at the mesh's mid-plane
    if (dim_ == 2)
    {
        const scalar zMid = 0.5*(mesh.bounds().min().z() + mesh.bounds().max().z());
        for (point& p : pts) p.z() = zMid;
    }

    meshSearch search(mesh);
    labelList cells(n);
    forAll(pts, i)
    {
        cells[i] = search.findCell(pts[i]);
    }

    const particleField& mass = particles.field("mass");

    for (const entry& e : constraintsDict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(constraintsDict)
                << "constraints: entry '" << e.keyword()
                << "' is not a dictionary; expected"
                << " name { type clamped|displacement|load; region {...}; }"
                << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        const label c = names_.size();

        names_.append(e.keyword());
        kinds_.append(kindNames.get("type", d));
        functions_.resize(c + 1);
        if (kinds_[c] == kind::displacement)
        {
            functions_.set(c, Function1<vector>::New("displacement", d));
        }
        else if (kinds_[c] == kind::load)
        {
            functions_.set(c, Function1<vector>::New("force", d));
        }

        autoPtr<seedRegion> region
        (
            seedRegion::New(d.subDict("region"), mesh)
        );
        boolList in;
        region->inside(pts, cells, in);

        label count = 0;
        scalar m = 0;
        forAll(in, i)
        {
            if (in[i] && (*index_)(i, 0) < 0)
            {
                (*index_)(i, 0) = c;
                ++count;
                m += mass(i, 0);
            }
        }
        count_.append(count);
        setMass_.append(m);

        if (count == 0)
        {
            FatalIOErrorInFunction(d)
                << "constraint " << e.keyword() << ": no particle of body "
                << particles.name() << " lies in its region (or every one"
                << " belongs to an earlier constraint)" << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::vector Foam::meshless::solidConstraints::value
(
    const label c,
    const scalar t
) const
{
    return functions_.set(c) ? functions_[c].value(t) : vector::zero;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::solidConstraints::prescribe
(
    const scalar t,
    const particleField& X0,
    particleField& x,
    particleField& U
) const
{
    if (names_.empty()) return;

    // Displacements and their rates (central difference: Function1 has no
    // derivative; exact for the piecewise linear tables)
    const scalar dt = 1e-7;
    List<vector> d(names_.size()), v(names_.size());
    forAll(names_, c)
    {
        d[c] = value(c, t);
        v[c] = (value(c, t + dt) - value(c, max(t - dt, 0.0)))
              /(t + dt - max(t - dt, 0.0));
    }

    const label n = x.size();
    for (label i = 0; i < n; ++i)
    {
        const label c = label((*index_)(i, 0));
        if (c < 0 || kinds_[c] == kind::load) continue;
        for (label k = 0; k < dim_; ++k)
        {
            x(i, k) = X0(i, k) + d[c][k];
            U(i, k) = v[c][k];
        }
    }
}


void Foam::meshless::solidConstraints::addLoads
(
    const scalar t,
    particleField& acc
) const
{
    List<vector> a(names_.size(), Zero);
    bool any = false;
    forAll(names_, c)
    {
        if (kinds_[c] == kind::load)
        {
            a[c] = value(c, t)/setMass_[c];
            any = true;
        }
    }
    if (!any) return;

    const label n = acc.size();
    for (label i = 0; i < n; ++i)
    {
        const label c = label((*index_)(i, 0));
        if (c < 0 || kinds_[c] != kind::load) continue;
        for (label k = 0; k < dim_; ++k) acc(i, k) += a[c][k];
    }
}


void Foam::meshless::solidConstraints::describe(Ostream& os) const
{
    forAll(names_, c)
    {
        os  << "    constraint " << names_[c] << ": "
            << kindNames[kinds_[c]] << " on " << count_[c] << " particles"
            << nl;
    }
}


// ************************************************************************* //

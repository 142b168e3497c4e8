/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "solidConstraints.H"
#include "seedRegion.H"
#include "meshSearch.H"
#include "movingLeastSquares.H"
#include "solidBodyMotionFunction.H"
#include "Time.H"

const Foam::Enum<Foam::meshless::solidConstraints::kind>
Foam::meshless::solidConstraints::kindNames
({
    { kind::clamped, "clamped" },
    { kind::displacement, "displacement" },
    { kind::motion, "motion" },
    { kind::load, "load" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::solidConstraints::solidConstraints
(
    const dictionary& bodyDict,
    particleSet& particles,
    const particleField& X0,
    const polyMesh& mesh,
    const smoothingKernel* kernel
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
    dim_(particles.dim()),
    mass_(&particles.field("mass"))
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
    // A replicated solid (parallel run) is whole on every processor, each
    // holding only its part of the mesh: a region's answer for a particle
    // is that of the processor whose cells hold it (a region of cells,
    // alone or in a union, intersection or difference, differs elsewhere)
    const bool combine = Pstream::parRun() && particles.replicated();
    labelList finder(combine ? n : 0, -1);
    if (combine)
    {
        forAll(cells, i)
        {
            if (cells[i] >= 0) finder[i] = Pstream::myProcNo();
        }
        Pstream::listCombineGather(finder, maxEqOp<label>());
        Pstream::listCombineScatter(finder);
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
        motions_.resize(c + 1);
        inverseAtZero_.resize(c + 1, septernion::I);
        if (kinds_[c] == kind::motion)
        {
            if (!d.isDict("motion"))
            {
                FatalIOErrorInFunction(d)
                    << "constraint " << e.keyword() << " (type motion):"
                    << " expected a dictionary 'motion' naming a"
                    << " solidBodyMotionFunction and its coefficients"
                    << " (motion { solidBodyMotionFunction rotatingMotion;"
                    << " ... })" << exit(FatalIOError);
            }
            if (!motionTime_.valid())
            {
                // From the case's controlDict in memory: reads no file
                const Time& runTime = mesh.time();
                motionTime_.reset
                (
                    new Time
                    (
                        runTime.controlDict(), runTime.rootPath(),
                        runTime.caseName(), "system", "constant", false, false
                    )
                );
            }
            motions_.set
            (
                c,
                solidBodyMotionFunction::New(d.subDict("motion"), *motionTime_)
            );
            // (resize set it to I, so motionAt gives the raw one here)
            inverseAtZero_[c] = inv(motionAt(c, 0));
        }
        else if (kinds_[c] == kind::displacement)
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
        if (combine)
        {
            // (a particle in no processor's cells: every processor's
            // answer is the same)
            forAll(in, i)
            {
                if (finder[i] >= 0 && finder[i] != Pstream::myProcNo())
                {
                    in[i] = false;
                }
            }
            Pstream::listCombineGather(in, orEqOp<bool>());
            Pstream::listCombineScatter(in);
        }

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
                << " belongs to an earlier constraint): expected a region"
                << " holding at least one particle" << exit(FatalIOError);
        }
    }

    // Constraints on a face (once every particle's constraint is known)
    loadIndex_.setSize(names_.size());
    loadShare_.setSize(names_.size());
    label c = 0;
    for (const entry& e : constraintsDict)
    {
        const dictionary& d = e.dict();
        const dictionary* faceDict = d.findDict("face");
        if (faceDict)
        {
            if (kinds_[c] == kind::displacement || kinds_[c] == kind::motion)
            {
                FatalIOErrorInFunction(d)
                    << "constraint " << e.keyword() << ": 'face' is for"
                    << " clamped and load constraints" << exit(FatalIOError);
            }
            if (!kernel)
            {
                FatalIOErrorInFunction(d)
                    << "constraint " << e.keyword() << ": a face needs the"
                    << " body's kernel, which this model does not pass"
                    << exit(FatalIOError);
            }
            const point p0 = faceDict->get<point>("point");
            vector nf = faceDict->get<vector>("normal");
            for (label k = dim_; k < 3; ++k) nf[k] = 0;
            if (mag(nf) < SMALL)
            {
                FatalIOErrorInFunction(*faceDict)
                    << "normal " << nf << ": expected a non-zero vector"
                    << (dim_ == 2 ? " in the body's plane" : "")
                    << exit(FatalIOError);
            }
            nf /= mag(nf);
            if (kinds_[c] == kind::clamped)
            {
                mirrorClamp(c, e.keyword(), d, particles, X0, p0, nf);
            }
            else
            {
                faceLoad(c, e.keyword(), d, particles, X0, *kernel, p0, nf);
            }
        }
        ++c;
    }

    // A face load's share on a clamped image (a traction up to the clamp)
    // acts on its mirror, reversed: the image moves as minus the mirror
    if (partner_.size())
    {
        forAll(loadIndex_, l)
        {
            forAll(loadIndex_[l], k)
            {
                const label m = partner_[loadIndex_[l][k]];
                if (m < 0) continue;
                loadIndex_[l][k] = m;
                loadShare_[l][k] = -loadShare_[l][k];
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::meshless::solidConstraints::~solidConstraints()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::solidConstraints::mirrorClamp
(
    const label c,
    const word& name,
    const dictionary& d,
    const particleSet& particles,
    const particleField& X0,
    const point& p0,
    const vector& nf
)
{
    const label n = particles.size();
    const particleField& V = particles.field("volume");
    if (partner_.empty()) partner_.setSize(n, -1);

    for (label i = 0; i < n; ++i)
    {
        if (label((*index_)(i, 0)) != c) continue;

        // The mirror image of X_i across the face
        point Xi(Zero);
        for (label k = 0; k < dim_; ++k) Xi[k] = X0(i, k);
        const point Xm = Xi - 2*((Xi - p0) & nf)*nf;

        // The particle there (a lattice symmetric about the face)
        const scalar tol = 0.01*std::pow(V(i, 0), 1.0/dim_);
        label best = -1;
        scalar best2 = sqr(tol);
        for (label j = 0; j < n; ++j)
        {
            scalar r2 = 0;
            for (label k = 0; k < dim_; ++k) r2 += sqr(X0(j, k) - Xm[k]);
            if (r2 < best2)
            {
                best2 = r2;
                best = j;
            }
        }
        if (best < 0 || !isFree(best))
        {
            FatalIOErrorInFunction(d)
                << "constraint " << name << ": the mirror image " << Xm
                << " of clamped particle " << particles.ids()[i] << " at "
                << Xi << " across the face is "
                << (best < 0 ? "not a particle" : "a constrained particle")
                << " of body " << particles.name() << "; seed the body on a"
                << " lattice symmetric about the face, no deeper behind it"
                << " than the body is long" << exit(FatalIOError);
        }
        partner_[i] = best;
    }
}


void Foam::meshless::solidConstraints::faceLoad
(
    const label c,
    const word& name,
    const dictionary& d,
    const particleSet& particles,
    const particleField& X0,
    const smoothingKernel& W,
    const point& p0,
    const vector& nf
)
{
    const label n = particles.size();
    const particleField& V = particles.field("volume");
    scalarList share(n, Zero);
    DynamicList<label> index;
    DynamicList<scalar> weight;

    for (label i = 0; i < n; ++i)
    {
        if (label((*index_)(i, 0)) != c) continue;

        // The share's point of action: the projection onto the face
        point Xi(Zero);
        for (label k = 0; k < dim_; ++k) Xi[k] = X0(i, k);
        const point p = Xi - ((Xi - p0) & nf)*nf;

        if (movingLeastSquaresWeights(p, X0, V, W, dim_, index, weight) <= 0)
        {
            FatalIOErrorInFunction(d)
                << "constraint " << name << ": the particles of body "
                << particles.name() << " around the point " << p
                << " of the face do not span " << dim_ << " dimensions"
                << exit(FatalIOError);
        }
        const scalar s = (*mass_)(i, 0)/setMass_[c];
        forAll(index, k)
        {
            share[index[k]] += s*weight[k];
        }
    }

    DynamicList<label> carriers;
    DynamicList<scalar> shares;
    forAll(share, i)
    {
        if (share[i] != 0)
        {
            carriers.append(i);
            shares.append(share[i]);
        }
    }
    loadIndex_[c].transfer(carriers);
    loadShare_[c].transfer(shares);
}



Foam::vector Foam::meshless::solidConstraints::value
(
    const label c,
    const scalar t
) const
{
    return functions_.set(c) ? functions_[c].value(t) : vector::zero;
}


Foam::septernion Foam::meshless::solidConstraints::motionAt
(
    const label c,
    const scalar t
) const
{
    motionTime_->setTime(t, 0);
    return motions_[c].transformation()*inverseAtZero_[c];
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

    // Rigid motions: the transformations at t and t -/+ dm (central
    // differences of the positions give the velocities)
    const scalar dm = 1e-6;
    List<septernion> Tm(names_.size()), Tc(names_.size()), Tp(names_.size());
    forAll(names_, c)
    {
        if (kinds_[c] != kind::motion) continue;
        Tm[c] = motionAt(c, t - dm);
        Tc[c] = motionAt(c, t);
        Tp[c] = motionAt(c, t + dm);
    }

    const label n = x.size();
    for (label i = 0; i < n; ++i)
    {
        const label c = label((*index_)(i, 0));
        if (c < 0 || kinds_[c] == kind::load) continue;
        if (kinds_[c] == kind::motion)
        {
            vector p0(Zero);
            for (label k = 0; k < dim_; ++k) p0[k] = X0(i, k);
            const vector xc = Tc[c].transformPoint(p0);
            const vector v =
                (Tp[c].transformPoint(p0) - Tm[c].transformPoint(p0))/(2*dm);
            for (label k = 0; k < dim_; ++k)
            {
                x(i, k) = xc[k];
                U(i, k) = v[k];
            }
            continue;
        }
        const label j = partner_.empty() ? -1 : partner_[i];
        if (j >= 0)
        {
            // Odd extension across the clamped face
            for (label k = 0; k < dim_; ++k)
            {
                x(i, k) = X0(i, k) - (x(j, k) - X0(j, k));
                U(i, k) = -U(j, k);
            }
            continue;
        }
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
        if (kinds_[c] != kind::load) continue;
        if (loadIndex_.size() && loadIndex_[c].size())
        {
            // On a face: the shares of the carriers
            const vector F = value(c, t);
            forAll(loadIndex_[c], k)
            {
                const label i = loadIndex_[c][k];
                const scalar s = loadShare_[c][k]/(*mass_)(i, 0);
                for (label j = 0; j < dim_; ++j) acc(i, j) += s*F[j];
            }
            continue;
        }
        a[c] = value(c, t)/setMass_[c];
        any = true;
    }
    if (!any) return;

    const label n = acc.size();
    for (label i = 0; i < n; ++i)
    {
        const label c = label((*index_)(i, 0));
        if (c < 0 || kinds_[c] != kind::load) continue;
        if (loadIndex_.size() && loadIndex_[c].size()) continue;
        for (label k = 0; k < dim_; ++k) acc(i, k) += a[c][k];
    }
}


void Foam::meshless::solidConstraints::describe(Ostream& os) const
{
    forAll(names_, c)
    {
        os  << "    constraint " << names_[c] << ": "
            << kindNames[kinds_[c]] << " on " << count_[c] << " particles";
        if (kinds_[c] == kind::clamped && partner_.size())
        {
            label m = 0;
            forAll(partner_, i)
            {
                m += (partner_[i] >= 0 && label((*index_)(i, 0)) == c);
            }
            if (m) os << ", mirrored across its face";
        }
        if (loadIndex_.size() && loadIndex_[c].size())
        {
            os  << ", acting on its face through " << loadIndex_[c].size()
                << " particles";
        }
        os  << nl;
    }
}


// ************************************************************************* //

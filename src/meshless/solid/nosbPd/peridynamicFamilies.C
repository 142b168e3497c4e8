/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "peridynamicFamilies.H"
#include "lagrangianIO.H"
#include "labelPair.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include <unordered_map>

const Foam::word Foam::meshless::peridynamicFamilies::brokenBondsName
(
    "brokenBonds"
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::peridynamicFamilies::peridynamicFamilies
(
    const particleField& X0,
    const particleField& V,
    const smoothingKernel& W
)
:
    dim_(X0.nComponents())
{
    const label n = X0.size();
    cellLinkedList cells(dim_, W.radius());
    cells.build(X0.data(), n);
    bonds_.build(cells, X0.data(), n, true);

    omegaV_.resize(bonds_.nPairs());
    intact_.assign(bonds_.nPairs(), 1);
    const label* idx = bonds_.indexData();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        for (label b = begin(i); b < end(i); ++b)
        {
            const label j = idx[b];
            scalar r2 = 0;
            for (label d = 0; d < dim_; ++d)
            {
                r2 += sqr(X0(j, d) - X0(i, d));
            }
            omegaV_[b] = W.W(std::sqrt(r2))*V(j, 0);
        }
    }

    reverse_.assign(bonds_.nPairs(), -1);
    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        for (label b = begin(i); b < end(i); ++b)
        {
            const label j = idx[b];
            for (label c = begin(j); c < end(j); ++c)
            {
                if (idx[c] == i) { reverse_[b] = c; break; }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::meshless::peridynamicFamilies::nBrokenSides() const
{
    label n = 0;
    for (const char mu : intact_) n += !mu;
    return n;
}


void Foam::meshless::peridynamicFamilies::damage
(
    const particleField& V,
    particleField& phi
) const
{
    const label* idx = bonds_.indexData();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < size(); ++i)
    {
        scalar all = 0, kept = 0;
        for (label b = begin(i); b < end(i); ++b)
        {
            const scalar Vj = V(idx[b], 0);
            all += Vj;
            if (intact_[b]) kept += Vj;
        }
        phi(i, 0) = all > 0 ? 1 - kept/all : 0;
    }
}


void Foam::meshless::peridynamicFamilies::writeBroken
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName
) const
{
    const std::vector<label>& ids = set.ids();
    DynamicList<labelPair> pairs;
    for (label i = 0; i < size(); ++i)
    {
        for (label b = begin(i); b < end(i); ++b)
        {
            const label j = neighbour(b);
            if (!intact_[b] && ids[i] < ids[j])
            {
                pairs.append(labelPair(ids[i], ids[j]));
            }
        }
    }

    IOobject io
    (
        brokenBondsName,
        timeName,
        lagrangianIO::cloudLocal(set.name()),
        runTime,
        IOobject::NO_READ,
        IOobject::NO_WRITE,
        false
    );
    mkDir(io.path());
    OFstream os(io.objectPath());
    io.writeHeader(os, "labelPairList");
    os  << "// Broken bonds of the peridynamic body: particle id pairs" << nl
        << pairs << nl;
    IOobject::writeEndDivider(os);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Failed writing " << os.name() << exit(FatalError);
    }
}


Foam::label Foam::meshless::peridynamicFamilies::readBroken
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName
)
{
    const fileName path =
        runTime.path()/timeName/lagrangianIO::cloudLocal(set.name())
       /brokenBondsName;
    if (!isFile(path)) return 0;

    IFstream is(path);
    IOobject io
    (
        brokenBondsName,
        timeName,
        lagrangianIO::cloudLocal(set.name()),
        runTime
    );
    if (!io.readHeader(is))
    {
        FatalIOErrorInFunction(is)
            << "Cannot read the header of " << path << exit(FatalIOError);
    }
    const List<labelPair> pairs(is);

    std::unordered_map<label, label> index;
    const std::vector<label>& ids = set.ids();
    for (label i = 0; i < set.size(); ++i) index[ids[i]] = i;

    for (const labelPair& p : pairs)
    {
        const auto a = index.find(p.first());
        const auto c = index.find(p.second());
        bool found = false;
        if (a != index.end() && c != index.end())
        {
            const label i = a->second, j = c->second;
            for (label b = begin(i); b < end(i); ++b)
            {
                if (neighbour(b) == j) { intact_[b] = 0; found = true; }
            }
            for (label b = begin(j); b < end(j); ++b)
            {
                if (neighbour(b) == i) intact_[b] = 0;
            }
        }
        if (!found)
        {
            FatalIOErrorInFunction(is)
                << path << ": broken bond " << p << " is not a bond of body "
                << set.name() << " (no such particle ids, or farther apart"
                << " than the horizon in the reference configuration)"
                << exit(FatalIOError);
        }
    }
    return pairs.size();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "peridynamicFamilies.H"
#include "pairLoop.H"
#include "lagrangianIO.H"
#include "atomicTimeWriter.H"
#include "labelPair.H"
#include "labelFieldIOField.H"
#include "SubList.H"
#include "IOField.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include <unordered_map>
#include <cmath>

const Foam::word Foam::meshless::peridynamicFamilies::brokenBondsName
(
    "brokenBonds"
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::peridynamicFamilies::peridynamicFamilies
(
    const neighbourRelation& bonds,
    std::vector<char>& intact
)
:
    bonds_(bonds),
    intact_(intact)
{
    bonds_.require(neighbourRelation::separation, "peridynamicFamilies");
    intact_.assign(bonds_.nPairs(), 1);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::meshless::peridynamicFamilies::nBrokenSides() const
{
    label n = 0;
    for (const char mu : intact_) n += !mu;
    return n;
}


namespace
{

//- Break the intact bonds of a particle stretched to s0 (each particle
//  writes only its own row); the count per particle
struct breakTerm
{
    typedef Foam::label sum;
    const double* x;
    Foam::label dim;
    double s0;
    char* intact;
    Foam::label* broken;

    sum start(const Foam::label) const { return 0; }
    void pair
    (
        sum& n, const Foam::meshless::pairView& v, const Foam::label i,
        const Foam::label q
    ) const
    {
        if (!intact[q]) return;
        const Foam::label j = v.j[q];
        double r2 = 0;
        for (Foam::label d = 0; d < dim; ++d)
        {
            const double dx = x[j*dim + d] - x[i*dim + d];
            r2 += dx*dx;
        }
        if ((std::sqrt(r2) - v.r[q])/v.r[q] >= s0)
        {
            intact[q] = 0;
            ++n;
        }
    }
    void finish(const Foam::label i, sum& n) const { broken[i] = n; }
};


//- Volumes of all and of the intact bonds of a particle: 1 - kept/all
struct damageTerm
{
    struct sum { double all, kept; };
    const char* intact;
    double* phi;

    sum start(const Foam::label) const { return {0, 0}; }
    void pair
    (
        sum& s, const Foam::meshless::pairView& v, const Foam::label,
        const Foam::label q
    ) const
    {
        const double Vj = v.V[v.j[q]];
        s.all += Vj;
        if (intact[q]) s.kept += Vj;
    }
    void finish(const Foam::label i, sum& s) const
    {
        phi[i] = s.all > 0 ? 1 - s.kept/s.all : 0;
    }
};

} // End anonymous namespace


Foam::label Foam::meshless::peridynamicFamilies::breakBonds
(
    const double* x,
    const scalar s0
)
{
    broken_.resize(size());
    gather
    (
        bonds_, nullptr,
        breakTerm{x, bonds_.dim(), s0, intact_.data(), broken_.data()}
    );
    label n = 0;
    for (const label b : broken_) n += b;
    return n;
}


void Foam::meshless::peridynamicFamilies::damage
(
    const particleField& V,
    particleField& phi
) const
{
    gather(bonds_, V.data(), damageTerm{intact_.data(), phi.data()});
}


void Foam::meshless::peridynamicFamilies::writeBroken
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName
) const
{
    const std::vector<label>& ids = set.ids();
    List<labelField> partners(size());
    for (label i = 0; i < size(); ++i)
    {
        label nb = 0;
        for (label b = begin(i); b < end(i); ++b)
        {
            if (!intact_[b]) ++nb;
        }
        labelField& p = partners[i];
        p.setSize(nb);
        nb = 0;
        for (label b = begin(i); b < end(i); ++b)
        {
            if (!intact_[b]) p[nb++] = ids[neighbour(b)];
        }
    }

    lagrangianIO::writeLabelLists
    (
        brokenBondsName, partners, runTime, timeName, set.name()
    );
}


Foam::label Foam::meshless::peridynamicFamilies::readBroken
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName
)
{
    const fileName dir(runTime.path()/timeName/lagrangianIO::cloudLocal(set.name()));
    const fileName path(dir/brokenBondsName);
    List<labelPair> pairs;
    if (isFile(path) || isFile(path + ".gz"))
    {
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

        // (id, id) pairs: per particle of the file, its broken partners (the
        // file's particles are its cloud's, in the order of the cloud's ids);
        // the pairs of labelPairList files of earlier versions as they are
        const word& cls = io.headerClassName();
        if
        (
            cls == labelFieldIOField::typeName
         || cls == labelFieldCompactIOField::typeName
        )
        {
            // OpenFOAM's utilities write the compact form (offsets and values)
            // in binary
            List<labelField> partners;
            if (cls == labelFieldIOField::typeName)
            {
                is >> partners;
            }
            else
            {
                const labelList offsets(is);
                const labelList values(is);
                bool ok = !offsets.empty() && offsets.first() == 0
                    && offsets.last() == values.size();
                for (label k = 1; ok && k < offsets.size(); ++k)
                {
                    ok = offsets[k] >= offsets[k - 1];
                }
                if (!ok)
                {
                    FatalIOErrorInFunction(is)
                        << path << ": the offsets of its compact lists do not"
                        << " run from 0 up to its " << values.size()
                        << " values: expected " << cls << " as OpenFOAM writes"
                        << " it" << exit(FatalIOError);
                }
                partners.setSize(offsets.size() - 1);
                forAll(partners, k)
                {
                    partners[k] = SubList<label>
                    (
                        values, offsets[k + 1] - offsets[k], offsets[k]
                    );
                }
            }
            const IOField<label> fileIds
            (
                IOobject
                (
                    "id",
                    timeName,
                    lagrangianIO::cloudLocal(set.name()),
                    runTime,
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE,
                    false
                )
            );
            if (fileIds.size() != partners.size())
            {
                FatalIOErrorInFunction(is)
                    << path << " has " << partners.size() << " entries, the"
                    << " cloud's id field " << fileIds.size() << ": expected an"
                    << " entry per particle of the cloud" << exit(FatalIOError);
            }
            DynamicList<labelPair> found;
            forAll(partners, k)
            {
                for (const label j : partners[k])
                {
                    found.append(labelPair(fileIds[k], j));
                }
            }
            pairs.transfer(found);
        }
        else if (io.headerClassName() == "labelPairList")
        {
            is >> pairs;
        }
        else
        {
            FatalIOErrorInFunction(is)
                << path << " is of class " << io.headerClassName()
                << ": expected " << labelFieldIOField::typeName
                << " (per particle the ids of its broken partners)"
                << exit(FatalIOError);
        }
    }
    if (Pstream::parRun() && set.replicated())
    {
        // The solid is whole on every processor: every processor's pairs
        // (a decomposed case's files each hold those of its particles)
        List<List<labelPair>> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = pairs;
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        DynamicList<labelPair> every;
        for (const List<labelPair>& l : all) every.append(l);
        pairs.transfer(every);
    }

    std::unordered_map<label, label> index;
    const std::vector<label>& ids = set.ids();
    for (label i = 0; i < set.size(); ++i) index[ids[i]] = i;

    label nPairs = 0;
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
            FatalErrorInFunction
                << path << ": broken bond " << p << " is not a bond of body "
                << set.name() << " (no such particle ids, or farther apart"
                << " than the horizon in the reference configuration)"
                << exit(FatalError);
        }
        // Each pair once: the new files list it from both particles
        if (p.first() < p.second()) ++nPairs;
    }
    return nPairs;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleDistribution.H"
#include "haloHook.H"
#include "Pstream.H"
#include "PstreamBuffers.H"
#include "UIPstream.H"
#include "UOPstream.H"
#include "treeBoundBox.H"
#include <mpi.h>
#include <algorithm>
#include <chrono>

void (*Foam::meshless::haloHook::refresh)() = nullptr;

Foam::meshless::particleDistribution*
Foam::meshless::particleDistribution::active_ = nullptr;


namespace
{

//- Adds the seconds of its lifetime to a total
struct timed
{
    double& total;
    const std::chrono::steady_clock::time_point start =
        std::chrono::steady_clock::now();

    ~timed()
    {
        total += std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - start
        ).count();
    }
};


//- Send the particles which of set (ids and every field) on os
void sendParticles
(
    Foam::UOPstream& os,
    Foam::meshless::particleSet& set,
    const std::vector<Foam::label>& which
)
{
    using namespace Foam;
    labelList ids(label(which.size()));
    forAll(ids, k) ids[k] = set.ids()[which[k]];
    os << ids;
    set.forEachField([&](const meshless::particleField& f)
    {
        const label nc = f.nComponents();
        scalarList d(ids.size()*nc);
        forAll(ids, k)
        {
            for (label c = 0; c < nc; ++c) d[k*nc + c] = f(which[k], c);
        }
        os << d;
    });
}


//- Append the particles processor q sent (sendParticles) to set
void receiveParticles
(
    Foam::UIPstream& is,
    Foam::meshless::particleSet& set,
    const Foam::label q
)
{
    using namespace Foam;
    labelList ids(is);
    const label n0 = set.appendIds(ids.cdata(), ids.size());
    set.forEachField([&](meshless::particleField& f)
    {
        const label nc = f.nComponents();
        scalarList d(is);
        if (d.size() != ids.size()*nc)
        {
            FatalErrorInFunction
                << "Body " << set.name() << ", field " << f.name()
                << ": processor " << q << " sent " << d.size()
                << " values for " << ids.size() << " particles,"
                << " expected " << nc << " each (the processors'"
                << " bodies have other fields)" << abort(FatalError);
        }
        std::copy(d.cbegin(), d.cend(), f.data() + size_t(n0)*nc);
    });
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::particleDistribution::refreshActive()
{
    if (active_) active_->refresh();
}


void Foam::meshless::particleDistribution::deactivate()
{
    if (active_ == this)
    {
        active_ = nullptr;
        haloHook::refresh = nullptr;
    }
}


Foam::point Foam::meshless::particleDistribution::position
(
    const particleField& x,
    const label i
) const
{
    point p(0, 0, zPlane_);
    for (label d = 0; d < dim_; ++d) p[d] = x(i, d);
    return p;
}


Foam::scalar Foam::meshless::particleDistribution::distSqr
(
    const double* p,
    const boundBox& b
) const
{
    scalar s = 0;
    for (label d = 0; d < dim_; ++d)
    {
        auto gap = [&](const scalar x)
        {
            return Foam::max
            (
                Foam::max(b.min()[d] - x, x - b.max()[d]), scalar(0)
            );
        };
        scalar e = gap(p[d]);
        if (periodic_.periodic(d))
        {
            const scalar L = periodic_.length(d);
            e = Foam::min(e, Foam::min(gap(p[d] + L), gap(p[d] - L)));
        }
        s += e*e;
    }
    return s;
}


Foam::boundBox Foam::meshless::particleDistribution::ownBox() const
{
    boundBox box(boundBox::invertedBox);
    for (const particleSet* set : sets_)
    {
        const particleField& x = set->positions();
        for (label i = 0; i < set->size(); ++i)
        {
            if (set->owns(i)) box.add(position(x, i));
        }
    }
    return box;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::particleDistribution::particleDistribution
(
    const polyMesh& mesh,
    const label dim,
    const scalar zPlane,
    const scalar radius,
    const std::vector<particleSet*>& sets
)
:
    mesh_(mesh),
    dim_(dim),
    zPlane_(zPlane),
    radius_(radius),
    sets_(sets),
    attached_(false),
    sendBuf_(Pstream::nProcs()),
    recvBuf_(Pstream::nProcs()),
    refreshes_(0),
    refreshSeconds_(0),
    migrateSeconds_(0),
    startSeconds_(0),
    attachSeconds_(0),
    valuesSent_(0),
    attachments_(0),
    haloSum_(0),
    ownSum_(0)
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();

    // The largest cell (its longest edge in the solution plane)
    scalar edge = 0;
    const pointField& pts = mesh.points();
    for (const Foam::edge& e : mesh.edges())
    {
        vector d = e.vec(pts);
        if (dim_ == 2) d.z() = 0;
        edge = Foam::max(edge, mag(d));
    }
    reduce(edge, maxOp<scalar>());

    // Every processor's part (its own points: polyMesh::bounds() is the
    // whole mesh's, reduced over the processors)
    List<boundBox> parts(nProcs);
    parts[me] = boundBox(mesh.points(), false);
    Pstream::gatherList(parts);
    Pstream::scatterList(parts);

    // A particle moves less than a cell and a halo width per step: the
    // centres of another processor's cells within a few cells of this part
    // decide where a particle that leaves it goes
    const scalar margin = 4*edge + 2*radius_;
    const pointField& cc = mesh.cellCentres();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label q = 0; q < nProcs; ++q)
    {
        if (q == me) continue;
        DynamicList<point> near;
        for (const point& c : cc)
        {
            if (distSqr(c.v_, parts[q]) < sqr(margin)) near.append(c);
        }
        UOPstream os(q, pBufs);
        os << pointField(near);
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    DynamicList<point> centres(cc);
    DynamicList<label> procs(labelList(cc.size(), me));
    for (label q = 0; q < nProcs; ++q)
    {
        if (q == me || !recvSizes[q]) continue;
        UIPstream is(q, pBufs);
        pointField theirs(is);
        centres.append(theirs);
        procs.append(labelList(theirs.size(), q));
    }
    centres_.transfer(centres);
    centreProc_.transfer(procs);

    treeBoundBox bb(centres_);
    bb.inflate(1e-4);
    tree_.reset
    (
        new indexedOctree<treeDataPoint>
        (
            treeDataPoint(centres_), bb, 8, 10.0, 3.0
        )
    );

    makeBins(0.5*edge);

    // Own centres: a replicated body's particle within a few cells of this
    // part may be this processor's
    ownCentres_ = cc;
    ownReach_ = mesh.bounds();
    ownReach_.min() -= vector::uniform(margin);
    ownReach_.max() += vector::uniform(margin);
    if (cc.size())
    {
        treeBoundBox own(ownCentres_);
        own.inflate(1e-4);
        ownTree_.reset
        (
            new indexedOctree<treeDataPoint>
            (
                treeDataPoint(ownCentres_), own, 8, 10.0, 3.0
            )
        );
    }

    halos_.resize(sets_.size());
    width_.resize(sets_.size());
    for (halo& h : halos_)
    {
        h.send.resize(nProcs);
        h.recvStart.assign(nProcs, 0);
        h.recvCount.assign(nProcs, 0);
        h.recvIndex.resize(nProcs);
    }
}


Foam::meshless::particleDistribution::~particleDistribution()
{
    deactivate();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::particleDistribution::makeBins(const scalar binSize)
{
    binSize_ = binSize > 0 ? binSize : 1;
    boundBox bb(centres_);
    binOrigin_ = bb.min();
    label n = 1;
    for (label d = 0; d < 3; ++d)
    {
        binCount_[d] =
            d < dim_ ? label(std::floor(bb.span()[d]/binSize_)) + 1 : 1;
        n *= binCount_[d];
    }
    binOwner_.clear();
    binStart_.clear();
    binCandidates_.clear();
    if (n > 32*centres_.size() + 1000)
    {
        // A few large cells among many small ones: the octree alone
        return;
    }
    binOwner_.assign(n, -1);
    binStart_.assign(n + 1, 0);

    // Any point of a bin is within r of its centre: its nearest cell
    // centre is within d0 + 2r of the bin's centre (d0: the bin centre's
    // nearest)
    const scalar r = 0.5*binSize_*std::sqrt(scalar(dim_));
    for (label k = 0; k < binCount_[2]; ++k)
    {
        for (label j = 0; j < binCount_[1]; ++j)
        {
            for (label i = 0; i < binCount_[0]; ++i)
            {
                point b(binOrigin_);
                b.x() += (i + 0.5)*binSize_;
                b.y() += (j + 0.5)*binSize_;
                if (dim_ == 3) b.z() += (k + 0.5)*binSize_;
                else b.z() = zPlane_;
                const label bin = i + binCount_[0]*(j + binCount_[1]*k);
                const pointIndexHit hit = tree_->findNearest(b, GREAT);
                if (hit.hit())
                {
                    const scalar d0 = mag(hit.hitPoint() - b);
                    labelList near(tree_->findSphere(b, sqr(d0 + 2*r)));
                    const label p = centreProc_[hit.index()];
                    bool pure = true;
                    for (const label c : near)
                    {
                        pure = pure && centreProc_[c] == p;
                    }
                    if (pure)
                    {
                        binOwner_[bin] = p;
                    }
                    else
                    {
                        // The few centres one of which is nearest
                        Foam::sort(near);
                        binCandidates_.insert
                        (
                            binCandidates_.end(), near.begin(), near.end()
                        );
                    }
                }
                binStart_[bin + 1] = label(binCandidates_.size());
            }
        }
    }
}


Foam::label Foam::meshless::particleDistribution::owner(const point& p) const
{
    if (!binOwner_.empty())
    {
        label idx[3] = {0, 0, 0};
        bool inside = true;
        for (label d = 0; d < dim_; ++d)
        {
            const scalar s = (p[d] - binOrigin_[d])/binSize_;
            inside = inside && s >= 0 && s < binCount_[d];
            idx[d] = inside ? label(s) : 0;
        }
        if (inside)
        {
            const label bin =
                idx[0] + binCount_[0]*(idx[1] + binCount_[1]*idx[2]);
            if (binOwner_[bin] >= 0) return binOwner_[bin];
            const label c0 = binStart_[bin];
            const label c1 = binStart_[bin + 1];
            if (c1 > c0)
            {
                label best = binCandidates_[c0];
                scalar bestD = magSqr(centres_[best] - p);
                for (label c = c0 + 1; c < c1; ++c)
                {
                    const scalar d = magSqr(centres_[binCandidates_[c]] - p);
                    if (d < bestD)
                    {
                        bestD = d;
                        best = binCandidates_[c];
                    }
                }
                return centreProc_[best];
            }
        }
    }
    const pointIndexHit hit = tree_->findNearest(p, GREAT);
    return hit.hit() ? centreProc_[hit.index()] : Pstream::myProcNo();
}


Foam::label Foam::meshless::particleDistribution::migrate
(
    const std::vector<bool>& move
)
{
    if (attached_)
    {
        FatalErrorInFunction
            << "Migration with the halos attached" << abort(FatalError);
    }
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    const timed clock{attachments_ ? migrateSeconds_ : startSeconds_};

    // Who goes where, per body
    std::vector<std::vector<std::vector<label>>> leaving(sets_.size());
    label nSent = 0;
    for (label b = 0; b < label(sets_.size()); ++b)
    {
        leaving[b].resize(nProcs);
        if (!move[b] || sets_[b]->replicated()) continue;
        particleSet& set = *sets_[b];
        const label n = set.size();
        const particleField& x = set.positions();
        owner_.resize(n);
        label* own = owner_.data();
        #pragma omp parallel for schedule(static) if (n > 256)
        for (label i = 0; i < n; ++i) own[i] = owner(position(x, i));
        for (label i = 0; i < n; ++i)
        {
            if (own[i] != me)
            {
                leaving[b][own[i]].push_back(i);
                ++nSent;
            }
        }
    }
    if (!returnReduce(nSent, sumOp<label>())) return 0;

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label q = 0; q < nProcs; ++q)
    {
        bool any = false;
        for (label b = 0; b < label(sets_.size()); ++b) any = any || !leaving[b][q].empty();
        if (!any) continue;
        UOPstream os(q, pBufs);
        for (label b = 0; b < label(sets_.size()); ++b)
        {
            sendParticles(os, *sets_[b], leaving[b][q]);
        }
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    for (label b = 0; b < label(sets_.size()); ++b)
    {
        std::vector<label> gone;
        for (const std::vector<label>& go : leaving[b])
        {
            gone.insert(gone.end(), go.begin(), go.end());
        }
        std::sort(gone.begin(), gone.end());
        sets_[b]->removeUnordered(gone);
    }

    for (label q = 0; q < nProcs; ++q)
    {
        if (q == me || !recvSizes[q]) continue;
        UIPstream is(q, pBufs);
        for (label b = 0; b < label(sets_.size()); ++b)
        {
            receiveParticles(is, *sets_[b], q);
        }
    }
    return nSent;
}


void Foam::meshless::particleDistribution::attachHalos()
{
    if (attached_) detachHalos();
    {
        const timed clock{attachSeconds_};
        appendHalos();
    }
    refresh();
}


void Foam::meshless::particleDistribution::appendHalos()
{
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();

    locateReplicated();
    List<boundBox> boxes(nProcs);
    boxes[me] = ownBox();
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);

    // The processors whose particles may be within reach of this one's
    const scalar R2 = sqr(radius_);
    DynamicList<label> near;
    if (boxes[me].valid())
    {
        boundBox reach(boxes[me]);
        reach.min() -= vector::uniform(radius_);
        reach.max() += vector::uniform(radius_);
        for (label q = 0; q < nProcs; ++q)
        {
            if (q == me || !boxes[q].valid()) continue;
            // Across a periodic direction any processor may be near
            if (periodic_.any() || reach.overlaps(boxes[q])) near.append(q);
        }
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label b = 0; b < label(sets_.size()); ++b)
    {
        halo& h = halos_[b];
        particleSet& set = *sets_[b];
        const bool whole = set.replicated();
        if (!whole) set.markHalo();
        for (std::vector<label>& s : h.send) s.clear();
        const particleField& x = set.positions();
        for (label i = 0; i < set.nOwned(); ++i)
        {
            if (whole && !set.owns(i)) continue;
            const double* p = x.data() + size_t(i)*x.nComponents();
            for (const label q : near)
            {
                if (distSqr(p, boxes[q]) < R2) h.send[q].push_back(i);
            }
        }
    }
    for (const label q : near)
    {
        bool any = false;
        for (label b = 0; b < label(sets_.size()); ++b) any = any || !halos_[b].send[q].empty();
        if (!any) continue;
        UOPstream os(q, pBufs);
        for (label b = 0; b < label(sets_.size()); ++b)
        {
            const std::vector<label>& s = halos_[b].send[q];
            labelList ids(label(s.size()));
            forAll(ids, k) ids[k] = sets_[b]->ids()[s[k]];
            os << ids;
        }
    }
    labelList recvSizes;
    pBufs.finishedSends(recvSizes);

    for (label q = 0; q < nProcs; ++q)
    {
        const bool from = q != me && recvSizes[q];
        autoPtr<UIPstream> is;
        if (from) is.reset(new UIPstream(q, pBufs));
        for (label b = 0; b < label(sets_.size()); ++b)
        {
            halo& h = halos_[b];
            particleSet& set = *sets_[b];
            h.recvStart[q] = set.size();
            h.recvCount[q] = 0;
            h.recvIndex[q].clear();
            if (!from) continue;
            labelList ids(is());
            h.recvCount[q] = ids.size();
            if (!set.replicated())
            {
                set.appendIds(ids.cdata(), ids.size());
                continue;
            }
            // Refreshed in place: the set is in the order of its ids
            const std::vector<label>& all = set.ids();
            for (const label id : ids)
            {
                auto it = std::lower_bound(all.begin(), all.end(), id);
                if (it == all.end() || *it != id)
                {
                    FatalErrorInFunction
                        << "Body " << set.name() << ": processor " << q
                        << " refreshes particle id " << id << ", which"
                        << " this processor's copy does not hold in the"
                        << " order of the ids" << abort(FatalError);
                }
                h.recvIndex[q].push_back(label(it - all.begin()));
            }
        }
    }

    ++attachments_;
    for (const particleSet* set : sets_)
    {
        haloSum_ += set->size() - set->nOwned();
        ownSum_ += set->nOwned();
    }

    attached_ = true;
    active_ = this;
    haloHook::refresh = &refreshActive;
}


void Foam::meshless::particleDistribution::refresh()
{
    if (!attached_) return;
    ++refreshes_;
    const timed clock{refreshSeconds_};
    const label nProcs = Pstream::nProcs();
    const int tag = UPstream::msgType() + 1;

    // Values per particle, over every field of each body
    std::vector<label>& width = width_;
    for (label b = 0; b < label(sets_.size()); ++b)
    {
        width[b] = 0;
        sets_[b]->forEachField
        (
            [&](const particleField& f) { width[b] += f.nComponents(); }
        );
    }

    const label start = UPstream::nRequests();
    for (label q = 0; q < nProcs; ++q)
    {
        label n = 0;
        for (label b = 0; b < label(sets_.size()); ++b) n += halos_[b].recvCount[q]*width[b];
        if (!n) continue;
        std::vector<double>& buf = recvBuf_[q];
        if (label(buf.size()) < n) buf.resize(n);
        UIPstream::read
        (
            Pstream::commsTypes::nonBlocking, q,
            reinterpret_cast<char*>(buf.data()), n*sizeof(double), tag,
            UPstream::worldComm
        );
    }
    for (label q = 0; q < nProcs; ++q)
    {
        label n = 0;
        for (label b = 0; b < label(sets_.size()); ++b) n += label(halos_[b].send[q].size())*width[b];
        if (!n) continue;
        std::vector<double>& buf = sendBuf_[q];
        if (label(buf.size()) < n) buf.resize(n);
        double* out = buf.data();
        for (label b = 0; b < label(sets_.size()); ++b)
        {
            const std::vector<label>& s = halos_[b].send[q];
            sets_[b]->forEachField([&](const particleField& f)
            {
                const label nc = f.nComponents();
                const double* d = f.data();
                for (const label i : s)
                {
                    for (label c = 0; c < nc; ++c) *out++ = d[i*nc + c];
                }
            });
        }
        valuesSent_ += n;
        UOPstream::write
        (
            Pstream::commsTypes::nonBlocking, q,
            reinterpret_cast<const char*>(buf.data()), n*sizeof(double),
            tag, UPstream::worldComm
        );
    }
    UPstream::waitRequests(start);

    for (label q = 0; q < nProcs; ++q)
    {
        const double* in = recvBuf_[q].data();
        for (label b = 0; b < label(sets_.size()); ++b)
        {
            const label n = halos_[b].recvCount[q];
            if (!n) continue;
            if (sets_[b]->replicated())
            {
                const std::vector<label>& idx = halos_[b].recvIndex[q];
                sets_[b]->forEachField([&](particleField& f)
                {
                    const label nc = f.nComponents();
                    double* d = f.data();
                    for (const label i : idx)
                    {
                        for (label c = 0; c < nc; ++c) d[i*nc + c] = *in++;
                    }
                });
                continue;
            }
            const label i0 = halos_[b].recvStart[q];
            sets_[b]->forEachField([&](particleField& f)
            {
                const label nc = f.nComponents();
                double* d = f.data() + size_t(i0)*nc;
                for (label k = 0; k < n*nc; ++k) d[k] = *in++;
            });
        }
    }
}


void Foam::meshless::particleDistribution::locateReplicated()
{
    const int me = Pstream::myProcNo();
    for (particleSet* set : sets_)
    {
        if (!set->replicated()) continue;
        const label n = set->size();
        const particleField& x = set->positions();
        nearest_.resize(n);
        distanceRank* near = nearest_.data();
        const bool any = ownTree_.valid();
        #pragma omp parallel for schedule(static) if (n > 256)
        for (label i = 0; i < n; ++i)
        {
            const point p = position(x, i);
            near[i] = {GREAT, me};
            if (any && ownReach_.contains(p))
            {
                const pointIndexHit hit = ownTree_->findNearest(p, GREAT);
                if (hit.hit()) near[i].d = magSqr(hit.hitPoint() - p);
            }
        }
        // The nearest over the processors; a tie goes to the lowest
        MPI_Allreduce
        (
            MPI_IN_PLACE, near, int(n), MPI_DOUBLE_INT, MPI_MINLOC,
            MPI_COMM_WORLD
        );
        std::vector<char>& own = set->ownMask();
        own.resize(n);
        for (label i = 0; i < n; ++i) own[i] = (near[i].rank == me);
    }
}


void Foam::meshless::particleDistribution::replicate(particleSet& set)
{
    set.setReplicated();
    set.ownMask().assign(set.size(), 1);
    if (!Pstream::parRun()) return;
    const label nProcs = Pstream::nProcs();
    const label me = Pstream::myProcNo();

    // Every processor's particles to every other
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    std::vector<label> all(set.size());
    for (label i = 0; i < set.size(); ++i) all[i] = i;
    for (label q = 0; q < nProcs; ++q)
    {
        if (q == me) continue;
        UOPstream os(q, pBufs);
        sendParticles(os, set, all);
    }
    pBufs.finishedSends();
    for (label q = 0; q < nProcs; ++q)
    {
        if (q == me) continue;
        UIPstream is(q, pBufs);
        receiveParticles(is, set, q);
    }

    // In the order of the ids: the same on every processor (and the
    // serial run's order of a set that never lost a particle)
    const std::vector<label>& ids = set.ids();
    std::vector<label> order(set.size());
    for (label i = 0; i < set.size(); ++i) order[i] = i;
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](const label a, const label b) { return ids[a] < ids[b]; }
    );
    set.reorder(order);
    for (label i = 1; i < set.size(); ++i)
    {
        if (set.ids()[i] == set.ids()[i - 1])
        {
            FatalErrorInFunction
                << "Body " << set.name() << ": particle id "
                << set.ids()[i] << " is held by two processors"
                << abort(FatalError);
        }
    }
    if (set.size())
    {
        set.setNextId(Foam::max(set.nextId(), set.ids().back() + 1));
    }
    set.ownMask().assign(set.size(), 0);
}


void Foam::meshless::particleDistribution::share
(
    particleSet& set,
    particleField& f
)
{
    share(set, f.data(), f.nComponents());
}


void Foam::meshless::particleDistribution::share
(
    const particleSet& set,
    double* d,
    const label nc
)
{
    if (!Pstream::parRun() || !set.replicated()) return;
    const label n = set.size();
    for (label i = 0; i < n; ++i)
    {
        if (set.owns(i)) continue;
        for (label c = 0; c < nc; ++c) d[i*nc + c] = 0;
    }
    // Each value has one owner: the sum is its value exactly
    MPI_Allreduce
    (
        MPI_IN_PLACE, d, int(n*nc), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD
    );
}


void Foam::meshless::particleDistribution::shareAll(particleSet& set)
{
    if (!Pstream::parRun() || !set.replicated()) return;
    set.forEachField([&](particleField& f) { share(set, f); });
}


Foam::label Foam::meshless::particleDistribution::globalSize
(
    const particleSet& set
)
{
    return set.replicated()
        ? set.size()
        : returnReduce(set.size(), sumOp<label>());
}


Foam::scalar Foam::meshless::particleDistribution::globalSum
(
    const particleSet& set,
    const scalar local
)
{
    return set.replicated() ? local : returnReduce(local, sumOp<scalar>());
}


void Foam::meshless::particleDistribution::runCost(dictionary& d) const
{
    d.add("processors", label(Pstream::nProcs()));
    d.add("haloWidth", radius_);
    d.add("attachments", attachments_);
    d.add("haloParticles", returnReduce(haloSum_, sumOp<double>()));
    d.add("ownParticles", returnReduce(ownSum_, sumOp<double>()));
    d.add("refreshes", refreshes_);
    d.add("refreshSeconds", refreshSeconds_);
    d.add("migrateSeconds", migrateSeconds_);
    d.add("startMigrateSeconds", startSeconds_);
    d.add("attachSeconds", attachSeconds_);
    d.add("valuesSent", valuesSent_);
}


void Foam::meshless::particleDistribution::detachHalos()
{
    if (!attached_) return;
    for (particleSet* set : sets_) set->truncate(set->nOwned());
    attached_ = false;
    deactivate();
}


// ************************************************************************* //

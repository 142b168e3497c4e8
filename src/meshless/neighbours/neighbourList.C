/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include "dispatchDim.H"
#include <algorithm>

#ifdef _OPENMP
#include <omp.h>
#endif

template<int Dim, bool Periodic>
void Foam::meshless::neighbourList::queryChunk
(
    const cellLinkedList& cellsB,
    const double* xA,
    const label i0,
    const label i1,
    const bool excludeSelf,
    std::vector<label>& buf,
    size_t& used
)
{
    const double r2max = cellsB.radius()*cellsB.radius();
    const label* sorted = cellsB.sortedData();
    const double* xB = cellsB.points();
    const periodicBox& box = cellsB.periodic();

    for (label i = i0; i < i1; ++i)
    {
        const double* p = xA + size_t(i)*Dim;
        const label skip = excludeSelf ? i : -1;
        const size_t before = used;

        auto row = [&](const label k0, const label k1)
        {
            // Room for every candidate, then a branch-free compaction: the
            // accept test is ~40 % true, a branch there mispredicts a lot
            if (buf.size() < used + (k1 - k0))
            {
                buf.resize(2*(used + (k1 - k0)));
            }
            label* out = buf.data() + used;
            for (label k = k0; k < k1; ++k)
            {
                const label j = sorted[k];
                double r2;
                if (Periodic)
                {
                    // Minimum image: the query visits the cells across
                    // the period, the pair's distance is that of its
                    // nearest image
                    const double* q = xB + size_t(j)*Dim;
                    double dx[Dim];
                    for (int d = 0; d < Dim; ++d) dx[d] = q[d] - p[d];
                    box.minimumImage<Dim>(dx);
                    r2 = 0;
                    for (int d = 0; d < Dim; ++d) r2 += dx[d]*dx[d];
                }
                else
                {
                    r2 = distanceSqr<Dim>(p, xB + size_t(j)*Dim);
                }
                *out = j;
                out += (r2 <= r2max) & (j != skip);
            }
            used = out - buf.data();
        };
        cellsB.forEachRowImpl<Dim, Periodic>(p, row);

        // Row length for now; turned into offsets by build
        offset_[i + 1] = label(used - before);
    }
}


Foam::meshless::neighbourList::neighbourList()
:
    size_(0),
    offset_(1, 0),
    index_(),
    threadIndex_(),
    threadStart_()
{}


void Foam::meshless::neighbourList::build
(
    const cellLinkedList& cellsB,
    const double* xA,
    const label nA,
    const bool excludeSelf
)
{
    const label dim = cellsB.dim();
    size_ = nA;
    offset_.resize(nA + 1);
    offset_[0] = 0;

    #ifdef _OPENMP
    const label nThreads = omp_get_max_threads();
    #else
    const label nThreads = 1;
    #endif
    if (label(threadIndex_.size()) < nThreads)
    {
        threadIndex_.resize(nThreads);
    }
    threadStart_.resize(nThreads + 1);

    #pragma omp parallel num_threads(nThreads)
    {
        #ifdef _OPENMP
        const label t = omp_get_thread_num();
        const label nt = omp_get_num_threads();
        #else
        const label t = 0;
        const label nt = 1;
        #endif

        // Fixed contiguous chunk of A for this thread
        const label i0 = label(static_cast<long long>(nA)*t/nt);
        const label i1 = label(static_cast<long long>(nA)*(t + 1)/nt);

        std::vector<label>& buf = threadIndex_[t];
        size_t used = 0;

        const bool periodic = cellsB.periodic().any();
        dispatchDim(dim, [&](auto d)
        {
            if (periodic)
            {
                queryChunk<d, true>(cellsB, xA, i0, i1, excludeSelf, buf, used);
            }
            else
            {
                queryChunk<d, false>(cellsB, xA, i0, i1, excludeSelf, buf, used);
            }
        });
        threadStart_[t + 1] = label(used);

        #pragma omp barrier
        #pragma omp single
        {
            threadStart_[0] = 0;
            for (label k = 0; k < nt; ++k)
            {
                threadStart_[k + 1] += threadStart_[k];
            }
            // Grow with headroom so that a slowly rising pair count (a
            // compressing flow) does not reallocate every step
            const size_t nPairs = threadStart_[nt];
            if (index_.capacity() < nPairs)
            {
                index_.reserve(nPairs + nPairs/8);
            }
            index_.resize(nPairs);
        }

        // Offsets of this chunk, then its neighbours into place
        label run = threadStart_[t];
        for (label i = i0; i < i1; ++i)
        {
            run += offset_[i + 1];
            offset_[i + 1] = run;
        }
        std::copy(buf.begin(), buf.begin() + used, index_.begin() + threadStart_[t]);
    }
}

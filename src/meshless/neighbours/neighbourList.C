/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include <algorithm>

#ifdef _OPENMP
#include <omp.h>
#endif

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
        const label i0 = label((long long)nA*t/nt);
        const label i1 = label((long long)nA*(t + 1)/nt);

        std::vector<label>& buf = threadIndex_[t];
        buf.clear();

        for (label i = i0; i < i1; ++i)
        {
            const label before = label(buf.size());
            cellsB.forEachNeighbour
            (
                xA + size_t(i)*dim,
                [&](const label j, const double)
                {
                    if (!excludeSelf || j != i) buf.push_back(j);
                }
            );
            // Row length for now; turned into offsets below
            offset_[i + 1] = label(buf.size()) - before;
        }
        threadStart_[t + 1] = label(buf.size());

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
        std::copy(buf.begin(), buf.end(), index_.begin() + threadStart_[t]);
    }
}

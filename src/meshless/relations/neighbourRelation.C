/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "neighbourRelation.H"
#include "dispatchDim.H"
#include "error.H"
#include <cmath>

Foam::meshless::neighbourRelation::neighbourRelation
(
    const word& name,
    const particleField& xA,
    const particleField& xB,
    const bool inner,
    const smoothingKernel& W,
    const cellLinkedList& cellsB,
    const unsigned geometry,
    const bool isStatic
)
:
    name_(name),
    xA_(xA),
    xB_(xB),
    inner_(inner),
    W_(W),
    cellsB_(cellsB),
    static_(isStatic),
    cached_(geometry),
    list_(),
    builds_(0),
    stamp_(-1)
{
    if (xA.nComponents() != xB.nComponents())
    {
        FatalErrorInFunction
            << "Relation " << name << ": points of dimension "
            << xA.nComponents() << " and " << xB.nComponents()
            << exit(FatalError);
    }
    if ((geometry & reversePairs) && !inner)
    {
        FatalErrorInFunction
            << "Relation " << name << ": reverse pairs need an inner relation"
            << exit(FatalError);
    }
}


void Foam::meshless::neighbourRelation::cache(const unsigned geometry)
{
    if ((geometry & reversePairs) && !inner_)
    {
        FatalErrorInFunction
            << "Relation " << name_ << ": reverse pairs need an inner relation"
            << exit(FatalError);
    }
    cached_ |= geometry;
}


template<int Dim, bool Periodic>
void Foam::meshless::neighbourRelation::geometryImpl()
{
    const label n = list_.size();
    const label np = list_.nPairs();
    const double* x = xA_.data();
    const double* y = xB_.data();
    const label* off = list_.offsetData();
    const label* idx = list_.indexData();
    const smoothingKernel& W = W_;
    const periodicBox& box = cellsB_.periodic();

    const bool sep = cached_ & separation;
    const bool val = cached_ & kernelValue;
    const bool grad = cached_ & kernelGradient;
    if (sep) { xij_.resize(size_t(np)*Dim); r_.resize(np); }
    else rWork_.resize(np);
    if (val) w_.resize(np);
    if (grad) dw_.resize(np);
    double* d = xij_.data();
    double* r = sep ? r_.data() : rWork_.data();
    double* w = val ? w_.data() : nullptr;
    double* dw = grad ? dw_.data() : nullptr;

    #pragma omp parallel for schedule(static) if (n > 64)
    for (label i = 0; i < n; ++i)
    {
        const double* xi = x + size_t(i)*Dim;
        for (label q = off[i]; q < off[i + 1]; ++q)
        {
            const double* yj = y + size_t(idx[q])*Dim;
            double s = 0;
            double dq[Dim];
            if (Periodic)
            {
                // Minimum image, also for points moved slightly out of the
                // box since the build
                for (int c = 0; c < Dim; ++c) dq[c] = yj[c] - xi[c];
                box.minimumImage<Dim>(dq);
                for (int c = 0; c < Dim; ++c) s += dq[c]*dq[c];
            }
            else
            {
                for (int c = 0; c < Dim; ++c)
                {
                    dq[c] = yj[c] - xi[c];
                    s += dq[c]*dq[c];
                }
            }
            r[q] = std::sqrt(s);
            if (sep)
            {
                for (int c = 0; c < Dim; ++c) d[size_t(q)*Dim + c] = dq[c];
            }
        }
        if (val || grad)
        {
            const label p = off[i];
            W.evaluate
            (
                r + p, off[i + 1] - p, w ? w + p : nullptr,
                dw ? dw + p : nullptr
            );
        }
    }
}


void Foam::meshless::neighbourRelation::computeReverse()
{
    const label n = list_.size();
    const label* off = list_.offsetData();
    const label* idx = list_.indexData();
    reverse_.assign(list_.nPairs(), -1);
    label* rev = reverse_.data();

    #pragma omp parallel for schedule(static)
    for (label a = 0; a < n; ++a)
    {
        for (label p = off[a]; p < off[a + 1]; ++p)
        {
            const label b = idx[p];
            for (label q = off[b]; q < off[b + 1]; ++q)
            {
                if (idx[q] == a)
                {
                    rev[p] = q;
                    break;
                }
            }
        }
    }
}


void Foam::meshless::neighbourRelation::require
(
    const unsigned geometry,
    const char* user
) const
{
    if ((cached_ & geometry) != geometry)
    {
        FatalErrorInFunction
            << "Relation " << name_ << " caches geometry " << cached_
            << ": " << user << " expected it to cache " << geometry
            << " (see neighbourRelation::geometry)" << abort(FatalError);
    }
}


void Foam::meshless::neighbourRelation::build()
{
    list_.build(cellsB_, xA_.data(), xA_.size(), inner_);
    if (cached_ & reversePairs) computeReverse();
    updateGeometry();
    ++builds_;
}


void Foam::meshless::neighbourRelation::update(const label stamp)
{
    if (builds_ > 0 && (static_ || stamp == stamp_)) return;
    build();
    stamp_ = stamp;
}


void Foam::meshless::neighbourRelation::updateGeometry()
{
    if (!(cached_ & (separation | kernelValue | kernelGradient))) return;
    const bool periodic = cellsB_.periodic().any();
    dispatchDim(dim(), [&](auto d)
    {
        if (periodic) geometryImpl<d, true>();
        else geometryImpl<d, false>();
    });
}


// ************************************************************************* //

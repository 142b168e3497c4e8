/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleField.H"
#include "error.H"
#include <algorithm>
#include <cmath>

const Foam::Enum<Foam::meshless::particleField::kind>
Foam::meshless::particleField::kindNames
({
    { kind::scalar, "scalar" },
    { kind::vector, "vector" },
    { kind::tensor, "tensor" },
});


Foam::label Foam::meshless::particleField::nComponents
(
    const kind k,
    const label dim
)
{
    switch (k)
    {
        case kind::scalar: return 1;
        case kind::vector: return dim;
        case kind::tensor: return dim*dim;
    }
    return 1;
}


Foam::meshless::particleField::particleField
(
    const word& name,
    const kind k,
    const label dim,
    const bool written
)
:
    name_(name),
    kind_(k),
    nCmpt_(nComponents(k, dim)),
    data_(),
    written_(written)
{}


void Foam::meshless::particleField::resize(const label n)
{
    data_.resize(size_t(n)*nCmpt_, 0.0);
}


void Foam::meshless::particleField::fill(const double v)
{
    std::fill(data_.begin(), data_.end(), v);
}


double Foam::meshless::particleField::maxMagnitude() const
{
    const label n = size();
    const label nc = nCmpt_;
    const double* v = data_.data();
    double max2 = 0;

    #pragma omp parallel for reduction(max:max2)
    for (label i = 0; i < n; ++i)
    {
        double m2 = 0;
        for (label c = 0; c < nc; ++c) m2 += v[i*nc + c]*v[i*nc + c];
        max2 = std::max(max2, m2);
    }
    return std::sqrt(max2);
}


void Foam::meshless::particleField::reorder
(
    const std::vector<label>& order,
    std::vector<double>& scratch
)
{
    const label n = label(order.size());
    if (n != size())
    {
        FatalErrorInFunction
            << "Field " << name_ << " has " << size()
            << " particles but the ordering has " << n
            << abort(FatalError);
    }
    if (scratch.size() < data_.size())
    {
        scratch.resize(data_.size());
    }
    const label nc = nCmpt_;
    const double* src = data_.data();
    double* dst = scratch.data();

    #pragma omp parallel for schedule(static)
    for (label i = 0; i < n; ++i)
    {
        const double* s = src + size_t(order[i])*nc;
        double* d = dst + size_t(i)*nc;
        for (label c = 0; c < nc; ++c) d[c] = s[c];
    }
    std::copy(dst, dst + data_.size(), data_.begin());
}

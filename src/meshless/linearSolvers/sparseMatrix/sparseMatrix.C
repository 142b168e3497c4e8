/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sparseMatrix.H"
#include <cmath>

namespace
{
    //- Fewer entries than this: one thread (a parallel region costs more)
    const Foam::label parallelMinEntries = 20000;
}


Foam::meshless::sparseMatrix::sparseMatrix()
:
    n_(0),
    nnz_(0),
    rowStart_(1, 0),
    columns_(),
    values_(),
    symmetric_(false),
    distributed_(false),
    rowOffset_(0),
    nGlobal_(0),
    haloRows_()
{}


void Foam::meshless::sparseMatrix::setDistribution
(
    const label rowOffset,
    const label nGlobal,
    const std::vector<label>& haloRows
)
{
    distributed_ = true;
    rowOffset_ = rowOffset;
    nGlobal_ = nGlobal;
    haloRows_ = haloRows;
}


void Foam::meshless::sparseMatrix::resize(const label n, const label nnz)
{
    // std::vector keeps its capacity when resized down
    rowStart_.resize(size_t(n) + 1);
    columns_.resize(size_t(nnz));
    values_.resize(size_t(nnz));
    n_ = n;
    nnz_ = nnz;
}


bool Foam::meshless::sparseMatrix::checkDiagonalFirst() const
{
    if (rowStart_[0] != 0 || rowStart_[n_] != nnz_)
    {
        return false;
    }
    for (label i = 0; i < n_; ++i)
    {
        const label start = rowStart_[i];
        const label end = rowStart_[i + 1];
        if (end <= start || columns_[start] != i)
        {
            return false;
        }
        const label nCols = n_ + label(haloRows_.size());
        for (label k = start; k < end; ++k)
        {
            if (columns_[k] < 0 || columns_[k] >= nCols)
            {
                return false;
            }
        }
    }
    return true;
}


void Foam::meshless::sparseMatrix::multiply
(
    const double* x,
    double* y
) const
{
    const label* rowStart = rowStart_.data();
    const label* columns = columns_.data();
    const double* values = values_.data();

    #pragma omp parallel for schedule(static) if (nnz_ > parallelMinEntries)
    for (label i = 0; i < n_; ++i)
    {
        double sum = 0;
        for (label k = rowStart[i]; k < rowStart[i + 1]; ++k)
        {
            sum += values[k]*x[columns[k]];
        }
        y[i] = sum;
    }
}


double Foam::meshless::sparseMatrix::residualNorm
(
    const double* b,
    const double* x
) const
{
    const label* rowStart = rowStart_.data();
    const label* columns = columns_.data();
    const double* values = values_.data();

    double sumSqr = 0;
    #pragma omp parallel for schedule(static) reduction(+:sumSqr) \
        if (nnz_ > parallelMinEntries)
    for (label i = 0; i < n_; ++i)
    {
        double r = b[i];
        for (label k = rowStart[i]; k < rowStart[i + 1]; ++k)
        {
            r -= values[k]*x[columns[k]];
        }
        sumSqr += r*r;
    }
    return std::sqrt(sumSqr);
}


double Foam::meshless::norm2(const double* v, const label n)
{
    double sumSqr = 0;
    #pragma omp parallel for schedule(static) reduction(+:sumSqr) \
        if (n > parallelMinEntries)
    for (label i = 0; i < n; ++i)
    {
        sumSqr += v[i]*v[i];
    }
    return std::sqrt(sumSqr);
}

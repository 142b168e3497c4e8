/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cellLinkedList.H"
#include "error.H"
#include <algorithm>
#include <limits>

Foam::meshless::cellLinkedList::cellLinkedList
(
    const label dim,
    const scalar radius,
    const periodicBox& periodic
)
:
    dim_(dim),
    radius_(radius),
    cellSize_(radius*(1 + 1e-10)),
    invCellSize_(1/cellSize_),
    origin_{0, 0, 0},
    nCells_{1, 1, 1},
    nParticles_(0),
    periodic_(periodic),
    cellSizeDir_{cellSize_, cellSize_, cellSize_},
    invCellSizeDir_{invCellSize_, invCellSize_, invCellSize_},
    visitAll_{false, false, false},
    x_(nullptr)
{
    if (dim != 2 && dim != 3)
    {
        FatalErrorInFunction
            << "Dimension " << dim << ": expected 2 or 3" << exit(FatalError);
    }
    if (!(radius > 0))
    {
        FatalErrorInFunction
            << "Search radius " << radius << ": expected > 0"
            << exit(FatalError);
    }
    for (label d = dim; d < 3; ++d)
    {
        if (periodic.periodic(d))
        {
            FatalErrorInFunction
                << "Periodic direction " << d << " in " << dim << "D"
                << exit(FatalError);
        }
    }
    for (label d = 0; d < dim; ++d)
    {
        if (periodic.periodic(d) && !(periodic.length(d) > 2*radius))
        {
            FatalErrorInFunction
                << "Period " << periodic.length(d) << " in direction " << d
                << ": expected more than twice the search radius " << radius
                << " (a point would see two images of a neighbour)"
                << exit(FatalError);
        }
    }
}


void Foam::meshless::cellLinkedList::build(const double* x, const label n)
{
    const label dim = dim_;
    x_ = x;
    nParticles_ = n;

    // Bounding box (min/max reductions are exact: thread-count independent)
    double lo[3] = {0, 0, 0};
    double hi[3] = {0, 0, 0};
    for (label d = 0; d < dim; ++d)
    {
        double l = std::numeric_limits<double>::max();
        double h = -l;
        #pragma omp parallel for reduction(min:l) reduction(max:h)
        for (label i = 0; i < n; ++i)
        {
            const double v = x[size_t(i)*dim + d];
            l = std::min(l, v);
            h = std::max(h, v);
        }
        if (n == 0) { l = 0; h = 0; }
        if (!std::isfinite(l) || !std::isfinite(h))
        {
            FatalErrorInFunction
                << "Non-finite particle coordinate in direction " << d
                << ": the run has diverged" << exit(FatalError);
        }
        lo[d] = l;
        hi[d] = h;
    }

    // Cell size: the radius, coarsened while the grid would be too large.
    // Along a periodic direction the grid is the period, in a whole number
    // of cells at least that wide.
    cellSize_ = radius_*(1 + 1e-10);
    const double maxCells = double(maxCellsPerParticle)*std::max<label>(n, 1) + 64;
    for (;;)
    {
        double total = 1;
        for (label d = 0; d < dim; ++d)
        {
            total *=
                periodic_.periodic(d)
              ? std::max(std::floor(periodic_.length(d)/cellSize_), 1.0)
              : std::floor((hi[d] - lo[d])/cellSize_) + 1;
        }
        if (total <= maxCells) break;
        cellSize_ *= 1.5;
    }
    invCellSize_ = 1/cellSize_;

    label total = 1;
    for (label d = 0; d < 3; ++d)
    {
        if (d < dim && periodic_.periodic(d))
        {
            const double L = periodic_.length(d);
            origin_[d] = periodic_.min(d);
            nCells_[d] = std::max(label(std::floor(L/cellSize_)), label(1));
            cellSizeDir_[d] = L/nCells_[d];
            invCellSizeDir_[d] = nCells_[d]/L;
            visitAll_[d] = nCells_[d] < 3;
        }
        else
        {
            origin_[d] = lo[d];
            nCells_[d] =
                d < dim ? label(std::floor((hi[d] - lo[d])*invCellSize_)) + 1 : 1;
            cellSizeDir_[d] = cellSize_;
            invCellSizeDir_[d] = invCellSize_;
            visitAll_[d] = false;
        }
        total *= nCells_[d];
    }

    // std::vector keeps its capacity on resize: these allocate only to grow
    cellOf_.resize(n);
    sorted_.resize(n);
    cellStart_.resize(total + 1);

    const label nx = nCells_[0];
    const label ny = nCells_[1];

    if (periodic_.any())
    {
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            const double* p = x + size_t(i)*dim;
            label c[3] = {0, 0, 0};
            for (label d = 0; d < dim; ++d)
            {
                if (periodic_.periodic(d))
                {
                    c[d] = periodicCell(d, p[d]);
                }
                else
                {
                    c[d] = label((p[d] - origin_[d])*invCellSize_);
                    if (c[d] >= nCells_[d]) c[d] = nCells_[d] - 1;
                }
            }
            cellOf_[i] = c[0] + nx*(c[1] + ny*c[2]);
        }
    }
    else
    {
        #pragma omp parallel for schedule(static)
        for (label i = 0; i < n; ++i)
        {
            const double* p = x + size_t(i)*dim;
            label c[3] = {0, 0, 0};
            for (label d = 0; d < dim; ++d)
            {
                c[d] = label((p[d] - origin_[d])*invCellSize_);
                if (c[d] >= nCells_[d]) c[d] = nCells_[d] - 1;
            }
            cellOf_[i] = c[0] + nx*(c[1] + ny*c[2]);
        }
    }

    // Counting sort, serial and stable: deterministic order within a cell
    std::fill(cellStart_.begin(), cellStart_.begin() + total + 1, 0);
    for (label i = 0; i < n; ++i)
    {
        ++cellStart_[cellOf_[i] + 1];
    }
    for (label c = 0; c < total; ++c)
    {
        cellStart_[c + 1] += cellStart_[c];
    }
    // Scatter using the cell starts as cursors, then restore them
    for (label i = 0; i < n; ++i)
    {
        sorted_[cellStart_[cellOf_[i]]++] = i;
    }
    for (label c = total; c > 0; --c)
    {
        cellStart_[c] = cellStart_[c - 1];
    }
    cellStart_[0] = 0;
}

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "seedLattice.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::seedLattice::seedLattice
(
    const point& origin,
    const scalar dx,
    const vector& offset,
    const label dim,
    const scalar zPlane
)
:
    origin_(origin),
    dx_(dx),
    offset_(offset),
    dim_(dim),
    zPlane_(zPlane)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::seedLattice::cellVolume() const
{
    return dim_ == 2 ? dx_*dx_ : dx_*dx_*dx_;
}


void Foam::meshless::seedLattice::range
(
    const direction d,
    const scalar xMin,
    const scalar xMax,
    label& lo,
    label& hi
) const
{
    // Relative round-off of (x - origin)/dx: a box edge meant to sit on a
    // lattice point must not lose it to 1e-16
    const scalar eps = 1e-9;
    lo = label(std::ceil((xMin - origin_[d])/dx_ - offset_[d] - eps));
    hi = label(std::floor((xMax - origin_[d])/dx_ - offset_[d] + eps));
}


Foam::point Foam::meshless::seedLattice::at
(
    const label i,
    const label j,
    const label k
) const
{
    return point
    (
        origin_.x() + (i + offset_.x())*dx_,
        origin_.y() + (j + offset_.y())*dx_,
        dim_ == 3 ? origin_.z() + (k + offset_.z())*dx_ : zPlane_
    );
}


Foam::tmp<Foam::pointField> Foam::meshless::seedLattice::points
(
    const boundBox& bb
) const
{
    label lo[3] = {0, 0, 0};
    label hi[3] = {0, 0, 0};
    for (direction d = 0; d < dim_; ++d)
    {
        range(d, bb.min()[d], bb.max()[d], lo[d], hi[d]);
        if (hi[d] < lo[d])
        {
            return tmp<pointField>::New();
        }
    }

    const label n =
        (hi[0] - lo[0] + 1)*(hi[1] - lo[1] + 1)*(hi[2] - lo[2] + 1);
    auto tpts = tmp<pointField>::New(n);
    pointField& pts = tpts.ref();

    label pointi = 0;
    for (label k = lo[2]; k <= hi[2]; ++k)
    {
        for (label j = lo[1]; j <= hi[1]; ++j)
        {
            for (label i = lo[0]; i <= hi[0]; ++i)
            {
                pts[pointi++] = at(i, j, k);
            }
        }
    }
    return tpts;
}


// ************************************************************************* //

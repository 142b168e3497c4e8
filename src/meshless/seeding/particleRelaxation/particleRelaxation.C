/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleRelaxation.H"
#include "dictionaryChecks.H"
#include "cellLinkedList.H"
#include "neighbourList.H"
#include "Random.H"
#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::particleRelaxation::particleRelaxation
(
    const dictionary& dict,
    const label dim,
    const scalar spacing,
    const periodicBox& periodic
)
:
    dim_(dim),
    spacing_(spacing),
    kernel_(),
    iterations_(readPositiveLabel(dict, "iterations")),
    perturbation_(readNonNegativeOrDefault(dict, "perturbation", 0.25)),
    seed_(dict.getOrDefault<label>("seed", 1)),
    coefficient_(readPositiveOrDefault(dict, "coefficient", 0.2)),
    maxStep_(readPositiveOrDefault(dict, "maxStep", 0.2)),
    tolerance_(readNonNegativeOrDefault(dict, "tolerance", 1e-4)),
    periodic_(periodic),
    done_(0),
    residual0_(0),
    residual_(0),
    refused_(0)
{
    if (perturbation_ >= 0.5)
    {
        FatalIOErrorInFunction(dict)
            << "perturbation " << perturbation_ << ": expected a random"
            << " shift below half the spacing (0 <= perturbation < 0.5),"
            << " e.g. 0.25" << exit(FatalIOError);
    }
    if (maxStep_ > 0.5)
    {
        FatalIOErrorInFunction(dict)
            << "maxStep " << maxStep_ << ": expected at most 0.5 (a move"
            << " per iteration of at most half the spacing), e.g. 0.2"
            << exit(FatalIOError);
    }
    dictionary kernelDict;
    kernelDict.add("type", word("wendlandC2"));
    kernelDict.add("smoothingLengthRatio", 1.3);
    if (dict.found("kernel"))
    {
        kernelDict = dict.subDict("kernel");
    }
    kernel_ = smoothingKernel::New(kernelDict, dim, spacing);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::meshless::particleRelaxation::gamma
(
    const std::vector<double>& xAll,
    const label n,
    const std::vector<double>& VAll,
    std::vector<double>& g
) const
{
    const label nAll = label(VAll.size());
    const label dim = dim_;
    const smoothingKernel& W = kernel_();

    cellLinkedList cells(dim, W.radius(), periodic_);
    cells.build(xAll.data(), nAll);
    neighbourList nbrs;
    nbrs.build(cells, xAll.data(), n, true);

    g.assign(size_t(n)*dim, 0.0);
    scalar largest = 0;
    const scalar h = W.h();

    #pragma omp parallel for schedule(static) reduction(max:largest)
    for (label i = 0; i < n; ++i)
    {
        double gi[3] = {0, 0, 0};
        const double* xi = &xAll[size_t(i)*dim];
        for (const label* p = nbrs.begin(i); p != nbrs.end(i); ++p)
        {
            const label j = *p;
            double r[3] = {0, 0, 0};
            for (label d = 0; d < dim; ++d) r[d] = xi[d] - xAll[size_t(j)*dim + d];
            if (periodic_.any())
            {
                if (dim == 2) periodic_.minimumImage<2>(r);
                else periodic_.minimumImage<3>(r);
            }
            double rr = 0;
            for (label d = 0; d < dim; ++d) rr += r[d]*r[d];
            const double F = W.gradFactor(std::sqrt(rr));
            for (label d = 0; d < dim; ++d) gi[d] -= 2*F*r[d]*VAll[j];
        }
        double mag = 0;
        for (label d = 0; d < dim; ++d)
        {
            g[size_t(i)*dim + d] = gi[d];
            mag += gi[d]*gi[d];
        }
        largest = std::max(largest, h*std::sqrt(mag));
    }
    return largest;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::meshless::particleRelaxation::residual
(
    const std::vector<double>& x,
    const scalar V,
    const std::vector<double>& xFixed,
    const std::vector<double>& VFixed
) const
{
    const label n = label(x.size())/dim_;
    std::vector<double> xAll(x);
    xAll.insert(xAll.end(), xFixed.begin(), xFixed.end());
    std::vector<double> VAll(n, V);
    VAll.insert(VAll.end(), VFixed.begin(), VFixed.end());
    std::vector<double> g;
    return gamma(xAll, n, VAll, g);
}


void Foam::meshless::particleRelaxation::relax
(
    std::vector<double>& x,
    const scalar V,
    const std::vector<double>& xFixed,
    const std::vector<double>& VFixed,
    const constraint& inside
)
{
    const label dim = dim_;
    const label n = label(x.size())/dim;
    const size_t nx = size_t(n)*dim;

    std::vector<double> xAll(x);
    xAll.insert(xAll.end(), xFixed.begin(), xFixed.end());
    std::vector<double> VAll(n, V);
    VAll.insert(VAll.end(), VFixed.begin(), VFixed.end());

    std::vector<double> trial(nx);
    std::vector<char> ok(n);
    std::vector<double> g;
    refused_ = 0;

    // Random shift, refused like any other move outside the region
    if (perturbation_ > 0)
    {
        Random rnd(seed_);
        for (size_t k = 0; k < nx; ++k)
        {
            trial[k] = xAll[k] + perturbation_*spacing_*(2*rnd.sample01<scalar>() - 1);
        }
        periodic_.wrap(trial.data(), n, dim);
        inside(trial.data(), n, ok);
        for (label i = 0; i < n; ++i)
        {
            if (!ok[i]) { ++refused_; continue; }
            for (label d = 0; d < dim; ++d) xAll[size_t(i)*dim + d] = trial[size_t(i)*dim + d];
        }
    }

    const scalar h = kernel_->h();
    const scalar c = coefficient_*h*h;
    const scalar cap = maxStep_*spacing_;
    residual0_ = gamma(xAll, n, VAll, g);
    done_ = 0;
    for (label it = 0; it < iterations_; ++it)
    {
        if (it) gamma(xAll, n, VAll, g);
        scalar largest = 0;
        for (label i = 0; i < n; ++i)
        {
            double s[3] = {0, 0, 0};
            double mag = 0;
            for (label d = 0; d < dim; ++d)
            {
                s[d] = c*g[size_t(i)*dim + d];
                mag += s[d]*s[d];
            }
            mag = std::sqrt(mag);
            const double f = mag > cap ? cap/mag : 1;
            largest = std::max(largest, f*mag);
            for (label d = 0; d < dim; ++d)
            {
                trial[size_t(i)*dim + d] = xAll[size_t(i)*dim + d] + f*s[d];
            }
        }
        periodic_.wrap(trial.data(), n, dim);
        inside(trial.data(), n, ok);
        for (label i = 0; i < n; ++i)
        {
            if (!ok[i]) { ++refused_; continue; }
            for (label d = 0; d < dim; ++d) xAll[size_t(i)*dim + d] = trial[size_t(i)*dim + d];
        }
        done_ = it + 1;
        if (largest < tolerance_*spacing_) break;
    }
    residual_ = gamma(xAll, n, VAll, g);
    std::copy(xAll.begin(), xAll.begin() + nx, x.begin());
}

// ************************************************************************* //

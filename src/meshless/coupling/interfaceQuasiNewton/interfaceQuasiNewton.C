/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "interfaceQuasiNewton.H"
#include "dictionaryChecks.H"
#include <cmath>

namespace
{

double vecDot(const std::vector<double>& a, const std::vector<double>& b)
{
    double s = 0;
    const size_t n = a.size();
    for (size_t i = 0; i < n; ++i) s += a[i]*b[i];
    return s;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::interfaceQuasiNewton::interfaceQuasiNewton
(
    const dictionary& dict
)
:
    maxIterations_(readPositiveLabel(dict, "maxIterations")),
    tolerance_(readInOpenRange(dict, "tolerance", 0, 1)),
    initialRelaxation_
    (
        dict.found("initialRelaxation")
      ? readInOpenRange(dict, "initialRelaxation", 0, 1 + SMALL)
      : 0.1
    ),
    reuse_
    (
        dict.found("reuse") ? readLabelInRange(dict, "reuse", 0, 100) : 8
    ),
    filter_
    (
        dict.found("filter") ? readInOpenRange(dict, "filter", 0, 1) : 1e-3
    ),
    lastSecant_(false),
    bestNorm_(GREAT),
    leastResidual_(GREAT),
    leastIteration_(0),
    iterations_(0),
    residual_(0),
    steps_(0),
    totalIterations_(0),
    unconverged_(0),
    most_(0),
    restarts_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::meshless::interfaceQuasiNewton::restartFromBest
(
    std::vector<double>& x
)
{
    current_ = columns();
    past_.clear();
    rLast_.clear();
    ++restarts_;
    for (size_t i = 0; i < x.size(); ++i)
    {
        x[i] = xBest_[i] + initialRelaxation_*rBest_[i];
    }
    lastSecant_ = false;
}


bool Foam::meshless::interfaceQuasiNewton::leastSquaresUpdate
(
    std::vector<double>& x,
    const std::vector<double>& xt
)
{
    // The columns in order: this step's, then the past steps', newest first
    std::vector<const std::vector<double>*> dR, dXt;
    for (label c = label(current_.dR.size()) - 1; c >= 0; --c)
    {
        dR.push_back(&current_.dR[c]);
        dXt.push_back(&current_.dXt[c]);
    }
    for (const columns& s : past_)
    {
        for (label c = label(s.dR.size()) - 1; c >= 0; --c)
        {
            dR.push_back(&s.dR[c]);
            dXt.push_back(&s.dXt[c]);
        }
    }
    const size_t n = x.size();
    const label m = label(dR.size());
    if (m == 0) return false;

    // Modified Gram-Schmidt, dropping a column whose part orthogonal to
    // the kept ones is below filter of its norm (QR1 filter); at most n
    if (label(Q_.size()) < m) Q_.resize(m);
    R_.assign(size_t(m)*m, 0.0);
    kept_.clear();
    for (label c = 0; c < m && kept_.size() < n; ++c)
    {
        const std::vector<double>& v = *dR[c];
        if (v.size() != n) continue;
        const double norm0 = std::sqrt(vecDot(v, v));
        if (norm0 == 0) continue;
        std::vector<double>& q = Q_[kept_.size()];
        q = v;
        const label nk = label(kept_.size());
        std::vector<double> rc(nk + 1, 0.0);
        for (label j = 0; j < nk; ++j)
        {
            const double s = vecDot(Q_[j], q);
            rc[j] = s;
            const std::vector<double>& qj = Q_[j];
            for (size_t i = 0; i < n; ++i) q[i] -= s*qj[i];
        }
        const double norm = std::sqrt(vecDot(q, q));
        if (norm <= filter_*norm0) continue;
        for (size_t i = 0; i < n; ++i) q[i] /= norm;
        rc[nk] = norm;
        for (label j = 0; j <= nk; ++j) R_[j*m + nk] = rc[j];
        kept_.push_back(c);
    }
    const label mk = label(kept_.size());
    if (mk == 0) return false;

    // R alpha = -Q^T r, back substitution
    std::vector<double> alpha(mk);
    for (label j = 0; j < mk; ++j) alpha[j] = -vecDot(Q_[j], r_);
    for (label j = mk - 1; j >= 0; --j)
    {
        double s = alpha[j];
        for (label l = j + 1; l < mk; ++l) s -= R_[j*m + l]*alpha[l];
        alpha[j] = s/R_[j*m + j];
    }

    // x^{k+1} = x~ + W alpha
    x = xt;
    for (label j = 0; j < mk; ++j)
    {
        const std::vector<double>& w = *dXt[kept_[j]];
        const double a = alpha[j];
        for (size_t i = 0; i < n; ++i) x[i] += a*w[i];
    }
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::interfaceQuasiNewton::beginStep()
{
    current_.dR.clear();
    current_.dXt.clear();
    iterations_ = 0;
    residual_ = 0;
    bestNorm_ = GREAT;
    leastResidual_ = GREAT;
    leastIteration_ = 0;
    lastSecant_ = false;
    rLast_.clear();
}


bool Foam::meshless::interfaceQuasiNewton::update
(
    std::vector<double>& x,
    const std::vector<double>& xt,
    const label k
)
{
    const size_t n = x.size();
    r_.resize(n);
    for (size_t i = 0; i < n; ++i) r_[i] = xt[i] - x[i];
    iterations_ = k + 1;

    const double rNorm = std::sqrt(vecDot(r_, r_));
    const double xtNorm = std::sqrt(vecDot(xt, xt));
    residual_ = xtNorm > 0 ? rNorm/xtNorm : (rNorm > 0 ? GREAT : 0);
    if (std::isfinite(rNorm) && residual_ < leastResidual_)
    {
        leastResidual_ = residual_;
        leastIteration_ = iterations_;
        xLeast_ = x;
    }
    if
    (
        rNorm <= tolerance_*xtNorm || iterations_ >= maxIterations_
     || !std::isfinite(rNorm)
    )
    {
        ++steps_;
        totalIterations_ += iterations_;
        most_ = std::max(most_, iterations_);
        if (!(rNorm <= tolerance_*xtNorm)) ++unconverged_;
        return true;
    }

    if (rNorm < bestNorm_)
    {
        bestNorm_ = rNorm;
        xBest_ = x;
        rBest_ = r_;
    }
    else if (lastSecant_ && rNorm > restartFactor*bestNorm_)
    {
        restartFromBest(x);
        return false;
    }

    // The reused columns, half the step's iterations on: they mislead (the
    // response has changed since they were taken: another step size, a
    // switch in the fluid); the step goes on from its best iterate with
    // columns of its own
    if (!past_.empty() && 2*iterations_ >= maxIterations_)
    {
        restartFromBest(x);
        return false;
    }

    // The new columns: differences with the last iteration of this step
    if (k > 0 && rLast_.size() == n)
    {
        std::vector<double> dr(n), dxt(n);
        for (size_t i = 0; i < n; ++i)
        {
            dr[i] = r_[i] - rLast_[i];
            dxt[i] = xt[i] - xtLast_[i];
        }
        current_.dR.push_back(std::move(dr));
        current_.dXt.push_back(std::move(dxt));
    }
    rLast_ = r_;
    xtLast_ = xt;

    lastSecant_ = leastSquaresUpdate(x, xt);
    if (!lastSecant_)
    {
        for (size_t i = 0; i < n; ++i) x[i] += initialRelaxation_*r_[i];
    }
    return false;
}


bool Foam::meshless::interfaceQuasiNewton::leastIterate
(
    std::vector<double>& x
)
{
    if
    (
        leastIteration_ == 0 || leastIteration_ == iterations_
     || xLeast_.size() != x.size()
    )
    {
        return false;
    }
    x = xLeast_;
    ++iterations_;
    ++totalIterations_;
    most_ = std::max(most_, iterations_);
    return true;
}


void Foam::meshless::interfaceQuasiNewton::endStep()
{
    if (reuse_ == 0) return;
    if (!current_.dR.empty())
    {
        past_.push_front(std::move(current_));
        current_ = columns();
    }
    while (label(past_.size()) > reuse_) past_.pop_back();
}


// ************************************************************************* //

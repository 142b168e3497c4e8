/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "solidJacobian.H"
#include "neighbourRelation.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::solidJacobian::solidJacobian
(
    const neighbourRelation& pairs,
    const label dim,
    const std::vector<char>& free,
    const std::vector<label>& mirror,
    const bool pairVelocity
)
:
    n_(pairs.size()),
    dim_(dim),
    free_(free),
    colours_(),
    reachStart_(n_ + 1, 0),
    reach_(),
    K_(n_*dim, n_*dim),
    D_(n_*dim, 0),
    C_(n_*dim, n_*dim),
    pairVelocity_(pairVelocity),
    J_(),
    lu_(),
    analysed_(false),
    shiftX_(0),
    shiftU_(0),
    assemblies_(0),
    factorisations_(0),
    rhs_(n_*dim, 0)
{
    const label* off = pairs.offsetData();
    const label* idx = pairs.indexData();

    // The images of each mirror (moved with it)
    std::vector<std::vector<label>> images(n_);
    for (label i = 0; i < n_; ++i)
    {
        if (mirror[i] >= 0) images[mirror[i]].push_back(i);
    }

    // Rows reached by column k: two rings of k and of its images, and the
    // mirror of every image among them (its force folds onto the mirror)
    std::vector<label> stamp(n_, -1);
    std::vector<label> rows;
    auto add = [&](const label i, const label k)
    {
        if (stamp[i] != k)
        {
            stamp[i] = k;
            rows.push_back(i);
        }
    };
    for (label k = 0; k < n_; ++k)
    {
        rows.clear();
        if (free_[k])
        {
            std::vector<label> seeds(1, k);
            seeds.insert(seeds.end(), images[k].begin(), images[k].end());
            for (const label s : seeds)
            {
                add(s, k);
                for (label q = off[s]; q < off[s + 1]; ++q)
                {
                    const label j = idx[q];
                    add(j, k);
                    for (label p = off[j]; p < off[j + 1]; ++p)
                    {
                        add(idx[p], k);
                    }
                }
            }
            const label nr = rows.size();
            for (label r = 0; r < nr; ++r)
            {
                if (mirror[rows[r]] >= 0) add(mirror[rows[r]], k);
            }
        }
        reachStart_[k + 1] = reachStart_[k] + rows.size();
        reach_.insert(reach_.end(), rows.begin(), rows.end());
    }

    // Greedy colouring: a column takes the first colour none of whose
    // columns reaches one of its rows
    std::vector<std::vector<char>> used;
    for (label k = 0; k < n_; ++k)
    {
        if (!free_[k]) continue;
        size_t c = 0;
        for (; c < used.size(); ++c)
        {
            bool clash = false;
            for (label r = reachStart_[k]; r < reachStart_[k + 1] && !clash; ++r)
            {
                clash = used[c][reach_[r]];
            }
            if (!clash) break;
        }
        if (c == used.size())
        {
            used.emplace_back(n_, 0);
            colours_.emplace_back();
        }
        for (label r = reachStart_[k]; r < reachStart_[k + 1]; ++r)
        {
            used[c][reach_[r]] = 1;
        }
        colours_[c].push_back(k);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::solidJacobian::assemble
(
    const double* a0,
    const double eps,
    const double epsU,
    const perturbed& evaluate
)
{
    typedef Eigen::Triplet<double> triplet;
    std::vector<triplet> entries;
    entries.reserve(reach_.size()*dim_*dim_);

    // -da/dx (offset 0) or -da/du (offset dim) by colours into M
    auto differences = [&]
    (
        const int offset,
        const double e,
        Eigen::SparseMatrix<double>& M
    )
    {
        entries.clear();
        for (const std::vector<label>& members : colours_)
        {
            for (int d = 0; d < dim_; ++d)
            {
                const double* a = evaluate(members, offset + d, e);
                for (const label k : members)
                {
                    const label col = k*dim_ + d;
                    for (label r = reachStart_[k]; r < reachStart_[k + 1]; ++r)
                    {
                        const label i = reach_[r];
                        if (!free_[i]) continue;
                        for (int c = 0; c < dim_; ++c)
                        {
                            const label row = i*dim_ + c;
                            const double v = -(a[row] - a0[row])/e;
                            if (v != 0) entries.emplace_back(row, col, v);
                        }
                    }
                }
            }
        }
        M.setZero();
        M.setFromTriplets(entries.begin(), entries.end());
        M.makeCompressed();
    };
    differences(0, eps, K_);

    if (pairVelocity_)
    {
        differences(dim_, epsU, C_);
    }
    else
    {
        // The velocity dependence, taken as diagonal
        const std::vector<label> none;
        const double* a = evaluate(none, -1, epsU);
        for (label i = 0; i < n_; ++i)
        {
            for (int e = 0; e < dim_; ++e)
            {
                const label row = i*dim_ + e;
                D_[row] = free_[i] ? -(a[row] - a0[row])/epsU : 0;
            }
        }
    }
    ++assemblies_;
    lu_.reset();
}


bool Foam::meshless::solidJacobian::factorise
(
    const double shiftX,
    const double shiftU
)
{
    const label nv = n_*dim_;
    Eigen::SparseMatrix<double> S(nv, nv);
    S.reserve(Eigen::VectorXi::Constant(nv, 1));
    for (label k = 0; k < nv; ++k)
    {
        S.insert(k, k) =
            shiftX + (free_[k/dim_] && !pairVelocity_ ? shiftU*D_[k] : 0);
    }
    if (pairVelocity_)
    {
        J_ = K_ + shiftU*C_ + S;
    }
    else
    {
        J_ = K_ + S;
    }
    J_.makeCompressed();
    if (!lu_ || !analysed_)
    {
        lu_.reset(new Eigen::SparseLU<Eigen::SparseMatrix<double>>());
        lu_->analyzePattern(J_);
        analysed_ = true;
    }
    lu_->factorize(J_);
    shiftX_ = shiftX;
    shiftU_ = shiftU;
    ++factorisations_;
    if (lu_->info() != Eigen::Success)
    {
        lu_.reset();
        analysed_ = false;
        return false;
    }
    return true;
}


void Foam::meshless::solidJacobian::solve(const double* r, double* dx) const
{
    const label nv = n_*dim_;
    Eigen::Map<const Eigen::VectorXd> b(r, nv);
    Eigen::Map<Eigen::VectorXd> x(dx, nv);
    x = lu_->solve(b);
    for (label i = 0; i < n_; ++i)
    {
        if (free_[i]) continue;
        for (int e = 0; e < dim_; ++e) dx[i*dim_ + e] = 0;
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    The correction matrix (correctionMatrix.H):

      - robustInverse: the exact inverse of a regular matrix; for a rank-
        deficient one (points on a line, in a plane) the pseudo-inverse,
        exact along the resolved directions and zero across, no NaN; zero
        for a zero matrix (an isolated particle); an eigenvalue floor
        bounds the inverse and leaves matrices above it exact;
      - inverse<Dim> with kernelWeight and with gradientWeight makes the
        corrected gradient exact for linear fields (1e-10) at every
        particle of a jittered lattice, interior and boundary, over one or
        two sources; moments is the matrix inverse<Dim> inverted;
      - fitWeights: order 1 exact for linear fields, order 2 exact for
        quadratic fields (the gradient from G, the second derivatives from
        H) at every particle of a lattice block, corners included, in 2D
        and 3D; a particle with a pair left out by the 'intact' mask falls
        back to order 1 (H = 0, the pair's G = 0) and stays exact for
        linear fields; an isolated particle is unresolved (G = 0).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "correctionMatrix.H"
#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

template<int Dim>
bool allFinite(const tensorD<Dim>& T)
{
    return T.allFinite();
}

//- Random orthonormal basis (columns) from a seed
template<int Dim>
tensorD<Dim> rotation(const unsigned seed)
{
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Eigen::Matrix<double, Dim, Dim> A;
    for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) A(a, b) = u(gen);
    Eigen::HouseholderQR<Eigen::Matrix<double, Dim, Dim>> qr(A);
    return qr.householderQ();
}

//- M = sum_k c_k x_k x_k^T of the offsets x_k = t_k R e (e: first
//  'rank' unit vectors mixed), i.e. points spanning 'rank' directions
template<int Dim>
tensorD<Dim> momentsOfPointsIn
(
    const int rank,
    const tensorD<Dim>& R,
    const unsigned seed
)
{
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    tensorD<Dim> M = tensorD<Dim>::Zero();
    for (int k = 0; k < 12; ++k)
    {
        vectorD<Dim> x = vectorD<Dim>::Zero();
        for (int d = 0; d < rank; ++d) x += 0.01*u(gen)*R.col(d);
        M += (0.5 + 0.5*std::abs(u(gen)))*(x*x.transpose());
    }
    return M;
}


template<int Dim>
void expectRegularInverse()
{
    const tensorD<Dim> M = momentsOfPointsIn<Dim>(Dim, rotation<Dim>(1), 2);
    tensorD<Dim> Minv;
    EXPECT_TRUE(correctionMatrix::robustInverse<Dim>(M, Minv));
    const tensorD<Dim> direct = M.inverse();
    EXPECT_TRUE(Minv == direct) << "the direct inverse";
    EXPECT_LT((Minv*M - tensorD<Dim>::Identity()).norm(), 1e-12);
}


template<int Dim>
void expectPseudoInverse(const int rank)
{
    // Points spanning 'rank' < Dim directions: M^+ M is the projection on
    // them (exact derivatives along), M^+ maps the others to zero
    const tensorD<Dim> R = rotation<Dim>(3 + rank);
    const tensorD<Dim> M = momentsOfPointsIn<Dim>(rank, R, 4);
    tensorD<Dim> Minv;
    EXPECT_FALSE(correctionMatrix::robustInverse<Dim>(M, Minv)) << rank;
    EXPECT_TRUE(allFinite<Dim>(Minv));
    const double scale = Minv.norm();
    EXPECT_GT(scale, 0);
    for (int d = 0; d < Dim; ++d)
    {
        const vectorD<Dim> e = R.col(d);
        if (d < rank)
        {
            EXPECT_LT((Minv*(M*e) - e).norm(), 1e-10) << "resolved " << d;
        }
        else
        {
            EXPECT_LT((Minv*e).norm(), 1e-10*scale) << "unresolved " << d;
        }
    }
    // Moore-Penrose
    EXPECT_LT((M*Minv*M - M).norm(), 1e-10*M.norm());
    EXPECT_LT((Minv*M*Minv - Minv).norm(), 1e-10*scale);
    EXPECT_LT((Minv - Minv.transpose()).norm(), 1e-12*scale);
}


template<int Dim>
void expectFloor()
{
    // Eigenvalues 1, 1e-2 (and 0.3 in 3D)
    const tensorD<Dim> R = rotation<Dim>(7);
    vectorD<Dim> lambda;
    lambda(0) = 1;
    lambda(1) = 1e-2;
    if (Dim == 3) lambda(Dim - 1) = 0.3;
    const tensorD<Dim> M = R*lambda.asDiagonal()*R.transpose();

    // A floor below every eigenvalue: the exact inverse
    tensorD<Dim> Minv;
    EXPECT_TRUE(correctionMatrix::robustInverse<Dim>(M, Minv, 5e-3));
    EXPECT_TRUE(Minv == tensorD<Dim>(M.inverse()));

    // A floor of 0.1: the small eigenvalue counts as 0.1, the others exact
    const double floor = 0.1;
    EXPECT_FALSE(correctionMatrix::robustInverse<Dim>(M, Minv, floor));
    for (int d = 0; d < Dim; ++d)
    {
        const vectorD<Dim> e = R.col(d);
        const double expected = 1/std::max(lambda(d), floor);
        EXPECT_LT((Minv*e - expected*e).norm(), 1e-10*expected) << d;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Dim, Dim>> eig(Minv);
    EXPECT_LE(eig.eigenvalues().maxCoeff()*floor, 1 + 1e-12);

    // Rank-deficient with a floor: unresolved directions stay zero
    const tensorD<Dim> line = momentsOfPointsIn<Dim>(1, R, 8);
    EXPECT_FALSE(correctionMatrix::robustInverse<Dim>(line, Minv, 1.0));
    const vectorD<Dim> e0 = R.col(0);
    EXPECT_LT((Minv*e0 - e0).norm(), 1e-10) << "along: 1/floor";
    for (int d = 1; d < Dim; ++d)
    {
        const vectorD<Dim> e = R.col(d);
        EXPECT_LT((Minv*e).norm(), 1e-10) << "across: zero";
    }
}

} // End anonymous namespace


TEST(correctionMatrix, robustInverseOfARegularMatrixIsTheInverse)
{
    expectRegularInverse<2>();
    expectRegularInverse<3>();
}

TEST(correctionMatrix, robustInverseOfPointsOnALineOrAPlane)
{
    expectPseudoInverse<2>(1);
    expectPseudoInverse<3>(1);
    expectPseudoInverse<3>(2);
}

TEST(correctionMatrix, robustInverseOfZeroIsZero)
{
    // An isolated particle: no moments, zero derivatives, no NaN
    tensorD<2> M2 = tensorD<2>::Zero(), Minv2 = tensorD<2>::Constant(7);
    EXPECT_FALSE(correctionMatrix::robustInverse<2>(M2, Minv2));
    EXPECT_TRUE(Minv2 == tensorD<2>::Zero());
    tensorD<3> M3 = tensorD<3>::Zero(), Minv3 = tensorD<3>::Constant(7);
    EXPECT_FALSE(correctionMatrix::robustInverse<3>(M3, Minv3, 0.5));
    EXPECT_TRUE(Minv3 == tensorD<3>::Zero());
}

TEST(correctionMatrix, robustInverseWithAFloor)
{
    expectFloor<2>();
    expectFloor<3>();
}


// * * * * * * * * * * * * * inverse<Dim>, moments  * * * * * * * * * * * * //

namespace
{

std::vector<double> jittered
(
    const label dim,
    const label nSide,
    const double dx,
    const double jitter,
    const unsigned seed
)
{
    std::vector<double> x = meshlessTest::latticePoints(dim, nSide, dx);
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(-jitter*dx, jitter*dx);
    for (auto& v : x) v += u(gen);
    return x;
}

//- f = 0.7 + b.x of particle i of x
double linear(const double* b, const particleField& x, const label i)
{
    double f = 0.7;
    for (label d = 0; d < x.nComponents(); ++d) f += b[d]*x(i, d);
    return f;
}

//- The corrected gradient sum_J c_IJ (f_J - f_I) M_I^-1 x_IJ over the
//  sources, with the source bodies' values f[k]
template<int Dim, class Weight>
struct correctedGradient
{
    typedef vectorD<Dim> sum;
    typedef const double* source;
    Weight weight;
    const double* fA;
    const double* const* fB;
    const double* Minv;
    double* grad;

    sum start(const label) const { return sum::Zero(); }
    source at(const pairSource&, const label k) const { return fB[k]; }
    void pair
    (
        sum& g, const source& f, const pairView& v, const label i,
        const label q
    ) const
    {
        g += (weight(v, q)*(f[v.j[q]] - fA[i]))*v.x<Dim>(q);
    }
    void finish(const label i, sum& g) const
    {
        vec<Dim>(grad, i) = ctens<Dim>(Minv, i)*g;
    }
};


template<int Dim, class Weight>
void expectCorrectedGradientExact
(
    const std::string& kernelDict,
    const bool twoBodies,
    const std::string& what
)
{
    // A jittered lattice block (one body, or split into two at its middle)
    const double dx = 0.01;
    const label nSide = Dim == 2 ? 16 : 8;
    autoPtr<smoothingKernel> W = meshlessTest::kernel(Dim, dx, kernelDict);
    const std::vector<double> all = jittered(Dim, nSide, dx, 0.3, 5);
    std::vector<double> xA, xB;
    for (size_t i = 0; i < all.size()/Dim; ++i)
    {
        auto& x = !twoBodies || all[i*Dim] < 0.5*nSide*dx ? xA : xB;
        x.insert(x.end(), &all[i*Dim], &all[i*Dim] + Dim);
    }
    meshlessTest::pairFixture fx(Dim);
    std::mt19937_64 gen(6);
    std::uniform_real_distribution<double> u(0.9, 1.1);
    std::vector<double> VA(xA.size()/Dim), VB(xB.size()/Dim);
    for (auto& v : VA) v = u(gen)*std::pow(dx, Dim);
    for (auto& v : VB) v = u(gen)*std::pow(dx, Dim);
    fx.addBody(xA, VA);
    fx.relate(0, 0, *W);
    if (twoBodies)
    {
        fx.addBody(xB, VB);
        fx.relate(0, 1, *W);
    }
    const std::vector<pairSource> sources = fx.sources(0);
    const label n = fx.size(0);

    std::vector<double> Minv(n*Dim*Dim), M(n*Dim*Dim);
    std::vector<char> degenerate(n, 1);
    correctionMatrix::inverse<Dim>
    (
        n, sources.data(), label(sources.size()), Weight(), 0, Minv.data(),
        degenerate.data()
    );
    EXPECT_EQ(meshlessTest::countFlags(degenerate), 0) << what;

    // moments of the single body is the matrix inverted
    if (!twoBodies)
    {
        correctionMatrix::moments<Dim>
        (
            *sources[0].rel, fx.V(0), Weight(), M.data()
        );
        for (label i = 0; i < n; ++i)
        {
            EXPECT_LT
            (
                (ctens<Dim>(M.data(), i)*ctens<Dim>(Minv.data(), i)
               - tensorD<Dim>::Identity()).norm(),
                1e-10
            ) << what << ": particle " << i;
        }
    }

    const double slopes[2][3] = {{2, -3, 0.5}, {-1.5, 4, 1}};
    for (const double* b : {slopes[0], slopes[1]})
    {
        std::vector<std::vector<double>> f(fx.nBodies());
        std::vector<const double*> fB;
        for (label k = 0; k < fx.nBodies(); ++k)
        {
            for (label i = 0; i < fx.size(k); ++i)
            {
                f[k].push_back(linear(b, fx.x(k), i));
            }
        }
        for (const pairSource& s : sources)
        {
            fB.push_back(f[&s.rel->pointsB() == &fx.x(0) ? 0 : 1].data());
        }
        std::vector<double> grad(n*Dim);
        gather
        (
            n, sources,
            correctedGradient<Dim, Weight>
            {
                Weight(), f[0].data(), fB.data(), Minv.data(), grad.data()
            }
        );
        double err = 0;
        for (label i = 0; i < n; ++i)
        {
            for (label d = 0; d < Dim; ++d)
            {
                err = std::max(err, std::abs(grad[i*Dim + d] - b[d]));
            }
        }
        EXPECT_LT(err, 1e-10) << what;
    }
}

const std::string gaussian = "type gaussian; smoothingLengthRatio 1.2;";
const std::string wendland = "type wendlandC2; smoothingLengthRatio 1.3;";
const std::string cubic = "type cubicSpline; smoothingLengthRatio 1.3;";

} // End anonymous namespace


TEST(correctionMatrix, kernelWeightMakesTheGradientExactForLinearFields)
{
    using correctionMatrix::kernelWeight;
    expectCorrectedGradientExact<2, kernelWeight>(gaussian, false, "2D");
    expectCorrectedGradientExact<3, kernelWeight>(gaussian, false, "3D");
    expectCorrectedGradientExact<2, kernelWeight>(wendland, true, "2D, two");
    expectCorrectedGradientExact<3, kernelWeight>(wendland, true, "3D, two");
}

TEST(correctionMatrix, gradientWeightMakesTheGradientExactForLinearFields)
{
    using correctionMatrix::gradientWeight;
    expectCorrectedGradientExact<2, gradientWeight>(wendland, false, "2D");
    expectCorrectedGradientExact<3, gradientWeight>(wendland, false, "3D");
    expectCorrectedGradientExact<2, gradientWeight>(cubic, true, "2D, two");
    expectCorrectedGradientExact<3, gradientWeight>(gaussian, true, "3D, two");
}


TEST(correctionMatrix, inverseFlagsDegenerateParticles)
{
    // A line of particles and an isolated one: every one flagged, M^-1 of
    // the isolated one zero, the line's along the line only
    const double dx = 0.01;
    std::vector<double> x;
    for (label i = 0; i < 8; ++i)
    {
        x.push_back(i*dx);
        x.push_back(i*dx);
    }
    x.push_back(5);
    x.push_back(5);
    autoPtr<smoothingKernel> W = meshlessTest::kernel(2, dx, wendland);
    meshlessTest::pairFixture fx(2);
    fx.addBody(x, dx*dx);
    fx.relate(0, 0, *W);
    const label n = fx.size(0);
    std::vector<double> Minv(4*n, -1);
    std::vector<char> degenerate(n, 0);
    correctionMatrix::inverse<2>
    (
        n, fx.sources(0).data(), 1, correctionMatrix::gradientWeight(), 0,
        Minv.data(), degenerate.data()
    );
    EXPECT_EQ(meshlessTest::countFlags(degenerate), n);
    const vectorD<2> across(1, -1);
    for (label i = 0; i < n - 1; ++i)
    {
        EXPECT_TRUE(ctens<2>(Minv.data(), i).allFinite());
        EXPECT_LT
        (
            (ctens<2>(Minv.data(), i)*across).norm(),
            1e-10*ctens<2>(Minv.data(), i).norm()
        ) << i;
        EXPECT_GT(ctens<2>(Minv.data(), i).norm(), 0) << i;
    }
    EXPECT_TRUE(ctens<2>(Minv.data(), n - 1) == tensorD<2>::Zero());

    // Without the flags' array
    std::vector<double> again(4*n);
    correctionMatrix::inverse<2>
    (
        n, fx.sources(0).data(), 1, correctionMatrix::gradientWeight(), 0,
        again.data()
    );
    EXPECT_TRUE(again == Minv);
}


// * * * * * * * * * * * * * * * * * fitWeights  * * * * * * * * * * * * * * //

namespace
{

//- f = a + b.x + x^T C x/2 with C symmetric (the leading dim x dim block
//  in 2D)
struct quadratic
{
    double a;
    double b[3];
    double C[3][3];

    double operator()(const particleField& x, const label i) const
    {
        const label dim = x.nComponents();
        double f = a;
        for (label p = 0; p < dim; ++p)
        {
            f += b[p]*x(i, p);
            for (label r = 0; r < dim; ++r)
            {
                f += 0.5*C[p][r]*x(i, p)*x(i, r);
            }
        }
        return f;
    }

    double gradient(const particleField& x, const label i, const label p)
    const
    {
        double g = b[p];
        for (label r = 0; r < x.nComponents(); ++r) g += C[p][r]*x(i, r);
        return g;
    }
};

const quadratic quadratic3 =
{
    0.4, {1.5, -2.0, 0.75},
    {{3.0, -1.0, 0.5}, {-1.0, 2.0, 1.25}, {0.5, 1.25, -4.0}}
};

const quadratic linear3 =
{
    0.4, {1.5, -2.0, 0.75}, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}
};


//- A jittered lattice block with a relation for the fit, the fields'
//  values, and grad u_i = sum_j (u_j - u_i) G_ij, Hess u_i likewise
template<int Dim>
struct fitBlock
{
    const double dx = 0.01;
    autoPtr<smoothingKernel> W;
    meshlessTest::pairFixture fx;
    const neighbourRelation* rel;
    std::vector<double> G, H;
    std::vector<char> resolved;

    fitBlock(const std::string& kernelDict, const bool isolated = false)
    :
        W(meshlessTest::kernel(Dim, dx, kernelDict)),
        fx(Dim)
    {
        std::vector<double> x = jittered(Dim, Dim == 2 ? 9 : 6, dx, 0.2, 9);
        if (isolated)
        {
            for (label d = 0; d < Dim; ++d) x.push_back(7.0);
        }
        fx.addBody(x, std::pow(dx, Dim));
        rel = &fx.relate(0, 0, *W);
    }

    label n() const { return fx.size(0); }

    template<class Weight>
    label fit(const label order, const char* intact = nullptr)
    {
        G.assign(rel->nPairs()*Dim, -1);
        H.assign(rel->nPairs()*Dim*Dim, -1);
        resolved.assign(n(), 2);
        return correctionMatrix::fitWeights<Dim>
        (
            *rel, fx.V(0), Weight(), order, dx, intact, G.data(), H.data(),
            resolved.data()
        );
    }

    //- Largest errors of the gradient and second derivatives of f at i
    std::pair<double, double> errors(const quadratic& f, const label i) const
    {
        const particleField& x = fx[0].x;
        const double fi = f(x, i);
        vectorD<Dim> g = vectorD<Dim>::Zero();
        tensorD<Dim> h = tensorD<Dim>::Zero();
        for (label q = rel->offset(i); q < rel->offset(i + 1); ++q)
        {
            const double df = f(x, rel->index(q)) - fi;
            g += df*cvec<Dim>(G.data(), q);
            h += df*ctens<Dim>(H.data(), q);
        }
        double eg = 0, eh = 0;
        for (label p = 0; p < Dim; ++p)
        {
            eg = std::max(eg, std::abs(g(p) - f.gradient(x, i, p)));
            for (label r = 0; r < Dim; ++r)
            {
                eh = std::max(eh, std::abs(h(p, r) - f.C[p][r]));
            }
        }
        return {eg, eh};
    }

    //- Whether H of all of i's pairs is zero (a fit of order 1)
    bool orderOne(const label i) const
    {
        for
        (
            size_t k = size_t(rel->offset(i))*Dim*Dim;
            k < size_t(rel->offset(i + 1))*Dim*Dim;
            ++k
        )
        {
            if (H[k] != 0) return false;
        }
        return true;
    }
};


template<int Dim, class Weight>
void expectFitExact(const std::string& kernelDict, const std::string& what)
{
    fitBlock<Dim> b(kernelDict);

    // Order 1: linear fields exact, no second derivatives
    EXPECT_EQ(b.template fit<Weight>(1), 0) << what;
    for (label i = 0; i < b.n(); ++i)
    {
        EXPECT_EQ(b.resolved[i], 1) << what << ": particle " << i;
        EXPECT_LT(b.errors(linear3, i).first, 1e-10) << what << ": " << i;
        EXPECT_TRUE(b.orderOne(i)) << what << ": " << i;
    }

    // Order 2: quadratic fields exact, corners included
    EXPECT_EQ(b.template fit<Weight>(2), 0) << what;
    for (label i = 0; i < b.n(); ++i)
    {
        EXPECT_EQ(b.resolved[i], 1) << what << ": particle " << i;
        const auto e = b.errors(quadratic3, i);
        EXPECT_LT(e.first, 1e-10) << what << ": gradient at " << i;
        EXPECT_LT(e.second, 1e-9) << what << ": 2nd derivatives at " << i;
        EXPECT_LT(b.errors(linear3, i).first, 1e-10) << what << ": " << i;
    }

    // ... which order 1 is not, at the corner
    b.template fit<Weight>(1);
    EXPECT_GT(b.errors(quadratic3, 0).first, 1e-4) << what;
}

} // End anonymous namespace


TEST(correctionMatrix, fitWeightsExactToTheirOrder2D)
{
    using namespace correctionMatrix;
    expectFitExact<2, kernelWeight>(gaussian, "2D, kernel weight");
    expectFitExact<2, gradientWeight>(wendland, "2D, gradient weight");
}

TEST(correctionMatrix, fitWeightsExactToTheirOrder3D)
{
    using namespace correctionMatrix;
    expectFitExact<3, kernelWeight>(gaussian, "3D, kernel weight");
    expectFitExact<3, gradientWeight>(wendland, "3D, gradient weight");
}


template<int Dim>
void expectBrokenPairFallsBackToOrderOne()
{
    using correctionMatrix::gradientWeight;
    fitBlock<Dim> b(wendland);
    const label nSide = Dim == 2 ? 9 : 6;
    label mid = 0;
    for (label d = Dim - 1; d >= 0; --d) mid = mid*nSide + nSide/2;

    // Drop one pair of the middle particle and one of the corner's
    std::vector<char> intact(b.rel->nPairs(), 1);
    const label qMid = b.rel->offset(mid) + 2;
    const label qCorner = b.rel->offset(0);
    intact[qMid] = 0;
    intact[qCorner] = 0;
    EXPECT_EQ(b.template fit<gradientWeight>(2, intact.data()), 0);

    for (label i = 0; i < b.n(); ++i)
    {
        EXPECT_EQ(b.resolved[i], 1) << i;
        EXPECT_LT(b.errors(linear3, i).first, 1e-10) << "linear at " << i;
        if (i == mid || i == 0)
        {
            EXPECT_TRUE(b.orderOne(i)) << "order 1 at " << i;
        }
        else
        {
            // Not a neighbour's broken pair: still of order 2
            const auto e = b.errors(quadratic3, i);
            EXPECT_LT(e.first, 1e-10) << "quadratic at " << i;
            EXPECT_LT(e.second, 1e-9) << "quadratic at " << i;
        }
    }
    for (const label q : {qMid, qCorner})
    {
        for (label d = 0; d < Dim; ++d) EXPECT_EQ(b.G[q*Dim + d], 0.0) << q;
    }
}

TEST(correctionMatrix, fitWeightsBrokenPairFallsBackToOrderOne)
{
    expectBrokenPairFallsBackToOrderOne<2>();
    expectBrokenPairFallsBackToOrderOne<3>();
}


TEST(correctionMatrix, fitWeightsIsolatedParticleIsUnresolved)
{
    fitBlock<2> b(wendland, true);
    const label iso = b.n() - 1;
    EXPECT_EQ(b.rel->offset(iso + 1), b.rel->offset(iso)) << "no neighbour";
    EXPECT_EQ(b.fit<correctionMatrix::gradientWeight>(2), 1);
    EXPECT_EQ(b.resolved[iso], 0);
    for (label i = 0; i < iso; ++i) EXPECT_EQ(b.resolved[i], 1) << i;

    // A pair of particles alone: order 1 singular in 2D, G = 0
    meshlessTest::pairFixture fx(2);
    fx.addBody({0, 0, 0.01, 0}, 1e-4);
    autoPtr<smoothingKernel> W = meshlessTest::kernel(2, 0.01, wendland);
    const neighbourRelation& rel = fx.relate(0, 0, *W);
    ASSERT_EQ(rel.nPairs(), 2);
    std::vector<double> G(4, -1);
    std::vector<char> resolved(2, 1);
    EXPECT_EQ
    (
        correctionMatrix::fitWeights<2>
        (
            rel, fx.V(0), correctionMatrix::gradientWeight(), 1, 0.01,
            nullptr, G.data(), nullptr, resolved.data()
        ),
        2
    );
    EXPECT_EQ(resolved[0], 0);
    EXPECT_EQ(resolved[1], 0);
    for (const double g : G) EXPECT_EQ(g, 0.0);
}


// ************************************************************************* //

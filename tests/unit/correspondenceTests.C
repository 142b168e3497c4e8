/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    The correspondence core shared by tlsph and nosbPd
    (correspondenceOperators.H over the reference relation, with the fit
    of correctionMatrix::fitWeights):

    - the two weightings (kernel gradient: c = -V_b W'(r)/r, L = h, tlsph;
      kernel: c = W(r) V_b, L = horizon, nosbPd) give the same F, the
      exact one, for the same affine map (orders 1 and 2) and quadratic map
      (order 2) at every particle of a jittered lattice block, corners
      included, 2D and 3D, with either kernel;
    - internalForce's forces sum to zero (linear momentum) and their
      moments too (angular momentum, an objective law) to round-off for a
      random displacement, with both weightings and both orders;
    - surfaceNormals on a lattice block: along every axis, zero where no
      face cuts the support (so zero at interior particles with a full
      support) and pointing out across the face that cuts it (positive dot
      product with the face normal on every face particle, along the
      normal at face centres).

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "referenceBlock.H"
#include "constitutiveLaw.H"
#include "smallTensor.H"
#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::meshless;
using meshlessTest::weighting;

namespace
{

const std::string cubicSplineDict =
    "type cubicSpline; smoothingLengthRatio 1.2;";

const std::string gaussianDict =
    "type gaussian; smoothingLengthRatio 1.2; horizon 3;";


//- x = A X + c (+ Q(X) when quadratic) and its exact F at X
template<int Dim>
struct testMap
{
    bool quadratic;
    double q = 2.0;     // 1/m: strains of order q L = 0.14 on the block

    static tensorD<Dim> A()
    {
        tensorD<Dim> M;
        if (Dim == 2) M << 1.1, 0.3, -0.2, 0.9;
        else M << 1.1, 0.3, 0.05, -0.2, 0.9, 0.1, 0.02, -0.15, 1.2;
        return M;
    }

    vectorD<Dim> operator()(const double* X) const
    {
        const Eigen::Map<const vectorD<Dim>> Xv(X);
        vectorD<Dim> x = A()*Xv;
        for (int i = 0; i < Dim; ++i) x(i) += 0.01*(i + 1);
        if (quadratic)
        {
            x(0) += q*X[0]*X[1];
            x(1) += 0.5*q*(X[0]*X[0] - X[1]*X[1]);
            if (Dim == 3) x(2) += q*X[1]*X[2] + q*X[0]*X[2];
        }
        return x;
    }

    tensorD<Dim> F(const double* X) const
    {
        tensorD<Dim> Fx = A();
        if (quadratic)
        {
            Fx(0, 0) += q*X[1];
            Fx(0, 1) += q*X[0];
            Fx(1, 0) += q*X[0];
            Fx(1, 1) -= q*X[1];
            if (Dim == 3)
            {
                Fx(2, 0) += q*X[2];
                Fx(2, 1) += q*X[2];
                Fx(2, 2) += q*(X[1] + X[0]);
            }
        }
        return Fx;
    }

    template<class Block>
    std::vector<double> place(const Block& b) const
    {
        std::vector<double> x(size_t(b.n())*Dim);
        for (label a = 0; a < b.n(); ++a)
        {
            vec<Dim>(x.data(), a) = (*this)(b.X() + size_t(a)*Dim);
        }
        return x;
    }
};


template<int Dim>
std::unique_ptr<meshlessTest::referenceBlock<Dim>> jitteredBlock
(
    const std::string& kernelDict,
    const double dx
)
{
    const std::vector<double> X =
        meshlessTest::jitteredPoints(Dim, Dim == 2 ? 10 : 7, dx, 0.2, 9);
    const std::vector<double> V(X.size()/Dim, std::pow(dx, Dim));
    return std::unique_ptr<meshlessTest::referenceBlock<Dim>>
    (
        new meshlessTest::referenceBlock<Dim>(X, V, dx, kernelDict)
    );
}


template<int Dim>
void expectSameExactF(const std::string& kernelDict)
{
    const double dx = 0.01;
    auto b = jitteredBlock<Dim>(kernelDict, dx);
    const label n = b->n();

    for (const label order : {1, 2})
    {
        for (const bool quadratic : {false, true})
        {
            if (quadratic && order == 1) continue;
            const testMap<Dim> map{quadratic};
            const std::vector<double> x = map.place(*b);
            std::vector<double> F[2];
            const weighting ws[2] =
                {weighting::kernel, weighting::kernelGradient};
            for (int k = 0; k < 2; ++k)
            {
                EXPECT_EQ(b->fit(ws[k], order), 0);
                EXPECT_EQ(meshlessTest::countFlags(b->resolved), n);
                F[k] = b->F(x);
            }
            double err[2] = {0, 0}, diff = 0;
            for (label a = 0; a < n; ++a)
            {
                const tensorD<Dim> Fx = map.F(b->X() + size_t(a)*Dim);
                for (int k = 0; k < 2; ++k)
                {
                    err[k] = std::max
                    (
                        err[k],
                        (ctens<Dim>(F[k].data(), a) - Fx).cwiseAbs().maxCoeff()
                    );
                }
                diff = std::max
                (
                    diff,
                    (ctens<Dim>(F[0].data(), a) - ctens<Dim>(F[1].data(), a))
                    .cwiseAbs().maxCoeff()
                );
            }
            const std::string what =
                std::to_string(Dim) + "D, " + kernelDict + " order "
              + std::to_string(order) + (quadratic ? ", quadratic" : ", affine");
            EXPECT_LT(err[0], 1e-10) << what << ", " << weightingName(ws[0]);
            EXPECT_LT(err[1], 1e-10) << what << ", " << weightingName(ws[1]);
            EXPECT_LT(diff, 1e-10) << what << ": the weightings differ";
        }
    }
}


autoPtr<constitutiveLaw> stVenantKirchhoff(const label dim)
{
    particleSet set("solid", dim);
    return constitutiveLaw::New
    (
        meshlessTest::dictFrom
        (
            std::string("constitutiveLaw { type stVenantKirchhoff; E 1e6;")
          + " nu 0.3;" + (dim == 2 ? " plane strain;" : "") + " }"
        ),
        dim,
        set
    );
}


template<int Dim>
void expectMomentumConserved(const std::string& kernelDict)
{
    const double dx = 0.01;
    auto b = jitteredBlock<Dim>(kernelDict, dx);
    const label n = b->n();
    const autoPtr<constitutiveLaw> law = stVenantKirchhoff(Dim);

    std::vector<double> x = testMap<Dim>{false}.place(*b);
    std::mt19937_64 gen(13);
    std::uniform_real_distribution<double> u(-0.2*dx, 0.2*dx);
    for (auto& v : x) v += u(gen);

    for (const weighting w : {weighting::kernel, weighting::kernelGradient})
    {
        for (const label order : {1, 2})
        {
            EXPECT_EQ(b->fit(w, order), 0);
            const std::vector<double> F = b->F(x);
            std::vector<double> P(size_t(n)*Dim*Dim);
            for (label a = 0; a < n; ++a)
            {
                const tensor Fa = toTensor(F.data(), a, Dim);
                fromTensor(law->stress(a, Fa, Fa), a, Dim, P.data());
            }
            const std::vector<double> f = b->internalForce(P);

            vectorD<Dim> sum = vectorD<Dim>::Zero();
            vector torque(Zero);
            double scale = 0, tscale = 0;
            for (label a = 0; a < n; ++a)
            {
                const vectorD<Dim> fa = cvec<Dim>(f.data(), a);
                sum += fa;
                scale += fa.cwiseAbs().sum();
                vector xa(Zero), fv(Zero);
                for (int i = 0; i < Dim; ++i)
                {
                    xa[i] = x[a*Dim + i];
                    fv[i] = fa(i);
                }
                torque += xa ^ fv;
                tscale += mag(xa)*mag(fv);
            }
            const std::string what =
                std::to_string(Dim) + "D, " + kernelDict + " "
              + weightingName(w) + ", order " + std::to_string(order);
            ASSERT_GT(scale, 0) << what;
            for (int i = 0; i < Dim; ++i)
            {
                EXPECT_LT(std::abs(sum(i))/scale, 1e-13) << what;
            }
            EXPECT_LT(mag(torque)/tscale, 1e-12) << what << ": torque";
        }
    }
}

} // End anonymous namespace


TEST(correspondence, bothWeightingsGiveTheSameExactF2D)
{
    expectSameExactF<2>(cubicSplineDict);
    expectSameExactF<2>(gaussianDict);
}


TEST(correspondence, bothWeightingsGiveTheSameExactF3D)
{
    expectSameExactF<3>(cubicSplineDict);
    expectSameExactF<3>(gaussianDict);
}


TEST(correspondence, internalForceConservesMomentum2D)
{
    expectMomentumConserved<2>(cubicSplineDict);
    expectMomentumConserved<2>(gaussianDict);
}


TEST(correspondence, internalForceConservesMomentum3D)
{
    expectMomentumConserved<3>(cubicSplineDict);
    expectMomentumConserved<3>(gaussianDict);
}


// * * * * * * * * * * * * * * * surfaceNormals  * * * * * * * * * * * * * * //

namespace
{

//- N_a = -sum_b V_b grad_a W_ab on a lattice block of n^Dim particles
//  (n odd: the faces have centre particles; no support cut by two
//  opposite faces). A lattice point at offset -k e_d (k > 0) lies in the
//  support when k dx < R (the kernel's weight is positive inside): the
//  face d- cuts a particle's support when (c_d + 1) dx < R, c_d its
//  lattice index
template<int Dim>
void expectSurfaceNormals(const std::string& kernelDict, const label n)
{
    const double dx = 0.01;
    const std::vector<double> X = meshlessTest::latticePoints(Dim, n, dx);
    const std::vector<double> V(X.size()/Dim, std::pow(dx, Dim));
    const meshlessTest::referenceBlock<Dim> b(X, V, dx, kernelDict);
    const label np = b.n();
    const double R = b.W->radius();
    ASSERT_LT(2*R, (n - 1)*dx) << "a support cut by two opposite faces";

    std::vector<double> N(size_t(np)*Dim, -1);
    correspondence::surfaceNormals<Dim>(b.rel(), b.V(), N.data());

    double largest = 0;
    for (label a = 0; a < np; ++a)
    {
        largest = std::max(largest, cvec<Dim>(N.data(), a).norm());
    }
    ASSERT_GT(largest, 0);

    const std::string what = std::to_string(Dim) + "D, " + kernelDict;
    label nInterior = 0, nFace = 0, nCentre = 0;
    for (label a = 0; a < np; ++a)
    {
        label c[3] = {a % n, (a/n) % n, a/(n*n)};
        const vectorD<Dim> Na = cvec<Dim>(N.data(), a);
        bool full = true, onFace = false;
        label nCut = 0;
        vectorD<Dim> outward = vectorD<Dim>::Zero();
        for (int d = 0; d < Dim; ++d)
        {
            const bool low = (c[d] + 1)*dx < R;
            const bool high = (n - c[d])*dx < R;
            full = full && !low && !high;
            nCut += low || high;
            if (!low && !high)
            {
                EXPECT_LT(std::abs(Na(d)), 1e-12*largest)
                    << what << ", particle " << a << ", axis " << d
                    << ": no face cuts the support";
            }
            else
            {
                // Out across the cut face: -e_d at the low face
                const double out = low ? -Na(d) : Na(d);
                EXPECT_GT(out, 1e-9*largest)
                    << what << ", particle " << a << ", axis " << d;
            }
            if (c[d] == 0 || c[d] == n - 1)
            {
                // On the face: positive dot product with its normal
                vectorD<Dim> normal = vectorD<Dim>::Zero();
                normal(d) = c[d] == 0 ? -1 : 1;
                EXPECT_GT(Na.dot(normal), 0)
                    << what << ", face particle " << a << ", axis " << d;
                onFace = true;
                outward = normal;
            }
        }
        if (full)
        {
            ++nInterior;
            EXPECT_LT(Na.norm(), 1e-12*largest)
                << what << ", interior particle " << a;
        }
        nFace += onFace;

        // A face centre: on one face, in the middle of the others
        bool centre = onFace && nCut == 1;
        for (int d = 0; d < Dim; ++d)
        {
            if (c[d] != 0 && c[d] != n - 1) centre = centre && 2*c[d] == n - 1;
        }
        if (centre)
        {
            ++nCentre;
            const double cosAngle = Na.dot(outward)/Na.norm();
            EXPECT_GT(cosAngle, std::cos(2*M_PI/180))
                << what << ", face centre " << a << ": within 2 degrees";
            const vectorD<Dim> tangential = Na - Na.dot(outward)*outward;
            EXPECT_LT(tangential.norm(), 1e-12*Na.norm())
                << what << ", face centre " << a << ": along the normal";
        }
    }
    EXPECT_GT(nInterior, 0) << what;
    EXPECT_EQ(nFace, label(std::pow(n, Dim) - std::pow(n - 2, Dim))) << what;
    EXPECT_EQ(nCentre, 2*Dim) << what;
}

} // End anonymous namespace


TEST(correspondence, surfaceNormalsVanishInsideAndPointOut2D)
{
    expectSurfaceNormals<2>(cubicSplineDict, 11);
    expectSurfaceNormals<2>(gaussianDict, 11);
}


TEST(correspondence, surfaceNormalsVanishInsideAndPointOut3D)
{
    expectSurfaceNormals<3>(cubicSplineDict, 9);
    expectSurfaceNormals<3>(gaussianDict, 9);
}


// ************************************************************************* //

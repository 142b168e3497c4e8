/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    The sub-iterations of a partitioned coupling step: interfaceQuasiNewton
    (IQN-ILS) on a linear fixed point x = A x + b whose plain iteration
    diverges as a staggered exchange with a large added mass does (an
    eigenvalue -15 of A, the mass ratio of the hydrostatic plate), and
    particleSetState, which sets a body back to the step's start.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "testHelpers.H"
#include "interfaceQuasiNewton.H"
#include "particleSetState.H"
#include <cmath>
#include <random>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

//- A = V diag(lambda) V^T, V orthonormal (random, seeded)
struct linearMap
{
    label n;
    std::vector<double> A;

    linearMap(const std::vector<double>& lambda, const unsigned seed)
    :
        n(lambda.size()),
        A(n*n, 0.0)
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<std::vector<double>> V(n, std::vector<double>(n));
        for (label k = 0; k < n; ++k)
        {
            for (label i = 0; i < n; ++i) V[k][i] = u(gen);
            for (label j = 0; j < k; ++j)
            {
                double s = 0;
                for (label i = 0; i < n; ++i) s += V[j][i]*V[k][i];
                for (label i = 0; i < n; ++i) V[k][i] -= s*V[j][i];
            }
            double s = 0;
            for (label i = 0; i < n; ++i) s += V[k][i]*V[k][i];
            for (label i = 0; i < n; ++i) V[k][i] /= std::sqrt(s);
        }
        for (label k = 0; k < n; ++k)
        {
            for (label i = 0; i < n; ++i)
            {
                for (label j = 0; j < n; ++j)
                {
                    A[i*n + j] += lambda[k]*V[k][i]*V[k][j];
                }
            }
        }
    }

    //- H(x) = A x + b
    std::vector<double> operator()
    (
        const std::vector<double>& x,
        const std::vector<double>& b
    ) const
    {
        std::vector<double> y(b);
        for (label i = 0; i < n; ++i)
        {
            for (label j = 0; j < n; ++j) y[i] += A[i*n + j]*x[j];
        }
        return y;
    }
};

//- Eigenvalues of an added-mass-like exchange: a piston mode at -15, the
//  others between -2.4 and 0.3
std::vector<double> addedMassSpectrum(const label n)
{
    std::vector<double> lambda(n);
    lambda[0] = -15;
    for (label k = 1; k < n; ++k) lambda[k] = -2.4 + 2.7*k/(n - 1);
    return lambda;
}

//- Iterate one step from x; the iterations it took
label solveStep
(
    interfaceQuasiNewton& iqn,
    const linearMap& H,
    const std::vector<double>& b,
    std::vector<double>& x
)
{
    iqn.beginStep();
    for (label k = 0; ; ++k)
    {
        const std::vector<double> xt = H(x, b);
        if (iqn.update(x, xt, k))
        {
            x = xt;
            break;
        }
    }
    iqn.endStep();
    return iqn.iterations();
}

//- The fixed point's residual max_i |H(x)_i - x_i| relative to max_i |x_i|
double fixedPointError
(
    const linearMap& H,
    const std::vector<double>& b,
    const std::vector<double>& x
)
{
    const std::vector<double> y = H(x, b);
    double r = 0, s = 0;
    for (size_t i = 0; i < x.size(); ++i)
    {
        r = std::max(r, std::abs(y[i] - x[i]));
        s = std::max(s, std::abs(x[i]));
    }
    return r/s;
}

} // End anonymous namespace


TEST(interfaceQuasiNewton, convergesWhereThePlainExchangeDiverges)
{
    const label n = 12;
    const linearMap H(addedMassSpectrum(n), 7);
    std::vector<double> b(n);
    for (label i = 0; i < n; ++i) b[i] = 1 + 0.1*i;

    // The plain exchange x <- H(x) grows by 15 per iteration
    {
        std::vector<double> x(n, 0.0);
        for (label k = 0; k < 10; ++k) x = H(x, b);
        double m = 0;
        for (double v : x) m = std::max(m, std::abs(v));
        EXPECT_GT(m, 1e8);
    }

    interfaceQuasiNewton iqn
    (
        meshlessTest::dictFrom
        (
            "maxIterations 50; tolerance 1e-10; initialRelaxation 0.05;"
            " reuse 0;"
        )
    );
    std::vector<double> x(n, 0.0);
    const label its = solveStep(iqn, H, b, x);
    // A secant method in n dimensions: at most n + 2 evaluations
    EXPECT_LE(its, n + 2);
    EXPECT_LT(fixedPointError(H, b, x), 1e-8);
    EXPECT_EQ(iqn.unconvergedSteps(), 0);
}


TEST(interfaceQuasiNewton, reusedColumnsSpeedTheNextSteps)
{
    const label n = 12;
    const linearMap H(addedMassSpectrum(n), 11);
    const dictionary reuse
    (
        meshlessTest::dictFrom
        (
            "maxIterations 50; tolerance 1e-8; initialRelaxation 0.05;"
            " reuse 4; filter 1e-8;"
        )
    );
    interfaceQuasiNewton iqn(reuse);
    std::vector<double> x(n, 0.0);
    label first = 0, last = 0;
    for (label step = 0; step < 6; ++step)
    {
        // The load changes from step to step, the map does not
        std::vector<double> b(n);
        for (label i = 0; i < n; ++i) b[i] = std::sin(0.3*step + i);
        const label its = solveStep(iqn, H, b, x);
        EXPECT_LT(fixedPointError(H, b, x), 1e-6) << "step " << step;
        if (step == 0) first = its;
        last = its;
    }
    // The columns of the first steps span the map: the later steps take
    // one or two evaluations beyond the first
    EXPECT_LE(last, 3);
    EXPECT_LT(last, first);
}


TEST(interfaceQuasiNewton, restartsWhereTheResponseSwitches)
{
    // x = A x + b + K max(0, x_0 - theta) e_0: a response that switches
    // (as a pressure floor does) steepens by K past theta
    const label n = 12;
    const linearMap H(addedMassSpectrum(n), 5);
    std::vector<double> b(n);
    for (label i = 0; i < n; ++i) b[i] = std::cos(1.0 + i);
    const double K = -40, theta = -0.05;
    const auto kinked = [&](const std::vector<double>& x)
    {
        std::vector<double> y = H(x, b);
        y[0] += K*std::max(0.0, x[0] - theta);
        return y;
    };
    interfaceQuasiNewton iqn
    (
        meshlessTest::dictFrom
        (
            "maxIterations 60; tolerance 1e-10; initialRelaxation 0.05;"
            " reuse 0;"
        )
    );
    std::vector<double> x(n, 0.0);
    iqn.beginStep();
    label k = 0;
    std::vector<double> xt;
    for (; ; ++k)
    {
        xt = kinked(x);
        if (iqn.update(x, xt, k)) break;
    }
    iqn.endStep();
    double r = 0, s = 0;
    for (label i = 0; i < n; ++i)
    {
        r = std::max(r, std::abs(xt[i] - x[i]));
        s = std::max(s, std::abs(xt[i]));
    }
    Info<< "    switching response: " << iqn.iterations() << " iterations, "
        << iqn.restarts() << " restarts, residual " << r/s << endl;
    // The secants across the switch overshoot: one restart (measured)
    EXPECT_GE(iqn.restarts(), 1);
    EXPECT_EQ(iqn.unconvergedSteps(), 0);
    EXPECT_LT(r/s, 1e-8);
}


TEST(interfaceQuasiNewton, aRelaxedStepThatGrowsTheResidualIsNoRestart)
{
    // An added-mass ratio of 200: the first, relaxed step (0.1) grows the
    // residual 19 times; the secants that follow converge, no restart
    const label n = 12;
    std::vector<double> lambda = addedMassSpectrum(n);
    lambda[0] = -200;
    const linearMap H(lambda, 9);
    std::vector<double> b(n, 1.0);
    interfaceQuasiNewton iqn
    (
        meshlessTest::dictFrom
        (
            "maxIterations 50; tolerance 1e-10; initialRelaxation 0.1;"
            " reuse 0;"
        )
    );
    std::vector<double> x(n, 0.0);
    EXPECT_LE(solveStep(iqn, H, b, x), n + 2);
    EXPECT_EQ(iqn.restarts(), 0);
    EXPECT_EQ(iqn.unconvergedSteps(), 0);
    EXPECT_LT(fixedPointError(H, b, x), 1e-8);
}


TEST(interfaceQuasiNewton, stopsAtMaxIterationsAndCountsIt)
{
    const label n = 12;
    const linearMap H(addedMassSpectrum(n), 3);
    std::vector<double> b(n, 1.0);
    interfaceQuasiNewton iqn
    (
        meshlessTest::dictFrom("maxIterations 3; tolerance 1e-12; reuse 0;")
    );
    std::vector<double> x(n, 0.0);
    EXPECT_EQ(solveStep(iqn, H, b, x), 3);
    EXPECT_EQ(iqn.unconvergedSteps(), 1);
    EXPECT_GT(iqn.residual(), 1e-12);
}


TEST(interfaceQuasiNewton, aStepAtMaxIterationsEndsAtItsLeastIterate)
{
    // Responses prescribed iteration by iteration: the first is the least
    // (|r|/|x~| = 0.1/1.1), the second's residual is 5 times its x~
    interfaceQuasiNewton iqn
    (
        meshlessTest::dictFrom("maxIterations 2; tolerance 1e-6; reuse 0;")
    );
    iqn.beginStep();
    std::vector<double> x{1, 0};
    ASSERT_FALSE(iqn.update(x, {1.1, 0}, 0));
    const std::vector<double> x1(x);
    EXPECT_NE(x1[0], 1.0);
    ASSERT_TRUE(iqn.update(x, {x1[0] + 5, 1}, 1));
    EXPECT_EQ(x, x1);                       // unchanged at maxIterations
    ASSERT_TRUE(iqn.leastIterate(x));
    EXPECT_EQ(x, (std::vector<double>{1, 0}));
    EXPECT_EQ(iqn.leastIteration(), 1);
    EXPECT_NEAR(iqn.leastResidual(), 0.1/1.1, 1e-14);
    EXPECT_EQ(iqn.iterations(), 3);         // the extra evaluation counted
    iqn.endStep();
    EXPECT_EQ(iqn.unconvergedSteps(), 1);
    EXPECT_EQ(iqn.mostIterations(), 3);

    // The last iterate the least: nothing to go back to
    iqn.beginStep();
    std::vector<double> y{1, 0};
    ASSERT_FALSE(iqn.update(y, {3, 0}, 0));
    ASSERT_TRUE(iqn.update(y, {y[0] + 1e-3, 0}, 1));
    const std::vector<double> y1(y);
    EXPECT_FALSE(iqn.leastIterate(y));
    EXPECT_EQ(y, y1);
    EXPECT_EQ(iqn.iterations(), 2);
    iqn.endStep();
}


TEST(interfaceQuasiNewton, reusedColumnsDroppedHalfwayThroughAStep)
{
    // A step converged (its columns kept for reuse), then a step whose
    // response has no fixed point (H(x)_i = x_i + 1 + sin(x_i)/2: the
    // residual between 0.5 and 1.5 per component, never 10 times its
    // smallest, so no restart for growth): at half maxIterations
    // the reused columns are dropped once (a restart); without reuse there
    // are none to drop
    const label n = 6;
    const linearMap H(addedMassSpectrum(n), 5);
    const std::vector<double> b(n, 1.0);
    for (const label reuse : {8, 0})
    {
        interfaceQuasiNewton iqn
        (
            meshlessTest::dictFrom
            (
                "maxIterations 10; tolerance 1e-8; initialRelaxation 0.05;"
                " reuse " + std::to_string(reuse) + ";"
            )
        );
        std::vector<double> x(n, 0.0);
        solveStep(iqn, H, b, x);
        ASSERT_EQ(iqn.unconvergedSteps(), 0);
        const label restarts = iqn.restarts();

        iqn.beginStep();
        for (label k = 0; ; ++k)
        {
            std::vector<double> xt(x);
            for (double& v : xt) v += 1 + 0.5*std::sin(v);
            if (iqn.update(x, xt, k)) break;
        }
        iqn.endStep();
        EXPECT_EQ(iqn.iterations(), 10);
        EXPECT_EQ(iqn.unconvergedSteps(), 1);
        EXPECT_EQ(iqn.restarts() - restarts, reuse ? 1 : 0)
            << "reuse " << reuse;
    }
}


TEST(interfaceQuasiNewton, badInputNamesTheKeyword)
{
    const std::string tol = meshlessTest::fatalMessage([]
    {
        interfaceQuasiNewton
        (
            meshlessTest::dictFrom("maxIterations 10; tolerance 2;")
        );
    });
    EXPECT_NE(tol.find("tolerance"), std::string::npos) << tol;

    const std::string its = meshlessTest::fatalMessage([]
    {
        interfaceQuasiNewton
        (
            meshlessTest::dictFrom("maxIterations 0; tolerance 1e-4;")
        );
    });
    EXPECT_NE(its.find("maxIterations"), std::string::npos) << its;

    const std::string missing = meshlessTest::fatalMessage([]
    {
        interfaceQuasiNewton(meshlessTest::dictFrom("tolerance 1e-4;"));
    });
    EXPECT_NE(missing.find("maxIterations"), std::string::npos) << missing;
}


TEST(particleSetState, restoresEveryFieldExactly)
{
    particleSet s("plate", 2);
    s.resize(5);
    particleField& U = s.addField("U", particleField::kind::vector);
    particleField& an = s.addScratchField("an", particleField::kind::vector);
    for (label i = 0; i < 5; ++i)
    {
        s.positions()(i, 0) = 0.1*i;
        U(i, 1) = -1.0*i;
        an(i, 0) = 3.0 + i;
    }
    const std::vector<double> x0
    (
        s.positions().data(), s.positions().data() + 10
    );
    particleSetState state;
    state.save(s);
    for (label k = 0; k < 10; ++k)
    {
        s.positions().data()[k] += 1;
        U.data()[k] *= 2;
        an.data()[k] = -7;
    }
    state.restore();
    for (label k = 0; k < 10; ++k)
    {
        EXPECT_EQ(s.positions().data()[k], x0[k]);
    }
    for (label i = 0; i < 5; ++i)
    {
        EXPECT_EQ(U(i, 1), -1.0*i);
        EXPECT_EQ(U(i, 0), 0.0);
        EXPECT_EQ(an(i, 0), 3.0 + i);
    }

    // A field left out of the save keeps its value
    particleSetState partial;
    partial.save(s, {&an});
    an.data()[0] = 42;
    U.data()[0] = 42;
    partial.restore();
    EXPECT_EQ(an(0, 0), 42.0);
    EXPECT_EQ(U(0, 0), 0.0);

    // Other particles: refused, naming the set
    s.resize(6);
    const std::string msg = meshlessTest::fatalMessage([&]{ state.restore(); });
    EXPECT_NE(msg.find("plate"), std::string::npos) << msg;
}


// ************************************************************************* //

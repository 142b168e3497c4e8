/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    Sparse linear solvers of the pressure Poisson equation: sparseMatrix's
    product, residual, diagonal-first check and grow-only buffers; every
    solver (CG, BiCGStab, BoomerAMG with PCG, GMRES or BiCGSTAB) against
    Eigen's SparseLU on the 5-point Poisson matrix of a 40 x 40 grid with
    Dirichlet boundaries (symmetric) and an upwind convection-diffusion one
    (not symmetric): the solution, the reported residuals (the true ones),
    a warm start from the solution, maxIter reached, b = 0, a solver used
    again on other sizes; and the errors of bad input.

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>
#include "linearSolver.H"
#include "eigenSolver.H"
#include "testHelpers.H"
#include "BoomerAMG.H"
#include <Eigen/SparseLU>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using namespace Foam;
using namespace Foam::meshless;

namespace
{

//- A x = b and its direct solution
struct linearSystem
{
    sparseMatrix A;
    std::vector<double> b;
    std::vector<double> xDirect;

    label n() const { return A.n(); }
};


//- The solution of the n x n system of the triplets by Eigen's SparseLU
std::vector<double> directSolve
(
    const label n,
    const std::vector<Eigen::Triplet<double>>& triplets,
    const std::vector<double>& b
)
{
    Eigen::SparseMatrix<double> direct(n, n);
    direct.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(direct);
    const Eigen::VectorXd x =
        lu.solve(Eigen::Map<const Eigen::VectorXd>(b.data(), n));
    return std::vector<double>(x.data(), x.data() + n);
}


//- The 5-point matrix of -Laplacian (times h^2) on m x m interior points of
//  a grid with Dirichlet boundaries, with upwind convection of cell Peclet
//  number pe along x and y (pe = 0: symmetric positive definite). Each row
//  diagonal first, then west, east, south, north. b of smooth and rough
//  parts; xDirect by Eigen's SparseLU.
linearSystem gridSystem(const label m, const double pe)
{
    linearSystem s;
    const label n = m*m;
    const label nnz = 5*n - 4*m;
    s.A.resize(n, nnz);
    s.A.setSymmetric(pe == 0);

    label* rowStart = s.A.rowStart();
    label* columns = s.A.columns();
    double* values = s.A.values();
    std::vector<Eigen::Triplet<double>> triplets;

    label k = 0;
    for (label j = 0; j < m; ++j)
    {
        for (label i = 0; i < m; ++i)
        {
            const label row = i + m*j;
            rowStart[row] = k;
            const auto add = [&](const label col, const double v)
            {
                columns[k] = col;
                values[k] = v;
                ++k;
                triplets.emplace_back(row, col, v);
            };
            add(row, 4 + 2*pe);
            if (i > 0) add(row - 1, -1 - pe);
            if (i < m - 1) add(row + 1, -1);
            if (j > 0) add(row - m, -1 - pe);
            if (j < m - 1) add(row + m, -1);
        }
    }
    rowStart[n] = k;

    s.b.resize(n);
    for (label i = 0; i < n; ++i)
    {
        s.b[i] = 1 + std::sin(0.1*i) + 0.5*std::cos(7.3*i);
    }

    s.xDirect = directSolve(n, triplets, s.b);
    return s;
}


double relativeDifference
(
    const std::vector<double>& x,
    const std::vector<double>& y
)
{
    double d = 0, ny = 0;
    for (size_t i = 0; i < x.size(); ++i)
    {
        d += (x[i] - y[i])*(x[i] - y[i]);
        ny += y[i]*y[i];
    }
    return std::sqrt(d/ny);
}


//- The true relative residual
double relativeResidual(const linearSystem& s, const std::vector<double>& x)
{
    return s.A.residualNorm(s.b.data(), x.data())/norm2(s.b.data(), s.n());
}


autoPtr<linearSolver> makeSolver(const std::string& dict)
{
    return linearSolver::New(meshlessTest::dictFrom(dict));
}


//- The solvers (dictionaries) of a symmetric or a non-symmetric matrix
std::vector<std::string> solversFor(const bool symmetric)
{
    std::vector<std::string> dicts
    {
        "solver BiCGStab;",
        "solver BoomerAMG;",
        "solver BoomerAMG; nonSymmetricSolver BiCGSTAB;"
    };
    if (symmetric)
    {
        dicts.push_back("solver CG;");
        dicts.push_back
        (
            "solver BoomerAMG; coarsening PMIS; relaxType l1Jacobi;"
        );
        dicts.push_back
        (
            "solver BoomerAMG; coarsening Falgout;"
            " relaxType symmetricGaussSeidel; strongThreshold 0.5;"
        );
    }
    return dicts;
}


//- Each solver of the grid system of each cell Peclet number (40 x 40),
//  made from its dictionary and extra entries, given to check
void forEachSolver
(
    const std::vector<double>& pecletNumbers,
    const std::string& extra,
    const std::function<void(const linearSystem&, linearSolver&)>& check
)
{
    for (const double pe : pecletNumbers)
    {
        const linearSystem s = gridSystem(40, pe);
        ASSERT_TRUE(s.A.checkDiagonalFirst());
        for (const std::string& d : solversFor(s.A.symmetric()))
        {
            SCOPED_TRACE(d + " Peclet " + std::to_string(pe));
            autoPtr<linearSolver> solver = makeSolver(d + extra);
            check(s, *solver);
        }
    }
}


//- From x = 0 to the direct solution, with the true residuals reported
void expectSolves(const linearSystem& s, linearSolver& solver)
{
    std::vector<double> x(s.n(), 0.0);
    const linearSolver::performance p =
        solver.solve(s.A, s.b.data(), x.data());

    EXPECT_EQ(p.solver, solver.type());
    EXPECT_TRUE(p.converged);
    EXPECT_GT(p.iterations, 0);
    EXPECT_DOUBLE_EQ(p.initialResidual, 1);
    EXPECT_LE(p.finalResidual, 1e-10);
    EXPECT_DOUBLE_EQ(p.finalResidual, relativeResidual(s, x));
    EXPECT_LT(relativeDifference(x, s.xDirect), 1e-6);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * sparseMatrix * * * * * * * * * * * * * * //

TEST(SparseMatrix, MultiplyResidualAndDiagonalFirst)
{
    //  | 4 -1  1 |
    //  | 2  3  0 |     columns of row 0 unsorted (diagonal first)
    //  | 0 -2  5 |
    sparseMatrix A;
    A.resize(3, 7);
    const label rowStart[] = {0, 3, 5, 7};
    const label columns[] = {0, 2, 1, 1, 0, 2, 1};
    const double values[] = {4, 1, -1, 3, 2, 5, -2};
    std::copy(rowStart, rowStart + 4, A.rowStart());
    std::copy(columns, columns + 7, A.columns());
    std::copy(values, values + 7, A.values());

    EXPECT_FALSE(A.symmetric());
    EXPECT_TRUE(A.checkDiagonalFirst());

    const double x[] = {1, 2, 3};
    double y[3];
    A.multiply(x, y);
    EXPECT_DOUBLE_EQ(y[0], 5);
    EXPECT_DOUBLE_EQ(y[1], 8);
    EXPECT_DOUBLE_EQ(y[2], 11);

    const double b[] = {5, 8, 11 + 2};
    EXPECT_DOUBLE_EQ(A.residualNorm(b, x), 2);
    EXPECT_DOUBLE_EQ(norm2(y, 3), std::sqrt(25.0 + 64 + 121));

    // Row 1 with its diagonal second
    std::swap(A.columns()[3], A.columns()[4]);
    EXPECT_FALSE(A.checkDiagonalFirst());
    std::swap(A.columns()[3], A.columns()[4]);

    // An empty row, a column out of range
    A.rowStart()[1] = 0;
    EXPECT_FALSE(A.checkDiagonalFirst());
    A.rowStart()[1] = 3;
    A.columns()[6] = 3;
    EXPECT_FALSE(A.checkDiagonalFirst());
}


TEST(SparseMatrix, ResizeOnlyGrows)
{
    sparseMatrix A;
    A.resize(100, 500);
    EXPECT_EQ(A.n(), 100);
    EXPECT_EQ(A.nnz(), 500);
    const label* rowStart = A.rowStart();
    const label* columns = A.columns();
    const double* values = A.values();

    A.resize(100, 500);
    EXPECT_EQ(A.rowStart(), rowStart);
    EXPECT_EQ(A.columns(), columns);
    EXPECT_EQ(A.values(), values);

    // Smaller, then back: the capacity is kept
    A.resize(40, 150);
    EXPECT_EQ(A.n(), 40);
    EXPECT_EQ(A.nnz(), 150);
    A.resize(100, 500);
    EXPECT_EQ(A.rowStart(), rowStart);
    EXPECT_EQ(A.columns(), columns);
    EXPECT_EQ(A.values(), values);
}


TEST(SparseMatrix, EigenSeesTheArraysWithoutACopy)
{
    const linearSystem s = gridSystem(5, 0);
    EXPECT_TRUE(s.A.checkDiagonalFirst());

    // What Eigen's iterative solvers keep of the matrix they are given
    const Eigen::Ref<const eigenCsrMatrix> ref(eigenMap(s.A));
    EXPECT_EQ(ref.valuePtr(), s.A.values());
    EXPECT_EQ(ref.innerIndexPtr(), s.A.columns());
    EXPECT_EQ(ref.outerIndexPtr(), s.A.rowStart());
}


// * * * * * * * * * * * * * * * * linearSolver * * * * * * * * * * * * * * //

TEST(LinearSolver, SymmetricPoissonMatchesDirectSolve)
{
    forEachSolver({0}, " tolerance 1e-10;", expectSolves);
}


TEST(LinearSolver, ConvectionDiffusionMatchesDirectSolve)
{
    forEachSolver({0.5}, " tolerance 1e-10;", expectSolves);
}


TEST(LinearSolver, WarmStartFromTheSolution)
{
    forEachSolver
    (
        {0, 0.5},
        " tolerance 1e-10;",
        [](const linearSystem& s, linearSolver& solver)
        {
            std::vector<double> x(s.xDirect);
            const linearSolver::performance p =
                solver.solve(s.A, s.b.data(), x.data());
            EXPECT_TRUE(p.converged);
            EXPECT_LE(p.iterations, 1);
            EXPECT_LE(p.initialResidual, 1e-10);
            EXPECT_LT(relativeDifference(x, s.xDirect), 1e-6);
        }
    );
}


TEST(LinearSolver, MaxIterReachedIsReportedNotFatal)
{
    forEachSolver
    (
        {0, 0.5},
        " tolerance 1e-10; maxIter 2;",
        [](const linearSystem& s, linearSolver& solver)
        {
            EXPECT_EQ(solver.maxIter(), 2);
            std::vector<double> x(s.n(), 0.0);
            const linearSolver::performance p =
                solver.solve(s.A, s.b.data(), x.data());
            EXPECT_FALSE(p.converged);
            EXPECT_EQ(p.iterations, 2);
            // CG's residual may grow (it minimises the error's A-norm)
            EXPECT_GT(p.finalResidual, 1e-10);
            EXPECT_TRUE(std::isfinite(p.finalResidual));
            EXPECT_DOUBLE_EQ(p.finalResidual, relativeResidual(s, x));
        }
    );
}


TEST(LinearSolver, ZeroRightHandSideGivesZero)
{
    linearSystem s = gridSystem(10, 0);
    std::fill(s.b.begin(), s.b.end(), 0.0);
    for (const std::string& d : solversFor(true))
    {
        SCOPED_TRACE(d);
        autoPtr<linearSolver> solver = makeSolver(d);
        std::vector<double> x(s.n(), 3.0);
        const linearSolver::performance p =
            solver->solve(s.A, s.b.data(), x.data());
        EXPECT_TRUE(p.converged);
        EXPECT_EQ(p.iterations, 0);
        EXPECT_EQ(p.finalResidual, 0);
        for (const double v : x) ASSERT_EQ(v, 0);
    }
}


TEST(LinearSolver, SolverKeptAcrossSizesAndMatrices)
{
    // The pattern and size change between steps of a particle method: the
    // sizes shrink and grow for each Krylov method (hypre's GMRES and
    // BiCGSTAB keep the work vectors of their first setup)
    const linearSystem small = gridSystem(20, 0);
    const linearSystem large = gridSystem(40, 0);
    const linearSystem nonSymmetric = gridSystem(30, 0.5);
    const linearSystem one = gridSystem(1, 0);
    const linearSystem four = gridSystem(2, 0.5);
    for (const std::string& d : solversFor(false))
    {
        SCOPED_TRACE(d);
        autoPtr<linearSolver> solver = makeSolver(d + " tolerance 1e-10;");
        for
        (
            const linearSystem* s
          : {&large, &small, &nonSymmetric, &one, &four, &nonSymmetric, &large}
        )
        {
            std::vector<double> x(s->n(), 0.0);
            const linearSolver::performance p =
                solver->solve(s->A, s->b.data(), x.data());
            EXPECT_TRUE(p.converged)
                << "n " << s->n() << " iterations " << p.iterations
                << " residuals " << p.initialResidual << " "
                << p.finalResidual;
            EXPECT_LT(relativeDifference(x, s->xDirect), 1e-6);
        }
    }
}


//- The grid system with its values scaled entry by entry by 1 + eps
//  sin(row + column) (the same pattern and symmetry), and its direct
//  solution
linearSystem perturbed(const linearSystem& s, const double eps)
{
    linearSystem p;
    const label n = s.n();
    const label nnz = s.A.rowStart()[n];
    p.A.resize(n, nnz);
    p.A.setSymmetric(s.A.symmetric());
    std::copy(s.A.rowStart(), s.A.rowStart() + n + 1, p.A.rowStart());
    std::copy(s.A.columns(), s.A.columns() + nnz, p.A.columns());
    std::vector<Eigen::Triplet<double>> triplets;
    for (label r = 0; r < n; ++r)
    {
        for (label k = s.A.rowStart()[r]; k < s.A.rowStart()[r + 1]; ++k)
        {
            // sin(row + column): a symmetric matrix stays symmetric
            const label c = p.A.columns()[k];
            p.A.values()[k] =
                s.A.values()[k]*(1 + eps*std::sin(double(r + c)));
            triplets.emplace_back(r, p.A.columns()[k], p.A.values()[k]);
        }
    }
    p.b = s.b;
    p.xDirect = directSolve(n, triplets, p.b);
    return p;
}


TEST(LinearSolver, BoomerAMGKeepsTheHierarchyOfANearbyMatrix)
{
    // An iterated coupling re-solves a step with the same pattern and
    // values moved slightly: the hierarchy is kept while the values moved
    // by at most reuseHierarchy of the largest entry, and the solution is
    // the new matrix's; with PCG (symmetric) and GMRES
    for (const double pe : {0.0, 0.5})
    for (const char* extra : {"", " reuseHierarchy 0;"})
    {
        SCOPED_TRACE(std::string(extra) + " Peclet " + std::to_string(pe));
        const linearSystem s0 = perturbed(gridSystem(40, pe), 0);
        const linearSystem near = perturbed(s0, 5e-4);
        const linearSystem far = perturbed(s0, 1e-2);
        ASSERT_EQ(near.A.symmetric(), pe == 0);
        ASSERT_GT(relativeDifference(near.xDirect, s0.xDirect), 1e-5);

        autoPtr<linearSolver> solver = makeSolver
        (
            std::string("solver BoomerAMG; tolerance 1e-10;") + extra
        );
        const BoomerAMG& amg = dynamic_cast<const BoomerAMG&>(*solver);
        const bool keeps = std::string(extra).empty();
        label setups = 0;
        for (const linearSystem* s : {&s0, &near, &near, &far, &s0})
        {
            std::vector<double> x(s->n(), 0.0);
            const linearSolver::performance p =
                solver->solve(s->A, s->b.data(), x.data());
            EXPECT_TRUE(p.converged);
            EXPECT_LT(relativeDifference(x, s->xDirect), 1e-7);
            // far and s0 differ by 1e-2 from the matrix before them
            setups += (!keeps || s == &s0 || s == &far);
            EXPECT_EQ(amg.hierarchySetups(), setups);
        }
    }

    // Another pattern: set up again
    autoPtr<linearSolver> solver = makeSolver("solver BoomerAMG;");
    const BoomerAMG& amg = dynamic_cast<const BoomerAMG&>(*solver);
    const linearSystem s0 = perturbed(gridSystem(40, 0.5), 0);
    const linearSystem other = perturbed(gridSystem(41, 0.5), 0);
    for (const linearSystem* s : {&s0, &other})
    {
        std::vector<double> x(s->n(), 0.0);
        EXPECT_TRUE(solver->solve(s->A, s->b.data(), x.data()).converged);
    }
    EXPECT_EQ(amg.hierarchySetups(), 2);
}


TEST(LinearSolver, BoomerAMGSetsUpAgainWhenAKeptHierarchyFails)
{
    // A kept hierarchy's solve that stops short of the tolerance goes on
    // from the x reached with the new matrix's own hierarchy (maxIter 3:
    // neither converges, 3 iterations each)
    const linearSystem s0 = perturbed(gridSystem(40, 0.5), 0);
    const linearSystem near = perturbed(s0, 5e-4);
    autoPtr<linearSolver> solver =
        makeSolver("solver BoomerAMG; tolerance 1e-12; maxIter 3;");
    const BoomerAMG& amg = dynamic_cast<const BoomerAMG&>(*solver);

    std::vector<double> x(s0.n(), 0.0);
    linearSolver::performance p = solver->solve(s0.A, s0.b.data(), x.data());
    EXPECT_FALSE(p.converged);
    EXPECT_EQ(p.iterations, 3);
    EXPECT_EQ(amg.hierarchySetups(), 1);

    std::fill(x.begin(), x.end(), 0.0);
    p = solver->solve(near.A, near.b.data(), x.data());
    EXPECT_FALSE(p.converged);
    EXPECT_EQ(p.iterations, 6);
    EXPECT_EQ(p.initialResidual, 1);
    EXPECT_LT(p.finalResidual, 1e-3);
    EXPECT_EQ(amg.hierarchySetups(), 2);
}


TEST(LinearSolver, Defaults)
{
    for (const char* name : {"CG", "BiCGStab", "BoomerAMG"})
    {
        autoPtr<linearSolver> solver =
            makeSolver(std::string("solver ") + name + ";");
        EXPECT_EQ(solver->type(), word(name));
        EXPECT_EQ(solver->tolerance(), 1e-8);
        EXPECT_EQ(solver->maxIter(), 1000);
        EXPECT_EQ(solver->needsSymmetric(), word(name) == "CG");
    }
}


TEST(LinearSolver, UnknownSolverListsTheValidNames)
{
    const std::string msg = meshlessTest::fatalMessage([]
    {
        makeSolver("solver GAMG;");
    });
    EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
    EXPECT_NE(msg.find("solver"), std::string::npos) << msg;
    EXPECT_NE(msg.find("GAMG"), std::string::npos) << msg;
    for (const char* name : {"CG", "BiCGStab", "BoomerAMG"})
    {
        EXPECT_NE(msg.find(name), std::string::npos) << msg;
    }
}


TEST(LinearSolver, CGRefusesANonSymmetricMatrix)
{
    const linearSystem s = gridSystem(10, 0.5);
    const std::string msg = meshlessTest::fatalMessage([&]
    {
        autoPtr<linearSolver> solver = makeSolver("solver CG;");
        std::vector<double> x(s.n(), 0.0);
        solver->solve(s.A, s.b.data(), x.data());
    });
    EXPECT_NE(msg.find("symmetric"), std::string::npos) << msg;
    EXPECT_NE(msg.find("BiCGStab"), std::string::npos) << msg;
    EXPECT_NE(msg.find("BoomerAMG"), std::string::npos) << msg;
}


TEST(LinearSolver, BadEntriesNameTheKeyword)
{
    const std::vector<std::pair<std::string, std::vector<std::string>>>
    cases
    {
        {"solver CG; tolerance -1;", {"'tolerance'", "(0, 1)"}},
        {"solver BiCGStab; tolerance 2;", {"'tolerance'", "(0, 1)"}},
        {"solver CG; maxIter 0;", {"'maxIter'", "> 0"}},
        {"solver BoomerAMG; strongThreshold 1;", {"'strongThreshold'"}},
        {
            "solver BoomerAMG; coarsening RS;",
            {"'coarsening'", "HMIS", "PMIS", "Falgout"}
        },
        {
            "solver BoomerAMG; relaxType Jacobi;",
            {"'relaxType'", "l1GaussSeidel", "l1Jacobi", "Chebyshev"}
        },
        {
            "solver BoomerAMG; nonSymmetricSolver CG;",
            {"'nonSymmetricSolver'", "GMRES", "BiCGSTAB"}
        },
        {"solver BoomerAMG; restart 0;", {"'restart'", "> 0"}},
        {"solver BoomerAMG; reuseHierarchy -1;", {"'reuseHierarchy'"}},
    };
    for (const auto& c : cases)
    {
        SCOPED_TRACE(c.first);
        const std::string msg = meshlessTest::fatalMessage([&]
        {
            makeSolver(c.first);
        });
        EXPECT_NE(msg.find("IOerror"), std::string::npos) << msg;
        for (const std::string& part : c.second)
        {
            EXPECT_NE(msg.find(part), std::string::npos) << msg;
        }
    }
}

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "BoomerAMG.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include <mpi.h>
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_ls.h>
#include <cstdlib>
#include <type_traits>
#include <vector>

// The column indices and values go to hypre without a conversion
static_assert
(
    std::is_same<Foam::label, HYPRE_BigInt>::value
 && std::is_same<Foam::label, HYPRE_Int>::value
 && std::is_same<double, HYPRE_Complex>::value,
    "hypre's HYPRE_Int and HYPRE_BigInt must be OpenFOAM's label and"
    " HYPRE_Complex double (Debian's libhypre-dev with WM_LABEL_SIZE=32)"
);

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(BoomerAMG, 0);
    addToRunTimeSelectionTable(linearSolver, BoomerAMG, dictionary);
}
}


const Foam::Enum<Foam::meshless::BoomerAMG::coarseningType>
Foam::meshless::BoomerAMG::coarseningNames
({
    { coarseningType::HMIS, "HMIS" },
    { coarseningType::PMIS, "PMIS" },
    { coarseningType::Falgout, "Falgout" },
});


const Foam::Enum<Foam::meshless::BoomerAMG::relaxationType>
Foam::meshless::BoomerAMG::relaxationNames
({
    { relaxationType::l1GaussSeidel, "l1GaussSeidel" },
    { relaxationType::symmetricGaussSeidel, "symmetricGaussSeidel" },
    { relaxationType::l1Jacobi, "l1Jacobi" },
    { relaxationType::Chebyshev, "Chebyshev" },
});


const Foam::Enum<Foam::meshless::BoomerAMG::interpolationType>
Foam::meshless::BoomerAMG::interpolationNames
({
    { interpolationType::classical, "classical" },
    { interpolationType::extendedI, "extendedI" },
});


const Foam::Enum<Foam::meshless::BoomerAMG::krylovType>
Foam::meshless::BoomerAMG::krylovNames
({
    { krylovType::GMRES, "GMRES" },
    { krylovType::BiCGSTAB, "BiCGSTAB" },
});


namespace
{

//- MPI_Finalize at exit, registered only when BoomerAMG started MPI
void finaliseMpi()
{
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised)
    {
        MPI_Finalize();
    }
}


//- Whether change is true on any process of comm (a decision before a
//  collective call: every process makes it, or none)
bool anyProcess(const bool change, MPI_Comm comm)
{
    if (comm == MPI_COMM_SELF) return change;
    int any = change;
    MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, comm);
    return any != 0;
}


bool mpiFinalised()
{
    int finalised = 0;
    MPI_Finalized(&finalised);
    return finalised != 0;
}


//- MPI (unless OpenFOAM's -parallel started it) and hypre, once
void initialiseHypre()
{
    static bool initialised = false;
    if (initialised)
    {
        return;
    }

    int running = 0;
    MPI_Initialized(&running);
    if (!running)
    {
        if (mpiFinalised())
        {
            FatalErrorInFunction
                << "MPI was finalised already: BoomerAMG cannot start it"
                << " again" << Foam::exit(Foam::FatalError);
        }
        // Only the thread that calls hypre uses MPI
        int provided = 0;
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
        std::atexit(finaliseMpi);
    }
    HYPRE_Init();
    initialised = true;
}


//- An error of a hypre call other than non-convergence (the caller
//  measures convergence) is a FatalError. hypre's error flag is global
//  and sticky: cleared here.
void check(const HYPRE_Int err, const char* call)
{
    if (err & ~HYPRE_ERROR_CONV)
    {
        char description[512] = {};
        HYPRE_DescribeError(err, description);
        HYPRE_ClearAllErrors();
        FatalErrorInFunction
            << "hypre's " << call << " failed (error " << err << "): "
            << description << Foam::exit(Foam::FatalError);
    }
    HYPRE_ClearAllErrors();
}


//- hypre's ParCSR Krylov methods have the same calls under their names
struct krylovMethod
{
    const char* name;
    HYPRE_Int (*create)(MPI_Comm, HYPRE_Solver*);
    HYPRE_Int (*destroy)(HYPRE_Solver);
    HYPRE_Int (*setTol)(HYPRE_Solver, HYPRE_Real);
    HYPRE_Int (*setMaxIter)(HYPRE_Solver, HYPRE_Int);
    HYPRE_Int (*setPrecond)
    (
        HYPRE_Solver,
        HYPRE_PtrToParSolverFcn,
        HYPRE_PtrToParSolverFcn,
        HYPRE_Solver
    );
    HYPRE_Int (*setup)
    (
        HYPRE_Solver,
        HYPRE_ParCSRMatrix,
        HYPRE_ParVector,
        HYPRE_ParVector
    );
    HYPRE_Int (*solve)
    (
        HYPRE_Solver,
        HYPRE_ParCSRMatrix,
        HYPRE_ParVector,
        HYPRE_ParVector
    );
    HYPRE_Int (*numIterations)(HYPRE_Solver, HYPRE_Int*);

    //- Settings of this method only (restart: GMRES's Krylov space size)
    void (*configure)(HYPRE_Solver, const HYPRE_Int restart);
};


const krylovMethod PCG
{
    "PCG",
    HYPRE_ParCSRPCGCreate,
    HYPRE_ParCSRPCGDestroy,
    HYPRE_ParCSRPCGSetTol,
    HYPRE_ParCSRPCGSetMaxIter,
    HYPRE_ParCSRPCGSetPrecond,
    HYPRE_ParCSRPCGSetup,
    HYPRE_ParCSRPCGSolve,
    HYPRE_ParCSRPCGGetNumIterations,
    [](HYPRE_Solver s, const HYPRE_Int)
    {
        // Converged on ||r||_2/||b||_2 (hypre's default: the norm of the
        // preconditioner)
        HYPRE_ParCSRPCGSetTwoNorm(s, 1);
    }
};


const krylovMethod GMRES
{
    "GMRES",
    HYPRE_ParCSRGMRESCreate,
    HYPRE_ParCSRGMRESDestroy,
    HYPRE_ParCSRGMRESSetTol,
    HYPRE_ParCSRGMRESSetMaxIter,
    HYPRE_ParCSRGMRESSetPrecond,
    HYPRE_ParCSRGMRESSetup,
    HYPRE_ParCSRGMRESSolve,
    HYPRE_ParCSRGMRESGetNumIterations,
    [](HYPRE_Solver s, const HYPRE_Int restart)
    {
        HYPRE_ParCSRGMRESSetKDim(s, restart);
    }
};


const krylovMethod BiCGSTAB
{
    "BiCGSTAB",
    HYPRE_ParCSRBiCGSTABCreate,
    HYPRE_ParCSRBiCGSTABDestroy,
    HYPRE_ParCSRBiCGSTABSetTol,
    HYPRE_ParCSRBiCGSTABSetMaxIter,
    HYPRE_ParCSRBiCGSTABSetPrecond,
    HYPRE_ParCSRBiCGSTABSetup,
    HYPRE_ParCSRBiCGSTABSolve,
    HYPRE_ParCSRBiCGSTABGetNumIterations,
    [](HYPRE_Solver, const HYPRE_Int) {}
};


//- The preconditioner's set-up when the hierarchy is kept: none
HYPRE_Int keptHierarchy
(
    HYPRE_Solver,
    HYPRE_ParCSRMatrix,
    HYPRE_ParVector,
    HYPRE_ParVector
)
{
    return 0;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * hypreObjects  * * * * * * * * * * * * * * //

struct Foam::meshless::BoomerAMG::hypreObjects
{
    //- The processes of the system: this one alone, or every one of a
    //  parallel run (a distributed matrix)
    MPI_Comm comm = MPI_COMM_SELF;

    //- The preconditioner, shared by the Krylov solvers
    HYPRE_Solver amg = nullptr;

    //- Krylov solvers, made when first needed: symmetric, non-symmetric,
    //  and the size of the system each was made for
    HYPRE_Solver krylov[2] = {nullptr, nullptr};
    const krylovMethod* method[2] = {&PCG, &GMRES};
    label krylovSize[2] = {-1, -1};
    label krylovOffset[2] = {-1, -1};

    HYPRE_IJMatrix A = nullptr;
    HYPRE_IJVector b = nullptr;
    HYPRE_IJVector x = nullptr;
    HYPRE_IJVector r = nullptr;
    label vectorSize = -1;
    label vectorOffset = -1;
    MPI_Comm vectorComm = MPI_COMM_SELF;

    HYPRE_ParCSRMatrix parA = nullptr;
    HYPRE_ParVector parB = nullptr;
    HYPRE_ParVector parX = nullptr;
    HYPRE_ParVector parR = nullptr;

    //- The global rows of this process, the entries of each row and, of a
    //  distributed matrix, the global columns (grow only)
    std::vector<HYPRE_BigInt> rows;
    std::vector<HYPRE_Int> rowSizes;
    std::vector<HYPRE_BigInt> columns;

    //- Krylov solvers' communicators
    MPI_Comm krylovComm[2] = {MPI_COMM_SELF, MPI_COMM_SELF};

    //- The matrix the hierarchy was set up for: its row starts, global
    //  columns and values, of this process's rows (hierarchyStart empty:
    //  none to keep)
    std::vector<label> hierarchyStart;
    std::vector<HYPRE_BigInt> hierarchyColumns;
    std::vector<double> hierarchyValues;
    label hierarchyOffset = -1;
    MPI_Comm hierarchyComm = MPI_COMM_SELF;

    //- Krylov iterations of the solve that set the hierarchy up, and the
    //  set-ups so far
    label hierarchyIterations = 0;
    label setups = 0;


    hypreObjects() = default;
    hypreObjects(const hypreObjects&) = delete;
    void operator=(const hypreObjects&) = delete;

    ~hypreObjects()
    {
        // At exit after MPI_Finalize hypre cannot free its objects: the
        // process is ending anyway
        if (mpiFinalised())
        {
            return;
        }
        for (label k = 0; k < 2; ++k)
        {
            if (krylov[k]) method[k]->destroy(krylov[k]);
        }
        if (amg) HYPRE_BoomerAMGDestroy(amg);
        destroyMatrix();
        destroyVectors();
    }

    void destroyMatrix()
    {
        if (A) HYPRE_IJMatrixDestroy(A);
        A = nullptr;
        parA = nullptr;
    }

    void destroyVectors()
    {
        if (b) HYPRE_IJVectorDestroy(b);
        if (x) HYPRE_IJVectorDestroy(x);
        if (r) HYPRE_IJVectorDestroy(r);
        b = x = r = nullptr;
        parB = parX = parR = nullptr;
        vectorSize = -1;
        vectorOffset = -1;
    }

    //- The Krylov solver of a (non-)symmetric matrix of n rows, made when
    //  first asked and again when n changed: hypre's GMRES and BiCGSTAB
    //  allocate their work vectors at their first setup only (PCG at
    //  every setup), of the size of that system
    HYPRE_Solver solver
    (
        const bool symmetric,
        const label n,
        const label offset,
        const scalar tolerance,
        const label restart
    )
    {
        const label k = symmetric ? 0 : 1;
        // The work vectors follow this process's rows
        const bool change = anyProcess
        (
            !krylov[k] || krylovSize[k] != n || krylovOffset[k] != offset
         || krylovComm[k] != comm,
            comm
        );
        if (krylov[k] && change)
        {
            method[k]->destroy(krylov[k]);
            krylov[k] = nullptr;
        }
        if (!krylov[k])
        {
            krylovSize[k] = n;
            krylovOffset[k] = offset;
            krylovComm[k] = comm;
            const krylovMethod& m = *method[k];
            check(m.create(comm, &krylov[k]), m.name);
            m.setTol(krylov[k], tolerance);
            m.setPrecond
            (
                krylov[k], HYPRE_BoomerAMGSolve, HYPRE_BoomerAMGSetup, amg
            );
            m.configure(krylov[k], restart);
            check(HYPRE_GetError(), m.name);
        }
        return krylov[k];
    }

    //- Global column of entry k of M
    static HYPRE_BigInt column(const sparseMatrix& M, const label k)
    {
        return M.distributed()
          ? HYPRE_BigInt(M.globalColumn(M.columns()[k]))
          : HYPRE_BigInt(M.columns()[k]);
    }

    //- Whether on every process M has the rows and pattern of the
    //  hierarchy's matrix and values within tolerance*max|a| of its
    //  (collective)
    bool closeToHierarchy(const sparseMatrix& M, const scalar tolerance)
    const
    {
        const label n = M.n();
        bool close =
            label(hierarchyStart.size()) == n + 1
         && hierarchyOffset == M.rowOffset()
         && hierarchyComm == comm;
        if (close)
        {
            const label* rs = M.rowStart();
            const label nnz = rs[n];
            close = label(hierarchyValues.size()) == nnz
                && std::equal(rs, rs + n + 1, hierarchyStart.begin());
            const double* v = M.values();
            double change = 0;
            double largest = 0;
            for (label k = 0; close && k < nnz; ++k)
            {
                close = column(M, k) == hierarchyColumns[k];
                change = std::max(change, std::abs(v[k] - hierarchyValues[k]));
                largest = std::max(largest, std::abs(hierarchyValues[k]));
            }
            close = close && change <= tolerance*largest;
        }
        return !anyProcess(!close, comm);
    }

    //- Remember M as the matrix of the hierarchy set up
    void keepHierarchy(const sparseMatrix& M)
    {
        const label n = M.n();
        const label* rs = M.rowStart();
        const label nnz = rs[n];
        hierarchyStart.assign(rs, rs + n + 1);
        hierarchyColumns.resize(nnz);
        for (label k = 0; k < nnz; ++k) hierarchyColumns[k] = column(M, k);
        hierarchyValues.assign(M.values(), M.values() + nnz);
        hierarchyOffset = M.rowOffset();
        hierarchyComm = comm;
    }

    //- A new IJ matrix of A (its pattern changes every step)
    void setMatrix(const sparseMatrix& M)
    {
        const label n = M.n();
        const label lo = M.rowOffset();
        const label* rowStart = M.rowStart();
        rows.resize(n);
        for (label i = 0; i < n; ++i) rows[i] = lo + i;
        rowSizes.resize(n);
        for (label i = 0; i < n; ++i)
        {
            rowSizes[i] = rowStart[i + 1] - rowStart[i];
        }

        destroyMatrix();
        HYPRE_IJMatrixCreate(comm, lo, lo + n - 1, lo, lo + n - 1, &A);
        HYPRE_IJMatrixSetObjectType(A, HYPRE_PARCSR);
        HYPRE_IJMatrixSetRowSizes(A, rowSizes.data());
        HYPRE_IJMatrixInitialize(A);
        if (M.distributed())
        {
            const label nnz = M.nnz();
            columns.resize(nnz);
            for (label k = 0; k < nnz; ++k) columns[k] = column(M, k);
            HYPRE_IJMatrixSetValues
            (
                A, n, rowSizes.data(), rows.data(), columns.data(),
                M.values()
            );
        }
        else
        {
            HYPRE_IJMatrixSetValues
            (
                A, n, rowSizes.data(), rows.data(), M.columns(), M.values()
            );
        }
        HYPRE_IJMatrixAssemble(A);
        void* object = nullptr;
        HYPRE_IJMatrixGetObject(A, &object);
        parA = static_cast<HYPRE_ParCSRMatrix>(object);
        check(HYPRE_GetError(), "IJ matrix assembly");
    }

    //- One IJ vector: made when the size changed, else filled again
    void setVector
    (
        HYPRE_IJVector& v,
        HYPRE_ParVector& par,
        const double* values,
        const label n
    )
    {
        if (!v)
        {
            HYPRE_IJVectorCreate
            (
                comm, vectorOffset, vectorOffset + n - 1, &v
            );
            HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
        }
        HYPRE_IJVectorInitialize(v);
        HYPRE_IJVectorSetValues(v, n, rows.data(), values);
        HYPRE_IJVectorAssemble(v);
        void* object = nullptr;
        HYPRE_IJVectorGetObject(v, &object);
        par = static_cast<HYPRE_ParVector>(object);
    }

    void setVectors
    (
        const double* bValues,
        const double* xValues,
        const label n,
        const label offset
    )
    {
        // Creating hypre's vectors is collective
        if
        (
            anyProcess
            (
                n != vectorSize || offset != vectorOffset
             || comm != vectorComm,
                comm
            )
        )
        {
            destroyVectors();
            vectorSize = n;
            vectorOffset = offset;
            vectorComm = comm;
        }
        setVector(b, parB, bValues, n);
        setVector(x, parX, xValues, n);
        check(HYPRE_GetError(), "IJ vector assembly");
    }

    //- ||b - A x||_2 of the whole system, with hypre's product
    double residualNorm()
    {
        if (!r)
        {
            HYPRE_IJVectorCreate
            (
                comm, vectorOffset, vectorOffset + vectorSize - 1, &r
            );
            HYPRE_IJVectorSetObjectType(r, HYPRE_PARCSR);
            HYPRE_IJVectorInitialize(r);
            HYPRE_IJVectorAssemble(r);
            void* object = nullptr;
            HYPRE_IJVectorGetObject(r, &object);
            parR = static_cast<HYPRE_ParVector>(object);
        }
        HYPRE_ParVectorCopy(parB, parR);
        HYPRE_ParCSRMatrixMatvec(-1.0, parA, parX, 1.0, parR);
        HYPRE_Real rr = 0;
        HYPRE_ParVectorInnerProd(parR, parR, &rr);
        check(HYPRE_GetError(), "residual");
        return std::sqrt(double(rr));
    }
};


// * * * * * * * * * * * * * * * * BoomerAMG  * * * * * * * * * * * * * * * //

Foam::meshless::BoomerAMG::BoomerAMG(const dictionary& dict)
:
    linearSolver(dict),
    strongThreshold_
    (
        dict.found("strongThreshold")
      ? readInOpenRange(dict, "strongThreshold", 0, 1)
      : 0.25
    ),
    coarsening_
    (
        readEnumOrDefault
        (
            dict, "coarsening", coarseningNames, coarseningType::HMIS
        )
    ),
    relaxation_
    (
        readEnumOrDefault
        (
            dict, "relaxType", relaxationNames,
            relaxationType::l1GaussSeidel
        )
    ),
    interpolation_
    (
        readEnumOrDefault
        (
            dict, "interpolation", interpolationNames,
            interpolationType::classical
        )
    ),
    aggressiveLevels_
    (
        dict.found("aggressiveLevels")
      ? readLabelInRange(dict, "aggressiveLevels", 0, 10)
      : 0
    ),
    nonSymmetricSolver_
    (
        readEnumOrDefault
        (
            dict, "nonSymmetricSolver", krylovNames, krylovType::GMRES
        )
    ),
    restart_
    (
        dict.found("restart") ? readPositiveLabel(dict, "restart") : 30
    ),
    reuseHierarchy_
    (
        readNonNegativeOrDefault(dict, "reuseHierarchy", 1e-3)
    ),
    hypre_(new hypreObjects),
    distributed_(false)
{
    initialiseHypre();

    hypreObjects& h = *hypre_;
    if (nonSymmetricSolver_ == krylovType::BiCGSTAB)
    {
        h.method[1] = &BiCGSTAB;
    }

    // One V-cycle as a preconditioner
    check(HYPRE_BoomerAMGCreate(&h.amg), "BoomerAMGCreate");
    HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
    HYPRE_BoomerAMGSetTol(h.amg, 0);
    HYPRE_BoomerAMGSetMaxIter(h.amg, 1);
    HYPRE_BoomerAMGSetStrongThreshold(h.amg, strongThreshold_);
    HYPRE_BoomerAMGSetCoarsenType(h.amg, HYPRE_Int(coarsening_));
    switch (relaxation_)
    {
        case relaxationType::l1GaussSeidel:
            HYPRE_BoomerAMGSetCycleRelaxType(h.amg, 13, 1);
            HYPRE_BoomerAMGSetCycleRelaxType(h.amg, 14, 2);
            break;
        case relaxationType::symmetricGaussSeidel:
            HYPRE_BoomerAMGSetRelaxType(h.amg, 6);
            break;
        case relaxationType::l1Jacobi:
            HYPRE_BoomerAMGSetRelaxType(h.amg, 18);
            break;
        case relaxationType::Chebyshev:
            HYPRE_BoomerAMGSetRelaxType(h.amg, 16);
            break;
    }
    HYPRE_BoomerAMGSetInterpType(h.amg, HYPRE_Int(interpolation_));
    HYPRE_BoomerAMGSetAggNumLevels(h.amg, HYPRE_Int(aggressiveLevels_));
    check(HYPRE_GetError(), "BoomerAMG settings");
}


Foam::meshless::BoomerAMG::~BoomerAMG()
{}


Foam::meshless::linearSolver::performance Foam::meshless::BoomerAMG::solve
(
    const sparseMatrix& A,
    const double* b,
    double* x
)
{
    hypreObjects& h = *hypre_;
    const label n = A.n();
    const bool symmetric = A.symmetric();
    const krylovMethod& method = *h.method[symmetric ? 0 : 1];
    HYPRE_Solver solver = nullptr;
    bool setUp = false;
    bool kept = false;

    // The Krylov solver, hypre's copies of A, b and x, and the hierarchy:
    // of this matrix, or the last one's when A is close to its matrix
    auto setUpSolve = [&](const label offset)
    {
        HYPRE_ClearAllErrors();
        solver = h.solver(symmetric, n, offset, tolerance(), restart_);
        kept = reuseHierarchy_ > 0 && h.closeToHierarchy(A, reuseHierarchy_);
        h.setMatrix(A);
        h.setVectors(b, x, n, offset);
        method.setPrecond
        (
            solver,
            HYPRE_BoomerAMGSolve,
            kept ? keptHierarchy : HYPRE_BoomerAMGSetup,
            h.amg
        );
        check(method.setup(solver, h.parA, h.parB, h.parX), method.name);
        if (!kept)
        {
            h.keepHierarchy(A);
            ++h.setups;
        }
        setUp = true;
    };

    // A distributed system spans the processors: hypre's copies first, so
    // that the residuals are the whole system's
    distributed_ = A.distributed();
    h.comm = distributed_ ? MPI_COMM_WORLD : MPI_COMM_SELF;
    if (distributed_)
    {
        setUpSolve(A.rowOffset());
    }

    const performance p = run
    (
        A, b, x,
        [&](const label maxIter)
        {
            // Set up once a solve
            if (!solver) setUpSolve(0);

            // Again from the x reached (h.x) when called again
            method.setMaxIter(solver, maxIter);
            check(method.solve(solver, h.parA, h.parB, h.parX), method.name);

            HYPRE_Int iterations = 0;
            method.numIterations(solver, &iterations);
            HYPRE_IJVectorGetValues(h.x, n, h.rows.data(), x);
            check(HYPRE_GetError(), method.name);
            return label(iterations);
        }
    );

    if (setUp && !kept && p.iterations > 0)
    {
        h.hierarchyIterations = p.iterations;
    }
    else if (kept && !p.converged)
    {
        // The kept hierarchy did not serve: again from the x reached with
        // this matrix's own
        h.hierarchyStart.clear();
        performance q = solve(A, b, x);
        q.initialResidual = p.initialResidual;
        q.iterations += p.iterations;
        return q;
    }
    else if (kept && p.iterations > 2*h.hierarchyIterations + 2)
    {
        // The kept hierarchy serves less and less: set up at the next solve
        h.hierarchyStart.clear();
    }
    return p;
}


Foam::label Foam::meshless::BoomerAMG::hierarchySetups() const
{
    return hypre_->setups;
}


double Foam::meshless::BoomerAMG::norm(const double* v, const label n) const
{
    if (!distributed_) return linearSolver::norm(v, n);
    double s = 0;
    for (label i = 0; i < n; ++i) s += v[i]*v[i];
    double sum = 0;
    MPI_Allreduce(&s, &sum, 1, MPI_DOUBLE, MPI_SUM, hypre_->comm);
    return std::sqrt(sum);
}


double Foam::meshless::BoomerAMG::residualNorm
(
    const sparseMatrix& A,
    const double* b,
    const double* x
) const
{
    if (!distributed_) return A.residualNorm(b, x);
    return hypre_->residualNorm();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    checkParticles

Group
    grpMeshQualityUtilities

Description
    checkMesh for particles: reads every cloud written at the selected times,
    searches neighbours within each body and between bodies with a smoothing
    kernel sized from each body's spacing (from its particle volume), and
    reports per body the neighbour counts and the kernel sum
    sum_j W_ij V_j (1 inside a well-resolved body, about 1/2 at a free
    surface). Adds the fields nNeighbours and kernelSum to the clouds
    (nothing else on disk is rewritten).

Usage
    \b checkParticles [-kernel wendlandC2] [-smoothingLengthRatio 1.3]
        [-time ...] [-latestTime]

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "timeSelector.H"
#include "particleSet.H"
#include "lagrangianIO.H"
#include "smoothingKernel.H"
#include "neighbourList.H"
#include <memory>

using namespace Foam::meshless;

namespace
{

struct stats
{
    scalar min = GREAT, max = -GREAT, sum = 0;
    label n = 0;
    void add(const scalar v) { min = Foam::min(min, v); max = Foam::max(max, v); sum += v; ++n; }
    scalar mean() const { return n ? sum/n : 0; }
};

Ostream& operator<<(Ostream& os, const stats& s)
{
    return os << "min " << s.min << " mean " << s.mean() << " max " << s.max;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote("Neighbour and kernel-sum statistics of the particles");
    timeSelector::addOptions();
    argList::addOption("kernel", "type", "Smoothing kernel (wendlandC2)");
    argList::addOption
    (
        "smoothingLengthRatio", "value", "h/dx of the kernel (1.3)"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    const instantList timeDirs = timeSelector::select0(runTime, args);

    dictionary kernelDict;
    kernelDict.add("type", args.getOrDefault<word>("kernel", "wendlandC2"));
    kernelDict.add
    (
        "smoothingLengthRatio",
        args.getOrDefault<scalar>("smoothingLengthRatio", 1.3)
    );

    const label dim = mesh.nSolutionD();

    forAll(timeDirs, timei)
    {
        runTime.setTime(timeDirs[timei], timei);
        const word timeName = runTime.timeName();
        const wordList names = lagrangianIO::clouds(runTime, timeName);
        if (names.empty()) continue;

        Info<< "Time = " << timeName << nl << endl;

        // Read every body with its own kernel
        std::vector<std::unique_ptr<particleSet>> sets;
        std::vector<std::unique_ptr<smoothingKernel>> kernels;
        for (const word& name : names)
        {
            sets.emplace_back(new particleSet(name, dim));
            particleSet& s = *sets.back();
            lagrangianIO::read(s, runTime, timeName);
            if (!s.found("volume") || s.size() == 0)
            {
                FatalErrorInFunction
                    << "Cloud " << name << " at time " << timeName
                    << " has no particle or no volume field"
                    << exit(FatalError);
            }
            scalar V = 0;
            for (label i = 0; i < s.size(); ++i) V += s.field("volume")(i, 0);
            const scalar dx = std::pow(V/s.size(), 1.0/dim);
            kernels.emplace_back
            (
                smoothingKernel::New(kernelDict, dim, dx).ptr()
            );
        }

        for (size_t a = 0; a < sets.size(); ++a)
        {
            particleSet& A = *sets[a];
            const smoothingKernel& W = *kernels[a];
            const double* xA = A.positions().data();
            const double* VA = A.field("volume").data();

            cellLinkedList cells(dim, W.radius());
            neighbourList list;
            cells.build(xA, A.size());
            list.build(cells, xA, A.size(), true);

            particleField& nNb =
                A.addField("nNeighbours", particleField::kind::scalar);
            particleField& sumW =
                A.addField("kernelSum", particleField::kind::scalar);

            #pragma omp parallel for schedule(static)
            for (label i = 0; i < A.size(); ++i)
            {
                double s = W.W(0)*VA[i];
                for (const label* j = list.begin(i); j != list.end(i); ++j)
                {
                    const double r2 = dim == 2
                        ? distanceSqr<2>(xA + i*dim, xA + *j*dim)
                        : distanceSqr<3>(xA + i*dim, xA + *j*dim);
                    s += W.W(std::sqrt(r2))*VA[*j];
                }
                nNb(i, 0) = list.nNeighbours(i);
                sumW(i, 0) = s;
            }

            stats sn, sw;
            for (label i = 0; i < A.size(); ++i)
            {
                sn.add(nNb(i, 0));
                sw.add(sumW(i, 0));
            }
            Info<< "Body " << A.name() << ": " << A.size() << " particles, h "
                << W.h() << ", support radius " << W.radius() << nl
                << "    neighbours  " << sn << nl
                << "    kernel sum  " << sw << nl;

            // Neighbours in the other bodies, within this body's support
            for (size_t b = 0; b < sets.size(); ++b)
            {
                if (a == b) continue;
                const particleSet& B = *sets[b];
                cellLinkedList cellsB(dim, W.radius());
                cellsB.build(B.positions().data(), B.size());
                neighbourList cross;
                cross.build(cellsB, xA, A.size(), false);
                label touching = 0;
                for (label i = 0; i < A.size(); ++i)
                {
                    touching += cross.nNeighbours(i) > 0;
                }
                Info<< "    with " << B.name() << ": " << cross.nPairs()
                    << " pairs, " << touching << " particles of "
                    << A.name() << " within reach" << nl;
            }
            Info<< endl;

            lagrangianIO::writeField(A, "nNeighbours", runTime, timeName);
            lagrangianIO::writeField(A, "kernelSum", runTime, timeName);
        }
    }

    Info<< "End" << nl << endl;
    return 0;
}

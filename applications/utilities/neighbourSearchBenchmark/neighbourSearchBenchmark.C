/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Application
    neighbourSearchBenchmark

Description
    Times the neighbour search of libmeshless on jittered lattices of a given
    size in 2D or 3D: building the cell-linked list (bounding box, cell of
    each particle, counting sort) and the neighbour list, after the
    particles have been sorted by cell as the solvers keep them. Prints one
    line per run: dim, particles, threads, pairs per particle and the median
    time per particle of each phase.

    The search radius is that of a Wendland C2 kernel with h = 1.3 dx
    (2.6 dx), the RKGC paper's fluid set-up.

Usage
    \b neighbourSearchBenchmark -dim 3 -n 1000000 [-repeat 5]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "clock.H"
#include "cellLinkedList.H"
#include "neighbourList.H"
#include "particleSet.H"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;
using namespace Foam::meshless;

static double seconds()
{
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}


int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    argList::noCheckProcessorDirectories();
    argList::addOption("dim", "2|3", "Dimension (default 3)");
    argList::addOption("n", "count", "Number of particles (default 1e5)");
    argList::addOption("repeat", "count", "Timed repetitions (default 5)");
    argList args(argc, argv, false, false, false);

    const label dim = args.getOrDefault<label>("dim", 3);
    const label nTarget = args.getOrDefault<label>("n", 100000);
    const label repeat = args.getOrDefault<label>("repeat", 5);

    const label perSide =
        label(std::round(std::pow(double(nTarget), 1.0/dim)));
    const double dx = 1.0/perSide;
    const double radius = 2.6*dx;

    particleSet set("fluid", dim);
    const label n = dim == 2 ? perSide*perSide : perSide*perSide*perSide;
    set.resize(n);
    std::mt19937_64 gen(1);
    std::uniform_real_distribution<double> jitter(-0.1*dx, 0.1*dx);
    {
        double* x = set.positions().data();
        label i = 0;
        for (label k = 0; k < (dim == 3 ? perSide : 1); ++k)
        for (label j = 0; j < perSide; ++j)
        for (label l = 0; l < perSide; ++l, ++i)
        {
            x[i*dim] = (l + 0.5)*dx + jitter(gen);
            x[i*dim + 1] = (j + 0.5)*dx + jitter(gen);
            if (dim == 3) x[i*dim + 2] = (k + 0.5)*dx + jitter(gen);
        }
        // Scramble, as after particles have moved for a while
        std::vector<label> order(n);
        for (label p = 0; p < n; ++p) order[p] = p;
        std::shuffle(order.begin(), order.end(), gen);
        set.reorder(order);
    }

    cellLinkedList cells(dim, radius);
    neighbourList list;

    // Sort by cell once, as the solvers do on (re)start
    const double t0 = seconds();
    cells.build(set.positions().data(), n);
    set.reorder(cells.order());
    const double tSort = seconds() - t0;

    std::vector<double> tCells, tList;
    for (label r = 0; r < repeat + 1; ++r)
    {
        const double a = seconds();
        cells.build(set.positions().data(), n);
        const double b = seconds();
        list.build(cells, set.positions().data(), n, true);
        const double c = seconds();
        if (r > 0)      // the first builds allocate: not steady state
        {
            tCells.push_back(b - a);
            tList.push_back(c - b);
        }
    }
    std::sort(tCells.begin(), tCells.end());
    std::sort(tList.begin(), tList.end());
    const double cellsMed = tCells[tCells.size()/2];
    const double listMed = tList[tList.size()/2];

    #ifdef _OPENMP
    const int threads = omp_get_max_threads();
    #else
    const int threads = 1;
    #endif

    Info<< "dim " << dim
        << " particles " << n
        << " threads " << threads
        << " pairsPerParticle " << double(list.nPairs())/n
        << " firstSortNsPerParticle " << 1e9*tSort/n
        << " cellListNsPerParticle " << 1e9*cellsMed/n
        << " neighbourListNsPerParticle " << 1e9*listMed/n
        << " totalNsPerParticle " << 1e9*(cellsMed + listMed)/n
        << endl;

    return 0;
}

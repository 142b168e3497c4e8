/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "error.H"
#include "IStringStream.H"
#include <random>
#include <sstream>

std::vector<double> meshlessTest::randomPoints
(
    const label dim,
    const label n,
    const double L,
    const unsigned seed
)
{
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(0, L);
    std::vector<double> x(size_t(n)*dim);
    for (auto& v : x) v = u(gen);
    return x;
}


std::vector<double> meshlessTest::latticePoints
(
    const label dim,
    const label nPerSide,
    const double dx
)
{
    const label nz = dim == 3 ? nPerSide : 1;
    std::vector<double> x;
    for (label k = 0; k < nz; ++k)
    {
        for (label j = 0; j < nPerSide; ++j)
        {
            for (label i = 0; i < nPerSide; ++i)
            {
                x.push_back(i*dx);
                x.push_back(j*dx);
                if (dim == 3) x.push_back(k*dx);
            }
        }
    }
    return x;
}


std::vector<double> meshlessTest::clusteredPoints
(
    const label dim,
    const label n,
    const unsigned seed
)
{
    std::mt19937_64 gen(seed);
    std::normal_distribution<double> g(0, 0.05);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> x;
    const label nClusters = 4;
    for (label c = 0; c < nClusters; ++c)
    {
        double centre[3] = {u(gen), u(gen), u(gen)};
        for (label i = 0; i < (n - 5)/nClusters; ++i)
        {
            for (label d = 0; d < dim; ++d) x.push_back(centre[d] + g(gen));
        }
    }
    // Outliers far away: the grid must coarsen, not explode
    while (label(x.size()) < n*dim)
    {
        for (label d = 0; d < dim; ++d) x.push_back(1e4*u(gen));
    }
    return x;
}


std::string meshlessTest::fatalMessage(const std::function<void()>& f)
{
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    std::string msg;
    try
    {
        f();
    }
    catch (const Foam::IOerror& err)
    {
        std::ostringstream os;
        os << err.message() << " [file: " << err.ioFileName() << "]";
        msg = "IOerror: " + os.str();
    }
    catch (const Foam::error& err)
    {
        msg = "error: " + std::string(err.message());
    }
    Foam::FatalError.dontThrowExceptions();
    Foam::FatalIOError.dontThrowExceptions();
    return msg;
}


Foam::dictionary meshlessTest::dictFrom(const std::string& text)
{
    Foam::IStringStream is(text);
    return Foam::dictionary(is);
}

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "testHelpers.H"
#include "neighbourRelation.H"
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


std::vector<double> meshlessTest::jitteredPoints
(
    const label dim,
    const label nPerSide,
    const double dx,
    const double jitter,
    const unsigned seed
)
{
    std::vector<double> x = latticePoints(dim, nPerSide, dx);
    if (jitter > 0)
    {
        std::mt19937_64 gen(seed);
        std::uniform_real_distribution<double> u(-jitter*dx, jitter*dx);
        for (auto& v : x) v += u(gen);
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


Foam::autoPtr<Foam::meshless::smoothingKernel> meshlessTest::kernel
(
    const label dim,
    const double dx,
    const std::string& dict
)
{
    return Foam::meshless::smoothingKernel::New(dictFrom(dict), dim, dx);
}


Foam::label meshlessTest::countFlags(const std::vector<char>& flags)
{
    label n = 0;
    for (const char f : flags) n += f != 0;
    return n;
}


// * * * * * * * * * * * * * * * * pairFixture  * * * * * * * * * * * * * * //

const unsigned meshlessTest::pairFixture::allGeometry =
    Foam::meshless::neighbourRelation::separation
  | Foam::meshless::neighbourRelation::kernelValue
  | Foam::meshless::neighbourRelation::kernelGradient;


meshlessTest::pairFixture::body::body
(
    const label dim,
    const std::vector<double>& points,
    const std::vector<double>& volumes
)
:
    x("x", Foam::meshless::particleField::kind::vector, dim),
    V("V", Foam::meshless::particleField::kind::scalar, dim)
{
    const label n = label(points.size())/dim;
    if (label(points.size()) != n*dim || label(volumes.size()) != n)
    {
        FatalErrorInFunction
            << points.size() << " coordinates and " << volumes.size()
            << " volumes for points of dimension " << dim
            << Foam::exit(Foam::FatalError);
    }
    x.resize(n);
    V.resize(n);
    std::copy(points.begin(), points.end(), x.data());
    std::copy(volumes.begin(), volumes.end(), V.data());
}


Foam::label meshlessTest::pairFixture::addBody
(
    const std::vector<double>& points,
    const std::vector<double>& volumes
)
{
    bodies_.emplace_back(new body(dim_, points, volumes));
    return nBodies() - 1;
}


Foam::label meshlessTest::pairFixture::addBody
(
    const std::vector<double>& points,
    const double volume
)
{
    return addBody(points, std::vector<double>(points.size()/dim_, volume));
}


Foam::meshless::neighbourRelation& meshlessTest::pairFixture::relate
(
    const label a,
    const label b,
    const Foam::meshless::smoothingKernel& W,
    const double skin,
    const unsigned geometry
)
{
    using namespace Foam::meshless;
    const double radius = W.radius()*(1 + skin);
    cellLinkedList* list = nullptr;
    for (const cells& c : cells_)
    {
        if (c.b == b && c.radius == radius) list = c.list.get();
    }
    if (!list)
    {
        cells_.push_back
        (
            cells{b, radius, std::unique_ptr<cellLinkedList>
            (
                new cellLinkedList(dim_, radius)
            )}
        );
        list = cells_.back().list.get();
        list->build(bodies_[b]->x.data(), bodies_[b]->size());
    }
    relations_.push_back
    (
        relation{a, b, std::unique_ptr<neighbourRelation>
        (
            new neighbourRelation
            (
                "relation" + Foam::name(a) + "-" + Foam::name(b),
                bodies_[a]->x, bodies_[b]->x, a == b, W, *list, geometry,
                false
            )
        )}
    );
    neighbourRelation& rel = *relations_.back().rel;
    rel.build();
    return rel;
}


std::vector<Foam::meshless::pairSource>
meshlessTest::pairFixture::sources(const label a) const
{
    std::vector<Foam::meshless::pairSource> s;
    for (const relation& r : relations_)
    {
        if (r.a == a) s.push_back({r.rel.get(), bodies_[r.b]->V.data()});
    }
    return s;
}


Foam::meshless::pairSource meshlessTest::pairFixture::source
(
    const Foam::meshless::neighbourRelation& rel
) const
{
    for (const relation& r : relations_)
    {
        if (r.rel.get() == &rel) return {&rel, bodies_[r.b]->V.data()};
    }
    FatalErrorInFunction
        << "Relation " << rel.name() << " is not the fixture's"
        << Foam::exit(Foam::FatalError);
    return {nullptr, nullptr};
}


void meshlessTest::pairFixture::rebuild()
{
    for (cells& c : cells_)
    {
        c.list->build(bodies_[c.b]->x.data(), bodies_[c.b]->size());
    }
    for (relation& r : relations_) r.rel->build();
}


void meshlessTest::pairFixture::updateGeometry()
{
    for (relation& r : relations_) r.rel->updateGeometry();
}

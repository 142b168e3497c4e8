/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lagrangianIO.H"
#include "IOField.H"
#include "IOobjectList.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "cloud.H"

namespace
{

using namespace Foam;
using namespace Foam::meshless;

IOobject cloudObject
(
    const word& name,
    const Time& runTime,
    const word& timeName,
    const word& body,
    const IOobject::readOption r = IOobject::NO_READ
)
{
    return IOobject
    (
        name,
        timeName,
        lagrangianIO::cloudLocal(body),
        runTime,
        r,
        IOobject::NO_WRITE,
        false
    );
}


//- 3D component of a dim-component field entry (padding 2D with zeros)
template<class Type>
void toFoam
(
    const particleField& f,
    const label dim,
    Field<Type>& out
)
{
    const label nc = pTraits<Type>::nComponents;
    const label n = f.size();
    out.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        Type v(Zero);
        if (nc == 1 || dim == 3)
        {
            for (label c = 0; c < nc; ++c) setComponent(v, c) = f(i, c);
        }
        else if (nc == 3)
        {
            setComponent(v, 0) = f(i, 0);
            setComponent(v, 1) = f(i, 1);
        }
        else    // 2D tensor: xx xy / yx yy into the 3x3 layout
        {
            setComponent(v, 0) = f(i, 0);
            setComponent(v, 1) = f(i, 1);
            setComponent(v, 3) = f(i, 2);
            setComponent(v, 4) = f(i, 3);
        }
        out[i] = v;
    }
}


template<class Type>
void fromFoam
(
    const Field<Type>& in,
    const label dim,
    particleField& f
)
{
    const label nc = pTraits<Type>::nComponents;
    for (label i = 0; i < in.size(); ++i)
    {
        const Type& v = in[i];
        if (nc == 1 || dim == 3)
        {
            for (label c = 0; c < nc; ++c) f(i, c) = component(v, c);
        }
        else if (nc == 3)
        {
            f(i, 0) = component(v, 0);
            f(i, 1) = component(v, 1);
        }
        else
        {
            f(i, 0) = component(v, 0);
            f(i, 1) = component(v, 1);
            f(i, 2) = component(v, 3);
            f(i, 3) = component(v, 4);
        }
    }
}


template<class Type>
void writeTypedField
(
    const particleField& f,
    const label dim,
    const Time& runTime,
    const word& timeName,
    const word& body
)
{
    IOField<Type> out(cloudObject(f.name(), runTime, timeName, body), label(0));
    toFoam(f, dim, out);
    out.write();
}


template<class Type>
void readFields
(
    particleSet& set,
    const IOobjectList& objects,
    const particleField::kind k
)
{
    for (const word& name : objects.sortedNames(IOField<Type>::typeName))
    {
        if (name == particleSet::positionsName) continue;
        IOField<Type> in(*objects.findObject(name));
        if (in.size() != set.size())
        {
            FatalErrorInFunction
                << in.objectPath() << ": field " << name << " has "
                << in.size()
                << " entries, the cloud has " << set.size() << " particles"
                << exit(FatalIOError);
        }
        fromFoam(in, set.dim(), set.addField(name, k));
    }
}

} // End anonymous namespace


Foam::fileName Foam::meshless::lagrangianIO::cloudLocal(const word& body)
{
    return cloud::prefix/body;
}


Foam::wordList Foam::meshless::lagrangianIO::clouds
(
    const Time& runTime,
    const word& timeName
)
{
    fileNameList dirs
    (
        readDir(runTime.path()/timeName/cloud::prefix, fileName::DIRECTORY)
    );
    wordList names(dirs.size());
    forAll(dirs, i)
    {
        names[i] = dirs[i];
    }
    Foam::sort(names);
    return names;
}


void Foam::meshless::lagrangianIO::write
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName,
    const scalar zPlane
)
{
    const label dim = set.dim();
    const label n = set.size();
    const particleField& x = set.positions();

    // Positions in the legacy format every lagrangian reader understands
    IOobject posIO
    (
        cloudObject(particleSet::positionsName, runTime, timeName, set.name())
    );
    mkDir(posIO.path());
    {
        OFstream os(posIO.objectPath(), IOstream::ASCII);
        posIO.writeHeader(os, "Cloud<passiveParticle>");
        os  << n << nl << token::BEGIN_LIST << nl;
        for (label i = 0; i < n; ++i)
        {
            os  << token::BEGIN_LIST << x(i, 0) << token::SPACE << x(i, 1)
                << token::SPACE << (dim == 3 ? x(i, 2) : zPlane)
                << token::END_LIST << " -1" << nl;
        }
        os  << token::END_LIST << nl;
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Failed writing " << os.name() << exit(FatalError);
        }
    }

    {
        IOField<label> ids(cloudObject("id", runTime, timeName, set.name()), n);
        std::copy(set.ids().begin(), set.ids().end(), ids.begin());
        ids.write();
    }

    for (const word& name : set.fieldNames())
    {
        if (name != particleSet::positionsName && set.field(name).written())
        {
            writeField(set, name, runTime, timeName);
        }
    }
}


void Foam::meshless::lagrangianIO::writeField
(
    const particleSet& set,
    const word& name,
    const Time& runTime,
    const word& timeName
)
{
    const label dim = set.dim();
    const particleField& f = set.field(name);
    switch (f.fieldKind())
    {
        case particleField::kind::scalar:
            writeTypedField<scalar>(f, dim, runTime, timeName, set.name());
            break;
        case particleField::kind::vector:
            writeTypedField<vector>(f, dim, runTime, timeName, set.name());
            break;
        case particleField::kind::tensor:
            writeTypedField<tensor>(f, dim, runTime, timeName, set.name());
            break;
    }
}


void Foam::meshless::lagrangianIO::read
(
    particleSet& set,
    const Time& runTime,
    const word& timeName
)
{
    const label dim = set.dim();

    IOobject posIO
    (
        cloudObject
        (
            particleSet::positionsName,
            runTime,
            timeName,
            set.name(),
            IOobject::MUST_READ
        )
    );
    IFstream is(posIO.objectPath());
    if (!is.good() || !posIO.readHeader(is))
    {
        FatalIOErrorInFunction(is)
            << "Cannot read the positions of cloud " << set.name()
            << " at time " << timeName << exit(FatalIOError);
    }

    const label n = readLabel(is);
    set.resize(n);
    particleField& x = set.positions();
    is.readBegin("positions");
    for (label i = 0; i < n; ++i)
    {
        vector p;
        label celli;
        is >> p >> celli;
        for (label d = 0; d < dim; ++d) x(i, d) = p[d];
    }
    is.readEnd("positions");
    is.check(FUNCTION_NAME);

    IOobjectList objects(runTime, timeName, cloudLocal(set.name()));

    const IOobject* idIO = objects.findObject("id");
    if (idIO)
    {
        IOField<label> ids(*idIO);
        if (ids.size() != n)
        {
            FatalErrorInFunction
                << ids.objectPath() << ": " << ids.size()
                << " ids for " << n << " positions"
                << exit(FatalIOError);
        }
        set.setIds(std::vector<label>(ids.begin(), ids.end()));
    }

    readFields<scalar>(set, objects, particleField::kind::scalar);
    readFields<vector>(set, objects, particleField::kind::vector);
    readFields<tensor>(set, objects, particleField::kind::tensor);
}

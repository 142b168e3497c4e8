/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lagrangianIO.H"
#include "atomicTimeWriter.H"
#include "IOField.H"
#include "labelFieldIOField.H"
#include "IOobjectList.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "cloud.H"
#include "indexedOctree.H"
#include "tetIndices.H"
#include "Random.H"
#include <cstring>
#include <limits>

namespace
{

using namespace Foam;
using namespace Foam::meshless;

//- Significant digits of ascii clouds, whatever writePrecision: a double
//  read back from them is the one written (a restart continues exactly)
const int restartPrecision = std::numeric_limits<double>::max_digits10;

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


//- Write a list as an IOField file at timeName in writeFormat and
//  writeCompression. Written directly rather than by regIOobject::write,
//  which moves an object to the Time's current name: timeName may be the
//  temporary directory of an atomic write (atomicTimeWriter), and the
//  header's location names the time it stands for.
template<class Type>
void writeList
(
    const word& name,
    const UList<Type>& values,
    const Time& runTime,
    const word& timeName,
    const word& body
)
{
    const IOobject io(cloudObject(name, runTime, timeName, body));
    const IOobject header
    (
        cloudObject(name, runTime, atomicTimeWriter::timeOf(timeName), body)
    );
    mkDir(io.path());
    OFstream os
    (
        io.objectPath(),
        runTime.writeFormat(),
        IOstream::currentVersion,
        runTime.writeCompression()
    );
    os.precision(max(os.precision(), restartPrecision));
    header.writeHeader(os, IOField<Type>::typeName);
    os  << values;
    IOobject::writeEndDivider(os);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Failed writing " << os.name() << exit(FatalError);
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
    Field<Type> out;
    toFoam(f, dim, out);
    writeList(f.name(), out, runTime, timeName, body);
}


//- Read a field file of a cloud; a file the parser cannot read (truncated,
//  damaged) is a FatalIOError that says so, names the cloud and keeps the
//  parser's message and line
template<class Type>
autoPtr<IOField<Type>> readIOField(const IOobject& io, const word& cloudName)
{
    const bool oldIO = FatalIOError.throwExceptions();
    const bool old = FatalError.throwExceptions();
    autoPtr<IOField<Type>> f;
    string why;
    label line = -1;
    try
    {
        f.reset(new IOField<Type>(io));
    }
    catch (const Foam::error& e)
    {
        why = e.message();
        if (const IOerror* ioe = dynamic_cast<const IOerror*>(&e))
        {
            line = ioe->ioStartLineNumber();
        }
    }
    FatalIOError.throwExceptions(oldIO);
    FatalError.throwExceptions(old);
    if (!f.valid())
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__, io.objectPath(), line
        )   << "Cannot read field " << io.name() << " of cloud " << cloudName
            << " at time " << io.instance().c_str() << ": the file is"
            << " truncated or damaged (" << why.c_str() << "). Expected a "
            << IOField<Type>::typeName << " with an entry per particle"
            << exit(FatalIOError);
    }
    return f;
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
        if
        (
            name == particleSet::positionsName
         || name == lagrangianIO::exactPositionName
        )
        {
            continue;
        }
        const autoPtr<IOField<Type>> pIn
        (
            readIOField<Type>(*objects.findObject(name), set.name())
        );
        const IOField<Type>& in = pIn();
        if (in.size() != set.size())
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, in.objectPath()
            )   << "Field " << name << " of cloud " << set.name()
                << " has " << in.size() << " entries, the cloud has "
                << set.size() << " particles (its positions): expected "
                << set.size() << " entries, one per particle"
                << exit(FatalIOError);
        }
        fromFoam(in, set.dim(), set.addField(name, k));
    }
}

//- What was found where a token was expected: the token, or the end of
//  the file
void describeFound(Istream& is, const token& t, const label i, const label n)
{
    if (!is.good() || t.undefined() || t.error())
    {
        FatalIOError
            << "the end of the file: the file is truncated";
        if (i >= 0)
        {
            FatalIOError
                << " (it ends at particle " << i << " of the " << n
                << " its count announces)";
        }
    }
    else
    {
        FatalIOError << t.info();
    }
}


//- The particle count at the start of a positions file, and its '('
label readPositionsCount(Istream& is, const fileName& file)
{
    token t(is);
    if (!is.good() || !t.isLabel() || t.labelToken() < 0)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, is.lineNumber())
            << "Expected the particle count after the header, found ";
        describeFound(is, t, -1, 0);
        FatalIOError << exit(FatalIOError);
    }
    const label n = t.labelToken();
    token open(is);
    if
    (
        !is.good()
     || !open.isPunctuation()
     || open.pToken() != token::BEGIN_LIST
    )
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, is.lineNumber())
            << "Expected '(' after the particle count " << n << ", found ";
        describeFound(is, open, 0, n);
        FatalIOError << exit(FatalIOError);
    }
    return n;
}


//- Particle i's line (i == n: the list's end) is not what it should be
void positionsError
(
    Istream& is,
    const fileName& file,
    const label i,
    const label n,
    const char* expected,
    const token& found
)
{
    FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, is.lineNumber());
    if (i < n)
    {
        FatalIOError
            << "Particle " << i << " of " << n << ": expected " << expected
            << " in its line '(x y z) celli', found ";
    }
    else
    {
        FatalIOError
            << "After the " << n << " particles its count announces:"
            << " expected " << expected << ", found ";
    }
    describeFound(is, found, i, n);
    FatalIOError << exit(FatalIOError);
}


void expectPunctuation
(
    Istream& is,
    const fileName& file,
    const token::punctuationToken p,
    const label i,
    const label n,
    const char* expected
)
{
    token t(is);
    if (!is.good() || !t.isPunctuation() || t.pToken() != p)
    {
        positionsError(is, file, i, n, expected, t);
    }
}


//- A coordinate or the cell label of particle i
token readPositionNumber
(
    Istream& is,
    const fileName& file,
    const label i,
    const label n,
    const char* expected
)
{
    token t(is);
    if (!is.good() || !t.isNumber())
    {
        positionsError(is, file, i, n, expected, t);
    }
    return t;
}


} // End anonymous namespace


const Foam::word Foam::meshless::lagrangianIO::exactPositionName
(
    "position"
);


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


namespace
{

//- The search tree of OpenFOAM's polyMesh::cellTree, with the face planes
//  for the inside test (its tets cost a test of every tet of every
//  candidate cell: 28 us a particle on a 2D dam break)
Foam::treeBoundBox locatorBounds(const Foam::polyMesh& mesh)
{
    using namespace Foam;
    treeBoundBox bb(mesh.points());
    Random rndGen(261782);
    bb = bb.extend(rndGen, 1e-4);
    bb.min() -= point(ROOTVSMALL, ROOTVSMALL, ROOTVSMALL);
    bb.max() += point(ROOTVSMALL, ROOTVSMALL, ROOTVSMALL);
    return bb;
}

} // End anonymous namespace


Foam::meshless::lagrangianIO::meshLocator::meshLocator(const polyMesh& mesh)
:
    mesh_(mesh),
    tree_
    (
        treeDataCell(true, mesh, polyMesh::FACE_PLANES),
        locatorBounds(mesh),
        8,
        10,
        5.0
    ),
    tetFace_(mesh.nCells(), -1),
    tetPt_(mesh.nCells(), -1)
{
    // The faces' tet base points: OpenFOAM makes them when first asked
    // for, with a collective exchange over the processor patches; made
    // here on every processor, not in locate, which a processor holding
    // no particle leaves early (a parallel run hung at its first write)
    (void)mesh.tetBasePtIs();
}


Foam::meshless::lagrangianIO::meshLocation
Foam::meshless::lagrangianIO::meshLocator::locate
(
    const particleSet& set,
    const scalar zPlane
) const
{
    const label dim = set.dim();
    const label n = set.size();
    const particleField& x = set.positions();
    meshLocation where;
    where.cell.setSize(n, -1);
    where.tetFace.setSize(n, -1);
    where.tetPt.setSize(n, -1);
    where.coordinates.setSize(n, barycentric(1, 0, 0, 0));
    if (n == 0 || mesh_.nCells() == 0)
    {
        return where;
    }
    const cellList& cells = mesh_.cells();
    const faceList& faces = mesh_.faces();
    const scalarField& V = mesh_.cellVolumes();

    // Per cell its first tet whose volume is not negligible against the
    // cell's (found once per cell, when a particle first needs it)
    labelList& tetFace = tetFace_;
    labelList& tetPt = tetPt_;
    auto firstTet = [&](const label c)
    {
        if (tetFace[c] >= 0) return;
        for (const label f : cells[c])
        {
            for (label k = 1; k < faces[f].size() - 1; ++k)
            {
                const tetIndices ti(c, f, k);
                if (mag(ti.tet(mesh_).mag()) > 1e-6*V[c])
                {
                    tetFace[c] = f;
                    tetPt[c] = k;
                    return;
                }
            }
        }
        FatalErrorInFunction
            << "Cell " << c << " of the mesh has no tet of non-zero volume"
            << abort(FatalError);
    };

    for (label i = 0; i < n; ++i)
    {
        const point p(x(i, 0), x(i, 1), dim == 3 ? x(i, 2) : zPlane);
        label c = tree_.findInside(p);
        if (c < 0)
        {
            c = tree_.findNearest(p, GREAT).index();
        }
        firstTet(c);
        where.cell[i] = c;
        where.tetFace[i] = tetFace[c];
        where.tetPt[i] = tetPt[c];
        where.coordinates[i] =
            tetIndices(c, tetFace[c], tetPt[c]).tet(mesh_)
           .pointToBarycentric(p);
    }
    return where;
}


void Foam::meshless::lagrangianIO::write
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName,
    const scalar zPlane
)
{
    meshLocation none;
    none.cell.setSize(set.size(), -1);
    write(set, runTime, timeName, zPlane, none);
}


void Foam::meshless::lagrangianIO::write
(
    const particleSet& set,
    const Time& runTime,
    const word& timeName,
    const scalar zPlane,
    const meshLocation& where
)
{
    const label dim = set.dim();
    const label n = set.size();
    const particleField& x = set.positions();
    if (where.cell.size() != n)
    {
        FatalErrorInFunction
            << "Cloud " << set.name() << ": " << where.cell.size()
            << " cells for " << n << " particles" << abort(FatalError);
    }
    const bool located = (where.coordinates.size() == n && n > 0);

    // A file of the cloud in OpenFOAM's Cloud layout: the positions (the
    // legacy format every lagrangian reader understands) and OpenFOAM's own
    // coordinates
    auto open = [&]
    (
        const word& name,
        autoPtr<OFstream>& os,
        const IOstream::streamFormat format
    )
    {
        const IOobject io(cloudObject(name, runTime, timeName, set.name()));
        const IOobject header
        (
            cloudObject
            (
                name, runTime, atomicTimeWriter::timeOf(timeName), set.name()
            )
        );
        mkDir(io.path());
        os.reset(new OFstream(io.objectPath(), format));
        os().precision(max(os().precision(), restartPrecision));
        header.writeHeader(os(), "Cloud<passiveParticle>");
        os() << n << nl << token::BEGIN_LIST << nl;
    };
    auto close = [](autoPtr<OFstream>& os)
    {
        os() << token::END_LIST << nl;
        IOobject::writeEndDivider(os());
        if (!os().good())
        {
            FatalErrorInFunction
                << "Failed writing " << os().name() << exit(FatalError);
        }
        os.clear();
    };

    pointField exact(n);
    {
        autoPtr<OFstream> os;
        open(particleSet::positionsName, os, IOstream::ASCII);
        for (label i = 0; i < n; ++i)
        {
            exact[i] =
                point(x(i, 0), x(i, 1), dim == 3 ? x(i, 2) : zPlane);
            os() << exact[i] << token::SPACE << where.cell[i] << nl;
        }
        close(os);
    }
    if (located || n == 0)
    {
        // In writeFormat (they only place the particles in the mesh; the
        // exact positions are the 'position' field's): binary as
        // OpenFOAM's particle writes it, the barycentric coordinates and
        // the cell, tet face and tet point packed
        autoPtr<OFstream> os;
        const IOstream::streamFormat format = runTime.writeFormat();
        open("coordinates", os, format);
        char buf[sizeof(barycentric) + 3*sizeof(label)];
        for (label i = 0; i < n; ++i)
        {
            if (format == IOstream::BINARY)
            {
                const label tet[3] =
                    {where.cell[i], where.tetFace[i], where.tetPt[i]};
                std::memcpy
                (
                    buf, where.coordinates[i].cdata(), sizeof(barycentric)
                );
                std::memcpy(buf + sizeof(barycentric), tet, sizeof(tet));
                os().write(buf, sizeof(buf));
                os() << nl;
            }
            else
            {
                os() << where.coordinates[i] << token::SPACE
                    << where.cell[i] << token::SPACE << where.tetFace[i]
                    << token::SPACE << where.tetPt[i] << nl;
            }
        }
        close(os);
    }
    writeList(exactPositionName, exact, runTime, timeName, set.name());

    {
        labelList ids(n);
        std::copy(set.ids().begin(), set.ids().end(), ids.begin());
        writeList("id", ids, runTime, timeName, set.name());
    }

    for (const word& name : set.fieldNames())
    {
        if
        (
            name != particleSet::positionsName
         && name != exactPositionName
         && set.field(name).written()
        )
        {
            writeField(set, name, runTime, timeName);
        }
    }
}


void Foam::meshless::lagrangianIO::writeLabelLists
(
    const word& name,
    const UList<labelField>& values,
    const Time& runTime,
    const word& timeName,
    const word& body
)
{
    writeList(name, values, runTime, timeName, body);
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


void Foam::meshless::lagrangianIO::addLegacyPositions
(
    const Time& runTime,
    const word& timeName,
    const word& body
)
{
    const fileName dir = runTime.path()/timeName/cloudLocal(body);
    const fileName posFile = dir/particleSet::positionsName;
    if
    (
        isFile(posFile) || isFile(posFile + ".gz")
     || !isFile(dir/exactPositionName)
    )
    {
        return;
    }
    IOobjectList objects(runTime, timeName, cloudLocal(body));
    const autoPtr<IOField<vector>> pExact
    (
        readIOField<vector>(*objects.findObject(exactPositionName), body)
    );
    const IOField<vector>& exact = pExact();

    const fileName tmp = posFile + ".tmp";
    {
        OFstream os(tmp, IOstream::ASCII);
        os.precision(max(os.precision(), restartPrecision));
        cloudObject(particleSet::positionsName, runTime, timeName, body)
            .writeHeader(os, "Cloud<passiveParticle>");
        os  << exact.size() << nl << token::BEGIN_LIST << nl;
        forAll(exact, i)
        {
            os  << exact[i] << token::SPACE << -1 << nl;
        }
        os  << token::END_LIST << nl;
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            FatalErrorInFunction
                << "Failed writing " << tmp << exit(FatalError);
        }
    }
    Foam::mv(tmp, posFile);
}


void Foam::meshless::lagrangianIO::read
(
    particleSet& set,
    const Time& runTime,
    const word& timeName
)
{
    const label dim = set.dim();

    IOobjectList objects(runTime, timeName, cloudLocal(set.name()));
    const IOobject* exactIO = objects.findObject(exactPositionName);
    const fileName posFile
    (
        cloudObject(particleSet::positionsName, runTime, timeName, set.name())
        .objectPath()
    );
    const bool readPositions =
        !exactIO || isFile(posFile) || isFile(posFile + ".gz");

    label n = 0;
    if (readPositions)
    {
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

        IFstream is(posFile);
        if (!is.good())
        {
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, posFile)
                << "Cannot open the positions of cloud " << set.name()
                << " at time " << timeName << ": expected a readable file"
                << exit(FatalIOError);
        }
        if (!posIO.readHeader(is))
        {
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, posFile)
                << "Cannot read the header of the positions of cloud "
                << set.name() << " at time " << timeName << " (empty or"
                << " truncated?): expected a FoamFile header of class "
                << "Cloud<passiveParticle>" << exit(FatalIOError);
        }

        // Every token checked, so that a truncated or damaged file says where
        // it ends instead of failing in the parser or reading garbage
        n = readPositionsCount(is, posFile);
        set.resize(n);
        particleField& x = set.positions();
        const bool binary = (is.format() == IOstream::BINARY);
        if (binary && (!is.checkLabelSize<>() || !is.checkScalarSize<>()))
        {
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, posFile)
                << "Binary positions of cloud " << set.name() << " with labels"
                << " of " << is.labelByteSize() << " and scalars of "
                << is.scalarByteSize() << " bytes: expected this build's "
                << sizeof(label) << " and " << sizeof(scalar) << " bytes (or"
                << " ascii)" << exit(FatalIOError);
        }
        for (label i = 0; i < n; ++i)
        {
            vector p;
            if (binary)
            {
                // OpenFOAM's binary positions: (x y z celli) packed
                char buf[sizeof(vector) + sizeof(label)];
                is.read(buf, sizeof(buf));
                if (!is.good())
                {
                    FatalIOError
                    (
                        FUNCTION_NAME, __FILE__, __LINE__, posFile,
                        is.lineNumber()
                    )   << "Particle " << i << " of " << n << ": cannot read its"
                        << " binary position and cell (the file is truncated or"
                        << " damaged)" << exit(FatalIOError);
                }
                std::memcpy(p.data(), buf, sizeof(vector));
            }
            else
            {
                expectPunctuation(is, posFile, token::BEGIN_LIST, i, n, "'('");
                for (direction d = 0; d < vector::nComponents; ++d)
                {
                    p[d] = readPositionNumber(is, posFile, i, n, "a coordinate")
                        .number();
                }
                expectPunctuation
                (
                    is, posFile, token::END_LIST, i, n,
                    "')' after three coordinates"
                );
                if
                (
                    !readPositionNumber(is, posFile, i, n, "a cell label")
                    .isLabel()
                )
                {
                    FatalIOError
                    (
                        FUNCTION_NAME, __FILE__, __LINE__, posFile,
                        is.lineNumber()
                    )   << "Particle " << i << " of " << n << ": expected a cell"
                        << " label (an integer, -1) after the position"
                        << exit(FatalIOError);
                }
            }
            for (label d = 0; d < dim; ++d) x(i, d) = p[d];
        }
        expectPunctuation
        (
            is, posFile, token::END_LIST, n, n, "')' closing the list"
        );

    }

    // The exact positions, when written: OpenFOAM's utilities round the
    // positions file's and write none of the project's (see the header)
    if (exactIO)
    {
        const autoPtr<IOField<vector>> pExact
        (
            readIOField<vector>(*exactIO, set.name())
        );
        const IOField<vector>& exact = pExact();
        if (readPositions && exact.size() != n)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, exact.objectPath()
            )   << "Field " << exactPositionName << " of cloud " << set.name()
                << " has " << exact.size() << " entries, the cloud has " << n
                << " particles (its positions): expected " << n
                << " entries, one per particle" << exit(FatalIOError);
        }
        n = exact.size();
        set.resize(n);
        particleField& x = set.positions();
        for (label i = 0; i < n; ++i)
        {
            for (label d = 0; d < dim; ++d) x(i, d) = exact[i][d];
        }
    }

    const IOobject* idIO = objects.findObject("id");
    if (idIO)
    {
        const autoPtr<IOField<label>> pIds
        (
            readIOField<label>(*idIO, set.name())
        );
        const IOField<label>& ids = pIds();
        if (ids.size() != n)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, ids.objectPath()
            )   << "The id field of cloud " << set.name() << " has "
                << ids.size() << " entries, the cloud has " << n
                << " particles (its positions): expected " << n
                << " ids, one per particle" << exit(FatalIOError);
        }
        set.setIds(std::vector<label>(ids.begin(), ids.end()));
    }

    readFields<scalar>(set, objects, particleField::kind::scalar);
    readFields<vector>(set, objects, particleField::kind::vector);
    readFields<tensor>(set, objects, particleField::kind::tensor);
}

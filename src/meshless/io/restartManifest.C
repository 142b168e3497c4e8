/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "restartManifest.H"
#include "lagrangianIO.H"
#include "atomicTimeWriter.H"
#include "IOField.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "HashSet.H"
#include "cloud.H"

const Foam::word Foam::meshless::restartManifest::manifestName
(
    "restartManifest"
);


namespace
{

using namespace Foam;
using namespace Foam::meshless;

//- The class a field of this kind is written with (lagrangianIO)
word fieldClass(const particleField::kind k)
{
    switch (k)
    {
        case particleField::kind::scalar: return IOField<scalar>::typeName;
        case particleField::kind::vector: return IOField<vector>::typeName;
        case particleField::kind::tensor: return IOField<tensor>::typeName;
    }
    return word::null;
}


//- Every file below dir, as paths relative to it (a compressed file
//  without its .gz)
void listFiles(const fileName& dir, const fileName& rel, DynamicList<fileName>& out)
{
    for (const fileName& f : readDir(dir/rel, fileName::FILE, true, false))
    {
        out.append(rel.empty() ? f : rel/f);
    }
    for (const fileName& d : readDir(dir/rel, fileName::DIRECTORY, false, false))
    {
        listFiles(dir, rel.empty() ? d : rel/d, out);
    }
}


//- Run f with FatalError and FatalIOError thrown instead of exiting;
//  false (and the message in why) when it raised one
template<class Function>
bool guarded(const Function& f, string& why)
{
    const bool oldIO = FatalIOError.throwExceptions();
    const bool old = FatalError.throwExceptions();
    bool ok = true;
    try
    {
        f();
    }
    catch (const Foam::error& e)
    {
        why = e.message();
        ok = false;
    }
    FatalIOError.throwExceptions(oldIO);
    FatalError.throwExceptions(old);
    return ok;
}


//- Read a manifest (FatalIOError from the parser when it is damaged)
dictionary readManifest(const fileName& file)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << "Cannot open the restart manifest" << exit(FatalIOError);
    }
    token t(is);
    if (!is.good() || !t.isWord() || t.wordToken() != "FoamFile")
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << "The restart manifest has no FoamFile header (empty or"
            << " truncated): expected a dictionary with 'bodies' and"
            << " 'files'" << exit(FatalIOError);
    }
    const dictionary header(is);
    dictionary manifest(is);
    if (!manifest.found("bodies") || !manifest.found("files"))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << "The restart manifest is incomplete (truncated?): expected"
            << " the entries 'bodies' and 'files'" << exit(FatalIOError);
    }
    return manifest;
}


//- What is wrong with one listed field of a body ("" if nothing)
string fieldProblem
(
    const fileName& file,
    const word& expectedClass,
    const label expectedSize
)
{
    if (!isFile(file))
    {
        return "the file is missing";
    }
    word cls;
    label size = -1;
    string why;
    if (!restartManifest::readClassAndSize(file, cls, size, why))
    {
        return why;
    }
    if (cls != expectedClass)
    {
        return "it is a " + cls;
    }
    if (size != expectedSize)
    {
        return "it has " + Foam::name(size) + " entries";
    }
    return string::null;
}


//- What is wrong with a body of a manifest at a time ("" if nothing):
//  field is set to the field or file concerned, expected to what it
//  should be
string bodyProblem
(
    const Time& runTime,
    const word& timeName,
    const word& body,
    const dictionary& manifest,
    fileName& file,
    string& expected
)
{
    const fileName timeDir(runTime.path()/timeName);
    const dictionary& bodyDict = manifest.subDict("bodies").subDict(body);
    const label size = bodyDict.get<label>("particles");
    const dictionary& fields = bodyDict.subDict("fields");
    for (const entry& e : fields)
    {
        const word cls(e.stream());
        file = timeDir/lagrangianIO::cloudLocal(body)/e.keyword();
        const string why = fieldProblem(file, cls, size);
        if (!why.empty())
        {
            expected = "a " + cls + " of " + Foam::name(size) + " entries";
            return why;
        }
    }
    const fileName local(lagrangianIO::cloudLocal(body));
    for (const fileName& f : manifest.get<fileNameList>("files"))
    {
        const bool ofBody = f.path() == local;
        const bool ofCloud = f.path().path() == fileName(cloud::prefix);
        if (ofBody || !ofCloud)
        {
            file = timeDir/f;
            if (!isFile(file))
            {
                expected = "the file " + f;
                return "the file is missing";
            }
        }
    }
    return string::null;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

Foam::fileName Foam::meshless::restartManifest::path
(
    const Time& runTime,
    const word& timeName
)
{
    return runTime.path()/timeName/"uniform"/manifestName;
}


bool Foam::meshless::restartManifest::found
(
    const Time& runTime,
    const word& timeName
)
{
    return isFile(path(runTime, timeName));
}


bool Foam::meshless::restartManifest::readClassAndSize
(
    const Foam::fileName& file,
    word& className,
    label& size,
    string& why
)
{
    IFstream is(file);
    if (!is.good())
    {
        why = "the file cannot be opened";
        return false;
    }
    string err;
    bool ok = true;
    const bool read = guarded
    (
        [&]()
        {
            token t(is);
            if (!is.good() || !t.isWord() || t.wordToken() != "FoamFile")
            {
                why = "the file has no FoamFile header (empty or damaged)";
                ok = false;
                return;
            }
            const dictionary header(is);
            className = header.getOrDefault<word>("class", word::null);
            token n(is);
            if (!is.good() || !n.isLabel())
            {
                why = "the file ends before its data (truncated)";
                ok = false;
                return;
            }
            size = n.labelToken();
        },
        err
    );
    if (!read)
    {
        why = "the file's header cannot be read (truncated or damaged)";
        return false;
    }
    return ok;
}


void Foam::meshless::restartManifest::write
(
    const UPtrList<const particleSet>& sets,
    const Time& runTime,
    const word& instance
)
{
    const fileName dir(runTime.path()/instance);

    dictionary bodies;
    HashSet<fileName> fieldFiles;
    forAll(sets, k)
    {
        const particleSet& set = sets[k];
        const label n = set.size();
        const fileName local(lagrangianIO::cloudLocal(set.name()));

        dictionary fields;
        auto add = [&](const word& name, const word& cls)
        {
            fields.add(name, cls);
            fieldFiles.insert(local/name);
        };
        add(particleSet::positionsName, "Cloud<passiveParticle>");
        add("id", IOField<label>::typeName);
        for (const word& name : set.fieldNames())
        {
            const particleField& f = set.field(name);
            if (name != particleSet::positionsName && f.written())
            {
                add(name, fieldClass(f.fieldKind()));
            }
        }

        dictionary body;
        body.add("particles", n);
        if (Pstream::parRun())
        {
            // What a reconstructed case holds (reconstructPar copies the
            // first processor's manifest)
            body.add("particlesGlobal", returnReduce(n, sumOp<label>()));
        }
        body.add("fields", fields);
        bodies.add(set.name(), body);
    }

    DynamicList<fileName> all;
    listFiles(dir, fileName::null, all);
    DynamicList<fileName> files;
    const fileName self(fileName("uniform")/manifestName);
    for (const fileName& f : all)
    {
        if (!fieldFiles.found(f) && f != self)
        {
            files.append(f);
        }
    }
    Foam::sort(files);

    dictionary manifest;
    manifest.add("bodies", bodies);
    manifest.add("files", fileNameList(files));

    atomicTimeWriter::writeUniform
    (
        runTime, instance, manifestName, manifest,
        "// What this time directory holds for a restart: per body its"
        " particle count\n"
        "// and the class of each field of its cloud (each with an entry"
        " per particle),\n"
        "// and every other file written with it. A start from this time"
        " checks them."
    );
}


Foam::string Foam::meshless::restartManifest::problem
(
    const Time& runTime,
    const word& timeName,
    const wordList& bodies
)
{
    const fileName timeDir(runTime.path()/timeName);
    string result;
    string err;
    const bool ok = guarded
    (
        [&]()
        {
            const fileName manifestFile(path(runTime, timeName));
            const bool hasManifest = isFile(manifestFile);
            dictionary manifest;
            if (hasManifest)
            {
                manifest = readManifest(manifestFile);
            }
            for (const word& body : bodies)
            {
                const fileName pos
                (
                    timeDir/lagrangianIO::cloudLocal(body)
                   /particleSet::positionsName
                );
                if
                (
                    hasManifest
                 && manifest.subDict("bodies").found(body)
                )
                {
                    fileName file;
                    string expected;
                    const string why = bodyProblem
                    (
                        runTime, timeName, body, manifest, file, expected
                    );
                    if (!why.empty())
                    {
                        result = file + ": " + why;
                        return;
                    }
                }
                else if (!isFile(pos))
                {
                    result = "no cloud of body " + body;
                    return;
                }
            }
        },
        err
    );
    if (!ok)
    {
        return "cannot be read: " + err;
    }
    return result;
}


Foam::word Foam::meshless::restartManifest::latestComplete
(
    const Time& runTime,
    const word& timeName,
    const wordList& bodies
)
{
    scalar current = GREAT;
    readScalar(timeName, current);
    const instantList times(Time::findTimes(runTime.path(), runTime.constant()));
    for (label i = times.size() - 1; i >= 0; --i)
    {
        const instant& t = times[i];
        if (t.name() == runTime.constant() || t.value() >= current)
        {
            continue;
        }
        if (problem(runTime, t.name(), bodies).empty())
        {
            return t.name();
        }
    }
    return word::null;
}


void Foam::meshless::restartManifest::checkBody
(
    const Time& runTime,
    const word& timeName,
    const word& body
)
{
    const fileName manifestFile(path(runTime, timeName));

    // The particles of this cloud (-1: none) and, in a parallel run, of
    // every processor's (a collective call, made for every body)
    const fileName cloudDir
    (
        runTime.path()/timeName/lagrangianIO::cloudLocal(body)
    );
    label local = -1;
    {
        word cls;
        label n = 0;
        string why;
        const fileName idFile(cloudDir/"id");
        if (isFile(idFile) && readClassAndSize(idFile, cls, n, why)) local = n;
    }
    const label global =
        Pstream::parRun()
      ? returnReduce(Foam::max(local, label(0)), sumOp<label>())
      : local;

    if (!isFile(manifestFile))
    {
        return;
    }
    dictionary manifest;
    string err;
    if (!guarded([&]() { manifest = readManifest(manifestFile); }, err))
    {
        const word earlier(latestComplete(runTime, timeName, wordList{body}));
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, manifestFile)
            << "Restart time directory " << timeName << ": its restart"
            << " manifest cannot be read (truncated or damaged: "
            << err.c_str() << "). Expected the dictionary of 'bodies' and"
            << " 'files' the solver writes last at each write time." << nl
            << "    ";
        if (earlier.empty())
        {
            FatalIOError << "No earlier time directory is complete.";
        }
        else
        {
            FatalIOError
                << "The latest earlier complete time directory is "
                << earlier.c_str() << ".";
        }
        FatalIOError << exit(FatalIOError);
    }
    const dictionary& bodies = manifest.subDict("bodies");
    if (!bodies.found(body))
    {
        // A cloud put into a written time by hand: read as seeded
        return;
    }

    // A part of the case the manifest lists whole (a processor's folder
    // from decomposePar, which copies the manifest) or the whole of a
    // case it lists a part of (reconstructPar copies the first
    // processor's): this cloud's own count, and decomposePar's exact
    // position field for the positions
    {
        dictionary& bodyDict = manifest.subDict("bodies").subDict(body);
        const label listed = bodyDict.get<label>("particles");
        const label whole =
            bodyDict.getOrDefault<label>("particlesGlobal", listed);
        if (local != listed && global == whole && global >= 0)
        {
            if (local < 0) return;
            bodyDict.set("particles", local);
        }
        if
        (
            !isFile(cloudDir/particleSet::positionsName)
         && isFile(cloudDir/lagrangianIO::exactPositionName)
        )
        {
            bodyDict.subDict("fields").remove(particleSet::positionsName);
        }
    }

    fileName file;
    string expected;
    const string why =
        bodyProblem(runTime, timeName, body, manifest, file, expected);
    if (why.empty())
    {
        return;
    }

    const word earlier(latestComplete(runTime, timeName, bodies.toc()));
    const fileName rel(file.relative(runTime.path()));
    FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
        << "Restart time directory " << timeName << " is incomplete: ";
    if (file.path() == runTime.path()/timeName/lagrangianIO::cloudLocal(body))
    {
        FatalIOError << "body " << body << ", ";
    }
    FatalIOError
        << rel.c_str() << ": " << why.c_str()
        << "; expected " << expected.c_str() << ", as listed in "
        << timeName.c_str() << "/uniform/" << manifestName.c_str()
        << nl << "    ";
    if (earlier.empty())
    {
        FatalIOError
            << "No earlier time directory is complete: seed the case again"
            << " (seedParticles) or restore the file.";
    }
    else
    {
        FatalIOError
            << "The latest earlier complete time directory is "
            << earlier.c_str() << ": continue from it (startFrom startTime;"
            << " startTime " << earlier.c_str() << ";), or restore the file.";
    }
    FatalIOError << exit(FatalIOError);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "atomicTimeWriter.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOdictionary.H"
#include "DynamicList.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

const Foam::word Foam::meshless::atomicTimeWriter::prefix(".incomplete.");

const Foam::word Foam::meshless::atomicTimeWriter::purgePrefix(".purged.");


// * * * * * * * * * * * * * * * Helper classes  * * * * * * * * * * * * * * //

Foam::meshless::atomicTimeWriter::timeNameScope::timeNameScope
(
    Time& runTime,
    const word& name
)
:
    runTime_(runTime),
    saved_(runTime.timeName())
{
    static_cast<dimensionedScalar&>(runTime_).name() = name;
}


Foam::meshless::atomicTimeWriter::timeNameScope::~timeNameScope()
{
    static_cast<dimensionedScalar&>(runTime_).name() = saved_;
}


namespace
{

//- Names in dir (hidden ones included: Foam::readDir skips those) that
//  begin with start and end with end
Foam::DynamicList<Foam::word> hiddenNames
(
    const Foam::fileName& dir,
    const std::string& start,
    const std::string& end
)
{
    Foam::DynamicList<Foam::word> found;
    if (DIR* d = ::opendir(dir.c_str()))
    {
        while (const dirent* e = ::readdir(d))
        {
            const std::string name(e->d_name);
            if
            (
                name != "." && name != ".."
             && name.size() >= start.size() + end.size()
             && name.compare(0, start.size(), start) == 0
             && name.compare(name.size() - end.size(), end.size(), end) == 0
            )
            {
                found.append(Foam::word(name, false));
            }
        }
        ::closedir(d);
    }
    return found;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::atomicTimeWriter::atomicTimeWriter(Time& runTime)
:
    runTime_(runTime),
    pending_(),
    written_()
{}


// * * * * * * * * * * * * * * * Static functions  * * * * * * * * * * * * * //

Foam::word Foam::meshless::atomicTimeWriter::temporaryName
(
    const word& timeName
)
{
    return prefix + timeName;
}


Foam::word Foam::meshless::atomicTimeWriter::timeOf(const word& instance)
{
    if (instance.compare(0, prefix.size(), prefix) == 0)
    {
        return instance.substr(prefix.size());
    }
    return instance;
}


void Foam::meshless::atomicTimeWriter::writeUniform
(
    const Time& runTime,
    const word& instance,
    const word& name,
    const dictionary& dict,
    const char* comment
)
{
    auto object = [&](const word& inst)
    {
        return IOobject
        (
            name,
            inst,
            "uniform",
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
    };
    const IOobject io(object(instance));
    mkDir(io.path());
    OFstream os(io.objectPath(), IOstream::ASCII);
    os.precision(std::numeric_limits<scalar>::max_digits10);
    object(timeOf(instance)).writeHeader(os, IOdictionary::typeName);
    if (comment)
    {
        os  << comment << nl << nl;
    }
    dict.write(os, false);
    IOobject::writeEndDivider(os);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Failed writing " << os.name() << exit(FatalError);
    }
}


Foam::autoPtr<Foam::dictionary> Foam::meshless::atomicTimeWriter::readUniform
(
    const Time& runTime,
    const word& timeName,
    const word& name,
    const char* expected
)
{
    const fileName file(runTime.path()/timeName/"uniform"/name);
    if (!isFile(file))
    {
        return nullptr;
    }
    IFstream is(file);
    IOobject io
    (
        name,
        timeName,
        "uniform",
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.readHeader(is))
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file)
            << "Cannot read the header of " << file << " (empty or"
            << " truncated): expected " << expected << exit(FatalIOError);
    }
    return autoPtr<dictionary>::New(is);
}


Foam::label Foam::meshless::atomicTimeWriter::removeLeftovers
(
    const Time& runTime
)
{
    const fileName dir(runTime.path());
    const DynamicList<word> found(hiddenNames(dir, prefix, ""));
    for (const word& name : found)
    {
        Info<< "Removing " << name << ": an incomplete time directory left"
            << " by an interrupted write (never used for a restart)" << endl;
        rmDir(dir/name);
    }
    for (const word& name : hiddenNames(dir, purgePrefix, ""))
    {
        Info<< "Removing " << name << ": a time directory purgeWrite had"
            << " begun to remove" << endl;
        rmDir(dir/name);
    }

    // The VTK writer's temporary files (vtpWriter), below VTK/ and VTK/<body>
    label nVtk = 0;
    const fileName vtk(dir/"VTK");
    if (isDir(vtk))
    {
        fileNameList dirs(readDir(vtk, fileName::DIRECTORY, false, false));
        dirs.append(fileName::null);
        for (const fileName& sub : dirs)
        {
            const fileName d(sub.empty() ? vtk : vtk/sub);
            for (const word& name : hiddenNames(d, ".", ".incomplete"))
            {
                Foam::rm(d/name);
                ++nVtk;
            }
        }
    }
    if (nVtk)
    {
        Info<< "Removed " << nVtk << " incomplete VTK file(s) below VTK/"
            << " left by an interrupted write" << endl;
    }
    if (found.size() || nVtk)
    {
        Info<< endl;
    }
    return found.size();
}


bool Foam::meshless::atomicTimeWriter::syncPath(const fileName& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
    {
        return false;
    }
    const bool ok = ::fsync(fd) == 0;
    ::close(fd);
    return ok;
}


void Foam::meshless::atomicTimeWriter::syncTree(const fileName& dir)
{
    // Unfiltered names (writeCompression's .gz kept), not following links
    for (const fileName& f : readDir(dir, fileName::FILE, false, false))
    {
        if (!syncPath(dir/f))
        {
            WarningInFunction
                << "Could not sync " << dir/f << " to disk" << endl;
        }
    }
    for (const fileName& d : readDir(dir, fileName::DIRECTORY, false, false))
    {
        syncTree(dir/d);
    }
    syncPath(dir);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::atomicTimeWriter::begin()
{
    if (pending())
    {
        FatalErrorInFunction
            << "A write of time " << pending_ << " is pending: commit it"
            << " before time " << runTime_.timeName() << abort(FatalError);
    }
    pending_ = runTime_.timeName();
    const fileName tmp(runTime_.path()/instance());
    if (isDir(tmp, false))
    {
        rmDir(tmp);
    }
    if (!mkDir(tmp))
    {
        FatalErrorInFunction
            << "Cannot create " << tmp << " to write time " << pending_
            << exit(FatalError);
    }
}


void Foam::meshless::atomicTimeWriter::writeTimeState
(
    const dictionary& extra
)
{
    if (!pending())
    {
        FatalErrorInFunction
            << "No write pending" << abort(FatalError);
    }

    // What Time::writeTimeDict writes, with the step at full precision
    dictionary timeDict;
    const int digits = std::numeric_limits<scalar>::max_digits10;
    timeDict.add
    (
        "value",
        Time::timeName(runTime_.timeToUserTime(runTime_.value()), digits)
    );
    timeDict.add("name", string(pending_));
    timeDict.add("index", runTime_.timeIndex());
    timeDict.add("deltaT", runTime_.timeToUserTime(runTime_.deltaTValue()));
    timeDict.add("deltaT0", runTime_.timeToUserTime(runTime_.deltaT0Value()));
    timeDict.merge(extra);
    writeUniform(runTime_, instance(), "time", timeDict);

    // Any AUTO_WRITE object of the registry (none of the solvers' own)
    timeNameScope scope(runTime_, instance());
    runTime_.objectRegistry::writeObject
    (
        runTime_.writeFormat(),
        IOstream::currentVersion,
        runTime_.writeCompression(),
        true
    );
}


void Foam::meshless::atomicTimeWriter::commit()
{
    if (!pending())
    {
        FatalErrorInFunction
            << "No write pending" << abort(FatalError);
    }
    const fileName tmp(runTime_.path()/instance());
    const fileName dst(runTime_.path()/pending_);

    // Every file on disk before the directory gets its name; in a
    // parallel run every processor's, so that the processors' renames
    // follow each other closely (a kill between them leaves processors at
    // different latest times, which a restart refuses)
    syncTree(tmp);
    if (Pstream::parRun()) returnReduce(true, andOp<bool>());

    bool done = false;
    if (isDir(dst, false))
    {
        // A time of an earlier run: exchange atomically, then remove the
        // old content (now under the temporary name)
        #ifdef RENAME_EXCHANGE
        if
        (
            ::renameat2
            (
                AT_FDCWD, tmp.c_str(), AT_FDCWD, dst.c_str(), RENAME_EXCHANGE
            ) == 0
        )
        {
            rmDir(tmp);
            done = true;
        }
        #endif
        if (!done)
        {
            // No atomic exchange on this file system: a moment without
            // the time, never a partial one
            const fileName hidden(runTime_.path()/(purgePrefix + pending_));
            if (::rename(dst.c_str(), hidden.c_str()) == 0)
            {
                rmDir(hidden);
            }
            else
            {
                rmDir(dst);
            }
        }
    }
    else if (exists(dst, false))
    {
        FatalErrorInFunction
            << "Cannot write time " << pending_ << ": " << dst
            << " exists and is not a directory" << exit(FatalError);
    }
    if (!done)
    {
        if (::rename(tmp.c_str(), dst.c_str()) != 0)
        {
            FatalErrorInFunction
                << "Cannot rename " << tmp << " to " << dst << ": "
                << std::strerror(errno) << exit(FatalError);
        }
    }
    syncPath(runTime_.path());

    if (written_.empty() || written_.back() != pending_)
    {
        written_.push_back(pending_);
    }
    pending_.clear();

    // purgeWrite: the oldest times this run wrote, once the new one is in
    // place (on every processor)
    if (Pstream::parRun()) returnReduce(true, andOp<bool>());
    const label purge =
        max(runTime_.controlDict().getOrDefault<label>("purgeWrite", 0), 0);
    if (purge > 0)
    {
        while (label(written_.size()) > purge)
        {
            // Hidden first, then removed: a kill while removing leaves no
            // partial time directory
            const fileName old(runTime_.path()/written_.front());
            const fileName hidden(runTime_.path()/(purgePrefix + written_.front()));
            if (::rename(old.c_str(), hidden.c_str()) == 0)
            {
                rmDir(hidden);
            }
            written_.pop_front();
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "monitor.H"
#include "particleScene.H"
#include "dictionaryChecks.H"
#include "OSspecific.H"
#include "IFstream.H"
#include "atomicTimeWriter.H"
#include "StringStream.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(monitor, 0);
    defineRunTimeSelectionTable(monitor, dictionary);
}
}

const Foam::word Foam::meshless::monitor::stateName("monitors");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::monitor::monitor
(
    const word& name,
    const dictionary& dict,
    const particleScene& scene
)
:
    name_(name),
    interval_
    (
        dict.found("interval") ? readPositiveLabel(dict, "interval") : 1
    ),
    lastTime_(-GREAT),
    scene_(scene)
{}


Foam::autoPtr<Foam::meshless::monitor> Foam::meshless::monitor::New
(
    const word& name,
    const dictionary& dict,
    const particleScene& scene
)
{
    const word monitorType(dict.get<word>("type"));
    return selectConstructor
    (
        dict, "monitor", monitorType, *dictionaryConstructorTablePtr_
    )(name, dict, scene);
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

Foam::OFstream& Foam::meshless::monitor::file()
{
    if (!file_.valid())
    {
        const Time& runTime = scene_.time();
        const fileName dir =
            runTime.globalPath()/"postProcessing"/name_/runTime.timeName();
        mkDir(dir);
        file_.reset(new OFstream(dir/(name_ + ".dat")));
        file_().precision(12);
        file_() << "# " << type() << " monitor " << name_ << nl << "# time";
        for (const word& c : columns()) file_() << tab << c;
        file_() << nl;
    }
    return file_();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::monitor::sample(const scalar t, const bool force)
{
    const Time& runTime = scene_.time();
    const bool first = lastTime_ == -GREAT;
    const bool onInterval = runTime.timeIndex() % interval_ == 0;
    if ((first || force || onInterval) && t != lastTime_)
    {
        lastTime_ = t;
        // Every processor takes part in the values' reductions, the master
        // writes them
        if (Pstream::master())
        {
            OFstream& os = file();
            os << t;
            writeValues(os);
            os << endl;
        }
        else
        {
            OStringStream os;
            writeValues(os);
        }
    }
}


const Foam::dictionary* Foam::meshless::monitor::restartState() const
{
    // Read once per process: every monitor of a scene asks at construction
    static autoPtr<dictionary> states;
    static fileName statesFile;

    const Time& runTime = scene_.time();
    const fileName file
    (
        runTime.path()/runTime.timeName()/"uniform"/stateName
    );
    if (statesFile != file)
    {
        statesFile = file;
        states = atomicTimeWriter::readUniform
        (
            runTime, runTime.timeName(), stateName,
            "the monitors' restart state, a dictionary with an entry per"
            " monitor"
        );
    }
    return states.valid() ? states->findDict(name_) : nullptr;
}


void Foam::meshless::monitor::writeStates
(
    const PtrList<monitor>& monitors,
    const Time& runTime,
    const word& instance
)
{
    dictionary states;
    for (const monitor& m : monitors)
    {
        dictionary d;
        m.writeState(d);
        if (!d.empty())
        {
            states.add(m.name(), d);
        }
    }
    if (states.empty())
    {
        return;
    }

    atomicTimeWriter::writeUniform
    (
        runTime, instance, stateName, states,
        "// The monitors' state a restart needs to continue their series"
    );
}


// ************************************************************************* //

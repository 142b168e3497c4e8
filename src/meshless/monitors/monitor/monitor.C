/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "monitor.H"
#include "particleScene.H"
#include "dictionaryChecks.H"
#include "OSspecific.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(monitor, 0);
    defineRunTimeSelectionTable(monitor, dictionary);
}
}


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
    calls_(0),
    lastTime_(-GREAT),
    dict_(dict),
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

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(monitorType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "monitor",
            monitorType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(name, dict, scene);
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
    if ((force || calls_ % interval_ == 0) && t != lastTime_)
    {
        lastTime_ = t;
        OFstream& os = file();
        os << t;
        writeValues(os);
        os << endl;
    }
    ++calls_;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleTimeLoop.H"
#include "atomicTimeWriter.H"
#include "dictionaryChecks.H"
#include "OFstream.H"
#include "OSspecific.H"
#ifdef _OPENMP
#include <omp.h>
#endif
#include "IOdictionary.H"
#include <chrono>
#include <cmath>
#include <cstdio>

namespace
{

double wallSeconds()
{
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

//- <time>/uniform/time of the Time's current time (empty when absent)
Foam::dictionary uniformTime(const Foam::Time& runTime)
{
    using Foam::IOobject;
    return Foam::IOdictionary
    (
        IOobject
        (
            "time",
            runTime.timeName(),
            "uniform",
            runTime,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );
}

} // End anonymous namespace


Foam::meshless::particleTimeLoop::particleTimeLoop
(
    Time& runTime,
    particleScene& scene
)
:
    runTime_(runTime),
    scene_(scene),
    adjustTimeStep_
    (
        runTime.controlDict().getOrDefault<bool>("adjustTimeStep", false)
    ),
    maxCo_(readPositiveOrDefault(runTime.controlDict(), "maxCo", 0.25)),
    maxDeltaT_(readPositiveOrDefault(runTime.controlDict(), "maxDeltaT", GREAT)),
    largestStep_(0),
    writeControl_(runTime.controlDict().get<word>("writeControl")),
    writeInterval_(readPositive(runTime.controlDict(), "writeInterval")),
    writeOrigin_(runTime.startTime().value())
{
    checkEndTime(runTime);

    // The write-time grid of the run's first start, when this start lies
    // on it (a restart from a write time)
    const dictionary timeDict(uniformTime(runTime));
    scalar origin = writeOrigin_;
    if (timeDict.readIfPresent("writeOrigin", origin))
    {
        const scalar k = (runTime.value() - origin)/writeInterval_;
        if (std::abs(k - std::round(k)) < 1e-6)
        {
            writeOrigin_ = origin;
        }
    }
    if (adjustTimeStep_ && !runTime.controlDict().found("maxCo"))
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "adjustTimeStep is on but 'maxCo' is missing: expected the"
            << " Courant number of the adaptive step (e.g. maxCo 0.25;)"
            << exit(FatalIOError);
    }
}


void Foam::meshless::particleTimeLoop::checkEndTime(const Time& runTime)
{
    const dictionary& dict = runTime.controlDict();
    if (dict.getOrDefault<word>("stopAt", "endTime") != "endTime")
    {
        return;
    }
    const scalar start = runTime.value();
    const scalar end = runTime.endTime().value();
    if (start < end - 0.5*runTime.deltaTValue())
    {
        return;
    }

    const entry* e = dict.findEntry("endTime", keyType::LITERAL);
    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__, dict.name(),
        e ? e->startLineNumber() : -1, e ? e->endLineNumber() : -1
    )   << "endTime " << runTime.timeName(end) << " is "
        << (end <= start ? "at or before" : "less than half a step after")
        << " the start time " << runTime.timeName() << " (startFrom "
        << dict.getOrDefault<word>("startFrom", "latestTime")
        << "): nothing to run. Expected endTime > " << runTime.timeName()
        << " (by at least half of deltaT " << runTime.deltaTValue() << ")"
        << exit(FatalIOError);
}


void Foam::meshless::particleTimeLoop::restoreStartTime(Time& runTime)
{
    const dictionary timeDict(uniformTime(runTime));
    // Written in user time, as Time writes it
    scalar userValue = 0;
    if (!timeDict.readIfPresent("value", userValue))
    {
        return;
    }
    const scalar value = runTime.userTimeToTime(userValue);
    if
    (
        value != runTime.value()
     && runTime.timeName(userValue) == runTime.timeName()
    )
    {
        runTime.setTime(value, runTime.timeIndex());
    }
}


void Foam::meshless::particleTimeLoop::prepareStart(Time& runTime)
{
    restoreStartTime(runTime);
    checkEndTime(runTime);
}


bool Foam::meshless::particleTimeLoop::lastStep() const
{
    // Time::run()'s test, without its side effects (function objects)
    return
        !(
            runTime_.value()
          < runTime_.endTime().value() - 0.5*runTime_.deltaTValue()
        );
}


Foam::scalar Foam::meshless::particleTimeLoop::adaptiveDeltaT
(
    const scalar stable
) const
{
    scalar dt = stable;

    // Land on the next write time and on the end time with equal steps no
    // longer than dt (Time::adjustDeltaT would round the step count to the
    // nearest, lengthening steps beyond the stable one by up to 50 %)
    const scalar t = runTime_.value();
    scalar target = runTime_.endTime().value();
    if (writeControl_ == "adjustableRunTime")
    {
        const scalar t0 = writeOrigin_;
        const scalar k = std::floor((t - t0)/writeInterval_ + 1e-9) + 1;
        target = min(target, t0 + k*writeInterval_);
    }
    const scalar remaining = target - t;
    if (remaining > 0)
    {
        dt = remaining/std::ceil(remaining/dt - 1e-9);
    }
    return dt;
}


void Foam::meshless::particleTimeLoop::writeRunCost
(
    const double loopSeconds,
    const label steps,
    const double particleSteps,
    const bool completed
) const
{
    dictionary d;
    d.add
    (
        "solver",
        runTime_.controlDict().getOrDefault<word>("application", "unknown")
    );
    #ifdef _OPENMP
    d.add("threads", label(omp_get_max_threads()));
    #else
    d.add("threads", label(1));
    #endif
    d.add("processors", label(Pstream::nProcs()));
    d.add("startTime", runTime_.startTime().value());
    d.add("time", runTime_.value());
    d.add("steps", steps);
    d.add("wallTime", loopSeconds);
    d.add("cpuTime", runTime_.elapsedCpuTime());
    d.add("particleSteps", particleSteps);
    d.add
    (
        "particleStepsPerSecond",
        loopSeconds > 0 ? particleSteps/loopSeconds : 0.0
    );
    d.add("completed", word(completed ? "true" : "false"));
    scene_.runCost(d);
    d.add("parts", scene_.costs().dict(loopSeconds, particleSteps));

    // The master's (the counts are every processor's, the times its own).
    // Complete or not at all: written beside, then renamed
    if (!Pstream::master()) return;
    const fileName dir =
        runTime_.globalPath()/"postProcessing"/"runCost"
       /runTime_.timeName(runTime_.startTime().value());
    mkDir(dir);
    const fileName tmp(dir/".runCost.tmp");
    {
        OFstream os(tmp);
        IOobject io
        (
            "runCost", runTime_.timeName(), runTime_,
            IOobject::NO_READ, IOobject::NO_WRITE, false
        );
        io.writeHeader(os, "dictionary");
        d.write(os, false);
        IOobject::writeEndDivider(os);
    }
    Foam::mv(tmp, dir/"runCost");
}


void Foam::meshless::particleTimeLoop::run(const stepFunction& step)
{
    const scalar stable = scene_.maxDeltaT(maxCo_);
    if (adjustTimeStep_ && stable >= 0.5*GREAT && maxDeltaT_ >= 0.5*GREAT)
    {
        FatalIOErrorInFunction(runTime_.controlDict())
            << "adjustTimeStep is on but no body limits the step (e.g. a"
            << " solid alone with integrator implicit): expected 'maxDeltaT'"
            << " in controlDict, or adjustTimeStep no with deltaT"
            << exit(FatalIOError);
    }
    if (adjustTimeStep_)
    {
        Info<< "Adaptive time step: maxCo " << maxCo_ << ", maxDeltaT "
            << maxDeltaT_ << nl << endl;
    }
    else if (runTime_.deltaTValue() > stable)
    {
        WarningInFunction
            << "Fixed deltaT " << runTime_.deltaTValue()
            << " exceeds the stable step " << stable
            << " of the initial state (maxCo " << maxCo_ << ")" << nl << endl;
    }

    // Everything of a write time goes into a temporary directory, renamed
    // to the time once complete (atomicTimeWriter): the scene's state and
    // OpenFOAM's uniform/time at the step, the function objects' state when
    // Time::run executes them after it; committed then
    atomicTimeWriter::removeLeftovers(runTime_);
    atomicTimeWriter writer(runTime_);
    auto running = [&]() -> bool
    {
        if (!writer.pending())
        {
            return runTime_.run();
        }
        bool r;
        {
            atomicTimeWriter::timeNameScope scope(runTime_, writer.instance());
            r = runTime_.run();
        }
        writer.commit();
        scene_.writeVtk();
        return r;
    };
    auto writeState = [&]()
    {
        writer.begin();
        atomicTimeWriter::timeNameScope scope(runTime_, writer.instance());
        dictionary loopState;
        loopState.add("writeOrigin", writeOrigin_);
        writer.writeTimeState(loopState);
        scene_.writeState();
    };

    const double start = wallSeconds();
    const scalar tStart = runTime_.value();
    double particleSteps = 0;
    label steps = 0;
    word lastWritten = runTime_.timeName();

    Info<< "Starting time loop" << nl << endl;
    scene_.sampleMonitors(runTime_.value());

    while (running())
    {
        if (adjustTimeStep_)
        {
            // A stable step six orders of magnitude below the largest step
            // of the run: a speed or an acceleration grew without bound
            const scalar stable = min(scene_.maxDeltaT(maxCo_), maxDeltaT_);
            if (stable < 1e-6*largestStep_)
            {
                FatalErrorInFunction
                    << "Blow-up at time " << runTime_.timeName()
                    << ": the stable time step collapsed to " << stable
                    << " s, below 1e-6 of the run's largest step ("
                    << largestStep_ << " s): a speed or an acceleration"
                    << " grew without bound (maxCo " << maxCo_ << ")" << nl
                    << "    Last good state on disk: time " << lastWritten
                    << exit(FatalError);
            }
            runTime_.setDeltaT(adaptiveDeltaT(stable), false);
        }

        ++runTime_;
        const scalar dt = runTime_.deltaTValue();
        largestStep_ = max(largestStep_, dt);
        const label nParticles = scene_.nParticles();

        step(runTime_.value() - dt, dt);
        particleSteps += nParticles;
        ++steps;

        scene_.checkState(lastWritten);
        scene_.sampleMonitors(runTime_.value(), lastStep());

        if (runTime_.writeTime())
        {
            // Committed by running(), before the next step's state check
            writeState();
            lastWritten = runTime_.timeName();
            writeRunCost(wallSeconds() - start, steps, particleSteps, false);
        }

        const double elapsed = wallSeconds() - start;
        const scalar done = runTime_.value() - tStart;
        const scalar left =
            max(runTime_.endTime().value() - runTime_.value(), 0);
        char line[256];
        std::snprintf
        (
            line, sizeof(line),
            "deltaT = %.6g  particles = %ld\n"
            "ExecutionTime = %.4g s  ClockTime = %.0f s  remaining ~ %.3g s",
            dt, long(nParticles), runTime_.elapsedCpuTime(),
            double(runTime_.elapsedClockTime()),
            done > 0 ? elapsed*left/done : 0.0
        );
        Info<< "Time = " << runTime_.timeName() << nl << line << nl << endl;
    }

    // Time writes only at write times; the final state is kept regardless
    // so that a run can always be continued from where it stopped
    if (lastWritten != runTime_.timeName())
    {
        Info<< "Writing the final state at time " << runTime_.timeName()
            << " (not a write time)" << nl << endl;
        writeState();
        writer.commit();
        scene_.writeVtk();
    }

    const double loop = wallSeconds() - start;
    writeRunCost(loop, steps, particleSteps, true);
    scene_.costs().print(Info, loop, particleSteps);
    char line[128];
    std::snprintf
    (
        line, sizeof(line), "Particle-steps per second: %.4g",
        loop > 0 ? particleSteps/loop : 0.0
    );
    Info<< nl << line << nl << endl;
}

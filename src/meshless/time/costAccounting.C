/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "costAccounting.H"
#include "IOstreams.H"
#include <algorithm>
#include <cstdio>

Foam::label Foam::meshless::costAccounting::part(const std::string& name)
{
    const auto iter = std::find(names_.begin(), names_.end(), name);
    if (iter != names_.end())
    {
        return label(iter - names_.begin());
    }
    names_.push_back(name);
    seconds_.push_back(0);
    calls_.push_back(0);
    return label(names_.size()) - 1;
}


void Foam::meshless::costAccounting::print
(
    Ostream& os,
    const double loopSeconds,
    const double particleSteps
) const
{
    char line[256];
    std::snprintf
    (
        line, sizeof(line), "    %-34s %12s %9s %16s",
        "part", "seconds", "% loop", "us/particle-step"
    );
    os  << "Cost per model and effect (wall-clock)" << nl << line << nl;
    for (size_t i = 0; i < names_.size(); ++i)
    {
        std::snprintf
        (
            line, sizeof(line), "    %-34s %12.4g %9.2f %16.4g",
            names_[i].c_str(),
            seconds_[i],
            loopSeconds > 0 ? 100*seconds_[i]/loopSeconds : 0.0,
            particleSteps > 0 ? 1e6*seconds_[i]/particleSteps : 0.0
        );
        os  << line << nl;
    }
    std::snprintf
    (
        line, sizeof(line), "    %-34s %12.4g %9.2f %16.4g",
        "time loop (all)", loopSeconds, 100.0,
        particleSteps > 0 ? 1e6*loopSeconds/particleSteps : 0.0
    );
    os  << line << nl;
}


Foam::dictionary Foam::meshless::costAccounting::dict
(
    const double loopSeconds,
    const double particleSteps
) const
{
    dictionary d;
    for (size_t i = 0; i < names_.size(); ++i)
    {
        dictionary p;
        p.add("seconds", seconds_[i]);
        p.add("calls", label(calls_[i]));
        p.add("share", loopSeconds > 0 ? seconds_[i]/loopSeconds : 0.0);
        p.add
        (
            "usPerParticleStep",
            particleSteps > 0 ? 1e6*seconds_[i]/particleSteps : 0.0
        );
        d.add(word(names_[i]), p);
    }
    return d;
}

/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "smoothingKernel.H"
#include "dictionaryChecks.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(smoothingKernel, 0);
    defineRunTimeSelectionTable(smoothingKernel, dictionary);
}
}


Foam::meshless::smoothingKernel::smoothingKernel
(
    const dictionary& dict,
    const label dim,
    const scalar spacing
)
:
    dim_(dim),
    h_(0),
    norm_(0),
    support_(0)
{
    if (dim != 2 && dim != 3)
    {
        FatalIOErrorInFunction(dict)
            << "Kernel dimension " << dim << ": expected 2 or 3"
            << exit(FatalIOError);
    }

    if (dict.found("smoothingLength"))
    {
        h_ = readPositive(dict, "smoothingLength");
    }
    else if (dict.found("smoothingLengthRatio"))
    {
        h_ = readPositive(dict, "smoothingLengthRatio")*spacing;
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Neither 'smoothingLength' (h) nor 'smoothingLengthRatio'"
            << " (h/dx) given: expected one of them" << exit(FatalIOError);
    }

    if (!(h_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Smoothing length " << h_ << " from spacing " << spacing
            << ": expected h > 0" << exit(FatalIOError);
    }
}


void Foam::meshless::smoothingKernel::setNormalisation(const scalar sigma)
{
    norm_ = sigma/(dim_ == 2 ? h_*h_ : h_*h_*h_);
    support_ = qMax();
}

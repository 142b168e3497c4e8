/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
-------------------------------------------------------------------------------
Description
    OpenFOAM's own scotch decomposition method (decomposePar's 'method
    scotch;'), compiled from the OpenFOAM source against Debian's scotch:
    Debian's OpenFOAM package ships only the stub of libscotchDecomp, which
    stops with "without the scotchDecomp library loaded". Built into the
    project's library folder, which comes first on LD_LIBRARY_PATH, so
    that decomposePar loads it instead of the stub.

\*---------------------------------------------------------------------------*/

#include "scotchDecomp.C"

// ************************************************************************* //

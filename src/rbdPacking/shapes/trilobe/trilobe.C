/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "trilobe.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(trilobe, 0);
    addToRunTimeSelectionTable(pelletShape, trilobe, dictionary);
}
}


// ************************************************************************* //

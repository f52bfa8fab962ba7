/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "quadrilobe.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(quadrilobe, 0);
    addToRunTimeSelectionTable(pelletShape, quadrilobe, dictionary);
}
}


// ************************************************************************* //

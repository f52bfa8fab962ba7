/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
-------------------------------------------------------------------------------
Application
    rbdPackBed

Description
    Skeleton (foundation in progress).
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    Info<< "End\n" << endl;
    return 0;
}

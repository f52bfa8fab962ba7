/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
-------------------------------------------------------------------------------
Application
    rbdPressureDrop

Group
    grpPostProcessingUtilities

Description
    Compare the pressure drop over the packed section of a bed case that
    rbdPackBed wrote and simpleFoam solved with the correlations of Ergun
    and of Eisfeld & Schnitzlein for the bed's own porosity
    (Foam::rbd::pressureDropComparison).

    Reads postProcessing/rbdPackBed/summary, constant/transportProperties,
    system/controlDict and the last values of the function objects
    pBedBottom, pBedTop and flowRate; prints the comparison and writes
    postProcessing/pressureDrop/comparison. Exits non-zero if the
    simulated pressure drop is missing (no function-object output), not
    finite or not positive.

Usage
    \b rbdPressureDrop [OPTION]

    Options:
      - \par -shape \<spheres|cylinders\>
        Eisfeld & Schnitzlein's constants for this pellet family (default:
        from the summary's pellet shape)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "pressureDropComparison.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Compare the simulated pressure drop over a packed bed with Ergun"
        " and Eisfeld-Schnitzlein"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "shape",
        "spheres|cylinders",
        "Eisfeld-Schnitzlein constants of this pellet family"
        " (default: from postProcessing/rbdPackBed/summary)"
    );

    #include "setRootCase.H"

    const rbd::pressureDropComparison comparison
    (
        args.path(),
        args.getOrDefault<word>("shape", word::null)
    );
    // (the constructor refuses a pressure drop that is not positive, a
    // flow rate that is not, and a viscosity out of range: nothing is
    // written then)
    comparison.report(Info);
    Info<< nl << "Wrote " << comparison.writeFile() << nl << endl;

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //

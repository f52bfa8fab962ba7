/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
-------------------------------------------------------------------------------
Application
    rbdPackBed

Group
    grpPreProcessingUtilities

Description
    Pack a random bed of catalyst pellets in a tube by hard-body rigid body
    dynamics (impulses with restitution and Coulomb friction, resting
    contacts as a linear complementarity problem, midpoint integration; no
    artificial damping), then write the pellets as one STL surface and the
    bed's porosity profiles.

    Reads system/packingDict (see the tutorials for a commented example);
    writes postProcessing/rbdPackBed/{summary,pellets.csv,
    radialPorosity.dat,axialPorosity.dat} and constant/triSurface/pellets.stl,
    and the CFD case around the bed for blockMesh, surfaceFeatureExtract,
    snappyHexMesh and simpleFoam (constant/triSurface/tube.stl, system/
    {blockMeshDict,surfaceFeatureExtractDict,snappyHexMeshDict,
    decomposeParDict,controlDict,fvSchemes,fvSolution}, constant/
    {transportProperties,turbulenceProperties}, 0/{U,p}; options in the
    cfdCase sub-dictionary). A case that holds the files of an earlier
    bed is refused before packing unless -overwrite (or
    cfdCase/overwrite), which removes them first: a case never mixes two
    beds. The run ends with a status (summary entry 'status'): only
    'settled' exits 0 and writes pellets.stl and the CFD case; notSettled,
    incomplete, stacked and interrupted (Ctrl-C or SIGTERM, which keep a
    checkpoint) exit 1 with a message saying what to change.
    Every dictionary entry is validated before anything runs or is written.

Usage
    \b rbdPackBed [OPTION]

    Options:
      - \par -dict \<file\>
        Read this dictionary instead of system/packingDict

      - \par -overwrite
        Remove the files of an earlier bed (pellets.stl, the CFD case, its
        mesh and results) and write the case anew

      - \par -acceptStatus
        Write pellets.stl and the CFD case, and exit 0, for a bed whose
        status is not 'settled'

      - \par -resume
        Continue the packing from postProcessing/rbdPackBed/checkpoint,
        which a run writes every simulation/checkpointInterval seconds of
        wall time and when it stops at endTime unsettled

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "sigFpe.H"
#include "packedBed.H"
#include "IStringStream.H"
#include <fstream>
#include <sstream>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Pack a random bed of pellets in a tube by hard-body rigid body"
        " dynamics and write it for snappyHexMesh.\n"
        "Reads system/packingDict (blocks container, pellets, loading,"
        " simulation, analysis, cfdCase; commented examples in"
        " tutorials/*/system/packingDict). Every entry is checked before"
        " the run; the effective settings, defaults included, are echoed"
        " at the start of the log.\n"
        "Writes constant/triSurface/pellets.stl, in postProcessing/"
        "rbdPackBed/ the summary, pellets.csv, radialPorosity.dat and"
        " axialPorosity.dat, and the CFD case (blockMesh,"
        " surfaceFeatureExtract,"
        " snappyHexMesh, simpleFoam).\n"
        "Example: rbdPackBed -case tutorials/spheres  (then blockMesh,"
        " surfaceFeatureExtract, snappyHexMesh -overwrite, simpleFoam;"
        " see the tutorial's Allrun)"
    );
    argList::noParallel();
    argList::noFunctionObjects();
    argList::addOption
    (
        "dict",
        "file",
        "Read this dictionary instead of system/packingDict"
    );
    argList::addBoolOption
    (
        "overwrite",
        "Remove the files of an earlier bed (pellets.stl, the CFD case"
        " files, constant/polyMesh, time and processor directories) and"
        " write the case anew; without it a case holding them is refused"
    );

    argList::addBoolOption
    (
        "acceptStatus",
        "Write pellets.stl and the CFD case, and exit 0, also for a bed"
        " whose status is not 'settled' (notSettled, incomplete, stacked)"
    );
    argList::addBoolOption
    (
        "resume",
        "Continue the packing from postProcessing/rbdPackBed/checkpoint"
        " (written every simulation/checkpointInterval s of wall time and"
        " when a run stops at endTime unsettled); the dictionary may change"
        " only simulation/{endTime,checkpointInterval,logInterval} and"
        " cfdCase"
    );

    #include "setRootCase.H"

    // No controlDict is needed: rbdPackBed writes the CFD case's own
    Time runTime
    (
        args.rootPath(), args.caseName(), "system", "constant", false, false
    );

    IOobject dictIO
    (
        "packingDict",
        runTime.system(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (args.found("dict"))
    {
        dictIO = IOobject::selectIO(dictIO, args.get<fileName>("dict"));
    }
    if (!isDir(runTime.path()))
    {
        FatalErrorInFunction
            << "The case " << runTime.path() << " is not a directory" << nl
            << "    (-case names the case directory, the one with "
            << "system/packingDict)" << nl
            << exit(FatalError);
    }
    if (!isFile(dictIO.objectPath()))
    {
        FatalErrorInFunction
            << "Cannot find the packing dictionary " << dictIO.objectPath()
            << nl << "    (system/packingDict of the case, or the file of "
            << "-dict); see tutorials/spheres/system/packingDict" << nl
            << exit(FatalError);
    }

    Info<< "Reading " << dictIO.objectPath() << nl << endl;

    // A number beyond the range of double (diameter 1e400) stops
    // OpenFOAM's parser on a floating-point exception: read without the
    // trap, so that the entry's check reports it (inf is not a size)
    autoPtr<IOdictionary> packingDictPtr;
    {
        const sigFpe::ignore noTrap;

        // An entry or a block given twice is an error: OpenFOAM's reader
        // keeps the last entry silently and merges two blocks. A first
        // parse in its 'error' input mode stops at the second one, naming
        // the file and the line (the directive shares the first line, so
        // the line numbers are the file's)
        {
            std::ifstream file(dictIO.objectPath());
            std::ostringstream text;
            text << "#inputMode error " << file.rdbuf();
            IStringStream is(text.str());
            is.name() = dictIO.objectPath();
            // (a string stream counts from 0; the file's first line is 1)
            is.lineNumber() = 1;
            const dictionary check(is);
            entry::resetInputMode();
        }

        packingDictPtr.reset(new IOdictionary(dictIO));
    }
    const IOdictionary& packingDict = packingDictPtr();

    // Validate everything, then run, then write
    rbd::packedBed bed(runTime, packingDict);
    if (args.found("overwrite"))
    {
        bed.setOverwrite(true);
    }
    bed.writeSettings(Info);
    if (args.found("acceptStatus"))
    {
        bed.setAcceptStatus(true);
    }
    if (args.found("resume"))
    {
        bed.resume();
    }
    bed.run();
    bed.write();

    // The command that continues this run from its checkpoint
    string resume("rbdPackBed -case " + runTime.path() + " -resume");
    if (args.found("dict"))
    {
        resume += " -dict " + args.get<fileName>("dict");
    }
    if (!bed.reportOutcome(Info, resume))
    {
        // Every status but 'settled' is a failure of the run. (argList's
        // destructor ends the process with status 0: 'return 1' from
        // main would not reach the shell)
        UPstream::exit(1);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //

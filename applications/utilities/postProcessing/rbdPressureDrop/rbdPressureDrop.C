/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
-------------------------------------------------------------------------------
Application
    rbdPressureDrop

Group
    grpPostProcessingUtilities

Description
    Compare the pressure drop of a bed case that rbdPackBed wrote and
    simpleFoam solved with the correlations of Ergun and of Eisfeld &
    Schnitzlein, each section at its own porosity
    (Foam::rbd::pressureDropComparison):
    - the packed section, floor to porosityHeight, without the loose top
      layer, at the summary's bulkPorosity: the pressure on its top plane
      is the area average of the cell values of p of the latest time on
      the plane (Foam::rbd::planeSection, as the function objects sample);
    - the whole bed, floor to the top of the highest pellet, at the
      summary's bedPorosity (the function objects pBedBottom, pBedTop).
    Prints the porosity each used and whether the case lies in each
    correlation's range (Re_p, Nv = dt/dpv, porosity, shape); and beside
    the summary's bulkPorosity and stlPorosity the porosity of the fluid
    mesh itself, its volume between the planes over pi D^2/4 L
    (planeSection::volumeBelow), so that one sees what the CFD saw.

    Reads postProcessing/rbdPackBed/summary, constant/transportProperties,
    system/controlDict, the last values of the function objects
    pBedBottom, pBedTop and flowRate, and the mesh and p of the latest
    time; prints the comparison and writes
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
#include "Time.H"
#include "polyMesh.H"
#include "pressureDropComparison.H"
#include "planeSection.H"

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

    rbd::pressureDropComparison comparison
    (
        args.path(),
        args.getOrDefault<word>("shape", word::null)
    );

    // The fluid mesh's volume in both sections (its porosity, what the
    // CFD saw), and the packed section's top plane, sampled on the latest
    // solution
    {
        #include "createTime.H"
        const instantList times(runTime.times());
        const fileName pFile
        (
            runTime.path()/times.last().name()/"p"
        );
        const bool solved = times.last().value() > 0 && isFile(pFile);
        if (solved)
        {
            runTime.setTime(times.last(), times.size() - 1);
        }
        if (!isDir(runTime.path()/"constant/polyMesh"))
        {
            FatalErrorInFunction
                << "No mesh in " << runTime.path()/"constant/polyMesh"
                << ": rbdPressureDrop compares a meshed and solved case"
                << " (blockMesh, snappyHexMesh -overwrite, simpleFoam)"
                << exit(FatalError);
        }
        const polyMesh mesh
        (
            IOobject
            (
                polyMesh::defaultRegion,
                runTime.timeName(),
                runTime,
                IOobject::MUST_READ
            )
        );

        const auto below = [&mesh](const scalar z)
        {
            return rbd::planeSection::volumeBelow
            (
                mesh.points(), mesh.faces(), mesh.nInternalFaces(), z
            );
        };
        const scalar z0 = comparison.bottomHeight();
        const scalar V0 = below(z0);
        comparison.setFluidVolumes
        (
            below(z0 + comparison.length()) - V0,
            comparison.hasPackedSection()
          ? below(comparison.packedTopHeight()) - V0
          : 0
        );

        if (comparison.hasPackedSection() && solved)
        {
            const scalar z = comparison.packedTopHeight();
            scalar area = 0;
            const scalar p = rbd::planeSection::areaAverage
            (
                rbd::planeSection::readInternalField(pFile, mesh.nCells()),
                rbd::planeSection::cellAreas
                (
                    mesh.points(), mesh.faces(), mesh.faceOwner(),
                    mesh.faceNeighbour(), mesh.nCells(), z
                ),
                area
            );
            Info<< "p on the packed section's top plane z = " << z
                << " m (time " << runTime.timeName() << ", fluid area "
                << area << " m^2): " << p << " m^2/s^2" << nl << endl;
            comparison.setPackedTopPressure(p);
        }
        else if (comparison.hasPackedSection())
        {
            Info<< "No solution (p of a time > 0) in " << runTime.path()
                << ": the packed section is not measured" << nl << endl;
        }
    }
    // (the constructor refuses a pressure drop that is not positive, a
    // flow rate that is not, and a viscosity out of range: nothing is
    // written then)
    comparison.report(Info);
    Info<< nl << "Wrote " << comparison.writeFile() << nl << endl;

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //

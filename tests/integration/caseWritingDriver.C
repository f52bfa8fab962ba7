/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
-------------------------------------------------------------------------------
Description
    Test driver for caseWritingEndToEnd.sh (built by tests/CMakeLists.txt
    into build/tests/caseWritingDriver).

    caseWritingDriver write <caseDir> ['<options dictionary entries>']
        write the hand-placed 18-sphere bed of caseWritingTestBed.H
        (dp = 10 mm, D = 40 mm): constant/triSurface/pellets.stl, the
        summary postProcessing/rbdPackBed/summary, and the case files of
        bedCaseWriter with the given options (e.g. "nIterations 100;")

    caseWritingDriver compare <caseDir>
        run pressureDropComparison on the solved case: print the table,
        write postProcessing/pressureDrop/comparison; exit 1 unless the
        simulated pressure drop is finite and positive
\*---------------------------------------------------------------------------*/

#include "bedCaseWriter.H"
#include "pressureDropComparison.H"
#include "foamFile.H"
#include "rbdPacking/caseWriting/caseWritingTestBed.H"
#include "IOstreams.H"
#include <cmath>

using namespace Foam;

int main(int argc, char* argv[])
{
    const std::string usage =
        "usage: caseWritingDriver write <caseDir> ['<options>']\n"
        "       caseWritingDriver compare <caseDir>\n";
    if (argc < 3)
    {
        std::cerr << usage;
        return 2;
    }
    const std::string mode(argv[1]);
    const fileName caseDir(argv[2]);

    if (mode == "write")
    {
        const scalar dp = 0.01;
        const pointField c = caseWritingTestBed::centres(dp);
        const dictionary options
        (
            rbd::parseDictionary(argc > 3 ? argv[3] : "")
        );
        const rbd::bedCaseSettings settings
        (
            caseWritingTestBed::tubeDiameter(dp),
            dp,
            caseWritingTestBed::bedHeight(dp),
            Zero,
            options
        );
        const scalar r = 0.5*dp*settings.pelletScale();

        caseWritingTestBed::writeSpheres
        (
            caseDir/"constant/triSurface"/rbd::bedCaseWriter::pelletFile,
            c, r
        );
        caseWritingTestBed::writeSummary(caseDir, dp);

        rbd::bedCaseWriter writer
        (
            caseDir,
            settings,
            [&](const point& p) { return caseWritingTestBed::inside(c, r, p); }
        );
        writer.write();

        Info<< "Wrote case " << caseDir << " for " << c.size()
            << " spheres, porosity " << caseWritingTestBed::porosity(dp)
            << nl << "caseWriting" << nl << "{" << nl << incrIndent;
        settings.write(Info);
        Info<< decrIndent << "}" << nl;
        return 0;
    }
    else if (mode == "compare")
    {
        const rbd::pressureDropComparison comparison(caseDir);
        comparison.report(Info);
        Info<< "Wrote " << comparison.writeFile() << nl;
        const scalar s = comparison.simulated();
        return (std::isfinite(s) && s > 0) ? 0 : 1;
    }
    std::cerr << usage;
    return 2;
}

// ************************************************************************* //

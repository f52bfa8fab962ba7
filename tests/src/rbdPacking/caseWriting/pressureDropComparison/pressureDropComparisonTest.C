// Unit tests for src/rbdPacking/caseWriting/pressureDropComparison: a case
// written by bedCaseWriter, with a hand-written summary and hand-written
// function-object output

#include <gtest/gtest.h>
#include "pressureDropComparison.H"
#include "correlations.H"
#include "bedCaseWriter.H"
#include "foamFile.H"
#include "OFstream.H"
#include "mathematicalConstants.H"
#include "rbdPacking/caseWriting/caseWritingTempDir.H"

using namespace Foam;

namespace
{
    const scalar dp = 0.01, D = 0.04, H = 0.05, eps = 0.45, nu = 1e-5;

    //- A surfaceFieldValue.dat as v1912 writes it
    void writeDat
    (
        const fileName& caseDir,
        const word& object,
        const word& startTime,
        const word& column,
        const List<scalar>& values
    )
    {
        const fileName file
        (
            caseDir/"postProcessing"/object/startTime/"surfaceFieldValue.dat"
        );
        mkDir(file.path());
        OFstream os(file);
        os.precision(10);
        os  << "# Region type : patch inlet" << nl
            << "# Faces         : 812" << nl
            << "# Time          \t" << column << nl;
        forAll(values, i)
        {
            os  << i + 1 << "               \t" << values[i] << nl;
        }
    }

    //- The case: dictionaries by bedCaseWriter, summary and output by hand
    void writeCase(const fileName& caseDir)
    {
        const rbd::bedCaseSettings s
        (
            D, dp, H, point::zero,
            rbd::parseDictionary("nu 1e-5;")
        );
        rbd::bedCaseWriter(caseDir, s, [](const point&) { return false; })
            .write();

        rbd::writeFoamFile
        (
            caseDir/"postProcessing/rbdPackBed/summary", "dictionary",
            "shape sphere; bedPorosity 0.45; bulkPorosity 0.41;"
            " tubeDiameter 0.04; pelletDiameter 0.01;"
            " bedHeight 0.05; porosityHeight 0.04;"
        );

        // An old run from 0, the newest from 100: the newest counts
        writeDat(caseDir, "flowRate", "0", "sum(phi)", {-1, -1});
        writeDat(caseDir, "pBedBottom", "0", "areaAverage(p)", {9, 9});
        writeDat(caseDir, "pBedTop", "0", "areaAverage(p)", {1, 1});
        writeDat
        (
            caseDir, "flowRate", "100", "sum(phi)", {-2e-6, -1.25e-6}
        );
        writeDat
        (
            caseDir, "pBedBottom", "100", "areaAverage(p)", {0.3, 0.2}
        );
        writeDat(caseDir, "pBedTop", "100", "areaAverage(p)", {0.02, 0.01});
    }
}


TEST(pressureDropComparison, readsTheCaseAndComparesWithCorrelations)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path());

    const rbd::pressureDropComparison c(tmp.path());
    const scalar U = 1.25e-6/(0.25*constant::mathematical::pi*sqr(D));
    EXPECT_DOUBLE_EQ(c.porosity(), eps);
    EXPECT_NEAR(c.length(), H, 1e-12);
    EXPECT_NEAR(c.superficialVelocity(), U, 1e-15);
    EXPECT_NEAR(c.reynoldsNumber(), U*dp/nu, 1e-12);
    EXPECT_NEAR(c.simulated(), (0.2 - 0.01)/H, 1e-12);
    EXPECT_EQ(c.shape(), "spheres");
    EXPECT_NEAR
    (
        c.ergun(), rbd::correlations::ergun(nu, 1, U, eps, dp), 1e-12
    );
    EXPECT_NEAR
    (
        c.eisfeldSchnitzlein(),
        rbd::correlations::eisfeldSchnitzlein
        (
            nu, 1, U, eps, dp, D,
            rbd::correlations::eisfeldSchnitzleinShape::sphere
        ),
        1e-12
    );

    // Cylinder constants on request: a larger viscous term (K1 = 190)
    const rbd::pressureDropComparison cyl(tmp.path(), "cylinders");
    EXPECT_NEAR
    (
        cyl.eisfeldSchnitzlein(),
        rbd::correlations::eisfeldSchnitzlein
        (
            nu, 1, U, eps, dp, D,
            rbd::correlations::eisfeldSchnitzleinShape::cylinder
        ),
        1e-12
    );
    EXPECT_GT(cyl.eisfeldSchnitzlein(), c.eisfeldSchnitzlein());

    const fileName file = c.writeFile();
    const dictionary d(rbd::readFoamFile(file));
    EXPECT_NEAR(d.get<scalar>("dPdLSimulated"), c.simulated(), 1e-9);
    EXPECT_NEAR
    (
        d.get<scalar>("ratioErgun"), c.simulated()/c.ergun(), 1e-9
    );
    EXPECT_FALSE(d.found("dPdLSimulatedPa"));
}


TEST(pressureDropComparison, correlationsUseTheVolumeEquivalentDiameter)
{
    // A cylinder bed: d = h = 10 mm, dpv = 1.5^(1/3) d; the correlations'
    // dp is dpv, not the nominal diameter
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path());
    // (as the summary holds it: 6 significant digits)
    const scalar dpv = readScalar(Foam::name(std::cbrt(1.5)*dp));
    rbd::writeFoamFile
    (
        tmp.path()/"postProcessing/rbdPackBed/summary", "dictionary",
        "shape cylinder; bedPorosity 0.45; tubeDiameter 0.04;"
        " pelletDiameter 0.01; volumeEquivalentDiameter "
      + Foam::name(dpv) + "; bedHeight 0.05;"
    );
    const rbd::pressureDropComparison c(tmp.path());
    const scalar U = c.superficialVelocity();
    EXPECT_EQ(c.shape(), "cylinders");
    EXPECT_NEAR(c.reynoldsNumber(), U*dpv/nu, 1e-12);
    EXPECT_NEAR
    (
        c.ergun(), rbd::correlations::ergun(nu, 1, U, eps, dpv),
        1e-9*c.ergun()
    );
    EXPECT_NEAR
    (
        c.eisfeldSchnitzlein(),
        rbd::correlations::eisfeldSchnitzlein
        (
            nu, 1, U, eps, dpv, D,
            rbd::correlations::eisfeldSchnitzleinShape::cylinder
        ),
        1e-9*c.eisfeldSchnitzlein()
    );
    // Creeping flow: the viscous term dominates, ~ 1/dp^2
    EXPECT_LT
    (
        c.ergun(), 0.8*rbd::correlations::ergun(nu, 1, U, eps, dp)
    );
    const dictionary d(rbd::readFoamFile(c.writeFile()));
    EXPECT_NEAR(d.get<scalar>("volumeEquivalentDiameter"), dpv, 1e-12);
}


TEST(pressureDropComparison, lastValueOfNewestRun)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path());
    const Pair<scalar> last =
        rbd::pressureDropComparison::lastValue(tmp.path(), "pBedBottom");
    EXPECT_EQ(last[0], 2);
    EXPECT_EQ(last[1], 0.2);
}


TEST(pressureDropComparisonDeath, stopsWithoutSimulationOutput)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path());
    rmDir(tmp.path()/"postProcessing/pBedTop");
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(tmp.path()).simulated(),
        ::testing::ExitedWithCode(1),
        "No output of function object pBedTop"
    );
}


TEST(pressureDropComparisonDeath, stopsWithoutSummary)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path());
    rm(tmp.path()/"postProcessing/rbdPackBed/summary");
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(tmp.path()).simulated(),
        ::testing::ExitedWithCode(1),
        "Cannot read .*summary"
    );
}


TEST(pressureDropComparisonDeath, rejectsShapesWithoutConstants)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path());
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(tmp.path(), "rings").simulated(),
        ::testing::ExitedWithCode(1),
        "No Eisfeld-Schnitzlein constants for shape 'rings'"
    );
    rbd::writeFoamFile
    (
        tmp.path()/"postProcessing/rbdPackBed/summary", "dictionary",
        "shape ring; bedPorosity 0.45; tubeDiameter 0.04;"
        " pelletDiameter 0.01; bedHeight 0.05;"
    );
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(tmp.path()).simulated(),
        ::testing::ExitedWithCode(1),
        "pellets of shape 'ring'(.|\n)*spheres(.|\n)*cylinders"
    );
}


TEST(pressureDropComparisonDeath, rejectsResultsOfNoFlowOrAbsurdInputs)
{
    // Each once a SIGFPE (zero flow rate, nu 0, a flow rate of 1e300) or
    // a comparison written for a negative or infinite pressure drop
    const caseWritingTest::tempDir tmp;
    const fileName c(tmp.path());
    writeCase(c);
    writeDat(c, "flowRate", "100", "sum(phi)", {0, 0});
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(c).simulated(),
        ::testing::ExitedWithCode(1),
        "superficial velocity of 0 m/s(.|\n)*allowed: \\(0, 1000\\] m/s"
    );
    writeDat(c, "flowRate", "100", "sum(phi)", {1e300});
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(c).simulated(),
        ::testing::ExitedWithCode(1),
        "allowed: \\(0, 1000\\] m/s"
    );
    writeDat(c, "flowRate", "100", "sum(phi)", {-2e-6, -1.25e-6});
    writeDat(c, "pBedTop", "100", "areaAverage(p)", {0.5, 0.5});
    EXPECT_EXIT
    (
        rbd::pressureDropComparison(c).simulated(),
        ::testing::ExitedWithCode(1),
        "simulated pressure drop .* is not a positive number"
    );
    writeDat(c, "pBedTop", "100", "areaAverage(p)", {0.02, 0.01});
    for (const char* nu : {"0", "-1", "1e10"})
    {
        rbd::writeFoamFile
        (
            c/"constant/transportProperties", "dictionary",
            std::string("transportModel Newtonian; nu ") + nu + ";"
        );
        EXPECT_EXIT
        (
            rbd::pressureDropComparison(c).simulated(),
            ::testing::ExitedWithCode(1),
            "Bad entry 'nu .*(.|\n)*allowed: a kinematic viscosity in"
            " \\(0, 1\\]"
        ) << nu;
    }
}

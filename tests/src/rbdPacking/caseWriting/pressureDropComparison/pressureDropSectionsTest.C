// Unit tests for src/rbdPacking/caseWriting/pressureDropComparison: the
// packed section below porosityHeight at the summary's bulk porosity next
// to the whole bed at bedPorosity, the porosity each used in the report,
// and the verdicts on the correlations' ranges (Re_p, Nv, porosity, shape)

#include <gtest/gtest.h>
#include "pressureDropComparison.H"
#include "correlations.H"
#include "bedCaseWriter.H"
#include "foamFile.H"
#include "OFstream.H"
#include "OStringStream.H"
#include "mathematicalConstants.H"
#include "rbdPacking/caseWriting/caseWritingTempDir.H"

using namespace Foam;

namespace
{
    const scalar dp = 0.01, D = 0.04, H = 0.05, nu = 1e-5;

    void writeDat
    (
        const fileName& caseDir,
        const word& object,
        const scalar value
    )
    {
        const fileName file
        (
            caseDir/"postProcessing"/object/"0"/"surfaceFieldValue.dat"
        );
        mkDir(file.path());
        OFstream os(file);
        os.precision(10);
        os  << "# Time          \tvalue" << nl << "1 \t" << value << nl;
    }

    //- A bed case of D = 4 dp, H = 5 dp: planes 0.05 m apart, pressures
    //  0.2 and 0.01 m^2/s^2, U = 1e-3 m/s (Re_p = 1)
    void writeCase(const fileName& caseDir, const std::string& summary)
    {
        const rbd::bedCaseSettings s
        (
            D, dp, H, point::zero, rbd::parseDictionary("nu 1e-5;")
        );
        rbd::bedCaseWriter(caseDir, s, [](const point&) { return false; })
            .write();
        rbd::writeFoamFile
        (
            caseDir/"postProcessing/rbdPackBed/summary", "dictionary",
            summary
        );
        writeDat
        (
            caseDir, "flowRate", -1e-3*0.25*constant::mathematical::pi*D*D
        );
        writeDat(caseDir, "pBedBottom", 0.2);
        writeDat(caseDir, "pBedTop", 0.01);
    }

    const std::string sphereSummary
    (
        "shape sphere; bedPorosity 0.45; bulkPorosity 0.41;"
        " tubeDiameter 0.04; pelletDiameter 0.01;"
        " bedHeight 0.05; porosityHeight 0.04;"
    );

    //- The reasons as one line, for a failure message
    std::string joined(const stringList& why)
    {
        std::string s;
        for (const string& w : why)
        {
            s += w + "; ";
        }
        return s;
    }

    bool has(const stringList& why, const std::string& text)
    {
        for (const string& s : why)
        {
            if (s.find(text) != std::string::npos)
            {
                return true;
            }
        }
        return false;
    }
}


TEST(pressureDropSections, packedSectionAtTheBulkPorosity)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path(), sphereSummary);

    rbd::pressureDropComparison c(tmp.path());
    ASSERT_TRUE(c.hasPackedSection());
    EXPECT_FALSE(c.packedMeasured());
    EXPECT_NEAR(c.packedTopHeight(), 0.04, 1e-12);

    c.setPackedTopPressure(0.05);
    ASSERT_TRUE(c.packedMeasured());
    const scalar U = c.superficialVelocity();
    EXPECT_NEAR(U, 1e-3, 1e-12);
    EXPECT_NEAR(c.packedSimulated(), (0.2 - 0.05)/0.04, 1e-12);
    EXPECT_DOUBLE_EQ(c.packedPorosity(), 0.41);
    EXPECT_NEAR
    (
        c.packedErgun(), rbd::correlations::ergun(nu, 1, U, 0.41, dp),
        1e-12
    );
    EXPECT_NEAR
    (
        c.packedEisfeldSchnitzlein(),
        rbd::correlations::eisfeldSchnitzlein
        (
            nu, 1, U, 0.41, dp, D,
            rbd::correlations::eisfeldSchnitzleinShape::sphere
        ),
        1e-12
    );
    // The whole bed keeps its own porosity
    EXPECT_DOUBLE_EQ(c.porosity(), 0.45);
    EXPECT_NEAR(c.simulated(), (0.2 - 0.01)/H, 1e-12);

    const dictionary d(rbd::readFoamFile(c.writeFile()));
    EXPECT_DOUBLE_EQ(d.get<scalar>("bedPorosity"), 0.45);
    const dictionary& packed = d.subDict("packedSection");
    EXPECT_DOUBLE_EQ(packed.get<scalar>("porosity"), 0.41);
    EXPECT_NEAR(packed.get<scalar>("zTop"), 0.04, 1e-12);
    EXPECT_NEAR
    (
        packed.get<scalar>("dPdLSimulated"), c.packedSimulated(), 1e-9
    );
    EXPECT_NEAR
    (
        packed.get<scalar>("ratioEisfeldSchnitzlein"),
        c.packedSimulated()/c.packedEisfeldSchnitzlein(), 1e-9
    );
    EXPECT_NEAR(d.get<scalar>("diameterRatio"), 4, 1e-12);

    // The report names the porosity of each section and where it is from
    OStringStream os;
    c.report(os);
    const std::string text(os.str());
    EXPECT_NE
    (
        text.find("without the loose top layer, z from 0 to 0.04 m"),
        std::string::npos
    ) << text;
    EXPECT_NE
    (
        text.find("porosity 0.41 (bulkPorosity of the summary"),
        std::string::npos
    ) << text;
    EXPECT_NE
    (
        text.find("porosity 0.45 (bedPorosity of the summary"),
        std::string::npos
    ) << text;
}


TEST(pressureDropSections, wholeBedOnlyWithoutPorosityHeight)
{
    const caseWritingTest::tempDir tmp;
    writeCase
    (
        tmp.path(),
        "shape sphere; bedPorosity 0.45; tubeDiameter 0.04;"
        " pelletDiameter 0.01; bedHeight 0.05;"
    );
    const rbd::pressureDropComparison c(tmp.path());
    EXPECT_FALSE(c.hasPackedSection());
    EXPECT_FALSE(rbd::readFoamFile(c.writeFile()).found("packedSection"));

    // A porosityHeight at the top plane is the whole bed again
    writeCase(tmp.path(), sphereSummary + " porosityHeight 0.05;");
    EXPECT_FALSE(rbd::pressureDropComparison(tmp.path()).hasPackedSection());
}


TEST(pressureDropSections, rangesOfTheCorrelations)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path(), sphereSummary);
    const rbd::pressureDropComparison c(tmp.path());

    // N = 4: Ergun (no wall correction) is outside, Eisfeld & Schnitzlein
    // (1.624 <= Nv <= 250, Re_p = 1, porosity 0.45, spheres) inside
    const stringList ergun(c.outsideRange("ergun"));
    EXPECT_EQ(ergun.size(), 1) << joined(ergun);
    EXPECT_TRUE(has(ergun, "Nv = dt/dpv = 4 not >= 10")) << joined(ergun);
    EXPECT_TRUE(c.outsideRange("eisfeldSchnitzlein").empty());

    OStringStream os;
    c.report(os);
    const std::string text(os.str());
    EXPECT_NE
    (
        text.find("Ergun: OUTSIDE its range: Nv = dt/dpv = 4"),
        std::string::npos
    ) << text;
    EXPECT_NE
    (
        text.find("Eisfeld-Schnitzlein: inside its range"),
        std::string::npos
    ) << text;

    const dictionary d(rbd::readFoamFile(c.writeFile()));
    EXPECT_FALSE(d.subDict("ranges").subDict("ergun").get<bool>("inRange"));
    EXPECT_TRUE
    (
        d.subDict("ranges").subDict("eisfeldSchnitzlein").get<bool>("inRange")
    );

    // The cylinders' constants for spheres: named as outside
    const rbd::pressureDropComparison cyl(tmp.path(), "cylinders");
    EXPECT_TRUE
    (
        has
        (
            cyl.outsideRange("eisfeldSchnitzlein"),
            "the constants of cylinders for sphere pellets"
        )
    );

    // Rings, a fast flow and a loose bed: Re_p, porosity and shape out
    writeCase
    (
        tmp.path(),
        "shape ring; bedPorosity 0.9; tubeDiameter 0.04;"
        " pelletDiameter 0.01; bedHeight 0.05;"
    );
    writeDat
    (
        tmp.path(), "flowRate",
        -20.0*0.25*constant::mathematical::pi*D*D
    );
    const rbd::pressureDropComparison ring(tmp.path(), "cylinders");
    const stringList es(ring.outsideRange("eisfeldSchnitzlein"));
    EXPECT_TRUE(has(es, "Re_p = 20000 not in [0.01, 17635]")) << joined(es);
    EXPECT_TRUE(has(es, "porosity 0.9 not in [0.33, 0.882]")) << joined(es);
    EXPECT_TRUE(has(es, "shape ring, fitted for sphere or cylinder pellets"))
        << joined(es);
    // Ergun: Re_p/(1 - eps) = 2e5 > 2500
    EXPECT_TRUE
    (
        has(ring.outsideRange("ergun"), "Re_p/(1 - eps) = 200000 not in")
    );
}


TEST(pressureDropSectionsDeath, packedSectionWithoutAPressureDrop)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path(), sphereSummary);
    rbd::pressureDropComparison c(tmp.path());
    EXPECT_EXIT
    (
        c.setPackedTopPressure(0.3),
        ::testing::ExitedWithCode(1),
        "pressure drop over the packed section(.|\n)*not a positive number"
    );
}


TEST(pressureDropSections, fluidMeshPorosityBesideTheSummarys)
{
    const caseWritingTest::tempDir tmp;
    writeCase(tmp.path(), sphereSummary + " stlPorosity 0.4102;");
    rbd::pressureDropComparison c(tmp.path());
    EXPECT_DOUBLE_EQ(c.stlPorosity(), 0.4102);
    EXPECT_FALSE(c.meshPorosityMeasured());

    // Fluid volumes of 0.4 and 0.44 of the tube over the whole bed (0.05 m)
    // and the packed section (0.04 m)
    const scalar A = 0.25*constant::mathematical::pi*D*D;
    c.setFluidVolumes(0.44*A*0.05, 0.4*A*0.04);
    c.setPackedTopPressure(0.05);
    ASSERT_TRUE(c.meshPorosityMeasured());
    EXPECT_NEAR(c.meshPorosity(), 0.44, 1e-12);
    EXPECT_NEAR(c.packedMeshPorosity(), 0.4, 1e-12);

    OStringStream os;
    c.report(os);
    const std::string text(os.str());
    EXPECT_NE
    (
        text.find
        (
            "Porosity of the packed section: bulkPorosity 0.41 (exact"
            " pellets), stlPorosity 0.4102 (pellets.stl), fluid mesh 0.4"
        ),
        std::string::npos
    ) << text;
    EXPECT_NE
    (
        text.find("Porosity of the whole bed: bedPorosity 0.45, fluid mesh"),
        std::string::npos
    ) << text;
    // The correlations stay at the summary's porosities
    EXPECT_NEAR
    (
        c.packedErgun(),
        rbd::correlations::ergun(nu, 1, c.superficialVelocity(), 0.41, dp),
        1e-12
    );

    const dictionary d(rbd::readFoamFile(c.writeFile()));
    EXPECT_NEAR(d.get<scalar>("meshPorosity"), 0.44, 1e-12);
    EXPECT_NEAR
    (
        d.subDict("packedSection").get<scalar>("meshPorosity"), 0.4, 1e-12
    );
    EXPECT_NEAR
    (
        d.subDict("packedSection").get<scalar>("stlPorosity"), 0.4102, 1e-12
    );

    // A summary without stlPorosity (an older bed): -1, not printed
    writeCase(tmp.path(), sphereSummary);
    EXPECT_EQ(rbd::pressureDropComparison(tmp.path()).stlPorosity(), -1);
}

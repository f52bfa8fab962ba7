// Unit tests for src/rbdPacking/caseWriting/bedCaseSettings

#include <gtest/gtest.h>
#include "bedCaseSettings.H"
#include "foamFile.H"

using namespace Foam;

namespace
{
    const scalar dp = 0.01;

    rbd::bedCaseSettings make(const char* options, const scalar H = 0.029)
    {
        return rbd::bedCaseSettings
        (
            4*dp, dp, H, point(0.1, -0.2, 0.5),
            rbd::parseDictionary(options)
        );
    }

    //- Fractional part of x
    scalar frac(const scalar x)
    {
        return x - std::floor(x);
    }
}

TEST(bedCaseSettings, defaults)
{
    const rbd::bedCaseSettings s = make("");
    EXPECT_EQ(s.cellsPerDiameter(), 8);
    EXPECT_DOUBLE_EQ(s.cellSize(), dp/8);
    EXPECT_EQ(s.pelletLevel(), 1);
    EXPECT_EQ(s.wallLevel(), 0);
    EXPECT_EQ(s.contactTreatment(), "none");
    EXPECT_DOUBLE_EQ(s.pelletScale(), 1);
    EXPECT_DOUBLE_EQ(s.nu(), 1.5e-5);
    EXPECT_NEAR(s.reynoldsNumber(), 1, 1e-12);
    EXPECT_NEAR(s.superficialVelocity(), 1.5e-5/dp, 1e-15);
    EXPECT_FALSE(s.overwrite());
    EXPECT_DOUBLE_EQ(s.bedBottom(), 0.5);
    EXPECT_DOUBLE_EQ(s.bedTop(), 0.529);
}

TEST(bedCaseSettings, readsOptions)
{
    const rbd::bedCaseSettings s = make
    (
        "cellsPerDiameter 10; pelletLevel 2; wallLevel 1; nu 1e-6; U 0.002;"
        " contactTreatment shrink; shrinkFactor 0.98; nIterations 50;"
        " nProcessors 4; overwrite yes;"
    );
    EXPECT_DOUBLE_EQ(s.cellSize(), dp/10);
    EXPECT_EQ(s.pelletLevel(), 2);
    EXPECT_EQ(s.wallLevel(), 1);
    EXPECT_DOUBLE_EQ(s.superficialVelocity(), 0.002);
    EXPECT_NEAR(s.reynoldsNumber(), 0.002*dp/1e-6, 1e-9);
    EXPECT_DOUBLE_EQ(s.pelletScale(), 0.98);
    EXPECT_EQ(s.nIterations(), 50);
    EXPECT_EQ(s.nProcessors(), 4);
    EXPECT_TRUE(s.overwrite());
}

TEST(bedCaseSettings, gridEnclosesTubeAndKeepsPlanesOffFaces)
{
    // Several bed heights, including multiples of the cell size
    for (const scalar H : {0.029, 0.02, 0.0125, 0.1, 0.003})
    {
        const rbd::bedCaseSettings s = make("", H);
        const scalar h = s.cellSize();
        const point& c = s.floorCentre();

        // Across: cells of exactly h, at least 3 cells beyond the tube
        EXPECT_NEAR((s.blockMax().x() - s.blockMin().x())/s.blockCells().x(),
            h, 1e-12);
        EXPECT_NEAR((s.blockMax().y() - s.blockMin().y())/s.blockCells().y(),
            h, 1e-12);
        EXPECT_GE(c.x() - s.blockMin().x(), s.tubeRadius() + 3*h - 1e-12);
        EXPECT_GE(s.blockMax().y() - c.y(), s.tubeRadius() + 3*h - 1e-12);

        // Along z: close to h; bed bottom and top at 0.3 and 0.8 of a cell
        const scalar dz = s.cellSizeZ();
        EXPECT_GT(dz, 0.75*h);
        EXPECT_LT(dz, 1.25*h);
        EXPECT_NEAR(frac((s.bedBottom() - s.blockMin().z())/dz), 0.3, 1e-9);
        EXPECT_NEAR(frac((s.bedTop() - s.blockMin().z())/dz), 0.8, 1e-9);

        // Inlet 2 dp, outlet 3 dp, to within a cell
        EXPECT_NEAR(s.inletLength(), 2*dp, dz);
        EXPECT_NEAR(s.outletLength(), 3*dp, dz);
    }
}

TEST(bedCaseSettings, singleDictionary)
{
    const rbd::bedCaseSettings s
    (
        rbd::parseDictionary
        (
            "tubeDiameter 0.05; pelletDiameter 0.01; bedHeight 0.1;"
            " inletLength 0.015; Re 10;"
        )
    );
    EXPECT_DOUBLE_EQ(s.tubeDiameter(), 0.05);
    EXPECT_DOUBLE_EQ(s.bedHeight(), 0.1);
    EXPECT_EQ(s.floorCentre(), point::zero);
    EXPECT_NEAR(s.inletLength(), 0.015, s.cellSizeZ());
    EXPECT_NEAR(s.reynoldsNumber(), 10, 1e-12);
}

TEST(bedCaseSettingsDeath, rejectsVelocityAndReynoldsTogether)
{
    EXPECT_EXIT
    (
        make("U 0.1; Re 1;"),
        ::testing::ExitedWithCode(1),
        "either U \\[m/s\\] or Re \\[-\\], not both"
    );
}

TEST(bedCaseSettingsDeath, rejectsMisspeltOption)
{
    EXPECT_EXIT
    (
        make("cellsPerDiamter 8;"),
        ::testing::ExitedWithCode(1),
        "Unknown entry 'cellsPerDiamter'"
    );
}

TEST(bedCaseSettingsDeath, rejectsBadValues)
{
    EXPECT_EXIT
    (
        make("cellsPerDiameter 1;"),
        ::testing::ExitedWithCode(1),
        "cellsPerDiameter(.|\n)*a whole number in \\[2, 64\\]"
    );
    // Upper bounds: the grid and tube.stl grow with both (wallLevel 30
    // overflowed the tube's facet count and stopped the run)
    EXPECT_EXIT
    (
        make("cellsPerDiameter 100000;"),
        ::testing::ExitedWithCode(1),
        "cellsPerDiameter 100000(.|\n)*\\[2, 64\\]"
    );
    EXPECT_EXIT
    (
        make("wallLevel 30;"),
        ::testing::ExitedWithCode(1),
        "wallLevel 30(.|\n)*\\[0, 4\\]"
    );
    EXPECT_EXIT
    (
        make("pelletLevel 9;"),
        ::testing::ExitedWithCode(1),
        "pelletLevel 9(.|\n)*\\[0, 5\\]"
    );
    EXPECT_EXIT
    (
        make("contactTreatment glue;"),
        ::testing::ExitedWithCode(1),
        "one of none \\| shrink \\| bridges \\| caps"
    );
    EXPECT_EXIT
    (
        make("contactTreatment bridges; bridgeDiameter 0.008;"),
        ::testing::ExitedWithCode(1),
        "bridgeDiameter 0.008(.|\n)*allowed"
    );
    EXPECT_EXIT
    (
        make("shrinkFactor 1.2;"),
        ::testing::ExitedWithCode(1),
        "shrinkFactor"
    );
}

TEST(bedCaseSettingsDeath, rejectsTubeNarrowerThanPellets)
{
    EXPECT_EXIT
    (
        rbd::bedCaseSettings
        (
            0.01, 0.02, 0.1, point::zero, dictionary()
        ),
        ::testing::ExitedWithCode(1),
        "must be wider than the pellets"
    );
}

TEST(bedCaseSettings, bedHeightGivenLater)
{
    // Options first (as rbdPackBed reads them before packing), bed height
    // after: the same settings as with the bed height given at once
    const dictionary options
    (
        rbd::parseDictionary("cellsPerDiameter 10; Re 2; stlFormat binary;")
    );
    rbd::bedCaseSettings later(4*dp, dp, point(0.1, -0.2, 0.5), options);
    EXPECT_FALSE(later.hasBedHeight());
    EXPECT_NEAR(later.reynoldsNumber(), 2, 1e-12);
    EXPECT_TRUE(later.binarySTL());

    later.setBedHeight(0.029);
    const rbd::bedCaseSettings atOnce
    (
        4*dp, dp, 0.029, point(0.1, -0.2, 0.5), options
    );
    EXPECT_TRUE(later.hasBedHeight());
    EXPECT_EQ(later.bedHeight(), atOnce.bedHeight());
    EXPECT_EQ(later.blockCells(), atOnce.blockCells());
    EXPECT_EQ(later.blockMin(), atOnce.blockMin());
    EXPECT_EQ(later.blockMax(), atOnce.blockMax());
    EXPECT_FALSE(make("").binarySTL());
}

TEST(bedCaseSettingsDeath, rejectsBadOptionsBeforeTheBedHeight)
{
    EXPECT_EXIT
    (
        rbd::bedCaseSettings
        (
            4*dp, dp, point::zero, rbd::parseDictionary("stlFormat obj;")
        ),
        ::testing::ExitedWithCode(1),
        "stlFormat obj(.|\n)*one of ascii \\| binary"
    );
    EXPECT_EXIT
    (
        rbd::bedCaseSettings
        (
            4*dp, dp, point::zero, rbd::parseDictionary("pelletLevl 1;")
        ),
        ::testing::ExitedWithCode(1),
        "Unknown entry 'pelletLevl'"
    );
}


TEST(bedCaseSettings, warnsOfEntriesOfAnotherContactTreatment)
{
    const auto warnings = [](const char* options)
    {
        ::testing::internal::CaptureStdout();
        ::testing::internal::CaptureStderr();
        make(options);
        return
            ::testing::internal::GetCapturedStdout()
          + ::testing::internal::GetCapturedStderr();
    };

    const std::string w = warnings
    (
        "contactTreatment shrink; shrinkFactor 0.98; bridgeDiameter 0.002;"
        " contactGap 1e-4;"
    );
    EXPECT_NE(w.find("bridgeDiameter in"), std::string::npos) << w;
    EXPECT_NE(w.find("is ignored: contactTreatment is shrink"),
        std::string::npos) << w;
    EXPECT_NE(w.find("contactGap in"), std::string::npos) << w;
    EXPECT_EQ(w.find("shrinkFactor in"), std::string::npos) << w;

    // Every entry used: no warning
    EXPECT_EQ
    (
        warnings("contactTreatment caps; capHeight 1e-4; contactGap 1e-4;")
            .find("is ignored"),
        std::string::npos
    );
}

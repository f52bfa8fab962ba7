// Unit tests for the layers scheme of src/rbdPacking/loading/loadingScheme:
// its release points against their definition (a hexagonal lattice of pitch
// 'spacing' bounding diameters through the axis, every point within
// R - r_b - positionDisturbance dp, nearest the axis first), counted against
// the lattice points in the disc found by brute force

#include <gtest/gtest.h>
#include "loadingScheme.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    dictionary parseLayers(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    // Lattice points within rhoMax, by brute force over a generous square
    label bruteCount(const scalar pitch, const scalar rhoMax)
    {
        const scalar h = pitch*std::sqrt(3.0)/2;
        label n = 0;
        for (label j = -100; j <= 100; ++j)
        {
            for (label i = -100; i <= 100; ++i)
            {
                const scalar x = i*pitch + ((j % 2) ? 0.5*pitch : 0);
                const scalar y = j*h;
                n += std::sqrt(x*x + y*y) <= rhoMax*(1 + 1e-12);
            }
        }
        return n;
    }
}


TEST(loadingSchemeLayers, latticePointsInTheDisc)
{
    for (const scalar rhoMax : {0.0, 0.004, 0.011, 0.02, 0.0451, 0.1})
    {
        const scalar pitch = 0.012;
        const pointField p(rbd::loadingScheme::layerPoints(pitch, rhoMax, 0.3));

        EXPECT_EQ(p.size(), bruteCount(pitch, rhoMax)) << "rhoMax " << rhoMax;
        ASSERT_GE(p.size(), 1);
        EXPECT_EQ(p[0], point(0, 0, 0.3));

        scalar lastRho = 0;
        forAll(p, a)
        {
            const scalar rho = std::sqrt(sqr(p[a].x()) + sqr(p[a].y()));
            EXPECT_LE(rho, rhoMax*(1 + 1e-12));
            EXPECT_EQ(p[a].z(), 0.3);
            EXPECT_GE(rho, lastRho - 1e-12) << "nearest the axis first";
            lastRho = rho;
            for (label b = 0; b < a; ++b)
            {
                EXPECT_GE(mag(p[a] - p[b]), pitch*(1 - 1e-12))
                    << "points " << a << ", " << b;
            }
        }
    }
}


TEST(loadingSchemeLayers, schemeReleasesFromEveryLatticePoint)
{
    // Spheres of 10 mm in a 50 mm tube, spacing 1.2: pitch 12 mm, so the
    // default positionDisturbance is (6 - 5)/10 = 0.1 (the pitch's bound),
    // and the points lie within R - r_b - 1 mm = 19 mm of the axis
    const rbd::tube tube50(0.05, 0.3, 0.5, 0.5);
    autoPtr<rbd::pelletShape> sphere
    (
        rbd::pelletShape::New
        (
            parseLayers("shape sphere; diameter 0.01; faces 80;")
        )
    );
    const rbd::loadingScheme layers
    (
        parseLayers("scheme layers; spacing 1.2;"), tube50, sphere()
    );
    EXPECT_EQ(layers.nColumns(), bruteCount(0.012, 0.019));
    EXPECT_EQ(layers.nColumns(), 7);     // the axis and a ring of six
    for (label c = 0; c < layers.nColumns(); ++c)
    {
        EXPECT_NEAR(layers.column(c).z(), layers.releaseHeight(), 1e-15);
    }

    // A tube barely wider than the pellet: the axis alone, as a column
    // (and a default positionDisturbance of (R - r_b)/dp = 0.025)
    const rbd::tube narrow(0.0105, 0.3, 0.5, 0.5);
    const rbd::loadingScheme single
    (
        parseLayers("scheme layers;"), narrow, sphere()
    );
    EXPECT_EQ(single.nColumns(), 1);
}


TEST(loadingSchemeLayers, theNextLayerWaitsForAwakeLayersOfPellets)
{
    // The layers wait while awakeLayers layers of nColumns() pellets are
    // awake: by default one layer (7 pellets at N = 5), rounded up, at
    // least one pellet; 0 releases without waiting, as do the columns
    const rbd::tube tube50(0.05, 0.3, 0.5, 0.5);
    autoPtr<rbd::pelletShape> sphere
    (
        rbd::pelletShape::New
        (
            parseLayers("shape sphere; diameter 0.01; faces 80;")
        )
    );
    const auto limit = [&](const std::string& text)
    {
        return rbd::loadingScheme(parseLayers(text), tube50, sphere())
            .awakeLimit();
    };
    EXPECT_EQ(limit("scheme layers;"), 7);
    EXPECT_EQ(limit("scheme layers; awakeLayers 2;"), 14);
    EXPECT_EQ(limit("scheme layers; awakeLayers 0.5;"), 4);
    EXPECT_EQ(limit("scheme layers; awakeLayers 0.01;"), 1);
    EXPECT_EQ(limit("scheme layers; awakeLayers 0;"), 0);
    EXPECT_EQ(limit("scheme column;"), 0);
    EXPECT_EQ(limit("scheme fourColumns;"), 0);
}


TEST(loadingSchemeLayersDeath, aNegativeAwakeLayersIsRefused)
{
    const rbd::tube tube50(0.05, 0.3, 0.5, 0.5);
    autoPtr<rbd::pelletShape> sphere
    (
        rbd::pelletShape::New
        (
            parseLayers("shape sphere; diameter 0.01; faces 80;")
        )
    );
    EXPECT_EXIT
    (
        rbd::loadingScheme
        (
            parseLayers("scheme layers; awakeLayers -1;"), tube50, sphere()
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'awakeLayers -1;'"
    );
}

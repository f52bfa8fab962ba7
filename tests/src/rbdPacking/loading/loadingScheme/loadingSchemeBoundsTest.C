// Unit tests for the bounds of src/rbdPacking/loading/loadingScheme (its
// Description, "Bounds"): at the largest (or smallest) allowed value of
// every entry, for many seeds, no pellet of a release reaches the wall or
// another pellet of the same release; just beyond a bound the entry is
// refused with its allowed range; the defaults lie within the bounds; the
// tutorials' loading blocks lie within them. The bounds are written out
// here from the geometry (bounding spheres of radius r_b about the centre,
// tube radius R, delta = positionDisturbance dp), not taken from the class.

#include <gtest/gtest.h>
#include "loadingScheme.H"
#include "IStringStream.H"
#include "IFstream.H"
#include "OSspecific.H"

#include <functional>

using namespace Foam;

namespace
{
    dictionary parseBounds(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    std::string num(const scalar x)
    {
        std::ostringstream os;
        os.precision(17);
        os << x;
        return os.str();
    }

    // Tube of D = 100 mm (wide enough for four columns of the cylinder)
    const rbd::tube tube100(0.1, 0.2, 0.6, 0.6);

    autoPtr<rbd::pelletShape> shapeOf(const std::string& text)
    {
        return rbd::pelletShape::New(parseBounds(text));
    }

    // One release of every point of L, seeds 1..nSeeds: the largest
    // distance of a bounding sphere beyond the wall and the largest
    // interpenetration of two bounding spheres [m] (0: none), and the
    // largest centre distance from the axis [m]
    struct releaseGaps
    {
        scalar wall = -GREAT;
        scalar pair = -GREAT;
        scalar rhoMax = 0;
        label points = 0;
    };

    releaseGaps releases
    (
        const std::string& entries,
        const rbd::pelletShape& shape,
        const rbd::tube& container,
        const label nSeeds
    )
    {
        releaseGaps g;
        const scalar rb = shape.boundingRadius();
        for (label seed = 1; seed <= nSeeds; ++seed)
        {
            rbd::loadingScheme L
            (
                parseBounds(entries + " seed " + std::to_string(seed) + ";"),
                container, shape
            );
            g.points = L.nColumns();
            List<point> x(L.nColumns());
            forAll(x, c)
            {
                quaternion q;
                L.nextPose(c, x[c], q);
                const scalar rho = rbd::tube::axialDistance(x[c]);
                g.rhoMax = max(g.rhoMax, rho);
                g.wall = max(g.wall, rho + rb - container.radius());
                for (label b = 0; b < c; ++b)
                {
                    g.pair = max(g.pair, 2*rb - mag(x[c] - x[b]));
                }
            }
        }
        return g;
    }
}


TEST(loadingSchemeBounds, releasesAtTheLimitsClearTheWallAndOneAnother)
{
    // Sphere (r_b = dp/2) and a cylinder d = 10 mm, h = 20 mm
    // (r_b = 11.18 mm > dp/2)
    const std::vector<std::string> shapes
    ({
        "shape sphere; diameter 0.01; faces 80;",
        "shape cylinder; diameter 0.01; height 0.02; faces 200;"
    });
    const scalar R = tube100.radius();
    const scalar dp = 0.01;
    const label nSeeds = 300;

    for (const std::string& shapeText : shapes)
    {
        autoPtr<rbd::pelletShape> s = shapeOf(shapeText);
        const scalar rb = s->boundingRadius();
        const scalar D = max(dp, 2*rb);

        // Entries at a bound, and whether it is the wall's (then some
        // draw must come near the wall: the bound is reached)
        std::vector<std::pair<std::string, bool>> cases;

        // column: delta = R - r_b
        cases.push_back
        ({
            "scheme column; positionDisturbance " + num((R - rb)/dp) + ";",
            true
        });

        // twoColumns, fourColumns: the largest delta (the two bounds on s
        // meet), and delta 0.3 with s at either bound
        for (const scalar k : {1.0, std::sqrt(2.0)})
        {
            const std::string scheme(k == 1 ? "twoColumns" : "fourColumns");
            const scalar deltaMax = (R - (1 + k)*rb)/(1 + k);
            cases.push_back
            ({
                "scheme " + scheme + "; positionDisturbance "
              + num(deltaMax/dp) + ";",
                true
            });
            const scalar delta = 0.3*dp;
            cases.push_back
            ({
                "scheme " + scheme + "; positionDisturbance 0.3; "
                "columnOffset " + num(k*(rb + delta)) + ";",
                false
            });
            cases.push_back
            ({
                "scheme " + scheme + "; positionDisturbance 0.3; "
                "columnOffset " + num(R - rb - delta) + ";",
                true
            });
        }

        // layers: the smallest spacing for delta 0.3 dp, and at spacing 1
        // the largest delta
        cases.push_back
        ({
            "scheme layers; positionDisturbance 0.3; spacing "
          + num(2*(rb + 0.3*dp)/D) + ";",
            false
        });
        cases.push_back
        ({
            "scheme layers; spacing 1; positionDisturbance "
          + num((0.5*D - rb)/dp) + ";",
            false
        });

        for (const auto& c : cases)
        {
            const releaseGaps g = releases(c.first, s(), tube100, nSeeds);
            EXPECT_GE(g.points, 1) << shapeText << c.first;
            // Rounding only: 1e-12 of the tube radius
            EXPECT_LE(g.wall, 1e-12*R) << shapeText << c.first;
            EXPECT_LE(g.pair, 1e-12*R) << shapeText << c.first;
            // ... and a wall bound is reached: some draw comes within
            // 0.05 dp of the wall (the disc is filled out to its rim)
            if (c.second)
            {
                EXPECT_GT(g.wall, -0.05*dp) << shapeText << c.first;
            }
        }
    }
}


TEST(loadingSchemeBoundsDeath, justBeyondABoundTheEntryIsRefused)
{
    // Spheres dp = 10 mm (r_b = 5 mm) in a tube of R = 50 mm, delta 3 mm:
    // column delta <= 45 mm; twoColumns s in [8, 42] mm; fourColumns
    // s in [sqrt(2) 8, 42] mm; delta <= (50 - 2.414 x 5)/2.414 mm
    // = 15.71 mm (four) or 20 mm (two); layers spacing >= 1.6 at delta 3 mm
    autoPtr<rbd::pelletShape> s = shapeOf
    (
        "shape sphere; diameter 0.01; faces 80;"
    );
    const scalar e = 1 + 1e-6;
    const std::vector<std::pair<std::string, std::string>> cases
    ({
        {
            "scheme column; positionDisturbance " + num(4.5*e) + ";",
            "Bad entry 'positionDisturbance 4.5[0-9]*;'(.|\n)*"
            "allowed: a number in \\[0, 4.5\\] \\[-\\] for scheme column"
        },
        {
            "scheme twoColumns; columnOffset " + num(0.008/e) + ";",
            "Bad entry 'columnOffset 0.00799[0-9]*;'(.|\n)*"
            "allowed: a number in \\[0.008, 0.042\\] \\[m\\] for scheme "
            "twoColumns with positionDisturbance 0.3"
        },
        {
            "scheme twoColumns; columnOffset " + num(0.042*e) + ";",
            "Bad entry 'columnOffset 0.042[0-9]*;'(.|\n)*"
            "allowed: a number in \\[0.008, 0.042\\]"
        },
        {
            "scheme fourColumns; columnOffset " + num(0.008) + ";",
            "Bad entry 'columnOffset 0.008;'(.|\n)*"
            "allowed: a number in \\[0.0113137, 0.042\\] \\[m\\] for scheme "
            "fourColumns"
        },
        {
            "scheme twoColumns; positionDisturbance " + num(2*e) + ";",
            "Bad entry 'positionDisturbance 2[.0-9]*;'(.|\n)*"
            "allowed: a number in \\[0, 2\\] \\[-\\] for scheme twoColumns"
        },
        {
            "scheme fourColumns; positionDisturbance 1.6;",
            "Bad entry 'positionDisturbance 1.6;'(.|\n)*"
            "allowed: a number in \\[0, 1.57107\\] \\[-\\] for scheme "
            "fourColumns"
        },
        {
            "scheme layers; positionDisturbance 0.3; spacing 1.59;",
            "Bad entry 'spacing 1.59;'(.|\n)*"
            "allowed: a number >= 1.6 \\[-\\] for scheme layers with "
            "positionDisturbance 0.3, or a positionDisturbance of at most "
            "0.295"
        },
        {
            "scheme layers; positionDisturbance 4.6;",
            "Bad entry 'positionDisturbance 4.6;'(.|\n)*"
            "allowed: a number in \\[0, 4.5\\] \\[-\\] for scheme layers"
        },
        {
            "releaseHeight 0.005;",
            "Bad entry 'releaseHeight 0.005;'(.|\n)*"
            "allowed: a height in \\(0.005, 0.195\\]"
        }
    });
    for (const auto& c : cases)
    {
        EXPECT_EXIT
        (
            rbd::loadingScheme(parseBounds(c.first), tube100, s()),
            ::testing::ExitedWithCode(1),
            c.second
        ) << c.first;
    }

    // A tube too narrow for the scheme even without a disturbance:
    // fourColumns needs R >= (1 + sqrt(2)) r_b = 12.07 mm, twoColumns
    // R >= 2 r_b = 10 mm
    const rbd::tube tube22(0.022, 0.1, 0.6, 0.6);
    EXPECT_EXIT
    (
        rbd::loadingScheme
        (
            parseBounds("scheme fourColumns; positionDisturbance 0;"),
            tube22, s()
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'scheme fourColumns;'(.|\n)*allowed: column \\| layers "
        "\\| twoColumns in this tube: fourColumns releases pellets side by "
        "side and needs R >= \\(1 \\+ sqrt\\(2\\)\\) r_b = 0.0120711 m"
    );
    const rbd::tube tube18(0.018, 0.1, 0.6, 0.6);
    EXPECT_EXIT
    (
        rbd::loadingScheme(parseBounds("scheme twoColumns;"), tube18, s()),
        ::testing::ExitedWithCode(1),
        "Bad entry 'scheme twoColumns;'(.|\n)*allowed: column \\| layers in "
        "this tube: twoColumns releases pellets side by side and needs "
        "R >= 2 r_b = 0.01 m"
    );
}


TEST(loadingSchemeBounds, defaultsLieWithinTheBounds)
{
    autoPtr<rbd::pelletShape> s = shapeOf
    (
        "shape sphere; diameter 0.01; faces 80;"
    );

    // twoColumns: columnOffset midway in [r_b + delta, R - r_b - delta],
    // R/2 (D = 40 mm, delta 3 mm)
    const rbd::tube tube40(0.04, 0.1, 0.6, 0.6);
    {
        rbd::loadingScheme L(parseBounds("scheme twoColumns;"), tube40, s());
        EXPECT_NEAR(L.column(0).x(), 0.01, 1e-15);
    }
    // fourColumns: midway in [sqrt(2)(r_b + delta), R - r_b - delta]
    {
        rbd::loadingScheme L(parseBounds("scheme fourColumns;"), tube40, s());
        EXPECT_NEAR
        (
            L.column(0).x(), 0.5*(std::sqrt(2.0)*0.008 + 0.012), 1e-15
        );
    }

    // A tube of 12 mm takes an offset of (R - r_b)/dp = 0.1 at most: the
    // default 0.3 becomes 0.1, and every release clears the wall
    const rbd::tube tube12(0.012, 0.1, 0.6, 0.6);
    {
        const releaseGaps g = releases("scheme column;", s(), tube12, 200);
        EXPECT_NEAR(g.rhoMax, 0.001, 0.0001);
        EXPECT_LE(g.wall, 1e-15);
    }

    // layers at spacing 1.2: pitch 12 mm, so delta <= (6 - 5) mm = 0.1 dp;
    // lattice points within R - r_b - delta = 19 mm at D = 50 mm: the axis
    // and a ring of six
    const rbd::tube tube50(0.05, 0.1, 0.6, 0.6);
    {
        const releaseGaps g = releases("scheme layers;", s(), tube50, 200);
        EXPECT_EQ(g.points, 7);
        EXPECT_LE(g.pair, 1e-15);
        EXPECT_LE(g.wall, 1e-15);
        EXPECT_GT(g.rhoMax, 0.0125);
        EXPECT_LE(g.rhoMax, 0.013*(1 + 1e-12));
    }
}


TEST(loadingSchemeBounds, tutorialsLoadWithinTheBounds)
{
    // Each tutorial's loading block, with its container and pellets, is
    // accepted (an entry beyond a bound would exit with its error)
    const fileName tutorials
    (
        fileName(RBD_TEST_SOURCE_DIR)/".."/".."/"tutorials"
    );
    const fileNameList cases(readDir(tutorials, fileName::DIRECTORY));
    ASSERT_GE(cases.size(), 3);
    for (const fileName& c : cases)
    {
        const fileName file(tutorials/c/"system"/"packingDict");
        ASSERT_TRUE(isFile(file)) << file;
        EXPECT_EXIT
        (
            {
                IFstream is(file);
                const dictionary dict(is);
                const rbd::tube container(dict.subDict("container"));
                autoPtr<rbd::pelletShape> s
                (
                    rbd::pelletShape::New(dict.subDict("pellets"))
                );
                const rbd::loadingScheme L
                (
                    dict.subDict("loading"), container, s()
                );
                ::exit(L.nColumns() >= 1 ? 0 : 2);
            },
            ::testing::ExitedWithCode(0),
            ""
        ) << file;
    }
}

// Unit tests for src/rbdPacking/shapes/lobedPellet (trilobe, quadrilobe)

#include <gtest/gtest.h>
#include "lobedPellet.H"
#include "cgalMeshTools.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

using namespace Foam;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    //- Area of the union of n discs of radius r on the circle of radius rc,
    //  brute force: midpoints of an m x m grid over the bounding square
    scalar unionAreaByGrid
    (
        const label n,
        const scalar r,
        const scalar rc,
        const label m
    )
    {
        const scalar L = rc + r;
        const scalar h = 2*L/m;
        label inside = 0;
        for (label i = 0; i < m; ++i)
        {
            const scalar x = -L + (i + 0.5)*h;
            for (label j = 0; j < m; ++j)
            {
                const scalar y = -L + (j + 0.5)*h;
                for (label k = 0; k < n; ++k)
                {
                    const scalar t = constant::mathematical::twoPi*k/n;
                    if
                    (
                        sqr(x - rc*std::cos(t)) + sqr(y - rc*std::sin(t))
                      < r*r
                    )
                    {
                        ++inside;
                        break;
                    }
                }
            }
        }
        return inside*h*h;
    }
}


TEST(lobedPellet, crossSectionAreaIsTheUnionOfTheLobes)
{
    for (const label n : {3, 4})
    {
        const scalar dl = 0.004;
        for (const scalar dc : {-1.0, 0.001, 0.0035})
        {
            const scalar pitch =
                dc < 0 ? rbd::lobedPellet::defaultPitchDiameter(n, dl) : dc;
            const scalar A =
                rbd::lobedPellet::crossSectionArea(n, dl, pitch);
            const scalar ref = unionAreaByGrid(n, 0.5*dl, 0.5*pitch, 1500);
            EXPECT_NEAR(A/ref, 1, 5e-4) << "n " << n << " dc " << pitch;
        }
    }
    // The limits: all lobes on the axis (one disc)
    EXPECT_NEAR
    (
        rbd::lobedPellet::crossSectionArea(3, 0.004, 1e-12),
        constant::mathematical::pi*4e-6, 1e-9*constant::mathematical::pi*4e-6
    );
}


TEST(lobedPellet, trilobeAndQuadrilobeMeshes)
{
    for (const word shape : {"trilobe", "quadrilobe"})
    {
        const label n = shape == "trilobe" ? 3 : 4;
        const dictionary d = parse
        (
            "shape " + shape + "; lobeDiameter 0.004; height 0.008;"
            " faces 8000;"
        );
        autoPtr<rbd::pelletShape> s = rbd::pelletShape::New(d);
        EXPECT_EQ(s->type(), shape);

        const rbd::triMesh& m = s->mesh();
        EXPECT_EQ(rbd::checkClosedSolid(m), "");
        EXPECT_NEAR(m.nFaces(), 8000, 400);

        // Default pitch: neighbouring axes one lobe radius apart
        const auto& lobed = refCast<const rbd::lobedPellet>(s());
        const scalar dc = lobed.pitchDiameter();
        EXPECT_NEAR(dc*std::sin(constant::mathematical::pi/n), 0.002, 1e-15);
        EXPECT_NEAR(s->diameter(), 0.004 + dc, 1e-15);

        // Volume: inscribed polygons, below the curved solid by < 0.3 %
        const scalar V = rbd::lobedPellet::crossSectionArea(n, 0.004, dc)
           *0.008;
        EXPECT_LT(s->volume(), V);
        EXPECT_GT(s->volume(), 0.997*V);
        EXPECT_NEAR(s->volume(), m.volume(), 1e-12*V);

        // Principal frame: n-fold symmetry, transverse moments equal,
        // axis along z (top and bottom caps at +-h/2)
        const vector I = s->principalInertiaPerDensity();
        EXPECT_NEAR(I.x()/I.y(), 1, 1e-6);
        const boundBox bb = m.bounds();
        EXPECT_NEAR(bb.min().z(), -0.004, 1e-12);
        EXPECT_NEAR(bb.max().z(), 0.004, 1e-12);
        // Vertices on the true surface, not always at the lobe tips
        const scalar rb = std::hypot(0.5*s->diameter(), 0.004);
        EXPECT_LE(s->boundingRadius(), rb*(1 + 1e-12));
        EXPECT_GT(s->boundingRadius(), rb*(1 - 1e-3));
    }
}


TEST(lobedPellet, volumeErrorFallsWithResolution)
{
    const scalar dc = rbd::lobedPellet::defaultPitchDiameter(3, 0.004);
    const scalar V = rbd::lobedPellet::crossSectionArea(3, 0.004, dc)*0.008;
    scalar errCoarse = 0, errFine = 0;
    for (const label faces : {1000, 8000})
    {
        const dictionary d = parse
        (
            "shape trilobe; lobeDiameter 0.004; height 0.008; faces "
          + std::to_string(faces) + ";"
        );
        const scalar err = 1 - rbd::pelletShape::New(d)->volume()/V;
        (faces == 1000 ? errCoarse : errFine) = err;
    }
    EXPECT_GT(errCoarse, 0);
    EXPECT_GT(errFine, 0);
    // ~1/faces: 8 times the faces, about 8 times smaller (at least 4)
    EXPECT_LT(errFine, errCoarse/4);
}


TEST(lobedPelletDeath, badSizesNameTheEntry)
{
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse("shape trilobe; lobeDiameter -0.004; height 0.008;")
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'lobeDiameter -0.004;'(.|\n)*allowed: a number > 0"
    );
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse
            (
                "shape quadrilobe; lobeDiameter 0.004; height 0.008;"
                " lobePitchDiameter 0.005;"
            )
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'lobePitchDiameter 0.005;'(.|\n)*below lobeDiameter"
    );
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse("shape trilobe; lobeDiameter 0.004; height 0.008; d 1;")
        ),
        ::testing::ExitedWithCode(1),
        "Unknown entry 'd'"
    );
}

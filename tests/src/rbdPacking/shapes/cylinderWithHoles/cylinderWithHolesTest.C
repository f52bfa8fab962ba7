// Unit tests for src/rbdPacking/shapes/cylinderWithHoles

#include <gtest/gtest.h>
#include "cylinderWithHoles.H"
#include "cgalMeshTools.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }
}


TEST(cylinderWithHoles, volumeAndMeshForSeveralHoleCounts)
{
    for (const label n : {1, 3, 4, 7})
    {
        const scalar D = 0.016, h = 0.012, dh = 0.0025;
        const dictionary d = parse
        (
            "shape cylinderWithHoles; diameter 0.016; height 0.012; holes "
          + std::to_string(n) + "; holeDiameter 0.0025; faces 8000;"
        );
        autoPtr<rbd::pelletShape> s = rbd::pelletShape::New(d);
        const rbd::triMesh& m = s->mesh();
        EXPECT_EQ(rbd::checkClosedSolid(m), "") << n << " holes";

        const scalar V = 0.25*pi*(sqr(D) - n*sqr(dh))*h;
        // Inscribed polygons: the outer circle too small, the holes too
        // (7 holes of 2.5 mm: +0.38 % in all)
        EXPECT_NEAR(s->volume()/V, 1, 5e-3) << n << " holes";
        EXPECT_NEAR(s->volume(), m.volume(), 1e-12*V);
        EXPECT_DOUBLE_EQ(s->diameter(), D);

        // Default pitch: hole-to-outside wall = hole-to-hole wall
        const auto& c = refCast<const rbd::cylinderWithHoles>(s());
        if (n > 1)
        {
            const scalar rc = 0.5*c.pitchDiameter();
            const scalar outer = 0.5*D - rc - 0.5*dh;
            const scalar between = 2*rc*std::sin(pi/n) - dh;
            EXPECT_NEAR(outer, between, 1e-15);
            EXPECT_GT(outer, 0);
        }
        else
        {
            EXPECT_EQ(c.pitchDiameter(), 0);
        }
    }
}


TEST(cylinderWithHoles, offCentreHoleMovesTheCentreOfMass)
{
    const dictionary d = parse
    (
        "shape cylinderWithHoles; diameter 0.01; height 0.01; holes 1;"
        " holeDiameter 0.004; holePitchDiameter 0.004; faces 4000;"
    );
    autoPtr<rbd::pelletShape> s = rbd::pelletShape::New(d);
    // The body frame is on the centre of mass: the mesh's first moment
    // about the origin vanishes (divergence theorem, x n_x over faces)
    const rbd::triMesh& m = s->mesh();
    vector first(Zero);
    for (const triFace& f : m.faces())
    {
        const point& a = m.points()[f[0]];
        const point& b = m.points()[f[1]];
        const point& c = m.points()[f[2]];
        const vector nA = 0.5*((b - a) ^ (c - a));
        // int_V x dV = 1/2 int_S x^2 n_x dS, and over a triangle
        // int x^2 dA = A (a^2 + b^2 + c^2 + ab + bc + ca)/6
        first.x() += 0.5*nA.x()*(sqr(a.x()) + sqr(b.x()) + sqr(c.x())
            + a.x()*b.x() + b.x()*c.x() + c.x()*a.x())/6;
        first.y() += 0.5*nA.y()*(sqr(a.y()) + sqr(b.y()) + sqr(c.y())
            + a.y()*b.y() + b.y()*c.y() + c.y()*a.y())/6;
    }
    EXPECT_LT(mag(first)/(s->volume()*0.005), 1e-9);
    // and the mesh's axis is still z: the caps at +-h/2
    EXPECT_NEAR(m.bounds().min().z(), -0.005, 1e-12);
    EXPECT_NEAR(m.bounds().max().z(), 0.005, 1e-12);
}


TEST(cylinderWithHolesDeath, holesThatDoNotFitNameEntryAndRange)
{
    // Default pitch, 4 holes: dh < D s/(1 + s) = 0.01*0.7071/1.7071
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse
            (
                "shape cylinderWithHoles; diameter 0.01; height 0.01;"
                " holes 4; holeDiameter 0.0045;"
            )
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'holeDiameter 0.0045;'(.|\n)*below 0.00414"
    );
    // Given pitch: holes reaching the outside
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse
            (
                "shape cylinderWithHoles; diameter 0.01; height 0.01;"
                " holes 3; holeDiameter 0.002; holePitchDiameter 0.009;"
            )
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'holePitchDiameter 0.009;'(.|\n)*below 0.008"
    );
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse
            (
                "shape cylinderWithHoles; diameter 0.01; height 0.01;"
                " holes 0; holeDiameter 0.002;"
            )
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'holes 0;'"
    );
    EXPECT_EXIT
    (
        rbd::pelletShape::New
        (
            parse
            (
                "shape cylinderWithHoles; diameter -0.01; height 0.01;"
                " holes 2; holeDiameter 0.002;"
            )
        ),
        ::testing::ExitedWithCode(1),
        "Bad entry 'diameter -0.01;'(.|\n)*> 0"
    );
}

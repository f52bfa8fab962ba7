// Unit tests for pelletShape::exactVolume() and volumeTrueMesh() (src/
// rbdPacking/shapes/pelletShape): every shape at its default faces, the
// volume-true mesh of the CFD case against the closed-form volume, in the
// frame of the contact mesh, which stays as it was.

#include <gtest/gtest.h>
#include "pelletShape.H"
#include "stlIO.H"
#include "pelletMeshes.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    //- Every shape at its default faces, with its volume from the
    //  dictionary's sizes (closed forms written out here)
    List<std::pair<std::string, scalar>> shapes()
    {
        // Lobes (see pelletMeshes.H): n (rc t sin(pi/n) + r^2 beta)
        const auto lobes = [](const label n, const scalar dl, const scalar h)
        {
            const scalar r = dl/2;
            const scalar rc = r/(2*std::sin(pi/n));
            const scalar s = std::sin(pi/n), c = std::cos(pi/n);
            const scalar t = rc*c + std::sqrt(sqr(r) - sqr(rc*s));
            const scalar beta = std::atan2(t*s, t*c - rc);
            return n*(rc*t*s + sqr(r)*beta)*h;
        };
        return
        {
            {"shape sphere; diameter 0.01;", pi/6*1e-6},
            {"shape cylinder; diameter 0.01; height 0.008;", pi/4*8e-7},
            {
                "shape ring; diameter 0.01; innerDiameter 0.006;"
                " height 0.01;",
                pi/4*(1e-4 - 3.6e-5)*0.01
            },
            {
                "shape trilobe; lobeDiameter 0.004; height 0.006;",
                lobes(3, 0.004, 0.006)
            },
            {
                "shape quadrilobe; lobeDiameter 0.004; height 0.006;",
                lobes(4, 0.004, 0.006)
            },
            {
                "shape cylinderWithHoles; diameter 0.01; height 0.008;"
                " holes 4; holeDiameter 0.002;",
                pi/4*(1e-4 - 4*4e-6)*0.008
            },
            {
                // One hole off the axis: the body frame is off the
                // cylinder's axis
                "shape cylinderWithHoles; diameter 0.01; height 0.01;"
                " holes 1; holeDiameter 0.004; holePitchDiameter 0.004;",
                pi/4*(1e-4 - 1.6e-5)*0.01
            }
        };
    }
}


TEST(volumeTrueMesh, everyShapeAtDefaultFacesHasTheExactVolume)
{
    for (const auto& sv : shapes())
    {
        autoPtr<rbd::pelletShape> s = rbd::pelletShape::New(parse(sv.first));
        const rbd::triMesh& contact = s->mesh();
        const rbd::triMesh& cfd = s->volumeTrueMesh();

        EXPECT_NEAR(s->exactVolume()/sv.second, 1, 1e-12) << sv.first;
        // Asked: 1e-6 relative; the solve gives round-off
        EXPECT_NEAR(cfd.volume()/sv.second, 1, 1e-10) << sv.first;
        // The contact mesh is inscribed: off (a ring's walls cancel to
        // 9e-7, holes make it larger)
        EXPECT_GT(mag(contact.volume()/sv.second - 1), 5e-7) << sv.first;

        // The same triangles, in the same body frame: every vertex near
        // its contact-mesh twin, those inside the flat faces exactly there
        // (a hole off the axis moves the centre of mass: the frame must
        // be the contact mesh's, not the volume-true mesh's own)
        EXPECT_EQ(cfd.faces(), contact.faces()) << sv.first;
        label same = 0;
        forAll(cfd.points(), i)
        {
            const scalar d = mag(cfd.points()[i] - contact.points()[i]);
            EXPECT_LT(d, 0.004*s->boundingRadius()) << sv.first;
            same += d == 0;
        }
        if (!s->isSphere())
        {
            EXPECT_GT(same, 0) << sv.first;
            EXPECT_NEAR
            (
                cfd.bounds().max().z(), contact.bounds().max().z(), 1e-15
            ) << sv.first;
            EXPECT_NEAR
            (
                cfd.bounds().min().z(), contact.bounds().min().z(), 1e-15
            ) << sv.first;
        }
        // Beyond the bounding radius by the facet offset only
        EXPECT_LT(cfd.boundingRadius(), 1.004*s->boundingRadius())
            << sv.first;
    }
}

TEST(volumeTrueMesh, stlPelletIsItsOwnMesh)
{
    const rbd::triMesh sphere(rbd::pelletMeshes::sphere(0.004, 320));
    const fileName f(rbdTest::tmpFile("volumeTrue.stl"));
    rbd::writeSTL(f, List<rbd::triMesh>(1, sphere), false);
    autoPtr<rbd::pelletShape> s = rbd::pelletShape::New
    (
        parse("shape stl; file \"" + f + "\";")
    );
    EXPECT_EQ(s->volumeTrueMesh().points(), s->mesh().points());
    EXPECT_EQ(s->exactVolume(), s->volume());
    Foam::rm(f);
}

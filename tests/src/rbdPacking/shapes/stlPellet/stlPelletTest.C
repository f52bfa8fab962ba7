// Unit tests for src/rbdPacking/shapes/stlPellet

#include <gtest/gtest.h>
#include "stlPellet.H"
#include "stlIO.H"
#include "pelletMeshes.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;

namespace
{
    dictionary stlDict(const fileName& file, const scalar scale)
    {
        IStringStream is
        (
            "shape stl; file \"" + file + "\"; scale "
          + std::to_string(scale) + ";"
        );
        return dictionary(is);
    }

    fileName writeMesh(const rbd::triMesh& m, const std::string& name)
    {
        const fileName f(rbdTest::tmpFile(name));
        rbd::writeSTL(f, List<rbd::triMesh>(1, m), false);
        return f;
    }
}


TEST(stlPellet, scaledClosedSurfaceInPrincipalFrame)
{
    // A box 1 x 2 x 3 file units at an offset, read in mm
    rbd::triMesh box(rbdTest::box(1, 2, 3));
    box.transform(tensor::I, vector(5, 6, 7));
    const fileName f(writeMesh(box, "box.stl"));

    autoPtr<rbd::pelletShape> s = rbd::pelletShape::New(stlDict(f, 0.001));
    EXPECT_EQ(s->type(), "stl");
    EXPECT_NEAR(s->volume(), 6e-9, 1e-20);
    EXPECT_NEAR(s->area(), 22e-6, 1e-17);
    // Box moments per density: V (b^2 + c^2)/12 ...
    const vector I = s->principalInertiaPerDensity();
    EXPECT_NEAR(I.x(), 6e-9*(4e-6 + 9e-6)/12, 1e-24);
    EXPECT_NEAR(I.z(), 6e-9*(1e-6 + 4e-6)/12, 1e-24);
    // Centre of mass at the origin
    const boundBox bb = s->mesh().bounds();
    EXPECT_NEAR(mag(bb.centre()), 0, 1e-15);
    EXPECT_NEAR(s->boundingRadius(), 0.5e-3*std::sqrt(14.0), 1e-15);
    EXPECT_NEAR(s->diameter(), s->volumeEquivalentDiameter(), 1e-18);
    Foam::rm(f);
}


TEST(stlPelletDeath, openInwardAndMissingSurfacesNameTheFile)
{
    const rbd::triMesh sphere(rbd::pelletMeshes::sphere(1, 320));

    const fileName open(writeMesh(rbdTest::without(sphere, {7}), "open.stl"));
    EXPECT_EXIT
    (
        rbd::pelletShape::New(stlDict(open, 0.001)),
        ::testing::ExitedWithCode(1),
        "Bad entry 'file .*open.stl.*;'(.|\n)*closed, outward-oriented"
        "(.|\n)*border edges"
    );

    rbd::triMesh inward(sphere);
    inward.flip();
    const fileName in(writeMesh(inward, "inward.stl"));
    EXPECT_EXIT
    (
        rbd::pelletShape::New(stlDict(in, 1)),
        ::testing::ExitedWithCode(1),
        "Bad entry 'file .*inward.stl.*;'(.|\n)*inward oriented"
    );

    // Two tetrahedra sharing an edge (the second is the first turned by
    // 180 degrees about x): four triangles at that edge
    pointField p(rbdTest::tetrahedron().points());
    p.append(point(0, -1, 0));
    p.append(point(0, 0, -1));
    const rbd::triMesh twoTets
    (
        p,
        List<triFace>
        ({
            triFace(0, 2, 1), triFace(0, 1, 3), triFace(0, 3, 2),
            triFace(1, 2, 3), triFace(0, 4, 1), triFace(0, 1, 5),
            triFace(0, 5, 4), triFace(1, 4, 5)
        })
    );
    const fileName nm(writeMesh(twoTets, "nonManifold.stl"));
    EXPECT_EXIT
    (
        rbd::pelletShape::New(stlDict(nm, 1)),
        ::testing::ExitedWithCode(1),
        "Bad entry 'file .*nonManifold.stl.*;'(.|\n)*not manifold"
    );
    Foam::rm(nm);

    EXPECT_EXIT
    (
        rbd::pelletShape::New(stlDict(rbdTest::tmpFile("missing.stl"), 1)),
        ::testing::ExitedWithCode(1),
        "Bad entry 'file .*missing.stl.*;'(.|\n)*cannot find"
    );

    EXPECT_EXIT
    (
        rbd::pelletShape::New(stlDict(in, -2)),
        ::testing::ExitedWithCode(1),
        "Bad entry 'scale -2"
    );
    Foam::rm(open);
    Foam::rm(in);
}

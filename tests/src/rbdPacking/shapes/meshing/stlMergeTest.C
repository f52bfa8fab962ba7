// Unit tests for src/rbdPacking/shapes/meshing/stlIO: vertices that differ
// by a rounding error are merged before the closure check
// (stlMergeTolerance, relative to the bounding box diagonal); a truly
// open surface is still refused

#include <gtest/gtest.h>
#include "stlIO.H"
#include "cgalMeshTools.H"
#include "pelletMeshes.H"
#include "OSspecific.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

#include <cstdio>
#include <fstream>

using namespace Foam;

namespace
{
    //- Write \c m as an ASCII STL in full double precision, each vertex
    //  of each triangle moved by (1 + k mod 7) * relJitter times the
    //  bounding box diagonal along x, y and z (k counts the vertex
    //  occurrences): a vertex shared by several triangles is written with
    //  a different rounding in each, as some exporters do
    void writeJittered
    (
        const fileName& f,
        const rbd::triMesh& m,
        const scalar relJitter
    )
    {
        const scalar diag = boundBox(m.points()).mag();
        std::ofstream os(f);
        os  << "solid jittered\n";
        label k = 0;
        char buf[128];
        for (const triFace& t : m.faces())
        {
            os  << "  facet normal 0 0 0\n    outer loop\n";
            for (const label pi : t)
            {
                const scalar d = (1 + (k++ % 7))*relJitter*diag;
                const point& p = m.points()[pi];
                std::snprintf
                (
                    buf, sizeof(buf), "      vertex %.17g %.17g %.17g\n",
                    p.x() + d, p.y() - d, p.z() + d
                );
                os  << buf;
            }
            os  << "    endloop\n  endfacet\n";
        }
        os  << "endsolid jittered\n";
    }
}


TEST(stlMerge, jitteredVerticesReadAsClosed)
{
    // A 10 mm cylinder, vertices jittered by 1e-15 to 7e-15 of the
    // diagonal (a few units in the last place)
    const rbd::triMesh cyl = rbd::pelletMeshes::cylinder(0.01, 0.01, 500);
    const fileName f = rbdTest::tmpFile("jittered.stl");
    writeJittered(f, cyl, 1e-15);

    // As read, without merging, it is not closed: the test can fail
    {
        pointField pts;
        List<triFace> faces;
        string why;
        ASSERT_TRUE(rbd::cgalMeshTools::readSTL(f, pts, faces, why)) << why;
        EXPECT_GT(pts.size(), cyl.points().size());
        const string problem =
            rbd::checkClosedSolid(rbd::triMesh(pts, faces));
        EXPECT_NE(problem.find("not closed"), std::string::npos) << problem;

        // mergeCloseVertices gives back the mesh's own vertices
        EXPECT_GT(rbd::mergeCloseVertices(pts, faces), 0);
        EXPECT_EQ(pts.size(), cyl.points().size());
        EXPECT_EQ(faces.size(), cyl.faces().size());
    }

    rbd::triMesh m;
    string why;
    ASSERT_TRUE(rbd::readSTL(f, 1, m, why)) << why;
    EXPECT_EQ(m.points().size(), cyl.points().size());
    EXPECT_EQ(m.faces().size(), cyl.faces().size());
    EXPECT_NEAR(m.volume()/cyl.volume(), 1, 1e-12);

    // In millimetres with scale 1e-3: the tolerance is relative, the same
    // file shape reads the same
    rbd::triMesh mm(cyl);
    mm.scale(1000);
    writeJittered(f, mm, 1e-15);
    ASSERT_TRUE(rbd::readSTL(f, 1e-3, m, why)) << why;
    EXPECT_NEAR(m.volume()/cyl.volume(), 1, 1e-12);
    Foam::rm(f);
}


TEST(stlMerge, openSurfaceStillRefused)
{
    const fileName f = rbdTest::tmpFile("open.stl");

    // A box with a triangle missing, jittered as above: merged, still open
    writeJittered(f, rbdTest::without(rbdTest::box(0.01, 0.01, 0.01), {3}),
        1e-15);
    rbd::triMesh m;
    string why;
    EXPECT_FALSE(rbd::readSTL(f, 1, m, why));
    EXPECT_NE(why.find("not closed"), std::string::npos) << why;

    // A gap of 1e-6 of the diagonal (1e-8 m for this box) is a gap, not
    // a rounding error: not merged, refused
    writeJittered(f, rbdTest::box(0.01, 0.01, 0.01), 1e-6);
    EXPECT_FALSE(rbd::readSTL(f, 1, m, why));
    EXPECT_NE(why.find("not closed"), std::string::npos) << why;
    Foam::rm(f);
}


TEST(stlMerge, collapsedTrianglesDropped)
{
    // Two points 1e-12 apart (relative 1e-12): one vertex; the triangle
    // that joined them is dropped, the other renumbered
    pointField pts({point(0, 0, 0), point(1, 0, 0), point(1, 1e-12, 0),
        point(0, 1, 0)});
    List<triFace> faces({triFace(0, 1, 2), triFace(0, 2, 3)});
    EXPECT_EQ(rbd::mergeCloseVertices(pts, faces), 1);
    EXPECT_EQ(pts.size(), 3);
    ASSERT_EQ(faces.size(), 1);
    EXPECT_EQ(faces[0][0], faces[0][0]);
    EXPECT_NE(faces[0][1], faces[0][2]);

    // Nothing within the tolerance: unchanged
    pointField far({point(0, 0, 0), point(1, 0, 0), point(0, 1, 0)});
    List<triFace> one({triFace(0, 1, 2)});
    EXPECT_EQ(rbd::mergeCloseVertices(far, one), 0);
    EXPECT_EQ(far.size(), 3);
    EXPECT_EQ(one.size(), 1);
}

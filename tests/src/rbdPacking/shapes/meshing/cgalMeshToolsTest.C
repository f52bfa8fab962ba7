// Unit tests for src/rbdPacking/shapes/meshing/cgalMeshTools

#include <gtest/gtest.h>
#include <fstream>
#include <string>
#include "cgalMeshTools.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

using namespace Foam;

namespace
{
    //- Does the answer of checkClosedSolid contain the text?
    ::testing::AssertionResult says(const rbd::triMesh& m, const char* text)
    {
        const string why = rbd::checkClosedSolid(m);
        if (why.find(text) != std::string::npos)
        {
            return ::testing::AssertionSuccess();
        }
        return ::testing::AssertionFailure()
            << "checkClosedSolid said '" << why << "', not '" << text << "'";
    }

    //- Two meshes as one
    rbd::triMesh join(const rbd::triMesh& a, const rbd::triMesh& b)
    {
        pointField p(a.points());
        p.append(b.points());
        List<triFace> f(a.faces());
        for (triFace t : b.faces())
        {
            for (label& i : t)
            {
                i += a.nPoints();
            }
            f.append(t);
        }
        return rbd::triMesh(p, f);
    }

    //- Drop the points that no triangle uses
    rbd::triMesh compact(const pointField& p, const List<triFace>& f)
    {
        labelList newIndex(p.size(), -1);
        DynamicList<point> q;
        List<triFace> g(f);
        for (triFace& t : g)
        {
            for (label& i : t)
            {
                if (newIndex[i] < 0)
                {
                    newIndex[i] = q.size();
                    q.append(p[i]);
                }
                i = newIndex[i];
            }
        }
        return rbd::triMesh(pointField(q), g);
    }
}


TEST(cgalMeshTools, closedSolidsPass)
{
    EXPECT_EQ(rbd::checkClosedSolid(rbdTest::box()), "");
    EXPECT_EQ(rbd::checkClosedSolid(rbdTest::tetrahedron()), "");
}

TEST(cgalMeshTools, defectsAreNamed)
{
    const rbd::triMesh box = rbdTest::box();

    EXPECT_TRUE(says(rbd::triMesh(), "no triangles"));
    EXPECT_TRUE(says(rbdTest::without(box, {0, 1}),
        "not closed: 4 border edges"));
    EXPECT_TRUE(says(rbdTest::without(box, {0}), "not closed: 3 border"));

    rbd::triMesh inward(box);
    inward.flip();
    EXPECT_TRUE(says(inward, "inward oriented"));

    List<triFace> f(box.faces());
    f[3].flip();
    EXPECT_TRUE(says(rbd::triMesh(box.points(), f),
        "inconsistently oriented"));

    // Disjoint, sharing an edge, sharing a vertex
    EXPECT_TRUE(says(join(box, box.transformed(tensor::I, vector(3, 0, 0))),
        "2 separate parts"));
    EXPECT_TRUE(says(join(box, box.transformed(tensor::I, vector(1, 1, 0))),
        "2 separate parts"));
    {
        // Glue the second box to the first along the edge x = y = 1
        rbd::triMesh two = join(box, box.transformed(tensor::I,
            vector(1, 1, 0)));
        List<triFace> g(two.faces());
        for (label facei = box.nFaces(); facei < g.size(); ++facei)
        {
            for (label& i : g[facei])
            {
                if (i == 8) i = 3;      // (1, 1, 0)
                if (i == 12) i = 7;     // (1, 1, 1)
            }
        }
        EXPECT_TRUE(says(compact(two.points(), g),
            "edges shared by more than two triangles"));
        // Only the vertex (1, 1, 0)
        for (label facei = box.nFaces(); facei < g.size(); ++facei)
        {
            for (label& i : g[facei])
            {
                if (i == 7) i = 12;
            }
        }
        EXPECT_TRUE(says(compact(two.points(), g),
            "form more than one fan"));
    }

    // A point used by no triangle
    pointField p(box.points());
    p.append(point(5, 5, 5));
    EXPECT_TRUE(says(rbd::triMesh(p, box.faces()), "belong to no triangle"));

    // Vertex (1, 1, 1) pulled through the face x = 0
    pointField q(box.points());
    q[7] = point(-1, 0.5, 0.5);
    EXPECT_TRUE(says(rbd::triMesh(q, box.faces()), "self-intersecting"));
}

TEST(cgalMeshTools, zeroAreaTriangleIsNamed)
{
    // Tetrahedron with point 4 on edge 1-2: triangle (2, 1, 4) is flat
    const rbd::triMesh t = rbdTest::tetrahedron();
    pointField p(t.points());
    p.append(0.5*(p[1] + p[2]));
    const List<triFace> f
    ({
        triFace(0, 1, 3), triFace(0, 3, 2), triFace(1, 2, 3),
        triFace(0, 2, 4), triFace(0, 4, 1), triFace(2, 1, 4)
    });
    EXPECT_TRUE(says(rbd::triMesh(p, f), "1 triangles of zero area"));
}

TEST(cgalMeshTools, loopSubdivisionQuadruplesFaces)
{
    const rbd::triMesh m =
        rbd::cgalMeshTools::loopSubdivision(rbdTest::tetrahedron(), 2);
    EXPECT_EQ(m.nFaces(), 4*4*4);
    EXPECT_EQ(m.nPoints(), 4 + 6 + 24);
    EXPECT_EQ(rbd::checkClosedSolid(m), "");
    // Loop smoothing shrinks the solid
    EXPECT_LT(m.volume(), 1.0/6);
}

TEST(cgalMeshTools, triangulateSquareWithHole)
{
    // Square [0, 1]^2 counter-clockwise, hole [0.25, 0.75]^2 clockwise,
    // one interior point
    const List<vector2D> pts
    ({
        {0, 0}, {1, 0}, {1, 1}, {0, 1},
        {0.25, 0.25}, {0.25, 0.75}, {0.75, 0.75}, {0.75, 0.25},
        {0.1, 0.5}
    });
    const labelListList loops({{0, 1, 2, 3}, {4, 5, 6, 7}});
    const List<triFace> tris =
        rbd::cgalMeshTools::triangulateRegion(pts, loops);

    // 2 Ni + Nb - 2 + 2 g triangles, all counter-clockwise, area 3/4
    EXPECT_EQ(tris.size(), 2*1 + 8 - 2 + 2*1);
    scalar area = 0;
    for (const triFace& t : tris)
    {
        const vector2D a = pts[t[1]] - pts[t[0]];
        const vector2D b = pts[t[2]] - pts[t[0]];
        const scalar A = 0.5*(a.x()*b.y() - a.y()*b.x());
        EXPECT_GT(A, 0);
        area += A;
    }
    EXPECT_NEAR(area, 0.75, 1e-15);
}


TEST(cgalMeshTools, successiveCutsLeaveNoDegenerateTriangles)
{
    // A pellet of a bed of six cylinders is capped at its contacts one cut
    // after another (contactGeometry::cap). The cut points are rounded to
    // doubles: the second of these cuts left two zero-area triangles, and
    // CGAL's clip failed on the third (an assertion on lines that do not
    // meet), so the case writer stopped. Each cut must leave a closed,
    // outward, non-self-intersecting solid without zero-area triangles.
    const std::string file
    (
        std::string(RBD_TEST_SOURCE_DIR)
      + "/rbdPacking/shapes/meshing/data/sixCylindersCapSequence.cuts"
    );
    std::ifstream is(file);
    ASSERT_TRUE(is.good()) << "cannot read " << file;
    std::string line;
    while (is.peek() == '#')
    {
        std::getline(is, line);
    }
    label nPlanes = 0;
    is >> nPlanes;
    List<point> p(nPlanes);
    List<vector> n(nPlanes);
    for (label k = 0; k < nPlanes; ++k)
    {
        is >> p[k].x() >> p[k].y() >> p[k].z()
           >> n[k].x() >> n[k].y() >> n[k].z();
    }
    label nPoints = 0, nFaces = 0;
    is >> nPoints >> nFaces;
    pointField x(nPoints);
    for (point& q : x)
    {
        is >> q.x() >> q.y() >> q.z();
    }
    List<triFace> f(nFaces);
    for (triFace& t : f)
    {
        is >> t[0] >> t[1] >> t[2];
    }
    ASSERT_FALSE(is.fail()) << "truncated " << file;
    ASSERT_EQ(nPlanes, 3);

    rbd::triMesh m(x, f);
    ASSERT_EQ(rbd::checkClosedSolid(m), "");
    scalar V = m.volume();
    for (label k = 0; k < nPlanes; ++k)
    {
        m = rbd::cgalMeshTools::clipByPlane(m, p[k], n[k]);
        EXPECT_EQ(rbd::checkClosedSolid(m), "") << "after cut " << k;

        // Each cap takes a little of the pellet, never all of it
        const scalar cutV = m.volume();
        EXPECT_LT(cutV, V) << "cut " << k;
        EXPECT_GT(cutV, 0.9*V) << "cut " << k;
        V = cutV;
    }
}

// Mesh contacts of src/rbdPacking/narrowPhase/meshContacts against closed
// forms: cube on the floor (4 corners), two boxes edge on edge, a vertex on
// a face, face on face interpenetrating, sphere against a mesh sphere;
// against brute force:
// washers touching or crossing, convex pairs against separating axes. The
// reduction of a flat patch: narrowPhase/contactReduction.

#include <gtest/gtest.h>
#include "meshContacts.H"
#include "sphereContacts.H"
#include "pelletMeshes.H"
#include "../../shapes/meshing/testMeshes.H"
#include "../../testTools/penetrationProbe.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar s = 0.01;          // cube side [m]
    const scalar band = 0.1*0.5*s*Foam::sqrt(3.0);

    //- Unit-side cube scaled to s, centred on the origin
    triMesh cube()
    {
        triMesh m(rbdTest::box(s, s, s));
        m.transform(tensor::I, vector::uniform(-0.5*s));
        return m;
    }

    rigidBody body(const point& x, const quaternion& q)
    {
        return rigidBody(1, vector::one, x, q, true);
    }

    //- Rotation taking unit vector a to unit vector b
    quaternion turn(const vector& a, const vector& b)
    {
        const vector axis(a ^ b);
        const scalar angle = Foam::atan2(mag(axis), a & b);
        return quaternion(axis/mag(axis), angle);
    }
}


TEST(meshContacts, cubeOnFloorGivesItsFourCorners)
{
    const triMesh m(cube());
    const meshContacts mc(m, band);
    const tube container(1, 1, 0.3, 0.5);

    const scalar gap = 1e-4;
    const rigidBody b(body(point(0.2, 0.1, 0.5*s + gap), quaternion(1)));
    DynamicList<contact> cs;
    mc.meshTube(0, b, container, cs);

    ASSERT_EQ(cs.size(), 4);
    const List<rigidBody> bodies({b});
    for (const contact& c : cs)
    {
        EXPECT_EQ(c.k, tubeBottom);
        EXPECT_NEAR(c.gap, gap, 1e-12);
        EXPECT_NEAR(mag(c.n - vector(0, 0, 1)), 0, 1e-12);
        EXPECT_NEAR(mag(c.p.x() - 0.2), 0.5*s, 1e-12);
        EXPECT_NEAR(mag(c.p.y() - 0.1), 0.5*s, 1e-12);
        EXPECT_NEAR(meshContacts::gap(c, bodies, container), gap, 1e-15);
        EXPECT_FALSE(c.centreBased);
    }
}


TEST(meshContacts, twoBoxesEdgeOnEdge)
{
    const triMesh m(cube());
    const meshContacts mc(m, band);

    // Lower box k: top edge along y at z = h/sqrt(2); upper box i: bottom
    // edge along x at gap above it
    const scalar half = 0.5*s*Foam::sqrt(2.0);
    const scalar gap = 2e-4;
    const rigidBody bk
    (
        body(point(0, 0, 0), quaternion(vector(0, 1, 0), 0.25*M_PI))
    );
    const rigidBody bi
    (
        body
        (
            point(0, 0, 2*half + gap),
            quaternion(vector(1, 0, 0), 0.25*M_PI)
        )
    );

    DynamicList<contact> cs;
    mc.meshMesh(1, bi, 0, bk, cs);

    ASSERT_EQ(cs.size(), 1);
    const contact& c = cs[0];
    EXPECT_EQ(c.i, 1);
    EXPECT_EQ(c.k, 0);
    EXPECT_NEAR(c.gap, gap, 1e-12);
    EXPECT_NEAR(mag(c.n - vector(0, 0, 1)), 0, 1e-9);
    EXPECT_NEAR(mag(c.p - point(0, 0, half + 0.5*gap)), 0, 1e-12);

    // And seen from the other side: the normal flips
    DynamicList<contact> rs;
    mc.meshMesh(0, bk, 1, bi, rs);
    ASSERT_EQ(rs.size(), 1);
    EXPECT_NEAR(rs[0].gap, gap, 1e-12);
    EXPECT_NEAR(mag(rs[0].n + vector(0, 0, 1)), 0, 1e-9);
}


TEST(meshContacts, vertexOnFace)
{
    const triMesh m(cube());
    const meshContacts mc(m, band);

    // Upper cube i stands on a corner: its diagonal (1, 1, 1) points down
    const quaternion q(turn(vector(1, 1, 1)/Foam::sqrt(3.0), vector(0, 0, -1)));
    const scalar gap = 3e-4;
    const scalar corner = 0.5*s*Foam::sqrt(3.0);
    const rigidBody bk(body(point(0, 0, 0), quaternion(1)));
    const rigidBody bi(body(point(0, 0, 0.5*s + corner + gap), q));

    DynamicList<contact> cs;
    mc.meshMesh(1, bi, 0, bk, cs);
    ASSERT_EQ(cs.size(), 1);
    EXPECT_NEAR(cs[0].gap, gap, 1e-12);
    EXPECT_NEAR(mag(cs[0].n - vector(0, 0, 1)), 0, 1e-12);
    EXPECT_NEAR(mag(cs[0].ri - vector(0, 0, -corner)), 0, 1e-12);

    // Face of i over the vertex of k: the normal points from k to i still
    DynamicList<contact> rs;
    mc.meshMesh(0, bk, 1, bi, rs);
    ASSERT_EQ(rs.size(), 1);
    EXPECT_NEAR(rs[0].gap, gap, 1e-12);
    EXPECT_NEAR(mag(rs[0].n + vector(0, 0, 1)), 0, 1e-12);
}


TEST(meshContacts, interpenetratingFacesGiveNegativeGapsAndTheirCorners)
{
    // Small cube (side s/2) sunk into the top of a cube of side s
    triMesh small(cube());
    small.scale(0.5);
    triMesh big(cube());

    // One mesh per meshContacts: both bodies are the big cube here, the
    // small one is checked against the closed form through the floor
    const meshContacts mc(big, band);
    const scalar depth = 1e-4;
    const rigidBody bk(body(point(0, 0, 0), quaternion(1)));
    const rigidBody bi
    (
        body
        (
            point(0.2*s, 0.3*s, s - depth),
            quaternion(vector(0, 0, 1), 0.3)
        )
    );
    DynamicList<contact> cs;
    mc.meshMesh(1, bi, 0, bk, cs);

    // Upper cube's bottom face over the lower's top face, overlapping in
    // a polygon: the reduced set keeps at most 4 points, all at -depth,
    // spanning (up to the merge distance) the overlap polygon
    ASSERT_GE(cs.size(), 3);
    ASSERT_LE(cs.size(), 4);
    for (const contact& c : cs)
    {
        EXPECT_NEAR(c.gap, -depth, 1e-12);
        EXPECT_NEAR(mag(c.n - vector(0, 0, 1)), 0, 1e-12);
        EXPECT_LE(mag(c.p.x()), 0.5*s + 1e-12);
        EXPECT_LE(mag(c.p.y()), 0.5*s + 1e-12);
    }

    // The gap follows a translation of the bodies (overlap correction)
    List<rigidBody> bodies({bk, bi});
    bodies[1].displace(vector(0, 0, 3*depth));
    for (const contact& c : cs)
    {
        EXPECT_NEAR(meshContacts::gap(c, bodies, tube(1, 1, 0, 0)), 2*depth,
            1e-12);
    }
}


TEST(meshContacts, sphereAgainstMeshSphereAgreesWithExactSphereContact)
{
    const scalar a = 0.005;
    const triMesh m(pelletMeshes::sphere(2*a, 1280));
    const meshContacts mc(m, 0.1*a);

    // Inscribed mesh: the mesh sphere is smaller by at most the sagitta of
    // its triangles
    scalar rMin = GREAT;
    for (const triFace& f : m.faces())
    {
        rMin = min(rMin, mag(f.centre(m.points())));
    }
    const scalar sagitta = a - rMin;
    ASSERT_LT(sagitta, 0.01*a);

    for (const scalar gap : {2e-4, 0.0, -1e-4})
    {
        const vector dir(vector(0.3, -0.5, 0.8)/mag(vector(0.3, -0.5, 0.8)));
        const rigidBody bk(body(point(0, 0, 0), quaternion(vector(1, 1, 0)
            /Foam::sqrt(2.0), 0.4)));
        const rigidBody bi(body((2*a + gap)*dir, quaternion(1)));

        contact exact;
        ASSERT_TRUE(sphereContacts::sphereSphere(1, bi, a, 0, bk, a, 0.1*a,
            exact));

        DynamicList<contact> cs;
        mc.sphereMesh(1, bi, a, 0, bk, cs);
        ASSERT_EQ(cs.size(), 1);
        EXPECT_GE(cs[0].gap, exact.gap - 1e-12);
        EXPECT_LE(cs[0].gap, exact.gap + sagitta);
        EXPECT_GT(cs[0].n & exact.n, Foam::cos(0.1));
    }
}


TEST(meshContacts, meshSpheresAgreeWithExactSpheres)
{
    const scalar a = 0.005;
    const triMesh m(pelletMeshes::sphere(2*a, 1280));
    const meshContacts mc(m, 0.1*a);
    scalar rMin = GREAT;
    for (const triFace& f : m.faces())
    {
        rMin = min(rMin, mag(f.centre(m.points())));
    }
    const scalar sagitta = a - rMin;

    const vector dir(vector(-0.2, 0.1, 1)/mag(vector(-0.2, 0.1, 1)));
    const scalar gap = 1e-4;
    const rigidBody bk(body(point(0, 0, 0), quaternion(vector(0, 0, 1), 1)));
    const rigidBody bi
    (
        body((2*a + gap)*dir, quaternion(vector(1, 0, 0), 0.7))
    );
    DynamicList<contact> cs;
    mc.meshMesh(1, bi, 0, bk, cs);
    ASSERT_GE(cs.size(), 1);
    // Every feature pair within the band lies within about sqrt(band/a)
    // of the line of centres; the deepest one on it
    scalar minGap = GREAT;
    vector nDeepest(Zero);
    for (const contact& c : cs)
    {
        if (c.gap < minGap)
        {
            minGap = c.gap;
            nDeepest = c.n;
        }
        EXPECT_GT(c.n & dir, Foam::cos(0.35));
    }
    EXPECT_GT(nDeepest & dir, Foam::cos(0.1));
    EXPECT_GE(minGap, gap - 1e-12);
    EXPECT_LE(minGap, gap + 2*sagitta);
}


// * * * * * * * * * * * Brute-force reference of washers * * * * * * * * * //

#include "pelletShape.H"
#include "IStringStream.H"
#include <random>

namespace
{
    //- Segment (p, q) crosses triangle (a, b, c)
    bool crosses
    (
        const point& p, const point& q,
        const point& a, const point& b, const point& c
    )
    {
        const vector d(q - p), e1(b - a), e2(c - a);
        const vector h(d ^ e2);
        const scalar det = e1 & h;
        if (mag(det) < 1e-30)
        {
            return false;
        }
        const vector s(p - a);
        const scalar u = (s & h)/det;
        const vector qv(s ^ e1);
        const scalar v = (d & qv)/det;
        const scalar t = (e2 & qv)/det;
        return u >= 0 && v >= 0 && u + v <= 1 && t >= 0 && t <= 1;
    }

    //- The surfaces of mesh m at poses (Ri, xi) and (Rk, xk) cross
    bool meshesCross
    (
        const triMesh& m,
        const tensor& Ri, const vector& xi,
        const tensor& Rk, const vector& xk
    )
    {
        const List<triFace>& fs = m.faces();
        const pointField& pts = m.points();
        for (label side = 0; side < 2; ++side)
        {
            const tensor& RA = side ? Rk : Ri;
            const vector& xA = side ? xk : xi;
            const tensor& RB = side ? Ri : Rk;
            const vector& xB = side ? xi : xk;
            pointField a(pts.size()), b(pts.size());
            forAll(pts, j)
            {
                a[j] = (RA & pts[j]) + xA;
                b[j] = (RB & pts[j]) + xB;
            }
            for (const triFace& fa : fs)
            {
                for (label j = 0; j < 3; ++j)
                {
                    const point& p = a[fa[j]];
                    const point& q = a[fa[(j + 1) % 3]];
                    for (const triFace& fb : fs)
                    {
                        if (crosses(p, q, b[fb[0]], b[fb[1]], b[fb[2]]))
                        {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }
}


TEST(meshContacts, washersTouchingOrCrossingAreNeverMissed)
{
    // Two washers (10/6/2 mm, 300 faces) at random orientations brought
    // together along a random direction: at the first touching position
    // (bisection on the brute-force crossing test of all edges against all
    // faces), and moved on by 10 % and 30 % of the band into each other,
    // meshMesh must report an interpenetration (a contact of gap <= 0)
    IStringStream is
    (
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.002;"
        " faces 300;"
    );
    const autoPtr<pelletShape> shape(pelletShape::New(dictionary(is)));
    const triMesh& m = shape->mesh();
    const scalar lambda = 0.1*m.boundingRadius();
    const meshContacts mc(m, lambda);

    std::mt19937 rng(11);
    std::uniform_real_distribution<double> U(-1, 1);
    auto randomQ = [&]()
    {
        const vector axis(U(rng), U(rng), U(rng));
        return quaternion(axis/mag(axis), 3*U(rng));
    };

    label missed = 0;
    const label nPoses = 15;
    for (label pose = 0; pose < nPoses; ++pose)
    {
        const quaternion qi(randomQ()), qk(randomQ());
        vector d(U(rng), U(rng), U(rng));
        d /= mag(d);
        const tensor Ri(qi.R()), Rk(qk.R());

        // Bisection for the first touch along d
        scalar lo = 0, hi = 2.2*m.boundingRadius();
        for (label it = 0; it < 30; ++it)
        {
            const scalar mid = 0.5*(lo + hi);
            (meshesCross(m, Ri, mid*d, Rk, Zero) ? lo : hi) = mid;
        }

        for (const scalar into : {0.0, 0.1, 0.3})
        {
            const scalar sep = hi - into*lambda;
            const rigidBody bi(body(sep*d, qi));
            const rigidBody bk(body(Zero, qk));
            DynamicList<contact> cs;
            mc.meshMesh(1, bi, 0, bk, cs);
            scalar gMin = GREAT;
            for (const contact& c : cs)
            {
                gMin = min(gMin, c.gap);
            }
            const scalar tol = into > 0 ? 0 : 1e-3*lambda;
            if (gMin > tol)
            {
                ++missed;
                ADD_FAILURE()
                    << "pose " << pose << " into " << into
                    << " contacts " << cs.size() << " gMin/lambda "
                    << gMin/lambda;
            }
        }
    }
    EXPECT_EQ(missed, 0);
}


TEST(meshContacts, convexPairsAgreeWithSeparatingAxes)
{
    // Two convex pellets of one mesh at random orientations, brought
    // together along a random direction to the first touch (bisection on
    // the exact penetration depth delta of the separating axis theorem,
    // testTools/penetrationProbe.H, independent of meshMesh), then 10 % of
    // the band apart and 5 % of the band into each other:
    // - apart: no contact interpenetrates;
    // - into: a contact is found, and the deepest is delta to within 1 %
    //   of the band (delta is about 5 % of the band): none missed, none
    //   seen too shallow, none deeper (a deeper one is pushed out by the
    //   overlap correction along its normal, which is then not the
    //   direction of least interpenetration: pellets were pushed
    //   sideways).
    // The regular tetrahedron (edge 10 mm, acute edges, 70.5 degrees) is
    // the hard case. Measured on these 100 poses at 5 % of the band:
    // deepest - delta within [-6e-15, 1e-15] band for the tetrahedra,
    // [-3e-15, 2e-15] for the cylinder (d = h = 10 mm, 300 faces); an
    // earlier narrow phase saw 1 of 400 tetrahedra poses at 5 % shallower
    // than delta (0.017 for 0.035 band), and the one before this test was
    // wrong for 162 and 171 of the 400 tetrahedra poses, most of them
    // missed.
    const scalar e = 0.01;
    const pointField tetPts
    ({
        point(0, 0, 0), point(e, 0, 0),
        point(0.5*e, 0.5*Foam::sqrt(3.0)*e, 0),
        point(0.5*e, Foam::sqrt(3.0)/6*e, Foam::sqrt(2.0/3.0)*e)
    });
    List<triFace> tetFaces(4);
    tetFaces[0] = triFace(0, 2, 1);
    tetFaces[1] = triFace(0, 1, 3);
    tetFaces[2] = triFace(1, 2, 3);
    tetFaces[3] = triFace(0, 3, 2);
    triMesh tet(tetPts, tetFaces);
    tet.transform(tensor::I, -sum(tetPts)/4.0);
    const triMesh cyl(pelletMeshes::cylinder(0.01, 0.01, 300));

    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(-1, 1);
    auto randomQ = [&]()
    {
        const vector axis(U(rng), U(rng), U(rng));
        return quaternion(axis/mag(axis), 3*U(rng));
    };

    const triMesh* meshes[] = {&tet, &cyl};
    for (const triMesh* m : meshes)
    {
        const bool isTet = m == &tet;
        const scalar lambda = 0.1*m->boundingRadius();
        const meshContacts mc(*m, lambda);

        // (the cylinder as a prism: its side faces' edges share one
        // direction, which keeps the axes few)
        const rbdTest::penetrationProbe probe
        (
            isTet
          ? rbdTest::penetrationProbe
            (
                *m, rbdTest::penetrationProbe::convexTag()
            )
          : rbdTest::penetrationProbe(*m)
        );

        label bad = 0;
        scalar shallowest = GREAT;
        scalar deepestSeen = -GREAT;
        for (label pose = 0; pose < 100; ++pose)
        {
            const quaternion qi(randomQ()), qk(randomQ());
            vector d(U(rng), U(rng), U(rng));
            d /= mag(d);
            const rigidBody bk(body(Zero, qk));

            scalar lo = 0, hi = 2.2*m->boundingRadius();
            for (label it = 0; it < 60; ++it)
            {
                const scalar mid = 0.5*(lo + hi);
                (probe.penetration(body(mid*d, qi), bk) > 0 ? lo : hi) = mid;
            }

            for (const scalar into : {-0.1, 0.05})
            {
                const rigidBody bi(body((hi - into*lambda)*d, qi));
                const scalar delta = probe.penetration(bi, bk);
                DynamicList<contact> cs;
                mc.meshMesh(1, bi, 0, bk, cs);
                scalar deepest = -GREAT;
                for (const contact& c : cs)
                {
                    deepest = max(deepest, -c.gap);
                }
                // (no contact: deepest = -GREAT, below the bound)
                const bool ok =
                    into < 0
                  ? deepest <= 0
                  : mag(deepest - delta) <= 1e-2*lambda;
                if (into > 0)
                {
                    shallowest = min(shallowest, (deepest - delta)/lambda);
                    deepestSeen = max(deepestSeen, (deepest - delta)/lambda);
                }
                if (!ok)
                {
                    ++bad;
                    ADD_FAILURE()
                        << (isTet ? "tetrahedra" : "cylinders")
                        << " pose " << pose << " into " << into
                        << ": deepest contact/lambda " << deepest/lambda
                        << ", depth/lambda " << delta/lambda
                        << ", contacts " << cs.size();
                }
            }
        }
        EXPECT_EQ(bad, 0);
        std::cout
            << "[ measured ] " << (isTet ? "tetrahedra" : "cylinders")
            << ": (deepest contact - depth)/band at 5 % of the band in ["
            << shallowest << ", " << deepestSeen << "]" << std::endl;
    }
}

// The narrow phase by shape pair: src/rbdPacking/narrowPhase/contactDispatch
// (which generator a pair and the container use, and the pair's material)

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"
#include "contactDispatch.H"
#include <sstream>

using namespace rbdTest;

namespace
{
    const scalar d = 0.01;
    const scalar band = 0.1*0.5*d;

    std::string describe(const contactDispatch& cd)
    {
        OStringStream os;
        cd.describe(os);
        return os.str();
    }

    rigidBody bodyAt(const point& x, const quaternion& q)
    {
        return rigidBody(1e-3, vector::one*1e-8, x, q, true);
    }
}


TEST(contactDispatch, pairModelOfEachShapeAndContactModel)
{
    const autoPtr<pelletShape> sphere(shapeOf("shape sphere; diameter 0.01;"));
    const autoPtr<pelletShape> cyl
    (
        shapeOf("shape cylinder; diameter 0.01; height 0.01; faces 200;")
    );
    EXPECT_EQ(contactDispatch::pairModel(sphere(), "auto"), "sphere");
    EXPECT_EQ(contactDispatch::pairModel(sphere(), "exact"), "sphere");
    EXPECT_EQ(contactDispatch::pairModel(sphere(), "mesh"), "mesh");
    EXPECT_EQ(contactDispatch::pairModel(cyl(), "exact"), "prism");
    EXPECT_EQ(contactDispatch::pairModel(cyl(), "mesh"), "mesh");

    // auto: the exact solid, but for holes off the axis (a wall inside a
    // bore has no curvature term yet; the rings' bore is on the axis and
    // measured within bounds, the off-axis holes were not): the meshes
    const struct { const char* dict; const char* autoModel; } shapes[] =
    {
        {"shape cylinder; diameter 0.01; height 0.01; faces 200;", "prism"},
        {"shape trilobe; lobeDiameter 0.004; height 0.008; faces 300;",
            "prism"},
        {"shape quadrilobe; lobeDiameter 0.004; height 0.008; faces 300;",
            "prism"},
        {"shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
            " faces 300;", "prism"},
        {"shape cylinderWithHoles; diameter 0.01; height 0.008; holes 4;"
            " holeDiameter 0.002; faces 400;", "mesh"}
    };
    for (const auto& s : shapes)
    {
        const autoPtr<pelletShape> shape(shapeOf(s.dict));
        EXPECT_EQ(contactDispatch::pairModel(shape(), "auto"), s.autoModel)
            << s.dict;
        EXPECT_EQ(contactDispatch::pairModel(shape(), "exact"), "prism")
            << s.dict;
        EXPECT_EQ(contactDispatch::pairModel(shape(), "mesh"), "mesh")
            << s.dict;
    }
}


TEST(contactDispatch, spherePairCarriesThePelletsMaterial)
{
    // Two spheres 0.1 band apart, and one on the floor: the pair's contact
    // has the pellets' restitution and friction, the floor's the tube's
    const autoPtr<pelletShape> sphere(shapeOf("shape sphere; diameter 0.01;"));
    const tube container(0.05, 0.1, 0.7, 0.2);
    const contactDispatch cd(sphere(), container, 0.4, 0.3, band, "auto");
    EXPECT_FALSE(cd.meshes());
    EXPECT_EQ(describe(cd), "exact sphere contacts");

    const rigidBody a(bodyAt(point(0, 0, 0.02), quaternion(1)));
    const rigidBody b(bodyAt(point(d + 0.1*band, 0, 0.02), quaternion(1)));
    DynamicList<contact> cs;
    cd.pelletPair(0, a, 1, b, cs);
    ASSERT_EQ(cs.size(), 1);
    EXPECT_EQ(cs[0].e, 0.4);
    EXPECT_EQ(cs[0].mu, 0.3);
    EXPECT_NEAR(cs[0].gap, 0.1*band, 1e-15);

    const rigidBody c(bodyAt(point(0, 0, 0.5*d), quaternion(1)));
    cs.clear();
    cd.pelletContainer(2, c, cs);
    ASSERT_EQ(cs.size(), 1);
    EXPECT_EQ(cs[0].k, label(tubeBottom));
    EXPECT_EQ(cs[0].e, 0.2);
    EXPECT_EQ(cs[0].mu, 0.7);

    // Far apart: nothing
    const rigidBody far(bodyAt(point(0.02, 0, 0.05), quaternion(1)));
    cs.clear();
    cd.pelletPair(0, a, 3, far, cs);
    EXPECT_EQ(cs.size(), 0);
}


TEST(contactDispatch, ringMeetsTheContainerUnderEachModel)
{
    // A ring standing on the floor: auto (the exact solid since rings
    // left their meshes) meets the floor by its exact rims, mesh by its
    // triangle mesh; both find the floor, with the tube's material
    const autoPtr<pelletShape> cyl
    (
        shapeOf
        (
            "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
            " faces 300;"
        )
    );
    const tube container(0.05, 0.1, 0.6, 0.1);
    const rigidBody b(bodyAt(point(0, 0, 0.5*d), quaternion(1)));

    for (const word model : {"auto", "mesh"})
    {
        const contactDispatch cd(cyl(), container, 0.5, 0.5, band, model);
        EXPECT_EQ(cd.meshes(), model == "mesh");
        const std::string text(describe(cd));
        EXPECT_EQ
        (
            text.find("exact ring contacts") != std::string::npos,
            model == "auto"
        ) << text;

        DynamicList<contact> cs;
        cd.pelletContainer(0, b, cs);
        ASSERT_GE(cs.size(), 3) << model;
        for (const contact& c : cs)
        {
            EXPECT_EQ(c.k, label(tubeBottom)) << model;
            EXPECT_NEAR(c.gap, 0, 1e-9) << model;
            EXPECT_EQ(c.e, 0.1);
            EXPECT_EQ(c.mu, 0.6);
        }
    }
}


TEST(contactDispatch, tableHasAGeneratorForEachGeometryAndTheContainer)
{
    // The diagonal of the pair table is filled for every geometry, and
    // each dispatch takes the geometry its contactModel names
    for
    (
        const contactDispatch::geometry g :
        {
            contactDispatch::sphereGeometry,
            contactDispatch::meshGeometry,
            contactDispatch::prismGeometry
        }
    )
    {
        const contactDispatch::pairEntry e = contactDispatch::pairOf(g, g);
        EXPECT_NE(e.generate, nullptr) << label(g);
        EXPECT_FALSE(e.reversed) << label(g);
    }

    const autoPtr<pelletShape> cyl
    (
        shapeOf("shape cylinder; diameter 0.01; height 0.01; faces 200;")
    );
    const autoPtr<pelletShape> sphere(shapeOf("shape sphere; diameter 0.01;"));
    const tube container(0.05, 0.1, 0.6, 0.1);
    EXPECT_EQ
    (
        contactDispatch(sphere(), container, 0.5, 0.5, band, "auto")
       .pelletGeometry(),
        contactDispatch::sphereGeometry
    );
    EXPECT_EQ
    (
        contactDispatch(cyl(), container, 0.5, 0.5, band, "auto")
       .pelletGeometry(),
        contactDispatch::prismGeometry
    );
    EXPECT_EQ
    (
        contactDispatch(cyl(), container, 0.5, 0.5, band, "mesh")
       .pelletGeometry(),
        contactDispatch::meshGeometry
    );
    EXPECT_EQ
    (
        contactDispatch(cyl(), container, 0.5, 0.5, band, "exact")
       .pelletGeometry(),
        contactDispatch::prismGeometry
    );
}


TEST(contactDispatch, materialIsSetInOnePlaceForEveryGeometry)
{
    // Two cylinders stacked face on face on the floor, 0.1 band apart,
    // under each contactModel: the generators leave e and mu; the pair's
    // contacts get the pellets' (0.4, 0.3), the floor's the tube's (0.2,
    // 0.7)
    const autoPtr<pelletShape> cyl
    (
        shapeOf("shape cylinder; diameter 0.01; height 0.01; faces 200;")
    );
    const tube container(0.05, 0.1, 0.7, 0.2);
    const rigidBody lower(bodyAt(point(0, 0, 0.5*d), quaternion(1)));
    const rigidBody upper
    (
        bodyAt(point(0, 0, 1.5*d + 0.1*band), quaternion(1))
    );
    for (const word model : {"auto", "mesh", "exact"})
    {
        const contactDispatch cd(cyl(), container, 0.4, 0.3, band, model);
        DynamicList<contact> cs;
        cd.pelletPair(1, upper, 0, lower, cs);
        ASSERT_GE(cs.size(), 3) << model;
        for (const contact& c : cs)
        {
            EXPECT_EQ(c.e, 0.4) << model;
            EXPECT_EQ(c.mu, 0.3) << model;
            EXPECT_GT(c.n.z(), 0.99) << model;
        }
        cs.clear();
        cd.pelletContainer(0, lower, cs);
        ASSERT_GE(cs.size(), 3) << model;
        for (const contact& c : cs)
        {
            EXPECT_EQ(c.e, 0.2) << model;
            EXPECT_EQ(c.mu, 0.7) << model;
        }
    }
}


TEST(contactDispatch, aReversedContactIsTheSameContactSeenFromTheOtherBody)
{
    // The floor-to-pellet contact of a mesh pair, reversed: bodies,
    // normal, its rate, material points and round features exchanged; its
    // gap from the material points is unchanged; reversed twice, the same
    const autoPtr<pelletShape> cyl
    (
        shapeOf("shape cylinder; diameter 0.01; height 0.01; faces 200;")
    );
    const tube container(0.05, 0.1, 0.7, 0.2);
    List<rigidBody> bodies(2);
    bodies[0] = bodyAt(point(0, 0, 0.5*d), quaternion(1));
    bodies[1] = bodyAt
    (
        point(0.001, 0, 1.5*d + 0.1*band),
        quaternion(vector(1, 0, 0), 0.01)
    );
    const contactDispatch cd(cyl(), container, 0.4, 0.3, band, "mesh");
    DynamicList<contact> cs;
    cd.pelletPair(1, bodies[1], 0, bodies[0], cs);
    ASSERT_GE(cs.size(), 1);
    for (contact c : cs)
    {
        c.axisI = vector(0, 0, 1);
        c.rhoI = 0.002;
        const contact r(reversed(c));
        EXPECT_EQ(r.i, c.k);
        EXPECT_EQ(r.k, c.i);
        EXPECT_EQ(r.n, -c.n);
        EXPECT_EQ(r.nDot, -c.nDot);
        EXPECT_EQ(r.ri, c.rk);
        EXPECT_EQ(r.rk, c.ri);
        EXPECT_EQ(r.axisK, c.axisI);
        EXPECT_EQ(r.rhoK, c.rhoI);
        EXPECT_EQ(r.p, c.p);
        EXPECT_EQ(r.e, c.e);
        EXPECT_NEAR
        (
            meshContacts::gap(r, bodies, container),
            meshContacts::gap(c, bodies, container),
            1e-15
        );
        const contact rr(reversed(r));
        EXPECT_EQ(rr.i, c.i);
        EXPECT_EQ(rr.n, c.n);
        EXPECT_EQ(rr.ri, c.ri);
        EXPECT_EQ(rr.axisI, c.axisI);
        EXPECT_EQ(rr.rhoI, c.rhoI);
    }
}

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


TEST(contactDispatch, cylinderMeetsTheContainerByItsHull)
{
    // A cylinder standing on the floor: auto meets the floor by its exact
    // hull (contacts on the rim polygon), mesh by its triangle mesh; both
    // find the floor, with the tube's material
    const autoPtr<pelletShape> cyl
    (
        shapeOf("shape cylinder; diameter 0.01; height 0.01; faces 200;")
    );
    const tube container(0.05, 0.1, 0.6, 0.1);
    const rigidBody b(bodyAt(point(0, 0, 0.5*d), quaternion(1)));

    for (const word model : {"auto", "mesh"})
    {
        const contactDispatch cd(cyl(), container, 0.5, 0.5, band, model);
        EXPECT_TRUE(cd.meshes());
        const std::string text(describe(cd));
        EXPECT_EQ
        (
            text.find("exact cylinder contacts") != std::string::npos,
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

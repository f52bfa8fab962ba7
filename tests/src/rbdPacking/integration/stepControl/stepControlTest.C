// The step length of src/rbdPacking/integration/stepControl (section 7 of
// docs/method.md, eq 38): closed forms of the helpers, and the bounds that
// keep a pair from closing the touching gap unseen

#include <gtest/gtest.h>
#include "stepControl.H"
#include "scalarList.H"
#include "sphereContacts.H"
#include "tube.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar r = 0.005;
    const scalar m = 1.3e-3;
    const vector I(0.4*m*r*r, 0.4*m*r*r, 0.4*m*r*r);
    const scalar g = 9.81;
    const scalar epsP = 1e-3;
    const scalar band = 0.1*r;
    const scalar touch = 1e-5*2*r;
    const scalar tubeRadius = 0.1;
    const scalar hMax = 0.025;

    rigidBody sphereAt(const point& x, const vector& v)
    {
        rigidBody b(m, I, x, quaternion(1), true);
        b.setState(x, quaternion(1), m*v, Zero);
        return b;
    }

    //- The contacts of sphere 0 at b with the wall of the tube of
    //  tubeRadius (not the floor)
    List<contact> wallContacts(const rigidBody& b)
    {
        const tube container(2*tubeRadius, 1, 0.5, 0.5);
        DynamicList<contact> found;
        sphereContacts::sphereTube(0, b, r, container, band, found);
        List<contact> wall;
        for (const contact& c : found)
        {
            if (c.k == tubeWall)
            {
                wall.append(c);
            }
        }
        return wall;
    }

    stepControl control(const bool centreGaps, const bool exactSolids = false)
    {
        return stepControl
        (
            g, epsP, band, touch, r, centreGaps, exactSolids, tubeRadius
        );
    }
}


TEST(stepControl, timeToCoverSolvesTheQuadratic)
{
    // a/2 h^2 + b h = c, also where b^2 >> a c (the stable form)
    for (const scalar a : {0.0, 1.0, 9.81, 1e4})
    {
        for (const scalar b : {0.0, 1e-6, 0.3, 30.0})
        {
            const scalar c = 1e-4;
            const scalar h = stepControl::timeToCover(a, b, c);
            if (a == 0 && b == 0)
            {
                EXPECT_EQ(h, GREAT);
                continue;
            }
            EXPECT_GE(h, 0);
            EXPECT_NEAR(0.5*a*h*h + b*h, c, 1e-12*c)
                << "a " << a << " b " << b;
        }
    }
}


TEST(stepControl, timeToLeaveCircleHitsTheCircle)
{
    const scalar rho = 0.02;
    const point p(0.005, -0.003, 0);
    for (const vector& v : {vector(1, 0, 0), vector(-0.2, 0.7, 0),
                           vector(1e-6, 0, 0), vector(0, -3, 0)})
    {
        const scalar t = stepControl::timeToLeaveCircle(p, v, rho);
        EXPECT_GT(t, 0);
        EXPECT_NEAR(mag(p + v*t), rho, 1e-12);
    }
    EXPECT_EQ(stepControl::timeToLeaveCircle(p, Zero, rho), GREAT);
}


TEST(stepControl, bodiesAtRestFallAtMostTheUnlistedClearance)
{
    // At rest far from everything: an unlisted pair may close lambda + the
    // two bodies' slacks under gravity on both bodies (2g) in free fall,
    // to half the touching gap; nothing else is shorter
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0.01, 0, 0.05), Zero);
    bs[1] = sphereAt(point(0.04, 0, 0.05), Zero);
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs;
    const List<contact> contacts;

    const scalar clearance = 0.5*r;
    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
        scalarList(2, 0.5*clearance)
    );
    EXPECT_DOUBLE_EQ
    (
        h,
        Foam::sqrt(2*(band + clearance - 0.5*touch)/(2*g))
    );

    // With a clearance that takes longer than the outer interval to fall
    EXPECT_EQ
    (
        control(true).choose
        (
            hMax, bs, fixed, awake, pairs, contacts,
            scalarList(2, 0.5)
        ),
        hMax
    );
}


TEST(stepControl, eachBodyCoversItsOwnSlack)
{
    // A pellet falling at 2 m/s with its whole slack (just listed again)
    // beside one at rest with none left: the fast one may cover half of
    // lambda (less half the touching gap) and its own slack; the one at
    // rest limits nothing. The bound of one clearance for the bed (skin
    // - 2 max|x - X| = 0 against twice the fastest) would be far shorter
    const scalar skinHalf = 0.25*r;
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0.01, 0, 0.05), vector(0, 0, -2));
    bs[1] = sphereAt(point(0.04, 0, 0.05), Zero);
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs;
    const List<contact> contacts;
    scalarList slack(2);
    slack[0] = skinHalf;
    slack[1] = 0;

    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts, slack
    );
    const scalar cover = 0.5*(band - 0.5*touch) + skinHalf;
    EXPECT_DOUBLE_EQ(h, stepControl::timeToCover(g, 2, cover));
    // 2 m/s over that distance, gravity helping: a little less than
    // cover/2
    EXPECT_LT(h, cover/2);
    EXPECT_GT(h, 0.9*cover/2);
    EXPECT_GT(h, stepControl::timeToCover(2*g, 4, band - 0.5*touch));
}


TEST(stepControl, approachingListedPairStopsShortOfTouching)
{
    // Two spheres closing head on at 2 m/s, apart by 1 mm (beyond the
    // band): after the step they are still apart, by about half the
    // touching gap (gravity bounded by 2g makes the step shorter)
    const scalar gap0 = 1e-3;
    const scalar u = 2;
    List<rigidBody> bs(2);
    // (off the axis: a mesh pellet on it takes eq 38 for the wall)
    bs[0] = sphereAt(point(0.01, 0, 0.05), vector(0.5*u, 0, 0));
    bs[1] = sphereAt(point(0.01 + 2*r + gap0, 0, 0.05), vector(-0.5*u, 0, 0));
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs({labelPair(0, 1)});
    const List<contact> contacts;

    for (const bool centreGaps : {true, false})
    {
        const scalar h = control(centreGaps).choose
        (
            hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
        );
        const scalar gapAfter = gap0 - u*h;
        EXPECT_GT(gapAfter, 0) << "centreGaps " << centreGaps;
        EXPECT_LE(gapAfter, gap0*1e-2) << "centreGaps " << centreGaps;
    }
}


TEST(stepControl, eq38BoundsAContactWithinTheBand)
{
    // A pair within the band separating sideways at |v_rel| = 3 m/s:
    // h <= 0.2 lambda/|v_rel| (eq 38) for meshes; spheres need no eq 38
    // (their gap is convex in the centres' motion)
    const scalar vRel = 3;
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0, 0, 0.05), vector(0, 0.5*vRel, 0));
    bs[1] = sphereAt(point(2*r + 0.5*band, 0, 0.05), vector(0, -0.5*vRel, 0));
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs({labelPair(0, 1)});

    List<contact> contacts(1);
    ASSERT_TRUE
    (
        sphereContacts::sphereSphere
        (
            0, bs[0], r, 1, bs[1], r, band, contacts[0]
        )
    );

    // Meshes: eq 38
    const scalar hMesh = control(false).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_LE(hMesh, 0.2*band/vRel*(1 + 1e-12));
    EXPECT_GT(hMesh, 0);

    // Spheres: not bounded by eq 38 (only by the unlisted pairs' bound
    // here), and over that step the true gap is at least the linear one
    // the resting solve holds, which is still positive
    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_GT(h, 100*0.2*band/vRel);
    const vector rEnd
    (
        (bs[1].x() + h*bs[1].v()) - (bs[0].x() + h*bs[0].v())
    );
    const scalar linearGap =
        contacts[0].gap - h*((bs[1].v() - bs[0].v()) & contacts[0].n);
    EXPECT_GE(mag(rEnd) - 2*r, linearGap - 1e-15);
    EXPECT_GT(linearGap, 0);
}


TEST(stepControl, aSlowApproachOfSpheresIsLeftToTheRestingSolve)
{
    // Two spheres side by side, 1e-6 m apart (ten touching gaps), closing
    // at 0.9 eps_p: a resting approach. Meshes stop it at half the touching
    // gap; spheres take a longer step, whose end the resting solve holds
    // at a linear gap >= 0 (the true gap is never below it)
    const scalar gap = 10*touch;
    const scalar u = 0.9*epsP;
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0, 0, 0.05), Zero);
    bs[1] = sphereAt(point(2*r + gap, 0, 0.05), vector(-u, 0, 0));
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs({labelPair(0, 1)});
    List<contact> contacts(1);
    ASSERT_TRUE
    (
        sphereContacts::sphereSphere
        (
            0, bs[0], r, 1, bs[1], r, band, contacts[0]
        )
    );
    const scalar untilTouching = (gap - 0.5*touch)/u;
    ASSERT_LT(untilTouching, 0.1*hMax);

    const scalar hMesh = control(false).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_LE(hMesh, untilTouching*(1 + 1e-12));
    EXPECT_GT(hMesh, 0);

    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_GT(h, 10*untilTouching);

    // Faster than eps_p it is a collision: stopped short of touching
    bs[1] = sphereAt(point(2*r + gap, 0, 0.05), vector(-2*epsP, 0, 0));
    const scalar hColliding = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_LE(hColliding, (gap - 0.5*touch)/(2*epsP)*(1 + 1e-12));
}


TEST(stepControl, aSlowApproachOfTheWallStopsShortOfTouching)
{
    // The concave wall keeps the bound for spheres too
    const scalar R = tubeRadius;
    const scalar gap = 10*touch;
    const scalar u = 0.9*epsP;
    List<rigidBody> bs(1);
    bs[0] = sphereAt(point(R - r - gap, 0, 0.05), vector(u, 0, 0));
    const boolList fixed(1, false);
    const labelList awake({0});
    const List<labelPair> pairs;
    const List<contact> contacts(wallContacts(bs[0]));
    ASSERT_EQ(contacts.size(), 1);

    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_LE(h, (contacts[0].gap - 0.5*touch)/u*(1 + 1e-9));
    EXPECT_GT(h, 0);
}


TEST(stepControl, eq38BoundsASphereWithinTheBandOfTheWall)
{
    // The wall is concave: a sphere within its band moving along it keeps
    // eq 38 (its gap closes faster than the linear gap says)
    const scalar R = tubeRadius;
    const scalar v = 3;
    List<rigidBody> bs(1);
    bs[0] = sphereAt(point(R - r - 0.5*band, 0, 0.05), vector(0, v, 0));
    const boolList fixed(1, false);
    const labelList awake({0});
    const List<labelPair> pairs;
    const List<contact> contacts(wallContacts(bs[0]));
    ASSERT_EQ(contacts.size(), 1);

    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_LE(h, 0.2*band/v*(1 + 1e-12));
    EXPECT_GT(h, 0);
}


TEST(stepControl, aSphereOnTheWallMovesLessThanItsCurvatureAllows)
{
    // A sphere at rest on the wall: its neighbours may push it along the
    // wall (up to g), and the concave wall closes the true gap by s^2/(2
    // (R - r)) beyond the linear gap the resting solve holds; the step
    // keeps that within half the touching gap
    const scalar R = tubeRadius;
    List<rigidBody> bs(1);
    bs[0] = sphereAt(point(R - r - 0.5*touch, 0, 0.05), Zero);
    const boolList fixed(1, false);
    const labelList awake({0});
    const List<labelPair> pairs;
    const List<contact> contacts(wallContacts(bs[0]));
    ASSERT_EQ(contacts.size(), 1);

    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    EXPECT_GT(h, 0);
    const scalar s = 0.5*g*sqr(h);
    EXPECT_LE(sqr(s)/(2*(R - r)), 0.5*touch*(1 + 1e-9));
    EXPECT_LT(h, 0.5*hMax);
}


TEST(stepControl, sphereSkimmingTheWallStaysInside)
{
    // A sphere moving along the wall's tangent closes the gap faster than
    // its radial speed says (the wall is concave): the step ends before
    // its centre leaves the circle of touching
    const scalar R = tubeRadius;
    const point x(R - r - 1e-3, 0, 0.05);
    const vector v(0, 1.1, 0);
    List<rigidBody> bs(1);
    bs[0] = sphereAt(x, v);
    const boolList fixed(1, false);
    const labelList awake({0});
    const List<labelPair> pairs;
    const List<contact> contacts;

    const scalar h = control(true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts,
            scalarList(bs.size(), 5*r)
    );
    const point xEnd = x + v*h;
    const scalar rhoEnd = Foam::sqrt(sqr(xEnd.x()) + sqr(xEnd.y()));
    EXPECT_LT(rhoEnd, R - r);
    EXPECT_GT(rhoEnd, R - r - 0.5*touch - 1e-9);
}


TEST(stepControl, aPairWithinTheBandWithoutContactsMayCloseHalfTheBand)
{
    // Exact solids: bounding spheres within the band (0.5 lambda apart)
    // but no contact, i.e. no feature within the band: the surfaces are
    // at least unseenGap lambda apart and may close that to half the
    // touching gap, not only eq 38's 0.2 lambda; with a contact the pair
    // keeps eq 38, and meshes keep it either way
    const scalar vRel = 3;
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0.01, 0, 0.05), vector(0, 0.5*vRel, 0));
    bs[1] = sphereAt
    (
        point(0.01 + 2*r + 0.5*band, 0, 0.05), vector(0, -0.5*vRel, 0)
    );
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs({labelPair(0, 1)});
    const scalarList slack(bs.size(), 5*r);

    const scalar hApart = control(false, true).choose
    (
        hMax, bs, fixed, awake, pairs, List<contact>(), slack
    );
    const scalar hMeshes = control(false, false).choose
    (
        hMax, bs, fixed, awake, pairs, List<contact>(), slack
    );
    EXPECT_LE(hMeshes, 0.2*band/vRel*(1 + 1e-12));
    const scalar closing = stepControl::unseenGap*band - 0.5*touch;
    EXPECT_DOUBLE_EQ(hApart, stepControl::timeToCover(2*g, vRel, closing));
    EXPECT_GT(hApart, 2*0.2*band/vRel);

    List<contact> contacts(1);
    contacts[0].i = 0;
    contacts[0].k = 1;
    contacts[0].n = vector(1, 0, 0);
    contacts[0].gap = 0.5*band;
    const scalar hTouching = control(false, true).choose
    (
        hMax, bs, fixed, awake, pairs, contacts, slack
    );
    EXPECT_LE(hTouching, 0.2*band/vRel*(1 + 1e-12));
}


TEST(stepControl, aSweptPelletIsHeldStillForTheOthers)
{
    // A pellet falling at 6 m/s onto one at rest 2 mm below (beyond the
    // band): unswept, the pair's time to touch bounds the step; swept
    // (pelletSweep), it stands still for the pair and the container, and
    // only its own unlisted pairs' bound is left
    const scalar gap0 = 2e-3;
    List<rigidBody> bs(2);
    bs[0] = sphereAt(point(0.01, 0, 0.05 + 2*r + gap0), vector(0, 0, -6));
    bs[1] = sphereAt(point(0.01, 0, 0.05), Zero);
    const boolList fixed(2, false);
    const labelList awake({0, 1});
    const List<labelPair> pairs({labelPair(0, 1)});
    const List<contact> contacts;
    const scalarList slack(bs.size(), 5*r);

    for (const bool centreGaps : {true, false})
    {
        const scalar h = control(centreGaps).choose
        (
            hMax, bs, fixed, awake, pairs, contacts, slack
        );
        EXPECT_LT(h, gap0/6);

        boolList held(fixed);
        held[0] = true;
        const scalar hSwept = control(centreGaps).choose
        (
            hMax, bs, held, awake, pairs, contacts, slack
        );
        EXPECT_DOUBLE_EQ
        (
            hSwept,
            stepControl::timeToCover(g, 6, 0.5*(band - 0.5*touch) + slack[0])
        ) << "centreGaps " << centreGaps;
        EXPECT_GT(hSwept, 10*h);
    }
}

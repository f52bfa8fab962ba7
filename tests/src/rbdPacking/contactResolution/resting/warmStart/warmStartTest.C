// The resting solve's warm start (src/rbdPacking/contactResolution/resting/
// warmStart): each contact guesses the state of the recorded point of its
// pair at its material point, the pair's flag where none is near

#include <gtest/gtest.h>
#include "warmStart.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar band = 1e-3;

    //- A body at x turned by angle about z
    rigidBody body(const point& x, const scalar angle)
    {
        const scalar I = 1e-6;
        return rigidBody
        (
            1e-3, vector(I, I, I), x,
            quaternion(vector(0, 0, 1), angle), true
        );
    }

    //- A material contact of i with k (k < 0: the container) at p
    contact at
    (
        const label i,
        const label k,
        const point& p,
        const UList<rigidBody>& bodies
    )
    {
        contact c;
        c.i = i;
        c.k = k;
        c.n = vector(0, 0, 1);
        c.p = p;
        c.ri = p - bodies[i].x();
        c.rk = k >= 0 ? p - bodies[k].x() : p;
        return c;
    }

    //- Contacts of body 0 with the floor at the points ps
    List<contact> onFloor
    (
        const UList<rigidBody>& bodies,
        const std::initializer_list<point> ps
    )
    {
        List<contact> cs;
        for (const point& p : ps)
        {
            cs.append(at(0, tubeBottom, p, bodies));
        }
        return cs;
    }
}


TEST(warmStart, aContactTakesTheStateOfItsMaterialPointAfterTheBodyMoved)
{
    // Two points of body 0 on the floor: one carried a force, one not
    List<rigidBody> bodies(1, body(point(0, 0, 0.005), 0));
    const List<contact> contacts
    (
        onFloor(bodies, {point(0.004, 0, 0), point(-0.004, 0, 0)})
    );
    warmStart ws;
    ws.record(bodies, contacts, scalarList({2.0, 0.0}));

    // The body turned by 90 degrees and moved: the same material points
    // are found again, listed the other way round
    bodies[0] = body(point(0.001, 0.002, 0.005), 0.5*M_PI);
    const List<contact> next
    (
        onFloor
        (
            bodies,
            {point(0.001, 0.002 - 0.004, 0), point(0.001, 0.002 + 0.004, 0)}
        )
    );
    ws.match(bodies, next, band);
    EXPECT_FALSE(ws.guess(0, next[0], true));
    EXPECT_TRUE(ws.guess(1, next[1], false));

    // The pair's flag alone says active for both
    EXPECT_TRUE(ws.guess(next[0], false));
    EXPECT_TRUE(ws.guess(next[1], false));
}


TEST(warmStart, aPointFartherThanTheReachTakesThePairFlag)
{
    List<rigidBody> bodies(1, body(point(0, 0, 0.005), 0));
    warmStart ws;

    // Another point of the same pair, beyond matchFraction band of the
    // recorded one, and one just within it
    const scalar reach = warmStart::matchFraction*band;
    const List<contact> next
    (
        onFloor
        (
            bodies,
            {point(0.004 - 1.5*reach, 0, 0), point(0.004 - 0.5*reach, 0, 0)}
        )
    );

    // The point recorded inactive; the pair active through a second, far
    // point that carried a force
    ws.record
    (
        bodies, onFloor(bodies, {point(0.004, 0, 0), point(-0.004, 0, 0)}),
        scalarList({0.0, 1.0})
    );
    ws.match(bodies, next, band);
    EXPECT_TRUE(ws.guess(0, next[0], false));   // no point near: the pair
    EXPECT_FALSE(ws.guess(1, next[1], true));   // its point: inactive
}


TEST(warmStart, aPairListedTheOtherWayRoundMatchesThroughTheOtherBody)
{
    // Turned differently: the point on body 1 must be taken in body 1's
    // frame
    List<rigidBody> bodies(2);
    bodies[0] = body(point(0, 0, 0.005), 0.7);
    bodies[1] = body(point(0, 0, 0.015), -0.4);
    List<contact> contacts(2);
    contacts[0] = at(1, 0, point(0.003, 0, 0.010), bodies);
    contacts[1] = at(1, 0, point(-0.003, 0, 0.010), bodies);
    warmStart ws;
    ws.record(bodies, contacts, scalarList({0.0, 3.0}));

    // The same points with i and k exchanged (the sleeping body second)
    List<contact> next(2);
    next[0] = reversed(contacts[0]);
    next[1] = reversed(contacts[1]);
    ws.match(bodies, next, band);
    EXPECT_FALSE(ws.guess(0, next[0], true));
    EXPECT_TRUE(ws.guess(1, next[1], false));
}


TEST(warmStart, theStateRoundTripsThroughEntriesAndPoints)
{
    List<rigidBody> bodies(1, body(point(0, 0, 0.005), 0));
    const List<contact> contacts
    (
        onFloor(bodies, {point(0.004, 0, 0), point(-0.004, 0, 0)})
    );
    warmStart ws;
    ws.record(bodies, contacts, scalarList({2.0, 0.0}));

    warmStart copy;
    copy.set(ws.entries(), ws.points());
    ws.match(bodies, contacts, band);
    copy.match(bodies, contacts, band);
    for (label ci = 0; ci < 2; ++ci)
    {
        EXPECT_EQ
        (
            ws.guess(ci, contacts[ci], ci == 0),
            copy.guess(ci, contacts[ci], ci == 0)
        );
    }
    EXPECT_TRUE(copy.guess(0, contacts[0], false));
    EXPECT_FALSE(copy.guess(1, contacts[1], true));
}


TEST(warmStart, aLaterPassOfTheSameSolveStartsFromEachContactsOwnAnswer)
{
    // The last step recorded two points of body 0 on the floor
    List<rigidBody> bodies(1, body(point(0, 0, 0.005), 0));
    warmStart ws;
    ws.record
    (
        bodies, onFloor(bodies, {point(0.004, 0, 0), point(-0.004, 0, 0)}),
        scalarList({0.0, 0.0})
    );

    // This step lists a new point first, then the two again
    const List<contact> contacts
    (
        onFloor
        (
            bodies,
            {point(0, 0.004, 0), point(0.004, 0, 0), point(-0.004, 0, 0)}
        )
    );
    ws.match(bodies, contacts, band);

    // Pass 1 recorded its answer (only the new point carries a force);
    // pass 2 (the staggered friction's) asks again without a new match:
    // each contact gets its own state, not that of the point the last
    // step's match pointed at
    ws.record(bodies, contacts, scalarList({5.0, 0.0, 0.0}));
    EXPECT_TRUE(ws.guess(0, contacts[0], false));
    EXPECT_FALSE(ws.guess(1, contacts[1], true));
    EXPECT_FALSE(ws.guess(2, contacts[2], true));
}

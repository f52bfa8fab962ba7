// Unit tests for src/rbdPacking/narrowPhase/floorSupport: which points near
// the floor are listed besides the corners the reductions keep. The
// settling they buy is asserted by the stability suite (stabilityMesh.
// cylinderOntoFloor, cylinderOntoACylinder.rimOnRim: a cylinder wobbling
// on its face, and one spinning on its rim, come to rest)

#include <gtest/gtest.h>
#include "floorSupport.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    //- A floor contact of a point at body offset ri with the given gap
    contact at(const vector& ri, const scalar gap)
    {
        contact c;
        c.i = 0;
        c.k = tubeBottom;
        c.n = vector(0, 0, 1);
        c.ri = ri;
        c.p = point(ri.x(), ri.y(), 0.5*gap);
        c.gap = gap;
        return c;
    }

    //- The points of a polygonal rim of n vertices (radius a [m]) tilted
    //  by tilt [rad] about x, lowest at angle -pi/2 (gap 0 there)
    std::vector<contact> tiltedRim(const label n, const scalar a, const scalar tilt)
    {
        std::vector<contact> cs;
        for (label k = 0; k < n; ++k)
        {
            const scalar t = 2*M_PI*k/n;
            const vector ri(a*Foam::cos(t), a*Foam::sin(t), 0);
            cs.push_back(at(ri, (ri.y() + a)*Foam::sin(tilt)));
        }
        return cs;
    }
}


TEST(floorSupport, addsTheNextLowestPointsWithinTheSpan)
{
    // A rim of 32 vertices tilted by 2 deg: the vertices next to the
    // lowest (k = 24) are added, lowest first, none beyond the span
    const scalar a = 0.005;
    const std::vector<contact> rim(tiltedRim(32, a, 2*M_PI/180));
    DynamicList<contact> contacts;
    contacts.append(rim[24]);
    const scalar span = 2e-5;
    floorSupport::addNear(rim, span, 1e-9, 0, contacts);

    ASSERT_GE(contacts.size(), 3);
    for (label ci = 1; ci < contacts.size(); ++ci)
    {
        EXPECT_LE(contacts[ci].gap, span) << ci;
        EXPECT_GE(contacts[ci].gap, contacts[ci - 1].gap - 1e-15) << ci;
    }
    // Both neighbours of the lowest are there
    for (const label k : {23, 25})
    {
        bool found = false;
        for (const contact& c : contacts)
        {
            found = found || mag(c.ri - rim[k].ri) < 1e-12;
        }
        EXPECT_TRUE(found) << k;
    }
    // Every vertex within the span is listed (fewer than nLowest here),
    // and no point twice
    label within = 0;
    for (const contact& c : rim)
    {
        within += c.gap <= span;
    }
    EXPECT_EQ(contacts.size(), within);
}


TEST(floorSupport, aFaceLyingFlatAddsNone)
{
    // Every vertex at the same gap (to within flatSpread of the span): the
    // corners hold the face
    const std::vector<contact> rim(tiltedRim(64, 0.005, 0));
    DynamicList<contact> contacts;
    contacts.append(rim[0]);
    floorSupport::addNear(rim, 1e-4, 1e-9, 0, contacts);
    EXPECT_EQ(contacts.size(), 1);
}


TEST(floorSupport, atMostNLowestAndNotTwice)
{
    // A face tilted by 0.5 deg: more than nLowest vertices within the
    // span; the listed ones are not added again
    const std::vector<contact> rim(tiltedRim(64, 0.005, 0.5*M_PI/180));
    DynamicList<contact> contacts;
    contacts.append(rim[48]);
    contacts.append(rim[16]);
    floorSupport::addNear(rim, 1e-4, 1e-9, 0, contacts);
    EXPECT_EQ(contacts.size(), 2 + floorSupport::nLowest);
    for (label x = 0; x < contacts.size(); ++x)
    {
        for (label y = x + 1; y < contacts.size(); ++y)
        {
            EXPECT_GT(mag(contacts[x].ri - contacts[y].ri), 1e-9);
        }
    }

    // Contacts before start are another pellet's: not compared
    DynamicList<contact> other;
    other.append(rim[1]);
    floorSupport::addNear(rim, 1e-4, 1e-9, 1, other);
    EXPECT_EQ(other.size(), 1 + floorSupport::nLowest);
}


TEST(floorSupport, nothingFarAboveTheLowest)
{
    // A rim tilted by 30 deg: only the lowest vertex lies within a span
    // smaller than its neighbours' rise
    const std::vector<contact> rim(tiltedRim(16, 0.005, M_PI/6));
    DynamicList<contact> contacts;
    contacts.append(rim[12]);
    floorSupport::addNear(rim, 1e-6, 1e-9, 0, contacts);
    EXPECT_EQ(contacts.size(), 1);

    // With a span that reaches the neighbours, those two
    floorSupport::addNear(rim, 3e-4, 1e-9, 0, contacts);
    ASSERT_EQ(contacts.size(), 3);
    for (const label k : {11, 13})
    {
        bool found = false;
        for (const contact& c : contacts)
        {
            found = found || mag(c.ri - rim[k].ri) < 1e-12;
        }
        EXPECT_TRUE(found) << k;
    }
}


// ************************************************************************* //

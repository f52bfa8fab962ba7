// The reduction of a pair's contacts (src/rbdPacking/narrowPhase/
// contactReduction): a flat patch to its deepest point and its corners,
// one group per normal; the tiers of gap keep what touches next and drop
// what no step can bring to touch; near the deepest point, the points of a
// curved support are kept, those between kept ones at or above their gap
// are not.

#include <gtest/gtest.h>
#include "contactReduction.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    contact at(const point& p, const scalar gap, const vector& n)
    {
        contact c;
        c.n = n;
        c.p = p;
        c.gap = gap;
        return c;
    }

    const vector ez(0, 0, 1);
}


TEST(contactReduction, keepsTheDeepestAndTheCornersOfAPatch)
{
    // A 5 x 5 grid of contacts on a plane, the corner (0, 0) deepest, and
    // one contact with another normal
    DynamicList<contact> cs;
    cs.append(at(point(0, 0, 1), 0, vector(1, 0, 0)));
    for (label i = 0; i < 5; ++i)
    {
        for (label j = 0; j < 5; ++j)
        {
            cs.append
            (
                at
                (
                    point(i, j, 0),
                    (i == 0 && j == 0) ? -1 : 0.01*(i + j),
                    ez
                )
            );
        }
    }
    contactReduction::reduce(cs, 0, 1e-6, 0);

    // The other normal is its own group
    ASSERT_EQ(cs.size(), 4 + 1);
    label corners = 0;
    label others = 0;
    scalar minGap = GREAT;
    for (const contact& c : cs)
    {
        if (c.n == vector(1, 0, 0))
        {
            ++others;
            continue;
        }
        const point& p = c.p;
        corners +=
            (p.x() == 0 || p.x() == 4) && (p.y() == 0 || p.y() == 4);
        minGap = min(minGap, c.gap);
    }
    EXPECT_EQ(others, 1);
    EXPECT_EQ(corners, 4);
    EXPECT_EQ(minGap, -1);
}


TEST(contactReduction, tiersKeepWhatTouchesNextAndDropWhatCannot)
{
    // A tilted square patch: the gaps rise along x by 0.15 tier per unit,
    // x = 0..9; tier 1. Tiers [0, 1), [1, 2), [2, 3) are kept (each to its
    // corners), the points 3 tiers or more above the deepest are dropped
    const scalar tier = 1;
    DynamicList<contact> cs;
    // Contacts before start are left alone
    cs.append(at(point(0, 0, 5), -7, ez));
    for (label i = 0; i < 10; ++i)
    {
        for (label j = 0; j < 4; ++j)
        {
            cs.append(at(point(i, j, 0), 0.35*tier*i + 1e-3*j, ez));
        }
    }
    contactReduction::reduce(cs, 1, 1e-6, tier);

    EXPECT_EQ(cs[0].gap, -7);
    ASSERT_GT(cs.size(), 1);
    scalar highest = -GREAT;
    label inFirstTier = 0;
    for (label a = 1; a < cs.size(); ++a)
    {
        highest = max(highest, cs[a].gap);
        inFirstTier += cs[a].gap < tier;
    }
    // Beyond contactReduction::nTiers tiers: dropped
    EXPECT_LT(highest, contactReduction::nTiers*tier);
    // The first tier (x = 0..2) holds the deepest and three more corners
    EXPECT_EQ(inFirstTier, 4);
    // At most four per tier
    EXPECT_LE(cs.size() - 1, 4*contactReduction::nTiers);
    // The deepest point is kept
    EXPECT_EQ(cs[1].gap, 0);
}


TEST(contactReduction, keepsTheNextPointsOfACurvedSupportButNotThoseBetween)
{
    // A polygonal rim on a plane, seen from the side: points on a circle
    // of radius 1 about (0, 0, 1), the lowest at x = 0 touching; the next
    // ones are within a fifth of the tier of it and are kept besides the
    // corners (they touch next as the rim rolls)
    const scalar tier = 0.1;
    DynamicList<contact> rim;
    for (label a = -3; a <= 3; ++a)
    {
        const scalar phi = 0.1*a;
        rim.append
        (
            at(point(Foam::sin(phi), 0, 0), 1 - Foam::cos(phi), ez)
        );
    }
    DynamicList<contact> cs(rim);
    contactReduction::reduce(cs, 0, 1e-9, tier);
    // Those within a fifth of the tier of the lowest (|a| <= 2: 1 - cos(0.2)
    // = 0.0199 < 0.02) are all kept, though only the lowest and the
    // farthest from it are corners (the rim seen from the side is a line)
    EXPECT_LT(cs.size(), rim.size());
    for (const contact& r : rim)
    {
        if (r.gap >= 0.2*tier)
        {
            continue;
        }
        bool kept = false;
        for (const contact& c : cs)
        {
            kept = kept || c.p == r.p;
        }
        EXPECT_TRUE(kept) << "rim point at x = " << r.p.x();
    }

    // A straight line of support, all touching: only its ends carry
    // force, the points between them are covered
    DynamicList<contact> line;
    for (label a = 0; a <= 6; ++a)
    {
        line.append(at(point(a, 0, 0), 0, ez));
    }
    contactReduction::reduce(line, 0, 1e-9, tier);
    ASSERT_EQ(line.size(), 2);
    EXPECT_EQ(min(line[0].p.x(), line[1].p.x()), 0);
    EXPECT_EQ(max(line[0].p.x(), line[1].p.x()), 6);
}

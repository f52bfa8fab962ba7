// Unit tests for src/rbdPacking/restart/stateIO: what the writer puts the
// reader gets back, to the bit (the checkpoint's promise)

#include <gtest/gtest.h>
#include "stateIO.H"
#include "point.H"

#include <cstring>
#include <limits>
#include <sstream>

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    bool sameBits(const scalar a, const scalar b)
    {
        return std::memcmp(&a, &b, sizeof(scalar)) == 0;
    }
}


TEST(stateIO, roundTripIsExact)
{
    // Values a decimal text form would round or lose: 0.1, 1/3, -0,
    // the smallest subnormal, the largest double
    const List<scalar> scalars
    ({
        0.1, 1.0/3.0, -0.0, std::numeric_limits<scalar>::denorm_min(),
        std::numeric_limits<scalar>::max(), -2.5e-300
    });
    const vector v(1.0/3.0, -0.0, 1e-310);
    const tensor t(0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 1.0/7.0);
    const quaternion q(std::cos(0.1), vector(std::sin(0.1)/3.0, 0, -0.5));
    const List<labelPair> pairs({labelPair(0, 7), labelPair(-1, labelMax)});
    const boolList flags({true, false, true});
    const std::string text("mt19937_64 state\n0 1 2");

    std::stringstream ss;
    stateWriter out(ss);
    out.putList(scalars).put(v).put(t).put(q).putList(pairs)
       .putList(flags).put(text).put(label(-42)).put(std::uint64_t(1) << 63);
    ASSERT_TRUE(out.good());

    List<scalar> scalars2;
    vector v2;
    tensor t2;
    quaternion q2;
    List<labelPair> pairs2;
    boolList flags2;
    std::string text2;
    label l2 = 0;
    std::uint64_t u2 = 0;
    stateReader in(ss, "test");
    in.getList(scalars2).get(v2).get(t2).get(q2).getList(pairs2)
      .getList(flags2).get(text2).get(l2).get(u2);

    ASSERT_EQ(scalars2.size(), scalars.size());
    forAll(scalars, i)
    {
        EXPECT_TRUE(sameBits(scalars[i], scalars2[i])) << "entry " << i;
    }
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        EXPECT_TRUE(sameBits(v[d], v2[d]));
    }
    for (direction d = 0; d < tensor::nComponents; ++d)
    {
        EXPECT_TRUE(sameBits(t[d], t2[d]));
    }
    EXPECT_TRUE(sameBits(q.w(), q2.w()));
    EXPECT_TRUE(sameBits(q.v().x(), q2.v().x()));
    EXPECT_TRUE(sameBits(q.v().z(), q2.v().z()));
    EXPECT_EQ(pairs2, pairs);
    EXPECT_EQ(flags2, flags);
    EXPECT_EQ(text2, text);
    EXPECT_EQ(l2, -42);
    EXPECT_EQ(u2, std::uint64_t(1) << 63);

    // Everything was read: the stream is at its end
    char c;
    EXPECT_FALSE(ss.read(&c, 1));
}


TEST(stateIO, dynamicListsReadBackWhole)
{
    DynamicList<point> a;
    for (label i = 0; i < 100; ++i)
    {
        a.append(point(i, -i, 0.1*i));
    }
    std::stringstream ss;
    stateWriter(ss).putList(a);

    DynamicList<point> b(3);
    b.append(point::one);
    stateReader(ss, "test").getList(b);
    ASSERT_EQ(b.size(), a.size());
    EXPECT_EQ(List<point>(b), List<point>(a));
}

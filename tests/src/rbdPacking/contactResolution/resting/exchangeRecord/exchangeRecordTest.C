// The record of how the block exchanges of large islands fared
// (src/rbdPacking/contactResolution/resting/exchangeRecord): tried while
// they converge often enough, skipped with a probe every probeInterval
// solves while they do not

#include <gtest/gtest.h>
#include "exchangeRecord.H"

using namespace Foam;
using namespace Foam::rbd;

TEST(exchangeRecord, triesWhileTheExchangesConverge)
{
    exchangeRecord r;
    for (label k = 0; k < 100; ++k)
    {
        ASSERT_TRUE(r.tryExchanges()) << k;
        // Two of three converge: above the break-even share
        r.record(k % 3 != 0);
    }
    EXPECT_GT(r.share(), exchangeRecord::breakEven);
}


TEST(exchangeRecord, skipsCyclingExchangesAndProbesThem)
{
    // Every try cycles: after a few the share falls below the break-even
    // and the solves go to the interior point alone, but for one try in
    // probeInterval
    exchangeRecord r;
    label tries = 0;
    label firstSkip = -1;
    const label solves = 400;
    for (label k = 0; k < solves; ++k)
    {
        if (r.tryExchanges())
        {
            ++tries;
            r.record(false);
        }
        else if (firstSkip < 0)
        {
            firstSkip = k;
        }
    }
    // (1 - 1/memory)^k < breakEven from k = 10 on
    EXPECT_EQ(firstSkip, 10);
    EXPECT_NEAR
    (
        scalar(tries), 10 + (solves - 10)/exchangeRecord::probeInterval, 1
    );
    EXPECT_LT(r.share(), exchangeRecord::breakEven);
}


TEST(exchangeRecord, followsABedWhoseExchangesStartConverging)
{
    // Skipping, then every probe converges: the share climbs back above
    // the break-even and every solve tries again
    exchangeRecord r;
    for (label k = 0; k < 50; ++k)
    {
        if (r.tryExchanges())
        {
            r.record(false);
        }
    }
    ASSERT_LT(r.share(), exchangeRecord::breakEven);
    label probes = 0;
    while (r.share() < exchangeRecord::breakEven)
    {
        if (r.tryExchanges())
        {
            ++probes;
            r.record(true);
        }
        ASSERT_LT(probes, 10);
    }
    for (label k = 0; k < 20; ++k)
    {
        EXPECT_TRUE(r.tryExchanges()) << k;
        r.record(true);
    }
}


TEST(exchangeRecord, itsStateGivesTheSameDecisions)
{
    // As a checkpoint restores it (share(), skipped(), set()): the same
    // decisions from there on
    exchangeRecord a;
    for (label k = 0; k < 37; ++k)
    {
        if (a.tryExchanges())
        {
            a.record(k % 5 == 0);
        }
    }
    exchangeRecord b;
    b.set(a.share(), a.skipped());
    for (label k = 0; k < 100; ++k)
    {
        const bool ta = a.tryExchanges();
        ASSERT_EQ(ta, b.tryExchanges()) << k;
        if (ta)
        {
            a.record(k % 7 == 0);
            b.record(k % 7 == 0);
        }
    }
    EXPECT_EQ(a.share(), b.share());
}

// Unit tests for src/rbdPacking/contactResolution/lcp/lcpActiveSet:
// activeSetUpdate, the candidate of an active set from the factor of
// another (Schur complement), against a factorisation of the set itself

#include <gtest/gtest.h>
#include "rbdPacking/contactResolution/lcp/lcpTestProblems.H"
#include "lcpActiveSet.H"
#include "blockPivotingLCP.H"
#include "rbdPacking/contactResolution/lcp/enumerationLCP/enumerationLCP.H"

using namespace Foam;
using namespace lcpTest;

namespace
{

// members (ascending) and pos of the set flagged by inF
void setOf
(
    const std::vector<bool>& inF,
    std::vector<label>& members,
    std::vector<label>& pos
)
{
    members.clear();
    pos.assign(inF.size(), -1);
    for (size_t i = 0; i < inF.size(); ++i)
    {
        if (inF[i])
        {
            pos[i] = members.size();
            members.push_back(i);
        }
    }
}

} // End anonymous namespace


TEST(activeSetUpdate, matchesTheFactorisationOfTheSet)
{
    // Heaps with more contacts than degrees of freedom (singular A,
    // regularised by eps as the block pivoting does): sets that differ
    // from a base of about 40 contacts by up to 4 joining and leaving
    rng gen(2033);
    int compared = 0;
    for (int trial = 0; trial < 60; ++trial)
    {
        const int nBodies = 10 + trial % 4;
        const int m = 6*nBodies + 4;
        const heap h = randomHeap(gen, nBodies, m, trial % 2 ? 1e-5 : 0);
        const Eigen::SparseMatrix<double> A(h.p.A.sparseView());
        const double eps = 1e-10*A.diagonal().maxCoeff();
        const Vec r(-h.p.b);

        std::vector<bool> inF0(m), inF(m);
        for (int i = 0; i < m; ++i)
        {
            inF0[i] = uniform(gen, 0, 1) < 0.6;
        }
        inF = inF0;
        const int changes = 1 + trial % 4;
        for (int c = 0; c < changes; ++c)
        {
            const int i = uniformInt(gen, 0, m - 1);
            inF[i] = !inF[i];
        }

        std::vector<label> base, basePos, members, pos;
        setOf(inF0, base, basePos);
        setOf(inF, members, pos);
        if (base.empty() || members.empty())
        {
            continue;
        }

        // The base factorised, as blockPivotingLCP keeps it
        rbd::activeSetFactor fac;
        Vec z0;
        ASSERT_TRUE
        (
            rbd::solveActiveSet
            (
                A, nullptr, base, basePos, eps, r, fac.ldlt, fac.system, z0
            )
        );
        fac.set(base, eps);

        // The set by its own factorisation, and by the update
        rbd::activeSetSystem system;
        rbd::preorderedLDLT ldlt;
        Vec zDirect, zUpdate;
        ASSERT_TRUE
        (
            rbd::solveActiveSet
            (
                A, nullptr, members, pos, eps, r, ldlt, system, zDirect
            )
        );
        const bool updated =
            fac.update.solve(A, base, fac.ldlt, pos, eps, 64, r, zUpdate);
        if (trial % 2 == 0 && !updated)
        {
            // No compliance: A_FF + eps I may be too ill-conditioned for
            // the border; the update declines (its residual check)
            continue;
        }
        ASSERT_TRUE(updated) << trial;
        ++compared;

        // The same residual on F (both solve A_FF z_F = r_F, refined) and
        // zero off F
        const Vec wDirect(A*zDirect - r), wUpdate(A*zUpdate - r);
        double scale = r.cwiseAbs().maxCoeff();
        double resD = 0, resU = 0;
        for (int i = 0; i < m; ++i)
        {
            if (inF[i])
            {
                resD = std::max(resD, std::abs(wDirect(i)));
                resU = std::max(resU, std::abs(wUpdate(i)));
            }
            else
            {
                EXPECT_EQ(zUpdate(i), 0) << trial << " " << i;
            }
        }
        EXPECT_LE(resU, std::max(10*resD, 1e-9*scale)) << trial;
        if (trial % 2 == 0)
        {
            // No compliance: A_FF may be singular, z_F then not unique;
            // with compliance it is
            continue;
        }
        EXPECT_LE
        (
            (zUpdate - zDirect).cwiseAbs().maxCoeff(),
            1e-6*zDirect.cwiseAbs().maxCoeff()
        ) << trial;
    }
    // Every compliant heap and some singular ones were compared
    EXPECT_GE(compared, 30);
}


TEST(activeSetUpdate, refusesLargeChangesAndMissingBases)
{
    rng gen(7);
    const heap h = randomHeap(gen, 9, 60, 1e-5);
    const Eigen::SparseMatrix<double> A(h.p.A.sparseView());
    const double eps = 1e-10*A.diagonal().maxCoeff();
    const Vec r(-h.p.b);
    const int m = 60;

    std::vector<bool> inF0(m, true), inF(m, true);
    for (int i = 0; i < 5; ++i)
    {
        inF[i] = false;
    }
    std::vector<label> base, basePos, members, pos;
    setOf(inF0, base, basePos);
    setOf(inF, members, pos);

    rbd::activeSetFactor fac;
    Vec z;

    // No base yet
    EXPECT_FALSE(fac.update.solve(A, base, fac.ldlt, pos, eps, 64, r, z));

    ASSERT_TRUE
    (
        rbd::solveActiveSet
        (
            A, nullptr, base, basePos, eps, r, fac.ldlt, fac.system, z
        )
    );
    fac.set(base, eps);

    // Five contacts left a base of 60: refused above a border of 4
    EXPECT_FALSE(fac.update.solve(A, base, fac.ldlt, pos, eps, 4, r, z));
    EXPECT_TRUE(fac.update.solve(A, base, fac.ldlt, pos, eps, 5, r, z));

    // Ten: more than one per minBasePerChange (8) of the base's 60
    for (int i = 5; i < 10; ++i)
    {
        inF[i] = false;
    }
    setOf(inF, members, pos);
    EXPECT_FALSE(fac.update.solve(A, base, fac.ldlt, pos, eps, 64, r, z));

    // invalidate() forgets the base
    fac.invalidate();
    EXPECT_FALSE(fac.update.solve(A, base, fac.ldlt, pos, eps, 64, r, z));
}


TEST(activeSetUpdate, blockPivotingSolvesTheSameWithAndWithoutUpdates)
{
    // The block exchanges alone (no interior point, no baraff) on heaps
    // of 64-82 contacts with compliance (z_F unique), from the empty
    // guess: the exchanges with candidates from updates (maxUpdate 16)
    // end where those with a factorisation each (maxUpdate 0) end, up to
    // round-off, which shows where the updates ran
    const char* pure =
        "interiorPointIterations 0; fallbackSize 0; maxIterations 100;";
    const rbd::blockPivotingLCP updating
    (
        parse(std::string("maxUpdate 16; ") + pure)
    );
    const rbd::blockPivotingLCP factorising
    (
        parse(std::string("maxUpdate 0; ") + pure)
    );
    rng gen(1990);
    int compared = 0, differed = 0;
    for (int trial = 0; trial < 40; ++trial)
    {
        const int nBodies = 10 + trial % 4;
        const heap h = randomHeap(gen, nBodies, 6*nBodies + 4, 1e-5);
        const Eigen::SparseMatrix<double> A(h.p.A.sparseView());
        Vec fU, fF;
        const rbd::lcpResult rF =
            factorising.solve(A, h.p.b, std::vector<bool>(), fF);
        if (!rF.converged)
        {
            // The exchanges cycled: not this test's subject
            continue;
        }
        const rbd::lcpResult rU =
            updating.solve(A, h.p.b, std::vector<bool>(), fU);
        EXPECT_TRUE(rU.converged) << trial;
        EXPECT_LE(rU.maxViolation, 1e-9) << trial;
        EXPECT_LE
        (
            (w(h.p, fU) - w(h.p, fF)).cwiseAbs().maxCoeff(),
            1e-7*wScale(h.p, fF)
        ) << trial;
        EXPECT_LE
        (
            (fU - fF).cwiseAbs().maxCoeff(), 1e-6*fF.cwiseAbs().maxCoeff()
        ) << trial;
        ++compared;
        differed += !(fU.array() == fF.array()).all();
    }
    EXPECT_GE(compared, 20);
    // The updates ran (their candidates differ from a factorisation's in
    // the last bits) on some of the heaps
    EXPECT_GE(differed, 5);
}

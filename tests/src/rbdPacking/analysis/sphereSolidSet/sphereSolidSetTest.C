// Unit tests for src/rbdPacking/analysis/sphereSolidSet: slab volumes and
// cylinder areas of one sphere against closed forms (caps, on-axis chord,
// elliptic integrals) and a brute-force quadrature; contact counts against
// an O(n^2) reference

#include <gtest/gtest.h>
#include "sphereSolidSet.H"
#include "mathematicalConstants.H"

#include <cmath>
#include <random>

using namespace Foam;

namespace
{
    const scalar pi = constant::mathematical::pi;

    rbd::sphereSolidSet oneSphere(const point& c, const scalar a)
    {
        return rbd::sphereSolidSet(List<point>({c}), a);
    }

    //- S_int without clipping in closed form (elliptic integrals)
    scalar areaElliptic(const scalar a, const scalar r, const scalar rho)
    {
        const scalar hMax2 = a*a - (r - rho)*(r - rho);
        if (hMax2 <= 0)
        {
            return 0;
        }
        const scalar k2 = 4*r*rho/hMax2;
        if (k2 == 0)
        {
            return 4*pi*r*std::sqrt(hMax2);
        }
        const scalar k = std::sqrt(k2);
        const scalar E =
            k <= 1
          ? std::comp_ellint_2(k)
          : k*std::comp_ellint_2(1/k) - (k - 1/k)*std::comp_ellint_1(1/k);
        return 8*r*std::sqrt(hMax2)*E;
    }

    //- S_int by the midpoint rule in the azimuth on the clipped chord
    //  (slow, obviously right; error ~ n^-1.5 at the arc ends)
    scalar areaBruteForce
    (
        const scalar a,
        const scalar r,
        const point& c,
        const scalar zLow,
        const scalar zHigh,
        const int n
    )
    {
        scalar sum = 0;
        for (int i = 0; i < n; ++i)
        {
            const scalar theta = 2*pi*(i + 0.5)/n;
            const scalar dx = r*std::cos(theta) - c.x();
            const scalar dy = r*std::sin(theta) - c.y();
            const scalar h2 = a*a - dx*dx - dy*dy;
            if (h2 > 0)
            {
                const scalar h = std::sqrt(h2);
                const scalar top = std::min(c.z() + h, zHigh);
                const scalar bottom = std::max(c.z() - h, zLow);
                sum += std::max(top - bottom, scalar(0));
            }
        }
        return sum*r*2*pi/n;
    }

    //- Integral of f over [lo, hi] by composite 5-point Gauss-Legendre
    template<class F>
    scalar integrate(const F& f, const scalar lo, const scalar hi, int panels)
    {
        static const scalar x[5] =
        {
            0, -0.5384693101056831, 0.5384693101056831,
            -0.9061798459386640, 0.9061798459386640
        };
        static const scalar w[5] =
        {
            0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
            0.2369268850561891, 0.2369268850561891
        };
        const scalar h = (hi - lo)/panels;
        scalar sum = 0;
        for (int p = 0; p < panels; ++p)
        {
            const scalar mid = lo + (p + 0.5)*h;
            for (int i = 0; i < 5; ++i)
            {
                sum += 0.5*h*w[i]*f(mid + 0.5*h*x[i]);
            }
        }
        return sum;
    }
}


TEST(sphereSolidSet, slabVolumeOfWholeSphereAndCaps)
{
    const scalar a = 0.005;
    const rbd::sphereSolidSet s(oneSphere(point(0.001, -0.002, 0.02), a));
    const scalar V = 4.0/3.0*pi*a*a*a;

    EXPECT_NEAR(s.volume(0, 0, 0.1), V, 1e-12*V);
    EXPECT_EQ(s.volume(0, 0.03, 0.1), 0);

    // Cap of height h = a/2 above z = cz + a/2: pi h^2 (3a - h)/3
    const scalar h = 0.5*a;
    const scalar cap = pi*h*h*(3*a - h)/3;
    EXPECT_NEAR(s.volume(0, 0, 0.02 + 0.5*a), V - cap, 1e-12*V);
    EXPECT_NEAR(s.volume(0, 0.02 - 0.5*a, 0.1), V - cap, 1e-12*V);
    EXPECT_NEAR(s.volume(0, 0.02, 0.1), 0.5*V, 1e-12*V);
}

TEST(sphereSolidSet, extents)
{
    const rbd::sphereSolidSet s
    (
        List<point>({point(3, 4, 10), point(0.2, 0, 1)}),
        1
    );
    EXPECT_NEAR(s.radialExtent(0).min(), 4, 1e-14);
    EXPECT_NEAR(s.radialExtent(0).max(), 6, 1e-14);
    EXPECT_EQ(s.radialExtent(1).min(), 0);
    EXPECT_NEAR(s.axialExtent(0).min(), 9, 1e-14);
    EXPECT_NEAR(s.axialExtent(0).max(), 11, 1e-14);
}

TEST(sphereSolidSet, cylinderAreaOnAxis)
{
    // Chord 2 sqrt(a^2 - r^2) all around the circle
    const scalar a = 1;
    const rbd::sphereSolidSet s(oneSphere(point(0, 0, 2), a));
    for (const scalar r : {1e-6, 0.1, 0.5, 0.9, 0.999999})
    {
        const scalar exact = 2*pi*r*2*std::sqrt(a*a - r*r);
        EXPECT_NEAR(s.cylinderArea(0, r, 0, 4), exact, 1e-13*4*pi*r) << r;
        // Clipped at the centre plane: half of it
        EXPECT_NEAR(s.cylinderArea(0, r, 2, 4), 0.5*exact, 1e-13*4*pi*r);
    }
    EXPECT_EQ(s.cylinderArea(0, 1.0000001, 0, 4), 0);
    EXPECT_EQ(s.cylinderArea(0, 0.5, 3.5, 4), 0);
}

TEST(sphereSolidSet, cylinderAreaAgainstEllipticIntegrals)
{
    // No clipping: sweep of the centre's distance rho and the radius r,
    // with near-tangent (|r - rho| = a) and near-full-circle (r + rho = a)
    // cases; error relative to the cylinder area 2 pi r 2a
    const scalar a = 1;
    scalar worst = 0;
    auto check = [&](const scalar r, const scalar rho)
    {
        const rbd::sphereSolidSet s(oneSphere(point(rho, 0, 0), a));
        const scalar err =
            std::abs(s.cylinderArea(0, r, -2, 2) - areaElliptic(a, r, rho))
           /(4*pi*r);
        worst = std::max(worst, err);
    };
    for (int i = 0; i <= 60; ++i)
    {
        for (int j = 1; j <= 60; ++j)
        {
            check(3.0*j/60 + 1e-3, 2.5*i/60);
        }
    }
    for (const scalar d : {1e-2, 1e-4, 1e-6, 1e-9, 1e-12})
    {
        for (const scalar rho : {1e-3, 0.3, 0.5, 0.9, 1.5})
        {
            for (const scalar sign : {-1.0, 1.0})
            {
                if (a - rho + sign*d > 0)
                {
                    check(a - rho + sign*d, rho);
                }
                check(rho + a - sign*d, rho);
                if (rho - a + sign*d > 0)
                {
                    check(rho - a + sign*d, rho);
                }
            }
        }
    }
    EXPECT_LT(worst, 1e-11);
}

TEST(sphereSolidSet, cylinderAreaClippedAgainstBruteForce)
{
    // Random spheres cut by the slab's planes in every way; the reference
    // is accurate to ~1e-9, so that is what this test can resolve
    const scalar a = 1;
    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst = 0;
    for (int n = 0; n < 60; ++n)
    {
        const scalar rho = 2*u(gen);
        const scalar phi = 2*pi*u(gen);
        const point c(rho*std::cos(phi), rho*std::sin(phi), 4*u(gen) - 0.5);
        const scalar r = std::max(std::abs(rho - a), 0.0) + 2*a*u(gen);
        const scalar zLow = u(gen);
        const scalar zHigh = zLow + 0.2 + 2.5*u(gen);

        const rbd::sphereSolidSet s(oneSphere(c, a));
        const scalar err =
            std::abs
            (
                s.cylinderArea(0, r, zLow, zHigh)
              - areaBruteForce(a, r, c, zLow, zHigh, 200000)
            )/(4*pi*r);
        worst = std::max(worst, err);
    }
    EXPECT_LT(worst, 1e-8);
}

TEST(sphereSolidSet, cylinderAreasIntegrateToVolume)
{
    // Coarea formula: int S_int(r) dr = volume in the slab
    const scalar a = 0.5;
    for
    (
        const point& c
      : {point(0.3, 0.4, 1), point(0.1, 0, 0.2), point(0, 0, 1.9),
         point(-1, 1, 0.5)}
    )
    {
        const rbd::sphereSolidSet s(oneSphere(c, a));
        const scalar lo = s.radialExtent(0).min();
        const scalar hi = s.radialExtent(0).max();
        const scalar integral = integrate
        (
            [&](scalar r){ return s.cylinderArea(0, r, 0, 2); },
            lo,
            hi,
            2000
        );
        EXPECT_NEAR(integral, s.volume(0, 0, 2), 1e-7*s.volume(0, 0, 2))
            << "centre x " << c.x() << " z " << c.z();
    }
}

TEST(sphereSolidSet, contactsOfSimpleCubicLattice)
{
    // 4 x 4 x 4 spheres at spacing 2a: 3 4 4 3 = 144 contacts
    const scalar a = 0.5;
    pointField c;
    for (int i = 0; i < 4; ++i)
    {
        for (int j = 0; j < 4; ++j)
        {
            for (int k = 0; k < 4; ++k)
            {
                c.append(point(i, j, k));
            }
        }
    }
    const rbd::sphereSolidSet s(c, a);
    const labelList counts(s.contactCounts(1e-9));
    EXPECT_EQ(counts[0], 3);                  // corner
    EXPECT_EQ(counts[1*16 + 1*4 + 1], 6);     // inside
    EXPECT_NEAR(s.meanCoordinationNumber(1e-9, -1, 10), 288.0/64, 1e-14);
    EXPECT_NEAR(s.meanCoordinationNumber(1e-9, 0.5, 2.5), 5, 1e-14);
    EXPECT_EQ(s.meanCoordinationNumber(1e-9, 20, 30), 0);

    // Pulled apart by more than the tolerance: no contact
    const rbd::sphereSolidSet apart(pointField(c*1.001), a);
    EXPECT_EQ(sum(apart.contactCounts(1e-4)), 0);
    EXPECT_EQ(sum(apart.contactCounts(1e-2)), 2*144);
}

TEST(sphereSolidSet, contactsAgainstAllPairs)
{
    std::mt19937 gen(3);
    std::uniform_real_distribution<scalar> u(0, 4);
    List<point> c(300);
    for (point& p : c)
    {
        p = point(u(gen), u(gen), u(gen));
    }
    const scalar a = 0.2;
    const scalar gap = 0.05;
    const rbd::sphereSolidSet s(c, a);
    const labelList counts(s.contactCounts(gap));

    labelList reference(c.size(), Zero);
    forAll(c, i)
    {
        forAll(c, j)
        {
            if (i != j && mag(c[i] - c[j]) <= 2*a + gap)
            {
                ++reference[i];
            }
        }
    }
    EXPECT_TRUE(counts == reference);
    EXPECT_GT(sum(reference), 0);
}

// The right-hand side of a normal row of src/rbdPacking/contactResolution/
// resting/normalRows (eq 28 and the step term), against hand values

#include <gtest/gtest.h>
#include "normalRows.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar a = 0.005;
    const scalar m = 2500*4.0/3.0*M_PI*a*a*a;
    const scalar Is = 0.4*m*a*a;
    const scalar g = 9.81;
    const scalar h = 1e-3;

    //- A sphere at height z moving at vz, and its floor contact (exact,
    //  centre-based) with the gap z - a
    struct sphereOnFloor
    {
        List<rigidBody> bs;
        boolList fixed;
        List<contact> cs;

        sphereOnFloor(const scalar z, const scalar vz)
        :
            bs(1),
            fixed(1, false),
            cs(1)
        {
            bs[0] = rigidBody
            (
                m, vector(Is, Is, Is), point(0, 0, z), quaternion(1), false
            );
            bs[0].setState
            (
                point(0, 0, z), quaternion(1), m*vector(0, 0, vz), Zero
            );
            contact& c = cs[0];
            c.i = 0;
            c.k = tubeBottom;
            c.n = vector(0, 0, 1);
            c.gap = z - a;
            c.p = point(0, 0, 0.5*(z - a));
            c.ri = c.p - bs[0].x();
            c.rk = point(0, 0, 0);
            c.centreBased = true;
        }
    };
}


TEST(normalRows, restingSphereRowIsGravityPlusTheStepTerm)
{
    // Touching, at rest: d'' = -g without contact forces, plus 2 (d + h
    // d')/h^2 = 0
    sphereOnFloor s(a, 0);
    const List<vector> F(1, vector(0, 0, -m*g));
    const List<vector> tau(1, Zero);
    const restingProblem p{s.bs, s.cs, s.fixed, h};
    EXPECT_NEAR(normalRows::normalB(p, s.cs[0], F, tau), -g, 1e-12);
}


TEST(normalRows, stepTermAsksTheGapToCloseAtMostToZero)
{
    // 10 um above the floor, falling at 2 cm/s: B = -g + 2 (d + h v)/h^2,
    // so that phi = 0 exactly where the sphere would not reach the floor
    // within the step (B >= 0), and a force where it would
    for (const scalar vz : {-0.005, -0.02})
    {
        const scalar d = 1e-5;
        sphereOnFloor s(a + d, vz);
        const List<vector> F(1, vector(0, 0, -m*g));
        const List<vector> tau(1, Zero);
        const restingProblem p{s.bs, s.cs, s.fixed, h};
        const scalar B = normalRows::normalB(p, s.cs[0], F, tau);
        EXPECT_NEAR(B, -g + 2*(d + h*vz)/sqr(h), 1e-9) << "vz " << vz;
        // The end-of-step gap under gravity alone, d + h v - g h^2/2,
        // is h^2/2 B: its sign is B's
        EXPECT_EQ(B > 0, d + h*vz - 0.5*g*h*h > 0) << "vz " << vz;
    }
}

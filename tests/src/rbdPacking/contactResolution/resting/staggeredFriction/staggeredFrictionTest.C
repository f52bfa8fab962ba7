// Staggered friction of src/rbdPacking/contactResolution/resting/
// staggeredFriction (eq 9): the force that stops the predicted slip,
// clamped to mu phi, against the slip

#include <gtest/gtest.h>
#include "staggeredFriction.H"

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    const scalar a = 0.005;
    const scalar m = 2500*4.0/3.0*M_PI*a*a*a;
    const scalar Is = 0.4*m*a*a;
    const scalar g = 9.81;
    const scalar h = 1e-3;

    //- The friction of a sphere sliding at vx on the floor under its
    //  weight (normal force m g), friction coefficient mu
    vector slidingFriction(const scalar vx, const scalar mu, vector& Ffric)
    {
        List<rigidBody> bs(1);
        bs[0] = rigidBody
        (
            m, vector(Is, Is, Is), point(0, 0, a), quaternion(1), true
        );
        bs[0].setState
        (
            point(0, 0, a), quaternion(1), m*vector(vx, 0, 0), Zero
        );
        const boolList fixed(1, false);
        List<contact> cs(1);
        contact& c = cs[0];
        c.i = 0;
        c.k = tubeBottom;
        c.n = vector(0, 0, 1);
        c.gap = 0;
        c.p = point(0, 0, 0);
        c.ri = c.p - bs[0].x();
        c.rk = c.p;
        c.mu = mu;
        c.centreBased = true;

        const restingProblem p{bs, cs, fixed, h};
        const List<vector> Fext(1, vector(0, 0, -m*g));
        const List<vector> tauExt(1, Zero);
        List<vector> Ftot(1, Zero), tauTot(1, Zero);
        List<vector> Ff(1, Zero), tauF(1, Zero);
        List<vector> friction(1, Zero);
        const List<scalar> phi(1, m*g);
        staggeredFriction
        (
            p, std::vector<bool>(1, true), std::vector<label>(1, 0), phi,
            Fext, tauExt, Ftot, tauTot, Ff, tauF, friction
        );
        Ffric = Ff[0];
        return friction[0];
    }
}


TEST(staggeredFriction, fastSlipGetsCoulombsLimitAgainstIt)
{
    // Sliding at 1 m/s: stopping that in one step would take far more
    // than mu m g, so the friction is mu m g against the slip
    vector Ff;
    const vector f = slidingFriction(1.0, 0.5, Ff);
    EXPECT_NEAR(f.x(), -0.5*m*g, 1e-12*m*g);
    EXPECT_NEAR(f.y(), 0, 1e-15);
    EXPECT_NEAR(f.z(), 0, 1e-15);
    EXPECT_NEAR(mag(Ff - f), 0, 1e-15);
}


TEST(staggeredFriction, slowSlipIsStoppedWithinTheLimit)
{
    // Sliding at 1 um/s: the force that stops the contact point within
    // the step, |f| = slip/(h w_t) with w_t = 1/m + a^2/Is (the sphere
    // also turns), below mu m g
    vector Ff;
    const scalar v = 1e-6;
    const vector f = slidingFriction(v, 0.5, Ff);
    const scalar wt = 1/m + a*a/Is;
    EXPECT_NEAR(f.x(), -v/(h*wt), 1e-9*v/(h*wt));
    EXPECT_LT(mag(f), 0.5*m*g);
}


TEST(staggeredFriction, noFrictionWithoutACoefficient)
{
    vector Ff;
    const vector f = slidingFriction(1.0, 0, Ff);
    EXPECT_EQ(mag(f), 0);
    EXPECT_EQ(mag(Ff), 0);
}

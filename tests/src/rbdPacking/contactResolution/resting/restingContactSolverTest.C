// Resting contact forces of src/rbdPacking/contactResolution/resting
// (eqs 27-35) on redundant contact points: the compliance of mesh contacts
// (restingCompliance) makes the forces unique and continuous

#include <gtest/gtest.h>
#include "restingContactSolver.H"
#include "coupledFriction.H"
#include "../../testTools/worldFixture.H"
#include <random>

using namespace Foam;
using namespace Foam::rbd;

namespace
{
    // A cylinder d = h = 10 mm of steel standing on its flat face
    const scalar a = 0.005;
    const scalar m = 8030*M_PI*a*a*2*a;
    const vector Ib
    (
        m*(3*a*a + 4*a*a)/12, m*(3*a*a + 4*a*a)/12, 0.5*m*a*a
    );
    const scalar g = 9.81;
    const scalar h = 1e-3;

    //- Proximity band [m] (0.1 a, as the default proximity)
    const scalar band = 0.1*a;

    //- The cylinder on the floor, touching it at n points of its rim at
    //  irregular angles (a mesh's vertices), each a hair above the floor:
    //  gaps of up to 1e-12 m, the round-off of a mesh transformed into
    //  place, which no rigid motion closes all at once
    struct cylinderOnItsFace
    {
        List<rigidBody> bs;
        boolList fixed;
        DynamicList<contact> cs;

        cylinderOnItsFace(const label n, const unsigned seed)
        :
            bs(1),
            fixed(1, false),
            cs()
        {
            const point x(0, 0, a);
            bs[0] = rigidBody(m, Ib, x, quaternion(1), true);

            std::mt19937 rng(seed);
            std::uniform_real_distribution<double> U(0, 1);
            for (label k = 0; k < n; ++k)
            {
                const scalar angle = 2*M_PI*(k + 0.4*U(rng))/n;
                contact c;
                c.i = 0;
                c.k = tubeBottom;
                c.n = vector(0, 0, 1);
                c.gap = 1e-12*U(rng);
                c.p = point(a*Foam::cos(angle), a*Foam::sin(angle), c.gap);
                c.ri = c.p - x;
                c.rk = point(c.p.x(), c.p.y(), 0);
                cs.append(c);
            }
        }

        //- The normal forces [N]; F and tau the resultant on the body
        List<scalar> forces
        (
            const scalar compliance,
            vector& F,
            vector& tau,
            const word& solver = "blockPivoting"
        ) const
        {
            const restingContactSolver rs
            (
                rbdTest::parseDict("lcpSolver " + solver + ";"), compliance,
                band
            );
            List<vector> Fs(1, vector(0, 0, -m*g));
            List<vector> taus(1, Zero);
            rs.solve(bs, cs, fixed, h, Fs, taus);
            F = Fs[0];
            tau = taus[0];
            return rs.normalForces();
        }
    };
}


TEST(restingCompliance, sharesTheWeightOverRedundantPoints)
{
    // Twelve rim points: the weight is shared by all of them (the exact
    // LCP has no unique answer; the compliant one is close to the least
    // sum of squares: every point carries about mg/12), and the cylinder
    // is held (no acceleration beyond the compliance's, c g)
    const scalar c = 1e-4;
    for (const word solver : {"blockPivoting", "baraff"})
    {
        for (unsigned seed = 1; seed <= 3; ++seed)
        {
            const cylinderOnItsFace s(12, seed);
            vector F, tau;
            const List<scalar> phi = s.forces(c, F, tau, solver);
            scalar sum = 0;
            for (const scalar f : phi)
            {
                EXPECT_GT(f, 0.5*m*g/12) << solver << " seed " << seed;
                EXPECT_LT(f, 1.5*m*g/12) << solver << " seed " << seed;
                sum += f;
            }
            EXPECT_NEAR(sum, m*g, 10*c*m*g) << solver;
            EXPECT_LT(mag(F), 10*c*m*g) << solver;
            EXPECT_LT(mag(tau), 10*c*m*g*a) << solver;
        }
    }
}


TEST(restingCompliance, exactForcesPickAVertexOfTheSolutionSet)
{
    // The same problem solved exactly (restingCompliance 0): the weight
    // goes to a few points and the rest carry nothing, a choice that
    // round-off decides (what made settled cylinders creep). The contrast
    // that motivates the compliance, not a test of it
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
        const cylinderOnItsFace s(12, seed);
        vector F, tau;
        const List<scalar> phi = s.forces(0, F, tau);
        label carrying = 0;
        for (const scalar f : phi)
        {
            carrying += f > 1e-3*m*g;
        }
        EXPECT_LE(carrying, 6) << "seed " << seed;
        EXPECT_LT(mag(F), 1e-6*m*g) << "seed " << seed;
    }
}


TEST(restingCompliance, forcesChangeLittleWithRoundOff)
{
    // Gaps drawn again (another round-off): the compliant forces move by
    // a fraction of a share, where the exact ones jump between vertices
    const scalar c = 1e-4;
    const cylinderOnItsFace s1(12, 7);
    cylinderOnItsFace s2(12, 7);
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> U(0, 1);
    for (contact& ct : s2.cs)
    {
        ct.gap = 1e-12*U(rng);
    }
    vector F, tau;
    const List<scalar> phi1 = s1.forces(c, F, tau);
    const List<scalar> phi2 = s2.forces(c, F, tau);
    forAll(phi1, k)
    {
        EXPECT_LT(mag(phi1[k] - phi2[k]), 0.1*m*g/12) << k;
    }
}


TEST(restingCompliance, leavesSphereContactsExact)
{
    // A centre-based contact (a sphere on the floor) gets no compliance:
    // its force is m g exactly, so a resting sphere does not sink
    List<rigidBody> bs(1);
    bs[0] = rigidBody(m, Ib, point(0, 0, a), quaternion(1), true);
    DynamicList<contact> cs;
    contact c;
    c.i = 0;
    c.k = tubeBottom;
    c.n = vector(0, 0, 1);
    c.p = point(0, 0, 0);
    c.centreBased = true;
    cs.append(c);
    const restingContactSolver rs(rbdTest::parseDict(""), 1e-2, band);
    List<vector> Fs(1, vector(0, 0, -m*g));
    List<vector> taus(1, Zero);
    rs.solve(bs, cs, boolList(1, false), h, Fs, taus);
    EXPECT_NEAR(rs.normalForces()[0], m*g, 1e-12*m*g);
    EXPECT_LT(mag(Fs[0]), 1e-12*m*g);
}


namespace
{
    //- The contacts of a cylinder's flat face centred at centre, in the
    //  plane of e1 and e2 with normal nrm: six points of its rim at
    //  irregular angles, body i (centre xi) on body k (centre xk; the
    //  plane for tubeBottom), friction coefficient mu
    void appendFaceContacts
    (
        DynamicList<contact>& cs,
        const point& centre,
        const vector& nrm,
        const vector& e1,
        const vector& e2,
        const label i,
        const point& xi,
        const label k,
        const point& xk,
        const scalar mu
    )
    {
        for (label j = 0; j < 6; ++j)
        {
            const scalar angle = 2*M_PI*(j + 0.3)/6;
            contact c;
            c.i = i;
            c.k = k;
            c.n = nrm;
            c.mu = mu;
            c.p = centre + a*(Foam::cos(angle)*e1 + Foam::sin(angle)*e2);
            c.ri = c.p - xi;
            c.rk = k == tubeBottom ? vector(c.p) : c.p - xk;
            cs.append(c);
        }
    }


    //- A cylinder standing on its flat face on a plane tilted by tilt
    //  [deg], friction coefficient mu, touching at six rim points, solved
    //  for one step with the friction coupled or staggered
    struct incline
    {
        //- The velocity one step of the resultant of gravity and all
        //  contact forces gives its contact points [m/s]
        scalar residual;

        //- Acceleration of the centre down the slope [m/s^2]
        scalar downhill;

        //- Sum of the normal forces [N]
        scalar normalForce;

        //- The normal forces [N]
        List<scalar> phi;

        incline
        (
            const scalar tiltDeg,
            const scalar mu,
            const bool coupled,
            const label rounds = restingContactSolver::defaultFrictionRounds
        )
        {
            const scalar tilt = tiltDeg*M_PI/180;
            const vector n(Foam::sin(tilt), 0, Foam::cos(tilt));
            const vector e1(Foam::cos(tilt), 0, -Foam::sin(tilt));
            const vector e2(0, 1, 0);
            const point x(a*n);

            List<rigidBody> bs(1);
            bs[0] =
                rigidBody(m, Ib, x, quaternion(vector(0, 1, 0), tilt), true);
            DynamicList<contact> cs;
            appendFaceContacts
            (
                cs, Zero, n, e1, e2, 0, x, tubeBottom, Zero, mu
            );

            const restingContactSolver rs
            (
                rbdTest::parseDict(""), 1e-5, band, coupled, rounds
            );
            List<vector> Fs(1, vector(0, 0, -m*g));
            List<vector> taus(1, Zero);
            rs.solve(bs, cs, boolList(1, false), h, Fs, taus);
            phi = rs.normalForces();
            normalForce = sum(phi);
            const vector dv(h*Fs[0]/m);
            const vector dOmega(h*(bs[0].invInertia() & taus[0]));
            residual = mag(dv) + a*mag(dOmega);
            downhill = (Fs[0] & e1)/m;
        }
    };
}


TEST(restingFriction, holdsACylinderOnAnInclineForTheForcesApplied)
{
    // The friction changes the normal forces (its torque loads the lower
    // rim), so friction found for the frictionless normal forces does not
    // hold the cylinder; normal forces and friction found together do:
    // the resultant of gravity and all contact forces vanishes, and no
    // contact pulls
    const incline held(20, 0.5, true);
    EXPECT_LT(held.residual, 1e-6);
    for (const scalar p : held.phi)
    {
        EXPECT_GE(p, 0);
    }
}


TEST(restingFriction, everyRoundCapHoldsAndSlidesAtCoulomb)
{
    // frictionRounds caps the coupled solves of an island; a round's
    // friction bounds are mu phi of the normal forces of the round before
    // (the first: of the frictionless solve). Normal forces and friction
    // are solved together in every round, so friction inside its bounds
    // (20 deg, mu 0.5: tan 20 = 0.36) holds the cylinder with one round
    // already; at the bounds (35 deg, mu 0.3: sliding) the first round's
    // bounds come from the frictionless normal forces, which carry the
    // same total on a single plane: the Coulomb rate to 1e-3 again
    const scalar tilt = 35*M_PI/180;
    const scalar mu = 0.3;
    const scalar exact = g*(Foam::sin(tilt) - mu*Foam::cos(tilt));
    for (const label rounds : {1, 2, 4})
    {
        const incline held(20, 0.5, true, rounds);
        const incline sliding(35, mu, true, rounds);
        std::cout
            << "[ measured ] frictionRounds " << rounds << ": held residual "
            << held.residual << " m/s, sliding downhill/exact "
            << sliding.downhill/exact << std::endl;
        EXPECT_LT(held.residual, 1e-6) << rounds;
        EXPECT_NEAR(sliding.downhill, exact, 1e-3*exact) << rounds;
        for (const scalar p : held.phi)
        {
            EXPECT_GE(p, 0) << rounds;
        }
    }
}


namespace
{
    //- A tower of n cylinders, each standing on the one below, the lowest
    //  on a plane tilted by tiltDeg [deg]; six rim points per face, mu
    //  between the plane and the lowest, muTower between the cylinders;
    //  solved for one step with the friction coupled
    struct tower
    {
        //- Acceleration of each centre down the slope [m/s^2]
        List<scalar> downhill;

        //- The smallest normal force [N]
        scalar leastNormalForce;

        //- What the solve did
        restingSolveResult res;

        tower
        (
            const label n,
            const scalar tiltDeg,
            const scalar mu,
            const scalar muTower
        )
        :
            downhill(n)
        {
            const scalar tilt = tiltDeg*M_PI/180;
            const vector nrm(Foam::sin(tilt), 0, Foam::cos(tilt));
            const vector e1(Foam::cos(tilt), 0, -Foam::sin(tilt));
            const vector e2(0, 1, 0);
            const quaternion q(vector(0, 1, 0), tilt);

            List<rigidBody> bs(n);
            for (label j = 0; j < n; ++j)
            {
                bs[j] = rigidBody(m, Ib, (2*j + 1)*a*nrm, q, true);
            }
            DynamicList<contact> cs;
            for (label j = 0; j < n; ++j)
            {
                // Face j: the bottom of cylinder j, on the plane (j = 0) or
                // on the top of cylinder j - 1
                appendFaceContacts
                (
                    cs, 2*j*a*nrm, nrm, e1, e2, j, bs[j].x(),
                    j == 0 ? label(tubeBottom) : j - 1,
                    j == 0 ? point(Zero) : bs[j - 1].x(),
                    j == 0 ? mu : muTower
                );
            }

            const restingContactSolver rs
            (
                rbdTest::parseDict(""), 1e-5, band, true,
                restingContactSolver::defaultFrictionRounds
            );
            List<vector> Fs(n, vector(0, 0, -m*g));
            List<vector> taus(n, Zero);
            res = rs.solve(bs, cs, boolList(n, false), h, Fs, taus);
            leastNormalForce = min(rs.normalForces());
            for (label j = 0; j < n; ++j)
            {
                downhill[j] = (Fs[j] & e1)/m;
            }
        }
    };
}


TEST(restingFriction, aTallTowerSlidesAtTheCoulombRate)
{
    // Ten cylinders stacked on a plane tilted by 5 deg, mu = 0.05 on the
    // plane (tan 5 deg = 0.087: the tower slides; the friction's moment
    // shifts the normal forces of the lowest face by half its radius, so
    // it does not tip) and 0.5 between the cylinders: the centre of mass
    // accelerates down the slope at g (sin - 0.05 cos) = 0.366 m/s^2.
    // An island of ten moving bodies (at least
    // coupledFriction::interiorPointBodies: the interior point alone in
    // later rounds, at most largeIslandRounds rounds; this tower settles
    // in two, so the cap is not what is tested) and one of three: the
    // solve says how many rounds it took, no contact pulls, and the mean
    // of the centres' accelerations is Coulomb's to 1 %. (The centres do not
    // accelerate alike: the compliance of the contacts lets a tower
    // bend, measured 0.95 to 1.06 of the mean from bottom to top for
    // ten, 0.9997 to 1.0005 for three, and as much at rest)
    const scalar tilt = 5*M_PI/180;
    const scalar mu = 0.05;
    const scalar exact = g*(Foam::sin(tilt) - mu*Foam::cos(tilt));
    for (const label n : {label(3), label(10)})
    {
        const tower t(n, 5, mu, 0.5);
        const scalar mean = sum(t.downhill)/n;
        std::cout
            << "[ measured ] tower of " << n << ": " << t.res.frictionRounds
            << " rounds, mean downhill/exact " << mean/exact
            << ", lowest " << t.downhill[0]/exact << ", highest "
            << t.downhill[n - 1]/exact << std::endl;
        EXPECT_TRUE(t.res.converged) << n;
        EXPECT_GE(t.res.frictionRounds, 1) << n;
        EXPECT_LE
        (
            t.res.frictionRounds, restingContactSolver::defaultFrictionRounds
        ) << n;
        if (n >= coupledFriction::interiorPointBodies)
        {
            EXPECT_LE
            (
                t.res.frictionRounds, coupledFriction::largeIslandRounds
            );
        }
        EXPECT_NEAR(mean, exact, 1e-2*exact) << n;
        EXPECT_GE(t.leastNormalForce, 0) << n;
    }
}


TEST(restingFriction, staggeredResistsTheSlipOnAnIncline)
{
    // restingFriction staggered (friction for the frictionless normal
    // forces, then the normal forces again) does not hold the cylinder
    // (the known defect of docs/history.md: measured residual 2.0e-3 m/s per
    // 1 ms step, 21 % of the weight), but its friction must oppose the
    // slip: without friction the residual is g sin(20 deg) h = 3.4e-3
    // m/s. Asserted: at most 75 % of that (measured 60 %), no contact
    // pulls, and the normal forces carry the normal weight
    const incline frictionless(20, 0, false);
    const incline staggered(20, 0.5, false);
    EXPECT_NEAR(frictionless.residual, g*Foam::sin(20*M_PI/180)*h, 1e-9);
    std::cout
        << "[ measured ] staggered residual " << staggered.residual
        << " m/s, " << staggered.residual/frictionless.residual
        << " of the frictionless" << std::endl;
    EXPECT_LT(staggered.residual, 0.75*frictionless.residual);
    for (const scalar p : staggered.phi)
    {
        EXPECT_GE(p, 0);
    }
    EXPECT_NEAR
    (
        staggered.normalForce, m*g*Foam::cos(20*M_PI/180), 1e-4*m*g
    );
}


TEST(restingFriction, slidesAtTheCoulombRateBeyondTheCone)
{
    // tan 35 deg = 0.70 > mu = 0.3: the cylinder slides (it tips only
    // beyond 45 deg), the normal forces carry m g cos(35 deg) and
    // Coulomb's friction mu m g cos(35 deg) acts against the slip, so the
    // centre accelerates down the slope at g (sin - mu cos) = 3.22 m/s^2.
    // Coupled: that, to 1e-3. Staggered (two Gauss-Seidel sweeps of
    // friction for the frictionless normal forces): never more friction
    // than Coulomb's, and at least 60 % of it (measured 84 %)
    const scalar tilt = 35*M_PI/180;
    const scalar mu = 0.3;
    const scalar coulomb = mu*g*Foam::cos(tilt);
    const scalar exact = g*Foam::sin(tilt) - coulomb;

    const incline coupled(35, mu, true);
    EXPECT_NEAR(coupled.downhill, exact, 1e-3*exact);
    EXPECT_NEAR(coupled.normalForce, m*g*Foam::cos(tilt), 1e-4*m*g);

    const incline staggered(35, mu, false);
    const scalar friction = g*Foam::sin(tilt) - staggered.downhill;
    std::cout
        << "[ measured ] staggered friction/Coulomb's " << friction/coulomb
        << ", coupled downhill/exact " << coupled.downhill/exact
        << std::endl;
    EXPECT_LE(friction, (1 + 1e-3)*coulomb);
    EXPECT_GE(friction, 0.6*coulomb);
    EXPECT_NEAR(staggered.normalForce, m*g*Foam::cos(tilt), 1e-4*m*g);
}


// ************************************************************************* //

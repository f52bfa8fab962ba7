// Physics of src/rbdPacking/world against closed forms, at several step
// sizes (the outer interval deltaT bounds every step).

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"

using namespace rbdTest;

namespace
{
    const scalar g = 9.81;
    const scalar d = 0.01;
    const scalar a = 0.5*d;

    std::string controlsWith(scalar deltaT)
    {
        return "deltaT " + std::to_string(deltaT) + ";";
    }
}


class freeFall : public ::testing::TestWithParam<scalar> {};

TEST_P(freeFall, matchesParabolaExactly)
{
    sphereScene s(1, d, 0, 1, 0, 1, controlsWith(GetParam()));
    const scalar z0 = 5;
    s().addBody(point(0, 0, z0), quaternion(1));
    s().setVelocity(0, vector(0.1, 0, 2), Zero);

    const scalar t = 0.3;
    s().advance(t);
    const rigidBody& b = s().bodies()[0];

    EXPECT_NEAR(b.x().z(), z0 + 2*t - 0.5*g*t*t, 1e-12);
    EXPECT_NEAR(b.x().x(), 0.1*t, 1e-12);
    EXPECT_NEAR(b.v().z(), 2 - g*t, 1e-12);
    EXPECT_GT(s().stats().steps, 1);
}

INSTANTIATE_TEST_SUITE_P(stepSizes, freeFall, ::testing::Values(0.025, 1e-3));


class bounce : public ::testing::TestWithParam<scalar> {};

TEST_P(bounce, apexIsRestitutionSquaredTimesDropHeight)
{
    const scalar e = 0.8;
    const scalar h = 0.1;   // drop height of the lowest point [m]
    sphereScene s(1, d, 0, 1, 0, e, controlsWith(GetParam()));
    s().addBody(point(0, 0, a + h), quaternion(1));

    // Fall, bounce, and record the highest point of the first rebound
    scalar apex = 0;
    bool bounced = false;
    while (s().time() < 0.5)
    {
        s().step(1e-3);
        const rigidBody& b = s().bodies()[0];
        if (b.v().z() > 0)
        {
            bounced = true;
        }
        if (bounced)
        {
            apex = max(apex, b.x().z() - a);
            if (b.v().z() < 0)
            {
                break;
            }
        }
    }
    ASSERT_TRUE(bounced);
    EXPECT_NEAR(apex, e*e*h, 1e-3*e*e*h);
    EXPECT_LT(s().stats().maxOverlap, 1e-6*d);
}

INSTANTIATE_TEST_SUITE_P(stepSizes, bounce, ::testing::Values(0.025, 2e-3));


TEST(sliding, sphereWithoutRotationStopsAfterVSquaredOverTwoMuG)
{
    const scalar mu = 0.3;
    const scalar v0 = 1;
    sphereScene s(1, d, 0, 0.5, mu, 0.5, "", false);
    s().addBody(point(-0.3, 0, a), quaternion(1));
    s().setVelocity(0, vector(v0, 0, 0), Zero);

    s().advance(1);
    const rigidBody& b = s().bodies()[0];

    EXPECT_NEAR(b.x().x() + 0.3, sqr(v0)/(2*mu*g), 1e-4);
    EXPECT_NEAR(mag(b.v()), 0, 1e-9);
    EXPECT_NEAR(b.x().z(), a, 1e-9);
}


TEST(sliding, rotatingSphereEndsRollingAtFiveSeventhsOfItsSpeed)
{
    const scalar mu = 0.3;
    const scalar v0 = 1;
    sphereScene s(1, d, 0, 0.5, mu, 0.5);
    s().addBody(point(-0.4, 0, a), quaternion(1));
    s().setVelocity(0, vector(v0, 0, 0), Zero);

    s().advance(0.5);
    const rigidBody& b = s().bodies()[0];

    // Rolling without slip: v = omega x (a e_z) ... v_x = omega_y a
    EXPECT_NEAR(b.v().x(), 5.0/7.0*v0, 1e-4);
    EXPECT_NEAR(b.omega().y()*a, b.v().x(), 1e-4);
    EXPECT_NEAR(b.x().z(), a, 1e-9);
}


TEST(resting, sphereOnFloorStaysPutForTenSeconds)
{
    sphereScene s(0.1, d, 0.1, 0.9, 0.6, 0.6);
    s().addBody(point(0.01, 0.02, a), quaternion(1));

    s().advance(10);
    const rigidBody& b = s().bodies()[0];

    EXPECT_NEAR(b.x().z(), a, 1e-9);
    EXPECT_NEAR(b.x().x(), 0.01, 1e-12);
    EXPECT_NEAR(b.x().y(), 0.02, 1e-12);
    EXPECT_LT(mag(b.v()), 1e-9);
    EXPECT_LT(s().stats().maxOverlap, 1e-9);
}


class restingColumn : public ::testing::TestWithParam<scalar> {};

TEST_P(restingColumn, twentySpheresInNarrowTubeStayStillForTenSeconds)
{
    // Tube of 1.6 dp: a zig-zag column, every sphere touching the wall and
    // its neighbours, built exactly at rest (the column of the paper's
    // narrowest beds). Parameter: pellet and wall friction.
    const scalar mu = GetParam();
    const scalar R = 0.8*d;
    const scalar rho = R - a;
    const scalar dz = Foam::sqrt(sqr(d) - sqr(2*rho));
    sphereScene s(2*R, d, mu, 0.9, mu, 0.6, "sleepVelocity 0;");
    List<point> start(20);
    forAll(start, i)
    {
        start[i] = point((i % 2 ? 1 : -1)*rho, 0, a + dz*i);
        s().addBody(start[i], quaternion(1));
    }

    s().advance(10);

    scalar drift = 0;
    forAll(start, i)
    {
        drift = max(drift, mag(s().bodies()[i].x() - start[i]));
    }
    EXPECT_LT(drift, 1e-6*d);
    EXPECT_LT(s().stats().maxOverlap, 1e-6*d);
    EXPECT_LT(s().currentMaxOverlap(), 1e-6*d);
    EXPECT_LT(s().kineticEnergy(), 1e-15);
    EXPECT_EQ(s().stats().lcpFailures, 0);
}

INSTANTIATE_TEST_SUITE_P(friction, restingColumn, ::testing::Values(0.0, 0.3));


TEST(settling, droppedSpheresComeToRestWithoutInterpenetration)
{
    // Ten spheres dropped one above the other into a tube of 3 dp settle:
    // the kinetic energy decays, nothing leaves the tube, no overlap
    sphereScene s(3*d, d, 0.1, 0.9, 0.6, 0.6);
    for (label i = 0; i < 10; ++i)
    {
        const scalar x = 0.3*d*Foam::cos(2.1*i);
        const scalar y = 0.3*d*Foam::sin(2.1*i);
        s().addBody(point(x, y, a + 1.2*d*(i + 1)), quaternion(1));
    }
    s().advance(4);
    EXPECT_LT(s().kineticEnergy(), 1e-9);
    EXPECT_LT(s().stats().maxOverlap, 1e-3*d);
    for (const rigidBody& b : s().bodies())
    {
        EXPECT_LE(tube::axialDistance(b.x()), 1.5*d - a + 1e-3*d);
        EXPECT_GE(b.x().z(), a - 1e-3*d);
        EXPECT_LT(b.x().z(), 5*d);
    }
}


TEST(freeFlight, spinningCylinderPrecessesAsTheClosedFormWithoutDamping)
{
    // A flat cylinder (d 10 mm, h 5 mm: principal inertia (I1, I1, I3),
    // I3 > I1) thrown spinning about a tilted axis, without gravity: the
    // torque-free axisymmetric top. With the world angular momentum L
    // (constant) and the symmetry axis e3, omega = L/I1 + lambda e3,
    // lambda = (L . e3)(1/I3 - 1/I1): the body precesses about L at
    // |L|/I1 and turns about e3 at lambda, so
    //     q(t) = q(L/|L|, |L| t/I1) q0 q(e3_body, lambda t);
    // the centre moves on a straight line, and no damping takes energy.
    // (A sphere's energy |L|^2/2I is constant whatever its orientation
    // does; this body's L . omega/2 is not.) Measured at steps of 1 ms
    // over 1 s: |q - q_exact| 7.5e-7, relative energy change 2.1e-10
    const tube container(1, 10, 0.1, 0.9);
    const autoPtr<pelletShape> shape
    (
        pelletShape::New
        (
            parseDict("shape cylinder; diameter 0.01; height 0.005;")
        )
    );
    const simulationControls controls
    (
        simulationDict("gravity 0;")
    );
    const pelletMaterial material{8030, 0.1, 0.9};
    world w(container, shape(), material, true, controls);

    const point x0(0.01, -0.02, 0.5);
    const quaternion q0(vector(1, 2, 0.5)/mag(vector(1, 2, 0.5)), 0.7);
    w.addBody(x0, q0);
    const vector v0(0.01, 0.02, 0);
    w.setVelocity(0, v0, vector(3, -1, 2));

    const rigidBody& b = w.bodies()[0];
    const tensor invIb(b.R().T() & b.invInertia() & b.R());
    const scalar I1 = 1/invIb.xx();
    const scalar I3 = 1/invIb.zz();
    ASSERT_NEAR(invIb.yy(), invIb.xx(), 1e-9*invIb.xx());
    ASSERT_GT(I3, 1.1*I1);

    const vector L0(b.L());
    const vector e3(b.R() & vector(0, 0, 1));
    const scalar lambda = (L0 & e3)*(1/I3 - 1/I1);
    const scalar E0 = w.kineticEnergy();

    scalar qError = 0;
    const scalar h = 1e-3;
    for (label k = 1; k <= 1000; ++k)
    {
        // (free flight: the step rule takes what it is given)
        w.advance(h);
        const scalar t = w.time();
        const quaternion exact
        (
            quaternion(L0/mag(L0), mag(L0)*t/I1)
           *q0
           *quaternion(vector(0, 0, 1), lambda*t)
        );
        const quaternion d(b.q() - exact), s(b.q() + exact);
        qError = max
        (
            qError,
            Foam::sqrt
            (
                min(sqr(d.w()) + magSqr(d.v()), sqr(s.w()) + magSqr(s.v()))
            )
        );
    }
    std::cout
        << "[ measured ] |q - q_exact| " << qError << ", energy change "
        << (w.kineticEnergy() - E0)/E0 << std::endl;
    EXPECT_LT(qError, 2.5e-6);
    EXPECT_LT(mag(b.L() - L0), 1e-12*mag(L0));
    EXPECT_NEAR(w.kineticEnergy(), E0, 1e-9*E0);
    EXPECT_LT(mag(b.x() - (x0 + v0*w.time())), 1e-12);
}


TEST(worldDeath, aCollapsedStepStopsTheRunInsteadOfHanging)
{
    // The overlap correction leaves interpenetrations up to the contact
    // tolerance (here 1e-6 m) that a band of 5e-7 m cannot hold: the step
    // collapsed to 1e-18 s and rbdPackBed hung without a word (packedBed
    // now refuses such settings; the engine stops by itself as well)
    EXPECT_EXIT
    (
        {
            sphereScene s
            (
                0.03, d, 0.1, 0.9, 0.6, 0.6,
                "proximity 1e-4; contactTolerance 1e-4;"
            );
            s().addBody(point(0, 0, 0.02), quaternion(1));
            s().addBody(point(0.001, 0, 0.035), quaternion(1));
            s().addBody(point(-0.001, 0.001, 0.05), quaternion(1));
            s().advance(2);
        },
        ::testing::ExitedWithCode(1),
        "time step stayed below"
    );
}

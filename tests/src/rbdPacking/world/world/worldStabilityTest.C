// Stability suite of src/rbdPacking/world (issue 6): hard sphere scenes,
// each stepped with its invariants checked after every step:
//   - no NaN or Inf in any state (|q| = 1 holds by construction, the
//     integrator normalises q; the orientation is tested against closed
//     forms in midpointIntegratorTest.C and worldTest.C);
//   - no pellet outside the tube (wall and floor);
//   - the largest interpenetration, at any step and before correction,
//     within the tolerance (0.2 % of dp);
//   - the kinetic energy never rises across a collision stage beyond
//     round-off (world::statistics::maxCollisionEnergyGain);
//   - the scene settles within a bounded number of steps, and a settled
//     scene does not creep.
// Sizes are small so that the suite runs in CI; the soak benchmark runs the
// same scenes larger and with many seeds.

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"

#include <random>
#include <algorithm>

using namespace rbdTest;

namespace
{
    const scalar d = 0.01;
    const scalar a = 0.5*d;

    //- Largest interpenetration allowed at any step [m]: 0.2 % of dp. The
    //  scenes stay below 0.01 % except the 20 m/s throw, which reaches
    //  0.12 % (the step rule bounds accelerations by g; a contact force
    //  of the resting solve can exceed that within one step)
    const scalar overlapTolerance = 2e-3*d;

    //- Sleeping as in the tutorials: point contacts have no rolling or
    //  spin resistance, so without sleep a sphere can keep rolling at
    //  constant energy (measured: 24 um/s at mu 0.95); with sleep the bed
    //  comes to a standstill
    const std::string sleepOn = "sleepVelocity 0.001;";

    //- Steps a sphere scene, checking the invariants at every step
    struct monitor
    {
        world& w;
        const tube& container;
        label badStates = 0;
        scalar maxEscape = 0;

        void check()
        {
            for (const rigidBody& b : w.bodies())
            {
                if (!finiteState(b))
                {
                    ++badStates;
                    continue;
                }
                const scalar r = Foam::sqrt(sqr(b.x().x()) + sqr(b.x().y()));
                maxEscape = max(maxEscape, r + a - container.radius());
                maxEscape = max(maxEscape, a - b.x().z());
            }
        }

        //- Step until time t; returns the steps taken
        label runUntil(const scalar t, const scalar hMax)
        {
            label steps = 0;
            while (w.time() < t - SMALL)
            {
                w.step(min(hMax, t - w.time()));
                check();
                ++steps;
            }
            return steps;
        }

        //- Run until the kinetic energy stays below energy [J] for
        //  quiet [s] (checked every interval), at most until tMax [s];
        //  returns the time it settled, or GREAT
        scalar settle
        (
            const scalar energy,
            const scalar quiet,
            const scalar tMax,
            const scalar hMax
        )
        {
            scalar calmSince = -1;
            while (w.time() < tMax)
            {
                runUntil(w.time() + 0.01, hMax);
                if (w.kineticEnergy() < energy)
                {
                    if (calmSince < 0)
                    {
                        calmSince = w.time();
                    }
                    if (w.time() - calmSince >= quiet)
                    {
                        return w.time();
                    }
                }
                else
                {
                    calmSince = -1;
                }
            }
            return GREAT;
        }

        //- Largest displacement of any pellet over further time dt
        scalar creep(const scalar dt, const scalar hMax)
        {
            List<point> x(w.bodies().size());
            forAll(x, i)
            {
                x[i] = w.bodies()[i].x();
            }
            const scalar E0 = w.kineticEnergy();
            scalar Emax = E0;
            for (label k = 0; k < 20; ++k)
            {
                runUntil(w.time() + dt/20, hMax);
                Emax = max(Emax, w.kineticEnergy());
            }
            // At rest nothing feeds energy in: it may only fall
            EXPECT_LE(Emax, E0*(1 + 1e-6) + 1e-15);
            scalar m = 0;
            forAll(x, i)
            {
                m = max(m, mag(w.bodies()[i].x() - x[i]));
            }
            return m;
        }

        void expectHealthy(const std::string& what) const
        {
            EXPECT_EQ(badStates, 0) << what;
            EXPECT_LT(maxEscape, overlapTolerance) << what;
            EXPECT_LT(w.stats().maxOverlap, overlapTolerance) << what;
            EXPECT_LT(w.stats().maxCollisionEnergyGain, 1e-9) << what;
        }
    };

    //- Drop n spheres, seeded, from random points of a column above the
    //  floor of a tube of diameter D
    void dropSpheres
    (
        world& w,
        const label n,
        const scalar D,
        const unsigned seed,
        const scalar spacing = 1.3*d,
        const scalar vz = 0
    )
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<scalar> u(-1, 1);
        const scalar rMax = max(0.5*D - a - 1e-4, 0.0);
        for (label i = 0; i < n; ++i)
        {
            scalar x, y;
            do
            {
                x = rMax*u(gen);
                y = rMax*u(gen);
            } while (sqr(x) + sqr(y) > sqr(rMax));
            const label id =
                w.addBody(point(x, y, a + 0.001 + spacing*i), quaternion(1));
            if (vz != 0)
            {
                w.setVelocity(id, vector(0, 0, vz), Zero);
            }
        }
    }

    //- Energy scale of n spheres: n m g dp [J]
    scalar energyScale(const world& w)
    {
        return
            w.bodies().size()*w.bodies()[0].mass()*9.81*d;
    }
}


TEST(stability, bouncySlipperySpheresInTheNarrowestTube)
{
    // COR 0.95 and mu 0.05 at N = 3.1: long rattling, little dissipation
    sphereScene s(3.1*d, d, 0.05, 0.95, 0.05, 0.95, sleepOn);
    dropSpheres(s(), 15, 3.1*d, 1);
    monitor m{s(), s.container};
    const scalar tSettled = m.settle(1e-7*energyScale(s()), 1.0, 15, 0.025);
    m.expectHealthy("COR 0.95, mu 0.05");
    EXPECT_LT(tSettled, 15);
    EXPECT_LT(s().stats().steps, 200000);
    EXPECT_LT(m.creep(1, 0.025), 1e-4*d);
    m.expectHealthy("COR 0.95, mu 0.05, settled");
}


TEST(stability, highFriction)
{
    sphereScene s(4*d, d, 0.95, 0.6, 0.95, 0.6, sleepOn);
    dropSpheres(s(), 20, 4*d, 2);
    monitor m{s(), s.container};
    EXPECT_LT(m.settle(1e-7*energyScale(s()), 1.0, 10, 0.025), 10);
    m.expectHealthy("mu 0.95");
    EXPECT_LT(m.creep(1, 0.025), 1e-4*d);
}


TEST(stability, fiftySphereRestingColumnWithPerStepChecks)
{
    // The zig-zag column of the narrowest tube (1.6 dp), built at rest
    const scalar R = 0.8*d;
    const scalar rho = R - a;
    const scalar dz = Foam::sqrt(sqr(d) - sqr(2*rho));
    sphereScene s(2*R, d, 0.3, 0.9, 0.3, 0.6, "sleepVelocity 0;");
    List<point> start(50);
    forAll(start, i)
    {
        start[i] = point((i % 2 ? 1 : -1)*rho, 0, a + dz*i);
        s().addBody(start[i], quaternion(1));
    }
    monitor m{s(), s.container};
    m.runUntil(3, 0.025);
    m.expectHealthy("50-sphere column");
    scalar drift = 0;
    forAll(start, i)
    {
        drift = max(drift, mag(s().bodies()[i].x() - start[i]));
    }
    EXPECT_LT(drift, 1e-6*d);
    EXPECT_EQ(s().stats().lcpFailures, 0);
}


TEST(stability, spheresStartingInContactWithEachOtherAndTheWall)
{
    // A ring of six spheres touching the wall and their neighbours, and a
    // seventh in the middle touching all six, on the floor: exact contact
    // (gap 0) everywhere at the start
    const scalar D = 3*d;
    sphereScene s(D, d, 0.1, 0.9, 0.6, 0.6, sleepOn);
    s().addBody(point(0, 0, a), quaternion(1));
    for (label k = 0; k < 6; ++k)
    {
        const scalar phi = k*constant::mathematical::pi/3;
        s().addBody(point(d*Foam::cos(phi), d*Foam::sin(phi), a), quaternion(1));
    }
    // ... and three in the pockets above them, a hair too high
    for (label k = 0; k < 3; ++k)
    {
        const scalar phi = (4*k + 1)*constant::mathematical::pi/6;
        s().addBody
        (
            point(0.577*d*Foam::cos(phi), 0.577*d*Foam::sin(phi), a + 0.9*d),
            quaternion(1)
        );
    }
    monitor m{s(), s.container};
    EXPECT_LT(m.settle(1e-7*energyScale(s()), 1.0, 5, 0.025), 5);
    m.expectHealthy("starting in contact");
    EXPECT_LT(m.creep(1, 0.025), 1e-4*d);
}


namespace
{
    //- The settled bed of bedSettlesTheSameWayAtTinyAndHugeOuterSteps:
    //  15 spheres dropped into a 4 dp tube, stepped with outer interval
    //  deltaT [s]; the centres' heights, sorted [m]
    struct settledBed
    {
        scalar tSettled;
        List<scalar> z;

        settledBed(const scalar deltaT, const unsigned seed)
        {
            sphereScene s
            (
                4*d, d, 0.1, 0.9, 0.6, 0.6,
                "deltaT " + std::to_string(deltaT) + ";"
            );
            dropSpheres(s(), 15, 4*d, seed);
            monitor m{s(), s.container};
            tSettled = m.settle(1e-7*energyScale(s()), 1.0, 10, deltaT);
            m.expectHealthy("deltaT " + std::to_string(deltaT));
            z.setSize(s().bodies().size());
            forAll(z, i)
            {
                z[i] = s().bodies()[i].x().z();
            }
            std::sort(z.begin(), z.end());
        }

        //- Mean height of the centres [m]
        scalar meanHeight() const
        {
            return average(z);
        }

        //- Spheres on the floor (centre within 1e-3 dp of a)
        label onTheFloor() const
        {
            label n = 0;
            for (const scalar zi : z)
            {
                n += zi < a + 1e-3*d;
            }
            return n;
        }
    };
}


TEST(stability, bedSettlesTheSameWayAtTinyAndHugeOuterSteps)
{
    // deltaT bounds every step; the step rule must keep a huge one safe:
    // the bed of huge outer steps is the bed of tiny ones, not one spoilt
    // by steps the rule let through. The runs are chaotic, so the beds
    // are compared by what chaos leaves alone: the spheres on the floor
    // and the mean height of the centres. Measured (seeds 3, 4, 5; tiny /
    // huge): on the floor 9/11, 10/10, 10/10; mean height 0.716/0.673,
    // 0.718/0.679, 0.703/0.683 dp. Asserted: on the floor within 2, mean
    // heights within 0.08 dp. A run is deterministic: the huge-step run
    // again gives the same poses, bit for bit
    const unsigned seed = 3;
    const settledBed tiny(1e-4, seed);
    const settledBed huge(0.5, seed);
    const settledBed again(0.5, seed);

    EXPECT_LT(tiny.tSettled, 10);
    EXPECT_LT(huge.tSettled, 10);
    EXPECT_TRUE(huge.z == again.z);
    EXPECT_NEAR(tiny.onTheFloor(), huge.onTheFloor(), 2);
    EXPECT_NEAR(tiny.meanHeight(), huge.meanHeight(), 0.08*d);
    std::cout
        << "[ measured ] on the floor " << tiny.onTheFloor() << " / "
        << huge.onTheFloor() << ", mean height " << tiny.meanHeight()/d
        << " / " << huge.meanHeight()/d << " dp" << std::endl;
}


TEST(stability, aSphereSkimmingTheConcaveWallStaysInside)
{
    // A sphere moving along the wall of a 31 mm tube, 3 mm from it (outside
    // the band) and hardly towards it: its gap along the straight path
    // closes with v_t^2/rho, far faster than its radial speed says. Seen
    // in the soak (COR 0.95, mu 0.05): 4e-5 m into the wall in one step.
    const scalar D = 0.031;
    sphereScene s(D, d, 0.05, 0.95, 0.05, 0.95);
    const scalar rho0 = 0.5*D - a - 3e-3;
    const label i = s().addBody(point(rho0, 0, 5*d), quaternion(1));
    s().setVelocity(i, vector(-0.01, 1.1, 0), Zero);
    monitor m{s(), s.container};
    // It reaches the wall after ~7 ms, the floor after ~0.1 s
    m.runUntil(0.05, 0.025);
    EXPECT_GT(s().stats().collisions, 0) << "it must reach the wall";
    m.runUntil(0.1, 0.025);
    m.expectHealthy("skimming the wall");
    // The step ends at touching: far tighter than the suite's tolerance
    // (2.5e-5 m without the exact time to the wall)
    EXPECT_LT(s().stats().maxOverlap, 1e-4*d);
}


TEST(stability, aThousandSpheres)
{
    // 1000 spheres in a 24 dp tube, released from a loose lattice just
    // above the floor (three layers, the third partly filled): the scale
    // case (broad phase, islands, sleep) at a size CI can afford. Spheres
    // without rotation (an effect a scene may switch off), wall and pellet
    // friction 0.6: they slide and stop. (With rotation the same bed
    // settles at 4.4 s of simulated time after 2.5 min of CPU, rolling on
    // the floor.) Settled: the kinetic energy below 1e-10 n m g dp for
    // 1 s; the usual 1e-7 n m g dp lets one of a thousand pellets slide
    // at 4 mm/s (it crept 0.1 mm in the next 0.5 s).
    const scalar D = 24*d;
    sphereScene s(D, d, 0.6, 0.6, 0.6, 0.6, sleepOn, false);
    std::mt19937 gen(7);
    std::uniform_real_distribution<scalar> u(-1, 1);
    const scalar pitch = 1.1*d;
    const scalar rMax = 0.5*D - a - 1e-4;
    label n = 0;
    for (label layer = 0; n < 1000; ++layer)
    {
        const scalar z = a + 0.2*d + layer*pitch;
        const label m = label(rMax/pitch);
        for (label ix = -m; ix <= m && n < 1000; ++ix)
        {
            for (label iy = -m; iy <= m && n < 1000; ++iy)
            {
                const scalar x = ix*pitch + 0.04*d*u(gen);
                const scalar y = iy*pitch + 0.04*d*u(gen);
                if (sqr(x) + sqr(y) <= sqr(rMax))
                {
                    s().addBody(point(x, y, z), quaternion(1));
                    ++n;
                }
            }
        }
    }
    ASSERT_EQ(s().bodies().size(), 1000);

    monitor m{s(), s.container};
    const scalar tSettled = m.settle(1e-10*energyScale(s()), 1.0, 5, 0.025);
    m.expectHealthy("1000 spheres");
    EXPECT_LT(tSettled, 5);
    EXPECT_LT(s().stats().steps, 50000);
    // Asleep, every pellet is held: no creep, and the bed costs nothing
    EXPECT_EQ(s().nSleeping(), 1000);
}


TEST(stability, fastDropFromHighUp)
{
    // 10 spheres thrown down at 20 m/s (a fall from 20 m): the step rule
    // must catch every impact (no tunnelling through the floor or a
    // pellet), for every seed.
    //
    // The heaps they end in, three layers in a tube of 3 d, do not all
    // come to rest: a sphere on the floor spinning about the vertical
    // (no spin resistance at a point contact), or one or two spheres
    // bouncing on top of the heap for seconds with an overlap correction
    // nearly every step (up to 80 000 in a run) (a known defect:
    // docs/history.md, Known limitations). Measured over
    // seeds 1-16, not settled by 10 s: 1 (the build before the per-body
    // broad phase), 4 (that build), 5 (that build with the broad phase's
    // bound taken from the least slack of any body, i.e. shorter steps).
    // Over seeds 1-72: 54 settled with eq 38 on every sphere contact, 45
    // without it on sphere-sphere and sphere-floor contacts (this build,
    // stepControl; 1.6 standard errors apart), every run healthy in both.
    // Asserted on seeds 1-24: every run healthy, and at least half
    // settled by 10 s (this build: 14 of 24; with eq 38: 17 of 24)
    label settled = 0;
    const unsigned nSeeds = 24;
    for (unsigned seed = 1; seed <= nSeeds; ++seed)
    {
        sphereScene s(3*d, d, 0.1, 0.9, 0.6, 0.6);
        dropSpheres(s(), 10, 3*d, seed, 3*d, -20);
        monitor m{s(), s.container};
        const scalar t = m.settle(1e-7*energyScale(s()), 1.0, 10, 0.025);
        settled += t < 10;
        std::cout
            << "[ measured ] fast drop, seed " << seed << ": "
            << (t < 10 ? "settled at " + std::to_string(t) + " s" : "creeps")
            << ", " << s().stats().projections << " overlap corrections"
            << std::endl;
        m.expectHealthy("fast drop, seed " + std::to_string(seed));
    }
    EXPECT_GE(2*settled, label(nSeeds));
}


// ************************************************************************* //

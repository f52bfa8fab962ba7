// Stability suite of src/rbdPacking/world for mesh pellets (issues 4 and
// 6), the counterpart of worldStabilityTest.C (spheres): Raschig rings
// (10/6/10 mm) and cylinders (d = h = 10 mm) on coarse meshes in the hard
// cases of a packing, each stepped with its invariants checked after every
// step:
//   - no NaN or Inf in any state (|q| = 1 holds by construction, the
//     integrator normalises q; the orientation is tested against closed
//     forms in midpointIntegratorTest.C and worldTest.C);
//   - no mesh vertex outside the tube (wall and floor; for a polyhedron
//     the vertices are its extreme points);
//   - the largest interpenetration at any step within 0.5 % of dp (the
//     target of issue 4), twice: as the world records it
//     (statistics::maxOverlap, before any correction) and as an
//     independent probe measures it (penetrationProbe: separating axes of
//     convex pieces of the mesh solids, not the narrow phase; it sees the
//     state after each step, the world's record the same state at the
//     start of the next);
//   - the kinetic energy never rises across a collision stage beyond
//     round-off (world::statistics::maxCollisionEnergyGain);
//   - the scene settles within a bounded time, and a settled scene does
//     not creep over one more second.
// Material: the paper's Table 3 (pellets mu 0.1, COR 0.9; wall mu 0.6,
// COR 0.6), sleep as in the tutorials.

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"
#include "../../testTools/penetrationProbe.H"
#include "packedBed.H"

#include <iostream>
#include <random>

using namespace rbdTest;


namespace
{
    const scalar dp = 0.01;

    //- Largest interpenetration allowed at any step [m]: 0.5 % of dp
    const scalar overlapTolerance = 5e-3*dp;

    const std::string cylinderDict =
        "shape cylinder; diameter 0.01; height 0.01; faces 300;";

    const std::string ringDict =
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01; "
        "faces 300;";

    const std::string sleepOn = "sleepVelocity 0.001;";

    //- The same on triangle meshes everywhere: contactModel auto packs
    //  cylinders and rings as exact solids, and the scenes of this suite
    //  are about meshes
    const std::string sleepOnMeshes = sleepOn + " contactModel mesh;";

    //- The ring scenes run on both: the meshes this suite is about, and
    //  the exact solids auto packs rings with
    const std::string ringModels[] =
        {sleepOnMeshes, sleepOn + " contactModel exact;"};

    //- Fall height for an impact at about 1 m/s [m]
    const scalar fall1 = 0.051;


    //- A world of cylinders or rings in a tube, the paper's materials
    struct meshScene
    {
        tube container;
        autoPtr<pelletShape> shape;
        simulationControls controls;
        pelletMaterial material;
        autoPtr<world> w;
        penetrationProbe probe;

        meshScene
        (
            const scalar tubeDiameter,
            const std::string& pellets,
            const std::string& simulation = sleepOn,
            const scalar rollingFriction = 0
        )
        :
            container(tubeDiameter, 1, 0.6, 0.6),
            shape(pelletShape::New(parseDict(pellets))),
            controls(simulationDict(simulation)),
            material{8030, 0.1, 0.9, rollingFriction},
            w(),
            probe(shape->mesh())
        {
            w.reset(new world(container, shape(), material, true, controls));
        }

        world& operator()()
        {
            return w();
        }

        //- Energy scale n m g dp [J]
        scalar energyScale() const
        {
            return w->bodies().size()*w->bodies()[0].mass()*9.81*dp;
        }

        //- Lowest z of the mesh of a pellet of orientation q centred at
        //  the origin [m]
        scalar meshLowest(const quaternion& q) const
        {
            const tmp<pointField> tp =
                shape->mesh().transformedPoints(tensor(q.R()), Zero);
            return min(tp().component(vector::Z));
        }

        //- Lowest z of the exact cylinder (d = h = dp) of orientation q
        //  centred at the origin, the hull the container contacts use [m]
        scalar hullLowest(const quaternion& q) const
        {
            const scalar uz = (tensor(q.R()) & vector(0, 0, 1)).z();
            return -0.5*dp*(mag(uz) + Foam::sqrt(max(1 - sqr(uz), 0.0)));
        }

        //- Add a pellet with orientation q whose lowest point (of the
        //  exact hull, or of the mesh) is at height z over (x, y);
        //  returns its index
        label addAt
        (
            const scalar x,
            const scalar y,
            const scalar z,
            const quaternion& q,
            const bool hull = true
        )
        {
            return w->addBody
            (
                point(x, y, z - (hull ? hullLowest(q) : meshLowest(q))), q
            );
        }

        //- Add a pellet with orientation q whose lowest mesh vertex is at
        //  p; returns its index
        label addLowestAt(const point& p, const quaternion& q)
        {
            const tmp<pointField> tp =
                shape->mesh().transformedPoints(tensor(q.R()), Zero);
            label low = 0;
            forAll(tp(), j)
            {
                if (tp()[j].z() < tp()[low].z())
                {
                    low = j;
                }
            }
            return w->addBody(p - tp()[low], q);
        }
    };


    //- Steps a mesh scene, checking the invariants at every step
    struct monitor
    {
        meshScene& s;
        label badStates = 0;
        scalar maxEscape = -GREAT;

        //- Largest penetration the probe found [m]
        scalar maxProbe = -GREAT;

        void check()
        {
            world& w = s();
            const UList<rigidBody>& bs = w.bodies();
            for (const rigidBody& b : bs)
            {
                if (!finiteState(b))
                {
                    ++badStates;
                    continue;
                }
                const tmp<pointField> tp =
                    s.shape->mesh().transformedPoints(b.R(), b.x());
                for (const point& p : tp())
                {
                    maxEscape = max(maxEscape, -p.z());
                    maxEscape = max
                    (
                        maxEscape,
                        tube::axialDistance(p) - s.container.radius()
                    );
                }
            }
            forAll(bs, i)
            {
                for (label k = i + 1; k < bs.size(); ++k)
                {
                    if (!w.sleeping()[i] || !w.sleeping()[k])
                    {
                        maxProbe =
                            max(maxProbe, s.probe.penetration(bs[i], bs[k]));
                    }
                }
            }
        }

        //- Step until time t; returns the steps taken
        label runUntil(const scalar t, const scalar hMax = 0.025)
        {
            label steps = 0;
            while (s().time() < t - SMALL)
            {
                s().step(min(hMax, t - s().time()));
                check();
                ++steps;
            }
            return steps;
        }

        //- Run until the kinetic energy stays below energy [J] for
        //  quiet [s], at most until tMax [s]; returns the time it settled,
        //  or GREAT
        scalar settle(const scalar energy, const scalar quiet,
            const scalar tMax)
        {
            scalar calmSince = -1;
            while (s().time() < tMax)
            {
                runUntil(s().time() + 0.01);
                if (s().kineticEnergy() < energy)
                {
                    if (calmSince < 0)
                    {
                        calmSince = s().time();
                    }
                    if (s().time() - calmSince >= quiet)
                    {
                        return s().time();
                    }
                }
                else
                {
                    calmSince = -1;
                }
            }
            return GREAT;
        }

        //- Largest displacement of any pellet over further time dt [m];
        //  the kinetic energy may not rise meanwhile
        scalar creep(const scalar dt)
        {
            const UList<rigidBody>& bs = s().bodies();
            List<point> x(bs.size());
            forAll(x, i)
            {
                x[i] = bs[i].x();
            }
            const scalar E0 = s().kineticEnergy();
            scalar Emax = E0;
            for (label k = 0; k < 20; ++k)
            {
                runUntil(s().time() + dt/20);
                Emax = max(Emax, s().kineticEnergy());
            }
            EXPECT_LE(Emax, E0*(1 + 1e-6) + 1e-15);
            scalar m = 0;
            forAll(x, i)
            {
                m = max(m, mag(bs[i].x() - x[i]));
            }
            return m;
        }

        //- Settle within tMax, then no creep over one more second
        void settleAndHold(const std::string& what, const scalar tMax)
        {
            const scalar t = settle(1e-7*s.energyScale(), 0.5, tMax);
            EXPECT_LT(t, tMax) << what;
            const scalar c = creep(1);
            EXPECT_LT(c, 1e-4*dp) << what;
            report(what);
        }

        void report(const std::string& what) const
        {
            std::cout
                << "[ measured ] " << what << ": t " << s().time()
                << " s, steps " << s().stats().steps
                << ", maxOverlap " << 100*s().stats().maxOverlap/dp
                << " % dp, probe " << 100*maxProbe/dp
                << " % dp, escape " << 100*maxEscape/dp
                << " % dp, energy gain "
                << s().stats().maxCollisionEnergyGain << std::endl;
        }

        void expectHealthy(const std::string& what) const
        {
            EXPECT_EQ(badStates, 0) << what;
            EXPECT_LT(maxEscape, overlapTolerance) << what;
            EXPECT_LT(s().stats().maxOverlap, overlapTolerance) << what;
            EXPECT_LT(maxProbe, overlapTolerance) << what;
            EXPECT_LT(s().stats().maxCollisionEnergyGain, 1e-9) << what;
        }
    };

    quaternion about(const vector& axis, const scalar degrees)
    {
        return quaternion
        (
            axis/mag(axis), degrees*constant::mathematical::pi/180
        );
    }
}


// * * * * * * * * * * * * * * * The probe itself * * * * * * * * * * * * * //

TEST(stabilityMesh, probeMeasuresKnownDepths)
{
    for (const std::string& dict : {cylinderDict, ringDict})
    {
        meshScene s(0.05, dict);
        const penetrationProbe& pr = s.probe;

        // The pieces tile the cross-section: the volume of the mesh
        EXPECT_NEAR
        (
            pr.area()*dp, s.shape->mesh().volume(),
            1e-9*s.shape->mesh().volume()
        ) << dict;
        EXPECT_EQ(pr.nPieces() > 1, dict == ringDict);

        // Coaxial, 0.1 mm closer than the height: 0.1 mm deep
        const auto body = [](const point& x, const quaternion& q)
        {
            return rigidBody(1, vector::one, x, q, true);
        };
        const rigidBody B(body(point(0, 0, 0), quaternion(1)));
        const quaternion turned(about(vector(0, 0, 1), 7));
        EXPECT_NEAR
        (
            pr.penetration(body(point(0, 0, 0.0099), turned), B), 1e-4,
            1e-12
        ) << dict;
        EXPECT_NEAR
        (
            pr.penetration(body(point(0, 0, 0.0101), turned), B), -1e-4,
            1e-12
        ) << dict;

        // Lying across the top cap 20 um deep, along either axis; a
        // ring's lowest side edge then runs along the cuts of the other's
        // pieces through its hole's vertices at 0 and 180 degrees, which
        // reads cos(180/n) of the depth, n the polygon's sides (in general
        // a cut through the deepest point reads at least cos 45 of it)
        const quaternion lying(about(vector(0, 1, 0), 90));
        const scalar up = -s.meshLowest(lying);
        for (const scalar turn : {0.0, 90.0, 10.0})
        {
            const quaternion q(about(vector(0, 0, 1), turn)*lying);
            const scalar d =
                pr.penetration(body(point(0, 0, 0.005 + up - 2e-5), q), B);
            if (dict == ringDict && turn != 10)
            {
                EXPECT_GT(d, 0.95*2e-5) << turn;
                EXPECT_LT(d, 2e-5 + 1e-12) << turn;
            }
            else
            {
                EXPECT_NEAR(d, 2e-5, 1e-12) << dict << turn;
            }
        }

        // Two lying crossed, side edge on side edge 20 um deep (no vertex
        // of either is inside the other), then 1 mm apart
        const scalar top = max
        (
            s.shape->mesh().transformedPoints(tensor(lying.R()), Zero)()
           .component(vector::Z)
        );
        const rigidBody D(body(point(0, 0, 0), lying));
        const quaternion crossed(about(vector(0, 0, 1), 90)*lying);
        EXPECT_NEAR
        (
            pr.penetration(body(point(0, 0, top + up - 2e-5), crossed), D),
            2e-5, 1e-12
        ) << dict;
        EXPECT_NEAR
        (
            pr.penetration(body(point(0, 0, top + up + 1e-3), crossed), D),
            -1e-3, 1e-12
        ) << dict;
    }

    // A ring's hole: a ring tilted by 45 degrees with its lowest rim
    // point on the axis of another, 0.5 mm below its top, is inside the
    // hole (its section there is 5.1 mm wide, the hole 6 mm), not in the
    // wall; moved 1 mm sideways it is in the wall
    meshScene s(0.05, ringDict);
    const rigidBody B(1, vector::one, point(0, 0, 0), quaternion(1), true);
    const quaternion q(about(vector(1, 0, 0), 45));
    const tmp<pointField> tp =
        s.shape->mesh().transformedPoints(tensor(q.R()), Zero);
    label low = 0;
    forAll(tp(), j)
    {
        if (tp()[j].z() < tp()[low].z())
        {
            low = j;
        }
    }
    const point x0(point(0, 0, 0.0045) - tp()[low]);
    const rigidBody inHole(1, vector::one, x0, q, true);
    EXPECT_LT(s.probe.penetration(inHole, B), -1e-4);
    const rigidBody inWall
    (
        1, vector::one, x0 + vector(0.001, 0, 0), q, true
    );
    EXPECT_GT(s.probe.penetration(inWall, B), 1e-4);
}


// * * * * * * * * * * * * * * * * * Rings * * * * * * * * * * * * * * * * //

TEST(stabilityMesh, ringsStackedInATube)
{
    // Three rings dropped coaxially onto each other in a tube too narrow
    // for them to turn over (13 mm): the second exactly coaxial (vertex
    // onto vertex, edges onto parallel edges), the third turned by 7
    // degrees about the axis and tilted by 2 (rims crossing)
    for (const std::string& simulation : ringModels)
    {
        const std::string what = "rings stacked, " + simulation;
        meshScene s(0.013, ringDict, simulation);
        s.addAt(0, 0, 0, quaternion(1));
        s.addAt(0, 0, 0.01 + 0.025, quaternion(1));
        s.addAt(0.0003, 0, 0.02 + 0.06,
            about(vector(0, 0, 1), 7)*about(vector(1, 0, 0), 2));
        monitor m{s};
        m.settleAndHold(what, 3);
        m.expectHealthy(what);
    }
}


TEST(stabilityMesh, ringHookedOntoARingOnTheFloor)
{
    // A ring lying on the floor of a tube too narrow (18 mm) for a second
    // one to lie beside it; the second, tilted, starts with its lowest rim
    // point 0.5 mm inside the hole of the first: the rim slides down
    // into the hole and catches on the inner edge (nonconvex contact),
    // the ring tips over onto the first and stays hooked with its rim
    // inside the hole
    // (tilt [deg], offset of the lowest point from the axis [m])
    const std::pair<scalar, scalar> starts[] =
        {{45, -0.001}, {45, 0.001}, {60, 0.001}};
    for (const std::string& simulation : ringModels)
    for (const auto& start : starts)
    {
        const scalar tilt = start.first;
        const scalar y = start.second;
        meshScene s(0.018, ringDict, simulation);
        s.addAt(0, 0, 0, quaternion(1));
        s.addLowestAt(point(0, y, 0.0095), about(vector(1, 0, 0), tilt));
        monitor m{s};
        m.check();
        ASSERT_LT(m.maxEscape, 1e-12);
        ASSERT_LT(m.maxProbe, 0);

        const std::string what =
            "ring hooked, tilt " + std::to_string(tilt)
          + ", y " + std::to_string(y) + ", " + simulation;
        m.settleAndHold(what, 4);
        m.expectHealthy(what);

        // Hooked: the lowest point of the upper ring is inside the
        // hole of the lower, below its top
        const rigidBody& b = s().bodies()[1];
        const tmp<pointField> tp =
            s.shape->mesh().transformedPoints(b.R(), b.x());
        label low = 0;
        forAll(tp(), j)
        {
            if (tp()[j].z() < tp()[low].z())
            {
                low = j;
            }
        }
        const point& p = tp()[low];
        EXPECT_LT(p.z(), 0.01 - 1e-4) << what;
        EXPECT_LT(tube::axialDistance(p - s().bodies()[0].x()), 0.003)
            << what;
    }
}


// * * * * * * * * * * * * * * * * Cylinders * * * * * * * * * * * * * * * //

class cylinderOntoFloor : public ::testing::TestWithParam<std::string> {};

TEST_P(cylinderOntoFloor, onAnEdgeAndOnACorner)
{
    // Side edge first (axis horizontal), rim corner first (axis tilted 30
    // degrees), at about 1 m/s
    for (const scalar tilt : {90.0, 30.0})
    {
        meshScene s
        (
            0.04, cylinderDict, sleepOn + "contactModel " + GetParam() + ";"
        );
        s.addAt(0, 0, fall1, about(vector(1, 0, 0), tilt));
        monitor m{s};
        const std::string what =
            "cylinder onto floor, tilt " + std::to_string(tilt)
          + ", " + GetParam();
        m.settleAndHold(what, 4);
        m.expectHealthy(what);
    }
}

INSTANTIATE_TEST_SUITE_P
(
    stabilityMesh, cylinderOntoFloor,
    ::testing::Values("auto", "mesh", "exact")
);


//- The lower cylinder lies on its side along x; the upper one lands on it
//  at about 1 m/s in the orientation q, its centre over (x, 0.3 mm)
struct cylinderDrop
{
    const char* name;
    vector axis;
    scalar degrees;
    scalar x;
};

void PrintTo(const cylinderDrop& d, std::ostream* os)
{
    *os << d.name;
}

namespace
{

//- The drops of a cylinder onto a lying one (mesh and exact suites)
const cylinderDrop cylinderDrops[] =
{
    // Crossed, side edge on side edge (edge/edge)
    {"crossed", vector(1, 0, 0), 90, 0},
    // Rim corner first onto the side
    {"cornerOnSide", vector(1, 1, 0), 40, 0.001},
    // Rim onto the rim of the lower one's end
    {"rimOnRim", vector(0, 1, 0), 60, 0.006},
    // Parallel, side on side
    {"parallel", vector(0, 1, 0), 90, 0.0005}
};

std::string dropName(const ::testing::TestParamInfo<cylinderDrop>& info)
{
    return std::string(info.param.name);
}

}

class cylinderOntoACylinder : public ::testing::TestWithParam<cylinderDrop>
{};

TEST_P(cylinderOntoACylinder, lyingOnItsSide)
{
    const cylinderDrop& d = GetParam();
    meshScene s(0.04, cylinderDict, sleepOnMeshes);
    s.addAt(0, 0, 0, about(vector(0, 1, 0), 90));
    s.addAt(d.x, 0.0003, 0.01 + fall1, about(d.axis, d.degrees));
    monitor m{s};
    m.settleAndHold(d.name, 4);
    m.expectHealthy(d.name);
}

INSTANTIATE_TEST_SUITE_P
(
    stabilityMesh, cylinderOntoACylinder, ::testing::ValuesIn(cylinderDrops),
    dropName
);


//- The same drops on the exact solids (contactModel exact): round rims and
//  walls roll without loss, so the rolling resistance of the contacts
//  (rollingResistance) brings the cylinder to rest
class cylinderOntoACylinderExact
:
    public ::testing::TestWithParam<cylinderDrop>
{};

TEST_P(cylinderOntoACylinderExact, lyingOnItsSideComesToRest)
{
    const cylinderDrop& d = GetParam();
    meshScene s
    (
        0.04, cylinderDict, sleepOn + "contactModel exact;",
        packedBed::defaultExactRollingFriction
    );
    s.addAt(0, 0, 0, about(vector(0, 1, 0), 90));
    s.addAt(d.x, 0.0003, 0.01 + fall1, about(d.axis, d.degrees));
    monitor m{s};
    m.settleAndHold(d.name, 4);
    m.expectHealthy(d.name);
}

INSTANTIATE_TEST_SUITE_P
(
    stabilityMesh, cylinderOntoACylinderExact,
    ::testing::ValuesIn(cylinderDrops), dropName
);


TEST(stabilityMesh, cylindersStartingInContactWithTheWallAndEachOther)
{
    // Upright on the floor: A touching the wall, B touching A side face
    // to side face (of their polygons); C lying on both, a hair too high;
    // D lying on its side against the wall: exact contact (gap 0)
    // everywhere at the start
    meshScene s(0.034, cylinderDict, sleepOnMeshes);
    const pointField& pts = s.shape->mesh().points();
    const scalar a = 0.5*dp;
    const scalar R = s.container.radius();

    // The normal of a side face of the polygon, and the apothem
    const vector2D p0(pts[0].x(), pts[0].y());
    ASSERT_NEAR(mag(p0), a, 1e-12);
    // (the midpoint of p0 and a neighbour on the polygon is the farthest
    // from the axis)
    scalar apothem = 0;
    vector2D side(Zero);
    for (const point& p : pts)
    {
        const vector2D q(p.x(), p.y());
        if (mag(mag(q) - a) < 1e-12 && mag(q - p0) > 1e-9)
        {
            const scalar h = mag(0.5*(q + p0));
            if (h > apothem + 1e-12)
            {
                apothem = h;
                side = 0.5*(q + p0)/h;
            }
        }
    }
    const vector n(side.x(), side.y(), 0);
    const vector t(n ^ vector(0, 0, 1));

    const point xA(-(R - a)*n);
    const point xB(xA + 2*apothem*n);
    s.addAt(xA.x(), xA.y(), 0, quaternion(1));
    // (B turned half a turn: its side face opposite A's is A's)
    s.addAt(xB.x(), xB.y(), 0, about(vector(0, 0, 1), 180));
    const point xC(0.5*(xA + xB));
    s.addAt(xC.x(), xC.y(), 0.01 + 1e-6, about(t, 90), false);
    const scalar rhoD = Foam::sqrt(sqr(R) - sqr(a)) - a;
    s.addAt(rhoD*n.x(), rhoD*n.y(), 0, about(n, 90));

    monitor m{s};
    m.check();
    EXPECT_LT(m.maxProbe, 1e-9);
    m.settleAndHold("starting in contact", 3);
    m.expectHealthy("starting in contact");
}


TEST(stabilityMesh, aSettledPileOfCylindersFallsAsleep)
{
    // Ten cylinders (200 faces) released tilted by 45 degrees one above
    // the other in a 33.65 mm tube (N = 3.37), the paper's materials:
    // once settled, every one sleeps. With the exact resting forces
    // (restingCompliance 0) the redundant mesh contacts' forces jumped
    // between vertices of their solution set and the settled cylinders
    // turned at 0.1-0.3 rad/s for ever: none slept in 5 s
    meshScene s
    (
        0.03365,
        "shape cylinder; diameter 0.01; height 0.01; faces 200;",
        sleepOnMeshes
    );
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> U(-1, 1);
    for (label n = 0; n < 10; ++n)
    {
        const vector axis(U(rng), U(rng), 0);
        s.addAt
        (
            0.001*U(rng), 0.001*U(rng), 0.001 + 0.016*n,
            about(axis, 45), false
        );
    }
    monitor m{s};
    scalar asleep = GREAT;
    while (s().time() < 5 && asleep == GREAT)
    {
        m.runUntil(s().time() + 0.05);
        if (s().nSleeping() == 10)
        {
            asleep = s().time();
        }
    }
    EXPECT_LT(asleep, 5);
    m.report("pile of ten cylinders");
    m.expectHealthy("pile of ten cylinders");
}

TEST(stabilityMesh, fastPelletsThrownOntoAPileStopAtTheirFirstTouch)
{
    // Two pellets lying side by side on the floor, four more thrown down onto
    // them at 8 m/s spinning at 60 rad/s (a fall from 3.3 m): the thrown
    // ones are swept through the steps of the pile (pelletSweep) and must
    // stop at their first touch, never in or through a pellet or the
    // floor. Exact cylinders, and rings on meshes; the same scene with
    // sweepSpeed 0 (every pellet bounds the step) for comparison; three
    // seeds of the throw. Measured: 0.54-0.90 of the steps of sweepSpeed
    // 0; largest overlap 0.012-0.21 % dp against 0.012-0.33 (cylinders),
    // 0.0004-0.0045 against 0.03-0.10 (rings). The build that left the
    // swept pellets' contacts out of the resting solve let a pellet the
    // solve pushed go 0.7 % dp into a swept one's start; the one whose
    // spin counted against its approach, 8 % dp
    for (const std::string& pellets : {cylinderDict, ringDict})
    for (const std::string sweepSpeed : {"0.5", "0"})
    for (const unsigned seed : {1u, 2u, 3u})
    {
        {
            const std::string what =
                pellets.substr(6, pellets.find(';') - 6) + ", sweepSpeed "
              + sweepSpeed + ", seed " + std::to_string(seed);
            meshScene s
            (
                0.04, pellets,
                (pellets == ringDict ? sleepOnMeshes : sleepOn)
              + " sweepSpeed " + sweepSpeed + ";"
            );
            std::mt19937 rng(seed);
            std::uniform_real_distribution<double> U(-1, 1);
            for (const scalar x : {-0.006, 0.006})
            {
                s.addAt(x, 0, 0.0005, about(vector(1, 0, 0), 90), false);
            }
            for (label n = 0; n < 4; ++n)
            {
                const label i = s.addAt
                (
                    0.004*U(rng), 0.004*U(rng), 0.03 + 0.015*n,
                    about(vector(U(rng), U(rng), U(rng)), 180*U(rng)), false
                );
                s().setVelocity
                (
                    i, vector(0, 0, -8),
                    60*vector(U(rng), U(rng), U(rng))/Foam::sqrt(3.0)
                );
            }
            monitor m{s};
            m.runUntil(0.3);
            m.report(what);
            std::cout
                << "[ measured ] " << what << ": "
                << s().stats().sweptSteps << " swept pellet steps, "
                << s().stats().sweepStops << " stopped at a touch"
                << std::endl;
            m.expectHealthy(what);
            if (sweepSpeed == "0")
            {
                EXPECT_EQ(s().stats().sweptSteps, 0) << what;
            }
            else
            {
                EXPECT_GT(s().stats().sweptSteps, 0) << what;
            }
        }
    }
}


// ************************************************************************* //

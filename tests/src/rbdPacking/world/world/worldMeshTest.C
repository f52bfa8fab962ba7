// Nonspherical pellets in src/rbdPacking/world (triangle-mesh narrow
// phase): resting on a face, falling off a rim, lying on the side, a
// nonconvex ring contact, a user STL pellet and a small bed of cylinders.
// Coarse meshes (100-300 faces) keep these fast.

#include <gtest/gtest.h>
#include <algorithm>
#include "../../testTools/worldFixture.H"
#include "OFstream.H"
#include <random>
#include <unistd.h>

using namespace rbdTest;

namespace
{
    //- A world of one nonspherical shape in a tube
    struct shapeScene
    {
        tube container;
        autoPtr<pelletShape> shape;
        simulationControls controls;
        pelletMaterial material;
        autoPtr<world> w;

        shapeScene
        (
            const scalar tubeDiameter,
            const std::string& pellets,
            const std::string& simulation = "",
            const scalar mu = 0.3,
            const scalar e = 0.3,
            const scalar muRolling = 0
        )
        :
            container(tubeDiameter, 1, mu, e),
            shape(pelletShape::New(parseDict(pellets))),
            controls(simulationDict(simulation)),
            material{8030, mu, e, muRolling},
            w()
        {
            w.reset(new world(container, shape(), material, true, controls));
        }

        world& operator()()
        {
            return w();
        }

        //- Largest distance of a mesh vertex outside the tube [m]
        scalar outside() const
        {
            scalar worst = -GREAT;
            for (const rigidBody& b : w->bodies())
            {
                const tmp<pointField> tp =
                    shape->mesh().transformedPoints(b.R(), b.x());
                for (const point& p : tp())
                {
                    worst = max(worst, -p.z());
                    worst = max
                    (
                        worst, tube::axialDistance(p) - container.radius()
                    );
                }
            }
            return worst;
        }

        //- Largest speed of a surface point (|v| + |omega| r_b) [m/s]
        scalar maxSpeed() const
        {
            scalar s = 0;
            for (const rigidBody& b : w->bodies())
            {
                s = max
                (
                    s, mag(b.v()) + mag(b.omega())*shape->boundingRadius()
                );
            }
            return s;
        }
    };

    const std::string cylinder10 =
        "shape cylinder; diameter 0.01; height 0.01; faces 150;";

    vector axisOf(const rigidBody& b)
    {
        return b.R() & vector(0, 0, 1);
    }
}


class restingCylinder : public ::testing::TestWithParam<std::string> {};

TEST_P(restingCylinder, onItsFaceStays)
{
    // Exact resting forces (restingCompliance 0): at rest to round-off.
    // Compliant (the default): the face's contacts sink by the compliance
    // each step until the overlap correction lifts them at the slop
    // (contactTolerance dp = 1e-6 m): the cylinder saws between the floor
    // and the slop, never further, well below 1 um/s
    const scalar slop = 1e-4*0.01;
    for (const bool exact : {true, false})
    {
        shapeScene s
        (
            0.05, cylinder10,
            "contactModel " + GetParam() + ";"
          + (exact ? "restingCompliance 0;" : "")
        );
        const point x0(0.003, -0.002, 0.005);
        s().addBody(x0, quaternion(1));

        s().advance(10);
        const rigidBody& b = s().bodies()[0];
        std::cout
            << "[ measured ] exact " << exact << ": drift "
            << mag(b.x() - x0) << " m, speed " << s.maxSpeed()
            << " m/s, overlap " << s().stats().maxOverlap << " m"
            << std::endl;
        EXPECT_GT(axisOf(b).z(), 1 - 1e-9);
        if (exact)
        {
            EXPECT_LT(mag(b.x() - x0), 1e-6);
            EXPECT_LT(s.maxSpeed(), 1e-6);
            EXPECT_LT(s().currentMaxOverlap(), 1e-6);
            EXPECT_LT(s().stats().maxOverlap, 1e-6);
        }
        else
        {
            EXPECT_LT(mag(b.x() - x0), slop);
            EXPECT_LT(s.maxSpeed(), 1e-5);
            EXPECT_LT(s().currentMaxOverlap(), 1.05*slop);
            EXPECT_LT(s().stats().maxOverlap, 1.05*slop);
        }
    }
}

TEST_P(restingCylinder, lyingOnItsSideStays)
{
    shapeScene s(0.05, cylinder10, "contactModel " + GetParam() + ";");

    // Axis along x; the mesh (a prism on a polygon with a vertex at angle
    // 0 about z) then has a vertex row at the bottom when rotated this way
    const quaternion q(vector(0, 1, 0), 0.5*M_PI);
    const tmp<pointField> tp =
        s.shape->mesh().transformedPoints(tensor(q.R()), Zero);
    scalar zMin = GREAT;
    for (const point& p : tp())
    {
        zMin = min(zMin, p.z());
    }
    const bool mesh = GetParam() == "mesh";
    const point x0(0, 0.004, mesh ? -zMin : 0.005);
    s().addBody(x0, q);

    s().advance(10);
    const rigidBody& b = s().bodies()[0];
    EXPECT_LT(mag(b.x() - x0), 2e-5);
    EXPECT_LT(mag(axisOf(b).z()), 1e-3);
    EXPECT_LT(s.maxSpeed(), 1e-4);
    EXPECT_LT(s().currentMaxOverlap(), 1e-6);
}

TEST(rollingResistance, aRollingCylinderComesToRest)
{
    // A cylinder lying on the floor of a wide tube, rolling at 0.05 m/s
    // (omega = v/r about its axis): on the exact round wall it rolls
    // without loss, unless the contact resists rolling. mu_r = 0.1
    // decelerates it at about mu_r g/(1.5) ~ 0.65 m/s^2: at rest (and
    // asleep) well within 0.5 s, a few millimetres on, still lying; with
    // mu_r = 0 it is still rolling after the same time
    const scalar r = 0.005;
    const scalar v = 0.05;
    for (const scalar muR : {0.0, 0.1})
    {
        shapeScene s
        (
            0.1, cylinder10, "contactModel exact; sleepVelocity 0.001;",
            0.3, 0.3, muR
        );
        const quaternion q(vector(1, 0, 0), 0.5*M_PI);
        const point x0(0, 0, r);
        s().addBody(x0, q);
        // Axis along -y; rolling towards +x: omega = (v/r) (0, 1, 0) x ...
        s().setVelocity(0, vector(v, 0, 0), vector(0, v/r, 0));

        s().advance(0.5);
        const rigidBody& b = s().bodies()[0];
        const scalar speed = mag(b.v());
        Info<< "[ measured ] mu_r " << muR << ": travelled "
            << b.x().x() - x0.x() << " m, speed " << speed << " m/s"
            << endl;
        EXPECT_LT(mag(axisOf(b).z()), 1e-3);
        EXPECT_NEAR(b.x().z(), r, 2e-6);
        if (muR > 0)
        {
            EXPECT_LT(speed, 1e-4);
            EXPECT_LT(b.x().x() - x0.x(), sqr(v)/(2*0.5*muR*9.81) + 1e-3);
        }
        else
        {
            EXPECT_GT(speed, 0.9*v);
        }
    }
}

TEST_P(restingCylinder, balancedOnItsRimFallsAndComesToRest)
{
    shapeScene s(0.05, cylinder10, "contactModel " + GetParam() + ";");

    // d = h: balanced at 45 degrees; 50 degrees falls onto the side
    const scalar tilt = 50*M_PI/180;
    const scalar z = 0.005*(Foam::cos(tilt) + Foam::sin(tilt)) + 1e-6;
    s().addBody(point(0, 0, z), quaternion(vector(1, 0, 0), tilt));

    // (3 s: the mesh cylinder may land on its side on a vertex row of its
    // polygon, an unstable equilibrium it leaves for a face after a time
    // round-off decides: 0.9 s in one run, toppled and at rest at 1.5 s)
    s().advance(3);
    const rigidBody& b = s().bodies()[0];
    EXPECT_LT(mag(axisOf(b).z()), 0.02);
    EXPECT_NEAR(b.x().z(), 0.005, 5e-4);
    EXPECT_LT(s.maxSpeed(), 1e-3);
    EXPECT_LT(s().stats().maxOverlap, 5e-5);
}

INSTANTIATE_TEST_SUITE_P
(
    contactModels, restingCylinder,
    ::testing::Values("auto", "mesh", "exact")
);


TEST(worldMesh, ringIntoTheHoleOfAnotherSettlesWithoutJitter)
{
    // Washers (10/6/2 mm): the upper one stands on edge over the hole of
    // the lower one and sinks into it (nonconvex contact with the inner
    // rim), then tips over and settles; on the triangle meshes and on the
    // exact solids (contactModel auto's for rings)
    for (const std::string model : {"mesh", "exact"})
    {
        SCOPED_TRACE("contactModel " + model);
        shapeScene s
        (
            0.04, "shape ring; diameter 0.01; innerDiameter 0.006; "
            "height 0.002; faces 300;", "contactModel " + model + ";"
        );
        s().addBody(point(0, 0, 0.001), quaternion(1));
        s().addBody
        (
            point(0, 0, 0.0075), quaternion(vector(0, 1, 0), 0.5*M_PI)
        );

        scalar lowest = GREAT;
        while (s().time() < 2)
        {
            s().step(0.025);
            lowest = min(lowest, s().bodies()[1].x().z());
        }

        // It went into the hole: the centre came below 5 mm + 2 mm
        // (resting on top of the washer would leave it at 7 mm)
        EXPECT_LT(lowest, 0.0068);

        // Settled, no jitter: nothing moves over the last half second
        scalar fastest = 0;
        const point x0(s().bodies()[1].x());
        while (s().time() < 2.5)
        {
            s().step(0.025);
            fastest = max(fastest, s.maxSpeed());
        }
        EXPECT_LT(fastest, 2e-3);
        EXPECT_LT(mag(s().bodies()[1].x() - x0), 1e-4);
        EXPECT_LT(s().currentMaxOverlap(), 5e-5);
        // Largest overlap of the run within the target, 0.5 % dp (measured
        // 0.002 % dp; 1.04 % dp before the rim crossing the other's side edge
        // below its cap was no longer taken for a 0.7 mm deep contact)
        EXPECT_LE(s().stats().maxOverlap, 0.005*s.shape->diameter());
        EXPECT_LT(s.outside(), 1e-6);
    }
}


TEST(worldMesh, washersDroppedOnEachOtherOverlapWithinTarget)
{
    // Two washers (10/6/2 mm) at random orientations dropped 12 mm apart.
    // A rim vertex on the other washer's flat face also projects onto its
    // wall faces, at the wall's edge, and was reported as deep as it is
    // inside the wall's plane (1.1-4.4 % dp with these seeds) and pushed
    // sideways; the largest overlap of the run is now within 0.5 % dp.
    // On the triangle meshes and on the exact solids
    for (const std::string model : {"mesh", "exact"})
    for (const unsigned seed : {6u, 7u, 8u})
    {
        SCOPED_TRACE("contactModel " + model);
        shapeScene s
        (
            0.03, "shape ring; diameter 0.01; innerDiameter 0.006; "
            "height 0.002; faces 300;", "contactModel " + model + ";"
        );
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> U(-1, 1);
        for (label n = 0; n < 2; ++n)
        {
            const vector axis(U(rng), U(rng), U(rng));
            s().addBody
            (
                point(0.002*U(rng), 0.002*U(rng), 0.006 + 0.012*n),
                quaternion(axis/mag(axis), 3*U(rng))
            );
        }
        s().advance(0.4);

        // They met: the upper one rests on or beside the lower one
        EXPECT_LT(s().bodies()[1].x().z(), 0.012) << "seed " << seed;
        EXPECT_LE(s().stats().maxOverlap, 0.005*s.shape->diameter())
            << "seed " << seed;
        EXPECT_LT(s.outside(), 0.005*s.shape->diameter());
    }
}


TEST(worldMesh, userTetrahedronPelletsPackInASmallTube)
{
    // Regular tetrahedron, edge 10 mm, as an ASCII STL file
    const fileName file
    (
        "/tmp/rbdWorldMeshTest-" + std::to_string(::getpid()) + "-tet.stl"
    );
    {
        const scalar e = 10;
        const point v[4] =
        {
            point(0, 0, 0), point(e, 0, 0),
            point(0.5*e, 0.5*Foam::sqrt(3.0)*e, 0),
            point(0.5*e, Foam::sqrt(3.0)/6*e, Foam::sqrt(2.0/3.0)*e)
        };
        const label f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
        OFstream os(file);
        os  << "solid tet" << nl;
        for (const auto& t : f)
        {
            const vector n((v[t[1]] - v[t[0]]) ^ (v[t[2]] - v[t[0]]));
            os  << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z()
                << nl << "outer loop" << nl;
            for (label j = 0; j < 3; ++j)
            {
                os  << "vertex " << v[t[j]].x() << ' ' << v[t[j]].y() << ' '
                    << v[t[j]].z() << nl;
            }
            os  << "endloop" << nl << "endfacet" << nl;
        }
        os  << "endsolid tet" << nl;
    }

    // Six seeds. The largest overlap of a run: the target is 0.5 % dp,
    // not met here in general. The runs are chaotic, and the tetrahedra's
    // acute edges make contacts that are taken too deep or missed (see
    // patchSeparation.H): a run that is quiet can find a contact 0.4 mm
    // deep in one step. Measured (% dpv, seeds 1-12): 0.40, 1.06, 6.9,
    // 0.76, 0.34, 0.78, 0.49, 0.80, 0.51, 0.28, 0.31, 1.41 (the build
    // before the per-body broad phase, on other trajectories: seeds 1-6
    // 0.42, 0.076, 6.9, 0.45, 0.44, 0.78, seeds 7-12 0.3-1.4); with the
    // staggered friction of earlier versions seven of seeds 1-12 were
    // above 2.5 (up to 10). Any change of a step's contacts or length
    // (their order, the broad phase's bound) gives other trajectories,
    // so the runs are judged as a sample, not one by one: at most one
    // run in six above 2 %, and it below 10 % (the known gap of
    // docs/history.md, Known limitations: one run in six overlaps by
    // several % dpv); their median below 1 %; the other checks every run
    label above2 = 0;
    std::vector<scalar> overlaps;
    for (unsigned seed = 1; seed <= 6; ++seed)
    {
        shapeScene s
        (
            0.025,
            "shape stl; file \"" + file + "\"; scale 0.001;"
        );

        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> U(-1, 1);
        for (label n = 0; n < 6; ++n)
        {
            const vector axis(U(rng), U(rng), U(rng));
            s().addBody
            (
                point(0.003*U(rng), 0.003*U(rng), 0.01 + 0.014*n),
                quaternion(axis/mag(axis), 3*U(rng))
            );
        }
        s().advance(2.5);

        EXPECT_LT(s.outside(), 5e-5) << "seed " << seed;
        EXPECT_LT(s().currentMaxOverlap(), 5e-5) << "seed " << seed;
        EXPECT_LT(s.maxSpeed(), 0.05) << "seed " << seed;
        for (const rigidBody& b : s().bodies())
        {
            EXPECT_LT(b.x().z(), 0.03) << "seed " << seed;
        }
        overlaps.push_back(s().stats().maxOverlap/s.shape->diameter());
        std::cout
            << "[ measured ] tetrahedra, seed " << seed << ": largest overlap "
            << 100*overlaps.back() << " % dpv" << std::endl;
        EXPECT_LT(overlaps.back(), 0.10) << "seed " << seed;
        above2 += overlaps.back() > 0.02;
    }
    std::remove(file.c_str());

    EXPECT_LE(above2, 1);
    std::sort(overlaps.begin(), overlaps.end());
    EXPECT_LT(0.5*(overlaps[2] + overlaps[3]), 0.01);
}


TEST(worldMesh, smallBedOfCylindersSettlesInsideTheTube)
{
    shapeScene s
    (
        0.03,
        "shape cylinder; diameter 0.005; height 0.005; faces 100;",
        "", 0.3, 0.5
    );
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1, 1);
    for (label n = 0; n < 10; ++n)
    {
        const vector axis(U(rng), U(rng), U(rng));
        s().addBody
        (
            point(0.007*U(rng), 0.007*U(rng), 0.005 + 0.0075*n),
            quaternion(axis/mag(axis), 3*U(rng))
        );
    }
    s().advance(0.8);

    const scalar dp = 0.005;
    // Ten cylinders, 0.8 s (20 cylinders, 1 s took 13-40 s). Overlap
    // within the target, 0.5 % dp, settled and during the run (measured
    // 0.18 % dp; up to 2.5 % dp before the fixes of issue 4)
    EXPECT_LE(s().currentMaxOverlap(), 0.005*dp);
    EXPECT_LE(s().stats().maxOverlap, 0.005*dp);
    EXPECT_LT(s.outside(), 0.005*dp);
    for (const rigidBody& b : s().bodies())
    {
        EXPECT_LT(b.x().z(), 0.03);
    }
}

// Unit tests for src/rbdPacking/analysis/correlations: hand-computed values
// of each formula, limits, and the fit statistics

#include <gtest/gtest.h>
#include "correlations.H"
#include "mathematicalConstants.H"

#include <cmath>

using namespace Foam;
namespace corr = Foam::rbd::correlations;

namespace
{
    //- A field from values (a braced pair would read as (size, value))
    scalarField field(std::initializer_list<scalar> values)
    {
        return scalarField(values);
    }
}

TEST(correlations, bulkPorosityByHand)
{
    // 0.4 + 0.05/5.6 + 0.412/5.6^2
    EXPECT_NEAR(corr::dixonSpheres(5.6), 0.4220663265, 1e-9);
    EXPECT_NEAR(corr::dixonCylinders(5), 0.408, 1e-12);
    EXPECT_NEAR(corr::foumenySpheres(5), 0.4185589195, 1e-9);
    EXPECT_NEAR(corr::benyahiaONeillSpheres(5.6), 0.4283027058, 1e-9);
    EXPECT_NEAR(corr::benyahiaONeillCylinders(5), 0.4270921334, 1e-9);
    EXPECT_NEAR(corr::benyahiaONeill(10, 1), 0.3633536385, 1e-9);
}

TEST(correlations, bulkPorosityLimits)
{
    // Infinite tube: loose random packing of spheres, eps ~ 0.38-0.40
    EXPECT_NEAR(corr::dixonSpheres(1e6), 0.4, 1e-6);
    EXPECT_NEAR(corr::benyahiaONeillSpheres(1e6), 0.39, 1e-6);
    EXPECT_NEAR(corr::foumenySpheres(1e6), 0.383, 1e-6);

    // The three sphere correlations agree to their scatter (5 %)
    for (const scalar N : {4.0, 5.6, 8.0, 10.0, 15.0, 20.0})
    {
        const scalar d = corr::dixonSpheres(N);
        EXPECT_NEAR(corr::foumenySpheres(N)/d, 1, 0.05) << "N = " << N;
        EXPECT_NEAR(corr::benyahiaONeillSpheres(N)/d, 1, 0.05) << "N = " << N;
    }

    // Foumeny is undefined for 0.723 N <= 1
    EXPECT_TRUE(std::isnan(corr::foumenySpheres(1.3)));
}

TEST(correlations, bulkPorositiesByFamily)
{
    EXPECT_TRUE(corr::familyOf("sphere") == corr::pelletFamily::sphere);
    EXPECT_TRUE(corr::familyOf("cylinder") == corr::pelletFamily::cylinder);
    EXPECT_TRUE(corr::familyOf("ring") == corr::pelletFamily::other);
    EXPECT_TRUE(corr::familyOf("stl") == corr::pelletFamily::other);

    const auto names = [](const List<Tuple2<word, scalar>>& values)
    {
        std::string s;
        for (const auto& v : values)
        {
            s += v.first() + ' ';
        }
        return s;
    };

    // Spheres: each name carries its own formula
    const scalar N = 5.6;
    const auto spheres =
        corr::bulkPorosities(corr::pelletFamily::sphere, N, 1);
    ASSERT_EQ
    (
        names(spheres),
        "dixon foumeny benyahiaONeill benyahiaONeillAnyShape "
    );
    EXPECT_EQ(spheres[0].second(), corr::dixonSpheres(N));
    EXPECT_EQ(spheres[1].second(), corr::foumenySpheres(N));
    EXPECT_EQ(spheres[2].second(), corr::benyahiaONeillSpheres(N));
    EXPECT_EQ(spheres[3].second(), corr::benyahiaONeill(N, 1));

    // Foumeny is undefined at N = 1.3 and left out
    EXPECT_EQ
    (
        names(corr::bulkPorosities(corr::pelletFamily::sphere, 1.3, 1)),
        "dixon benyahiaONeill benyahiaONeillAnyShape "
    );

    // Cylinders: the cylinders' forms, the sphericity in the any-shape one
    const scalar phi = 0.8735804647;
    const auto cylinders =
        corr::bulkPorosities(corr::pelletFamily::cylinder, N, phi);
    ASSERT_EQ
    (
        names(cylinders), "dixon benyahiaONeill benyahiaONeillAnyShape "
    );
    EXPECT_EQ(cylinders[0].second(), corr::dixonCylinders(N));
    EXPECT_EQ(cylinders[1].second(), corr::benyahiaONeillCylinders(N));
    EXPECT_EQ(cylinders[2].second(), corr::benyahiaONeill(N, phi));

    // Anything else: the any-shape form only
    const auto rings =
        corr::bulkPorosities(corr::pelletFamily::other, N, 0.6);
    ASSERT_EQ(names(rings), "benyahiaONeillAnyShape ");
    EXPECT_EQ(rings[0].second(), corr::benyahiaONeill(N, 0.6));
}


TEST(correlations, dixonCylindersAgainstPaperTable2)
{
    // The paper's Table 2 gives Dixon's porosity 0.395 for cylinders
    // d = h = 10 mm at dt/dp = 6.98, i.e. dt/dpv = 6.98/1.1447 = 6.098:
    // the recalled form reproduces the printed three digits
    const scalar pi = constant::mathematical::pi;
    const scalar dpv = corr::dpv(pi/4*0.01*0.01*0.01);
    EXPECT_NEAR(corr::dixonCylinders(0.0698/dpv), 0.395, 5e-4);
}


TEST(correlations, pelletSize)
{
    const scalar pi = constant::mathematical::pi;
    EXPECT_NEAR(corr::sphericity(4.0/3.0*pi, 4*pi), 1, 1e-14);
    EXPECT_NEAR(corr::sphericity(1, 6), 0.8059959770, 1e-9);          // cube
    EXPECT_NEAR(corr::sphericity(pi/4, 1.5*pi), 0.8735804647, 1e-9);  // d = h
    EXPECT_NEAR(corr::dpv(pi/6), 1, 1e-14);
    EXPECT_NEAR(corr::dpv(pi/4), 1.1447142426, 1e-9);  // cylinder d = h = 1
}

TEST(correlations, radialVoidFractionAtWallAndFar)
{
    EXPECT_DOUBLE_EQ(corr::deKlerk(0, 0.4), 1);
    for (const scalar N : {2.61, 3.5, 4.0, 5.6, 8.0, 13.0, 20.0})
    {
        EXPECT_NEAR(corr::mueller(0, N), 1, 1e-14) << "N = " << N;
    }
    // Damped to its bulk value (b = 0.304 - 0.724/N is small for N -> 2.61)
    for (const scalar N : {4.0, 5.6, 8.0, 13.0, 20.0})
    {
        EXPECT_NEAR(corr::mueller(80, N), corr::muellerBulk(N), 1e-3)
            << "N = " << N;
    }
    EXPECT_NEAR(corr::deKlerk(20, 0.4), 0.4, 1e-5);
    EXPECT_NEAR(corr::muellerBulk(5.6), 0.365 + 0.220/5.6, 1e-14);
    EXPECT_TRUE(std::isnan(corr::mueller(0.5, 2.5)));

    // Not evaluated at and near the pole of a at N = 3.156 (exactly there
    // it divided by zero)
    EXPECT_FALSE(corr::muellerApplies(3.156));
    EXPECT_FALSE(corr::muellerApplies(3.2));
    EXPECT_TRUE(std::isnan(corr::mueller(0.5, 3.156)));
    EXPECT_TRUE(corr::muellerApplies(3.3));
    EXPECT_TRUE(corr::muellerApplies(2.61));
    EXPECT_FALSE(corr::muellerApplies(2.6));
}

TEST(correlations, deKlerkFirstMinimum)
{
    // Near the wall de Klerk is the parabola 2.14 z^2 - 2.53 z + 1, with
    // its minimum 1 - 2.53^2/(4 2.14) at z = 2.53/4.28
    scalar zMin = 0, epsMin = 2;
    for (int i = 0; i <= 1000; ++i)
    {
        const scalar z = 0.001*i;
        if (corr::deKlerk(z, 0.4) < epsMin)
        {
            epsMin = corr::deKlerk(z, 0.4);
            zMin = z;
        }
    }
    EXPECT_NEAR(zMin, 2.53/4.28, 1e-3);
    EXPECT_NEAR(epsMin, 1 - 2.53*2.53/(4*2.14), 1e-6);
}

TEST(correlations, pressureDropByHand)
{
    // mu = 1e-3 Pa s, U = 1 mm/s, eps = 0.4, dp = 10 mm:
    // 150 1e-3 0.36 1e-3/(0.064 1e-4) = 8.4375 Pa/m (creeping flow)
    EXPECT_NEAR(corr::ergun(1e-3, 0, 1e-3, 0.4, 0.01), 8.4375, 1e-12);
    // + 1.75 1000 0.6 1e-6/(0.064 0.01) = 1.640625 Pa/m
    EXPECT_NEAR(corr::ergun(1e-3, 1000, 1e-3, 0.4, 0.01), 10.078125, 1e-12);

    // dt = 50 mm: A = 1 + 2/9, B = (1.15 0.04 + 0.87)^2
    const auto sphere = corr::eisfeldSchnitzleinShape::sphere;
    EXPECT_NEAR
    (
        corr::eisfeldSchnitzlein(1e-3, 0, 1e-3, 0.4, 0.01, 0.05, sphere),
        12.9402777778,
        1e-9
    );
    EXPECT_NEAR
    (
        corr::eisfeldSchnitzlein(1e-3, 1000, 1e-3, 0.4, 0.01, 0.05, sphere),
        12.9402777778 + 1.3656220006,
        1e-9
    );

    // Infinite tube, creeping flow: K1/150 times Ergun
    const auto cylinder = corr::eisfeldSchnitzleinShape::cylinder;
    EXPECT_NEAR
    (
        corr::eisfeldSchnitzlein(1e-3, 0, 1e-3, 0.4, 0.01, 1e9, cylinder),
        190.0/150.0*8.4375,
        1e-6
    );
}

TEST(correlations, eisfeldSchnitzleinLimits)
{
    const scalar eps = 0.4, dp = 0.01, U = 0.1, mu = 1e-3, rho = 1000;
    const auto sphere = corr::eisfeldSchnitzleinShape::sphere;

    // dt >> dp: A -> 1, B -> k2^2; viscous term 154/150 of Ergun's,
    // inertial term (1/k2^2)/1.75 of Ergun's
    const scalar wide = 1e9*dp;
    EXPECT_NEAR
    (
        corr::eisfeldSchnitzlein(mu, 0, U, eps, dp, wide, sphere)
       /corr::ergun(mu, 0, U, eps, dp),
        154.0/150.0, 1e-6
    );
    EXPECT_NEAR
    (
        corr::eisfeldSchnitzlein(0, rho, U, eps, dp, wide, sphere)
       /corr::ergun(0, rho, U, eps, dp),
        1/sqr(0.87)/1.75, 1e-6
    );

    // Creeping flow in a narrow tube: the wall factor (154/150) A^2
    for (const scalar N : {3.0, 5.0, 10.0})
    {
        const scalar A = 1 + 2/(3*N*(1 - eps));
        EXPECT_NEAR
        (
            corr::eisfeldSchnitzlein(mu, 0, U, eps, dp, N*dp, sphere)
           /corr::ergun(mu, 0, U, eps, dp),
            154.0/150.0*sqr(A), 1e-12
        );
    }
}

TEST(correlations, fitStatistics)
{
    const scalarField y({1.0, 2.0, 3.0, 4.0});
    const scalarField yRef({1.0, 2.0, 3.0, 5.0});

    // SS_res = 1, SS_tot = 5 about mean(y) = 2.5
    EXPECT_NEAR(corr::rSquared(y, yRef), 0.8, 1e-14);
    EXPECT_NEAR(corr::rmse(y, yRef), 0.5, 1e-14);
    EXPECT_DOUBLE_EQ(corr::rSquared(y, y), 1);
    EXPECT_DOUBLE_EQ(corr::rmse(y, y), 0);

    const scalarField x({0.0, 0.5, 1.0});
    const scalarField f
    (
        corr::evaluate(x, [](scalar z){ return corr::deKlerk(z, 0.4); })
    );
    ASSERT_EQ(f.size(), 3);
    EXPECT_DOUBLE_EQ(f[1], corr::deKlerk(0.5, 0.4));

    EXPECT_TRUE
    (
        std::isnan(corr::rSquared(field({2, 2}), field({1, 2})))
    );
}

TEST(correlationsDeath, fitStatisticsRejectSizeMismatch)
{
    EXPECT_EXIT
    (
        corr::rmse(field({1, 2}), field({1, 2, 3})),
        ::testing::ExitedWithCode(1),
        "differ in size"
    );
}

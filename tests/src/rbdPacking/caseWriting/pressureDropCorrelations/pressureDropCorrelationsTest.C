// Unit tests for src/rbdPacking/caseWriting/pressureDropCorrelations:
// against values worked out by hand (and checked in Python) and against
// the limits the formulas must reach

#include <gtest/gtest.h>
#include "pressureDropCorrelations.H"

using namespace Foam;
namespace pdc = Foam::rbd::pressureDropCorrelations;

namespace
{
    // eps, dp [m], U [m/s], mu [Pa s], rho [kg/m^3], dt [m]
    const scalar eps = 0.4, dp = 0.01, U = 0.1, mu = 1e-3, rho = 1000;
    const scalar dt = 0.04;
}

TEST(pressureDropCorrelations, ergunByHand)
{
    // 150 mu (1-eps)^2 U/(eps^3 dp^2) = 843.75 Pa/m,
    // 1.75 rho (1-eps) U^2/(eps^3 dp) = 16406.25 Pa/m
    EXPECT_NEAR(pdc::ergun(eps, dp, U, mu, rho), 17250.0, 1e-9);
    EXPECT_NEAR(pdc::ergun(eps, dp, U, mu, 0), 843.75, 1e-9);
}

TEST(pressureDropCorrelations, eisfeldSchnitzleinByHand)
{
    // N = 4: A = 1 + 2/(3*4*0.6) = 1.27778,
    // B = (1.15/16 + 0.87)^2 = 0.887129 (spheres), (2/16 + 0.77)^2 (cyl.)
    EXPECT_NEAR
    (
        pdc::eisfeldSchnitzlein(eps, dp, dt, U, mu, rho, "spheres"),
        14917.644991443869, 1e-7
    );
    EXPECT_NEAR
    (
        pdc::eisfeldSchnitzlein(eps, dp, dt, U, mu, rho, "cylinders"),
        16699.762776815463, 1e-7
    );
}

TEST(pressureDropCorrelations, eisfeldSchnitzleinWideTubeLimit)
{
    // dt >> dp: A -> 1, B -> k2^2; creeping flow: ratio to Ergun 154/150
    const scalar wide = 1e9*dp;
    EXPECT_NEAR
    (
        pdc::eisfeldSchnitzlein(eps, dp, wide, U, mu, 0, "spheres")
       /pdc::ergun(eps, dp, U, mu, 0),
        154.0/150.0, 1e-6
    );
    // inertial term alone: (1/k2^2)/1.75
    EXPECT_NEAR
    (
        pdc::eisfeldSchnitzlein(eps, dp, wide, U, 0, rho, "spheres")
       /pdc::ergun(eps, dp, U, 0, rho),
        1/sqr(0.87)/1.75, 1e-6
    );
}

TEST(pressureDropCorrelations, creepingFlowWallFactor)
{
    // Viscous term only: E-S/Ergun = (154/150) A^2 for any N
    for (const scalar N : {3.0, 5.0, 10.0})
    {
        const scalar A = 1 + 2/(3*N*(1 - eps));
        EXPECT_NEAR
        (
            pdc::eisfeldSchnitzlein(eps, dp, N*dp, U, mu, 0, "spheres")
           /pdc::ergun(eps, dp, U, mu, 0),
            154.0/150.0*sqr(A), 1e-12
        );
    }
}

TEST(pressureDropCorrelationsDeath, rejectsUnknownShape)
{
    EXPECT_EXIT
    (
        pdc::eisfeldSchnitzlein(eps, dp, dt, U, mu, rho, "rings"),
        ::testing::ExitedWithCode(1),
        "No Eisfeld-Schnitzlein constants for shape 'rings'"
    );
}

// Unit tests for src/rbdPacking/analysis/bedVoidage: bulk porosity, radial
// (eq 39) and axial profiles of sphere beds against closed forms, against
// each other (all must account for the same solid volume), and the files

#include <gtest/gtest.h>
#include "bedVoidage.H"
#include "sphereSolidSet.H"
#include "correlations.H"
#include "mathematicalConstants.H"
#include "OStringStream.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "../../testTools/dataRows.H"

#include <cmath>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace Foam;

namespace
{
    const scalar pi = constant::mathematical::pi;

    //- Random non-overlapping spheres of radius a inside a tube of radius
    //  R, centres in zLow <= z <= zHigh (random sequential addition)
    pointField randomBed
    (
        const scalar R,
        const scalar a,
        const scalar zLow,
        const scalar zHigh,
        const label n,
        const unsigned seed
    )
    {
        std::mt19937 gen(seed);
        std::uniform_real_distribution<scalar> u(0, 1);
        pointField c;
        for (label attempt = 0; attempt < 100000 && c.size() < n; ++attempt)
        {
            const scalar rho = (R - a)*std::sqrt(u(gen));
            const scalar phi = 2*pi*u(gen);
            const point p
            (
                rho*std::cos(phi),
                rho*std::sin(phi),
                zLow + (zHigh - zLow)*u(gen)
            );
            bool free = true;
            for (const point& q : c)
            {
                if (magSqr(p - q) < sqr(2*a))
                {
                    free = false;
                    break;
                }
            }
            if (free)
            {
                c.append(p);
            }
        }
        return c;
    }

    //- Composite 5-point Gauss-Legendre of f over [lo, hi]
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


TEST(bedVoidage, singleSphereBulkPorosity)
{
    const scalar R = 0.02, H = 0.05, a = 0.005;
    const scalar V = 4.0/3.0*pi*a*a*a;

    // Fully below H
    const rbd::sphereSolidSet inside(List<point>({point(0.01, 0, 0.01)}), a);
    EXPECT_NEAR
    (
        rbd::bedVoidage(inside, R, H).bulkPorosity(),
        1 - V/(pi*R*R*H),
        1e-14
    );

    // Cut by z = H through the centre plane shifted by a/2: loses a cap
    // of height a/2
    const rbd::sphereSolidSet cut(List<point>({point(0, 0.01, H - 0.5*a)}), a);
    const scalar h = 0.5*a;
    const scalar cap = pi*h*h*(3*a - h)/3;
    const rbd::bedVoidage bed(cut, R, H);
    EXPECT_NEAR(bed.solidVolume(), V - cap, 1e-12*V);
    EXPECT_NEAR(bed.bulkPorosity(), 1 - (V - cap)/(pi*R*R*H), 1e-14);
}

TEST(bedVoidage, onAxisSphereRadialProfile)
{
    // eps(r) = 1 - 2 sqrt(a^2 - r^2)/H inside the sphere's radius, 1 outside
    const scalar R = 1, H = 3, a = 0.45;
    const rbd::sphereSolidSet s(List<point>({point(0, 0, 1.5)}), a);
    const rbd::bedVoidage bed(s, R, H);

    const label nb = 100;
    const scalarField r(bed.radialBinCentres(nb));
    const scalarField eps(bed.radialProfile(nb));
    ASSERT_EQ(eps.size(), nb);
    forAll(r, k)
    {
        const scalar exact =
            r[k] < a ? 1 - 2*std::sqrt(a*a - r[k]*r[k])/H : 1;
        EXPECT_NEAR(eps[k], exact, 1e-13) << "r = " << r[k];
        EXPECT_NEAR(bed.radialPorosity(r[k]), eps[k], 1e-15);
    }
    EXPECT_NEAR(r[0], 0.005, 1e-15);
    EXPECT_NEAR(r[nb - 1], 0.995, 1e-15);
}

TEST(bedVoidage, wallSphereGivesVoidAtWall)
{
    // A sphere touching the wall covers a patch of the cylinder r = R - d
    // whose area vanishes with d, so eps -> 1 at the wall
    const scalar R = 1, H = 2, a = 0.2;
    const rbd::sphereSolidSet s(List<point>({point(0, R - a, 1)}), a);
    const rbd::bedVoidage bed(s, R, H);

    scalar previous = 0;
    for (const scalar d : {1e-1, 1e-2, 1e-3, 1e-4, 1e-6})
    {
        const scalar eps = bed.radialPorosity(R - d);
        EXPECT_GT(eps, previous) << "d = " << d;
        EXPECT_LT(1 - eps, 2*d) << "d = " << d;
        previous = eps;
    }
    EXPECT_EQ(bed.radialPorosity(R), 1);
}

TEST(bedVoidage, randomBedRadialAxialAndBulkAgree)
{
    // N = 5.6, dp = 1: 40 non-overlapping spheres, some cut by the slab's
    // planes. All three views must account for the same solid volume.
    const scalar a = 0.5, R = 2.8, zLow = 0, zHigh = 4;
    const pointField c(randomBed(R, a, zLow - 0.3, zHigh + 0.3, 40, 11));
    ASSERT_EQ(c.size(), 40);
    const rbd::sphereSolidSet s(c, a);
    const rbd::bedVoidage bed(s, R, zLow, zHigh);
    const scalar V = bed.solidVolume();
    const scalar height = zHigh - zLow;

    // Radial: int_0^R (1 - eps) 2 pi r H dr = V (eps as a function of r)
    const scalar radialIntegral = integrate
    (
        [&](scalar r){ return (1 - bed.radialPorosity(r))*2*pi*r*height; },
        0,
        R,
        2000
    );
    EXPECT_NEAR(radialIntegral, V, 1e-6*V);

    // The same with the 100-bin profile (midpoint rule in r)
    const label nb = 100;
    const scalarField r(bed.radialBinCentres(nb));
    const scalarField eps(bed.radialProfile(nb));
    scalar binSum = 0;
    forAll(r, k)
    {
        binSum += (1 - eps[k])*2*pi*r[k]*height*(R/nb);
    }
    EXPECT_NEAR(binSum, V, 5e-4*V);   // measured 4e-5

    // The binned profile is the point function at the bin centres (the
    // spatial cull loses nothing)
    forAll(r, k)
    {
        EXPECT_NEAR(eps[k], bed.radialPorosity(r[k]), 1e-14);
    }

    // Axial: mean of the slab void fractions = bulk porosity
    for (const label nz : {1, 7, 100})
    {
        const scalarField epsZ(bed.axialProfile(nz));
        EXPECT_NEAR(average(epsZ), bed.bulkPorosity(), 1e-13) << nz;
    }
}

TEST(bedVoidage, axialProfileOfOneSphere)
{
    // Slab [z0, z1] inside one sphere: V = pi [a^2 t - t^3/3]
    const scalar R = 1, a = 0.5;
    const rbd::sphereSolidSet s(List<point>({point(0, 0, 1)}), a);
    const rbd::bedVoidage bed(s, R, 0, 2);
    const scalarField eps(bed.axialProfile(4));   // slabs of height 0.5
    const scalarField z(bed.axialBinCentres(4));

    // Slab [0.5, 1]: t from -0.5 to 0, a half sphere
    const scalar half = 2.0/3.0*pi*a*a*a;
    EXPECT_NEAR(eps[0], 1, 1e-15);
    EXPECT_NEAR(eps[1], 1 - half/(pi*R*R*0.5), 1e-14);
    EXPECT_NEAR(eps[2], eps[1], 1e-14);
    EXPECT_NEAR(eps[3], 1, 1e-15);
    EXPECT_NEAR(z[1], 0.75, 1e-15);
}

TEST(bedVoidage, writesProfiles)
{
    const scalar a = 0.5, R = 2.8;
    const pointField c(randomBed(R, a, 0, 4, 30, 5));
    const rbd::sphereSolidSet s(c, a);
    const rbd::bedVoidage bed(s, R, 4);

    OStringStream radial;
    bed.writeRadialProfile(radial, 20, 2*a, true);
    const std::string text(radial.str());
    EXPECT_NE
    (
        text.find("# r [m]  (R-r)/dp [-]  eps [-]  deKlerk"),
        std::string::npos
    );
    EXPECT_NE(text.find("R^2 = "), std::string::npos);

    const auto data = rbdTest::dataRows(text);
    ASSERT_EQ(data.size(), 20u);
    const scalarField eps(bed.radialProfile(20));
    const scalar epsBulk = bed.bulkPorosity();
    for (size_t k = 0; k < data.size(); ++k)
    {
        ASSERT_EQ(data[k].size(), 5u);
        EXPECT_NEAR(data[k][1], (R - data[k][0])/(2*a), 1e-8);
        EXPECT_NEAR(data[k][2], eps[k], 1e-8);
        EXPECT_NEAR
        (
            data[k][3],
            rbd::correlations::deKlerk(data[k][1], epsBulk),
            1e-8
        );
        EXPECT_NEAR
        (
            data[k][4],
            rbd::correlations::mueller(data[k][1], 2*R/(2*a)),
            1e-8
        );
    }

    OStringStream plain;
    bed.writeRadialProfile(plain, 10, 2*a, false);
    const auto plainData = rbdTest::dataRows(plain.str());
    ASSERT_EQ(plainData.size(), 10u);
    EXPECT_EQ(plainData[0].size(), 3u);

    OStringStream axial;
    bed.writeAxialProfile(axial, 8);
    const auto axialData = rbdTest::dataRows(axial.str());
    ASSERT_EQ(axialData.size(), 8u);
    EXPECT_EQ(axialData[0].size(), 2u);
    EXPECT_NEAR(axialData[0][0], 0.25, 1e-12);

    // The files into a directory: the correlations only for spheres
    const fileName dir("bedVoidageTest.tmp");
    rmDir(dir);
    bed.write(dir, 10, 8, 2*a, true);
    EXPECT_TRUE(isFile(dir/"radialPorosity.dat"));
    EXPECT_TRUE(isFile(dir/"axialPorosity.dat"));
    EXPECT_TRUE(isFile(dir/"radialCorrelations.dat"));
    rmDir(dir);
    bed.write(dir, 10, 8, 2*a, false);
    EXPECT_TRUE(isFile(dir/"radialPorosity.dat"));
    EXPECT_FALSE(isFile(dir/"radialCorrelations.dat"));
    rmDir(dir);
}


TEST(bedVoidage, sphereRadialFitsAgainstProfile)
{
    // N = 5.6: the statistics of the profile against the correlations
    // evaluated at the bin centres' wall distance
    const scalar a = 0.5, R = 2.8, dp = 2*a;
    const pointField c(randomBed(R, a, 0, 4, 30, 7));
    const rbd::sphereSolidSet s(c, a);
    const rbd::bedVoidage bed(s, R, 4);

    const label nBins = 25;
    const scalarField eps(bed.radialProfile(nBins));
    const scalarField r(bed.radialBinCentres(nBins));
    scalarField deKlerk(nBins), mueller(nBins);
    forAll(r, k)
    {
        const scalar z = (R - r[k])/dp;
        deKlerk[k] = rbd::correlations::deKlerk(z, bed.bulkPorosity());
        mueller[k] = rbd::correlations::mueller(z, 2*R/dp);
    }

    const dictionary fits(bed.sphereRadialFits(nBins, dp));
    const dictionary& dK = fits.subDict("deKlerk");
    const dictionary& M = fits.subDict("mueller");
    EXPECT_NEAR
    (
        dK.get<scalar>("rSquared"),
        rbd::correlations::rSquared(eps, deKlerk),
        1e-12
    );
    EXPECT_NEAR
    (
        dK.get<scalar>("rmse"), rbd::correlations::rmse(eps, deKlerk), 1e-12
    );
    EXPECT_NEAR
    (
        M.get<scalar>("rSquared"),
        rbd::correlations::rSquared(eps, mueller),
        1e-12
    );
    EXPECT_NEAR
    (
        M.get<scalar>("rmse"), rbd::correlations::rmse(eps, mueller), 1e-12
    );

    // The header of radialPorosity.dat prints the same numbers
    OStringStream os;
    bed.writeRadialProfile(os, nBins, dp, true);
    OStringStream expected;
    expected.precision(10);
    expected
        << "R^2 = " << dK.get<scalar>("rSquared")
        << ", RMSE = " << dK.get<scalar>("rmse");
    EXPECT_NE(os.str().find(expected.str()), std::string::npos)
        << expected.str();

    // An empty tube: eps = 1 everywhere, R^2 undefined and left out
    const rbd::sphereSolidSet none(pointField(), a);
    const dictionary emptyFits
    (
        rbd::bedVoidage(none, R, 4).sphereRadialFits(nBins, dp)
    );
    EXPECT_FALSE(emptyFits.subDict("deKlerk").found("rSquared"));
    EXPECT_TRUE(emptyFits.subDict("deKlerk").found("rmse"));

    // Mueller's form is undefined below N = 2.61: no statistics
    const rbd::bedVoidage narrow(s, 1.2, 4);
    const dictionary narrowFits(narrow.sphereRadialFits(nBins, dp));
    EXPECT_FALSE(narrowFits.found("mueller"));
    EXPECT_TRUE(narrowFits.subDict("deKlerk").found("rmse"));
}


TEST(bedVoidage, writesNoNaNWhereMuellerDoesNotApply)
{
    // N = 2.4 (below Mueller's range) and N = 3.156 (the pole of its a,
    // where rbdPackBed stopped on a division by zero): the profile and the
    // correlation files have no Mueller column and no NaN
    const scalar a = 0.5, dp = 2*a;
    for (const scalar N : {2.4, 3.156})
    {
        const scalar R = 0.5*N*dp;
        const rbd::sphereSolidSet s(randomBed(R, a, 0, 4, 10, 3), a);
        const rbd::bedVoidage bed(s, R, 4);
        const fileName dir("bedVoidageNoMuellerTest.tmp");
        rmDir(dir);
        bed.write(dir, 20, 8, dp, true);
        for (const word file : {"radialPorosity.dat", "radialCorrelations.dat"})
        {
            std::ifstream is(dir/file);
            const std::string text
            (
                (std::istreambuf_iterator<char>(is)),
                std::istreambuf_iterator<char>()
            );
            EXPECT_EQ(text.find("nan"), std::string::npos) << file;
            EXPECT_NE(text.find("Mueller: not applicable"), std::string::npos)
                << file;
            const auto data = rbdTest::dataRows(text);
            ASSERT_FALSE(data.empty()) << file;
            // r, z, (eps,) de Klerk
            EXPECT_EQ
            (
                data.front().size(),
                file == "radialPorosity.dat" ? 4u : 3u
            ) << file << " at N = " << N;
        }
        rmDir(dir);
    }
}


TEST(bedVoidage, writesSphereCorrelations)
{
    const scalar a = 0.5, R = 2.8, dp = 2*a;
    const pointField c(randomBed(R, a, 0, 4, 30, 5));
    const rbd::sphereSolidSet s(c, a);
    const rbd::bedVoidage bed(s, R, 4);

    OStringStream os;
    bed.writeSphereCorrelations(os, 11, dp);
    const auto data = rbdTest::dataRows(os.str());
    ASSERT_EQ(data.size(), 11u);

    // From the wall (both correlations 1 there) to the axis
    EXPECT_NEAR(data.front()[0], R, 1e-12);
    EXPECT_NEAR(data.front()[1], 0, 1e-12);
    EXPECT_NEAR(data.front()[2], 1, 1e-12);
    EXPECT_NEAR(data.front()[3], 1, 1e-12);
    EXPECT_NEAR(data.back()[0], 0, 1e-12);
    EXPECT_NEAR(data.back()[1], R/dp, 1e-12);
    for (const auto& row : data)
    {
        ASSERT_EQ(row.size(), 4u);
        EXPECT_NEAR(row[1], (R - row[0])/dp, 1e-9);
        EXPECT_NEAR
        (
            row[2],
            rbd::correlations::deKlerk(row[1], bed.bulkPorosity()),
            1e-9
        );
        EXPECT_NEAR
        (
            row[3], rbd::correlations::mueller(row[1], 2*R/dp), 1e-9
        );
    }

    // The file has the documented number of points
    const fileName dir("bedVoidageCorrelationsTest.tmp");
    rmDir(dir);
    bed.write(dir, 10, 8, dp, true);
    std::ifstream is(dir/"radialCorrelations.dat");
    const std::string text
    (
        (std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>()
    );
    EXPECT_EQ
    (
        rbdTest::dataRows(text).size(),
        size_t(rbd::bedVoidage::correlationPoints)
    );
    rmDir(dir);
}

TEST(bedVoidageDeath, rejectsBadBinsAndTube)
{
    const rbd::sphereSolidSet s(List<point>({point(0, 0, 1)}), 0.5);
    EXPECT_EXIT
    (
        rbd::bedVoidage(s, 1, 2).radialProfile(0),
        ::testing::ExitedWithCode(1),
        "number of bins 0 is not >= 1"
    );
    EXPECT_EXIT
    (
        rbd::bedVoidage(s, 1, 2, 2),
        ::testing::ExitedWithCode(1),
        "zHigh > zLow"
    );
    EXPECT_EXIT
    (
        {
            OStringStream os;
            rbd::bedVoidage(s, 1, 2).writeSphereCorrelations(os, 1, 1);
        },
        ::testing::ExitedWithCode(1),
        "number of points 1 is not >= 2"
    );
}

// Unit tests for src/rbdPacking/analysis/orientationStatistics: aligned,
// crossed and isotropic axes against closed forms, the slab filter and the
// file

#include <gtest/gtest.h>
#include "orientationStatistics.H"
#include "quaternion.H"
#include "OSspecific.H"
#include "IFstream.H"
#include "mathematicalConstants.H"

#include <random>
#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    const scalar pi = constant::mathematical::pi;
}


TEST(orientationStatistics, alignedAndCrossedAxes)
{
    // Axis along +z or -z: 0 degrees; any axis in the xy plane: 90
    const List<point> x({point(0, 0, 0.01), point(0, 0, 0.02),
        point(0, 0, 0.03), point(0, 0, 0.04)});
    const List<tensor> R
    ({
        tensor::I,
        quaternion(vector(1, 0, 0), pi).R(),
        quaternion(vector(1, 0, 0), 0.5*pi).R(),
        quaternion(normalised(vector(1, 1, 0)), 0.5*pi).R()
    });
    const rbd::orientationStatistics all(x, R);
    EXPECT_EQ(all.size(), 4);
    EXPECT_NEAR(all.angles()[0], 0, 1e-7);
    EXPECT_NEAR(all.angles()[1], 0, 1e-7);
    EXPECT_NEAR(all.angles()[2], 0.5*pi, 1e-12);
    EXPECT_NEAR(all.angles()[3], 0.5*pi, 1e-12);
    EXPECT_NEAR(all.meanAngle(), 45, 1e-5);
    EXPECT_NEAR(all.meanCos2(), 0.5, 1e-12);
    EXPECT_NEAR(all.orderParameter(), 0.25, 1e-12);
    const labelList h(all.histogram(9));
    EXPECT_EQ(h[0], 2);
    EXPECT_EQ(h[8], 2);

    // Slab filter: centres in [0.025, 0.05]
    const rbd::orientationStatistics top(x, R, 0.025, 0.05);
    EXPECT_EQ(top.size(), 2);
    EXPECT_NEAR(top.meanAngle(), 90, 1e-10);
    EXPECT_NEAR(top.orderParameter(), -0.5, 1e-12);
}


TEST(orientationStatistics, isotropicAxesGiveOneRadian)
{
    // Uniform random rotations: normalised Gaussian quaternions
    std::mt19937 gen(7);
    std::normal_distribution<scalar> g;
    const label n = 20000;
    List<point> x(n, point::zero);
    List<tensor> R(n);
    for (label i = 0; i < n; ++i)
    {
        quaternion q(g(gen), vector(g(gen), g(gen), g(gen)));
        q.normalize();
        R[i] = q.R();
    }
    const rbd::orientationStatistics s(x, R);
    // mean theta = int_0^1 acos(u) du = 1 rad; sd of theta
    // sqrt(pi - 3) rad = 21.6 deg, so the mean's sd is 0.15 deg
    EXPECT_NEAR(s.meanAngle(), 180/pi, 0.6);
    EXPECT_NEAR(s.meanCos2(), 1.0/3, 0.01);
    EXPECT_NEAR(s.orderParameter(), 0, 0.015);

    const label nBins = 9;
    const labelList h(s.histogram(nBins));
    EXPECT_EQ(sum(h), n);
    for (label k = 0; k < nBins; ++k)
    {
        const scalar iso =
            std::cos(0.5*pi*k/nBins) - std::cos(0.5*pi*(k + 1)/nBins);
        EXPECT_NEAR(scalar(h[k])/n, iso, 0.01) << "bin " << k;
    }

    // The file: header lines, then one line per bin
    const fileName dir
    (
        "/tmp/rbdOrientationTest-" + std::to_string(::getpid())
    );
    s.write(dir, nBins);
    std::ifstream is(dir/"orientation.dat");
    std::string line;
    label data = 0, header = 0;
    scalar fractionSum = 0;
    while (std::getline(is, line))
    {
        if (line[0] == '#')
        {
            ++header;
            continue;
        }
        std::istringstream ls(line);
        scalar t1, t2, frac, iso;
        label count;
        ls >> t1 >> t2 >> count >> frac >> iso;
        EXPECT_NEAR(t2 - t1, 10, 1e-12);
        EXPECT_EQ(count, h[data]);
        fractionSum += frac;
        ++data;
    }
    EXPECT_EQ(header, 4);
    EXPECT_EQ(data, nBins);
    EXPECT_NEAR(fractionSum, 1, 1e-9);
    Foam::rmDir(dir);
}

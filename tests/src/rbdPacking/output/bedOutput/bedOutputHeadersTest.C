// Unit tests for src/rbdPacking/output/bedOutput (issue 26, item 7 and 8):
// one N = dt/dp in the .dat headers with Nv = dt/dpv named apart, the
// axial profile from the floor to the bed top, the summary's units as
// comments

#include <gtest/gtest.h>
#include "bedOutput.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "OStringStream.H"
#include "OSspecific.H"
#include "foamFile.H"
#include "mathematicalConstants.H"
#include "../../testTools/dataRows.H"

#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    std::string contents(const fileName& f)
    {
        std::ifstream is(f);
        std::stringstream ss;
        ss << is.rdbuf();
        return ss.str();
    }
    fileName tmpCase()
    {
        return "/tmp/rbdBedOutputHeadersTest-" + std::to_string(::getpid());
    }
}


TEST(bedOutputHeaders, cylindersNamesNAndNvAndCoversTheBed)
{
    // d = h = 10 mm in a 40 mm tube: N = dt/dp = 4 with the bounding
    // diameter dp = d sqrt(2), Nv = dt/dpv = 4/1.5^(1/3)
    const rbd::tube container(parse("diameter 0.04; height 0.1;"));
    autoPtr<rbd::pelletShape> shape = rbd::pelletShape::New
    (
        parse("shape cylinder; diameter 0.01; height 0.01; faces 1000;")
    );
    const vector I = shape->principalInertiaPerDensity();
    List<rbd::rigidBody> bodies;
    bodies.append(rbd::rigidBody(1, I, point(-0.008, 0, 0.005),
        quaternion(1), true));
    bodies.append(rbd::rigidBody(1, I, point(0.008, 0, 0.005),
        quaternion(1), true));
    // One high up: the loose top layer
    bodies.append(rbd::rigidBody(1, I, point(0, 0, 0.016),
        quaternion(1), true));

    const fileName dir(tmpCase());
    rmDir(dir);
    rbd::bedOutput out(dir, container, shape(), bodies);
    const scalar top = rbd::bedOutput::bedTop(shape(), bodies);
    EXPECT_NEAR(top, 0.016 + shape->boundingRadius(), 1e-15);

    const scalar H = 0.01;
    const dictionary analysis(out.writeProfiles(H, 20, 10));

    // radialPorosity.dat: N of the bounding diameter, Nv named apart
    const std::string radial(contents(out.directory()/"radialPorosity.dat"));
    const scalar dp = shape->diameter();
    const scalar dpv = shape->volumeEquivalentDiameter();
    EXPECT_NEAR(dpv, std::cbrt(1.5)*0.01, 1e-12);
    std::ostringstream N, Nv;
    N.precision(10);
    Nv.precision(10);
    N << "N = dt/dp = " << 0.04/dp << ";";
    Nv << "Nv = dt/dpv = " << 0.04/dpv;
    EXPECT_NE(radial.find(N.str()), std::string::npos) << radial;
    EXPECT_NE(radial.find(Nv.str()), std::string::npos) << radial;
    EXPECT_NE(radial.find("(R-r)/dpv [-]"), std::string::npos) << radial;
    // The wall distance column is in dpv (the paper's)
    const auto r = rbdTest::dataRows(radial);
    ASSERT_EQ(r.size(), 20u);
    EXPECT_NEAR(r[0][1], (0.02 - r[0][0])/dpv, 1e-8);

    // axialPorosity.dat: from the floor to the top of the highest pellet,
    // not to H
    const auto z = rbdTest::dataRows(contents(out.directory()/"axialPorosity.dat"));
    ASSERT_EQ(z.size(), 10u);
    const scalar dz = top/10;
    EXPECT_NEAR(z.front()[0], 0.5*dz, 1e-9);
    EXPECT_NEAR(z.back()[0], top - 0.5*dz, 1e-9);
    EXPECT_GT(z.back()[0], H);
    // The slabs' mean is the porosity of the whole bed (the exact
    // cylinders: the mesh's volumes scaled to the exact volume)
    const scalar Vm = shape->exactVolume();
    scalar mean = 0;
    for (const auto& row : z)
    {
        mean += row[1]/z.size();
    }
    EXPECT_NEAR
    (
        mean, 1 - 3*Vm/(constant::mathematical::pi*0.0004*top), 1e-9
    );
    // The bulk porosity stays below H: the two upright ones only
    EXPECT_NEAR
    (
        analysis.get<scalar>("bulkPorosity"),
        1 - 2*Vm/(constant::mathematical::pi*0.0004*H), 1e-10
    );
    rmDir(dir);
}


TEST(bedOutputHeaders, spheresOneDiameter)
{
    const rbd::tube container(parse("diameter 0.04; height 0.1;"));
    autoPtr<rbd::pelletShape> shape =
        rbd::pelletShape::New(parse("shape sphere; diameter 0.01;"));
    const vector I = shape->principalInertiaPerDensity();
    List<rbd::rigidBody> bodies;
    bodies.append(rbd::rigidBody(1, I, point(0, 0, 0.005), quaternion(1),
        true));
    bodies.append(rbd::rigidBody(1, I, point(0.01, 0, 0.005),
        quaternion(1), true));
    const fileName dir(tmpCase());
    rmDir(dir);
    rbd::bedOutput out(dir, container, shape(), bodies);
    out.writeProfiles(0.01, 20, 10);
    const std::string radial(contents(out.directory()/"radialPorosity.dat"));
    EXPECT_NE
    (
        radial.find("pellet diameter dp = 0.01 m, N = dt/dp = 4\n"),
        std::string::npos
    ) << radial;
    EXPECT_EQ(radial.find("Nv"), std::string::npos) << radial;
    EXPECT_NE(radial.find("(R-r)/dp [-]"), std::string::npos);
    // Its Mueller comparison is at N = 4
    EXPECT_NE(radial.find("eps_b = 0.42"), std::string::npos) << radial;
    rmDir(dir);
}


TEST(bedOutputHeaders, summaryUnitsAsComments)
{
    const rbd::tube container(parse("diameter 0.04; height 0.1;"));
    autoPtr<rbd::pelletShape> shape =
        rbd::pelletShape::New(parse("shape sphere; diameter 0.01;"));
    const List<rbd::rigidBody> bodies;
    const fileName dir(tmpCase());
    rmDir(dir);
    rbd::bedOutput out(dir, container, shape(), bodies);

    dictionary summary;
    summary.add("pellets", 30);
    summary.add("shape", word("sphere"));
    summary.add("tubeDiameter", 0.04);
    summary.add("diameterRatio", 4.0);
    summary.add("bulkPorosity", 0.41);
    summary.add("someNewEntry", 7);
    dictionary fits;
    fits.add("rSquared", 0.9);
    summary.add("radialCorrelations", dictionary());
    summary.subDict("radialCorrelations").add("deKlerk", fits);
    summary.add("simulatedTime", 2.5);
    out.writeSummary(summary);

    const fileName file(out.directory()/"summary");
    const std::string text(contents(file));
    EXPECT_NE(text.find("tubeDiameter    0.04;  // [m] dt\n"),
        std::string::npos) << text;
    EXPECT_NE(text.find("diameterRatio   4;  // [-] N = dt/dp\n"),
        std::string::npos) << text;
    EXPECT_NE(text.find("simulatedTime   2.5;  // [s]\n"),
        std::string::npos) << text;
    EXPECT_NE(text.find("rSquared        0.9;  // [-] R^2\n"),
        std::string::npos) << text;
    // An entry without a known unit is written without a comment
    EXPECT_NE(text.find("someNewEntry    7;\n"), std::string::npos) << text;

    // Still the same dictionary
    const dictionary back(rbd::readFoamFile(file));
    EXPECT_EQ(back.get<label>("pellets"), 30);
    EXPECT_EQ(back.get<word>("shape"), "sphere");
    EXPECT_DOUBLE_EQ(back.get<scalar>("bulkPorosity"), 0.41);
    EXPECT_DOUBLE_EQ
    (
        back.subDict("radialCorrelations").subDict("deKlerk")
            .get<scalar>("rSquared"),
        0.9
    );
    EXPECT_EQ(back.toc().size(), summary.toc().size());

    // Every entry packedBed and orientationStatistics write has a unit
    for
    (
        const word key
      : {
            "pellets", "requestedPellets", "status", "shape",
            "tubeDiameter", "pelletDiameter", "volumeEquivalentDiameter",
            "diameterRatio", "volumeEquivalentDiameterRatio",
            "bulkPorosity", "stlPorosity", "porosityHeight",
            "bulkPorosityCorrelations",
            "radialCorrelations", "bedHeight", "bedPorosity", "maxOverlap",
            "finalMaxOverlap", "simulatedTime", "wallTime", "cpuTime",
            "steps", "collisions", "lcpFailures", "kineticEnergy",
            "settled", "contactTreatment", "treatedContacts",
            "orientedPellets", "meanAxisAngle", "stdDevAxisAngle",
            "axisOrderParameter"
        }
    )
    {
        EXPECT_FALSE(rbd::bedOutput::summaryUnit(key).empty()) << key;
    }
    rmDir(dir);
}

// Unit tests for src/rbdPacking/loading/placementFile and the loading
// scheme 'placement': the poses read back as written (pellets.csv's
// format, comments, blank lines and DOS line ends allowed), quaternions
// normalised, the line of each pellet kept for the messages. The refusals
// of bad files are tests/integration/badInput.cases (placement*): they
// stop the program with a FatalIOError

#include <gtest/gtest.h>
#include "placementFile.H"
#include "loadingScheme.H"
#include "IStringStream.H"
#include "../../caseWriting/caseWritingTempDir.H"

#include <fstream>

using namespace Foam;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    // Tube of D = 40 mm, H = 100 mm
    const rbd::tube tube40(0.04, 0.1, 0.6, 0.6);

    autoPtr<rbd::pelletShape> cylinder()
    {
        return rbd::pelletShape::New
        (
            parse("shape cylinder; diameter 0.01; height 0.01; faces 200;")
        );
    }

    // A file of this text in a fresh directory; removed with it
    struct tempFile
    {
        caseWritingTest::tempDir dir;
        std::string path;

        explicit tempFile(const std::string& text)
        :
            path(dir.path()/"placement.csv")
        {
            std::ofstream os(path);
            os << text;
        }
    };
}


TEST(placementFile, readsThePosesOfPelletsCsvLineByLine)
{
    // Header, a comment, a blank line, DOS line ends, blanks around
    // fields, a quaternion 1e-9 off unit length
    const tempFile f
    (
        "id,shape,x,y,z,qw,qx,qy,qz\r\n"
        "# two cylinders\r\n"
        "0,cylinder,0.01,0,0.02,1,0,0,0\r\n"
        "\r\n"
        " 1 , cylinder , -0.005 , 0.002 , 0.045 , 0.6 , 0.8000000008 , 0 , 0\r\n"
    );
    autoPtr<rbd::pelletShape> s = cylinder();
    const rbd::placementFile P
    (
        parse("file \"" + f.path + "\";"), tube40, s()
    );

    ASSERT_EQ(P.size(), 2);
    EXPECT_EQ(P.x(0), point(0.01, 0, 0.02));
    EXPECT_EQ(P.x(1), point(-0.005, 0.002, 0.045));
    EXPECT_EQ(P.line(0), 3);
    EXPECT_EQ(P.line(1), 5);
    EXPECT_DOUBLE_EQ(P.q(0).w(), 1);
    EXPECT_NEAR(P.q(1).w(), 0.6, 1e-9);
    EXPECT_NEAR(P.q(1).v().x(), 0.8, 1e-9);
    EXPECT_NEAR(sqr(P.q(1).w()) + magSqr(P.q(1).v()), 1, 1e-15);
    EXPECT_DOUBLE_EQ(P.highestCentre(), 0.045);
    EXPECT_EQ(P.path(), fileName(f.path));
}


TEST(placementFile, readsWhatBedOutputWrites)
{
    // pellets.csv as bedOutput::writePellets writes it (12 digits): the
    // poses come back to its precision, the quaternions of unit length
    std::ostringstream os;
    os.precision(12);
    os << "id,shape,x,y,z,qw,qx,qy,qz\n";
    const quaternion q0(vector(1, 2, 3)/mag(vector(1, 2, 3)), 0.7);
    const quaternion q1(vector(0, 1, 0), 2.1);
    os << 0 << ",cylinder," << 0.0031 << ',' << -0.0042 << ',' << 0.0123
       << ',' << q0.w() << ',' << q0.v().x() << ',' << q0.v().y() << ','
       << q0.v().z() << '\n';
    os << 1 << ",cylinder," << -0.011 << ',' << 0.0 << ',' << 0.031
       << ',' << q1.w() << ',' << q1.v().x() << ',' << q1.v().y() << ','
       << q1.v().z() << '\n';
    const tempFile f(os.str());
    autoPtr<rbd::pelletShape> s = cylinder();
    const rbd::placementFile P
    (
        parse("file \"" + f.path + "\";"), tube40, s()
    );

    ASSERT_EQ(P.size(), 2);
    EXPECT_LT(mag(P.x(0) - point(0.0031, -0.0042, 0.0123)), 1e-15);
    EXPECT_NEAR(P.q(0).w(), q0.w(), 1e-12);
    EXPECT_LT(mag(P.q(0).v() - q0.v()), 1e-12);
    EXPECT_NEAR(P.q(1).w(), q1.w(), 1e-12);
    EXPECT_LT(mag(P.q(1).v() - q1.v()), 1e-12);
}


TEST(placementFile, schemePlacementHasNoReleasePoints)
{
    const tempFile f
    (
        "id,shape,x,y,z,qw,qx,qy,qz\n"
        "0,cylinder,0,0,0.03,1,0,0,0\n"
        "1,cylinder,0,0,0.06,1,0,0,0\n"
        "2,cylinder,0.01,0,0.08,1,0,0,0\n"
    );
    autoPtr<rbd::pelletShape> s = cylinder();
    const rbd::loadingScheme L
    (
        parse("scheme placement; file \"" + f.path + "\";"), tube40, s()
    );

    EXPECT_TRUE(L.placed());
    EXPECT_EQ(L.scheme(), word("placement"));
    EXPECT_EQ(L.nColumns(), 0);
    EXPECT_EQ(L.placement().size(), 3);
    EXPECT_DOUBLE_EQ(L.releaseHeight(), 0.08);

    // The release schemes read no file
    const rbd::loadingScheme C(parse("scheme column;"), tube40, s());
    EXPECT_FALSE(C.placed());
    EXPECT_EQ(C.nColumns(), 1);
}

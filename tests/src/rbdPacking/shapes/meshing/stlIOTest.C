// Unit tests for src/rbdPacking/shapes/meshing/stlIO

#include <gtest/gtest.h>
#include "stlIO.H"
#include "cgalMeshTools.H"
#include "pelletMeshes.H"
#include "quaternion.H"
#include "OSspecific.H"
#include "rbdPacking/shapes/meshing/testMeshes.H"

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace Foam;

namespace
{
    std::string contents(const fileName& f)
    {
        std::ifstream is(f, std::ios::binary);
        std::stringstream ss;
        ss << is.rdbuf();
        return ss.str();
    }

    label count(const std::string& text, const std::string& word)
    {
        label n = 0;
        for
        (
            auto pos = text.find(word);
            pos != std::string::npos;
            pos = text.find(word, pos + 1)
        )
        {
            ++n;
        }
        return n;
    }

    //- readSTL must fail with a reason containing the text
    ::testing::AssertionResult rejects(const fileName& f, const char* text)
    {
        rbd::triMesh m;
        string why;
        if (rbd::readSTL(f, 1, m, why))
        {
            return ::testing::AssertionFailure() << f << " was accepted";
        }
        if (why.find(text) == std::string::npos)
        {
            return ::testing::AssertionFailure()
                << "reason '" << why << "' lacks '" << text << "'";
        }
        if (!m.empty())
        {
            return ::testing::AssertionFailure() << "mesh not emptied";
        }
        return ::testing::AssertionSuccess();
    }

    void writeOne(const fileName& f, const rbd::triMesh& m, const bool binary)
    {
        rbd::writeSTL(f, List<rbd::triMesh>(1, m), binary);
    }
}


TEST(stlIO, asciiRoundTrip)
{
    const rbd::triMesh ring = rbd::pelletMeshes::ring(0.01, 0.006, 0.01, 2000);
    const fileName f = rbdTest::tmpFile("ring.stl");
    writeOne(f, ring, false);

    const std::string text = contents(f);
    EXPECT_EQ(text.rfind("solid pellets\n", 0), 0u);
    EXPECT_NE(text.find("endsolid pellets\n"), std::string::npos);

    rbd::triMesh m;
    string why;
    ASSERT_TRUE(rbd::readSTL(f, 1, m, why)) << why;
    EXPECT_EQ(m.nFaces(), ring.nFaces());
    EXPECT_EQ(m.nPoints(), ring.nPoints());
    EXPECT_NEAR(m.volume()/ring.volume(), 1, 1e-7);
    Foam::rm(f);
}

TEST(stlIO, binaryRoundTripAndLayout)
{
    const rbd::triMesh ring = rbd::pelletMeshes::ring(0.01, 0.006, 0.01, 2000);
    const fileName f = rbdTest::tmpFile("ring-binary.stl");
    writeOne(f, ring, true);

    // 80-byte header not starting with "solid", count, 50 bytes a triangle
    const std::string bytes = contents(f);
    ASSERT_EQ(label(bytes.size()), 84 + 50*ring.nFaces());
    EXPECT_NE(bytes.substr(0, 5), "solid");
    uint32_t n = 0;
    for (int i = 0; i < 4; ++i)
    {
        n |= uint32_t(uint8_t(bytes[80 + i])) << (8*i);
    }
    EXPECT_EQ(label(n), ring.nFaces());

    rbd::triMesh m;
    string why;
    ASSERT_TRUE(rbd::readSTL(f, 1, m, why)) << why;
    EXPECT_EQ(m.nFaces(), ring.nFaces());
    EXPECT_EQ(m.nPoints(), ring.nPoints());
    // Single precision
    EXPECT_NEAR(m.volume()/ring.volume(), 1, 1e-6);
    Foam::rm(f);
}

TEST(stlIO, scaleIsApplied)
{
    const fileName f = rbdTest::tmpFile("box-mm.stl");
    writeOne(f, rbdTest::box(10, 20, 30), false);
    rbd::triMesh m;
    string why;
    ASSERT_TRUE(rbd::readSTL(f, 1e-3, m, why)) << why;
    EXPECT_NEAR(m.volume(), 6e-6, 1e-18);
    EXPECT_FALSE(rbd::readSTL(f, 0, m, why));
    EXPECT_NE(why.find("scale factor"), std::string::npos);
    Foam::rm(f);
}

TEST(stlIO, manyPelletsAsOneSolid)
{
    const rbd::triMesh body = rbd::pelletMeshes::cylinder(0.01, 0.01, 300);
    for (const bool binary : {false, true})
    {
        const fileName f = rbdTest::tmpFile
        (
            binary ? "bed-binary.stl" : "bed.stl"
        );
        {
            rbd::stlWriter w(f, binary);
            for (label i = 0; i < 3; ++i)
            {
                const tensor R = quaternion(vector(1, 0, 0), 0.5*i).R();
                w.write(body, R, vector(0.02*i, 0, 0));
            }
            EXPECT_EQ(w.nTriangles(), 3*body.nFaces());
        }   // closed here

        if (!binary)
        {
            const std::string text = contents(f);
            EXPECT_EQ(count(text, "solid pellets"), 2);    // solid, endsolid
            EXPECT_EQ(count(text, "endsolid"), 1);
        }

        // All triangles are there, at their places
        pointField p;
        List<triFace> t;
        string why;
        ASSERT_TRUE(rbd::cgalMeshTools::readSTL(f, p, t, why)) << why;
        EXPECT_EQ(t.size(), 3*body.nFaces());
        EXPECT_NEAR(rbd::triMesh(p, t).volume(), 3*body.volume(), 1e-12);
        EXPECT_NEAR(max(p).x(), 0.04 + 0.005, 1e-7);

        // ... and as a pellet shape it is three parts
        EXPECT_TRUE(rejects(f, "3 separate parts"));
        Foam::rm(f);
    }
}

TEST(stlIO, badFilesAreRejectedWithReason)
{
    EXPECT_TRUE(rejects(rbdTest::tmpFile("missing.stl"), "cannot find file"));

    const fileName open = rbdTest::tmpFile("open.stl");
    writeOne(open, rbdTest::without(rbdTest::box(), {10, 11}), false);
    EXPECT_TRUE(rejects(open, "not closed: 4 border edges"));
    EXPECT_TRUE(rejects(open, "open.stl"));
    Foam::rm(open);

    const fileName inward = rbdTest::tmpFile("inward.stl");
    rbd::triMesh box = rbdTest::box();
    box.flip();
    writeOne(inward, box, true);
    EXPECT_TRUE(rejects(inward, "inward oriented"));
    Foam::rm(inward);

    const fileName junk = rbdTest::tmpFile("junk.stl");
    {
        std::ofstream os(junk);
        for (int i = 0; i < 10; ++i)
        {
            os << "this is not an STL file\n";
        }
    }
    EXPECT_TRUE(rejects(junk, "cannot read"));
    Foam::rm(junk);

    const fileName empty = rbdTest::tmpFile("empty.stl");
    {
        std::ofstream os(empty);
    }
    EXPECT_TRUE(rejects(empty, "no triangles"));
    Foam::rm(empty);
}

TEST(stlIO, openFoamReadsBinaryBed)
{
    // OpenFOAM's own STL reader (surfaceCheck of Debian's OpenFOAM v1912)
    if (std::system("command -v surfaceCheck > /dev/null 2>&1") != 0)
    {
        GTEST_SKIP() << "surfaceCheck not on PATH";
    }

    const rbd::triMesh body = rbd::pelletMeshes::ring(0.01, 0.006, 0.01, 500);
    // In a directory of its own: surfaceCheck writes its findings (.vtp,
    // .obj) next to the surface
    const fileName dir = rbdTest::tmpFile("surfaceCheck");
    ASSERT_TRUE(Foam::mkDir(dir));
    const fileName f = dir/"bed-of.stl";
    {
        rbd::stlWriter w(f, true);
        w.write(body, tensor::I, vector::zero);
        w.write(body, quaternion(vector(0, 1, 0), 1.0).R(), vector(0.02, 0, 0));
    }
    const fileName log = dir/"surfaceCheck.log";
    const std::string cmd =
        "surfaceCheck " + f + " > " + log + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << contents(log);

    const std::string out = contents(log);
    EXPECT_NE
    (
        out.find
        (
            "Triangles    : " + std::to_string(2*body.nFaces())
          + " in 1 region(s)"
        ),
        std::string::npos
    ) << out;
    EXPECT_NE(out.find("Surface is closed"), std::string::npos) << out;
    EXPECT_NE(out.find("Number of unconnected parts : 2"), std::string::npos)
        << out;
    Foam::rmDir(dir);
}

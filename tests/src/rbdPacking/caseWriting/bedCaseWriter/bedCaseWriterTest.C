// Unit tests for src/rbdPacking/caseWriting/bedCaseWriter, on the
// hand-placed bed of caseWritingTestBed.H (18 spheres, D = 4 dp)

#include <gtest/gtest.h>
#include "bedCaseWriter.H"
#include "foamFile.H"
#include "IFstream.H"
#include "OFstream.H"
#include "mathematicalConstants.H"
#include "labelPair.H"
#include "dimensionedScalar.H"
#include <sstream>
#include "rbdPacking/caseWriting/caseWritingTestBed.H"
#include "rbdPacking/caseWriting/caseWritingTempDir.H"

using namespace Foam;
namespace bed = caseWritingTestBed;

namespace
{
    const scalar dp = 0.01;

    rbd::bedCaseSettings settings(const char* options = "")
    {
        return rbd::bedCaseSettings
        (
            bed::tubeDiameter(dp), dp, bed::bedHeight(dp), point::zero,
            rbd::parseDictionary(options)
        );
    }

    //- The bed's inside test
    rbd::bedCaseWriter::insideFunction spheres()
    {
        const pointField c = bed::centres(dp);
        return [c](const point& p) { return bed::inside(c, 0.5*dp, p); };
    }

    //- Radial distance from the tube axis
    scalar radius(const point& p)
    {
        return Foam::sqrt(sqr(p.x()) + sqr(p.y()));
    }

    //- Distance from p to the nearest sphere surface (< 0 inside)
    scalar clearance(const point& p)
    {
        scalar d = GREAT;
        for (const point& c : bed::centres(dp))
        {
            d = min(d, mag(p - c) - 0.5*dp);
        }
        return d;
    }

    //- Vertices of an ASCII STL
    List<point> stlVertices(const fileName& file)
    {
        IFstream is(file);
        DynamicList<point> v;
        std::string line;
        while (is.good())
        {
            is.getLine(line);
            std::istringstream words(line);
            std::string key;
            point p;
            if (words >> key && key == "vertex")
            {
                words >> p.x() >> p.y() >> p.z();
                v.append(p);
            }
        }
        return List<point>(std::move(v));
    }
}


TEST(caseWritingTestBed, spheresNeitherOverlapNorTouchTheWall)
{
    const pointField c = bed::centres(dp);
    ASSERT_EQ(c.size(), 18);
    scalar top = 0;
    forAll(c, i)
    {
        EXPECT_LT(radius(c[i]) + 0.5*dp, 0.5*bed::tubeDiameter(dp));
        EXPECT_GE(c[i].z() - 0.5*dp, -1e-15);
        top = max(top, c[i].z() + 0.5*dp);
        for (label j = 0; j < i; ++j)
        {
            EXPECT_GT(mag(c[i] - c[j]), 1.05*dp) << i << ' ' << j;
        }
    }
    EXPECT_NEAR(top, bed::bedHeight(dp), 1e-15);
}


TEST(bedCaseWriter, writesEveryFile)
{
    const caseWritingTest::tempDir tmp;
    ASSERT_FALSE(tmp.path().empty());
    const rbd::bedCaseSettings s = settings();
    const rbd::bedCaseWriter writer(tmp.path(), s, spheres());

    const fileNameList kept = writer.write();
    EXPECT_EQ(kept.size(), 0);

    for (const fileName& f : rbd::bedCaseWriter::files())
    {
        ASSERT_TRUE(isFile(tmp.path()/f)) << f;
        if (f.ext() != "stl")
        {
            // Parses, with the FoamFile header OpenFOAM's tools expect
            IFstream is(tmp.path()/f);
            const dictionary d(is, true);
            EXPECT_EQ
            (
                d.subDict("FoamFile").get<word>("object"), f.name()
            ) << f;
        }
    }

    // Patch names: snappy geometry names, block patches, field entries
    const dictionary snappy
    (
        rbd::readFoamFile(tmp.path()/"system/snappyHexMeshDict")
    );
    const dictionary& geometry = snappy.subDict("geometry");
    EXPECT_EQ
    (
        geometry.subDict("pellets.stl").get<word>("name"), "pellets"
    );
    EXPECT_EQ(geometry.subDict("tube.stl").get<word>("name"), "wall");
    EXPECT_TRUE(snappy.found("addLayersControls"));
    const dictionary& refinement =
        snappy.subDict("castellatedMeshControls").subDict
        (
            "refinementSurfaces"
        );
    EXPECT_EQ
    (
        refinement.subDict("pellets").get<labelPair>("level"),
        labelPair(1, 1)
    );

    const dictionary U(rbd::readFoamFile(tmp.path()/"0/U"));
    const dictionary& Ubf = U.subDict("boundaryField");
    for (const char* patch : {"inlet", "outlet", "wall", "pellets"})
    {
        EXPECT_TRUE(Ubf.found(patch)) << patch;
    }
    EXPECT_FALSE(Ubf.found("bridges"));
    const dictionary p(rbd::readFoamFile(tmp.path()/"0/p"));
    EXPECT_EQ
    (
        p.subDict("boundaryField").subDict("pellets").get<word>("type"),
        "zeroGradient"
    );

    // Inlet velocity and viscosity as set
    ITstream& inlet = Ubf.subDict("inlet").lookup("value");
    word uniform;
    vector Uin;
    inlet >> uniform >> Uin;
    EXPECT_LT(mag(Uin - vector(0, 0, s.superficialVelocity())), 1e-15);
    const dictionary transport
    (
        rbd::readFoamFile(tmp.path()/"constant/transportProperties")
    );
    EXPECT_DOUBLE_EQ
    (
        dimensionedScalar("nu", dimArea/dimTime, transport).value(), s.nu()
    );
    EXPECT_EQ
    (
        rbd::readFoamFile(tmp.path()/"constant/turbulenceProperties")
       .get<word>("simulationType"),
        "laminar"
    );

    // Background box of the settings
    const dictionary block
    (
        rbd::readFoamFile(tmp.path()/"system/blockMeshDict")
    );
    const List<point> vertices = block.get<List<point>>("vertices");
    ASSERT_EQ(vertices.size(), 8);
    EXPECT_LT(mag(vertices[0] - s.blockMin()), 1e-12);
    EXPECT_LT(mag(vertices[6] - s.blockMax()), 1e-12);

    // Sampling planes at the bed's bottom and top
    const dictionary control
    (
        rbd::readFoamFile(tmp.path()/"system/controlDict")
    );
    const auto planeZ = [&](const word& object)
    {
        return control.subDict("functions").subDict(object)
            .subDict("sampledSurfaceDict").subDict("pointAndNormalDict")
            .get<point>("point").z();
    };
    EXPECT_DOUBLE_EQ(planeZ(rbd::bedCaseWriter::bedBottomObject), 0);
    EXPECT_NEAR
    (
        planeZ(rbd::bedCaseWriter::bedTopObject), bed::bedHeight(dp), 1e-12
    );

    // Decomposition along the axis
    const dictionary decompose
    (
        rbd::readFoamFile(tmp.path()/"system/decomposeParDict")
    );
    EXPECT_EQ(decompose.get<label>("numberOfSubdomains"), s.nProcessors());
    EXPECT_EQ(decompose.get<word>("method"), "hierarchical");
}


TEST(bedCaseWriter, keepsExistingFilesUnlessOverwrite)
{
    const caseWritingTest::tempDir tmp;
    const fileName control(tmp.path()/"system/controlDict");
    mkDir(control.path());
    {
        OFstream os(control);
        os << "// the user's own controlDict" << nl;
    }
    const auto firstLine = [&]()
    {
        IFstream is(control);
        std::string line;
        is.getLine(line);
        return line;
    };

    {
        const rbd::bedCaseWriter writer(tmp.path(), settings(), spheres());
        const fileNameList kept = writer.write();
        ASSERT_EQ(kept.size(), 1);
        EXPECT_EQ(kept[0], "system/controlDict");
        EXPECT_EQ(firstLine(), "// the user's own controlDict");
        EXPECT_TRUE(isFile(tmp.path()/"system/blockMeshDict"));
    }
    {
        const rbd::bedCaseWriter writer
        (
            tmp.path(), settings("overwrite yes;"), spheres()
        );
        EXPECT_EQ(writer.write().size(), 0);
        EXPECT_NE(firstLine(), "// the user's own controlDict");
        EXPECT_EQ
        (
            rbd::readFoamFile(control).get<word>("application"),
            "simpleFoam"
        );
    }
}


TEST(bedCaseWriter, locationInMeshInFluidOffFaces)
{
    const rbd::bedCaseSettings s = settings();
    point p;
    ASSERT_TRUE(rbd::bedCaseWriter::findLocationInMesh(s, spheres(), p));

    const scalar h = s.cellSize();
    EXPECT_LT(radius(p), s.tubeRadius() - 2*h);
    EXPECT_GT(clearance(p), 0);
    EXPECT_GT(p.z(), s.blockMin().z());
    EXPECT_LT(p.z(), s.blockMax().z());

    // At the chosen fractions of its background cell: on no face of any
    // refinement level
    const vector span = s.blockMax() - s.blockMin();
    for (direction i = 0; i < 3; ++i)
    {
        const scalar x = (p[i] - s.blockMin()[i])/span[i]*s.blockCells()[i];
        EXPECT_NEAR
        (
            x - std::floor(x), rbd::bedCaseWriter::cellFractions[i], 1e-9
        );
    }

    // and it is what snappyHexMeshDict gets
    const caseWritingTest::tempDir tmp;
    rbd::bedCaseWriter(tmp.path(), s, spheres()).write();
    const point written =
        rbd::readFoamFile(tmp.path()/"system/snappyHexMeshDict")
       .subDict("castellatedMeshControls").get<point>("locationInMesh");
    EXPECT_LT(mag(written - p), 1e-12);
}


TEST(bedCaseWriter, locationInMeshFoundInsideTheBed)
{
    // Pretend the empty sections are solid: the point must come from the
    // scan of the bed, outside every sphere by at least a cell along the
    // axes, and inside the tube
    const rbd::bedCaseSettings s = settings();
    const rbd::bedCaseWriter::insideFunction bedOnly = spheres();
    const auto blocked = [&](const point& x)
    {
        return x.z() < s.bedBottom() || x.z() > s.bedTop() || bedOnly(x);
    };

    point p;
    ASSERT_TRUE(rbd::bedCaseWriter::findLocationInMesh(s, blocked, p));
    const scalar h = max(s.cellSize(), s.cellSizeZ());
    EXPECT_GT(p.z(), s.bedBottom());
    EXPECT_LT(p.z(), s.bedTop());
    EXPECT_LT(radius(p), s.tubeRadius() - 2*s.cellSize());
    EXPECT_FALSE(blocked(p));
    for (direction i = 0; i < 3; ++i)
    {
        vector e(Zero);
        e[i] = h;
        EXPECT_FALSE(blocked(p + e));
        EXPECT_FALSE(blocked(p - e));
    }
}


TEST(bedCaseWriter, noLocationInMeshWhenAllIsSolid)
{
    point p;
    EXPECT_FALSE
    (
        rbd::bedCaseWriter::findLocationInMesh
        (
            settings(), [](const point&) { return true; }, p
        )
    );
}


TEST(bedCaseWriterDeath, writeStopsWithoutLocationInMesh)
{
    const caseWritingTest::tempDir tmp;
    const rbd::bedCaseWriter writer
    (
        tmp.path(), settings(), [](const point&) { return true; }
    );
    EXPECT_EXIT
    (
        writer.write(),
        ::testing::ExitedWithCode(1),
        "No point in the fluid"
    );
}


TEST(bedCaseWriterDeath, refusesSettingsWithoutBedHeight)
{
    const caseWritingTest::tempDir tmp;
    const rbd::bedCaseSettings noHeight(0.04, 0.01, point::zero, dictionary());
    EXPECT_EXIT
    (
        rbd::bedCaseWriter
        (
            tmp.path(), noHeight, [](const point&) { return false; }
        ),
        ::testing::ExitedWithCode(1),
        "bed height has not been given"
    );
}


TEST(bedCaseWriter, tubeHasTheAreaOfTheCircleAndOutreachesTheBox)
{
    const caseWritingTest::tempDir tmp;
    const rbd::bedCaseSettings s = settings();
    rbd::bedCaseWriter(tmp.path(), s, spheres()).write();

    const List<point> v =
        stlVertices(tmp.path()/"constant/triSurface/tube.stl");
    ASSERT_GT(v.size(), 0);

    scalar rMin = GREAT, rMax = 0, zMin = GREAT, zMax = -GREAT;
    DynamicList<scalar> angles;
    for (const point& p : v)
    {
        rMin = min(rMin, radius(p));
        rMax = max(rMax, radius(p));
        zMin = min(zMin, p.z());
        zMax = max(zMax, p.z());
    }
    EXPECT_NEAR(rMin, rMax, 1e-12);
    EXPECT_LT(zMin, s.blockMin().z());
    EXPECT_GT(zMax, s.blockMax().z());

    // Distinct corner angles on the bottom ring = number of sides n;
    // regular polygon area n/2 r^2 sin(2 pi/n) equals pi R^2
    label n = 0;
    for (const point& p : v)
    {
        if (p.z() < zMin + 1e-12)
        {
            bool seen = false;
            const scalar a = std::atan2(p.y(), p.x());
            for (const scalar b : angles)
            {
                seen = seen || mag(a - b) < 1e-9;
            }
            if (!seen)
            {
                angles.append(a);
                ++n;
            }
        }
    }
    const scalar pi = constant::mathematical::pi;
    EXPECT_GE(n, 64);
    EXPECT_NEAR
    (
        0.5*n*sqr(rMax)*Foam::sin(2*pi/n), pi*sqr(s.tubeRadius()),
        1e-9*sqr(s.tubeRadius())
    );
    // No facet wider than a background cell at the wall
    EXPECT_LE(2*pi*rMax/n, s.cellSize());
}


TEST(bedCaseWriter, addedSurfaceGetsGeometryFeaturesAndPatchEntries)
{
    const caseWritingTest::tempDir tmp;
    rbd::bedCaseWriter writer(tmp.path(), settings(), spheres());
    writer.addSurface("bridges", "bridges.stl", 2);
    ASSERT_EQ(writer.surfaces().size(), 1);
    writer.write();

    const dictionary snappy
    (
        rbd::readFoamFile(tmp.path()/"system/snappyHexMeshDict")
    );
    EXPECT_EQ
    (
        snappy.subDict("geometry").subDict("bridges.stl").get<word>("name"),
        "bridges"
    );
    EXPECT_EQ
    (
        snappy.subDict("castellatedMeshControls")
       .subDict("refinementSurfaces").subDict("bridges")
       .get<labelPair>("level"),
        labelPair(2, 2)
    );
    EXPECT_TRUE
    (
        rbd::readFoamFile(tmp.path()/"system/surfaceFeatureExtractDict")
       .found("bridges.stl")
    );
    const dictionary U(rbd::readFoamFile(tmp.path()/"0/U"));
    EXPECT_EQ
    (
        U.subDict("boundaryField").subDict("bridges").get<word>("type"),
        "noSlip"
    );
}


TEST(bedCaseWriterDeath, rejectsTakenSurfaceName)
{
    rbd::bedCaseWriter writer(".", settings(), spheres());
    EXPECT_EXIT
    (
        writer.addSurface("pellets", "more.stl", 1),
        ::testing::ExitedWithCode(1),
        "Surface name 'pellets' is taken"
    );
    EXPECT_EXIT
    (
        writer.addSurface("inlet", "inlet.stl", 1),
        ::testing::ExitedWithCode(1),
        "is taken by the block mesh"
    );
}

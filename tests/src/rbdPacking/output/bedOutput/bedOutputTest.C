// Unit tests for src/rbdPacking/output/bedOutput with nonspherical
// pellets: pellets.stl of posed meshes, profiles from meshSolidSet,
// orientation statistics, bridges in the pellets solid

#include <gtest/gtest.h>
#include "bedOutput.H"
#include "cgalMeshTools.H"
#include "IStringStream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"

using namespace Foam;
using Foam::constant::mathematical::pi;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }
}


TEST(bedOutput, cylindersWriteMeshesProfilesAndOrientation)
{
    const rbd::tube container(parse("diameter 0.04; height 0.1;"));
    autoPtr<rbd::pelletShape> shape = rbd::pelletShape::New
    (
        parse("shape cylinder; diameter 0.01; height 0.01; faces 1000;")
    );
    // Two upright cylinders on the floor, one lying on top
    const vector I = shape->principalInertiaPerDensity();
    List<rbd::rigidBody> bodies;
    bodies.append(rbd::rigidBody(1, I, point(-0.008, 0, 0.005),
        quaternion(1), true));
    bodies.append(rbd::rigidBody(1, I, point(0.008, 0, 0.005),
        quaternion(1), true));
    bodies.append(rbd::rigidBody(1, I, point(0, 0, 0.016),
        quaternion(vector(1, 0, 0), 0.5*pi), true));

    const fileName dir
    (
        "/tmp/rbdBedOutputTest-" + std::to_string(::getpid())
    );
    rbd::bedOutput out(dir, container, shape(), bodies);

    // pellets.stl: three posed meshes in one solid
    out.writeSTL(false, 1);
    pointField pts;
    List<triFace> faces;
    string why;
    ASSERT_TRUE(rbd::cgalMeshTools::readSTL(out.stlFile(), pts, faces, why))
        << why;
    EXPECT_EQ(faces.size(), 3*shape->mesh().nFaces());
    // The STL holds the volume-true meshes: the cylinder's exact volume
    // (the contact mesh is 0.3 % smaller at 1000 faces)
    const scalar Vm = pi/4*sqr(0.01)*0.01;
    EXPECT_LT(shape->mesh().volume(), (1 - 1e-3)*Vm);
    // (ASCII STL: single precision)
    EXPECT_NEAR(rbd::triMesh(pts, faces).volume(), 3*Vm, 1e-5*Vm);

    // Porosity below H = 0.01: the two upright ones whole, the lying one
    // (axis along y, centre 0.016) reaches down to 0.011: nothing of it;
    // of the exact cylinders
    const dictionary analysis(out.writeProfiles(0.01, 20, 10));
    EXPECT_NEAR
    (
        analysis.get<scalar>("bulkPorosity"),
        1 - 2*Vm/(pi*0.0004*0.01),
        1e-10
    );
    // The sphere correlations are for spheres only
    EXPECT_FALSE(analysis.found("radialCorrelations"));
    EXPECT_TRUE(isFile(out.directory()/"radialPorosity.dat"));

    // Orientation of the pellets with centres below H = 0.02: 0, 0, 90
    dictionary summary;
    out.writeOrientation(0.02, 9, summary);
    EXPECT_EQ(summary.get<label>("orientedPellets"), 3);
    EXPECT_NEAR(summary.get<scalar>("meanAxisAngle"), 30, 1e-6);
    EXPECT_TRUE(isFile(out.directory()/"orientation.dat"));

    // Bridges at the contacts of the list: one between pellets 2 and 0
    // (at the top face of 0), one of pellet 1 with the wall; the tube
    // bottom is skipped
    const rbd::bedCaseSettings settings
    (
        0.04, shape->volumeEquivalentDiameter(), point::zero,
        parse("contactTreatment bridges;")
    );
    List<rbd::contact> contacts(3);
    for (rbd::contact& c : contacts)
    {
        c.nDot = Zero;
        c.e = 0.9;
        c.mu = 0.1;
        c.centreBased = false;
    }
    contacts[0].i = 2; contacts[0].k = 0; contacts[0].n = vector(0, 0, 1);
    contacts[0].p = point(-0.008, 0, 0.010); contacts[0].gap = 0;
    // (pellet 1's surface x = 0.013 as the wall: the caps below cut it)
    contacts[1].i = 1; contacts[1].k = rbd::tubeWall;
    contacts[1].n = vector(-1, 0, 0); contacts[1].p = point(0.013, 0, 0.005);
    contacts[1].gap = 0;
    contacts[2].i = 1; contacts[2].k = rbd::tubeBottom;
    contacts[2].n = vector(0, 0, 1); contacts[2].p = point(0.008, 0, 0);
    contacts[2].gap = 0;
    label n = 0;
    const List<rbd::triMesh> s = out.pelletSurfaces(settings, contacts, n);
    EXPECT_EQ(n, 2);
    ASSERT_EQ(s.size(), 5);
    const scalar db = settings.bridgeDiameter();
    EXPECT_NEAR(db, 0.2*shape->volumeEquivalentDiameter(), 1e-15);
    EXPECT_NEAR(s[3].volume()/(0.25*pi*db*db*db), 1, 0.03);
    EXPECT_EQ(out.writeSTL(settings, contacts), 2);

    // caps: the cut pellets lose material, no surface is added
    const rbd::bedCaseSettings caps
    (
        0.04, shape->volumeEquivalentDiameter(), point::zero,
        parse("contactTreatment caps; capHeight 0.0002;")
    );
    const List<rbd::triMesh> c = out.pelletSurfaces(caps, contacts, n);
    ASSERT_EQ(c.size(), 3);
    // Upright cylinder 0 cut at its top face: a disc slab 0.2 mm thick
    EXPECT_NEAR(Vm - c[0].volume(), 0.0002*Vm/0.01, 1e-3*Vm);
    // Cylinder 1 flattened at the wall: a circular segment of height hc
    // (of the volume-true polygon: within 10 % of the circle's)
    const scalar r = 0.005, hc = 0.0002;
    const scalar segment =
        sqr(r)*std::acos((r - hc)/r) - (r - hc)*std::sqrt(2*r*hc - sqr(hc));
    EXPECT_NEAR((Vm - c[1].volume())/(segment*0.01), 1, 0.1);
    EXPECT_EQ(rbd::checkClosedSolid(c[1]), "");

    Foam::rmDir(dir);
}


TEST(bedOutput, capsCutAPelletAtTheWallWithoutATouchingContact)
{
    // An upright cylinder whose exact rim reaches 10 um beyond the wall (an
    // overlap of 0.1 % dp) and no contact in the list: with caps it is cut
    // by the wall's tangent plane, its written surface ending capHeight/2
    // or more inside the wall; without a treatment it crosses the wall
    const scalar R = 0.02;
    const rbd::tube container(parse("diameter 0.04; height 0.1;"));
    autoPtr<rbd::pelletShape> shape = rbd::pelletShape::New
    (
        parse("shape cylinder; diameter 0.01; height 0.01; faces 400;")
    );
    const vector I = shape->principalInertiaPerDensity();
    List<rbd::rigidBody> bodies;
    bodies.append(rbd::rigidBody(1, I, point(R - 0.005 + 1e-5, 0, 0.005),
        quaternion(1), true));
    const fileName dir
    (
        "/tmp/rbdBedOutputWallCapTest-" + std::to_string(::getpid())
    );
    rbd::bedOutput out(dir, container, shape(), bodies);
    const List<rbd::contact> none;
    auto reach = [](const rbd::triMesh& m)
    {
        scalar rho = 0;
        for (const point& x : m.points())
        {
            rho = max(rho, rbd::tube::axialDistance(x));
        }
        return rho;
    };

    label n = -1;
    const rbd::bedCaseSettings plain
    (
        0.04, shape->volumeEquivalentDiameter(), point::zero,
        parse("contactTreatment none;")
    );
    EXPECT_GT(reach(out.pelletSurfaces(plain, none, n)[0]), R);

    const scalar hc = 0.0002;
    const rbd::bedCaseSettings caps
    (
        0.04, shape->volumeEquivalentDiameter(), point::zero,
        parse("contactTreatment caps; capHeight 0.0002;")
    );
    const List<rbd::triMesh> c = out.pelletSurfaces(caps, none, n);
    EXPECT_EQ(n, 1);
    EXPECT_LE(reach(c[0]), R - 0.5*hc);
    EXPECT_GT(reach(c[0]), R - 2*hc);
    EXPECT_EQ(rbd::checkClosedSolid(c[0]), "");
    Foam::rmDir(dir);
}


// ************************************************************************* //

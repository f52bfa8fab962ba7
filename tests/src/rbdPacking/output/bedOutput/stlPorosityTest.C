// Unit tests for the porosity of pellets.stl (src/rbdPacking/output/
// bedOutput: surfacePorosity, the summary's stlPorosity) against the
// bulk porosity of the exact pellets (writeProfiles' bulkPorosity), for
// every shape at its default faces, and how the contact treatments shift
// it.

#include <gtest/gtest.h>
#include "bedOutput.H"
#include "meshSolidSet.H"
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

    fileName tmpCase(const std::string& name)
    {
        return
            "/tmp/rbdStlPorosityTest-" + name + "-"
          + std::to_string(::getpid());
    }

    //- Two layers of 3 x 3 pellets, each turned its own way, not touching;
    //  the tube radius leaves them room. The slab of the bulk porosity
    //  (H 0.3 rb below the centres of the upper layer) cuts the upper
    //  layer off its centres
    List<rbd::rigidBody> twoLayers
    (
        const rbd::pelletShape& shape,
        scalar& R,
        scalar& H
    )
    {
        const scalar rb = shape.boundingRadius();
        const scalar pitch = 2.05*rb;
        const vector I = shape.principalInertiaPerDensity();
        List<rbd::rigidBody> bodies;
        label k = 0;
        for (const scalar z : {1.01*rb, 3.1*rb})
        {
            for (label i = -1; i <= 1; ++i)
            {
                for (label j = -1; j <= 1; ++j)
                {
                    const quaternion q
                    (
                        normalised(vector(1, 2 + k, 3 - 0.5*k)),
                        0.3 + 0.7*k
                    );
                    bodies.append
                    (
                        rbd::rigidBody
                        (
                            1, I, point(i*pitch, j*pitch, z), q, true
                        )
                    );
                    ++k;
                }
            }
        }
        R = std::sqrt(2.0)*pitch + 1.05*rb;
        H = 2.8*rb;
        return bodies;
    }

    //- The pellets dictionaries: every shape at its default faces
    const std::initializer_list<const char*> shapes
    {
        "shape sphere; diameter 0.01;",
        "shape cylinder; diameter 0.01; height 0.01;",
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;",
        "shape trilobe; lobeDiameter 0.004; height 0.006;",
        "shape quadrilobe; lobeDiameter 0.004; height 0.006;",
        "shape cylinderWithHoles; diameter 0.01; height 0.008; holes 4;"
        " holeDiameter 0.002;"
    };
}


TEST(stlPorosity, agreesWithBulkPorosityForEveryShapeAtDefaultFaces)
{
    for (const char* text : shapes)
    {
        autoPtr<rbd::pelletShape> shape = rbd::pelletShape::New(parse(text));
        scalar R = 0, H = 0;
        const List<rbd::rigidBody> bodies(twoLayers(shape(), R, H));
        const rbd::tube container
        (
            parse
            (
                "diameter " + std::to_string(2*R) + "; height "
              + std::to_string(10*H) + ";"
            )
        );
        const fileName dir(tmpCase(shape->type()));
        const rbd::bedOutput out(dir, container, shape(), bodies);

        const scalar bulk =
            out.writeProfiles(H, 10, 10).get<scalar>("bulkPorosity");
        const rbd::bedCaseSettings none
        (
            2*R, shape->volumeEquivalentDiameter(), point::zero,
            parse("contactTreatment none;")
        );
        label n = -1;
        const List<rbd::triMesh> surfaces
        (
            out.pelletSurfaces(none, List<rbd::contact>(), n)
        );
        EXPECT_EQ(n, 0);
        ASSERT_EQ(surfaces.size(), bodies.size());
        const scalar stl = out.surfacePorosity(surfaces, H);

        // The inscribed contact meshes would hold less solid
        pointField centres(bodies.size());
        tensorField rotations(bodies.size());
        forAll(bodies, i)
        {
            centres[i] = bodies[i].x();
            rotations[i] = bodies[i].R();
        }
        const rbd::meshSolidSet inscribed(shape->mesh(), centres, rotations);
        scalar Vi = 0;
        forAll(bodies, i)
        {
            Vi += inscribed.volume(i, 0, H);
        }
        const scalar inscribedEps = 1 - Vi/(pi*sqr(R)*H);

        // The whole lower layer and part of the upper
        const scalar Vp = shape->exactVolume()/(pi*sqr(container.radius())*H);
        EXPECT_GT(1 - bulk, 9.01*Vp) << text;
        EXPECT_LT(1 - bulk, 13.5*Vp) << text;
        EXPECT_NEAR(stl, bulk, 1e-3) << text;
        std::cout
            << shape->type() << " (" << shape->mesh().nFaces()
            << " faces): bulkPorosity " << bulk << ", stlPorosity " << stl
            << " (" << stl - bulk << "), inscribed meshes "
            << inscribedEps << " (" << inscribedEps - bulk << ")\n";
        Foam::rmDir(dir);
    }
}

TEST(stlPorosity, coarseSpheresAreVolumeTrueToo)
{
    // 320 faces: the inscribed spheres lack 3.4 % of their volume, the
    // bed's porosity is off by about 0.034 (1 - eps); the volume-true
    // facets agree with the exact spheres
    autoPtr<rbd::pelletShape> shape =
        rbd::pelletShape::New(parse("shape sphere; diameter 0.01; faces 320;"));
    scalar R = 0, H = 0;
    const List<rbd::rigidBody> bodies(twoLayers(shape(), R, H));
    const rbd::tube container
    (
        parse("diameter " + std::to_string(2*R) + "; height 1;")
    );
    const fileName dir(tmpCase("coarse"));
    const rbd::bedOutput out(dir, container, shape(), bodies);
    const scalar bulk =
        out.writeProfiles(H, 10, 10).get<scalar>("bulkPorosity");
    const rbd::bedCaseSettings none
    (
        2*R, 0.01, point::zero, parse("contactTreatment none;")
    );
    label n = 0;
    const scalar stl = out.surfacePorosity
    (
        out.pelletSurfaces(none, List<rbd::contact>(), n), H
    );
    EXPECT_NEAR(stl, bulk, 1e-3);
    // The exact spheres' solid: 9 whole and 9 caps of height 0.7 a
    const scalar a = 0.005, h = 0.7*a;
    const scalar Rt = container.radius();
    EXPECT_NEAR
    (
        bulk,
        1 - 9*(pi/6*1e-6 + pi*sqr(h)*(3*a - h)/3)/(pi*sqr(Rt)*H),
        1e-12
    );
    // The inscribed spheres would be off by about 3.4 % of the solid
    std::cout
        << "spheres of 320 faces: bulkPorosity " << bulk
        << ", stlPorosity " << stl << " (" << stl - bulk << ")\n";
    Foam::rmDir(dir);
}

TEST(stlPorosity, treatmentsShiftItAsDefined)
{
    // Two spheres of radius a = 5 mm, one on the other, touching; the slab
    // holds both whole (their facets too: 1 % of a above the floor)
    const scalar a = 0.005;
    const scalar z0 = 1.01*a;
    autoPtr<rbd::pelletShape> shape =
        rbd::pelletShape::New(parse("shape sphere; diameter 0.01;"));
    const vector I = shape->principalInertiaPerDensity();
    List<rbd::rigidBody> bodies;
    bodies.append(rbd::rigidBody(1, I, point(0, 0, z0), quaternion(1), true));
    bodies.append
    (
        rbd::rigidBody(1, I, point(0, 0, z0 + 2*a), quaternion(1), true)
    );
    const rbd::tube container(parse("diameter 0.03; height 0.1;"));
    const fileName dir(tmpCase("treatments"));
    const rbd::bedOutput out(dir, container, shape(), bodies);
    const scalar H = 5*a;
    const scalar Vbed = pi*sqr(0.015)*H;

    List<rbd::contact> contacts(1);
    contacts[0].i = 1;
    contacts[0].k = 0;
    contacts[0].n = vector(0, 0, 1);
    contacts[0].p = point(0, 0, z0 + a);
    contacts[0].gap = 0;

    const auto porosity = [&](const std::string& entries)
    {
        const rbd::bedCaseSettings settings
        (
            0.03, 2*a, point::zero, parse(entries)
        );
        label n = 0;
        return out.surfacePorosity
        (
            out.pelletSurfaces(settings, contacts, n), H
        );
    };

    // none: the two volume-true spheres, exact
    const scalar eps0 = porosity("contactTreatment none;");
    const scalar V = 2*pi/6*pow3(2*a);
    EXPECT_NEAR(eps0, 1 - V/Vbed, 1e-12);

    // shrink s: solid times s^3
    const scalar s = 0.99;
    EXPECT_NEAR
    (
        1 - porosity("contactTreatment shrink; shrinkFactor 0.99;"),
        pow3(s)*(1 - eps0),
        1e-12
    );

    // bridges: one cylinder of diameter db and length db (gap 0), all of
    // it counted; its mesh is an inscribed polygon prism (2 % smaller)
    const scalar db = 0.002;
    const scalar dBridge =
        eps0 - porosity("contactTreatment bridges; bridgeDiameter 0.002;");
    EXPECT_NEAR(dBridge*Vbed/(pi/4*sqr(db)*db), 1, 0.03);

    // caps hc: each sphere loses a cap pi hc^2 (3a - hc)/3 at the contact;
    // the facets are offset from the true sphere by up to 0.3 % of a =
    // 15 % of hc here, so the cut caps differ from the true ones by up to
    // about 30 %
    const scalar hc = 0.0001;
    const scalar dCaps =
        porosity("contactTreatment caps; capHeight 0.0001;") - eps0;
    const scalar caps = 2*pi*sqr(hc)*(3*a - hc)/3;
    EXPECT_GT(dCaps, 0);
    EXPECT_NEAR(dCaps*Vbed/caps, 1, 0.35);
    std::cout
        << "two spheres: stlPorosity none " << eps0 << ", bridges -"
        << dBridge << " (" << dBridge*Vbed/(pi/4*sqr(db)*db)
        << " of the bridge), caps +" << dCaps << " ("
        << dCaps*Vbed/caps << " of the two true caps)\n";
    Foam::rmDir(dir);
}

// Unit tests for src/rbdPacking/shapes/meshing/pelletMeshes
//
// Exactness: the mass properties of a prism mesh equal those of the
// polygonal prism it is (regular n-gons for circles). Convergence: volume
// and inertia approach the closed forms of the curved solids as the face
// count grows; the bounds at the paper's face counts (section 8: 3120
// sphere, 4400 cylinder, 8008 ring) are the measured errors, rounded up.

#include <gtest/gtest.h>
#include "pelletMeshes.H"
#include "massProperties.H"
#include "cgalMeshTools.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace Foam::constant::mathematical;

namespace
{
    //- Closed-form properties of a solid (per unit density)
    struct solid
    {
        scalar V;
        scalar Ix;     // about x (= about y for the shapes here)
        scalar Iz;     // about the axis z
    };

    //- Relative errors of a mesh against a solid (x, y, z moments)
    struct errors
    {
        scalar V, Ix, Iy, Iz;
    };

    errors relErrors(const rbd::triMesh& m, const solid& s)
    {
        const rbd::massProperties mp(m, 1);
        EXPECT_LT(mag(mp.centreOfMass()), 1e-12);
        return
        {
            mp.volume()/s.V - 1,
            mp.inertia().xx()/s.Ix - 1,
            mp.inertia().yy()/s.Ix - 1,
            mp.inertia().zz()/s.Iz - 1
        };
    }

    scalar maxErr(const errors& e)
    {
        return max(max(mag(e.V), mag(e.Ix)), max(mag(e.Iy), mag(e.Iz)));
    }

    //- Prism of cross-section area A, polar second moment J, height H
    solid prism(const scalar A, const scalar J, const scalar H)
    {
        return {A*H, H*J/2 + A*pow3(H)/12, H*J};
    }

    //- Regular n-gon of circumradius r: area and polar moment
    scalar ngonArea(const label n, const scalar r)
    {
        return 0.5*n*sqr(r)*std::sin(twoPi/n);
    }
    scalar ngonJ(const label n, const scalar r)
    {
        return n*pow4(r)/12*std::sin(twoPi/n)*(2 + std::cos(twoPi/n));
    }

    //- Number of top-rim points at distance r from c
    label nRim
    (
        const rbd::triMesh& m,
        const vector2D& c,
        const scalar r,
        const scalar zTop
    )
    {
        label n = 0;
        for (const point& p : m.points())
        {
            if
            (
                mag(p.z() - zTop) < 1e-12
             && mag(mag(vector2D(p.x(), p.y()) - c) - r) < 1e-12
            )
            {
                ++n;
            }
        }
        return n;
    }

    solid sphereSolid(const scalar d)
    {
        const scalar V = pi/6*pow3(d);
        return {V, 0.4*V*sqr(d/2), 0.4*V*sqr(d/2)};
    }

    solid ringSolid(const scalar D, const scalar d, const scalar H)
    {
        const scalar R2 = sqr(D/2), r2 = sqr(d/2);
        return prism(pi*(R2 - r2), pi/2*(sqr(R2) - sqr(r2)), H);
    }

    //- Lobed cross-section (see pelletMeshes.H): area and polar moment
    void lobesSection
    (
        const label n,
        const scalar dl,
        scalar& A,
        scalar& J
    )
    {
        const scalar r = dl/2;
        const scalar rc = rbd::pelletMeshes::defaultLobeCentreRadius(n, dl);
        const scalar s = std::sin(pi/n), c = std::cos(pi/n);
        const scalar t = rc*c + std::sqrt(sqr(r) - sqr(rc*s));
        const scalar beta = std::atan2(t*s, t*c - rc);

        // Wedge of lobe 0: triangles (O, C, V), (O, V', C) and the sector
        // of half-angle beta about C = (rc, 0)
        const vector2D C(rc, 0), V(t*c, t*s);
        const scalar triA = 0.5*rc*V.y();
        const scalar triJ =
            triA/6*(magSqr(C) + magSqr(V) + (C & V));
        const scalar secA = sqr(r)*beta;
        const scalar secJ =
            pow4(r)*beta/2 + 2*rc*(2.0/3)*pow3(r)*std::sin(beta)
          + secA*sqr(rc);
        A = n*(2*triA + secA);
        J = n*(2*triJ + secJ);
    }
}


// * * * * * * * * * * * * * * * * * Sphere * * * * * * * * * * * * * * * * //

TEST(pelletMeshes, sphereFaceCountIs20Times4PowK)
{
    EXPECT_EQ(rbd::pelletMeshes::sphere(0.01, 1).nFaces(), 20);
    EXPECT_EQ(rbd::pelletMeshes::sphere(0.01, 300).nFaces(), 320);
    EXPECT_EQ(rbd::pelletMeshes::sphere(0.01, 1280).nFaces(), 1280);
    EXPECT_EQ(rbd::pelletMeshes::sphere(0.01, 3120).nFaces(), 5120);
}

TEST(pelletMeshes, sphereConvergesToClosedForm)
{
    const scalar d = 0.01;
    const solid s = sphereSolid(d);

    scalar prev = GREAT;
    for (const label faces : {320, 1280, 5120})
    {
        const rbd::triMesh m = rbd::pelletMeshes::sphere(d, faces);
        for (const point& p : m.points())
        {
            ASSERT_NEAR(mag(p), d/2, 1e-15);
        }
        const errors e = relErrors(m, s);
        // Inscribed: too small; error ~ 1/faces
        EXPECT_LT(e.V, 0);
        EXPECT_LT(maxErr(e), prev/3.5);
        prev = maxErr(e);
    }
    // 5120 faces (the level for the paper's 3120): measured
    // dV = -0.215 %, dI = -0.357 %
    EXPECT_LT(prev, 3.6e-3);
}


// * * * * * * * * * * * * * * * * Prisms  * * * * * * * * * * * * * * * * //

TEST(pelletMeshes, cylinderIsExactPolygonPrism)
{
    const scalar d = 0.01, H = 0.012;
    const rbd::triMesh m = rbd::pelletMeshes::cylinder(d, H, 1000);
    const label n = nRim(m, vector2D::zero, d/2, H/2);
    ASSERT_GE(n, 16);
    const errors e = relErrors
    (
        m,
        prism(ngonArea(n, d/2), ngonJ(n, d/2), H)
    );
    EXPECT_LT(maxErr(e), 1e-12);
}

TEST(pelletMeshes, cylinderConvergesToClosedForm)
{
    const scalar d = 0.01, H = 0.01;
    const scalar r2 = sqr(d/2);
    const solid s = prism(pi*r2, pi/2*sqr(r2), H);

    scalar prev = GREAT;
    for (const label faces : {1100, 4400, 17600})
    {
        const rbd::triMesh m = rbd::pelletMeshes::cylinder(d, H, faces);
        EXPECT_NEAR(m.nFaces(), faces, 0.05*faces);
        const errors e = relErrors(m, s);
        EXPECT_LT(e.V, 0);
        EXPECT_LT(maxErr(e), prev/3.5);
        prev = maxErr(e);
        if (faces == 4400)
        {
            // Measured: dV = -0.147 %, dIx = -0.209 %, dIz = -0.293 %
            EXPECT_LT(maxErr(e), 3.0e-3);
        }
    }
}

TEST(pelletMeshes, ringIsExactPolygonPrism)
{
    const scalar D = 0.01, d = 0.006, H = 0.01;
    const rbd::triMesh m = rbd::pelletMeshes::ring(D, d, H, 3000);
    const label no = nRim(m, vector2D::zero, D/2, H/2);
    const label ni = nRim(m, vector2D::zero, d/2, H/2);
    ASSERT_GE(ni, 16);
    const errors e = relErrors
    (
        m,
        prism
        (
            ngonArea(no, D/2) - ngonArea(ni, d/2),
            ngonJ(no, D/2) - ngonJ(ni, d/2),
            H
        )
    );
    EXPECT_LT(maxErr(e), 1e-12);
}

TEST(pelletMeshes, paperRingConvergesToClosedForm)
{
    // Paper ring: 10/6/10 mm
    const solid s = ringSolid(0.01, 0.006, 0.01);
    scalar prev = GREAT;
    for (const label faces : {2000, 8008, 32000})
    {
        const rbd::triMesh m =
            rbd::pelletMeshes::ring(0.01, 0.006, 0.01, faces);
        EXPECT_NEAR(m.nFaces(), faces, 0.02*faces);
        const errors e = relErrors(m, s);
        EXPECT_LT(maxErr(e), prev/3.5);
        prev = maxErr(e);
        if (faces == 8008)
        {
            // Measured (7880 faces): dV = -9e-7 (the inner and outer
            // polygons cancel), dIx = -0.076 %, dIz = -0.151 %
            EXPECT_LT(maxErr(e), 1.6e-3);
        }
    }
}

TEST(pelletMeshes, lobesConvergeToClosedForm)
{
    const scalar dl = 0.004, H = 0.006;
    for (const label n : {3, 4})
    {
        scalar A, J;
        lobesSection(n, dl, A, J);
        const solid s = prism(A, J, H);

        scalar prev = GREAT;
        for (const label faces : {500, 2000, 8000})
        {
            const rbd::triMesh m = rbd::pelletMeshes::lobes(n, dl, H, faces);
            const errors e = relErrors(m, s);
            EXPECT_LT(e.V, 0) << n << " lobes";
            EXPECT_LT(maxErr(e), prev/3) << n << " lobes";
            prev = maxErr(e);
        }
        // Measured at 8000 faces: dV = -0.134 % (3 lobes), -0.142 % (4),
        // dIz = -0.261 %, -0.280 %
        EXPECT_LT(prev, 3e-3) << n << " lobes";
    }
}

TEST(pelletMeshes, cylinderWithHolesIsExactPolygonPrism)
{
    const scalar D = 0.01, H = 0.008, dh = 0.002;
    for (const label nHoles : {2, 4, 7})
    {
        const rbd::triMesh m =
            rbd::pelletMeshes::cylinderWithHoles(D, H, nHoles, dh, 2000);
        const scalar rh =
            rbd::pelletMeshes::defaultHoleCircleRadius(D, nHoles, dh);
        const label no = nRim(m, vector2D::zero, D/2, H/2);
        const label nh = nRim(m, vector2D(rh, 0), dh/2, H/2);
        ASSERT_GE(nh, 16);

        // In-plane second moments: regular polygons are isotropic (J/2
        // about every axis through their centre), holes shifted to c_k
        const scalar Ah = ngonArea(nh, dh/2), Jh = ngonJ(nh, dh/2);
        scalar A = ngonArea(no, D/2);
        scalar Sxx = ngonJ(no, D/2)/2, Syy = Sxx;
        for (label k = 0; k < nHoles; ++k)
        {
            const scalar theta = twoPi*k/nHoles;
            A -= Ah;
            Sxx -= Jh/2 + Ah*sqr(rh*std::cos(theta));
            Syy -= Jh/2 + Ah*sqr(rh*std::sin(theta));
        }
        const rbd::massProperties mp(m, 1);
        EXPECT_NEAR(mp.volume()/(A*H), 1, 1e-12);
        // About x: int (y^2 + z^2) dV
        EXPECT_NEAR(mp.inertia().xx()/(H*Syy + A*pow3(H)/12), 1, 1e-12);
        EXPECT_NEAR(mp.inertia().yy()/(H*Sxx + A*pow3(H)/12), 1, 1e-12);
        EXPECT_NEAR(mp.inertia().zz()/(H*(Sxx + Syy)), 1, 1e-12);
    }
}

TEST(pelletMeshes, oneHoleIsTheRing)
{
    const rbd::triMesh a = rbd::pelletMeshes::ring(0.01, 0.004, 0.01, 2000);
    const rbd::triMesh b =
        rbd::pelletMeshes::cylinderWithHoles(0.01, 0.01, 1, 0.004, 2000);
    EXPECT_EQ(a.nFaces(), b.nFaces());
    EXPECT_NEAR(a.volume(), b.volume(), 1e-18);
}


// * * * * * * * * * * * * * * * Validity * * * * * * * * * * * * * * * * * //

TEST(pelletMeshes, allShapesAreClosedManifoldOutward)
{
    const List<std::pair<std::string, rbd::triMesh>> meshes
    ({
        {"sphere", rbd::pelletMeshes::sphere(0.01, 1280)},
        {"cylinder", rbd::pelletMeshes::cylinder(0.01, 0.01, 1000)},
        {"flat cylinder", rbd::pelletMeshes::cylinder(0.01, 0.001, 300)},
        {"ring", rbd::pelletMeshes::ring(0.01, 0.006, 0.01, 2000)},
        {"thin ring", rbd::pelletMeshes::ring(0.01, 0.0095, 0.01, 1000)},
        {"trilobe", rbd::pelletMeshes::lobes(3, 0.004, 0.006, 1000)},
        {"quadrilobe", rbd::pelletMeshes::lobes(4, 0.004, 0.006, 1000)},
        {"2 holes", rbd::pelletMeshes::cylinderWithHoles
            (0.01, 0.008, 2, 0.002, 1500)},
        {"7 holes", rbd::pelletMeshes::cylinderWithHoles
            (0.01, 0.008, 7, 0.0015, 1500)}
    });
    for (const auto& nm : meshes)
    {
        EXPECT_EQ(rbd::checkClosedSolid(nm.second), "") << nm.first;
        EXPECT_GT(nm.second.volume(), 0) << nm.first;
    }
}

TEST(pelletMeshes, faceCountsNearTarget)
{
    for (const label faces : {1000, 4400, 8008})
    {
        for
        (
            const rbd::triMesh& m
          : {
                rbd::pelletMeshes::cylinder(0.01, 0.01, faces),
                rbd::pelletMeshes::ring(0.01, 0.006, 0.01, faces),
                rbd::pelletMeshes::lobes(3, 0.004, 0.006, faces),
                rbd::pelletMeshes::cylinderWithHoles
                    (0.01, 0.008, 4, 0.002, faces)
            }
        )
        {
            EXPECT_NEAR(m.nFaces(), faces, 0.05*faces);
        }
    }
}


// * * * * * * * * * * * * * * * Arguments  * * * * * * * * * * * * * * * * //

TEST(pelletMeshes, geometryErrorsExplainBadSizes)
{
    using namespace rbd::pelletMeshes;
    EXPECT_EQ(ringError(0.01, 0.006, 0.01, 100), "");
    EXPECT_NE(ringError(0.01, 0.01, 0.01, 100).find("smaller"),
        std::string::npos);
    EXPECT_NE(sphereError(-1, 100).find("diameter must be > 0"),
        std::string::npos);
    EXPECT_NE(cylinderError(0.01, 0.01, 0).find("face count"),
        std::string::npos);
    EXPECT_NE(lobesError(5, 0.004, 0.006, 100).find("3 or 4"),
        std::string::npos);
    EXPECT_NE(lobesError(3, 0.004, 0.006, 100, 0.002).find("lobe axes"),
        std::string::npos);
    EXPECT_EQ(lobesError(4, 0.004, 0.006, 100, 0.0019), "");
    EXPECT_EQ(cylinderWithHolesError(0.01, 0.01, 4, 0.002, 100), "");
    EXPECT_NE(cylinderWithHolesError(0.01, 0.01, 4, 0.003, 100, 0.002).find
        ("overlap"), std::string::npos);
    EXPECT_NE(cylinderWithHolesError(0.01, 0.01, 1, 0.002, 100, 0.004).find
        ("outer surface"), std::string::npos);
    EXPECT_EQ(cylinderWithHolesError(0.01, 0.01, 0, 0, 100), "");
}

TEST(pelletMeshesDeath, badSizesStop)
{
    EXPECT_EXIT
    (
        rbd::pelletMeshes::ring(0.006, 0.01, 0.01, 1000),
        ::testing::ExitedWithCode(1),
        "Invalid Raschig ring: the inner diameter"
    );
}

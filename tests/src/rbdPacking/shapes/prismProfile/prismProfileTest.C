// The exact solid of a prism over circular arcs:
// src/rbdPacking/shapes/prismProfile. Areas against closed forms, the signed
// distance against a dense sampling of the surface with an inside test of
// its own (inside a disc, in no hole, |z| <= h), the exposed arcs of the
// pellet shapes, and the profiles of the shapes against their meshes.

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"
#include "prismProfile.H"
#include "pelletShape.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

#include <random>
#include <sstream>
#include <vector>

using namespace Foam;
using namespace Foam::rbd;
using constant::mathematical::pi;
using constant::mathematical::twoPi;

namespace
{
    using rbdTest::str;

    //- The signed distance alone, and the 2-D one
    scalar sdOf(const prismProfile& prof, const point& p)
    {
        vector g;
        return prof.signedDistance(p, g);
    }

    scalar distance2DOf
    (
        const prismProfile& prof,
        const vector2D& p,
        vector2D& g
    )
    {
        label arcI;
        return prof.distance2D(p, g, arcI);
    }

    using rbdTest::shapeOf;

    //- A prism as the test knows it: solid discs and holes (profile
    //  frame), half height, its size d (outer diameter) and the dictionary
    //  of the pellet shape that has it
    struct prismCase
    {
        std::string name;
        std::string entries;
        List<vector2D> discs;
        List<scalar> discRadii;
        List<vector2D> holes;
        List<scalar> holeRadii;
        scalar h;
        scalar d;

        //- Inside the cross-section: in a disc and in no hole (the test's
        //  own, not prismProfile::inside2D)
        bool inside2D(const vector2D& p) const
        {
            bool in = false;
            forAll(discs, j)
            {
                in = in || magSqr(p - discs[j]) < sqr(discRadii[j]);
            }
            forAll(holes, j)
            {
                in = in && !(magSqr(p - holes[j]) < sqr(holeRadii[j]));
            }
            return in;
        }

        bool inside(const point& p) const
        {
            return mag(p.z()) <= h && inside2D(vector2D(p.x(), p.y()));
        }

        //- The profile: the shape's, or built from the lists where the
        //  case has no shape
        autoPtr<prismProfile> profile() const
        {
            if (entries.empty())
            {
                return autoPtr<prismProfile>::New
                (
                    discs, discRadii, holes, holeRadii, h
                );
            }
            return shapeOf(entries)->prism();
        }
    };

    //- Points on circles of radius r about the origin at the angles
    //  2 pi k/n (lobes, holes)
    List<vector2D> onCircle(const label n, const scalar r)
    {
        List<vector2D> c(n);
        forAll(c, k)
        {
            const scalar t = twoPi*k/n;
            c[k] = r*vector2D(Foam::cos(t), Foam::sin(t));
        }
        return c;
    }

    //- Lobes: default radius of the circle of lobe axes, r/(2 sin(pi/n))
    //  (lobedPellet.H), and the half-angle beta of a lobe's arc seen from
    //  its axis (the valley point of lobes 0 and 1 on the ray at pi/n at
    //  the distance t from the pellet axis)
    scalar lobeCentreRadius(const label n, const scalar r)
    {
        return r/(2*Foam::sin(pi/n));
    }

    scalar lobeValleyRadius(const label n, const scalar r, const scalar rc)
    {
        return
            rc*Foam::cos(pi/n) + Foam::sqrt(sqr(r) - sqr(rc*Foam::sin(pi/n)));
    }

    scalar lobeBeta(const label n, const scalar r, const scalar rc)
    {
        const scalar t = lobeValleyRadius(n, r, rc);
        return
            Foam::atan2(t*Foam::sin(pi/n), t*Foam::cos(pi/n) - rc);
    }

    //- The cases: the five pellet shapes and a profile of no shape (two
    //  discs of different radii, a hole across the outline, a hole inside)
    std::vector<prismCase> cases()
    {
        std::vector<prismCase> cs;

        cs.push_back
        ({
            "cylinder",
            "shape cylinder; diameter 0.01; height 0.01; faces 400;",
            List<vector2D>({vector2D::zero}), List<scalar>({0.005}),
            List<vector2D>(), List<scalar>(), 0.005, 0.01
        });
        cs.push_back
        ({
            "ring",
            "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
            " faces 400;",
            List<vector2D>({vector2D::zero}), List<scalar>({0.005}),
            List<vector2D>({vector2D::zero}), List<scalar>({0.003}),
            0.005, 0.01
        });
        for (const label n : {3, 4})
        {
            const scalar r = 0.002;
            const scalar rc = lobeCentreRadius(n, r);
            cs.push_back
            ({
                n == 3 ? "trilobe" : "quadrilobe",
                std::string("shape ") + (n == 3 ? "trilobe" : "quadrilobe")
              + "; lobeDiameter 0.004; height 0.008; faces 1000;",
                onCircle(n, rc), List<scalar>(n, r),
                List<vector2D>(), List<scalar>(), 0.004, 2*(r + rc)
            });
        }
        {
            // Default pitch circle (cylinderWithHoles.H):
            // dc = (D + dh)/(1 + 2 sin(pi/n))
            const scalar D = 0.01, dh = 0.002;
            const label n = 4;
            const scalar rh = 0.5*(D + dh)/(1 + 2*Foam::sin(pi/n));
            cs.push_back
            ({
                "cylinderWithHoles",
                "shape cylinderWithHoles; diameter 0.01; height 0.01;"
                " holes 4; holeDiameter 0.002; faces 2000;",
                List<vector2D>({vector2D::zero}), List<scalar>({0.5*D}),
                onCircle(n, rh), List<scalar>(n, 0.5*dh), 0.005, D
            });
        }
        cs.push_back
        ({
            "twoDiscsAndHoles",
            "",
            List<vector2D>({vector2D(0, 0), vector2D(0.006, 0.001)}),
            List<scalar>({0.005, 0.003}),
            List<vector2D>({vector2D(0.004, -0.0035), vector2D(-0.002, 0.001)}),
            List<scalar>({0.002, 0.0015}),
            0.003, 0.014
        });
        return cs;
    }


    //- A dense sampling of the surface of a prism, independent of
    //  prismProfile: every circle sampled at spacing s and a sample kept
    //  where it is boundary (a disc's point in no other disc and in no
    //  hole, a hole's point in a disc and in no other hole); the lateral
    //  walls are these points at the heights -h + m dz (rims included),
    //  the end faces the grid points (s i, s j) inside the cross-section.
    //  Every sample is a point of the true surface, so the distance to the
    //  nearest one is at least the true distance, and at most that plus
    //  the spacing error: about 1.75 s (a face point next to the outline:
    //  s/sqrt(2) to the grid, then s along the outline)
    class sampledSurface
    {
        const prismCase& c_;
        scalar s_;
        scalar dz_;
        std::vector<vector2D> outline_;

    public:

        sampledSurface(const prismCase& c, const scalar s)
        :
            c_(c),
            s_(s),
            dz_(0),
            outline_()
        {
            const label nD = c.discs.size();
            const label nC = nD + c.holes.size();
            auto centre = [&](const label j)
            {
                return j < nD ? c.discs[j] : c.holes[j - nD];
            };
            auto radius = [&](const label j)
            {
                return j < nD ? c.discRadii[j] : c.holeRadii[j - nD];
            };
            for (label i = 0; i < nC; ++i)
            {
                const label n = label(std::ceil(twoPi*radius(i)/s));
                for (label k = 0; k < n; ++k)
                {
                    const scalar t = twoPi*k/n;
                    const vector2D p
                    (
                        centre(i)
                      + radius(i)*vector2D(Foam::cos(t), Foam::sin(t))
                    );
                    bool inDisc = false, inHole = false;
                    for (label j = 0; j < nC; ++j)
                    {
                        if
                        (
                            j != i
                         && mag(p - centre(j)) < radius(j)*(1 - 1e-12)
                        )
                        {
                            (j < nD ? inDisc : inHole) = true;
                        }
                    }
                    if ((i < nD ? !inDisc : inDisc) && !inHole)
                    {
                        outline_.push_back(p);
                    }
                }
            }
            dz_ = 2*c.h/std::ceil(2*c.h/s);
        }

        //- Distance of p to the nearest sample
        scalar distance(const point& p) const
        {
            const vector2D p2(p.x(), p.y());

            // Walls: the nearest height of the grid, clamped to [-h, h]
            const scalar zc = min(c_.h, max(-c_.h, p.z()));
            const scalar zg =
                -c_.h + dz_*std::round((zc + c_.h)/dz_);
            scalar best = GREAT;
            for (const vector2D& q : outline_)
            {
                best = min(best, magSqr(p2 - q));
            }
            best += sqr(p.z() - zg);

            // Faces: the nearest grid point, where it is inside
            const vector2D g
            (
                s_*std::round(p2.x()/s_), s_*std::round(p2.y()/s_)
            );
            if (c_.inside2D(g))
            {
                best =
                    min(best, magSqr(p2 - g) + sqr(mag(p.z()) - c_.h));
            }
            return Foam::sqrt(best);
        }

        //- Largest distance of a surface point from the nearest sample
        scalar error() const
        {
            return 1.75*s_;
        }

        const std::vector<vector2D>& outline() const
        {
            return outline_;
        }
    };
}


TEST(prismProfile, areasOfTheShapesAreTheirClosedForms)
{
    const std::vector<prismCase> cs(cases());
    auto areaOf = [&](const std::string& name)
    {
        for (const prismCase& c : cs)
        {
            if (c.name == name)
            {
                return c.profile()->area();
            }
        }
        return scalar(-1);
    };

    EXPECT_NEAR(areaOf("cylinder")/(pi*sqr(0.005)), 1, 1e-12);
    EXPECT_NEAR
    (
        areaOf("ring")/(pi*(sqr(0.005) - sqr(0.003))), 1, 1e-12
    );
    for (const label n : {3, 4})
    {
        const scalar r = 0.002;
        const scalar rc = lobeCentreRadius(n, r);
        const scalar beta = lobeBeta(n, r, rc);
        const scalar A = n*(rc*r*Foam::sin(beta) + sqr(r)*beta);
        EXPECT_NEAR(areaOf(n == 3 ? "trilobe" : "quadrilobe")/A, 1, 1e-12)
            << n << " lobes";
    }
    EXPECT_NEAR
    (
        areaOf("cylinderWithHoles")/(pi*(sqr(0.005) - 4*sqr(0.001))), 1,
        1e-12
    );

    // A lobed profile of a pitch other than the default, and one off-centre
    // hole: the same closed forms
    {
        const scalar r = 0.002, rc = 0.0015;
        const prismProfile p
        (
            onCircle(3, rc), List<scalar>(3, r), List<vector2D>(),
            List<scalar>(), 0.004
        );
        const scalar beta = lobeBeta(3, r, rc);
        EXPECT_NEAR
        (
            p.area()/(3*(rc*r*Foam::sin(beta) + sqr(r)*beta)), 1, 1e-12
        );
        const prismProfile q
        (
            List<vector2D>({vector2D::zero}), List<scalar>({0.005}),
            List<vector2D>({vector2D(0.001, -0.002)}), List<scalar>({0.0015}),
            0.004
        );
        EXPECT_NEAR(q.area()/(pi*(sqr(0.005) - sqr(0.0015))), 1, 1e-12);
    }

    // No closed form: the midpoints of a grid inside the cross-section
    // (the test's own inside test); grid error about 1e-5 relative
    const prismCase& g = cs.back();
    const label m = 2000;
    const scalar x0 = -0.005, x1 = 0.009, y0 = -0.0055, y1 = 0.005;
    const scalar dx = (x1 - x0)/m, dy = (y1 - y0)/m;
    label in = 0;
    for (label i = 0; i < m; ++i)
    {
        for (label j = 0; j < m; ++j)
        {
            in += g.inside2D(vector2D(x0 + (i + 0.5)*dx, y0 + (j + 0.5)*dy));
        }
    }
    const scalar byGrid = in*dx*dy;
    EXPECT_NEAR(g.profile()->area()/byGrid, 1, 1e-4) << g.name;
}


TEST(prismProfile, signedDistanceIsTheDistanceToTheSampledSurface)
{
    // Several thousand random points within two bounding radii (half of
    // them near the solid): the signed distance
    // - is at most the distance to the nearest sample (every sample is a
    //   surface point; to 1e-9 relative) and at least that less the
    //   sampling error (spacing 0.001 d);
    // - is negative exactly inside (the test's own inside test);
    // - has a unit gradient g, and p - sd g lies on the surface (its own
    //   signed distance vanishes) at the distance |sd| from p.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> U(-1, 1);

    for (const prismCase& c : cases())
    {
        const autoPtr<prismProfile> prof(c.profile());
        const sampledSurface surface(c, 1e-3*c.d);
        const scalar rb = prof->boundingRadius();
        const scalar R = prof->outerRadius();
        const point o(prof->Q().T() & (-prof->t()));

        label nPoints = 0, nInside = 0;
        label nPart[3] = {0, 0, 0};
        scalar worstAbove = -GREAT, worstBelow = -GREAT, worstUnit = 0;
        for (label k = 0; k < 4000; ++k)
        {
            point p;
            if (k % 2 == 0)
            {
                do
                {
                    p = point(U(rng), U(rng), U(rng));
                } while (magSqr(p) > 1);
                p = o + 2*rb*p;
            }
            else
            {
                p = point
                (
                    (R + 0.1*c.d)*U(rng), (R + 0.1*c.d)*U(rng),
                    (c.h + 0.1*c.d)*U(rng)
                );
            }
            ++nPoints;

            vector g;
            label arcI = -1;
            prismProfile::part where;
            const scalar sd = prof->signedDistance(p, g, arcI, where);
            const scalar ref = surface.distance(p);
            const bool in = c.inside(p);
            nInside += in;

            worstAbove = max(worstAbove, (mag(sd) - ref)/c.d);
            worstBelow = max(worstBelow, (ref - mag(sd))/c.d);
            EXPECT_LE(mag(sd), ref*(1 + 1e-9) + 1e-15)
                << c.name << " p " << str(p);
            EXPECT_GE(mag(sd), ref - surface.error())
                << c.name << " p " << str(p);
            if (mag(sd) > 1e-12*c.d)
            {
                EXPECT_EQ(sd < 0, in)
                    << c.name << " p " << str(p) << " sd " << sd;
            }

            // (unit to rounding: g = (p - q)/|sd| with q the nearest point
            // loses digits where |sd| is small; 6e-12 seen)
            EXPECT_NEAR(mag(g), 1, 1e-10) << c.name << " p " << str(p);
            worstUnit = max(worstUnit, mag(mag(g) - 1));
            const point foot(p - sd*g);
            EXPECT_NEAR(sdOf(prof(), foot)/c.d, 0, 1e-9)
                << c.name << " p " << str(p) << " foot " << str(foot);

            // The part named is where the foot is: a rim or a wall on the
            // arc named (-1: at an end of an arc, a corner), a face at |z|
            // = h inside the cross-section
            ASSERT_TRUE(arcI >= -1 && arcI < prof->arcs().size());
            const vector2D f2(foot.x(), foot.y());
            const scalar eps = 1e-9*c.d;
            bool onArc = false;
            if (arcI >= 0)
            {
                const prismProfile::arc& a = prof->arcs()[arcI];
                onArc =
                    mag(mag(f2 - a.c) - a.r) < eps
                 && (
                        a.within(f2 - a.c)
                     || mag(f2 - a.c - a.r*a.u0) < eps
                     || mag(f2 - a.c - a.r*a.u1) < eps
                    );
            }
            else
            {
                // A corner: the foot is an end of some arc
                for (const prismProfile::arc& a : prof->arcs())
                {
                    onArc =
                        onArc
                     || mag(f2 - a.c - a.r*a.u0) < eps
                     || mag(f2 - a.c - a.r*a.u1) < eps;
                }
            }
            const bool onEnd = mag(mag(foot.z()) - c.h) < eps;
            ++nPart[label(where)];
            if (where == prismProfile::part::rim)
            {
                EXPECT_TRUE(onArc && onEnd) << c.name << " p " << str(p);
            }
            else if (where == prismProfile::part::wall)
            {
                EXPECT_TRUE(onArc && mag(foot.z()) < c.h + eps)
                    << c.name << " p " << str(p);
            }
            else
            {
                vector2D gf;
                EXPECT_TRUE
                (
                    onEnd
                 && (
                        c.inside2D(f2)
                     || mag(distance2DOf(prof(), f2, gf)) < eps
                    )
                ) << c.name << " p " << str(p);
            }

            // The 2-D query agrees with the section's own inside test
            vector2D g2;
            const vector2D p2(p.x(), p.y());
            const scalar d2 = distance2DOf(prof(), p2, g2);
            EXPECT_EQ(prof->inside2D(p2), c.inside2D(p2)) << c.name << str(p2);
            if (mag(d2) > 1e-12*c.d)
            {
                EXPECT_EQ(d2 < 0, c.inside2D(p2)) << c.name << str(p2);
            }
        }
        EXPECT_GT(nInside, nPoints/20) << c.name;
        for (const label n : nPart)
        {
            EXPECT_GT(n, nPoints/50) << c.name;
        }
        std::cout
            << "[ measured ] " << c.name << ": " << nPoints << " points, "
            << nInside << " inside; (|sd| - sampled)/d in ["
            << -worstBelow << ", " << worstAbove << "] (sampling error "
            << surface.error()/c.d << "); | |g| - 1 | <= " << worstUnit
            << std::endl;
    }
}


TEST(prismProfile, gradientIsUnitCloseToTheSurface)
{
    // Points at 1e-6 r down to 1.1e-12 r off a cylinder's wall and a
    // trilobe's lobe, inside and outside: the gradient (the contact normal
    // of prismContacts) is the unit radial direction to rounding. Found:
    // distance2D takes g = (p - q)/|p - q| with q = c + (r/rho)(p - c), and
    // p - q loses its digits to cancellation as the distance falls: at
    // 1e-10 r |g| is 1 to 1.7e-6 and its direction off by 8e-7, at 1.1e-12
    // r (just above the 1e-12 r where the arc's normal is taken instead)
    // by up to 3e-4 and 1.7e-4 (trilobe); (p - c)/rho, signed, would be
    // exact
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> U(0, 1);
    for (const prismCase& c : cases())
    {
        if (c.name != "cylinder" && c.name != "trilobe")
        {
            continue;
        }
        const autoPtr<prismProfile> prof(c.profile());
        scalar worstNorm = 0, worstDirection = 0, worstAt = 0;
        for (const scalar rel : {1e-6, 1e-8, 1e-10, 1e-11, 1.1e-12})
        {
            for (label k = 0; k < 200; ++k)
            {
                // A point of an arc away from its ends, moved off it along
                // its radius
                const prismProfile::arc& a =
                    prof->arcs()[label(U(rng)*prof->arcs().size())];
                const scalar t = a.t0 + a.span*(0.1 + 0.8*U(rng));
                const vector2D e(Foam::cos(t), Foam::sin(t));
                for (const scalar side : {1.0, -1.0})
                {
                    const vector2D q(a.c + a.r*(1 + side*rel)*e);
                    const point p(q.x(), q.y(), 0.3*c.h);
                    vector g;
                    prof->signedDistance(p, g);
                    const vector radial(a.sense*e.x(), a.sense*e.y(), 0);
                    const scalar norm = mag(mag(g) - 1);
                    const scalar direction = mag(g/mag(g) - radial);
                    if (norm > worstNorm)
                    {
                        worstNorm = norm;
                        worstAt = rel;
                    }
                    worstDirection = max(worstDirection, direction);
                }
            }
        }
        EXPECT_LT(worstNorm, 1e-12)
            << c.name << ": | |g| - 1 | " << worstNorm << " at " << worstAt
            << " r off the wall";
        EXPECT_LT(worstDirection, 1e-12) << c.name;
        std::cout
            << "[ measured ] " << c.name << ": within 1e-6 r of the wall"
            << " | |g| - 1 | <= " << worstNorm << " (at " << worstAt
            << " r), direction error <= " << worstDirection << std::endl;
    }
}


TEST(prismProfile, pointsOfTheSampledSurfaceAreAtZeroDistance)
{
    // The other way round: the samples of the outline at every height
    // have signed distance 0 (to 1e-12 d), and, away from the corners of
    // the outline (where two arcs meet), points moved off them along the
    // gradient by 0.01 d have 0.01 d
    for (const prismCase& c : cases())
    {
        const autoPtr<prismProfile> prof(c.profile());
        const sampledSurface surface(c, 1e-2*c.d);
        for (const vector2D& q : surface.outline())
        {
            scalar toCorner = GREAT;
            for (const prismProfile::arc& a : prof->arcs())
            {
                if (!a.fullCircle())
                {
                    toCorner = min(toCorner, mag(q - a.c - a.r*a.u0));
                    toCorner = min(toCorner, mag(q - a.c - a.r*a.u1));
                }
            }
            for (const scalar z : {-c.h, -0.3*c.h, 0.0, 0.7*c.h, c.h})
            {
                const point p(q.x(), q.y(), z);
                vector g;
                const scalar sd = prof->signedDistance(p, g);
                ASSERT_NEAR(sd/c.d, 0, 1e-12) << c.name << " p " << str(p);
                if (toCorner > 0.05*c.d)
                {
                    EXPECT_NEAR
                    (
                        sdOf(prof(), p + 0.01*c.d*g)/c.d, 0.01, 1e-12
                    ) << c.name << " p " << str(p) << " g " << str(g);
                }
            }
        }
    }
}


TEST(prismProfile, exposedArcsOfTheShapes)
{
    const std::vector<prismCase> cs(cases());
    auto profileOf = [&](const std::string& name)
    {
        for (const prismCase& c : cs)
        {
            if (c.name == name)
            {
                return c.profile();
            }
        }
        return autoPtr<prismProfile>();
    };

    // Cylinder: one full circle, convex
    {
        const autoPtr<prismProfile> p(profileOf("cylinder"));
        ASSERT_EQ(p->arcs().size(), 1);
        const prismProfile::arc& a = p->arcs()[0];
        EXPECT_TRUE(a.fullCircle());
        EXPECT_EQ(a.sense, 1);
        EXPECT_NEAR(a.r, 0.005, 1e-15);
        EXPECT_NEAR(mag(a.c), 0, 1e-15);
        EXPECT_NEAR(p->outerRadius(), 0.005, 1e-15);
        EXPECT_NEAR(p->boundingRadius(), Foam::sqrt(2.0)*0.005, 1e-15);
    }

    // Ring: two full circles, the bore's concave
    {
        const autoPtr<prismProfile> p(profileOf("ring"));
        ASSERT_EQ(p->arcs().size(), 2);
        label outer = 0, bore = 0;
        for (const prismProfile::arc& a : p->arcs())
        {
            EXPECT_TRUE(a.fullCircle());
            EXPECT_NEAR(mag(a.c), 0, 1e-15);
            if (a.sense > 0)
            {
                ++outer;
                EXPECT_NEAR(a.r, 0.005, 1e-15);
            }
            else
            {
                ++bore;
                EXPECT_EQ(a.sense, -1);
                EXPECT_NEAR(a.r, 0.003, 1e-15);
            }
        }
        EXPECT_EQ(outer, 1);
        EXPECT_EQ(bore, 1);
    }

    // Lobes: n convex arcs of span 2 beta whose ends meet at the valley
    // points, at the distance t from the axis at the angles
    // 2 pi (k + 1/2)/n
    for (const label n : {3, 4})
    {
        const autoPtr<prismProfile> p
        (
            profileOf(n == 3 ? "trilobe" : "quadrilobe")
        );
        const scalar r = 0.002;
        const scalar rc = lobeCentreRadius(n, r);
        const scalar t = lobeValleyRadius(n, r, rc);
        const scalar beta = lobeBeta(n, r, rc);
        ASSERT_EQ(p->arcs().size(), n);
        std::vector<bool> valleyHit(n, false);
        for (const prismProfile::arc& a : p->arcs())
        {
            EXPECT_EQ(a.sense, 1);
            EXPECT_FALSE(a.fullCircle());
            EXPECT_NEAR(a.r, r, 1e-15);
            EXPECT_NEAR(mag(a.c), rc, 1e-15);
            EXPECT_NEAR(a.span, 2*beta, 1e-12) << n << " lobes";
            EXPECT_NEAR(mag(a.at(a.t0) - (a.c + a.r*a.u0)), 0, 1e-15);

            // Each end is a valley point, and the end of one arc the
            // start of another
            for (const vector2D& e : {a.c + a.r*a.u0, a.c + a.r*a.u1})
            {
                EXPECT_NEAR(mag(e), t, 1e-12) << n << " lobes";
                scalar angle = Foam::atan2(e.y(), e.x());
                if (angle < 0)
                {
                    angle += twoPi;
                }
                const scalar k = angle*n/twoPi - 0.5;
                EXPECT_NEAR(k, std::round(k), 1e-9) << n << " lobes";
                valleyHit[label(std::round(k)) % n] = true;
            }
            const vector2D end(a.c + a.r*a.u1);
            label starts = 0;
            for (const prismProfile::arc& b : p->arcs())
            {
                starts += mag(b.c + b.r*b.u0 - end) < 1e-12;
            }
            EXPECT_EQ(starts, 1) << n << " lobes";
        }
        for (const bool hit : valleyHit)
        {
            EXPECT_TRUE(hit) << n << " lobes";
        }
        EXPECT_NEAR(p->outerRadius(), rc + r, 1e-15);
    }

    // Cylinder with holes: the outer circle and four concave ones
    {
        const autoPtr<prismProfile> p(profileOf("cylinderWithHoles"));
        ASSERT_EQ(p->arcs().size(), 5);
        label concave = 0;
        for (const prismProfile::arc& a : p->arcs())
        {
            EXPECT_TRUE(a.fullCircle());
            concave += a.sense < 0;
        }
        EXPECT_EQ(concave, 4);
    }

    // No shape: two discs and a hole across the outline. Every end of an
    // arc lies on two circles and is the end of exactly one other arc (the
    // outline closes), and the midpoint of every arc is boundary: inside
    // the section just behind it, outside just ahead (sense)
    {
        const prismCase& c = cs.back();
        const autoPtr<prismProfile> p(c.profile());
        label nPartial = 0;
        for (const prismProfile::arc& a : p->arcs())
        {
            const scalar tm = a.t0 + 0.5*a.span;
            const vector2D m(a.at(tm));
            const vector2D out(a.sense*(m - a.c)/a.r);
            EXPECT_TRUE(c.inside2D(m - 1e-6*c.d*out)) << str(m);
            EXPECT_FALSE(c.inside2D(m + 1e-6*c.d*out)) << str(m);
            if (a.fullCircle())
            {
                continue;
            }
            ++nPartial;
            for (const vector2D& e : {a.c + a.r*a.u0, a.c + a.r*a.u1})
            {
                label others = 0;
                for (const prismProfile::arc& b : p->arcs())
                {
                    if (&b == &a)
                    {
                        continue;
                    }
                    others +=
                        mag(b.c + b.r*b.u0 - e) < 1e-12
                     || mag(b.c + b.r*b.u1 - e) < 1e-12;
                }
                EXPECT_EQ(others, 1) << "end " << str(e);
            }
        }
        // Big disc, small disc, the hole across both outlines (two
        // pieces: the bore's part inside the discs); the inner hole whole
        EXPECT_GE(nPartial, 3);
        label concave = 0;
        for (const prismProfile::arc& a : p->arcs())
        {
            concave += a.sense < 0;
        }
        EXPECT_GE(concave, 2);
    }
}


TEST(prismProfile, concaveArcsAreTheBoresAndHoles)
{
    // A ring's bore and the holes are concave arcs; the lobes meet at
    // corners (cusps), not on concave arcs. contactModel auto packs every
    // profile but those with holes off the axis as exact solids
    // (contactDispatch)
    for (const prismCase& c : cases())
    {
        const autoPtr<prismProfile> p(c.profile());
        bool concave = false;
        for (const prismProfile::arc& a : p->arcs())
        {
            concave = concave || a.sense < 0;
        }
        EXPECT_EQ(p->hasConcaveArc(), concave) << c.name;
        const bool bored =
            c.name == "ring" || c.name == "cylinderWithHoles"
         || c.name == "twoDiscsAndHoles";
        EXPECT_EQ(p->hasConcaveArc(), bored) << c.name;

        // contactModel auto keeps the meshes for holes off the axis only;
        // the ring's bore is on it
        const bool offAxis =
            c.name == "cylinderWithHoles" || c.name == "twoDiscsAndHoles";
        EXPECT_EQ(p->hasOffAxisHole(), offAxis) << c.name;
    }
}


TEST(prismProfile, shapesPlaceTheirProfileWhereTheirMeshIs)
{
    // The mesh's vertices lie on the true surface (an inscribed mesh):
    // mapped into the profile frame (p = Q^T (x - t)) their signed distance
    // vanishes. The meshed shapes (lobes, holes) move their mesh to the
    // principal axes, and their profile with it
    for (const prismCase& c : cases())
    {
        if (c.entries.empty())
        {
            continue;
        }
        const autoPtr<pelletShape> shape(shapeOf(c.entries));
        const autoPtr<prismProfile> prof(shape->prism());
        ASSERT_TRUE(prof.valid()) << c.name;
        const tensor& Q = prof->Q();
        EXPECT_NEAR(mag((Q & Q.T()) - tensor::I), 0, 1e-12) << c.name;
        EXPECT_NEAR(det(Q), 1, 1e-12) << c.name;
        scalar worst = 0;
        for (const point& x : shape->mesh().points())
        {
            const point p(Q.T() & (x - prof->t()));
            worst = max(worst, mag(sdOf(prof(), p)));
        }
        EXPECT_LT(worst, 1e-9*c.d) << c.name;
        // (the mesh is inscribed: its bounding radius is at most the
        // solid's, by at most its sagitta)
        EXPECT_LE(shape->boundingRadius(), prof->boundingRadius()*(1 + 1e-12))
            << c.name;
        EXPECT_GT(shape->boundingRadius(), 0.99*prof->boundingRadius())
            << c.name;
    }
    EXPECT_FALSE(shapeOf("shape sphere; diameter 0.01;")->prism().valid());
}


// ************************************************************************* //

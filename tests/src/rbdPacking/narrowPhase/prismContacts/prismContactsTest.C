// Exact contacts of prism pellets: src/rbdPacking/narrowPhase/prismContacts.
// Against brute force (the least signed distance of either pellet over the
// other's true surface, prismProfile) on 10 000 random poses near contact
// of each pair; against closed forms (a cylinder on another's top face,
// crossed and parallel lying cylinders, a cylinder on its rim on a face,
// two rims crossing, a ring across another's bore, pellets stacked with
// their outlines on each other) and brute force (hooked washers, a tilted
// ring dipping into a bore); with the container (round rims, and the rims
// of a trilobe); and against the triangle narrow phase (meshContacts) on
// the same configurations, to the mesh's resolution.

#include <gtest/gtest.h>
#include "../../testTools/worldFixture.H"
#include "prismContacts.H"
#include "contactReduction.H"
#include "meshContacts.H"
#include "pelletShape.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <chrono>
#include <random>
#include <sstream>

using namespace Foam;
using namespace Foam::rbd;
using constant::mathematical::pi;
using constant::mathematical::twoPi;

namespace
{
    using rbdTest::str;

    std::string str(const quaternion& q)
    {
        std::ostringstream os;
        os.precision(17);
        os << "quaternion(" << q.w() << ", vector(" << q.v().x() << ", "
            << q.v().y() << ", " << q.v().z() << "))";
        return os.str();
    }

    std::string strFull(const vector& v)
    {
        std::ostringstream os;
        os.precision(17);
        os << "point(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
        return os.str();
    }

    //- Body of the tests (not isotropic, so that R follows q)
    rigidBody bodyAt(const point& x, const quaternion& q)
    {
        return rigidBody(1e-3, vector(1, 2, 3)*1e-8, x, q, true);
    }

    //- Rotation by angle [rad] about a unit axis
    quaternion turn(const vector& axis, const scalar angle)
    {
        return quaternion(axis/mag(axis), angle);
    }

    //- Uniformly random orientation
    quaternion randomQ(std::mt19937& rng)
    {
        std::normal_distribution<double> N(0, 1);
        const scalar w = N(rng);
        const vector v(N(rng), N(rng), N(rng));
        const scalar m = Foam::sqrt(sqr(w) + magSqr(v));
        return quaternion(w/m, v/m);
    }

    //- Uniformly random unit vector
    vector randomDirection(std::mt19937& rng)
    {
        std::normal_distribution<double> N(0, 1);
        const vector v(N(rng), N(rng), N(rng));
        return v/mag(v);
    }

    //- A pellet shape with its exact solid and narrow phase, the band as
    //  the world's (0.1 of the bounding radius), d its diameter
    struct pellet
    {
        autoPtr<pelletShape> shape;
        autoPtr<prismProfile> profile;
        scalar band;
        scalar d;
        autoPtr<prismContacts> contacts;

        explicit pellet(const std::string& entries)
        :
            shape(),
            profile(),
            band(0),
            d(0),
            contacts()
        {
            shape = rbdTest::shapeOf(entries);
            profile = shape->prism();
            band = 0.1*shape->boundingRadius();
            d = shape->diameter();
            contacts.reset(new prismContacts(profile(), band));
        }

        //- Contacts of body i (1) with body k (0)
        DynamicList<contact> pair(const rigidBody& bi, const rigidBody& bk)
            const
        {
            DynamicList<contact> cs;
            contacts->prismPrism(1, bi, 0, bk, cs);
            return cs;
        }
    };

    const char* const cylinderEntries =
        "shape cylinder; diameter 0.01; height 0.01; faces 400;";
    const char* const ringEntries =
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
        " faces 400;";
    const char* const trilobeEntries =
        "shape trilobe; lobeDiameter 0.004; height 0.008; faces 1000;";
    const char* const holesEntries =
        "shape cylinderWithHoles; diameter 0.01; height 0.01; holes 4;"
        " holeDiameter 0.002; faces 2000;";
    const char* const washerEntries =
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.002;"
        " faces 400;";

    scalar minGap(const UList<contact>& cs)
    {
        scalar g = GREAT;
        for (const contact& c : cs)
        {
            g = min(g, c.gap);
        }
        return g;
    }

    const contact& deepest(const UList<contact>& cs)
    {
        label best = 0;
        forAll(cs, j)
        {
            if (cs[j].gap < cs[best].gap)
            {
                best = j;
            }
        }
        return cs[best];
    }


    // * * * * * * * * * * * * * * Brute force  * * * * * * * * * * * * * //

    //- The signed distance of pellet b at points of the profile frame of
    //  pellet a (both of profile p): x_b = M x_a + t
    struct otherDistance
    {
        const prismProfile& p;
        tensor M;
        vector t;

        otherDistance
        (
            const prismProfile& prof,
            const rigidBody& a,
            const rigidBody& b
        )
        :
            p(prof),
            M(Zero),
            t(Zero)
        {
            const tensor Ra(a.R() & p.Q());
            const vector ta((a.R() & p.t()) + a.x());
            const tensor Rb(b.R() & p.Q());
            const vector tb((b.R() & p.t()) + b.x());
            M = Rb.T() & Ra;
            t = Rb.T() & (ta - tb);
        }

        scalar operator()(const point& x) const
        {
            vector g;
            return p.signedDistance((M & x) + t, g);
        }
    };

    //- Signed distance of the pellet at body b at a world point
    scalar worldDistance
    (
        const prismProfile& p,
        const rigidBody& b,
        const point& y
    )
    {
        vector g;
        return p.signedDistance
        (
            p.Q().T() & ((b.R().T() & (y - b.x())) - p.t()), g
        );
    }

    //- A piece of a prism's surface: of a rim (angles a0..a1 of an arc,
    //  height b0 = b1), of a lateral wall (angles a0..a1, heights b0..b1)
    //  or of an end face (the square x a0..a1, y b0..b1 at height z), with
    //  the value f at its centre and its radius (the largest distance of
    //  its points from the centre: on an arc the arc length bounds the
    //  chord)
    struct cell
    {
        enum kindType { rim, wall, face };

        kindType kind;
        label arc;
        scalar a0, a1, b0, b1, z;
        scalar f;
        scalar radius;
    };

    //- Least value over the surface of a prism (profile frame) of a
    //  1-Lipschitz function f (the other pellet's exact signed distance):
    //  no point of a cell lies below f(centre) - radius. The surface is cut
    //  into cells (rims and lateral walls over the exposed arcs, squares of
    //  the end faces, a square counted where its centre is inside the
    //  cross-section), and every cell that may reach below the least value
    //  found (or cap) less tol is cut in three along its longer side (the
    //  middle third keeps its centre and value) until its radius is below
    //  tol (tolFace on the faces). The least value found is a value of f at
    //  a surface point; the true least value is at most tol below it (a
    //  few tolFace where a face is deepest next to the outline, which the
    //  rims sample too): the minimum over a sampling of the whole surface
    //  as dense as tol, without evaluating every sample. decide: stop at
    //  the first value below cap (whether the least is below cap, or at
    //  least cap - tol).
    template<class F>
    scalar surfaceMinimum
    (
        const prismProfile& prof,
        const F& f,
        const scalar cap,
        const scalar tolCurve,
        const scalar tolFace,
        const bool decide
    )
    {
        const List<prismProfile::arc>& arcs = prof.arcs();
        const scalar h = prof.halfHeight();
        scalar best = GREAT;
        std::vector<cell> stack;

        auto tol = [&](const cell& c)
        {
            return c.kind == cell::face ? tolFace : tolCurve;
        };

        // Evaluate the centre (unless known) and keep the cell where it may
        // reach below the least value; true: decided
        auto push = [&](cell c, const bool known)
        {
            bool sample = true;
            if (c.kind == cell::face)
            {
                c.radius =
                    0.5*Foam::sqrt(sqr(c.a1 - c.a0) + sqr(c.b1 - c.b0));
                const vector2D m(0.5*(c.a0 + c.a1), 0.5*(c.b0 + c.b1));
                vector2D g2;
                label arcI;
                const scalar d2 = prof.distance2D(m, g2, arcI);
                if (d2 >= c.radius)
                {
                    // No point of the square inside the cross-section
                    return false;
                }
                sample = d2 <= 0;
                if (!known)
                {
                    c.f = f(point(m.x(), m.y(), c.z));
                }
            }
            else
            {
                const prismProfile::arc& a = arcs[c.arc];
                c.radius =
                    0.5
                   *Foam::sqrt(sqr(a.r*(c.a1 - c.a0)) + sqr(c.b1 - c.b0));
                if (!known)
                {
                    const vector2D q(a.at(0.5*(c.a0 + c.a1)));
                    c.f = f(point(q.x(), q.y(), 0.5*(c.b0 + c.b1)));
                }
            }
            if (sample)
            {
                best = min(best, c.f);
            }
            if
            (
                c.radius > tol(c)
             && c.f - c.radius < min(best, cap) - tol(c)
            )
            {
                stack.push_back(c);
            }
            return decide && best < cap;
        };

        forAll(arcs, ai)
        {
            const prismProfile::arc& a = arcs[ai];
            const label n = label(std::ceil(a.span/(pi/2)));
            const scalar dt = a.span/n;
            const label nz = max(label(1), label(std::ceil(2*h/(a.r*dt))));
            for (label j = 0; j < n; ++j)
            {
                const scalar t0 = a.t0 + j*dt;
                const scalar t1 = t0 + dt;
                for (const scalar z : {-h, h})
                {
                    if (push({cell::rim, ai, t0, t1, z, z, 0, 0, 0}, false))
                    {
                        return best;
                    }
                }
                for (label m = 0; m < nz; ++m)
                {
                    const scalar z0 = -h + (2*h*m)/nz;
                    const scalar z1 = -h + (2*h*(m + 1))/nz;
                    if (push({cell::wall, ai, t0, t1, z0, z1, 0, 0, 0}, false))
                    {
                        return best;
                    }
                }
            }
        }
        const scalar R = prof.outerRadius();
        for (const scalar z : {-h, h})
        {
            if (push({cell::face, -1, -R, R, -R, R, z, 0, 0}, false))
            {
                return best;
            }
        }

        while (!stack.empty())
        {
            const cell c(stack.back());
            stack.pop_back();
            if (c.f - c.radius >= min(best, cap) - tol(c))
            {
                continue;
            }
            bool splitA = true;
            if (c.kind == cell::wall)
            {
                splitA = arcs[c.arc].r*(c.a1 - c.a0) >= c.b1 - c.b0;
            }
            else if (c.kind == cell::face)
            {
                splitA = c.a1 - c.a0 >= c.b1 - c.b0;
            }
            cell parts[3] = {c, c, c};
            if (splitA)
            {
                const scalar third = (c.a1 - c.a0)/3;
                parts[0].a1 = parts[1].a0 = c.a0 + third;
                parts[1].a1 = parts[2].a0 = c.a1 - third;
            }
            else
            {
                const scalar third = (c.b1 - c.b0)/3;
                parts[0].b1 = parts[1].b0 = c.b0 + third;
                parts[1].b1 = parts[2].b0 = c.b1 - third;
            }
            if
            (
                push(parts[1], true) || push(parts[0], false)
             || push(parts[2], false)
            )
            {
                return best;
            }
        }
        return best;
    }

    //- The least signed distance of either pellet over the other's
    //  surface (gap, or minus the deepest penetration), brute force:
    //  exact to tol (values above cap: only that they are)
    scalar bruteGap
    (
        const pellet& P,
        const rigidBody& bi,
        const rigidBody& bk,
        const scalar cap,
        const scalar tolCurve,
        const scalar tolFace,
        const bool decide = false
    )
    {
        const prismProfile& p = P.profile();
        const scalar m1 = surfaceMinimum
        (
            p, otherDistance(p, bi, bk), cap, tolCurve, tolFace, decide
        );
        if (decide && m1 < cap)
        {
            return m1;
        }
        const scalar m2 = surfaceMinimum
        (
            p, otherDistance(p, bk, bi), min(cap, m1), tolCurve, tolFace,
            decide
        );
        return min(m1, m2);
    }

    //- The brute-force gap at its most accurate: 2e-5 d on rims and
    //  walls, 1e-4 d on the faces
    scalar bruteGap(const pellet& P, const rigidBody& bi, const rigidBody& bk)
    {
        return bruteGap(P, bi, bk, P.band + 0.01*P.d, 2e-5*P.d, 1e-4*P.d);
    }

    //- Move body i from x0 along u to where the brute-force gap with k
    //  crosses target (bisection on s in [0, sMax], i at x0 + s u, the gap
    //  below target at s = 0 and above at sMax): the position on the side
    //  above, whose gap lies in [target - tol d, target + sMax/2^iterations)
    point placeAt
    (
        const pellet& P,
        const point& x0,
        const quaternion& qi,
        const vector& u,
        const scalar sMax,
        const rigidBody& bk,
        const scalar target,
        const label iterations = 14,
        const scalar tol = 1e-4
    )
    {
        scalar lo = 0, hi = sMax;
        for (label it = 0; it < iterations; ++it)
        {
            const scalar mid = 0.5*(lo + hi);
            const rigidBody bi(bodyAt(x0 + mid*u, qi));
            const bool below =
                bruteGap(P, bi, bk, target, tol*P.d, tol*P.d, true)
              < target;
            (below ? lo : hi) = mid;
        }
        return x0 + hi*u;
    }

    //- Every contact is the exact signed distance of one pellet at a
    //  material point of the other, on the other's surface, with a unit
    //  normal and gap = n . (x_i + r_i - x_k - r_k). (Unit to 1e-6 only:
    //  where the gap is a few 1e-11 m the normal is unit to no better than
    //  1e-8, prismProfileTest gradientIsUnitCloseToTheSurface)
    void checkConsistent
    (
        const pellet& P,
        const rigidBody& bi,
        const rigidBody& bk,
        const UList<contact>& cs,
        label& bad,
        const std::string& where = ""
    )
    {
        const prismProfile& p = P.profile();
        const scalar tol = 1e-9*P.d;
        for (const contact& c : cs)
        {
            const point yi(bi.x() + c.ri);
            const point yk(bk.x() + c.rk);
            const bool onI =
                mag(worldDistance(p, bi, yi)) < tol
             && mag(worldDistance(p, bk, yi) - c.gap) < tol;
            const bool onK =
                mag(worldDistance(p, bk, yk)) < tol
             && mag(worldDistance(p, bi, yk) - c.gap) < tol;
            const bool ok =
                (onI || onK)
             && mag(mag(c.n) - 1) < 1e-6
             && mag((c.n & (yi - yk)) - c.gap) < tol
             && c.i == 1 && c.k == 0 && !c.centreBased;
            if (!ok && bad++ < 5)
            {
                ADD_FAILURE()
                    << where << " contact gap " << c.gap << " n "
                    << str(c.n) << " |n| - 1 " << mag(c.n) - 1 << " ri "
                    << str(c.ri) << " rk " << str(c.rk) << " n . (y_i - y_k)"
                    << " - gap " << (c.n & (yi - yk)) - c.gap << " on i "
                    << onI << " on k " << onK;
            }
        }
    }


    // * * * * * * * * * * * * * Random poses  * * * * * * * * * * * * * * //

    //- 10 000 random poses near contact of a pair of the shape: random
    //  orientations, body i moved from k's centre along a random direction
    //  to where the brute-force gap crosses a random target (bisection,
    //  placeAt), so that the gap lies in [-0.002 d, band) (half of them in
    //  [-0.002 d, 0.0009 d]). Per pose:
    //  - every contact is consistent (checkConsistent): its gap is the
    //    exact signed distance of one pellet at a point of the other's
    //    surface, so that no contact lies below the true least gap, and
    //    the least contact gap is at least the true one;
    //  - no surface point lies more than 0.001 d below the least contact
    //    gap (the band where there is none): brute force (surfaceMinimum,
    //    deciding) finds no value 0.0008 d below it, to 0.0002 d, or,
    //    where it finds one, the brute-force least gap to 5e-5 d is within
    //    0.001 d;
    //  - every measureEvery-th pose, the brute-force least gap to 5e-5 d
    //    (rims and walls; 1e-4 d on the faces) is the least contact gap
    //    within 0.001 d: the disagreements printed
    void checkRandomPoses
    (
        const std::string& name,
        const std::string& entries,
        const label seed,
        const label nPoses = 10000,
        const label measureEvery = 40
    )
    {
        const auto start = std::chrono::steady_clock::now();
        const pellet P(entries);
        const scalar d = P.d;
        const scalar tol = 1e-3*d;
        const scalar rb = P.shape->boundingRadius();

        // Placement: the gap lies in [target - tolPlace, target + ds)
        const scalar sMax = 2*rb + P.band + 0.01*d;
        const label iterations = 12;
        const scalar ds = sMax/(1 << iterations);
        const scalar tolPlace = 1.5e-3;
        const scalar lo = -0.002*d + tolPlace*d;
        const scalar hi = P.band - ds - 1e-4*d;

        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> U(0, 1);

        label bad = 0, inconsistent = 0, refined = 0;
        label withContacts = 0, nContacts = 0, nMeasured = 0;
        scalar lowest = GREAT, highest = -GREAT;
        scalar worstAbove = 0, worstBelow = 0;
        for (label pose = 0; pose < nPoses; ++pose)
        {
            const quaternion qi(randomQ(rng)), qk(randomQ(rng));
            const vector u(randomDirection(rng));
            const scalar target =
                pose % 2
              ? lo + (hi - lo)*U(rng)
              : lo + (0.0009*d - lo)*U(rng);
            const rigidBody bk(bodyAt(Zero, qk));
            const point xi
            (
                placeAt
                (
                    P, Zero, qi, u, sMax, bk, target, iterations, tolPlace
                )
            );
            const rigidBody bi(bodyAt(xi, qi));

            const DynamicList<contact> cs(P.pair(bi, bk));
            const scalar reported = min(minGap(cs), P.band);
            withContacts += !cs.empty();
            nContacts += cs.size();
            lowest = min(lowest, reported);
            highest = max(highest, reported);
            std::ostringstream where;
            where.precision(17);
            where
                << name << ": body i at " << strFull(xi) << " "
                << str(qi) << ", k at the origin " << str(qk)
                << ": contacts " << cs.size() << ", least gap " << minGap(cs);
            checkConsistent(P, bi, bk, cs, inconsistent, where.str());

            const scalar cap = reported - 0.8*tol;
            const bool below =
                bruteGap(P, bi, bk, cap, 0.2*tol, 0.2*tol, true) < cap;
            refined += below;
            if (below || pose % measureEvery == 0)
            {
                const scalar brute =
                    bruteGap(P, bi, bk, P.band + 0.01*d, 5e-5*d, 1e-4*d);
                const scalar diff = reported - min(brute, P.band);
                ++nMeasured;
                worstAbove = max(worstAbove, diff);
                worstBelow = max(worstBelow, -diff);
                if
                (
                    (mag(diff) > tol || brute < -0.002*d || brute >= P.band)
                 && bad++ < 5
                )
                {
                    ADD_FAILURE()
                        << where.str() << "; brute force " << brute;
                }
            }
        }
        const scalar seconds =
            std::chrono::duration<double>
            (
                std::chrono::steady_clock::now() - start
            ).count();

        EXPECT_EQ(bad, 0);
        EXPECT_EQ(inconsistent, 0);
        std::cout
            << "[ measured ] " << name << " pairs: " << nPoses
            << " poses checked, least contact gap/d in [" << lowest/d
            << ", " << highest/d << "], " << withContacts << " with contacts, "
            << scalar(nContacts)/nPoses
            << " per pose; none more than 0.001 d above a surface"
            << " point (" << refined << " looked at closer); on "
            << nMeasured << " of them (least contact gap - brute force)/d in"
            << " [" << -worstBelow/d << ", " << worstAbove/d << "]; "
            << seconds << " s" << std::endl;
    }
}


// * * * * * * * * * * * * Accuracy on random poses  * * * * * * * * * * * //

TEST(prismContacts, randomCylinderPairsAgreeWithBruteForce)
{
    checkRandomPoses("cylinder", cylinderEntries, 1);
}


TEST(prismContacts, randomRingPairsAgreeWithBruteForce)
{
    checkRandomPoses("ring", ringEntries, 2);
}


TEST(prismContacts, randomTrilobePairsAgreeWithBruteForce)
{
    checkRandomPoses("trilobe", trilobeEntries, 3);
}


TEST(prismContacts, randomCylinderWithHolesPairsAgreeWithBruteForce)
{
    checkRandomPoses("cylinderWithHoles", holesEntries, 4);
}



// * * * * * * * * * * * * Closed-form configurations * * * * * * * * * * //

namespace
{
    //- Radius and half height of the cylinder and of the rings [m]
    const scalar r = 0.005;

    const vector ex(1, 0, 0);
    const vector ey(0, 1, 0);
    const vector ez(0, 0, 1);

    //- Body z along world x
    quaternion lyingAlongX()
    {
        return turn(ey, 0.5*pi);
    }

    //- Largest triangle spanned by the contact points [m^2]
    scalar largestTriangle(const UList<contact>& cs)
    {
        scalar area = 0;
        forAll(cs, a)
        {
            for (label b = a + 1; b < cs.size(); ++b)
            {
                for (label c = b + 1; c < cs.size(); ++c)
                {
                    area =
                        max
                        (
                            area,
                            0.5*mag((cs[b].p - cs[a].p) ^ (cs[c].p - cs[a].p))
                        );
                }
            }
        }
        return area;
    }

    //- Cylinder i tilted by alpha about x with its lowest rim point at low
    //  (half height = radius = r): the centre
    point tiltedCentre(const point& low, const scalar alpha)
    {
        return
            low
          - vector
            (
                0,
                r*Foam::sin(alpha) - r*Foam::cos(alpha),
                -(r*Foam::cos(alpha) + r*Foam::sin(alpha))
            );
    }

    //- Rims crossing: i's axis along the tangent tau of k's top rim at
    //  the angle psi (sign: which way i extends), the plane of its near
    //  rim through k's rim point P, its lowest rim point g above P
    rigidBody crossingRim(const scalar psi, const scalar sign, const scalar g)
    {
        const point P(r*Foam::cos(psi), r*Foam::sin(psi), r);
        const vector tau(-Foam::sin(psi), Foam::cos(psi), 0);
        return
            bodyAt
            (
                P + (g + r)*ez + sign*r*tau,
                turn(ez, psi)*turn(ex, -sign*0.5*pi)
            );
    }

    //- The brute-force gap and the least contact gap agree within 0.001 d
    void expectBruteForce
    (
        const pellet& P,
        const rigidBody& bi,
        const rigidBody& bk,
        const std::string& what
    )
    {
        const scalar brute = bruteGap(P, bi, bk);
        const DynamicList<contact> cs(P.pair(bi, bk));
        const scalar reported = min(minGap(cs), P.band);
        EXPECT_LT(brute, P.band) << what;
        EXPECT_NEAR(reported/P.d, brute/P.d, 1e-3) << what;
        label bad = 0;
        checkConsistent(P, bi, bk, cs, bad);
        EXPECT_EQ(bad, 0) << what;
        std::cout
            << "[ measured ] " << what << ": brute force " << brute/P.d
            << " d, least contact gap " << reported/P.d << " d ("
            << cs.size() << " contacts)" << std::endl;
    }
}


TEST(prismContacts, cylinderStandingOnACylindersTopFace)
{
    // i stands on k's top face, off the axis and turned about it, at gap g
    // (or into it by |g|): the least gap is g, and the contacts at g are
    // the corners of the support (at least three, spanning a triangle),
    // n = e_z, inside both discs, midway across the gap. Where the two
    // rims pass each other, contacts of other normals and larger gaps
    // join them (the reduction keeps 4 per group of normals and tier of
    // gap): 10 contacts at g = 2e-4, 3 of them at g. Seen from the other
    // pellet the normals flip
    const pellet P(cylinderEntries);
    for (const scalar g : {2e-4, 0.0, -1e-4})
    {
        const rigidBody bk(bodyAt(Zero, quaternion(1)));
        const point xi(0.3*r, 0.2*r, 2*r + g);
        const rigidBody bi(bodyAt(xi, turn(ez, 0.7)));

        for (const bool swap : {false, true})
        {
            const rigidBody& b1 = swap ? bk : bi;
            const rigidBody& b0 = swap ? bi : bk;
            const vector up(swap ? -ez : ez);
            DynamicList<contact> cs;
            P.contacts->prismPrism(1, b1, 0, b0, cs);
            ASSERT_GE(cs.size(), 3) << "gap " << g;
            EXPECT_NEAR(minGap(cs), g, 1e-12) << "gap " << g;
            DynamicList<contact> support;
            for (const contact& c : cs)
            {
                EXPECT_GE(c.gap, g - 1e-12);
                if (c.gap < g + 1e-12)
                {
                    support.append(c);
                    EXPECT_NEAR(mag(c.n - up), 0, 1e-9);
                    EXPECT_NEAR(c.p.z(), r + 0.5*g, 1e-12);
                    EXPECT_LE(mag(vector2D(c.p.x(), c.p.y())), r*(1 + 1e-9));
                    EXPECT_LE
                    (
                        mag(vector2D(c.p.x() - xi.x(), c.p.y() - xi.y())),
                        r*(1 + 1e-9)
                    );
                }
            }
            EXPECT_GE(support.size(), 3) << "gap " << g << " swap " << swap;
            EXPECT_LE(support.size(), 4) << "gap " << g << " swap " << swap;
            EXPECT_GT(largestTriangle(support), 0.2*sqr(r)) << "gap " << g;
            label bad = 0;
            checkConsistent(P, b1, b0, cs, bad);
            EXPECT_EQ(bad, 0);
        }
    }
}


TEST(prismContacts, coaxialStandingCylindersGiveTheFourCornersOfTheFace)
{
    // Coaxial and turned: the rims lie on each other, every rim point is
    // a support point at gap g >= 0; cut to four corners, n = e_z
    const pellet P(cylinderEntries);
    for (const scalar g : {2e-4, 0.0})
    {
        const rigidBody bk(bodyAt(Zero, quaternion(1)));
        const rigidBody bi(bodyAt(point(0, 0, 2*r + g), turn(ez, 0.7)));
        const DynamicList<contact> cs(P.pair(bi, bk));
        ASSERT_EQ(cs.size(), 4) << "gap " << g;
        for (const contact& c : cs)
        {
            EXPECT_NEAR(c.gap, g, 1e-12);
            EXPECT_NEAR(mag(c.n - ez), 0, 1e-9);
        }
        EXPECT_GT(largestTriangle(cs), 0.9*sqr(r));
    }
}


namespace
{
    //- The point of the bottom face of pellet b deepest inside its
    //  cross-section (a grid of 100 x 100 points), world frame
    point deepInside(const pellet& P, const rigidBody& b)
    {
        const prismProfile& p = P.profile();
        const scalar R = p.outerRadius();
        vector2D best(Zero);
        scalar deepest = GREAT;
        for (label i = 0; i < 100; ++i)
        {
            for (label j = 0; j < 100; ++j)
            {
                const vector2D q(-R + 0.02*R*(i + 0.5), -R + 0.02*R*(j + 0.5));
                vector2D g;
                label arcI;
                const scalar d2 = p.distance2D(q, g, arcI);
                if (d2 < deepest)
                {
                    deepest = d2;
                    best = q;
                }
            }
        }
        const point x(best.x(), best.y(), -p.halfHeight());
        return (b.R() & ((p.Q() & x) + p.t())) + b.x();
    }
}


TEST(prismContacts, alignedStacksReportTheirOverlap)
{
    // Two pellets of one shape stacked with their outlines on top of each
    // other in plan view (coaxial cylinders and rings, trilobes and
    // cylinders with holes of one orientation), or nearly so (a cylinder
    // off the axis by 1e-6 d and 1e-3 d), overlapping by delta = 0.01 d
    // and 0.05 d: the deepest penetration is delta (i's bottom face lies
    // delta deep in k, brute force), and the least contact gap must be
    // -delta within 0.001 d. Found: every feature sample of prismContacts
    // is a rim or wall point, and each rim lies on (or within the offset
    // of) the other's lateral wall, so that the least gap reported is
    // minus the offset with a radial normal (0 when aligned), whatever
    // the overlap
    struct stack
    {
        const char* entries;
        scalar offset;
    };
    for
    (
        const stack& st
      : {
            stack{cylinderEntries, 0}, stack{cylinderEntries, 1e-8},
            stack{cylinderEntries, 1e-5}, stack{ringEntries, 0},
            stack{trilobeEntries, 0}, stack{holesEntries, 0}
        }
    )
    {
        const pellet P(st.entries);
        const scalar H = 2*P.profile->halfHeight();
        for (const scalar delta : {0.01*P.d, 0.05*P.d})
        {
            const rigidBody bk(bodyAt(Zero, quaternion(1)));
            const rigidBody bi
            (
                bodyAt(point(st.offset, 0, H - delta), quaternion(1))
            );
            // The witness: the point of i's bottom face deepest in the
            // cross-section lies delta deep in k (k's top face is nearest;
            // no brute force: over two faces flat on each other it would
            // refine both faces all over)
            const scalar brute =
                worldDistance(P.profile(), bk, deepInside(P, bi));
            EXPECT_NEAR(brute, -delta, 1e-12);
            const DynamicList<contact> cs(P.pair(bi, bk));
            ASSERT_GE(cs.size(), 1);
            const contact& c = deepest(cs);
            EXPECT_NEAR(c.gap/P.d, -delta/P.d, 1e-3)
                << st.entries << " offset " << st.offset << " overlap "
                << delta << ": brute force " << brute << ", least contact"
                << " gap " << c.gap << " n " << str(c.n);
        }
    }
}


TEST(prismContacts, crossedLyingCylindersTouchAtOnePoint)
{
    // k lies along x, i along the horizontal at gamma from x with its axis
    // 2 r + g above k's: gap = distance of the axes - d = g, one contact
    // where the axes cross in plan view, n = e_z
    const pellet P(cylinderEntries);
    for (const scalar gamma : {0.5*pi, pi/3})
    {
        for (const scalar g : {3e-4, -1e-4})
        {
            const rigidBody bk(bodyAt(Zero, lyingAlongX()));
            const point xi(0.1*r, -0.2*r, 2*r + g);
            const rigidBody bi(bodyAt(xi, turn(ez, gamma)*lyingAlongX()));
            const scalar s = 0.2*r/Foam::sin(gamma);
            const point crossing(xi.x() + s*Foam::cos(gamma), 0, r + 0.5*g);

            const DynamicList<contact> cs(P.pair(bi, bk));
            ASSERT_EQ(cs.size(), 1) << "gamma " << gamma << " gap " << g;
            EXPECT_NEAR(cs[0].gap, g, 1e-9*r);
            EXPECT_NEAR(mag(cs[0].n - ez), 0, 1e-6);
            EXPECT_NEAR(mag(cs[0].p - crossing), 0, 1e-5*r)
                << str(cs[0].p) << " expected " << str(crossing);
            label bad = 0;
            checkConsistent(P, bi, bk, cs, bad);
            EXPECT_EQ(bad, 0);
        }
    }
}


TEST(prismContacts, parallelLyingCylindersTouchAtTheEndsOfTheirLine)
{
    // Both along x, side by side in y at gap g, i shifted by 0.2 r along x
    // (and turned about its axis): the line contact from x = -0.8 r (i's
    // rim) to x = r (k's rim) is cut to its two ends, both at gap g with
    // n = e_y (rim samples next to an end, a little above g, come in the
    // next tier of gap: 4 contacts in all)
    const pellet P(cylinderEntries);
    for (const scalar g : {2e-4, -1e-4})
    {
        const rigidBody bk(bodyAt(Zero, lyingAlongX()));
        const rigidBody bi
        (
            bodyAt(point(0.2*r, 2*r + g, 0), turn(ex, 0.4)*lyingAlongX())
        );
        const DynamicList<contact> cs(P.pair(bi, bk));
        std::vector<scalar> xs;
        for (const contact& c : cs)
        {
            EXPECT_GE(c.gap, g - 1e-9*r);
            if (c.gap < g + 1e-9*r)
            {
                EXPECT_NEAR(mag(c.n - ey), 0, 1e-6);
                EXPECT_NEAR(c.p.y(), r + 0.5*g, 1e-9*r);
                EXPECT_NEAR(c.p.z(), 0, 1e-5*r);
                xs.push_back(c.p.x());
            }
        }
        ASSERT_EQ(xs.size(), 2) << "gap " << g;
        std::sort(xs.begin(), xs.end());
        EXPECT_NEAR(xs[0], -0.8*r, 1e-9*r);
        EXPECT_NEAR(xs[1], r, 1e-9*r);
        label bad = 0;
        checkConsistent(P, bi, bk, cs, bad);
        EXPECT_EQ(bad, 0);
    }
}


namespace
{
    //- The least distance into (or from) pellet b of the points of pellet
    //  a's surface (rims, lateral wall; a cylinder, dense: 0.01 degrees,
    //  1 um) within reach of the world point near [m]
    scalar surfaceGapNear
    (
        const pellet& P,
        const rigidBody& a,
        const rigidBody& b,
        const point& near,
        const scalar reach
    )
    {
        const prismProfile& p = P.profile();
        const scalar R = p.outerRadius();
        const scalar h = p.halfHeight();
        auto world = [&](const point& x)
        {
            return (a.R() & ((p.Q() & x) + p.t())) + a.x();
        };
        scalar least = GREAT;
        const label nT = 36000;
        for (label j = 0; j < nT; ++j)
        {
            const scalar t = twoPi*j/nT;
            const scalar c = Foam::cos(t), s = Foam::sin(t);
            // Where this generator passes within reach of near
            const point lo(world(point(R*c, R*s, -h)));
            const point hi(world(point(R*c, R*s, h)));
            const vector e(hi - lo);
            const scalar u = ((near - lo) & e)/magSqr(e);
            const point foot(lo + max(0.0, min(1.0, u))*e);
            if (mag(foot - near) > reach)
            {
                continue;
            }
            const label nZ = label(2*h/1e-6);
            for (label m = 0; m <= nZ; ++m)
            {
                const point y(world(point(R*c, R*s, -h + 2*h*m/nZ)));
                if (mag(y - near) <= reach)
                {
                    least = min(least, worldDistance(p, b, y));
                }
            }
        }
        return least;
    }
}


TEST(prismContacts, bothEndsOfALyingCylinderRockingOnAnother)
{
    // Two lying cylinders of the 78-cylinder validation bed (N = 3.55,
    // seed 1, step 32 814, poses from the run): the upper one lies along
    // the lower's wall, a line contact from B (the upper's rim at -h, -0.9
    // um, the deepest) to A (its rim at +h, +0.1 um), and rocks between
    // them. The narrow phase gave B and, near A, only the rim sample 0.2
    // rad off at +51 um: the rim's refinement took no step (a cap of 0 on
    // the fixed height scaled every step to nothing), and the wall's, in
    // (angle, height), slid down the line to B. A, unlisted, sank 50 um
    // (0.5 % d) in the next step of 3.1 ms. Both ends must be listed
    // within 0.001 d of their brute-force gap
    const pellet P(cylinderEntries);
    const rigidBody lower
    (
        bodyAt
        (
            point(0.011278503759727236, -0.0041864925812143041,
                  0.08838889669736158),
            quaternion(0.42062753803087183, vector(-0.22748439043036561,
                       0.69948054494901801, 0.53108407394539459))
        )
    );
    const rigidBody upper
    (
        bodyAt
        (
            point(0.011054389927414216, -0.0044595471669995014,
                  0.098449074626211927),
            quaternion(-0.27732524422879501, vector(0.5136908336960041,
                       0.526412198083548, 0.61814450899364215))
        )
    );
    const DynamicList<contact> cs(P.pair(upper, lower));
    const scalar reach = 1.5e-3;
    for (const point& place : {point(0.0127, -0.0002, 0.0931),
                               point(0.00964, -0.00846, 0.09378)})
    {
        const scalar brute = min
        (
            surfaceGapNear(P, upper, lower, place, reach),
            surfaceGapNear(P, lower, upper, place, reach)
        );
        ASSERT_LT(brute, P.band) << str(place);
        scalar listed = GREAT;
        for (const contact& c : cs)
        {
            if (mag(c.p - place) < reach)
            {
                listed = min(listed, c.gap);
            }
        }
        std::cout
            << "[ measured ] near " << str(place) << ": brute force "
            << brute/P.d << " d, least contact gap there " << listed/P.d
            << " d" << std::endl;
        EXPECT_NEAR(listed/P.d, brute/P.d, 1e-3) << str(place);
    }
    label bad = 0;
    checkConsistent(P, upper, lower, cs, bad);
    EXPECT_EQ(bad, 0);
}


TEST(prismContacts, cylinderOnItsRimOnAFace)
{
    // i tilted by 30 degrees about x with its lowest rim point at g above
    // k's top face (inside it in plan view): i is all above z = h + g, k
    // below z = h, so the least gap is g at that point, n = e_z
    const pellet P(cylinderEntries);
    for (const scalar g : {2e-4, -1e-4})
    {
        const point low(0.1*r, -0.2*r, r + g);
        const rigidBody bk(bodyAt(Zero, quaternion(1)));
        const rigidBody bi(bodyAt(tiltedCentre(low, pi/6), turn(ex, pi/6)));
        const DynamicList<contact> cs(P.pair(bi, bk));
        ASSERT_GE(cs.size(), 1);
        const contact& c = deepest(cs);
        EXPECT_NEAR(c.gap, g, 1e-9*r) << "gap " << g;
        EXPECT_NEAR(mag(c.n - ez), 0, 1e-6);
        EXPECT_NEAR(mag(c.p - (low - 0.5*g*ez)), 0, 1e-5*r) << str(c.p);
        label bad = 0;
        checkConsistent(P, bi, bk, cs, bad);
        EXPECT_EQ(bad, 0);
    }
}


TEST(prismContacts, aRimsMinimumBetweenSamplesIsOneContact)
{
    // The pose of cylinderOnItsRimOnAFace, i turned about its own axis
    // so that its lowest rim point lies between two of the rim's samples
    // (every 15 degrees), 5 degrees from the nearer. The refined minimum
    // is the contact there (its gap exact), and it stands in for that
    // sample. Both listed (the wall's refinement at its end level found
    // this minimum and the sample stayed beside it), 0.44 mm and 9.5 um
    // of gap apart, they are two nearly equal rows of the resting LCP;
    // with every rim minimum refined that way, a 30-trilobe bed crept for
    // 23 s of its 30 (docs/restingSolveCost.md, "Thirty-first session").
    // The next sample, 10 degrees off and 38 um higher, stays
    const pellet P(cylinderEntries);
    const scalar sample = twoPi/24;
    for (const scalar spin : {sample/3, -sample/3, 0.5*sample})
    {
        const scalar g = 1e-4;
        const point low(0.1*r, -0.2*r, r + g);
        const rigidBody bk(bodyAt(Zero, quaternion(1)));
        const rigidBody bi
        (
            bodyAt(tiltedCentre(low, pi/6), turn(ex, pi/6)*turn(ez, spin))
        );
        const DynamicList<contact> cs(P.pair(bi, bk));
        ASSERT_GE(cs.size(), 1);
        const contact& c = deepest(cs);
        EXPECT_NEAR(c.gap, g, 1e-9*r) << "spin " << spin;
        EXPECT_NEAR(mag(c.p - (low - 0.5*g*ez)), 0, 1e-5*r) << str(c.p);
        scalar nearest = GREAT;
        for (const contact& o : cs)
        {
            if (&o != &c)
            {
                nearest = min(nearest, mag(o.p - c.p));
            }
        }
        std::cout
            << "[ measured ] spin " << spin/sample << " sample: "
            << cs.size() << " contacts, the nearest to the lowest point "
            << nearest/(r*sample) << " sample spacings from it" << std::endl;
        EXPECT_GT(nearest, 0.45*r*sample) << "spin " << spin;
        label bad = 0;
        checkConsistent(P, bi, bk, cs, bad);
        EXPECT_EQ(bad, 0);
    }
}


TEST(prismContacts, twoRimsCrossing)
{
    // Edge on edge: i's rim crosses k's top rim at right angles in plan
    // view (crossingRim), i extending either way along the tangent: i is
    // all above z = h + g, k below z = h; the least gap is g, at k's rim
    // point P, n = e_z. (Along k's rim the gap rises as the fourth power
    // of the distance from P: the point is found to about 1e-4 r.) Into
    // each other by |g| the deepest point is not P (k's rim 1e-4 along
    // the tangent lies |g| - 1e-10 m inside i, its face and wall alike):
    // brute force, and g to 1e-5 relative
    const pellet P(cylinderEntries);
    const scalar psi = 0.7;
    const point Pk(r*Foam::cos(psi), r*Foam::sin(psi), r);
    for (const scalar sign : {1.0, -1.0})
    {
        for (const scalar g : {2e-4, -1e-4})
        {
            const rigidBody bk(bodyAt(Zero, quaternion(1)));
            const rigidBody bi(crossingRim(psi, sign, g));
            const DynamicList<contact> cs(P.pair(bi, bk));
            ASSERT_GE(cs.size(), 1);
            const contact& c = deepest(cs);
            label bad = 0;
            checkConsistent(P, bi, bk, cs, bad);
            EXPECT_EQ(bad, 0);
            if (g > 0)
            {
                EXPECT_NEAR(c.gap, g, 1e-9*r) << "sign " << sign;
                EXPECT_NEAR(mag(c.n - ez), 0, 1e-6);
                EXPECT_NEAR(mag(c.p - (Pk + 0.5*g*ez)), 0, 1e-3*r)
                    << str(c.p);
            }
            else
            {
                EXPECT_NEAR(c.gap, g, 1e-5*mag(g)) << "sign " << sign;
                EXPECT_NEAR(mag(c.n - ez), 0, 1e-3);
                expectBruteForce
                (
                    P, bi, bk,
                    std::string("rims crossing into each other, sign ")
                  + (sign > 0 ? "+" : "-")
                );
            }
        }
    }
}


TEST(prismContacts, ringLyingAcrossAnotherRingsBore)
{
    // Ring i (10/6/10 mm) on its wall, axis horizontal, across the bore of
    // ring k standing: its lowest line (x = 0.3 mm, z = h + g) lies over
    // k's top face on both sides of the bore, so that the least gap is g
    // on either side, n = e_z. The contacts: the least gap g, none below,
    // and on either side of the bore one within 0.001 d of g. (Measured:
    // the -y side at g, from i's rim; on the +y side the reduction keeps
    // the sample of k's outer rim at 90 degrees, 8.6e-4 d above g, rather
    // than the minimum refined 3.4 degrees from it, at g: both lie in the
    // first tier, and the sample is farther from the deepest point; with
    // the line at x = 0.5 mm instead, 2.4e-3 d above g)
    const pellet P(ringEntries);
    const scalar ri = 0.003;
    for (const scalar g : {2e-4, -1e-4})
    {
        const rigidBody bk(bodyAt(Zero, quaternion(1)));
        const rigidBody bi
        (
            bodyAt(point(0.0003, 0.0002, 2*r + g), turn(ex, -0.5*pi))
        );
        const DynamicList<contact> cs(P.pair(bi, bk));
        scalar plus = GREAT, minus = GREAT;
        for (const contact& c : cs)
        {
            EXPECT_GE(c.gap, g - 1e-12);
            if ((c.n & ez) > Foam::cos(contactReduction::clusterAngle))
            {
                if (c.p.y() > ri)
                {
                    plus = min(plus, c.gap);
                }
                if (c.p.y() < -ri)
                {
                    minus = min(minus, c.gap);
                }
            }
        }
        EXPECT_NEAR(minGap(cs), g, 1e-12);
        EXPECT_NEAR(plus/P.d, g/P.d, 1e-3) << "gap " << g;
        EXPECT_NEAR(minus/P.d, g/P.d, 1e-3) << "gap " << g;
        label bad = 0;
        checkConsistent(P, bi, bk, cs, bad);
        EXPECT_EQ(bad, 0);
        std::cout
            << "[ measured ] ring across a bore at g = " << g/P.d << " d: "
            << cs.size() << " contacts, least gap on the +y side g + "
            << (plus - g)/P.d << " d, on the -y side g + " << (minus - g)/P.d
            << " d" << std::endl;
    }
}


TEST(prismContacts, tiltedRingDippingIntoABoreAgreesWithBruteForce)
{
    // Ring i, axis tilted 25 degrees from the horizontal, lowered onto the
    // bore of ring k standing until the brute-force gap is 0.001 d, 1e-4 d
    // and -5e-4 d: its rim dips into the bore onto k's inner rim
    const pellet P(ringEntries);
    const rigidBody bk(bodyAt(Zero, quaternion(1)));
    const quaternion qi(turn(ez, 0.3)*turn(ex, -0.5*pi + 25*pi/180));
    for (const scalar target : {1e-3, 1e-4, -5e-4})
    {
        const point xi
        (
            placeAt
            (
                P, point(0.0004, -0.0003, 0), qi, ez,
                2*P.shape->boundingRadius() + 0.01*P.d, bk, target*P.d
            )
        );
        expectBruteForce
        (
            P, bodyAt(xi, qi), bk,
            "ring dipping into a bore at " + std::to_string(target) + " d"
        );
    }
}


TEST(prismContacts, hookedWashersAgreeWithBruteForce)
{
    // Washers 10/6/2 mm (a ring 10 mm high cannot pass another's bore):
    // k stands, i's axis along y, slightly turned, its wall through k's
    // bore and k's wall through its own; i moved along x from deep in k's
    // bore wall until the brute-force gap is 0.002 d, 2e-4 d and -5e-4 d
    const pellet P(washerEntries);
    const rigidBody bk(bodyAt(Zero, quaternion(1)));
    const quaternion qi(turn(ez, 0.1)*turn(ex, -0.5*pi + 0.05));
    for (const scalar target : {2e-3, 2e-4, -5e-4})
    {
        const point xi
        (
            placeAt
            (
                P, point(0.001, 0.0001, 0.00005), qi, ex, 0.0032, bk,
                target*P.d
            )
        );
        expectBruteForce
        (
            P, bodyAt(xi, qi), bk,
            "hooked washers at " + std::to_string(target) + " d"
        );
    }
}


// * * * * * * * * * * * * * * * Container  * * * * * * * * * * * * * * * //

TEST(prismContacts, cylinderAndRingLyingOnTheFloor)
{
    // A cylinder or ring meets the container by cylinderTube with round
    // rims: lying on the floor, the lowest point of each rim at gap g (the
    // points a quarter turn round are r above the floor, beyond the band):
    // two contacts, at the ends of the line; besides them only the floor's
    // next points (floorSupport: material points of the circles, rhoI 0,
    // within floorNearSpan band above the lowest)
    const tube container(0.05, 0.1, 0.3, 0.5);
    for (const char* entries : {cylinderEntries, ringEntries})
    {
        const pellet P(entries);
        for (const scalar g : {2e-4, -1e-4})
        {
            const quaternion q(turn(ez, 0.4)*lyingAlongX());
            const rigidBody b(bodyAt(point(0.002, -0.001, r + g), q));
            const vector axis(b.R() & ez);
            DynamicList<contact> all;
            P.contacts->prismTube(0, b, container, all);
            DynamicList<contact> cs;
            for (const contact& c : all)
            {
                if (c.rhoI != 0)
                {
                    cs.append(c);
                }
                else
                {
                    EXPECT_GT(c.gap, g) << entries;
                    EXPECT_LE(c.gap, g + floorNearSpan*P.band) << entries;
                }
            }
            ASSERT_EQ(cs.size(), 2) << entries << " gap " << g;
            scalar along = 0;
            for (const contact& c : cs)
            {
                EXPECT_EQ(c.k, label(tubeBottom));
                EXPECT_NEAR(c.gap, g, 1e-12);
                EXPECT_NEAR(mag(c.n - ez), 0, 1e-12);
                EXPECT_NEAR((b.x() + c.ri).z(), g, 1e-12);
                EXPECT_NEAR(mag(c.ri & axis), r, 1e-12);
                along += c.ri & axis;
            }
            EXPECT_NEAR(along, 0, 1e-12);
        }
    }
}


namespace
{
    //- Lowest point over the rims of a prism at body b: on an arc at
    //  height z the world height is linear in (cos t, sin t), least at the
    //  angle of minus the horizontal part of e_z in the profile frame (if
    //  within the arc) or at an end [m]
    scalar lowestRimPoint(const prismProfile& p, const rigidBody& b)
    {
        const tensor M(b.R() & p.Q());
        const vector G(M.T() & ez);
        const scalar base = ((b.R() & p.t()) + b.x()).z();
        scalar low = GREAT;
        for (const prismProfile::arc& a : p.arcs())
        {
            for (const scalar z : {-p.halfHeight(), p.halfHeight()})
            {
                auto height = [&](const vector2D& u)
                {
                    return
                        base + G.x()*(a.c.x() + a.r*u.x())
                      + G.y()*(a.c.y() + a.r*u.y()) + G.z()*z;
                };
                const vector2D down(-G.x(), -G.y());
                if (mag(down) > VSMALL && a.within(down))
                {
                    low = min(low, height(down/mag(down)));
                }
                if (!a.fullCircle())
                {
                    low = min(low, min(height(a.u0), height(a.u1)));
                }
            }
        }
        return low;
    }

    //- Largest axial distance over the rims of an upright prism at body b
    //  (rims in horizontal planes): per arc |C| + r where the direction of
    //  its centre C from the tube axis lies within the arc, else an end
    scalar outermostRimPoint(const prismProfile& p, const rigidBody& b)
    {
        const tensor M(b.R() & p.Q());
        const vector T((b.R() & p.t()) + b.x());
        scalar far = 0;
        for (const prismProfile::arc& a : p.arcs())
        {
            auto world = [&](const vector2D& q)
            {
                return (M & point(q.x(), q.y(), p.halfHeight())) + T;
            };
            const point C(world(a.c));
            const vector out(C.x(), C.y(), 0);
            const vector outProfile(M.T() & (out/mag(out)));
            if (a.within(vector2D(outProfile.x(), outProfile.y())))
            {
                far = max(far, mag(out) + a.r);
            }
            for (const vector2D& u : {a.u0, a.u1})
            {
                far = max(far, tube::axialDistance(world(a.c + a.r*u)));
            }
        }
        return far;
    }
}


TEST(prismContacts, trilobeOnTheFloorAndAtTheWall)
{
    // The generic path (no round hull): the rims against the floor and the
    // wall. Standing upright on the floor at gap g: every contact at g,
    // n = e_z, the support cut to its corners. Tilted at random: the least
    // gap is the lowest rim point's height (closed form), none below.
    // Standing near the wall: the least gap is R - the largest axial
    // distance of the rims (closed form), n = -e_r
    const pellet P(trilobeEntries);
    const prismProfile& prof = P.profile();
    const scalar h = prof.halfHeight();
    const tube container(0.04, 0.1, 0.3, 0.5);
    const scalar R = container.radius();

    for (const scalar g : {2e-4, -1e-4})
    {
        const rigidBody b(bodyAt(point(0.003, 0.001, h + g), turn(ez, 0.3)));
        DynamicList<contact> cs;
        P.contacts->prismTube(0, b, container, cs);
        ASSERT_GE(cs.size(), 3) << "gap " << g;
        ASSERT_LE(cs.size(), 4) << "gap " << g;
        for (const contact& c : cs)
        {
            EXPECT_EQ(c.k, label(tubeBottom));
            EXPECT_NEAR(c.gap, g, 1e-12);
            EXPECT_NEAR(mag(c.n - ez), 0, 1e-12);
            EXPECT_NEAR((b.x() + c.ri).z(), g, 1e-12);
        }
        EXPECT_GT(largestTriangle(cs), 0.1*sqr(P.d));
    }

    std::mt19937 rng(7);
    scalar worst = 0;
    for (label pose = 0; pose < 50; ++pose)
    {
        const quaternion q(randomQ(rng));
        const scalar g = (pose % 2 ? 1e-4 : -5e-5);
        const rigidBody b0(bodyAt(point(0.002, -0.001, 0.02), q));
        const scalar z = 0.02 - lowestRimPoint(prof, b0) + g;
        const rigidBody b(bodyAt(point(0.002, -0.001, z), q));
        ASSERT_NEAR(lowestRimPoint(prof, b), g, 1e-12);
        DynamicList<contact> cs;
        P.contacts->prismTube(0, b, container, cs);
        ASSERT_GE(cs.size(), 1) << "pose " << pose;
        EXPECT_NEAR(minGap(cs), g, 1e-9*P.d) << "pose " << pose;
        worst = max(worst, mag(minGap(cs) - g));
        for (const contact& c : cs)
        {
            EXPECT_EQ(c.k, label(tubeBottom));
            EXPECT_GE(c.gap, g - 1e-12);
            EXPECT_NEAR((b.x() + c.ri).z(), c.gap, 1e-12);
        }
    }
    std::cout
        << "[ measured ] trilobe on the floor, 50 tilted poses: |least gap -"
        << " lowest rim point| <= " << worst << " m" << std::endl;

    for (const scalar phi : {0.0, 0.4, 1.3})
    {
        const quaternion q(turn(ez, phi));
        const vector er(Foam::cos(0.2), Foam::sin(0.2), 0);
        // Out along e_r until the rims are about 1e-4 from the wall
        scalar D = 0;
        for (label it = 0; it < 4; ++it)
        {
            const rigidBody b0(bodyAt(D*er + 0.05*ez, q));
            D += R - outermostRimPoint(prof, b0) - 1e-4;
        }
        const rigidBody b(bodyAt(D*er + 0.05*ez, q));
        const scalar gap = R - outermostRimPoint(prof, b);
        ASSERT_LT(gap, P.band);
        DynamicList<contact> cs;
        P.contacts->prismTube(0, b, container, cs);
        ASSERT_GE(cs.size(), 1) << "phi " << phi;
        EXPECT_NEAR(minGap(cs), gap, 1e-9*P.d) << "phi " << phi;
        for (const contact& c : cs)
        {
            EXPECT_EQ(c.k, label(tubeWall));
            EXPECT_GE(c.gap, gap - 1e-12);
            const point y(b.x() + c.ri);
            EXPECT_NEAR(R - tube::axialDistance(y), c.gap, 1e-12);
            EXPECT_NEAR
            (
                mag(c.n + vector(y.x(), y.y(), 0)/tube::axialDistance(y)),
                0, 1e-12
            );
        }
    }
}


// * * * * * * * * * * * * * Mesh against exact  * * * * * * * * * * * * * //

namespace
{
    //- The distinct angles about the z axis of the points at distance r
    //  from it (to 1e-9 r): the vertices of a rim polygon of radius r of a
    //  prism mesh
    label rimVertices(const pointField& points, const scalar r)
    {
        std::vector<scalar> angles;
        for (const point& p : points)
        {
            if (mag(Foam::sqrt(sqr(p.x()) + sqr(p.y())) - r) <= 1e-9*r)
            {
                angles.push_back(Foam::atan2(p.y(), p.x()));
            }
        }
        std::sort(angles.begin(), angles.end());
        label n = 0;
        for (size_t k = 0; k < angles.size(); ++k)
        {
            n += k == 0 || angles[k] - angles[k - 1] > 1e-9;
        }
        return n;
    }

    //- Sagitta of the mesh's polygons: r (1 - cos(pi/n)) for every circle
    //  of the profile, n the mesh's vertices on it (at either end), the
    //  largest [m]
    scalar meshSagitta(const pellet& P)
    {
        const pointField& pts = P.shape->mesh().points();
        scalar sag = 0;
        for (const prismProfile::arc& a : P.profile->arcs())
        {
            const label n = rimVertices(pts, a.r);
            EXPECT_GE(n, 16);
            sag = max(sag, a.r*(1 - Foam::cos(pi/n)));
        }
        return sag;
    }
}


TEST(prismContacts, meshContactsAgreeToTheMeshResolution)
{
    // The triangle narrow phase (meshContacts) on the shapes' meshes of
    // 4000 faces, inscribed in the true surface, on the configurations
    // above: its least gap is the exact one within the sagittas of the two
    // pellets' polygons, 2 r (1 - cos(pi/n)), plus 1e-6 d
    const pellet cyl
    (
        "shape cylinder; diameter 0.01; height 0.01; faces 4000;"
    );
    const pellet ring
    (
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
        " faces 4000;"
    );
    const pellet washer
    (
        "shape ring; diameter 0.01; innerDiameter 0.006; height 0.002;"
        " faces 4000;"
    );
    const rigidBody standing(bodyAt(Zero, quaternion(1)));

    struct configuration
    {
        std::string name;
        const pellet* P;
        rigidBody bi;
    };
    std::vector<configuration> configurations;
    configurations.push_back
    ({
        "cylinder on its rim", &cyl,
        bodyAt(tiltedCentre(point(0.1*r, -0.2*r, r + 2e-4), pi/6),
            turn(ex, pi/6))
    });
    configurations.push_back
    ({
        "rims crossing", &cyl, crossingRim(0.7, 1, 2e-4)
    });
    configurations.push_back
    ({
        "ring across a bore", &ring,
        bodyAt(point(0.0003, 0.0002, 2*r + 2e-4), turn(ex, -0.5*pi))
    });
    {
        const quaternion q(turn(ez, 0.3)*turn(ex, -0.5*pi + 25*pi/180));
        configurations.push_back
        ({
            "ring dipping into a bore", &ring,
            bodyAt
            (
                placeAt
                (
                    ring, point(0.0004, -0.0003, 0), q, ez,
                    2*ring.shape->boundingRadius() + 0.01*ring.d, standing,
                    0.005*ring.d
                ),
                q
            )
        });
    }
    {
        const quaternion q(turn(ez, 0.1)*turn(ex, -0.5*pi + 0.05));
        configurations.push_back
        ({
            "hooked washers", &washer,
            bodyAt
            (
                placeAt
                (
                    washer, point(0.001, 0.0001, 0.00005), q, ex, 0.0032,
                    standing, 0.005*washer.d
                ),
                q
            )
        });
    }

    for (const configuration& c : configurations)
    {
        const pellet& P = *c.P;
        const meshContacts mc(P.shape->mesh(), P.band);
        const scalar bound = 2*meshSagitta(P) + 1e-6*P.d;

        const DynamicList<contact> exact(P.pair(c.bi, standing));
        DynamicList<contact> meshed;
        mc.meshMesh(1, c.bi, 0, standing, meshed);
        ASSERT_GE(exact.size(), 1) << c.name;
        ASSERT_GE(meshed.size(), 1) << c.name;
        const scalar gExact = minGap(exact);
        const scalar gMesh = minGap(meshed);
        EXPECT_NEAR(gMesh, gExact, bound) << c.name;
        std::cout
            << "[ measured ] " << c.name << ": least gap exact "
            << gExact/P.d << " d, mesh " << gMesh/P.d << " d, difference "
            << (gMesh - gExact)/P.d << " d (bound " << bound/P.d << " d)"
            << std::endl;
    }
}


// ************************************************************************* //

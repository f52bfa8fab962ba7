// Unit tests for src/rbdPacking/narrowPhase/bodyBVH: the tree, the mesh
// topology and the two-tree descent against brute force (every node's box
// from its triangles, all pairs of triangles for the descent) and closed
// forms (an L-shaped prism whose one concave edge is known)

#include <gtest/gtest.h>
#include "bodyBVH.H"
#include "pelletShape.H"
#include "IStringStream.H"
#include "quaternion.H"

#include <random>
#include <set>

using namespace Foam;

namespace
{
    dictionary parse(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    //- Prism of height h over the L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2)
    //  (counter-clockwise, reflex corner (1,1)), outward, 20 triangles:
    //  its edge up from (1,1) is the one concave edge
    rbd::triMesh lPrism(const scalar h = 1)
    {
        const scalar xy[6][2] =
            {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        pointField p(12);
        for (label i = 0; i < 6; ++i)
        {
            p[i] = point(xy[i][0], xy[i][1], 0);
            p[i + 6] = point(xy[i][0], xy[i][1], h);
        }
        DynamicList<triFace> f;
        // Caps: a fan from the reflex corner 3 (top counter-clockwise seen
        // from +z, bottom reversed)
        const label fan[4][2] = {{4, 5}, {5, 0}, {0, 1}, {1, 2}};
        for (const auto& t : fan)
        {
            f.append(triFace(3 + 6, t[0] + 6, t[1] + 6));
            f.append(triFace(3, t[1], t[0]));
        }
        // Sides: quad b_i b_i+1 t_i+1 t_i
        for (label i = 0; i < 6; ++i)
        {
            const label j = (i + 1) % 6;
            f.append(triFace(i, j, j + 6));
            f.append(triFace(i, j + 6, i + 6));
        }
        return rbd::triMesh(p, List<triFace>(f));
    }

    //- A point for the messages
    std::string str(const point& p)
    {
        return
            "(" + std::to_string(p.x()) + " " + std::to_string(p.y()) + " "
          + std::to_string(p.z()) + ")";
    }

    //- Closest point on segment [a, b] to p
    point closestOnSegment(const point& a, const point& b, const point& p)
    {
        const vector d(b - a);
        const scalar t = min(max(((p - a) & d)/magSqr(d), 0.0), 1.0);
        return a + t*d;
    }

    //- Distance from p to triangle abc, by another route than the one
    //  under test: the projection on the plane if inside (barycentric
    //  coordinates), else the nearest of the three edges
    scalar pointTriangleDistance
    (
        const point& p, const point& a, const point& b, const point& c,
        point& closest
    )
    {
        const vector n((b - a) ^ (c - a));
        const point q(p - n*(((p - a) & n)/magSqr(n)));
        const scalar u = (((c - b) ^ (q - b)) & n)/magSqr(n);
        const scalar v = (((a - c) ^ (q - c)) & n)/magSqr(n);
        const scalar w = 1 - u - v;
        if (u >= 0 && v >= 0 && w >= 0)
        {
            closest = q;
            return mag(p - q);
        }
        scalar best = GREAT;
        const point* e[3][2] = {{&a, &b}, {&b, &c}, {&c, &a}};
        for (const auto& s : e)
        {
            const point x(closestOnSegment(*s[0], *s[1], p));
            if (mag(p - x) < best)
            {
                best = mag(p - x);
                closest = x;
            }
        }
        return best;
    }

    //- Distance between segments [p1, q1] and [p2, q2] (Ericson 5.1.9)
    scalar segmentDistance
    (
        const point& p1, const point& q1, const point& p2, const point& q2
    )
    {
        const vector d1(q1 - p1), d2(q2 - p2), r(p1 - p2);
        const scalar a = d1 & d1, e = d2 & d2, f = d2 & r;
        const scalar c = d1 & r, b = d1 & d2;
        const scalar denom = a*e - b*b;
        scalar s =
            denom > SMALL*a*e
          ? min(max((b*f - c*e)/denom, 0.0), 1.0)
          : 0;
        scalar t = (b*s + f)/e;
        if (t < 0)
        {
            t = 0;
            s = min(max(-c/a, 0.0), 1.0);
        }
        else if (t > 1)
        {
            t = 1;
            s = min(max((b - c)/a, 0.0), 1.0);
        }
        return mag((p1 + s*d1) - (p2 + t*d2));
    }

    //- An upper bound of the distance between two triangles (exact when
    //  they do not intersect): the nearest of the six vertex-triangle and
    //  nine edge-edge distances
    scalar triangleDistance
    (
        const FixedList<point, 3>& A,
        const FixedList<point, 3>& B
    )
    {
        scalar d = GREAT;
        point x;
        for (label i = 0; i < 3; ++i)
        {
            d = min(d, pointTriangleDistance(A[i], B[0], B[1], B[2], x));
            d = min(d, pointTriangleDistance(B[i], A[0], A[1], A[2], x));
            for (label j = 0; j < 3; ++j)
            {
                d = min
                (
                    d,
                    segmentDistance
                    (
                        A[i], A[(i + 1) % 3], B[j], B[(j + 1) % 3]
                    )
                );
            }
        }
        return d;
    }

    //- The leaf of every face
    labelList leafOfFace(const rbd::bodyBVH& T)
    {
        labelList leaf(T.mesh().nFaces(), -1);
        forAll(T.nodes(), n)
        {
            const rbd::bodyBVH::node& nd = T.nodes()[n];
            if (nd.leaf())
            {
                for (label j = nd.first; j < nd.first + nd.count; ++j)
                {
                    leaf[T.order()[j]] = n;
                }
            }
        }
        return leaf;
    }

    //- Every structural property of a tree, by brute force
    void checkTree(const rbd::bodyBVH& T, const label leafSize)
    {
        const rbd::triMesh& m = T.mesh();
        const pointField& pts = m.points();
        const List<triFace>& fs = m.faces();
        const label nF = m.nFaces();

        // order is a permutation of the faces
        ASSERT_EQ(T.order().size(), nF);
        {
            labelList seen(nF, 0);
            for (const label f : T.order())
            {
                ASSERT_TRUE(f >= 0 && f < nF);
                ++seen[f];
            }
            for (const label s : seen)
            {
                ASSERT_EQ(s, 1);
            }
        }

        // Root covers all; leaves partition order; boxes tight
        ASSERT_GT(T.nodes().size(), 0);
        EXPECT_EQ(T.nodes()[0].first, 0);
        EXPECT_EQ(T.nodes()[0].count, nF);
        labelList covered(nF, 0);
        forAll(T.nodes(), n)
        {
            const rbd::bodyBVH::node& nd = T.nodes()[n];
            point lo(point::uniform(GREAT)), hi(point::uniform(-GREAT));
            for (label j = nd.first; j < nd.first + nd.count; ++j)
            {
                for (const label p : fs[T.order()[j]])
                {
                    lo = min(lo, pts[p]);
                    hi = max(hi, pts[p]);
                }
            }
            EXPECT_EQ(nd.lo, lo) << "node " << n;
            EXPECT_EQ(nd.hi, hi) << "node " << n;
            EXPECT_NEAR(mag(nd.centre - 0.5*(lo + hi)), 0, 1e-15);
            EXPECT_NEAR(nd.radius, 0.5*mag(hi - lo), 1e-15);
            // Every vertex of the node inside its sphere
            for (label j = nd.first; j < nd.first + nd.count; ++j)
            {
                for (const label p : fs[T.order()[j]])
                {
                    ASSERT_LE(mag(pts[p] - nd.centre), nd.radius*(1 + 1e-12));
                }
            }

            if (nd.leaf())
            {
                EXPECT_EQ(nd.right, -1);
                EXPECT_GE(nd.count, 1);
                EXPECT_LE(nd.count, leafSize);
                std::set<label> ps, es;
                for (label j = nd.first; j < nd.first + nd.count; ++j)
                {
                    ++covered[j];
                    const label f = T.order()[j];
                    for (label q = 0; q < 3; ++q)
                    {
                        ps.insert(fs[f][q]);
                        const label e = T.faceEdges()[f][q];
                        if (T.edges()[e].feature)
                        {
                            es.insert(e);
                        }
                    }
                }
                const labelList& lp = T.leafPoints(n);
                const labelList& le = T.leafEdges(n);
                EXPECT_EQ(std::set<label>(lp.begin(), lp.end()), ps);
                EXPECT_EQ(label(ps.size()), lp.size()) << "each point once";
                EXPECT_EQ(std::set<label>(le.begin(), le.end()), es);
                EXPECT_EQ(label(es.size()), le.size()) << "each edge once";
                continue;
            }

            // Inner: more than leafSize triangles, split at the median of
            // the centroids along the longest box axis
            EXPECT_GT(nd.count, leafSize);
            const rbd::bodyBVH::node& l = T.nodes()[nd.left];
            const rbd::bodyBVH::node& r = T.nodes()[nd.right];
            EXPECT_EQ(l.first, nd.first);
            EXPECT_EQ(l.count, nd.count/2);
            EXPECT_EQ(r.first, nd.first + l.count);
            EXPECT_EQ(l.count + r.count, nd.count);
            const vector span(hi - lo);
            direction axis = 0;
            for (direction k = 1; k < 3; ++k)
            {
                if (span[k] > span[axis]) axis = k;
            }
            auto centroid = [&](const label f)
            {
                return
                    pts[fs[f][0]][axis] + pts[fs[f][1]][axis]
                  + pts[fs[f][2]][axis];
            };
            scalar maxLeft = -GREAT, minRight = GREAT;
            for (label j = l.first; j < l.first + l.count; ++j)
            {
                maxLeft = max(maxLeft, centroid(T.order()[j]));
            }
            for (label j = r.first; j < r.first + r.count; ++j)
            {
                minRight = min(minRight, centroid(T.order()[j]));
            }
            EXPECT_LE(maxLeft, minRight) << "node " << n;
        }
        for (const label c : covered)
        {
            ASSERT_EQ(c, 1) << "a face in one leaf exactly";
        }
    }

    //- Every edge, face-edge and point-face entry, by brute force, for a
    //  closed mesh
    void checkTopology(const rbd::bodyBVH& T)
    {
        const rbd::triMesh& m = T.mesh();
        const pointField& pts = m.points();
        const List<triFace>& fs = m.faces();
        // Euler: a closed triangle mesh has 3 F / 2 edges
        EXPECT_EQ(2*T.edges().size(), 3*m.nFaces());
        forAll(fs, f)
        {
            // Unit outward normals
            const vector n
            (
                (pts[fs[f][1]] - pts[fs[f][0]])
              ^ (pts[fs[f][2]] - pts[fs[f][0]])
            );
            EXPECT_NEAR(mag(T.normals()[f] - n/mag(n)), 0, 1e-12);
            for (label j = 0; j < 3; ++j)
            {
                const rbd::bodyBVH::edgeInfo& e =
                    T.edges()[T.faceEdges()[f][j]];
                EXPECT_TRUE
                (
                    edge(e.a, e.b) == edge(fs[f][j], fs[f][(j + 1) % 3])
                );
                EXPECT_TRUE(e.f1 == f || e.f2 == f);
            }
        }
        for (const rbd::bodyBVH::edgeInfo& e : T.edges())
        {
            ASSERT_GE(e.f2, 0) << "closed: two faces per edge";
            EXPECT_NE(e.f1, e.f2);
            const vector d(pts[e.b] - pts[e.a]);
            const label faces[2] = {e.f1, e.f2};
            const vector us[2] = {e.u1, e.u2};
            for (label k = 0; k < 2; ++k)
            {
                const triFace& t = fs[faces[k]];
                ASSERT_TRUE(t.found(e.a) && t.found(e.b));
                // Inward in-plane direction perpendicular to the edge,
                // towards the face's third point
                label o = t[0];
                for (const label p : t)
                {
                    if (p != e.a && p != e.b) o = p;
                }
                EXPECT_NEAR(mag(us[k]), 1, 1e-12);
                EXPECT_NEAR(us[k] & d, 0, 1e-12*mag(d));
                EXPECT_NEAR(us[k] & T.normals()[faces[k]], 0, 1e-12);
                EXPECT_GT(us[k] & (pts[o] - pts[e.a]), 0);
            }
            EXPECT_NEAR
            (
                mag(e.outward - T.normals()[e.f1] - T.normals()[e.f2]), 0, 1e-15
            );
        }
        forAll(pts, p)
        {
            std::set<label> expected;
            forAll(fs, f)
            {
                if (fs[f].found(p)) expected.insert(f);
            }
            const labelList& pf = T.pointFaces()[p];
            EXPECT_EQ(std::set<label>(pf.begin(), pf.end()), expected);
            EXPECT_EQ(label(expected.size()), pf.size());
        }
    }

    //- Random rotation (axis uniform on the sphere, angle uniform)
    tensor randomRotation(std::mt19937& gen)
    {
        std::uniform_real_distribution<double> U(0, 1);
        const scalar ct = 2*U(gen) - 1;
        const scalar st = std::sqrt(1 - ct*ct);
        const scalar phi = constant::mathematical::twoPi*U(gen);
        const vector axis(st*std::cos(phi), st*std::sin(phi), ct);
        return quaternion(axis, constant::mathematical::pi*U(gen)).R();
    }

    struct descentCount
    {
        label visited = 0;
        label required = 0;
        label leafPairs = 0;
    };

    //- The descent of A against B in pose (R, t) within band: every pair
    //  of faces within band by brute force lies in a visited pair of
    //  leaves; every visited pair's leaf spheres are within band
    descentCount checkDescent
    (
        const rbd::bodyBVH& A,
        const rbd::bodyBVH& B,
        const tensor& R,
        const vector& t,
        const scalar band
    )
    {
        std::set<std::pair<label, label>> visited;
        label calls = 0;
        A.leafPairs
        (
            B, R, t, band,
            [&](const label la, const label lb)
            {
                ++calls;
                visited.insert({la, lb});
            }
        );
        descentCount n;
        n.visited = visited.size();
        EXPECT_EQ(calls, n.visited) << "each pair of leaves once";

        label leavesA = 0, leavesB = 0;
        for (const auto& nd : A.nodes()) leavesA += nd.leaf();
        for (const auto& nd : B.nodes()) leavesB += nd.leaf();
        n.leafPairs = leavesA*leavesB;

        for (const auto& pr : visited)
        {
            const auto& a = A.nodes()[pr.first];
            const auto& b = B.nodes()[pr.second];
            EXPECT_TRUE(a.leaf() && b.leaf());
            EXPECT_LE
            (
                mag(((R & a.centre) + t) - b.centre),
                a.radius + b.radius + band + 1e-12
            );
        }

        // All pairs of faces
        const pointField& pa = A.mesh().points();
        const pointField& pb = B.mesh().points();
        const List<triFace>& fa = A.mesh().faces();
        const List<triFace>& fb = B.mesh().faces();
        List<FixedList<point, 3>> ta(fa.size()), tb(fb.size());
        List<point> ca(fa.size()), cb(fb.size());
        List<scalar> ra(fa.size()), rb(fb.size());
        forAll(fa, i)
        {
            for (label k = 0; k < 3; ++k) ta[i][k] = (R & pa[fa[i][k]]) + t;
            ca[i] = (ta[i][0] + ta[i][1] + ta[i][2])/3;
            ra[i] = 0;
            for (label k = 0; k < 3; ++k)
            {
                ra[i] = max(ra[i], mag(ta[i][k] - ca[i]));
            }
        }
        forAll(fb, j)
        {
            for (label k = 0; k < 3; ++k) tb[j][k] = pb[fb[j][k]];
            cb[j] = (tb[j][0] + tb[j][1] + tb[j][2])/3;
            rb[j] = 0;
            for (label k = 0; k < 3; ++k)
            {
                rb[j] = max(rb[j], mag(tb[j][k] - cb[j]));
            }
        }
        const labelList leafA(leafOfFace(A)), leafB(leafOfFace(B));
        forAll(fa, i)
        {
            forAll(fb, j)
            {
                if (mag(ca[i] - cb[j]) > ra[i] + rb[j] + band)
                {
                    continue;
                }
                if (triangleDistance(ta[i], tb[j]) <= band)
                {
                    ++n.required;
                    EXPECT_TRUE(visited.count({leafA[i], leafB[j]}))
                        << "faces " << i << ", " << j << " within band, "
                        << "leaves " << leafA[i] << ", " << leafB[j]
                        << " not visited";
                }
            }
        }
        return n;
    }
}


TEST(bodyBVH, lPrismTopologyAndFeatureEdgesClosedForm)
{
    const rbd::triMesh m(lPrism(0.5));
    const rbd::bodyBVH T(m, 2);
    checkTree(T, 2);
    checkTopology(T);

    // 20 triangles, 30 edges; feature edges (sharp and convex): the 12 cap
    // outlines and 5 of the 6 vertical edges; not the one up from the
    // reflex corner (1,1) (concave), nor the 6 side and 6 cap diagonals
    // (flat)
    EXPECT_EQ(T.edges().size(), 30);
    label features = 0;
    for (const auto& e : T.edges())
    {
        const point& a = m.points()[e.a];
        const point& b = m.points()[e.b];
        const bool vertical = a.x() == b.x() && a.y() == b.y();
        // The outline's edges are axis-aligned, the fan's diagonals not
        const bool capOutline =
            a.z() == b.z() && (a.x() == b.x() || a.y() == b.y());
        const bool reflex = vertical && a.x() == 1 && a.y() == 1;
        const bool expected = (vertical && !reflex) || capOutline;
        EXPECT_EQ(e.feature, expected) << str(a) << " " << str(b);
        features += e.feature;
    }
    EXPECT_EQ(features, 17);
}


TEST(bodyBVH, pelletMeshesTreeAndTopologyByBruteForce)
{
    for
    (
        const std::string d :
        {
            "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
            " faces 300;",
            "shape trilobe; lobeDiameter 0.004; height 0.008; faces 300;",
            "shape cylinderWithHoles; diameter 0.01; height 0.008; holes 4;"
            " holeDiameter 0.002; faces 400;"
        }
    )
    {
        autoPtr<rbd::pelletShape> s = rbd::pelletShape::New(parse(d));
        for (const label leafSize : {1, 4, 7})
        {
            SCOPED_TRACE(d + " leafSize " + std::to_string(leafSize));
            const rbd::bodyBVH T(s->mesh(), leafSize);
            checkTree(T, leafSize);
            checkTopology(T);
            // A concave pellet has concave sharp edges (bore, holes,
            // valleys between lobes), and convex ones
            label concave = 0, convex = 0;
            for (const auto& e : T.edges())
            {
                const bool sharp =
                    (T.normals()[e.f1] & T.normals()[e.f2])
                  < std::cos(rbd::bodyBVH::sharpAngle);
                if (sharp)
                {
                    (e.feature ? convex : concave) += 1;
                }
            }
            EXPECT_GT(concave, 0);
            EXPECT_GT(convex, 0);
        }
    }
}


TEST(bodyBVH, closestOnFaceAndBoxDistanceAgainstAnotherRoute)
{
    const rbd::triMesh m(lPrism(0.7));
    const rbd::bodyBVH T(m, 3);
    std::mt19937 gen(4);
    std::uniform_real_distribution<double> U(-1, 3);
    for (label k = 0; k < 2000; ++k)
    {
        const point p(U(gen), U(gen), U(gen));
        forAll(m.faces(), f)
        {
            const triFace& t = m.faces()[f];
            point ref;
            const scalar d = pointTriangleDistance
            (
                p, m.points()[t[0]], m.points()[t[1]], m.points()[t[2]], ref
            );
            const point c(T.closestOnFace(f, p));
            ASSERT_NEAR(mag(p - c), d, 1e-12) << str(p) << " face " << f;
            ASSERT_NEAR(mag(c - ref), 0, 1e-9) << str(p) << " face " << f;
        }
        forAll(T.nodes(), n)
        {
            const auto& nd = T.nodes()[n];
            const point q(min(max(p, nd.lo), nd.hi));
            ASSERT_NEAR(T.boxDistance(n, p), mag(p - q), 1e-15);
            ASSERT_NEAR(T.boxDistanceSqr(n, p), magSqr(p - q), 1e-15);
        }
    }
}


TEST(bodyBVH, descentFindsEveryPairOfFacesWithinBand)
{
    autoPtr<rbd::pelletShape> ring = rbd::pelletShape::New
    (
        parse
        (
            "shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;"
            " faces 300;"
        )
    );
    autoPtr<rbd::pelletShape> lobe = rbd::pelletShape::New
    (
        parse("shape trilobe; lobeDiameter 0.004; height 0.008; faces 300;")
    );
    const rbd::bodyBVH A(ring->mesh(), 4);
    const rbd::bodyBVH B(lobe->mesh(), 4);
    const scalar reach = ring->boundingRadius() + lobe->boundingRadius();

    std::mt19937 gen(11);
    std::uniform_real_distribution<double> U(0, 1);
    label required = 0, visited = 0, all = 0;
    for (label pose = 0; pose < 40; ++pose)
    {
        const tensor R(randomRotation(gen));
        // Centre distances from deep overlap to just beyond reach
        const scalar ct = 2*U(gen) - 1;
        const scalar st = std::sqrt(1 - ct*ct);
        const scalar phi = constant::mathematical::twoPi*U(gen);
        const vector t
        (
            (0.3 + 0.8*U(gen))*reach
           *vector(st*std::cos(phi), st*std::sin(phi), ct)
        );
        for (const scalar band : {0.0, 2e-4, 1e-3})
        {
            SCOPED_TRACE
            (
                "pose " + std::to_string(pose) + " band "
              + std::to_string(band)
            );
            const descentCount n = checkDescent(A, B, R, t, band);
            required += n.required;
            visited += n.visited;
            all += n.leafPairs;
        }
    }
    // The poses bring faces within band (the check is not empty), and the
    // descent prunes: it visits a small part of all pairs of leaves
    EXPECT_GT(required, 1000);
    EXPECT_LT(visited, all/10);
    std::cout << "pairs of faces within band " << required << ", pairs of "
        << "leaves visited " << visited << " of " << all << std::endl;

    // Beyond reach + band: nothing
    label far = 0;
    A.leafPairs
    (
        B, tensor::I, vector(reach + 2e-3, 0, 0), 1e-3,
        [&](const label, const label) { ++far; }
    );
    EXPECT_EQ(far, 0);
}

/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshContacts.H"
#include "floorSupport.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::meshContacts::clusterAngle =
    20*Foam::constant::mathematical::pi/180;

const Foam::label Foam::rbd::meshContacts::nTiers = 3;

const Foam::label Foam::rbd::meshContacts::maxKeepAll = 8;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using namespace Foam::rbd;

    //- A vertex takes part when one of its faces faces the other surface:
    //  its normal and the other's normal n are opposed at least this much
    const scalar facing = 0.05;

    //- Barycentric tolerance of "the projection falls inside the face"
    const scalar insideTol = 1e-9;

    //- Relative end tolerance of "the closest points are inside the edges"
    const scalar edgeTol = 1e-6;

    //- Normal cone tolerance (cosine) of edge/edge contacts
    const scalar coneTol = 1e-3;

    //- Edges closer to parallel than this (sine) give no edge/edge contact
    const scalar parallelSin = 1e-3;

    //- Projection of p onto the plane of triangle (a, b, c) falls inside
    bool projectsInside
    (
        const point& p,
        const point& a,
        const point& b,
        const point& c
    )
    {
        const vector v0(b - a), v1(c - a), v2(p - a);
        const scalar d00 = v0 & v0, d01 = v0 & v1, d11 = v1 & v1;
        const scalar d20 = v2 & v0, d21 = v2 & v1;
        const scalar den = d00*d11 - d01*d01;
        if (den <= VSMALL)
        {
            return false;
        }
        const scalar v = (d11*d20 - d01*d21)/den;
        const scalar w = (d00*d21 - d01*d20)/den;
        return v >= -insideTol && w >= -insideTol && v + w <= 1 + insideTol;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::point& Foam::rbd::meshContacts::moved
(
    const label p,
    const tensor& R,
    const vector& t
) const
{
    if (stamp_[p] != stampNow_)
    {
        stamp_[p] = stampNow_;
        moved_[p] = (R & bvh_.mesh().points()[p]) + t;
    }
    return moved_[p];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::meshContacts::meshContacts(const triMesh& mesh, const scalar band)
:
    bvh_(mesh),
    band_(band),
    depth_(band),
    radius_(mesh.boundingRadius()),
    mergeDistance_(1e-3*mesh.boundingRadius()),
    moved_(mesh.nPoints()),
    stamp_(mesh.nPoints(), -1),
    stampNow_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::meshContacts::meshMesh
(
    const label i,
    const rigidBody& bi,
    const label k,
    const rigidBody& bk,
    DynamicList<contact>& contacts
) const
{
    const label start = contacts.size();

    // Pose of i in the frame of k: p_k = R p_i + t
    const tensor& Rk = bk.R();
    const tensor R(Rk.T() & bi.R());
    const vector t(Rk.T() & (bi.x() - bk.x()));
    ++stampNow_;

    const pointField& pts = bvh_.mesh().points();
    const List<triFace>& fs = bvh_.mesh().faces();
    const vectorField& nf = bvh_.normals();
    const List<bodyBVH::edgeInfo>& es = bvh_.edges();
    const labelListList& pf = bvh_.pointFaces();
    const List<bodyBVH::node>& nodes = bvh_.nodes();
    const labelList& order = bvh_.order();

    const vector wi(bi.omega());
    const vector wk(bk.omega());

    // Bounding spheres apart by more than the band: nothing to find
    if (magSqr(bi.x() - bk.x()) >= sqr(2*radius_ + band_))
    {
        return;
    }

    // A feature pair may be met in several leaf pairs (a point or an edge
    // shared by two leaves): the duplicate contacts coincide, and reduce()
    // keeps one of them (it drops points within mergeDistance of a kept
    // one), which is cheaper than remembering the pairs seen

    // World contact from a point on i (pI) and one on k (pK), frame of k,
    // with the normal nK (frame of k) and its rate nDot (world)
    // key: the vertex of a vertex contact (points of k offset by nPoints),
    // -1 for edge/edge
    const label nPts = pts.size();
    std::vector<label>& keys = keys_;
    keys.clear();
    auto add = [&]
    (
        const point& pI, const point& pK, const vector& nK,
        const scalar gap, const vector& nDot, const label key
    )
    {
        keys.push_back(key);
        const point pIw((Rk & pI) + bk.x());
        const point pKw((Rk & pK) + bk.x());
        contact c;
        c.i = i;
        c.k = k;
        c.n = (Rk & nK);
        c.gap = gap;
        c.p = 0.5*(pIw + pKw);
        c.nDot = nDot;
        c.e = 0;
        c.mu = 0;
        c.centreBased = false;
        c.ri = pIw - bi.x();
        c.rk = pKw - bk.x();
        contacts.append(c);
    };

    // Separating axes of two local patches, as the convex hulls of their
    // faces' corners: faces fA of the body in pose (RA, tA) and fB of the
    // body in pose (RB, tB), frame of k; axes: the faces' normals and the
    // cross products of their edges. Returns the least overlap of their
    // projections (< 0: apart), or any value below floor once one is.
    // Patches stand in for the bodies near a contact: for a convex body
    // this is the minimum translation distance there; a nonconvex body's
    // patch hull is larger than the body, so the overlap is never less.
    auto patchOverlap = [&]
    (
        const DynamicList<label>& fA, const tensor& RA, const vector& tA,
        const DynamicList<label>& fB, const tensor& RB, const vector& tB,
        const scalar floor
    )
    {
        auto project = [&]
        (
            const DynamicList<label>& fl, const tensor& RR, const vector& tt,
            const vector& u, scalar& lo, scalar& hi
        )
        {
            lo = GREAT;
            hi = -GREAT;
            for (const label f : fl)
            {
                for (const label c : fs[f])
                {
                    const scalar x = ((RR & pts[c]) + tt) & u;
                    lo = min(lo, x);
                    hi = max(hi, x);
                }
            }
        };
        scalar least = GREAT;
        auto along = [&](const vector& axis)
        {
            const scalar m = mag(axis);
            if (m < 1e-9)
            {
                return false;
            }
            const vector u(axis/m);
            scalar loA, hiA, loB, hiB;
            project(fA, RA, tA, u, loA, hiA);
            project(fB, RB, tB, u, loB, hiB);
            least = min(least, min(hiA - loB, hiB - loA));
            return least < floor;
        };
        for (const label f : fA)
        {
            if (along(RA & nf[f]))
            {
                return least;
            }
        }
        for (const label f : fB)
        {
            if (along(RB & nf[f]))
            {
                return least;
            }
        }
        for (const label f : fA)
        {
            for (label ea = 0; ea < 3; ++ea)
            {
                vector da
                (
                    RA & (pts[fs[f][(ea + 1) % 3]] - pts[fs[f][ea]])
                );
                da /= max(mag(da), VSMALL);
                for (const label g : fB)
                {
                    for (label eb = 0; eb < 3; ++eb)
                    {
                        vector db
                        (
                            RB & (pts[fs[g][(eb + 1) % 3]] - pts[fs[g][eb]])
                        );
                        db /= max(mag(db), VSMALL);
                        if (along(da ^ db))
                        {
                            return least;
                        }
                    }
                }
            }
        }
        return least;
    };

    // The faces around points a and b (b < 0: a only), each once
    auto facesAround = [&]
    (
        const label a, const label b, DynamicList<label>& patch
    )
    {
        patch.clear();
        for (const label c : {a, b})
        {
            if (c < 0)
            {
                continue;
            }
            for (const label g : pf[c])
            {
                if (!patch.found(g))
                {
                    patch.append(g);
                }
            }
        }
    };

    // A contact deeper than this is checked against the separating axes of
    // the patches around its features (patchOverlap) [m] ...
    const scalar checkDepth = 1e-2*band_;

    // ... and dropped if they overlap by less than this part of its depth:
    // the contact overstates the interpenetration (its normal is not the
    // direction of least interpenetration), and a shallower contact holds
    // the pair (the rim of a Raschig ring resting 1 um deep on another's
    // cap, passing 0.7 mm from a side edge of the other's wall just below
    // its top, was seen 0.7 mm deep along a horizontal normal, and the
    // overlap correction pushed the rings 0.7 mm sideways)
    const scalar overstated = 0.9;

    // A vertex behind the plane of the face it projects onto: is the face
    // the contact? At an acute edge (a tetrahedron's, 70.5 degrees) a
    // vertex outside the other body, in front of a face around f that
    // meets it convexly (f's corners behind its plane), can be behind the
    // plane of f and project into it (a tetrahedron's tip 0.6 mm from
    // another was reported 0.6 mm deep). Yet a vertex in front of that
    // face can be a real contact: the other body's edge cuts through the
    // vertex's corner (rejecting those missed tetrahedra 0.03 mm into each
    // other). So: such a vertex, or one deeper than checkDepth, is dropped
    // if its faces and the faces around f are apart, or overlap by less
    // than overstated times its depth. Vertex v of the body in pose (Rv,
    // tv), face f of the body in pose (RR, tt), depth [m], frame of k.
    DynamicList<label> patchA, patchB;
    auto separated = [&]
    (
        const label v, const tensor& Rv, const vector& tv,
        const label f, const tensor& RR, const vector& tt,
        const scalar depth
    )
    {
        const triFace& tf = fs[f];
        const scalar tol = 1e-9*radius_;
        const point p((Rv & pts[v]) + tv);
        bool inFront = false;
        for (const label c : tf)
        {
            for (const label g : pf[c])
            {
                if (g == f || inFront)
                {
                    continue;
                }
                const vector ng(RR & nf[g]);
                const point o((RR & pts[fs[g][0]]) + tt);
                if (((p - o) & ng) <= tol)
                {
                    continue;
                }
                bool convex = true;
                for (const label w : tf)
                {
                    if ((((RR & pts[w]) + tt - o) & ng) > tol)
                    {
                        convex = false;
                        break;
                    }
                }
                inFront = convex;
            }
        }
        const bool deep = depth > checkDepth;
        if (!inFront && !deep)
        {
            return false;
        }
        facesAround(v, -1, patchA);
        patchB.clear();
        for (const label c : tf)
        {
            for (const label g : pf[c])
            {
                if (!patchB.found(g))
                {
                    patchB.append(g);
                }
            }
        }
        const scalar least = deep ? overstated*depth : 0;
        return patchOverlap(patchA, Rv, tv, patchB, RR, tt, least) < least;
    };

    // Vertex v of i over face f of k
    auto vertexOfI = [&](const label v, const point& p, const label f)
    {
        const triFace& tf = fs[f];
        const vector& n = nf[f];
        const scalar s = (p - pts[tf[0]]) & n;
        if (s >= band_ || s <= -depth_)
        {
            return;
        }
        if (!projectsInside(p, pts[tf[0]], pts[tf[1]], pts[tf[2]]))
        {
            return;
        }
        bool faces = false;
        for (const label g : pf[v])
        {
            if (((R & nf[g]) & n) < -facing)
            {
                faces = true;
                break;
            }
        }
        if (!faces || (s < 0 && separated(v, R, t, f, tensor::I, Zero, -s)))
        {
            return;
        }
        const vector nW(Rk & n);
        add(p, p - s*n, n, s, wk ^ nW, v);
    };

    // Vertex v of k over face f of i
    auto vertexOfK = [&](const label v, const point& p, const label f)
    {
        const triFace& tf = fs[f];
        const point& a = moved(tf[0], R, t);
        const vector n(R & nf[f]);
        const scalar s = (p - a) & n;
        if (s >= band_ || s <= -depth_)
        {
            return;
        }
        if
        (
           !projectsInside(p, a, moved(tf[1], R, t), moved(tf[2], R, t))
        )
        {
            return;
        }
        bool faces = false;
        for (const label g : pf[v])
        {
            if ((nf[g] & n) < -facing)
            {
                faces = true;
                break;
            }
        }
        if (!faces || (s < 0 && separated(v, tensor::I, Zero, f, R, t, -s)))
        {
            return;
        }
        const vector nW(Rk & -n);
        add(p - s*n, p, -n, s, wi ^ nW, nPts + v);
    };

    // Edge ei of i against edge ek of k
    auto edgeEdge = [&](const label ei, const label ek)
    {
        const bodyBVH::edgeInfo& eI = es[ei];
        const bodyBVH::edgeInfo& eK = es[ek];
        const point& p1 = moved(eI.a, R, t);
        const vector d1(moved(eI.b, R, t) - p1);
        const point& p2 = pts[eK.a];
        const vector d2(pts[eK.b] - p2);

        const vector cr(d1 ^ d2);
        const scalar crMag = mag(cr);
        const scalar a = d1 & d1;
        const scalar e = d2 & d2;
        if (crMag <= parallelSin*Foam::sqrt(a*e))
        {
            return;
        }

        // Closest points of the two lines (Ericson 2005, section 5.1.9)
        const vector r(p1 - p2);
        const scalar b = d1 & d2;
        const scalar c = d1 & r;
        const scalar f = d2 & r;
        const scalar den = a*e - b*b;
        const scalar s = (b*f - c*e)/den;
        const scalar u = (a*f - b*c)/den;
        if (s <= edgeTol || s >= 1 - edgeTol || u <= edgeTol || u >= 1 - edgeTol)
        {
            return;
        }

        // Normal from k to i: out of k's edge, in both normal cones
        vector n(cr/crMag);
        scalar sign = 1;
        if ((n & eK.outward) < 0)
        {
            n = -n;
            sign = -1;
        }
        if ((n & eK.u1) > coneTol || (n & eK.u2) > coneTol)
        {
            return;
        }
        if (((R & eI.u1) & -n) > coneTol || ((R & eI.u2) & -n) > coneTol)
        {
            return;
        }

        const point cI(p1 + s*d1);
        const point cK(p2 + u*d2);
        const scalar gap = (cI - cK) & n;
        if (gap >= band_ || gap <= -depth_)
        {
            return;
        }

        // Crossing edges (gap < 0). With n in both normal cones each edge
        // is the other body's extreme feature along n, so -gap is the
        // overlap of the two bodies' projections on n: the depth along n,
        // at least the true depth, and no depth at all when another axis
        // separates them. Two checks against the faces near the edges:
        // 1. separating faces: a face of an edge separates the bodies when
        //    the other edge's faces (its local vertices) are all in front
        //    of its plane (a vertex of a tetrahedron sliding down the side
        //    of another was seen 0.8 band deep at its bottom edge while 0.2
        //    band outside the side face);
        // 2. deeper than checkDepth, the patches around the two edges
        //    (the faces around their ends) must overlap by overstated
        //    times the depth: along another axis the bodies separate
        //    sooner, and the depth along n overstates (patchOverlap).
        // Not asked: that the closest points are inside the other body.
        // At an acute edge (a tetrahedron's, 70.5 degrees) the closest
        // point may be in front of the other edge's face while the edges
        // cross (rejecting those let tetrahedra sink 0.6 mm into each
        // other unseen), and near the end of an edge it may be outside the
        // face there while the edge cuts off the other's corner.
        if (gap < 0)
        {
            // The vertices of the faces of edge e (pose RR, tt) all in
            // front of the plane (o, m): that plane separates
            auto inFront = [&]
            (
                const bodyBVH::edgeInfo& e, const tensor& RR,
                const vector& tt, const point& o, const vector& m
            )
            {
                for (const label f : {e.f1, e.f2})
                {
                    for (const label v : fs[f])
                    {
                        if ((((RR & pts[v]) + tt - o) & m) < 0)
                        {
                            return false;
                        }
                    }
                }
                return true;
            };
            for (const label f : {eK.f1, eK.f2})
            {
                if (inFront(eI, R, t, pts[fs[f][0]], nf[f]))
                {
                    return;
                }
            }
            for (const label f : {eI.f1, eI.f2})
            {
                if
                (
                    inFront
                    (
                        eK, tensor::I, Zero, moved(fs[f][0], R, t),
                        R & nf[f]
                    )
                )
                {
                    return;
                }
            }

            // 2. the patches around both edges overlap by the depth
            if (-gap > checkDepth)
            {
                facesAround(eI.a, eI.b, patchA);
                facesAround(eK.a, eK.b, patchB);
                const scalar least = -overstated*gap;
                if
                (
                    patchOverlap(patchA, R, t, patchB, tensor::I, Zero, least)
                  < least
                )
                {
                    return;
                }
            }
        }

        // n' from the rotation of both edges (world frame)
        const vector d1w(Rk & d1);
        const vector d2w(Rk & d2);
        const vector crW(Rk & cr);
        const vector crDot(((wi ^ d1w) ^ d2w) + (d1w ^ (wk ^ d2w)));
        const vector hat(crW/crMag);
        const vector nDot(sign*(crDot - hat*(hat & crDot))/crMag);

        add(cI, cK, n, gap, nDot, -1);
    };

    // A vertex p of one body (neighbour points q, frame of k) against a
    // feature edge (a, d, cone u1, u2, face normals n1, n2) of the other,
    // the closest point inside the edge: n = +-(p - c)/|p - c| out of the
    // edge, in the edge's normal cone, the vertex extreme along -n
    auto vertexEdge =
    [&](const point& p, const labelList& faces, const bool onI,
        const bodyBVH::edgeInfo& eInfo,
        const point& a, const vector& d, const vector& u1, const vector& u2,
        const vector& n1, const vector& n2, point& c, vector& n, scalar& gap)
    {
        const scalar dd = d & d;
        const scalar s = ((p - a) & d)/dd;
        if (s <= edgeTol || s >= 1 - edgeTol)
        {
            return false;
        }
        c = a + s*d;
        const vector r(p - c);
        const scalar dist = mag(r);
        if (dist >= band_ || dist <= VSMALL)
        {
            return false;
        }
        n = r/dist;
        gap = dist;
        // Inside: behind the planes of both faces of the edge (not just
        // against its mean outward direction: at an acute edge, 70.5
        // degrees for a tetrahedron, a point in front of one face can be
        // against it, and a vertex outside was reported 0.5 mm deep)
        if ((r & n1) < 0 && (r & n2) < 0)
        {
            n = -n;
            gap = -dist;
            if (dist >= depth_)
            {
                return false;
            }
        }
        if ((n & u1) > coneTol || (n & u2) > coneTol)
        {
            return false;
        }
        for (const label f : faces)
        {
            for (const label w : fs[f])
            {
                const point q(onI ? moved(w, R, t) : pts[w]);
                const vector e(q - p);
                if ((e & n) < -coneTol*mag(e))
                {
                    return false;
                }
            }
        }
        // Inside, deeper than checkDepth: the patches around the vertex
        // and the edge must overlap by the depth (a vertex behind both
        // faces of a tetrahedron's edge but beyond a third one, outside,
        // was reported 0.5 mm deep)
        if (gap < 0 && dist > checkDepth)
        {
            patchA.clear();
            patchA.append(faces);
            facesAround(eInfo.a, eInfo.b, patchB);
            const scalar least = overstated*dist;
            const scalar ov =
                onI
              ? patchOverlap(patchA, R, t, patchB, tensor::I, Zero, least)
              : patchOverlap(patchA, tensor::I, Zero, patchB, R, t, least);
            if (ov < least)
            {
                return false;
            }
        }
        return true;
    };

    // The points and feature edges of a pair of leaves that can come within
    // the band of the other leaf, the edges with their boxes (frame of k)
    // grown by half the band: two features with disjoint grown boxes are
    // more than the band apart, and every contact joins features closer
    // than the band (its gap lies in (-depth, band), depth = band), so the
    // tests below skip such pairs without changing what is found. Most
    // pairs of edges of two touching leaves are such pairs: their closest
    // points lie outside the edges, which edgeEdge finds only after the
    // lines' closest points (these filters halved the narrow phase of 80-
    // face spheres)
    std::vector<segmentBox>& edgesI = edgesI_;
    std::vector<segmentBox>& edgesK = edgesK_;
    std::vector<label>& pointsI = pointsI_;
    std::vector<label>& pointsK = pointsK_;
    const scalar halfBand = 0.5*band_;
    auto grownBox = [halfBand](const point& a, const point& b)
    {
        segmentBox sb;
        sb.lo = min(a, b) - vector::uniform(halfBand);
        sb.hi = max(a, b) + vector::uniform(halfBand);
        return sb;
    };
    auto apart = [](const segmentBox& x, const segmentBox& y)
    {
        for (direction j = 0; j < 3; ++j)
        {
            if (x.lo[j] > y.hi[j] || y.lo[j] > x.hi[j])
            {
                return true;
            }
        }
        return false;
    };
    auto outside = [halfBand](const segmentBox& x, const point& p)
    {
        for (direction j = 0; j < 3; ++j)
        {
            if (p[j] < x.lo[j] - halfBand || p[j] > x.hi[j] + halfBand)
            {
                return true;
            }
        }
        return false;
    };

    bvh_.leafPairs
    (
        bvh_, R, t, band_,
        [&](const label li, const label lk)
        {
            const bodyBVH::node& ni = nodes[li];
            const bodyBVH::node& nk = nodes[lk];
            const point ci((R & ni.centre) + t);

            // Edges of i near k's leaf box, edges of k near i's leaf sphere
            segmentBox grownLeafK;
            grownLeafK.lo = nk.lo - vector::uniform(halfBand);
            grownLeafK.hi = nk.hi + vector::uniform(halfBand);
            edgesI.clear();
            for (const label ei : bvh_.leafEdges(li))
            {
                const bodyBVH::edgeInfo& e = es[ei];
                segmentBox sb(grownBox(moved(e.a, R, t), moved(e.b, R, t)));
                sb.edge = ei;
                if (!apart(sb, grownLeafK))
                {
                    edgesI.push_back(sb);
                }
            }
            edgesK.clear();
            for (const label ek : bvh_.leafEdges(lk))
            {
                const bodyBVH::edgeInfo& e = es[ek];
                const point& a = pts[e.a];
                const vector d(pts[e.b] - a);
                const scalar s =
                    min(max(((ci - a) & d)/max(d & d, VSMALL), 0.0), 1.0);
                if (magSqr(a + s*d - ci) < sqr(ni.radius + band_))
                {
                    segmentBox sb(grownBox(a, pts[e.b]));
                    sb.edge = ek;
                    edgesK.push_back(sb);
                }
            }

            // Points of i's leaf near k's leaf box, over k's faces
            pointsI.clear();
            for (const label v : bvh_.leafPoints(li))
            {
                const point& p = moved(v, R, t);
                if (bvh_.boxDistanceSqr(lk, p) >= sqr(band_))
                {
                    continue;
                }
                pointsI.push_back(v);
                for (label b = nk.first; b < nk.first + nk.count; ++b)
                {
                    vertexOfI(v, p, order[b]);
                }
            }

            // Points of k's leaf near i's leaf (its sphere), over i's faces
            pointsK.clear();
            for (const label v : bvh_.leafPoints(lk))
            {
                const point& p = pts[v];
                if (magSqr(p - ci) >= sqr(ni.radius + band_))
                {
                    continue;
                }
                pointsK.push_back(v);
                for (label a = ni.first; a < ni.first + ni.count; ++a)
                {
                    vertexOfK(v, p, order[a]);
                }
            }

            for (const segmentBox& sI : edgesI)
            {
                for (const segmentBox& sK : edgesK)
                {
                    if (!apart(sI, sK))
                    {
                        edgeEdge(sI.edge, sK.edge);
                    }
                }
            }

            // Vertices against edges (a vertex near an edge projects onto
            // neither face; parallel edges give no edge/edge contact)
            point cE;
            vector nE;
            scalar gE;
            for (const label v : pointsI)
            {
                const point& p = moved(v, R, t);
                for (const segmentBox& sK : edgesK)
                {
                    if (outside(sK, p))
                    {
                        continue;
                    }
                    const bodyBVH::edgeInfo& e = es[sK.edge];
                    if
                    (
                        vertexEdge
                        (
                            p, pf[v], true, e, pts[e.a], pts[e.b] - pts[e.a],
                            e.u1, e.u2, nf[e.f1], nf[e.f2], cE, nE, gE
                        )
                    )
                    {
                        add(p, cE, nE, gE, wk ^ (Rk & nE), v);
                    }
                }
            }
            for (const label v : pointsK)
            {
                const point& p = pts[v];
                for (const segmentBox& sI : edgesI)
                {
                    if (outside(sI, p))
                    {
                        continue;
                    }
                    const bodyBVH::edgeInfo& e = es[sI.edge];
                    const point& a = moved(e.a, R, t);
                    if
                    (
                        vertexEdge
                        (
                            p, pf[v], false, e, a, moved(e.b, R, t) - a,
                            R & e.u1, R & e.u2, R & nf[e.f1], R & nf[e.f2],
                            cE, nE, gE
                        )
                    )
                    {
                        // Normal out of i's edge: from k to i is -nE
                        add(cE, p, -nE, gE, wi ^ (Rk & -nE), nPts + v);
                    }
                }
            }
        }
    );

    // Spurious depths. A vertex is as far from the other body as its
    // nearest contact; a contact that puts it deeper inside than that
    // measures the depth to a face or an edge it is not closest to (a
    // vertex of a rim on another pellet's bottom face is far inside the
    // plane of that pellet's wall, onto which it projects at its lower
    // edge): drop it. Such contacts made impacts look up to the band deep
    // (maxOverlap), and the overlap correction and the impulses then
    // pushed the pellets sideways along the wrong normal.
    if (nearest_.size() != size_t(2*nPts))
    {
        nearest_.assign(2*nPts, GREAT);
    }
    for (label a = start; a < contacts.size(); ++a)
    {
        const label key = keys[a - start];
        if (key >= 0 && mag(contacts[a].gap) < mag(nearest_[key]))
        {
            nearest_[key] = contacts[a].gap;
        }
    }
    label j = start;
    for (label a = start; a < contacts.size(); ++a)
    {
        const label key = keys[a - start];
        const scalar gap = contacts[a].gap;
        if (key >= 0 && -gap > mag(nearest_[key]))
        {
            continue;
        }
        if (j != a)
        {
            contacts[j] = contacts[a];
        }
        ++j;
    }
    for (label a = start; a < contacts.size(); ++a)
    {
        const label key = keys[a - start];
        if (key >= 0)
        {
            nearest_[key] = GREAT;
        }
    }
    contacts.setSize(j);

    reduce(contacts, start, mergeDistance_, 0.1*band_);
}


void Foam::rbd::meshContacts::meshTube
(
    const label i,
    const rigidBody& bi,
    const tube& container,
    DynamicList<contact>& contacts
) const
{
    const tensor& Ri = bi.R();
    const point& x = bi.x();
    const scalar Rt = container.radius();
    const List<bodyBVH::node>& nodes = bvh_.nodes();
    const labelList& order = bvh_.order();
    const List<triFace>& fs = bvh_.mesh().faces();

    if (nodes.empty())
    {
        return;
    }
    const scalar rb = nodes[0].radius;
    const bool nearBottom = x.z() - rb < band_;
    const bool nearWall = tube::axialDistance(x) + rb > Rt - band_;
    if (!nearBottom && !nearWall)
    {
        return;
    }

    ++stampNow_;
    DynamicList<label> bottomPts, wallPts;
    DynamicList<label> stack(32);
    stack.append(0);
    while (stack.size())
    {
        const bodyBVH::node& nd = nodes[stack.remove()];
        const point c((Ri & nd.centre) + x);
        const bool bottom = nearBottom && c.z() - nd.radius < band_;
        const bool wall =
            nearWall && tube::axialDistance(c) + nd.radius > Rt - band_;
        if (!bottom && !wall)
        {
            continue;
        }
        if (!nd.leaf())
        {
            stack.append(nd.left);
            stack.append(nd.right);
            continue;
        }
        for (label a = nd.first; a < nd.first + nd.count; ++a)
        {
            for (const label v : fs[order[a]])
            {
                if (stamp_[v] == stampNow_)
                {
                    continue;
                }
                const point& p = moved(v, Ri, x);
                if (p.z() < band_)
                {
                    bottomPts.append(v);
                }
                if (Rt - tube::axialDistance(p) < band_)
                {
                    wallPts.append(v);
                }
            }
        }
    }

    label start = contacts.size();
    for (const label v : bottomPts)
    {
        const point& p = moved_[v];
        if (p.z() <= -depth_)
        {
            continue;
        }
        contact c;
        c.i = i;
        c.k = tubeBottom;
        c.n = vector(0, 0, 1);
        c.gap = p.z();
        c.p = point(p.x(), p.y(), 0.5*p.z());
        c.nDot = Zero;
        c.e = container.restitution();
        c.mu = container.friction();
        c.centreBased = false;
        c.ri = p - x;
        c.rk = point(p.x(), p.y(), 0);
        contacts.append(c);
    }
    {
        // The corners of the support, and the points one step can bring
        // down beside them (floorSupport)
        const std::vector<contact> all
        (
            contacts.begin() + start, contacts.end()
        );
        reduce(contacts, start, mergeDistance_, 0.1*band_);
        floorSupport::addNear
        (
            all, floorNearSpan*band_, mergeDistance_, start, contacts
        );
    }

    start = contacts.size();
    for (const label v : wallPts)
    {
        const point& p = moved_[v];
        const scalar rho = tube::axialDistance(p);
        const scalar gap = Rt - rho;
        if (gap <= -depth_ || rho < VSMALL)
        {
            continue;
        }
        const vector er(p.x()/rho, p.y()/rho, 0);
        contact c;
        c.i = i;
        c.k = tubeWall;
        c.n = -er;
        c.gap = gap;
        c.p = p + 0.5*gap*er;
        c.nDot = Zero;
        c.e = container.restitution();
        c.mu = container.friction();
        c.centreBased = false;
        c.ri = p - x;
        c.rk = p + gap*er;
        contacts.append(c);
    }
    reduce(contacts, start, mergeDistance_, 0.1*band_);
}


void Foam::rbd::meshContacts::sphereMesh
(
    const label i,
    const rigidBody& bi,
    const scalar a,
    const label k,
    const rigidBody& bk,
    DynamicList<contact>& contacts
) const
{
    const tensor& Rk = bk.R();
    const point c(Rk.T() & (bi.x() - bk.x()));
    const List<bodyBVH::node>& nodes = bvh_.nodes();
    const labelList& order = bvh_.order();
    const vectorField& nf = bvh_.normals();
    const scalar reach = a + band_;

    // Closest points of the faces within reach, outside the mesh
    struct candidate
    {
        scalar dist;
        point q;
        vector n;
    };
    std::vector<candidate> found;

    DynamicList<label> stack(32);
    if (nodes.size())
    {
        stack.append(0);
    }
    while (stack.size())
    {
        const label ni = stack.remove();
        if (bvh_.boxDistance(ni, c) > reach)
        {
            continue;
        }
        const bodyBVH::node& nd = nodes[ni];
        if (!nd.leaf())
        {
            stack.append(nd.left);
            stack.append(nd.right);
            continue;
        }
        for (label j = nd.first; j < nd.first + nd.count; ++j)
        {
            const label f = order[j];
            const point q(bvh_.closestOnFace(f, c));
            const vector d(c - q);
            const scalar dist = mag(d);
            if (dist >= reach || dist <= a - depth_)
            {
                continue;
            }
            if ((d & nf[f]) <= 0)
            {
                // Centre behind the face: inside or at the back of it
                continue;
            }
            found.push_back({dist, q, dist > VSMALL ? d/dist : nf[f]});
        }
    }

    // The nearest point of every group of directions
    std::sort
    (
        found.begin(), found.end(),
        [](const candidate& x, const candidate& y) { return x.dist < y.dist; }
    );
    const scalar cosGroup = Foam::cos(0.25*constant::mathematical::pi);
    std::vector<candidate> kept;
    for (const candidate& cd : found)
    {
        bool near = false;
        for (const candidate& kd : kept)
        {
            if ((kd.n & cd.n) > cosGroup)
            {
                near = true;
                break;
            }
        }
        if (!near)
        {
            kept.push_back(cd);
        }
    }

    for (const candidate& cd : kept)
    {
        const vector n(Rk & cd.n);
        const point qW((Rk & cd.q) + bk.x());
        contact ct;
        ct.i = i;
        ct.k = k;
        ct.n = n;
        ct.gap = cd.dist - a;
        ct.p = qW + 0.5*ct.gap*n;
        ct.nDot = (bk.omega() ^ n);
        ct.e = 0;
        ct.mu = 0;
        ct.centreBased = false;
        ct.ri = -a*n;
        ct.rk = qW - bk.x();
        contacts.append(ct);
    }
}


Foam::scalar Foam::rbd::meshContacts::gap
(
    const contact& c,
    const UList<rigidBody>& bodies,
    const tube& container
)
{
    const point pI(bodies[c.i].x() + c.ri);
    if (c.k == tubeBottom)
    {
        return pI.z();
    }
    if (c.k == tubeWall)
    {
        return container.radius() - tube::axialDistance(pI);
    }
    return c.n & (pI - bodies[c.k].x() - c.rk);
}


void Foam::rbd::meshContacts::reduce
(
    DynamicList<contact>& contacts,
    const label start,
    const scalar mergeDistance,
    const scalar tier,
    const label keepAll,
    const label laterCorners
)
{
    const label n = contacts.size() - start;
    if (n <= 1)
    {
        return;
    }

    // Deepest first
    std::vector<contact> cs(contacts.begin() + start, contacts.end());
    std::stable_sort
    (
        cs.begin(), cs.end(),
        [](const contact& x, const contact& y) { return x.gap < y.gap; }
    );

    // Groups of normals
    const scalar cosGroup = Foam::cos(clusterAngle);
    std::vector<std::vector<label>> groups;
    for (label a = 0; a < n; ++a)
    {
        bool placed = false;
        for (auto& g : groups)
        {
            if ((cs[g.front()].n & cs[a].n) > cosGroup)
            {
                g.push_back(a);
                placed = true;
                break;
            }
        }
        if (!placed)
        {
            groups.push_back({a});
        }
    }

    contacts.setSize(start);
    std::vector<label> level;
    std::vector<label> kept;
    for (const auto& g : groups)
    {
        const vector& nG = cs[g.front()].n;
        const scalar g0 = cs[g.front()].gap;
        kept.clear();

        // Tangential position relative to the group's deepest point
        const point& pG = cs[g.front()].p;
        auto tang = [&](const label a)
        {
            const vector d(cs[a].p - pG);
            return d - nG*(nG & d);
        };

        for (label t = 0; t < (tier > 0 ? nTiers : 1); ++t)
        {
            // The points of this tier of gaps (g is sorted by gap)
            level.clear();
            for (const label a : g)
            {
                const scalar above = cs[a].gap - g0;
                if (above >= t*tier && (above < (t + 1)*tier || tier <= 0))
                {
                    level.push_back(a);
                }
            }
            if (level.empty())
            {
                continue;
            }

            // The corners of the tier
            const label first = kept.size();
            auto corners = [&]()
            {
                const vector o(tang(level.front()));
                auto rel = [&](const label a) { return tang(a) - o; };

                // 1. the deepest point
                kept.push_back(level.front());

                // 2. the farthest from it
                label a1 = -1;
                scalar best = mergeDistance;
                for (const label a : level)
                {
                    const scalar d = mag(rel(a));
                    if (d > best)
                    {
                        best = d;
                        a1 = a;
                    }
                }
                if (a1 < 0)
                {
                    return;
                }
                kept.push_back(a1);
                if (t > 0 && laterCorners <= 2)
                {
                    return;
                }
                const vector e1(rel(a1));

                // 3. the largest triangle
                label a2 = -1;
                best = mergeDistance*mag(e1);
                vector side(Zero);
                for (const label a : level)
                {
                    const vector cr(e1 ^ rel(a));
                    const scalar area = mag(cr);
                    if (area > best)
                    {
                        best = area;
                        a2 = a;
                        side = cr;
                    }
                }
                if (a2 < 0)
                {
                    return;
                }
                kept.push_back(a2);

                // 4. the largest area added outside the triangle (0, 1, 2)
                const vector corner[3] = {Zero, e1, rel(a2)};
                const vector up(side/mag(side));
                label a3 = -1;
                best = mergeDistance*mag(e1);
                for (const label a : level)
                {
                    const vector q(rel(a));
                    for (label j = 0; j < 3; ++j)
                    {
                        const vector& u = corner[j];
                        const vector& w = corner[(j + 1) % 3];
                        // Positive when q lies outside edge (u, w)
                        const scalar area = -(((w - u) ^ (q - u)) & up);
                        if (area > best)
                        {
                            best = area;
                            a3 = a;
                        }
                    }
                }
                if (a3 >= 0)
                {
                    kept.push_back(a3);
                }
            };
            corners();

            // The points of the first tier within a fifth of the tier of
            // the deepest are all kept, up to maxKeepAll: next to a point of
            // support, a curved or tilted support (the rim of a polygonal
            // cylinder rolling or rocking on a plane) has points about to
            // touch that are not corners of the tier (rim vertices inside
            // the rim's plane); dropped, each landed unseen up to 10 um
            // deep, and the overlap correction that lifted it out kept the
            // cylinder rolling. More of them: a flat patch, whose corners
            // hold it.
            // Not those between kept ones (tangentially) and not below the
            // gap interpolated from them, which a rigid motion cannot
            // bring to touch first (the middle of a line of support).
            auto covered = [&](const label a)
            {
                const vector x(tang(a));
                const scalar ga = cs[a].gap + 1e-9*tier;
                const label nK = kept.size();
                for (label j = 0; j < nK; ++j)
                {
                    const vector xj(tang(kept[j]));
                    const scalar gj = cs[kept[j]].gap;
                    if (mag(x - xj) <= mergeDistance)
                    {
                        return true;
                    }
                    for (label l = j + 1; l < nK; ++l)
                    {
                        const vector xl(tang(kept[l]));
                        const scalar gl = cs[kept[l]].gap;
                        const vector d(xl - xj);
                        const scalar u = ((x - xj) & d)/max(magSqr(d), VSMALL);
                        if
                        (
                            u >= 0 && u <= 1
                         && mag(x - xj - u*d) <= mergeDistance
                         && ga >= gj + u*(gl - gj)
                        )
                        {
                            return true;
                        }
                        for (label m = l + 1; m < nK; ++m)
                        {
                            const vector xm(tang(kept[m]));
                            const vector cr(d ^ (xm - xj));
                            const scalar area2 = magSqr(cr);
                            if (area2 <= sqr(sqr(mergeDistance)))
                            {
                                continue;
                            }
                            // Barycentric coordinates of x in (j, l, m)
                            const scalar bl =
                                (((x - xj) ^ (xm - xj)) & cr)/area2;
                            const scalar bm = ((d ^ (x - xj)) & cr)/area2;
                            const scalar bj = 1 - bl - bm;
                            if
                            (
                                bj >= 0 && bl >= 0 && bm >= 0
                             && ga >= bj*gj + bl*gl + bm*cs[kept[m]].gap
                            )
                            {
                                return true;
                            }
                        }
                    }
                }
                return false;
            };
            label nNear = 0;
            for (const label a : level)
            {
                nNear += cs[a].gap - cs[level.front()].gap < 0.2*tier;
            }
            if (t == 0 && nNear <= keepAll)
            {
                for (const label a : level)
                {
                    if (cs[a].gap - cs[level.front()].gap >= 0.2*tier)
                    {
                        break;
                    }
                    if (!covered(a))
                    {
                        kept.push_back(a);
                    }
                }
            }

            for (size_t j = first; j < kept.size(); ++j)
            {
                contacts.append(cs[kept[j]]);
            }
        }
    }
}


// ************************************************************************* //

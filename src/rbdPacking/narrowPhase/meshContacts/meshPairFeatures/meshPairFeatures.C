/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshPairFeatures.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

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

    //- Boxes x and y are disjoint
    template<class Box>
    bool apart(const Box& x, const Box& y)
    {
        for (direction j = 0; j < 3; ++j)
        {
            if (x.lo[j] > y.hi[j] || y.lo[j] > x.hi[j])
            {
                return true;
            }
        }
        return false;
    }

    //- Point p is outside box x grown by margin
    template<class Box>
    bool outside(const Box& x, const point& p, const scalar margin)
    {
        for (direction j = 0; j < 3; ++j)
        {
            if (p[j] < x.lo[j] - margin || p[j] > x.hi[j] + margin)
            {
                return true;
            }
        }
        return false;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rbd::meshPairFeatures::add
(
    const point& pI,
    const point& pK,
    const vector& nK,
    const scalar gap,
    const vector& nDot,
    const label key
)
{
    const tensor& Rk = bk_->R();
    keys_.push_back(key);
    const point pIw((Rk & pI) + bk_->x());
    const point pKw((Rk & pK) + bk_->x());
    contact c;
    c.i = i_;
    c.k = k_;
    c.n = (Rk & nK);
    c.gap = gap;
    c.p = 0.5*(pIw + pKw);
    c.nDot = nDot;
    c.e = 0;
    c.mu = 0;
    c.centreBased = false;
    c.ri = pIw - bi_->x();
    c.rk = pKw - bk_->x();
    contacts_->append(c);
}


void Foam::rbd::meshPairFeatures::vertexOfI
(
    const label v,
    const point& p,
    const label f
)
{
    const pointField& pts = bvh_.mesh().points();
    const triFace& tf = bvh_.mesh().faces()[f];
    const vectorField& nf = bvh_.normals();
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
    for (const label g : bvh_.pointFaces()[v])
    {
        if (((R_ & nf[g]) & n) < -facing)
        {
            faces = true;
            break;
        }
    }
    if
    (
        !faces
     || (s < 0 && patches_.vertexFace(v, R_, t_, f, tensor::I, Zero, -s))
    )
    {
        return;
    }
    const vector nW(bk_->R() & n);
    add(p, p - s*n, n, s, wk_ ^ nW, v);
}


void Foam::rbd::meshPairFeatures::vertexOfK
(
    const label v,
    const point& p,
    const label f
)
{
    const triFace& tf = bvh_.mesh().faces()[f];
    const vectorField& nf = bvh_.normals();
    const point& a = movedI_[tf[0]];
    const vector n(R_ & nf[f]);
    const scalar s = (p - a) & n;
    if (s >= band_ || s <= -depth_)
    {
        return;
    }
    if (!projectsInside(p, a, movedI_[tf[1]], movedI_[tf[2]]))
    {
        return;
    }
    bool faces = false;
    for (const label g : bvh_.pointFaces()[v])
    {
        if ((nf[g] & n) < -facing)
        {
            faces = true;
            break;
        }
    }
    if
    (
        !faces
     || (s < 0 && patches_.vertexFace(v, tensor::I, Zero, f, R_, t_, -s))
    )
    {
        return;
    }
    const vector nW(bk_->R() & -n);
    add(p - s*n, p, -n, s, wi_ ^ nW, bvh_.mesh().nPoints() + v);
}


void Foam::rbd::meshPairFeatures::edgeEdge(const label ei, const label ek)
{
    const pointField& pts = bvh_.mesh().points();
    const bodyBVH::edgeInfo& eI = bvh_.edges()[ei];
    const bodyBVH::edgeInfo& eK = bvh_.edges()[ek];
    const point& p1 = movedI_[eI.a];
    const vector d1(movedI_[eI.b] - p1);
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
    if (((R_ & eI.u1) & -n) > coneTol || ((R_ & eI.u2) & -n) > coneTol)
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

    // Crossing edges (gap < 0). With n in both normal cones each edge is
    // the other body's extreme feature along n, so -gap is the overlap of
    // the two bodies' projections on n: the depth along n, at least the
    // true depth, and no depth at all when another axis separates them
    if (gap < 0 && patches_.edgeEdge(eI, eK, R_, t_, -gap))
    {
        return;
    }

    // n' from the rotation of both edges (world frame)
    const tensor& Rk = bk_->R();
    const vector d1w(Rk & d1);
    const vector d2w(Rk & d2);
    const vector crW(Rk & cr);
    const vector crDot(((wi_ ^ d1w) ^ d2w) + (d1w ^ (wk_ ^ d2w)));
    const vector hat(crW/crMag);
    const vector nDot(sign*(crDot - hat*(hat & crDot))/crMag);

    add(cI, cK, n, gap, nDot, -1);
}


bool Foam::rbd::meshPairFeatures::vertexEdge
(
    const point& p, const labelList& faces, const bool onI,
    const bodyBVH::edgeInfo& eInfo,
    const point& a, const vector& d, const vector& u1,
    const vector& u2, const vector& n1, const vector& n2,
    point& c, vector& n, scalar& gap
)
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
    // against its mean outward direction: at an acute edge, 70.5 degrees
    // for a tetrahedron, a point in front of one face can be against it,
    // and a vertex outside was reported 0.5 mm deep)
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
    const pointField& pts = bvh_.mesh().points();
    const List<triFace>& fs = bvh_.mesh().faces();
    for (const label f : faces)
    {
        for (const label w : fs[f])
        {
            const point q(onI ? movedI_[w] : pts[w]);
            const vector e(q - p);
            if ((e & n) < -coneTol*mag(e))
            {
                return false;
            }
        }
    }
    return
        gap >= 0 || !patches_.vertexEdge(faces, onI, eInfo, R_, t_, dist);
}


Foam::rbd::meshPairFeatures::segmentBox
Foam::rbd::meshPairFeatures::grownBox(const point& a, const point& b) const
{
    const scalar halfBand = 0.5*band_;
    segmentBox sb;
    sb.lo = min(a, b) - vector::uniform(halfBand);
    sb.hi = max(a, b) + vector::uniform(halfBand);
    return sb;
}


void Foam::rbd::meshPairFeatures::leafPair(const label li, const label lk)
{
    const pointField& pts = bvh_.mesh().points();
    const vectorField& nf = bvh_.normals();
    const List<bodyBVH::edgeInfo>& es = bvh_.edges();
    const labelListList& pf = bvh_.pointFaces();
    const labelList& order = bvh_.order();
    const bodyBVH::node& ni = bvh_.nodes()[li];
    const bodyBVH::node& nk = bvh_.nodes()[lk];
    const point ci((R_ & ni.centre) + t_);
    const scalar halfBand = 0.5*band_;

    // Edges of i near k's leaf box, edges of k near i's leaf sphere
    segmentBox grownLeafK;
    grownLeafK.lo = nk.lo - vector::uniform(halfBand);
    grownLeafK.hi = nk.hi + vector::uniform(halfBand);
    edgesI_.clear();
    for (const label ei : bvh_.leafEdges(li))
    {
        const bodyBVH::edgeInfo& e = es[ei];
        segmentBox sb(grownBox(movedI_[e.a], movedI_[e.b]));
        sb.edge = ei;
        if (!apart(sb, grownLeafK))
        {
            edgesI_.push_back(sb);
        }
    }
    edgesK_.clear();
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
            edgesK_.push_back(sb);
        }
    }

    // Points of i's leaf near k's leaf box, over k's faces
    pointsI_.clear();
    for (const label v : bvh_.leafPoints(li))
    {
        const point& p = movedI_[v];
        if (bvh_.boxDistanceSqr(lk, p) >= sqr(band_))
        {
            continue;
        }
        pointsI_.push_back(v);
        for (label b = nk.first; b < nk.first + nk.count; ++b)
        {
            vertexOfI(v, p, order[b]);
        }
    }

    // Points of k's leaf near i's leaf (its sphere), over i's faces
    pointsK_.clear();
    for (const label v : bvh_.leafPoints(lk))
    {
        const point& p = pts[v];
        if (magSqr(p - ci) >= sqr(ni.radius + band_))
        {
            continue;
        }
        pointsK_.push_back(v);
        for (label a = ni.first; a < ni.first + ni.count; ++a)
        {
            vertexOfK(v, p, order[a]);
        }
    }

    for (const segmentBox& sI : edgesI_)
    {
        for (const segmentBox& sK : edgesK_)
        {
            if (!apart(sI, sK))
            {
                edgeEdge(sI.edge, sK.edge);
            }
        }
    }

    // Vertices against edges (a vertex near an edge projects onto neither
    // face; parallel edges give no edge/edge contact)
    const tensor& Rk = bk_->R();
    point cE;
    vector nE;
    scalar gE;
    for (const label v : pointsI_)
    {
        const point& p = movedI_[v];
        for (const segmentBox& sK : edgesK_)
        {
            if (outside(sK, p, halfBand))
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
                add(p, cE, nE, gE, wk_ ^ (Rk & nE), v);
            }
        }
    }
    const label nPts = pts.size();
    for (const label v : pointsK_)
    {
        const point& p = pts[v];
        for (const segmentBox& sI : edgesI_)
        {
            if (outside(sI, p, halfBand))
            {
                continue;
            }
            const bodyBVH::edgeInfo& e = es[sI.edge];
            const point& a = movedI_[e.a];
            if
            (
                vertexEdge
                (
                    p, pf[v], false, e, a, movedI_[e.b] - a,
                    R_ & e.u1, R_ & e.u2, R_ & nf[e.f1], R_ & nf[e.f2],
                    cE, nE, gE
                )
            )
            {
                // Normal out of i's edge: from k to i is -nE
                add(cE, p, -nE, gE, wi_ ^ (Rk & -nE), nPts + v);
            }
        }
    }
}


void Foam::rbd::meshPairFeatures::dropSpuriousDepths()
{
    DynamicList<contact>& contacts = *contacts_;
    const label nKeys = 2*bvh_.mesh().nPoints();
    if (nearest_.size() != size_t(nKeys))
    {
        nearest_.assign(nKeys, GREAT);
    }
    for (label a = start_; a < contacts.size(); ++a)
    {
        const label key = keys_[a - start_];
        if (key >= 0 && mag(contacts[a].gap) < mag(nearest_[key]))
        {
            nearest_[key] = contacts[a].gap;
        }
    }
    label j = start_;
    for (label a = start_; a < contacts.size(); ++a)
    {
        const label key = keys_[a - start_];
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
    for (label a = start_; a < contacts.size(); ++a)
    {
        const label key = keys_[a - start_];
        if (key >= 0)
        {
            nearest_[key] = GREAT;
        }
    }
    contacts.setSize(j);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::meshPairFeatures::meshPairFeatures
(
    const bodyBVH& bvh,
    const scalar band
)
:
    bvh_(bvh),
    band_(band),
    depth_(band),
    patches_(bvh, band, bvh.mesh().boundingRadius()),
    movedI_(bvh.mesh().points()),
    i_(-1),
    k_(-1),
    bi_(nullptr),
    bk_(nullptr),
    R_(tensor::I),
    t_(Zero),
    wi_(Zero),
    wk_(Zero),
    contacts_(nullptr),
    start_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::meshPairFeatures::find
(
    const label i,
    const rigidBody& bi,
    const label k,
    const rigidBody& bk,
    DynamicList<contact>& contacts
)
{
    // Pose of i in the frame of k: p_k = R p_i + t
    const tensor& Rk = bk.R();
    i_ = i;
    k_ = k;
    bi_ = &bi;
    bk_ = &bk;
    R_ = (Rk.T() & bi.R());
    t_ = (Rk.T() & (bi.x() - bk.x()));
    wi_ = bi.omega();
    wk_ = bk.omega();
    contacts_ = &contacts;
    start_ = contacts.size();
    movedI_.setPose(R_, t_);
    keys_.clear();

    bvh_.leafPairs
    (
        bvh_, R_, t_, band_,
        [this](const label li, const label lk) { leafPair(li, lk); }
    );

    dropSpuriousDepths();
    contacts_ = nullptr;
}


// ************************************************************************* //

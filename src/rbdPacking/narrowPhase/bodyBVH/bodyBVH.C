/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bodyBVH.H"
#include "EdgeMap.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::bodyBVH::sharpAngle =
    Foam::constant::mathematical::pi/180;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::rbd::bodyBVH::build
(
    const label first,
    const label count,
    const label leaf
)
{
    const pointField& pts = mesh_.points();
    const List<triFace>& fs = mesh_.faces();

    point lo(point::uniform(GREAT));
    point hi(point::uniform(-GREAT));
    for (label j = first; j < first + count; ++j)
    {
        for (const label p : fs[order_[j]])
        {
            lo = min(lo, pts[p]);
            hi = max(hi, pts[p]);
        }
    }

    const label n = nodes_.size();
    nodes_.append(node());
    {
        node& nd = nodes_[n];
        nd.lo = lo;
        nd.hi = hi;
        nd.centre = 0.5*(lo + hi);
        nd.radius = 0.5*mag(hi - lo);
        nd.left = -1;
        nd.right = -1;
        nd.first = first;
        nd.count = count;
    }

    if (count <= leaf)
    {
        return n;
    }

    // Median split of the centroids along the longest axis
    const vector span(hi - lo);
    direction axis = 0;
    if (span.y() > span[axis]) axis = 1;
    if (span.z() > span[axis]) axis = 2;

    auto centroid = [&](const label f)
    {
        return (pts[fs[f][0]][axis] + pts[fs[f][1]][axis] + pts[fs[f][2]][axis]);
    };
    const label half = count/2;
    std::nth_element
    (
        order_.begin() + first,
        order_.begin() + first + half,
        order_.begin() + first + count,
        [&](const label a, const label b) { return centroid(a) < centroid(b); }
    );

    const label l = build(first, half, leaf);
    const label r = build(first + half, count - half, leaf);
    nodes_[n].left = l;
    nodes_[n].right = r;
    return n;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::bodyBVH::bodyBVH(const triMesh& mesh, const label leafSize)
:
    mesh_(mesh),
    nodes_(),
    order_(identity(mesh.nFaces())),
    normals_(mesh.faceNormals()),
    edges_(),
    faceEdges_(mesh.nFaces()),
    pointFaces_(mesh.nPoints())
{
    const pointField& pts = mesh_.points();
    const List<triFace>& fs = mesh_.faces();

    // Tree
    if (mesh.nFaces())
    {
        nodes_.setCapacity(2*mesh.nFaces()/max(leafSize, label(1)) + 1);
        build(0, mesh.nFaces(), max(leafSize, label(1)));
    }

    // Points to faces
    {
        labelList nPf(mesh.nPoints(), 0);
        for (const triFace& f : fs)
        {
            for (const label p : f)
            {
                ++nPf[p];
            }
        }
        forAll(pointFaces_, p)
        {
            pointFaces_[p].setSize(nPf[p]);
            nPf[p] = 0;
        }
        forAll(fs, fi)
        {
            for (const label p : fs[fi])
            {
                pointFaces_[p][nPf[p]++] = fi;
            }
        }
    }

    // Edges with their faces
    EdgeMap<label> index(3*mesh.nFaces()/2);
    DynamicList<edgeInfo> es(3*mesh.nFaces()/2);
    forAll(fs, fi)
    {
        const triFace& f = fs[fi];
        for (label j = 0; j < 3; ++j)
        {
            const edge e(f[j], f[(j + 1) % 3]);
            auto iter = index.find(e);
            if (iter.found())
            {
                es[*iter].f2 = fi;
                faceEdges_[fi][j] = *iter;
            }
            else
            {
                edgeInfo ei;
                ei.a = e.first();
                ei.b = e.second();
                ei.f1 = fi;
                ei.f2 = -1;
                ei.u1 = Zero;
                ei.u2 = Zero;
                ei.outward = Zero;
                ei.feature = false;
                faceEdges_[fi][j] = es.size();
                index.insert(e, es.size());
                es.append(ei);
            }
        }
    }
    edges_.transfer(es);

    // Opposite point of face f to edge (a, b)
    auto opposite = [&](const label f, const edgeInfo& e)
    {
        for (const label p : fs[f])
        {
            if (p != e.a && p != e.b)
            {
                return p;
            }
        }
        return fs[f][0];
    };

    // Inward direction in face f, perpendicular to the edge
    auto inward = [&](const label f, const edgeInfo& e)
    {
        const vector d(pts[e.b] - pts[e.a]);
        const vector w(pts[opposite(f, e)] - pts[e.a]);
        vector u(w - d*((w & d)/max(magSqr(d), VSMALL)));
        return u/max(mag(u), VSMALL);
    };

    const scalar cosSharp = Foam::cos(sharpAngle);
    for (edgeInfo& e : edges_)
    {
        e.u1 = inward(e.f1, e);
        if (e.f2 < 0)
        {
            e.outward = normals_[e.f1];
            continue;
        }
        e.u2 = inward(e.f2, e);
        e.outward = normals_[e.f1] + normals_[e.f2];
        const bool sharp = (normals_[e.f1] & normals_[e.f2]) < cosSharp;
        const bool convex =
            ((pts[opposite(e.f2, e)] - pts[e.a]) & normals_[e.f1]) < 0;
        e.feature = sharp && convex;
    }

    // Per leaf: its points and feature edges, each once
    leafPoints_.setSize(nodes_.size());
    leafEdges_.setSize(nodes_.size());
    forAll(nodes_, n)
    {
        const node& nd = nodes_[n];
        if (!nd.leaf())
        {
            continue;
        }
        DynamicList<label> ps(3*nd.count), fe(3*nd.count);
        for (label j = nd.first; j < nd.first + nd.count; ++j)
        {
            const label f = order_[j];
            for (label q = 0; q < 3; ++q)
            {
                if (!ps.found(fs[f][q]))
                {
                    ps.append(fs[f][q]);
                }
                const label e = faceEdges_[f][q];
                if (edges_[e].feature && !fe.found(e))
                {
                    fe.append(e);
                }
            }
        }
        leafPoints_[n].transfer(ps);
        leafEdges_[n].transfer(fe);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::bodyBVH::boxDistance
(
    const label n,
    const point& p
) const
{
    return Foam::sqrt(boxDistanceSqr(n, p));
}


Foam::point Foam::rbd::bodyBVH::closestOnFace
(
    const label f,
    const point& p
) const
{
    // Ericson, Real-Time Collision Detection (2005), section 5.1.5
    const pointField& pts = mesh_.points();
    const triFace& t = mesh_.faces()[f];
    const point& a = pts[t[0]];
    const point& b = pts[t[1]];
    const point& c = pts[t[2]];

    const vector ab(b - a), ac(c - a), ap(p - a);
    const scalar d1 = ab & ap, d2 = ac & ap;
    if (d1 <= 0 && d2 <= 0) return a;

    const vector bp(p - b);
    const scalar d3 = ab & bp, d4 = ac & bp;
    if (d3 >= 0 && d4 <= d3) return b;

    const scalar vc = d1*d4 - d3*d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
    {
        return a + (d1/(d1 - d3))*ab;
    }

    const vector cp(p - c);
    const scalar d5 = ab & cp, d6 = ac & cp;
    if (d6 >= 0 && d5 <= d6) return c;

    const scalar vb = d5*d2 - d1*d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
    {
        return a + (d2/(d2 - d6))*ac;
    }

    const scalar va = d3*d6 - d5*d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    {
        return b + ((d4 - d3)/((d4 - d3) + (d5 - d6)))*(c - b);
    }

    const scalar denom = 1/(va + vb + vc);
    return a + (vb*denom)*ab + (vc*denom)*ac;
}


// ************************************************************************* //

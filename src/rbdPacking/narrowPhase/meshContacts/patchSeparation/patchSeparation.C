/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "patchSeparation.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::patchSeparation::overstated = 0.9;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::rbd::patchSeparation::overlap
(
    const DynamicList<label>& fA, const tensor& RA, const vector& tA,
    const DynamicList<label>& fB, const tensor& RB, const vector& tB,
    const scalar floor
) const
{
    const pointField& pts = bvh_.mesh().points();
    const List<triFace>& fs = bvh_.mesh().faces();
    const vectorField& nf = bvh_.normals();

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

    // The faces' normals, then the cross products of their edges
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
            vector da(RA & (pts[fs[f][(ea + 1) % 3]] - pts[fs[f][ea]]));
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
}


void Foam::rbd::patchSeparation::facesAround
(
    const label a,
    const label b,
    DynamicList<label>& patch
) const
{
    const labelListList& pf = bvh_.pointFaces();
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
}


bool Foam::rbd::patchSeparation::inFront
(
    const bodyBVH::edgeInfo& e,
    const tensor& RR,
    const vector& tt,
    const point& o,
    const vector& m
) const
{
    const pointField& pts = bvh_.mesh().points();
    const List<triFace>& fs = bvh_.mesh().faces();
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
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::patchSeparation::patchSeparation
(
    const bodyBVH& bvh,
    const scalar band,
    const scalar radius
)
:
    bvh_(bvh),
    checkDepth_(1e-2*band),
    tol_(1e-9*radius),
    patchA_(),
    patchB_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::rbd::patchSeparation::vertexFace
(
    const label v, const tensor& Rv, const vector& tv,
    const label f, const tensor& RR, const vector& tt,
    const scalar depth
)
{
    const pointField& pts = bvh_.mesh().points();
    const List<triFace>& fs = bvh_.mesh().faces();
    const vectorField& nf = bvh_.normals();
    const labelListList& pf = bvh_.pointFaces();

    // Is the vertex in front of a face g around f that meets f convexly?
    const triFace& tf = fs[f];
    const point p((Rv & pts[v]) + tv);
    bool inFrontOfNeighbour = false;
    for (const label c : tf)
    {
        for (const label g : pf[c])
        {
            if (g == f || inFrontOfNeighbour)
            {
                continue;
            }
            const vector ng(RR & nf[g]);
            const point o((RR & pts[fs[g][0]]) + tt);
            if (((p - o) & ng) <= tol_)
            {
                continue;
            }
            bool convex = true;
            for (const label w : tf)
            {
                if ((((RR & pts[w]) + tt - o) & ng) > tol_)
                {
                    convex = false;
                    break;
                }
            }
            inFrontOfNeighbour = convex;
        }
    }
    const bool deep = depth > checkDepth_;
    if (!inFrontOfNeighbour && !deep)
    {
        return false;
    }
    facesAround(v, -1, patchA_);
    patchB_.clear();
    for (const label c : tf)
    {
        for (const label g : pf[c])
        {
            if (!patchB_.found(g))
            {
                patchB_.append(g);
            }
        }
    }
    const scalar least = deep ? overstated*depth : 0;
    return overlap(patchA_, Rv, tv, patchB_, RR, tt, least) < least;
}


bool Foam::rbd::patchSeparation::edgeEdge
(
    const bodyBVH::edgeInfo& eI,
    const bodyBVH::edgeInfo& eK,
    const tensor& R,
    const vector& t,
    const scalar depth
)
{
    const pointField& pts = bvh_.mesh().points();
    const List<triFace>& fs = bvh_.mesh().faces();
    const vectorField& nf = bvh_.normals();

    // 1. a face of either edge separates
    for (const label f : {eK.f1, eK.f2})
    {
        if (inFront(eI, R, t, pts[fs[f][0]], nf[f]))
        {
            return true;
        }
    }
    for (const label f : {eI.f1, eI.f2})
    {
        if
        (
            inFront
            (
                eK, tensor::I, Zero, (R & pts[fs[f][0]]) + t, R & nf[f]
            )
        )
        {
            return true;
        }
    }

    // 2. the patches around both edges overlap by the depth
    if (depth > checkDepth_)
    {
        facesAround(eI.a, eI.b, patchA_);
        facesAround(eK.a, eK.b, patchB_);
        const scalar least = overstated*depth;
        return
            overlap(patchA_, R, t, patchB_, tensor::I, Zero, least) < least;
    }
    return false;
}


bool Foam::rbd::patchSeparation::vertexEdge
(
    const labelList& faces,
    const bool onI,
    const bodyBVH::edgeInfo& eInfo,
    const tensor& R,
    const vector& t,
    const scalar depth
)
{
    if (depth <= checkDepth_)
    {
        return false;
    }
    patchA_.clear();
    patchA_.append(faces);
    facesAround(eInfo.a, eInfo.b, patchB_);
    const scalar least = overstated*depth;
    const scalar ov =
        onI
      ? overlap(patchA_, R, t, patchB_, tensor::I, Zero, least)
      : overlap(patchA_, tensor::I, Zero, patchB_, R, t, least);
    return ov < least;
}


// ************************************************************************* //

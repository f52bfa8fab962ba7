/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshContacts.H"
#include "floorSupport.H"
#include "contactReduction.H"
#include "containerContact.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::meshContacts::meshContacts(const triMesh& mesh, const scalar band)
:
    bvh_(mesh),
    band_(band),
    depth_(band),
    radius_(mesh.boundingRadius()),
    mergeDistance_(1e-3*mesh.boundingRadius()),
    moved_(bvh_.mesh().points()),
    features_(bvh_, band)
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
    // Bounding spheres apart by more than the band: nothing to find
    if (magSqr(bi.x() - bk.x()) >= sqr(2*radius_ + band_))
    {
        return;
    }
    const label start = contacts.size();
    features_.find(i, bi, k, bk, contacts);
    contactReduction::reduce(contacts, start, mergeDistance_, 0.1*band_);
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

    moved_.setPose(Ri, x);
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
                if (moved_.has(v))
                {
                    continue;
                }
                const point& p = moved_[v];
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
        contacts.append(containerPointContact(i, x, p, tubeBottom, container));
    }
    {
        // The corners of the support, and the points one step can bring
        // down beside them (floorSupport)
        const std::vector<contact> all
        (
            contacts.begin() + start, contacts.end()
        );
        contactReduction::reduce(contacts, start, mergeDistance_, 0.1*band_);
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
        if (Rt - rho <= -depth_ || rho < VSMALL)
        {
            continue;
        }
        contacts.append(containerPointContact(i, x, p, tubeWall, container));
    }
    contactReduction::reduce(contacts, start, mergeDistance_, 0.1*band_);
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


// ************************************************************************* //

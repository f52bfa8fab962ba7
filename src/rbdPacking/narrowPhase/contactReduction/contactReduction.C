/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactReduction.H"
#include "mathematicalConstants.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::contactReduction::clusterAngle =
    20*Foam::constant::mathematical::pi/180;

const Foam::label Foam::rbd::contactReduction::nTiers = 3;

const Foam::label Foam::rbd::contactReduction::maxKeepAll = 8;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::contactReduction::contactReduction
(
    const DynamicList<contact>& contacts,
    const label start,
    const scalar mergeDistance,
    const scalar tier
)
:
    cs_(contacts.begin() + start, contacts.end()),
    mergeDistance_(mergeDistance),
    tier_(tier),
    origin_(Zero),
    normal_(Zero)
{
    // Deepest first
    std::stable_sort
    (
        cs_.begin(), cs_.end(),
        [](const contact& x, const contact& y) { return x.gap < y.gap; }
    );
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::vector<std::vector<Foam::label>>
Foam::rbd::contactReduction::groupsByNormal() const
{
    const scalar cosGroup = Foam::cos(clusterAngle);
    std::vector<std::vector<label>> groups;
    const label n = cs_.size();
    for (label a = 0; a < n; ++a)
    {
        bool placed = false;
        for (auto& g : groups)
        {
            if ((cs_[g.front()].n & cs_[a].n) > cosGroup)
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
    return groups;
}


Foam::vector Foam::rbd::contactReduction::tangential(const label a) const
{
    const vector d(cs_[a].p - origin_);
    return d - normal_*(normal_ & d);
}


void Foam::rbd::contactReduction::corners
(
    const std::vector<label>& level,
    const bool later,
    const label laterCorners,
    std::vector<label>& kept
) const
{
    const vector o(tangential(level.front()));
    auto rel = [&](const label a) { return tangential(a) - o; };

    // 1. the deepest point
    kept.push_back(level.front());

    // 2. the farthest from it
    label a1 = -1;
    scalar best = mergeDistance_;
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
    if (later && laterCorners <= 2)
    {
        return;
    }
    const vector e1(rel(a1));

    // 3. the largest triangle
    label a2 = -1;
    best = mergeDistance_*mag(e1);
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
    best = mergeDistance_*mag(e1);
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
}


bool Foam::rbd::contactReduction::covered
(
    const label a,
    const std::vector<label>& kept
) const
{
    const vector x(tangential(a));
    const scalar ga = cs_[a].gap + 1e-9*tier_;
    const label nK = kept.size();
    for (label j = 0; j < nK; ++j)
    {
        const vector xj(tangential(kept[j]));
        const scalar gj = cs_[kept[j]].gap;
        if (mag(x - xj) <= mergeDistance_)
        {
            return true;
        }
        for (label l = j + 1; l < nK; ++l)
        {
            // On the segment (j, l)
            const vector xl(tangential(kept[l]));
            const scalar gl = cs_[kept[l]].gap;
            const vector d(xl - xj);
            const scalar u = ((x - xj) & d)/max(magSqr(d), VSMALL);
            if
            (
                u >= 0 && u <= 1
             && mag(x - xj - u*d) <= mergeDistance_
             && ga >= gj + u*(gl - gj)
            )
            {
                return true;
            }

            // In the triangle (j, l, m)
            for (label m = l + 1; m < nK; ++m)
            {
                const vector xm(tangential(kept[m]));
                const vector cr(d ^ (xm - xj));
                const scalar area2 = magSqr(cr);
                if (area2 <= sqr(sqr(mergeDistance_)))
                {
                    continue;
                }
                // Barycentric coordinates of x in (j, l, m)
                const scalar bl = (((x - xj) ^ (xm - xj)) & cr)/area2;
                const scalar bm = ((d ^ (x - xj)) & cr)/area2;
                const scalar bj = 1 - bl - bm;
                if
                (
                    bj >= 0 && bl >= 0 && bm >= 0
                 && ga >= bj*gj + bl*gl + bm*cs_[kept[m]].gap
                )
                {
                    return true;
                }
            }
        }
    }
    return false;
}


void Foam::rbd::contactReduction::reduceGroup
(
    const std::vector<label>& g,
    const label keepAll,
    const label laterCorners,
    DynamicList<contact>& contacts
)
{
    origin_ = cs_[g.front()].p;
    normal_ = cs_[g.front()].n;
    const scalar g0 = cs_[g.front()].gap;
    std::vector<label> kept, level;

    for (label t = 0; t < (tier_ > 0 ? nTiers : 1); ++t)
    {
        // The points of this tier of gaps (g is sorted by gap)
        level.clear();
        for (const label a : g)
        {
            const scalar above = cs_[a].gap - g0;
            if (above >= t*tier_ && (above < (t + 1)*tier_ || tier_ <= 0))
            {
                level.push_back(a);
            }
        }
        if (level.empty())
        {
            continue;
        }

        const label first = kept.size();
        corners(level, t > 0, laterCorners, kept);

        // The points of the first tier within a fifth of the tier of the
        // deepest are all kept, up to keepAll: next to a point of support,
        // a curved or tilted support (the rim of a polygonal cylinder
        // rolling or rocking on a plane) has points about to touch that
        // are not corners of the tier (rim vertices inside the rim's
        // plane); dropped, each landed unseen up to 10 um deep, and the
        // overlap correction that lifted it out kept the cylinder rolling.
        // More of them: a flat patch, whose corners hold it. Not those
        // covered by kept ones, which a rigid motion cannot bring to touch
        // first (the middle of a line of support).
        const scalar gLevel = cs_[level.front()].gap;
        label nNear = 0;
        for (const label a : level)
        {
            nNear += cs_[a].gap - gLevel < 0.2*tier_;
        }
        if (t == 0 && nNear <= keepAll)
        {
            for (const label a : level)
            {
                if (cs_[a].gap - gLevel >= 0.2*tier_)
                {
                    break;
                }
                if (!covered(a, kept))
                {
                    kept.push_back(a);
                }
            }
        }

        for (size_t j = first; j < kept.size(); ++j)
        {
            contacts.append(cs_[kept[j]]);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::contactReduction::reduce
(
    DynamicList<contact>& contacts,
    const label start,
    const scalar mergeDistance,
    const scalar tier,
    const label keepAll,
    const label laterCorners
)
{
    if (contacts.size() - start <= 1)
    {
        return;
    }
    contactReduction reduction(contacts, start, mergeDistance, tier);
    contacts.setSize(start);
    for (const std::vector<label>& g : reduction.groupsByNormal())
    {
        reduction.reduceGroup(g, keepAll, laterCorners, contacts);
    }
}


// ************************************************************************* //

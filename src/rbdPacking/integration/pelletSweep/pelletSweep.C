/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pelletSweep.H"
#include "tube.H"
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// The rotation from qa to qb as r = qa^-1 qb with r.w >= 0 (the shorter
// way), and its angle [rad]
Foam::quaternion relativeRotation
(
    const Foam::quaternion& qa,
    const Foam::quaternion& qb,
    Foam::scalar& angle
)
{
    Foam::quaternion r(Foam::inv(qa)*qb);
    if (r.w() < 0)
    {
        r = Foam::quaternion(-r.w(), -r.v());
    }
    angle = 2*Foam::atan2(Foam::mag(r.v()), r.w());
    return r;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::pelletSweep::pelletSweep
(
    const scalar speed,
    const scalar touch,
    const scalar band,
    const scalar unseenClosing,
    const scalar boundingRadius,
    const bool centreGaps,
    const scalar tubeRadius
)
:
    speed_(speed),
    touch_(touch),
    band_(band),
    unseenClosing_(unseenClosing),
    rb_(boundingRadius),
    centreGaps_(centreGaps),
    tubeRadius_(tubeRadius)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::pelletSweep::surfaceSpeed(const rigidBody& b) const
{
    return mag(b.v()) + (centreGaps_ ? 0 : mag(b.omega())*rb_);
}


Foam::scalar Foam::rbd::pelletSweep::advanceFor
(
    const scalar gap,
    const bool seen
) const
{
    if (!seen)
    {
        return max(gap - 0.5*touch_, unseenClosing_);
    }
    return gap <= touch_ ? 0 : min(gap - 0.5*touch_, 0.2*band_);
}


Foam::scalar Foam::rbd::pelletSweep::relativeSpeed
(
    const label i,
    const UList<rigidBody>& bodies,
    const boolList& fixed,
    const UList<label>& neighbours
) const
{
    const rigidBody& b = bodies[i];
    scalar u = 0;
    for (const label k : neighbours)
    {
        const rigidBody& bk = bodies[k];
        if (fixed[k])
        {
            u = max(u, surfaceSpeed(b));
            continue;
        }
        scalar uk = mag(b.v() - bk.v());
        if (!centreGaps_)
        {
            uk += (mag(b.omega()) + mag(bk.omega()))*rb_;
        }
        u = max(u, uk);
    }
    if
    (
        b.x().z() < 2*rb_
     || tube::axialDistance(b.x()) + 2*rb_ > tubeRadius_
    )
    {
        u = max(u, surfaceSpeed(b));
    }
    return u;
}


bool Foam::rbd::pelletSweep::clearOf
(
    const point& x0,
    const point& x1,
    const point& xk,
    const scalar gap
) const
{
    // The nearest point of the segment to xk
    const vector d(x1 - x0);
    const scalar dd = magSqr(d);
    const scalar s =
        dd > 0 ? min(max(((xk - x0) & d)/dd, scalar(0)), scalar(1)) : 0;
    return mag(x0 + s*d - xk) - 2*rb_ >= gap;
}


bool Foam::rbd::pelletSweep::clearOfContainer
(
    const point& x0,
    const point& x1,
    const scalar gap
) const
{
    // Height and distance from the axis are extreme at the ends (the
    // latter convex along the segment)
    return
        min(x0.z(), x1.z()) - rb_ >= gap
     && tubeRadius_
      - max(tube::axialDistance(x0), tube::axialDistance(x1)) - rb_ >= gap;
}


void Foam::rbd::pelletSweep::select
(
    const UList<rigidBody>& bodies,
    const boolList& fixed,
    const UList<label>& awake,
    const UList<contact>& contacts,
    const UList<DynamicList<label>>& neighbours,
    DynamicList<label>& swept
) const
{
    swept.clear();
    if (!on())
    {
        return;
    }

    // Near: a contact closer than clearGap lambda (resting or about to)
    std::vector<bool> touching(bodies.size(), false);
    for (const contact& c : contacts)
    {
        if (c.gap < clearGap*band_)
        {
            touching[c.i] = true;
            if (c.k >= 0)
            {
                touching[c.k] = true;
            }
        }
    }

    // Candidates, the faster first (ties: the lower index)
    std::vector<std::pair<scalar, label>> fast;
    for (const label i : awake)
    {
        if (touching[i])
        {
            continue;
        }
        const scalar u = relativeSpeed(i, bodies, fixed, neighbours[i]);
        if (u > speed_)
        {
            fast.emplace_back(-u, i);
        }
    }
    std::sort(fast.begin(), fast.end());

    // No two listed neighbours: each is swept against the others' final
    // poses
    std::vector<bool> taken(bodies.size(), false);
    for (const auto& f : fast)
    {
        const label i = f.second;
        bool free = true;
        for (const label k : neighbours[i])
        {
            if (taken[k])
            {
                free = false;
                break;
            }
        }
        if (free)
        {
            taken[i] = true;
            swept.append(i);
        }
    }
    std::sort(swept.begin(), swept.end());
}


void Foam::rbd::pelletSweep::interpolate
(
    const rigidBody& a,
    const rigidBody& b,
    const scalar s,
    rigidBody& at
)
{
    scalar angle = 0;
    const quaternion r(relativeRotation(a.q(), b.q(), angle));
    quaternion q(a.q());
    const scalar sinHalf = mag(r.v());
    if (sinHalf > VSMALL)
    {
        const scalar half = 0.5*s*angle;
        q = a.q()*quaternion(Foam::cos(half), (Foam::sin(half)/sinHalf)*r.v());
        q.normalize();
    }
    at.setState
    (
        a.x() + s*(b.x() - a.x()),
        q,
        a.P() + s*(b.P() - a.P()),
        a.L() + s*(b.L() - a.L())
    );
}


Foam::scalar Foam::rbd::pelletSweep::sweep
(
    const rigidBody& start,
    rigidBody& body,
    const advanceFunction& advance
) const
{
    // (spheres' gaps do not turn with them)
    scalar angle = 0;
    if (body.rotates() && !centreGaps_)
    {
        relativeRotation(start.q(), body.q(), angle);
    }
    // No surface point moves more than D per unit of s
    const scalar D = mag(body.x() - start.x()) + angle*rb_;
    if (D <= 0)
    {
        return 1;
    }

    const rigidBody end(body);
    rigidBody trial(start);
    scalar s = 0;
    for (label j = 0; j < maxAdvances; ++j)
    {
        if (j > 0)
        {
            interpolate(start, end, s, trial);
        }
        const scalar d = advance(trial);
        if (d <= 0)
        {
            // Touching (at the start too, where the others came within
            // the touching gap of it): it stays here
            break;
        }
        s += d/D;
        if (s >= 1)
        {
            return 1;
        }
    }

    interpolate(start, end, s, body);
    return s;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sleepControl.H"
#include "stateIO.H"
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::sleepControl::sleepControl
(
    const scalar sleepVelocity,
    const scalar sleepTime,
    const scalar boundingRadius,
    const scalar band,
    const bool rotates,
    const bool spheres
)
:
    sleepVelocity_(sleepVelocity),
    sleepTime_(sleepTime),
    rb_(boundingRadius),
    band_(band),
    turns_(rotates && !spheres),
    spheres_(spheres),
    slowTime_(),
    anchorX_(),
    anchorQ_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::sleepControl::addBody(const point& x, const quaternion& q)
{
    slowTime_.append(0);
    anchorX_.append(x);
    anchorQ_.append(q);
}


bool Foam::rbd::sleepControl::fallAsleep
(
    const scalar h,
    const UList<rigidBody>& bodies,
    const boolList& fixed,
    const UList<label>& awake,
    const UList<contact>& contacts,
    boolList& sleeps
)
{
    if (sleepVelocity_ <= 0)
    {
        return false;
    }
    const scalar drift = sleepVelocity_*sleepTime_;

    // Who rests on whom: a contact whose normal, from the other pellet
    // towards this one, points up
    std::vector<std::pair<label, label>> restsOn;
    for (const contact& c : contacts)
    {
        if (c.k < 0)
        {
            continue;
        }
        if (c.n.z() > 0 && !fixed[c.k])
        {
            restsOn.emplace_back(c.i, c.k);
        }
        else if (c.n.z() < 0 && !fixed[c.i])
        {
            restsOn.emplace_back(c.k, c.i);
        }
    }

    for (const label i : awake)
    {
        const rigidBody& b = bodies[i];

        scalar moved = mag(b.x() - anchorX_[i]);
        if (turns_)
        {
            // Angle of the rotation from the anchor, at the bounding radius
            const quaternion& qa = anchorQ_[i];
            const scalar cosHalf = min
            (
                mag(b.q().w()*qa.w() + (b.q().v() & qa.v())),
                scalar(1)
            );
            moved += 2*Foam::acos(cosHalf)*rb_;
        }

        if (moved > drift)
        {
            anchorX_[i] = b.x();
            anchorQ_[i] = b.q();
            slowTime_[i] = 0;
            continue;
        }

        slowTime_[i] += h;
    }

    // The still pellets that may sleep: each rests only on sleepers, the
    // container or other pellets that fall asleep with it (pellets resting
    // on each other, as interlocked rings do, sleep together), found by
    // removing the still pellets that rest on a pellet staying awake until
    // none is left
    sleeps.setSize(bodies.size());
    sleeps = false;
    bool anyStill = false;
    for (const label i : awake)
    {
        sleeps[i] = slowTime_[i] >= sleepTime_;
        anyStill = anyStill || sleeps[i];
    }
    if (!anyStill)
    {
        return false;
    }

    // Only a pellet resting on another or touching the container may
    // sleep: one still in the air (a slow fall at a small gravity, a large
    // sleepVelocity) stays awake
    {
        std::vector<bool> supported(bodies.size(), false);
        for (const contact& c : contacts)
        {
            if (c.k < 0 || c.n.z() > 0)
            {
                supported[c.i] = true;
            }
            else if (c.n.z() < 0)
            {
                supported[c.k] = true;
            }
        }
        for (const label i : awake)
        {
            sleeps[i] = sleeps[i] && supported[i];
        }
    }
    for (bool removed = true; removed; )
    {
        removed = false;
        for (const auto& pr : restsOn)
        {
            if (sleeps[pr.first] && !sleeps[pr.second])
            {
                sleeps[pr.first] = false;
                removed = true;
            }
        }
    }

    bool any = false;
    for (const label i : awake)
    {
        any = any || sleeps[i];
    }
    return any;
}


bool Foam::rbd::sleepControl::wake
(
    const label i,
    const UList<rigidBody>& bodies,
    boolList& fixed,
    const UList<DynamicList<label>>& adjacency
)
{
    const scalar below = spheres_ ? 0 : 0.5*rb_;
    const scalar reach = sqr(2*rb_ + band_);

    bool woke = false;
    DynamicList<label> stack;
    stack.append(i);
    bool first = true;
    while (stack.size())
    {
        const label j = stack.remove();
        if (!fixed[j] && !first)
        {
            continue;
        }
        first = false;
        woke = woke || fixed[j];
        fixed[j] = false;
        slowTime_[j] = 0;
        anchorX_[j] = bodies[j].x();
        anchorQ_[j] = bodies[j].q();

        if (j >= adjacency.size())
        {
            continue;
        }
        for (const label k : adjacency[j])
        {
            if
            (
                fixed[k]
             && bodies[k].x().z() > bodies[j].x().z() - below
             && magSqr(bodies[k].x() - bodies[j].x()) <= reach
            )
            {
                stack.append(k);
            }
        }
    }
    return woke;
}


void Foam::rbd::sleepControl::writeState(stateWriter& out) const
{
    out.putList(slowTime_).putList(anchorX_).putList(anchorQ_);
}


Foam::label Foam::rbd::sleepControl::readState(stateReader& in)
{
    in.getList(slowTime_).getList(anchorX_).getList(anchorQ_);
    const label n = slowTime_.size();
    return anchorX_.size() == n && anchorQ_.size() == n ? n : -1;
}


// ************************************************************************* //

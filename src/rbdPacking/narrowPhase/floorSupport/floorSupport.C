/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "floorSupport.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::rbd::floorSupport::addNear
(
    const std::vector<contact>& candidates,
    const scalar span,
    const scalar mergeDistance,
    const label start,
    DynamicList<contact>& contacts
)
{
    // The candidates by gap, lowest first (stable: equal gaps in the
    // candidates' order, as everywhere in the contact lists)
    std::vector<label> order(candidates.size());
    for (label a = 0; a < label(order.size()); ++a)
    {
        order[a] = a;
    }
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](const label x, const label y)
        {
            return candidates[x].gap < candidates[y].gap;
        }
    );
    if (order.empty())
    {
        return;
    }
    const scalar gapLow = candidates[order[0]].gap;

    // A face lying flat (its near points' gaps within flatSpread span of
    // each other) is held by the corners already
    scalar gapHigh = gapLow;
    for (const contact& c : candidates)
    {
        if (c.gap <= gapLow + span)
        {
            gapHigh = max(gapHigh, c.gap);
        }
    }
    if (gapHigh - gapLow <= flatSpread*span)
    {
        return;
    }

    label added = 0;
    for (const label a : order)
    {
        const contact& c = candidates[a];
        if (added >= nLowest || c.gap > gapLow + span)
        {
            break;
        }
        bool found = false;
        for (label ci = start; ci < contacts.size() && !found; ++ci)
        {
            found = magSqr(contacts[ci].ri - c.ri) <= sqr(mergeDistance);
        }
        if (!found)
        {
            contacts.append(c);
            ++added;
        }
    }
}


// ************************************************************************* //

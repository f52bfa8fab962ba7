/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactIslands.H"
#include <numeric>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::rbd::contactIslands::findRoot(label a)
{
    while (parent_[a] != a)
    {
        parent_[a] = parent_[parent_[a]];
        a = parent_[a];
    }
    return a;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::contactIslands::build
(
    const UList<contact>& contacts,
    const boolList& fixed,
    const label nBodies
)
{
    clear();
    const label n0 = parent_.size();
    if (nBodies > n0)
    {
        parent_.resize(nBodies);
        std::iota(parent_.begin() + n0, parent_.end(), n0);
        islandOf_.resize(nBodies);
    }

    // Contacts connected through bodies that move
    for (const contact& c : contacts)
    {
        touched_.push_back(c.i);
        if (c.k >= 0 && !fixed[c.k])
        {
            touched_.push_back(c.k);
            parent_[findRoot(c.i)] = findRoot(c.k);
        }
    }

    forAll(contacts, ci)
    {
        const label r = findRoot(contacts[ci].i);
        if (islandOf_[r].empty())
        {
            roots_.push_back(r);
        }
        islandOf_[r].push_back(ci);
    }
}


void Foam::rbd::contactIslands::clear()
{
    for (const label r : roots_)
    {
        islandOf_[r].clear();
    }
    roots_.clear();
    for (const label b : touched_)
    {
        parent_[b] = b;
    }
    touched_.clear();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sphereContacts.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

bool Foam::rbd::sphereContacts::sphereSphere
(
    const label i,
    const rigidBody& bi,
    const scalar ai,
    const label k,
    const rigidBody& bk,
    const scalar ak,
    const scalar band,
    contact& c
)
{
    const vector d(bi.x() - bk.x());
    const scalar dist2 = magSqr(d);
    const scalar reach = ai + ak + band;

    if (dist2 >= sqr(reach) || dist2 < VSMALL)
    {
        return false;
    }

    const scalar dist = Foam::sqrt(dist2);
    const vector n(d/dist);
    const vector dv(bi.v() - bk.v());

    c.i = i;
    c.k = k;
    c.n = n;
    c.gap = dist - ai - ak;
    c.p = bk.x() + (ak + 0.5*c.gap)*n;
    c.nDot = (dv - n*(n & dv))/dist;
    c.centreBased = true;

    return true;
}


void Foam::rbd::sphereContacts::sphereTube
(
    const label i,
    const rigidBody& bi,
    const scalar a,
    const tube& container,
    const scalar band,
    DynamicList<contact>& contacts
)
{
    const point& x = bi.x();

    // Flat bottom, z = 0
    const scalar zGap = x.z() - a;
    if (zGap < band)
    {
        contact c;
        c.i = i;
        c.k = tubeBottom;
        c.n = vector(0, 0, 1);
        c.gap = zGap;
        c.p = point(x.x(), x.y(), 0.5*zGap);
        c.nDot = Zero;
        c.centreBased = true;
        contacts.append(c);
    }

    // Lateral wall, radius R
    const scalar rho = tube::axialDistance(x);
    const scalar rGap = container.radius() - rho - a;
    if (rGap < band && rho > VSMALL)
    {
        const vector er(x.x()/rho, x.y()/rho, 0);
        const vector vh(bi.v().x(), bi.v().y(), 0);

        contact c;
        c.i = i;
        c.k = tubeWall;
        c.n = -er;
        c.gap = rGap;
        c.p = (rho + a + 0.5*rGap)*er + vector(0, 0, x.z());
        c.nDot = -(vh - er*(er & vh))/rho;
        c.centreBased = true;
        contacts.append(c);
    }
}


Foam::scalar Foam::rbd::sphereContacts::gap
(
    const contact& c,
    const UList<rigidBody>& bodies,
    const scalar a,
    const tube& container
)
{
    const point& xi = bodies[c.i].x();
    if (c.k == tubeBottom)
    {
        return xi.z() - a;
    }
    if (c.k == tubeWall)
    {
        return container.radius() - tube::axialDistance(xi) - a;
    }
    return mag(xi - bodies[c.k].x()) - 2*a;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cylinderContacts.H"
#include "floorSupport.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- Unit projection of d normal to the unit axis ax; a fixed normal
    //  direction when d is along the axis
    vector normalTo(const vector& d, const vector& ax)
    {
        vector w(d - ax*(ax & d));
        const scalar m = mag(w);
        if (m > 1e-12*max(mag(d), scalar(1)))
        {
            return w/m;
        }
        w = (mag(ax.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0));
        w -= ax*(ax & w);
        return w/mag(w);
    }
}


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::rbd::cylinderContacts::cylinderTube
(
    const label i,
    const rigidBody& bi,
    const scalar a,
    const scalar b,
    const tube& container,
    const scalar band,
    DynamicList<contact>& contacts,
    const UList<scalar>& rimAngles
)
{
    const point& x = bi.x();
    const scalar rb = Foam::sqrt(sqr(a) + sqr(b));
    const scalar Rt = container.radius();
    const bool nearBottom = x.z() - rb < band;
    const bool nearWall = tube::axialDistance(x) + rb > Rt - band;
    if (!nearBottom && !nearWall)
    {
        return;
    }

    const vector ax(bi.R() & vector(0, 0, 1));
    const label nRim = rimAngles.size();

    auto add = [&](const point& p, const label part, const scalar gap)
    {
        contact c;
        c.i = i;
        c.k = part;
        c.gap = gap;
        c.nDot = Zero;
        c.e = container.restitution();
        c.mu = container.friction();
        c.centreBased = false;
        c.ri = p - x;
        if (part == tubeBottom)
        {
            c.n = vector(0, 0, 1);
            c.p = point(p.x(), p.y(), 0.5*p.z());
            c.rk = point(p.x(), p.y(), 0);
        }
        else
        {
            const scalar rho = tube::axialDistance(p);
            const vector er(p.x()/rho, p.y()/rho, 0);
            c.n = -er;
            c.p = p + 0.5*gap*er;
            c.rk = p + gap*er;
        }
        if (nRim < 3)
        {
            // A circular rim: the point slides along it as the cylinder
            // turns about its axis (contact.H); d its radial direction
            const vector w(c.ri - ax*(ax & c.ri));
            c.axisI = ax;
            c.rhoI = -(c.n & w);
        }
        contacts.append(c);
    };

    // The rim points to try for the direction d (unit, normal to the
    // axis) from the rim centre c: the circle's point, or the vertices of
    // the polygon edge its angle falls on
    const tensor& R = bi.R();
    auto rimPoints = [&](const point& c, const vector& d, point q[2])
    {
        if (nRim < 3)
        {
            q[0] = c + a*d;
            return label(1);
        }
        const vector db(R.T() & d);
        const scalar phi = Foam::atan2(db.y(), db.x());
        label j = label
        (
            std::upper_bound(rimAngles.begin(), rimAngles.end(), phi)
          - rimAngles.begin()
        );
        const scalar theta[2] =
        {
            rimAngles[(j + nRim - 1) % nRim], rimAngles[j % nRim]
        };
        for (label k = 0; k < 2; ++k)
        {
            q[k] =
                c
              + a
               *(
                    R
                  & vector(Foam::cos(theta[k]), Foam::sin(theta[k]), 0)
                );
        }
        return label(2);
    };

    for (const scalar side : {-1.0, 1.0})
    {
        const point c(x + side*b*ax);
        point q[2];

        if (nearBottom && c.z() - a < band)
        {
            const vector w(normalTo(vector(0, 0, -1), ax));
            const vector u(ax ^ w);
            const label start = contacts.size();
            for (const vector& d : {w, u, -w, -u})
            {
                const label nq = rimPoints(c, d, q);
                for (label k = 0; k < nq; ++k)
                {
                    if (q[k].z() < band)
                    {
                        add(q[k], tubeBottom, q[k].z());
                    }
                }
            }
            {
                // The rim's points that one step can bring down, beside the
                // four candidates (floorSupport): the polygon's vertices,
                // or points of the circle every 360/nCircleSamples degrees
                // (material points: they turn with the body)
                const label kept = contacts.size();
                const label nSample = nRim >= 3 ? nRim : nCircleSamples;
                for (label k = 0; k < nSample; ++k)
                {
                    const scalar t =
                        nRim >= 3
                      ? rimAngles[k]
                      : constant::mathematical::twoPi*k/nSample;
                    const point p
                    (
                        c + a*(R & vector(Foam::cos(t), Foam::sin(t), 0))
                    );
                    if (p.z() < band)
                    {
                        add(p, tubeBottom, p.z());
                        contacts.last().axisI = Zero;
                        contacts.last().rhoI = 0;
                    }
                }
                const std::vector<contact> rim
                (
                    contacts.begin() + kept, contacts.end()
                );
                contacts.setSize(kept);
                floorSupport::addNear
                (
                    rim, floorNearSpan*band, 1e-9*a, start, contacts
                );
            }
        }

        if (nearWall && tube::axialDistance(c) + a > Rt - band)
        {
            vector er
            (
                tube::axialDistance(c) > VSMALL
              ? vector(c.x(), c.y(), 0) : vector(1, 0, 0)
            );
            // The fixed point from a start direction: a local maximum of
            // rho over the rim
            auto outward = [&](vector w)
            {
                for (label iter = 0; iter < 50; ++iter)
                {
                    const point p(c + a*w);
                    if (tube::axialDistance(p) < VSMALL)
                    {
                        break;
                    }
                    const vector wNew
                    (
                        normalTo(vector(p.x(), p.y(), 0), ax)
                    );
                    const scalar change = magSqr(wNew - w);
                    w = wNew;
                    if (change < 1e-20)
                    {
                        break;
                    }
                }
                return w;
            };
            auto rimRho = [&](const vector& d)
            {
                const label nq = rimPoints(c, d, q);
                scalar rho = 0;
                for (label k = 0; k < nq; ++k)
                {
                    rho = max(rho, tube::axialDistance(q[k]));
                }
                return rho;
            };
            const vector w0(normalTo(er, ax));
            vector w(outward(w0));

            // rho can have two maxima over a tilted rim near the axis (a
            // disc leaning across a narrow tube): the one found from e_r of
            // the centre may be the lower (a disc went 7 % of its diameter
            // through the wall). The global one: every vertex of a
            // polygonal rim, or the fixed points from four starts on a
            // circle; taken only where it is higher, so that every other
            // contact stays as it was
            {
                const scalar rhoFound = rimRho(w);
                vector wBest(w);
                scalar rhoBest = rhoFound;
                if (nRim >= 3)
                {
                    for (const scalar t : rimAngles)
                    {
                        const vector d
                        (
                            R & vector(Foam::cos(t), Foam::sin(t), 0)
                        );
                        const scalar rho = tube::axialDistance(c + a*d);
                        if (rho > rhoBest)
                        {
                            rhoBest = rho;
                            wBest = d;
                        }
                    }
                }
                else
                {
                    for (const vector& d0 : {-w0, ax ^ w0, w0 ^ ax})
                    {
                        const vector d(outward(d0));
                        const scalar rho = rimRho(d);
                        if (rho > rhoBest)
                        {
                            rhoBest = rho;
                            wBest = d;
                        }
                    }
                }
                if (rhoBest > rhoFound + 1e-12*Rt)
                {
                    w = wBest;
                }
            }
            const vector u(ax ^ w);
            for (const vector& d : {w, u, -w, -u})
            {
                const label nq = rimPoints(c, d, q);
                for (label k = 0; k < nq; ++k)
                {
                    const scalar rho = tube::axialDistance(q[k]);
                    if (rho > VSMALL && Rt - rho < band)
                    {
                        add(q[k], tubeWall, Rt - rho);
                    }
                }
            }
        }
    }
}


Foam::List<Foam::scalar> Foam::rbd::cylinderContacts::rimAngles
(
    const pointField& points,
    const scalar a
)
{
    std::vector<scalar> angles;
    for (const point& p : points)
    {
        if (mag(Foam::sqrt(sqr(p.x()) + sqr(p.y())) - a) <= 1e-9*a)
        {
            angles.push_back(Foam::atan2(p.y(), p.x()));
        }
    }
    std::sort(angles.begin(), angles.end());
    List<scalar> unique;
    for (const scalar t : angles)
    {
        if (unique.empty() || t - unique.last() > 1e-9)
        {
            unique.append(t);
        }
    }
    return unique;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cylinderContacts.H"
#include "floorSupport.H"
#include "containerContact.H"
#include "mathematicalConstants.H"

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


// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using namespace Foam::rbd;

    //- The contacts of the two rims of one cylinder (radius a) with the
    //  tube's bottom and wall: the candidate points of each rim circle,
    //  appended; e and mu are left to the caller
    class rimsInTube
    {
        const label i_;
        const rigidBody& bi_;
        const scalar a_;
        const tube& container_;
        const scalar band_;
        DynamicList<contact>& contacts_;

        //- The axis (world)
        const vector ax_;

    public:

        rimsInTube
        (
            const label i,
            const rigidBody& bi,
            const scalar a,
            const tube& container,
            const scalar band,
            DynamicList<contact>& contacts
        )
        :
            i_(i),
            bi_(bi),
            a_(a),
            container_(container),
            band_(band),
            contacts_(contacts),
            ax_(bi.R() & vector(0, 0, 1))
        {}

        //- Append the contact of rim point p with part (tubeBottom or
        //  tubeWall)
        void add(const point& p, const containerPart part) const
        {
            contact c(containerPointContact(i_, bi_.x(), p, part, container_));
            // The point slides along the rim as the cylinder turns about
            // its axis (contact.H); w its radial direction
            const vector w(c.ri - ax_*(ax_ & c.ri));
            c.axisI = ax_;
            c.rhoI = -(c.n & w);
            contacts_.append(c);
        }

        //- The rim point in the direction d (unit, normal to the axis)
        //  from the rim centre c
        point rimPoint(const point& c, const vector& d) const
        {
            return c + a_*d;
        }

        //- The bottom contacts of the rim centred at c: its lowest point
        //  and the points at 90, 180 and 270 degrees from it, then the
        //  points one step can bring down (floorSupport)
        void bottom(const point& c) const
        {
            const vector w(normalTo(vector(0, 0, -1), ax_));
            const vector u(ax_ ^ w);
            const label start = contacts_.size();
            for (const vector& d : {w, u, -w, -u})
            {
                const point q(rimPoint(c, d));
                if (q.z() < band_)
                {
                    add(q, tubeBottom);
                }
            }

            // The rim's points that one step can bring down, beside the
            // four candidates (floorSupport): points of the circle every
            // 360/nCircleSamples degrees (material points: they turn with
            // the body)
            const tensor& R = bi_.R();
            const label kept = contacts_.size();
            const label nSample = cylinderContacts::nCircleSamples;
            for (label k = 0; k < nSample; ++k)
            {
                const scalar t = constant::mathematical::twoPi*k/nSample;
                const point p
                (
                    c + a_*(R & vector(Foam::cos(t), Foam::sin(t), 0))
                );
                if (p.z() < band_)
                {
                    add(p, tubeBottom);
                    contacts_.last().axisI = Zero;
                    contacts_.last().rhoI = 0;
                }
            }
            const std::vector<contact> rim
            (
                contacts_.begin() + kept, contacts_.end()
            );
            contacts_.setSize(kept);
            floorSupport::addNear
            (
                rim, floorNearSpan*band_, 1e-9*a_, start, contacts_
            );
        }

        //- The fixed point of "the rim point furthest along e_r of the
        //  last one" from the start direction w: a local maximum of rho
        //  over the rim centred at c
        vector outward(const point& c, vector w) const
        {
            for (label iter = 0; iter < 50; ++iter)
            {
                const point p(c + a_*w);
                if (tube::axialDistance(p) < VSMALL)
                {
                    break;
                }
                const vector wNew(normalTo(vector(p.x(), p.y(), 0), ax_));
                const scalar change = magSqr(wNew - w);
                w = wNew;
                if (change < 1e-20)
                {
                    break;
                }
            }
            return w;
        }

        //- rho of the rim point in direction d
        scalar rimRho(const point& c, const vector& d) const
        {
            return tube::axialDistance(rimPoint(c, d));
        }

        //- The direction of the rim point of largest rho. rho can have two
        //  maxima over a tilted rim near the axis (a disc leaning across a
        //  narrow tube): the one found from e_r of the centre may be the
        //  lower (a disc went 7 % of its diameter through the wall). The
        //  global one: the fixed points from four starts on the circle;
        //  taken only where it is higher, so that every other contact
        //  stays as it was
        vector outermost(const point& c) const
        {
            const vector er
            (
                tube::axialDistance(c) > VSMALL
              ? vector(c.x(), c.y(), 0) : vector(1, 0, 0)
            );
            const vector w0(normalTo(er, ax_));
            const vector w(outward(c, w0));

            const scalar rhoFound = rimRho(c, w);
            vector wBest(w);
            scalar rhoBest = rhoFound;
            for (const vector& d0 : {-w0, ax_ ^ w0, w0 ^ ax_})
            {
                const vector d(outward(c, d0));
                const scalar rho = rimRho(c, d);
                if (rho > rhoBest)
                {
                    rhoBest = rho;
                    wBest = d;
                }
            }
            return
                rhoBest > rhoFound + 1e-12*container_.radius() ? wBest : w;
        }

        //- The wall contacts of the rim centred at c: its outermost point
        //  and the points at 90, 180 and 270 degrees from it
        void wall(const point& c) const
        {
            const scalar Rt = container_.radius();
            const vector w(outermost(c));
            const vector u(ax_ ^ w);
            for (const vector& d : {w, u, -w, -u})
            {
                const point q(rimPoint(c, d));
                const scalar rho = tube::axialDistance(q);
                if (rho > VSMALL && Rt - rho < band_)
                {
                    add(q, tubeWall);
                }
            }
        }
    };
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
    DynamicList<contact>& contacts
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

    const rimsInTube rims(i, bi, a, container, band, contacts);
    const vector ax(bi.R() & vector(0, 0, 1));
    for (const scalar side : {-1.0, 1.0})
    {
        const point c(x + side*b*ax);
        if (nearBottom && c.z() - a < band)
        {
            rims.bottom(c);
        }
        if (nearWall && tube::axialDistance(c) + a > Rt - band)
        {
            rims.wall(c);
        }
    }
}


// ************************************************************************* //

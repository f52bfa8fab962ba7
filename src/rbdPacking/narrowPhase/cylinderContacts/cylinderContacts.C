/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cylinderContacts.H"
#include "floorSupport.H"
#include "containerContact.H"
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


// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using namespace Foam::rbd;

    //- The contacts of the two rims of one cylinder (radius a) with the
    //  tube's bottom and wall: the candidates of each rim (circle points or
    //  polygon vertices), appended; e and mu are left to the caller
    class rimsInTube
    {
        const label i_;
        const rigidBody& bi_;
        const scalar a_;
        const tube& container_;
        const scalar band_;
        DynamicList<contact>& contacts_;
        const UList<scalar>& rimAngles_;

        //- The axis (world) and the vertices per rim (< 3: circles)
        const vector ax_;
        const label nRim_;

    public:

        rimsInTube
        (
            const label i,
            const rigidBody& bi,
            const scalar a,
            const tube& container,
            const scalar band,
            DynamicList<contact>& contacts,
            const UList<scalar>& rimAngles
        )
        :
            i_(i),
            bi_(bi),
            a_(a),
            container_(container),
            band_(band),
            contacts_(contacts),
            rimAngles_(rimAngles),
            ax_(bi.R() & vector(0, 0, 1)),
            nRim_(rimAngles.size())
        {}

        //- Append the contact of rim point p with part (tubeBottom or
        //  tubeWall)
        void add(const point& p, const containerPart part) const
        {
            contact c(containerPointContact(i_, bi_.x(), p, part, container_));
            if (nRim_ < 3)
            {
                // A circular rim: the point slides along it as the
                // cylinder turns about its axis (contact.H); d its radial
                // direction
                const vector w(c.ri - ax_*(ax_ & c.ri));
                c.axisI = ax_;
                c.rhoI = -(c.n & w);
            }
            contacts_.append(c);
        }

        //- The rim points to try for the direction d (unit, normal to the
        //  axis) from the rim centre c: the circle's point, or the
        //  vertices of the polygon edge its angle falls on; returns how
        //  many (1 or 2)
        label rimPoints(const point& c, const vector& d, point q[2]) const
        {
            if (nRim_ < 3)
            {
                q[0] = c + a_*d;
                return 1;
            }
            const tensor& R = bi_.R();
            const vector db(R.T() & d);
            const scalar phi = Foam::atan2(db.y(), db.x());
            const label j = label
            (
                std::upper_bound(rimAngles_.begin(), rimAngles_.end(), phi)
              - rimAngles_.begin()
            );
            const scalar theta[2] =
            {
                rimAngles_[(j + nRim_ - 1) % nRim_], rimAngles_[j % nRim_]
            };
            for (label k = 0; k < 2; ++k)
            {
                q[k] =
                    c
                  + a_
                   *(
                        R
                      & vector(Foam::cos(theta[k]), Foam::sin(theta[k]), 0)
                    );
            }
            return 2;
        }

        //- The bottom contacts of the rim centred at c: its lowest point
        //  and the points at 90, 180 and 270 degrees from it, then the
        //  points one step can bring down (floorSupport)
        void bottom(const point& c) const
        {
            const vector w(normalTo(vector(0, 0, -1), ax_));
            const vector u(ax_ ^ w);
            const label start = contacts_.size();
            point q[2];
            for (const vector& d : {w, u, -w, -u})
            {
                const label nq = rimPoints(c, d, q);
                for (label k = 0; k < nq; ++k)
                {
                    if (q[k].z() < band_)
                    {
                        add(q[k], tubeBottom);
                    }
                }
            }

            // The rim's points that one step can bring down, beside the
            // four candidates (floorSupport): the polygon's vertices, or
            // points of the circle every 360/nCircleSamples degrees
            // (material points: they turn with the body)
            const tensor& R = bi_.R();
            const label kept = contacts_.size();
            const label nSample =
                nRim_ >= 3 ? nRim_ : cylinderContacts::nCircleSamples;
            for (label k = 0; k < nSample; ++k)
            {
                const scalar t =
                    nRim_ >= 3
                  ? rimAngles_[k]
                  : constant::mathematical::twoPi*k/nSample;
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

        //- The largest rho of the rim points tried for direction d
        scalar rimRho(const point& c, const vector& d) const
        {
            point q[2];
            const label nq = rimPoints(c, d, q);
            scalar rho = 0;
            for (label k = 0; k < nq; ++k)
            {
                rho = max(rho, tube::axialDistance(q[k]));
            }
            return rho;
        }

        //- The direction of the rim point of largest rho. rho can have two
        //  maxima over a tilted rim near the axis (a disc leaning across a
        //  narrow tube): the one found from e_r of the centre may be the
        //  lower (a disc went 7 % of its diameter through the wall). The
        //  global one: every vertex of a polygonal rim, or the fixed
        //  points from four starts on a circle; taken only where it is
        //  higher, so that every other contact stays as it was
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
            if (nRim_ >= 3)
            {
                const tensor& R = bi_.R();
                for (const scalar t : rimAngles_)
                {
                    const vector d(R & vector(Foam::cos(t), Foam::sin(t), 0));
                    const scalar rho = tube::axialDistance(c + a_*d);
                    if (rho > rhoBest)
                    {
                        rhoBest = rho;
                        wBest = d;
                    }
                }
            }
            else
            {
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
            point q[2];
            for (const vector& d : {w, u, -w, -u})
            {
                const label nq = rimPoints(c, d, q);
                for (label k = 0; k < nq; ++k)
                {
                    const scalar rho = tube::axialDistance(q[k]);
                    if (rho > VSMALL && Rt - rho < band_)
                    {
                        add(q[k], tubeWall);
                    }
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

    const rimsInTube rims(i, bi, a, container, band, contacts, rimAngles);
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

/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshSolidSet.H"
#include "volumeBelowPlane.H"
#include "error.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <cmath>

using Foam::constant::mathematical::pi;
using Foam::constant::mathematical::twoPi;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using Foam::rbd::twiceAreaXY;

    //- Twice the signed area of the 2D triangle (a, b, q)
    inline scalar cross2D
    (
        const scalar ax, const scalar ay,
        const scalar bx, const scalar by,
        const scalar qx, const scalar qy
    )
    {
        return (bx - ax)*(qy - ay) - (by - ay)*(qx - ax);
    }

    //- Distance of the origin from the xy projection of the triangle
    scalar originDistanceXY(const point& a, const point& b, const point& c)
    {
        const scalar A = twiceAreaXY(a, b, c);
        const scalar s0 = cross2D(a.x(), a.y(), b.x(), b.y(), 0, 0);
        const scalar s1 = cross2D(b.x(), b.y(), c.x(), c.y(), 0, 0);
        const scalar s2 = cross2D(c.x(), c.y(), a.x(), a.y(), 0, 0);
        if
        (
            A != 0
         && ((A > 0 && s0 >= 0 && s1 >= 0 && s2 >= 0)
          || (A < 0 && s0 <= 0 && s1 <= 0 && s2 <= 0))
        )
        {
            return 0;
        }
        scalar d2 = GREAT;
        const point* v[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k)
        {
            const point& u = *v[k];
            const point& w = *v[(k + 1) % 3];
            const scalar dx = w.x() - u.x();
            const scalar dy = w.y() - u.y();
            const scalar l2 = dx*dx + dy*dy;
            scalar t = l2 > 0 ? -(u.x()*dx + u.y()*dy)/l2 : 0;
            t = std::min(std::max(t, scalar(0)), scalar(1));
            d2 = std::min(d2, sqr(u.x() + t*dx) + sqr(u.y() + t*dy));
        }
        return std::sqrt(d2);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::rbd::meshSolidSet::meshSolidSet
(
    const triMesh& body,
    const UList<point>& centres,
    const UList<tensor>& rotations
)
:
    body_(body),
    centres_(centres),
    rotations_(rotations),
    axial_(centres.size()),
    radial_(centres.size()),
    cached_(-1),
    points_()
{
    if (centres.size() != rotations.size())
    {
        FatalErrorInFunction
            << centres.size() << " centres but " << rotations.size()
            << " rotations" << exit(FatalError);
    }
    if (!(body_.volume() > 0))
    {
        FatalErrorInFunction
            << "The body mesh encloses no positive volume ("
            << body_.volume() << " m^3): not closed and outward"
            << exit(FatalError);
    }

    forAll(centres_, i)
    {
        const pointField& p = posed(i);
        scalarMinMax z;
        scalar rMax = 0;
        for (const point& x : p)
        {
            z.add(x.z());
            rMax = std::max(rMax, std::hypot(x.x(), x.y()));
        }
        scalar rMin = GREAT;
        for (const triFace& f : body_.faces())
        {
            rMin = std::min
            (
                rMin,
                originDistanceXY(p[f[0]], p[f[1]], p[f[2]])
            );
            if (rMin == 0)
            {
                break;
            }
        }
        axial_[i] = z;
        radial_[i] = scalarMinMax(rMin, rMax);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::pointField& Foam::rbd::meshSolidSet::posed(const label i) const
{
    if (cached_ != i)
    {
        points_ = body_.transformedPoints(rotations_[i], centres_[i]);
        cached_ = i;
    }
    return points_;
}


Foam::scalar Foam::rbd::meshSolidSet::volumeBelow
(
    const label i,
    const scalar c
) const
{
    if (c <= axial_[i].min())
    {
        return 0;
    }
    const pointField& p = posed(i);

    // Sum of A_xy (zbar - c) over the parts of the triangles below c
    scalar V = 0;
    for (const triFace& f : body_.faces())
    {
        addVolumeBelowPlane(p[f[0]], p[f[1]], p[f[2]], c, V);
    }
    return V;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::rbd::meshSolidSet::volume
(
    const label i,
    const scalar zLow,
    const scalar zHigh
) const
{
    if (!(zHigh > zLow))
    {
        return 0;
    }
    const scalar lo = std::max(zLow, axial_[i].min());
    const scalar hi = std::min(zHigh, axial_[i].max());
    if (!(hi > lo))
    {
        return 0;
    }
    const scalar below = hi >= axial_[i].max()
      ? pelletVolume() : volumeBelow(i, hi);
    return below - volumeBelow(i, lo);
}


Foam::scalar Foam::rbd::meshSolidSet::cylinderArea
(
    const label i,
    const scalar r,
    const scalar zLow,
    const scalar zHigh
) const
{
    if
    (
        !(r > 0) || !(zHigh > zLow)
     || r < radial_[i].min() || r > radial_[i].max()
     || zHigh <= axial_[i].min() || zLow >= axial_[i].max()
    )
    {
        return 0;
    }

    const pointField& p = posed(i);
    const scalar r2 = r*r;
    const scalar height = zHigh - zLow;

    scalar sum = 0;
    scalar angles[6];
    scalar pieces[12];

    for (const triFace& f : body_.faces())
    {
        const point& a = p[f[0]];
        const point& b = p[f[1]];
        const point& c = p[f[2]];

        if (std::max(a.z(), std::max(b.z(), c.z())) <= zLow)
        {
            continue;
        }
        const scalar ra2 = sqr(a.x()) + sqr(a.y());
        const scalar rb2 = sqr(b.x()) + sqr(b.y());
        const scalar rc2 = sqr(c.x()) + sqr(c.y());
        if (std::max(ra2, std::max(rb2, rc2)) < r2)
        {
            continue;
        }
        const scalar A2 = twiceAreaXY(a, b, c);
        if (A2 == 0)
        {
            continue;
        }

        // Crossings of the circle with the projected edges, each edge
        // from its lower point index, so that both triangles of an edge
        // get the same angles
        int nAngles = 0;
        for (int k = 0; k < 3; ++k)
        {
            label iu = f[k];
            label iw = f[(k + 1) % 3];
            if (iu > iw)
            {
                std::swap(iu, iw);
            }
            const point& u = p[iu];
            const point& w = p[iw];
            const scalar dx = w.x() - u.x();
            const scalar dy = w.y() - u.y();
            const scalar qa = dx*dx + dy*dy;
            if (!(qa > 0))
            {
                continue;
            }
            const scalar qb = u.x()*dx + u.y()*dy;
            const scalar qc = sqr(u.x()) + sqr(u.y()) - r2;
            const scalar disc = qb*qb - qa*qc;
            if (disc < 0)
            {
                continue;
            }
            const scalar s = std::sqrt(disc);
            for (const scalar t : {(-qb - s)/qa, (-qb + s)/qa})
            {
                if (t >= 0 && t <= 1)
                {
                    angles[nAngles++] = std::atan2
                    (
                        u.y() + t*dy, u.x() + t*dx
                    );
                }
            }
        }

        // Is the generator at theta inside the projected triangle?
        auto inside = [&](const scalar theta)
        {
            const scalar qx = r*std::cos(theta);
            const scalar qy = r*std::sin(theta);
            const scalar s0 = cross2D(a.x(), a.y(), b.x(), b.y(), qx, qy);
            const scalar s1 = cross2D(b.x(), b.y(), c.x(), c.y(), qx, qy);
            const scalar s2 = cross2D(c.x(), c.y(), a.x(), a.y(), qx, qy);
            return
                A2 > 0
              ? (s0 >= 0 && s1 >= 0 && s2 >= 0)
              : (s0 <= 0 && s1 <= 0 && s2 <= 0);
        };

        // The plane over the triangle: z = alpha + gx x + gy y; on the
        // circle z = alpha + rho cos(theta - phi)
        const scalar gx =
            ((b.z() - a.z())*(c.y() - a.y())
           - (c.z() - a.z())*(b.y() - a.y()))/A2;
        const scalar gy =
            ((c.z() - a.z())*(b.x() - a.x())
           - (b.z() - a.z())*(c.x() - a.x()))/A2;
        const scalar alpha = a.z() - gx*a.x() - gy*a.y();
        const scalar rho = r*std::hypot(gx, gy);
        const scalar phi = std::atan2(gy, gx);

        // Height at theta by barycentric interpolation (bounded by the
        // vertices' heights even for steep triangles)
        auto zAt = [&](const scalar theta)
        {
            const scalar qx = r*std::cos(theta);
            const scalar qy = r*std::sin(theta);
            scalar l0 = cross2D(b.x(), b.y(), c.x(), c.y(), qx, qy)/A2;
            scalar l1 = cross2D(c.x(), c.y(), a.x(), a.y(), qx, qy)/A2;
            scalar l2 = cross2D(a.x(), a.y(), b.x(), b.y(), qx, qy)/A2;
            l0 = std::max(l0, scalar(0));
            l1 = std::max(l1, scalar(0));
            l2 = std::max(l2, scalar(0));
            const scalar l = l0 + l1 + l2;
            return (l0*a.z() + l1*b.z() + l2*c.z())/l;
        };

        // Integral of clamp(z) - zLow over an arc inside the triangle
        auto arcIntegral = [&](const scalar t1, const scalar t2)
        {
            int n = 0;
            pieces[n++] = t1;
            if (rho > 0)
            {
                for (const scalar zl : {zLow, zHigh})
                {
                    const scalar k = (zl - alpha)/rho;
                    if (k > -1 && k < 1)
                    {
                        const scalar ac = std::acos(k);
                        for (scalar th : {phi + ac, phi - ac})
                        {
                            th -= twoPi*std::floor((th - t1)/twoPi);
                            if (th > t1 && th < t2)
                            {
                                pieces[n++] = th;
                            }
                        }
                    }
                }
            }
            pieces[n++] = t2;
            std::sort(pieces + 1, pieces + n - 1);

            scalar I = 0;
            for (int k = 0; k + 1 < n; ++k)
            {
                const scalar d = pieces[k + 1] - pieces[k];
                if (!(d > 0))
                {
                    continue;
                }
                const scalar tm = 0.5*(pieces[k] + pieces[k + 1]);
                const scalar zm = zAt(tm);
                if (zm <= zLow)
                {
                    continue;
                }
                if (zm >= zHigh)
                {
                    I += height*d;
                    continue;
                }
                I +=
                    d*(zm - zLow)
                  + rho*std::cos(tm - phi)*(2*std::sin(0.5*d) - d);
            }
            return I;
        };

        scalar I = 0;
        if (nAngles == 0)
        {
            if (inside(0))
            {
                I = arcIntegral(0, twoPi);
            }
        }
        else
        {
            std::sort(angles, angles + nAngles);
            for (int k = 0; k < nAngles; ++k)
            {
                const scalar t1 = angles[k];
                const scalar t2 =
                    k + 1 < nAngles ? angles[k + 1] : angles[0] + twoPi;
                if (t2 > t1 && inside(0.5*(t1 + t2)))
                {
                    I += arcIntegral(t1, t2);
                }
            }
        }

        sum += (A2 > 0 ? I : -I);
    }

    return r*sum;
}


// ************************************************************************* //

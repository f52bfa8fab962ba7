/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "prismProfile.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    inline scalar cross2(const vector2D& a, const vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    }

    //- Relative tolerance of "strictly inside a circle" [-]
    const scalar insideTol = 1e-12;

    //- Largest distance from o of a point of the arc [m]
    scalar farthest(const Foam::rbd::prismProfile::arc& a, const vector2D& o)
    {
        const vector2D d(a.c - o);
        const scalar m = mag(d);
        if (m < VSMALL)
        {
            return a.r;
        }
        // The circle's farthest point from o is along (c - o)
        if (a.within(d))
        {
            return m + a.r;
        }
        return max(mag(a.c + a.r*a.u0 - o), mag(a.c + a.r*a.u1 - o));
    }
}


// * * * * * * * * * * * * * * * * Arc  * * * * * * * * * * * * * * * * * * //

bool Foam::rbd::prismProfile::arc::fullCircle() const
{
    return span >= constant::mathematical::twoPi*(1 - 1e-12);
}


bool Foam::rbd::prismProfile::arc::within(const vector2D& d) const
{
    if (fullCircle())
    {
        return true;
    }
    if (span <= constant::mathematical::pi)
    {
        return cross2(u0, d) >= 0 && cross2(d, u1) >= 0;
    }
    // The complement spans less than pi
    return !(cross2(u1, d) > 0 && cross2(d, u0) > 0);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::prismProfile::prismProfile
(
    const List<vector2D>& discCentres,
    const List<scalar>& discRadii,
    const List<vector2D>& holeCentres,
    const List<scalar>& holeRadii,
    const scalar halfHeight
)
:
    discCentres_(discCentres),
    discRadii_(discRadii),
    holeCentres_(holeCentres),
    holeRadii_(holeRadii),
    h_(halfHeight),
    arcs_(),
    Q_(tensor::I),
    t_(Zero),
    boundingRadius_(0),
    outerRadius_(0)
{
    if
    (
        discCentres_.empty()
     || discCentres_.size() != discRadii_.size()
     || holeCentres_.size() != holeRadii_.size()
     || !(h_ > 0)
    )
    {
        FatalErrorInFunction
            << "A prism needs at least one disc, a radius per centre and a"
            << " positive half height" << exit(FatalError);
    }
    findArcs();
    setFrame(tensor::I, Zero);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::rbd::prismProfile::findArcs()
{
    using constant::mathematical::twoPi;

    const label nDiscs = discCentres_.size();
    const label nCircles = nDiscs + holeCentres_.size();
    auto centre = [&](const label j)
    {
        return j < nDiscs ? discCentres_[j] : holeCentres_[j - nDiscs];
    };
    auto radius = [&](const label j)
    {
        return j < nDiscs ? discRadii_[j] : holeRadii_[j - nDiscs];
    };
    auto strictlyIn = [&](const vector2D& p, const label j)
    {
        return mag(p - centre(j)) < radius(j)*(1 - insideTol);
    };

    std::vector<arc> found;
    for (label i = 0; i < nCircles; ++i)
    {
        const vector2D ci(centre(i));
        const scalar ri = radius(i);
        const bool solid = i < nDiscs;

        std::vector<scalar> cuts;
        for (label j = 0; j < nCircles; ++j)
        {
            if (j == i)
            {
                continue;
            }
            const vector2D dc(centre(j) - ci);
            const scalar D = mag(dc);
            const scalar rj = radius(j);
            if (D <= VSMALL || D >= ri + rj || D <= mag(ri - rj))
            {
                continue;
            }
            const scalar a = (sqr(ri) - sqr(rj) + sqr(D))/(2*D);
            const scalar alpha = Foam::acos(max(-1.0, min(1.0, a/ri)));
            const scalar phi = Foam::atan2(dc.y(), dc.x());
            for (const scalar t : {phi - alpha, phi + alpha})
            {
                scalar tt = std::fmod(t, twoPi);
                if (tt < 0)
                {
                    tt += twoPi;
                }
                cuts.push_back(tt);
            }
        }
        std::sort(cuts.begin(), cuts.end());

        // The pieces [cuts[k], cuts[k+1]] (wrapping), or the whole circle
        std::vector<std::pair<scalar, scalar>> pieces;
        if (cuts.empty())
        {
            pieces.push_back({0, twoPi});
        }
        else
        {
            for (size_t k = 0; k < cuts.size(); ++k)
            {
                const scalar a = cuts[k];
                const scalar b =
                    k + 1 < cuts.size() ? cuts[k + 1] : cuts[0] + twoPi;
                if (b - a > 1e-12)
                {
                    pieces.push_back({a, b - a});
                }
            }
        }

        for (const auto& pc : pieces)
        {
            const scalar tm = pc.first + 0.5*pc.second;
            const vector2D m(ci + ri*vector2D(Foam::cos(tm), Foam::sin(tm)));
            bool inDisc = false;
            bool inHole = false;
            for (label j = 0; j < nCircles; ++j)
            {
                if (j != i && strictlyIn(m, j))
                {
                    (j < nDiscs ? inDisc : inHole) = true;
                }
            }
            // A disc's arc is boundary where no other disc covers it and
            // no hole removes it; a hole's where a disc is around it and
            // no other hole
            const bool exposed = (solid ? !inDisc : inDisc) && !inHole;
            if (!exposed)
            {
                continue;
            }
            arc a;
            a.c = ci;
            a.r = ri;
            a.t0 = pc.first;
            a.span = pc.second;
            a.sense = solid ? 1 : -1;
            a.u0 = vector2D(Foam::cos(a.t0), Foam::sin(a.t0));
            a.u1 =
                vector2D
                (
                    Foam::cos(a.t0 + a.span), Foam::sin(a.t0 + a.span)
                );
            found.push_back(a);
        }
    }

    arcs_.setSize(label(found.size()));
    forAll(arcs_, k)
    {
        arcs_[k] = found[k];
    }
    if (arcs_.empty())
    {
        FatalErrorInFunction
            << "The cross-section has no boundary (holes cover the discs)"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vector2D> Foam::rbd::prismProfile::onCircle
(
    const label n,
    const scalar r
)
{
    List<vector2D> points(n);
    forAll(points, k)
    {
        const scalar theta = constant::mathematical::twoPi*k/n;
        points[k] = r*vector2D(Foam::cos(theta), Foam::sin(theta));
    }
    return points;
}


void Foam::rbd::prismProfile::setFrame(const tensor& Q, const vector& t)
{
    Q_ = Q;
    t_ = t;

    // The body origin in the profile frame
    const vector o(Q_.T() & (-t_));
    const vector2D o2(o.x(), o.y());
    const scalar dz = max(mag(h_ - o.z()), mag(-h_ - o.z()));
    boundingRadius_ = 0;
    outerRadius_ = 0;
    for (const arc& a : arcs_)
    {
        boundingRadius_ =
            max(boundingRadius_, Foam::sqrt(sqr(farthest(a, o2)) + sqr(dz)));
        outerRadius_ = max(outerRadius_, farthest(a, vector2D::zero));
    }
}


bool Foam::rbd::prismProfile::hasConcaveArc() const
{
    for (const arc& a : arcs_)
    {
        if (a.sense < 0)
        {
            return true;
        }
    }
    return false;
}


bool Foam::rbd::prismProfile::hasOffAxisHole() const
{
    // Off the axis by more than a millionth of the profile's size: the
    // shapes place their holes on a circle of a radius that is either
    // zero or a fraction of the diameter
    forAll(holeCentres_, j)
    {
        if (mag(holeCentres_[j]) > 1e-6*outerRadius_)
        {
            return true;
        }
    }
    return false;
}


bool Foam::rbd::prismProfile::inside2D(const vector2D& p) const
{
    bool in = false;
    forAll(discCentres_, j)
    {
        if (magSqr(p - discCentres_[j]) < sqr(discRadii_[j]))
        {
            in = true;
            break;
        }
    }
    if (!in)
    {
        return false;
    }
    forAll(holeCentres_, j)
    {
        if (magSqr(p - holeCentres_[j]) <= sqr(holeRadii_[j]))
        {
            return false;
        }
    }
    return true;
}


Foam::scalar Foam::rbd::prismProfile::distance2D
(
    const vector2D& p,
    vector2D& g,
    label& nearestArc
) const
{
    scalar best = GREAT;
    vector2D q(Zero);
    label bestArc = 0;

    // The outward normal where the nearest point lies inside an arc: its
    // radial direction, exact to round-off at any distance (p - q loses
    // its digits close to the wall)
    vector2D radial(Zero);
    bool inArc = false;
    forAll(arcs_, k)
    {
        const arc& a = arcs_[k];
        const vector2D d(p - a.c);
        const scalar rho = mag(d);
        scalar dist;
        vector2D qk;
        bool inside = false;
        if (rho > VSMALL && a.within(d))
        {
            dist = mag(rho - a.r);
            qk = a.c + (a.r/rho)*d;
            inside = true;
        }
        else if (a.fullCircle())
        {
            dist = a.r;
            qk = a.c + a.r*vector2D(1, 0);
        }
        else
        {
            const vector2D q0(a.c + a.r*a.u0);
            const vector2D q1(a.c + a.r*a.u1);
            const scalar d0 = mag(p - q0);
            const scalar d1 = mag(p - q1);
            dist = d0 < d1 ? d0 : d1;
            qk = d0 < d1 ? q0 : q1;
        }
        if (dist < best)
        {
            best = dist;
            q = qk;
            bestArc = k;
            inArc = inside;
            if (inside)
            {
                radial = (a.sense/rho)*d;
            }
        }
    }

    nearestArc = inArc ? bestArc : -1;
    const scalar s = inside2D(p) ? -1 : 1;
    const arc& a = arcs_[bestArc];
    if (inArc)
    {
        g = radial;
    }
    else if (best > 1e-12*a.r)
    {
        g = (s/best)*(p - q);
    }
    else
    {
        // At an end of an arc: the outward normal of the arc there
        g = (a.sense/a.r)*(q - a.c);
    }
    return s*best;
}


Foam::scalar Foam::rbd::prismProfile::signedDistance
(
    const point& p,
    vector& g,
    label& nearestArc,
    part& where
) const
{
    vector2D g2;
    const scalar d = distance2D(vector2D(p.x(), p.y()), g2, nearestArc);
    const scalar sz = p.z() < 0 ? -1 : 1;
    const scalar w = mag(p.z()) - h_;

    if (d > 0 && w > 0)
    {
        // Nearest a rim
        const scalar m = Foam::sqrt(sqr(d) + sqr(w));
        g = vector(d*g2.x(), d*g2.y(), w*sz)/m;
        where = part::rim;
        return m;
    }
    if (d > w)
    {
        // Nearest the lateral wall (inside or outside)
        g = vector(g2.x(), g2.y(), 0);
        where = part::wall;
        return d;
    }
    // Nearest an end face
    g = vector(0, 0, sz);
    where = part::face;
    return w;
}


Foam::scalar Foam::rbd::prismProfile::area() const
{
    scalar A = 0;
    for (const arc& a : arcs_)
    {
        const scalar t1 = a.t0 + a.span;
        const scalar piece =
            0.5
           *(
                sqr(a.r)*a.span
              + a.r
               *(
                    a.c.x()*(Foam::sin(t1) - Foam::sin(a.t0))
                  - a.c.y()*(Foam::cos(t1) - Foam::cos(a.t0))
                )
            );
        A += a.sense*piece;
    }
    return A;
}


// ************************************************************************* //

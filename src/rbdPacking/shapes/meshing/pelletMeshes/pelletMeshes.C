/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pelletMeshes.H"
#include "prismProfile.H"
#include <stdexcept>
#include <string>
#include "cgalMeshTools.H"
#include "mathematicalConstants.H"
#include "error.H"

using namespace Foam::constant::mathematical;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- A circular arc, counter-clockwise for sweep > 0 [m, rad]
    struct arc
    {
        vector2D centre;
        scalar radius;
        scalar start;
        scalar sweep;
        label minSegments;
    };

    //- Closed boundary curve: arcs end to end
    typedef List<arc> arcLoop;

    //- Planar region: outer loop counter-clockwise, holes clockwise
    struct region
    {
        List<arcLoop> loops;
        label nHoles;
        scalar area;
        scalar perimeter;
    };

    arc circle(const vector2D& c, const scalar r, const bool hole)
    {
        return arc{c, r, 0, hole ? -twoPi : twoPi, 16};
    }


    //- Boundary points (at spacing about h) and loops of point indices
    void sampleBoundary
    (
        const region& reg,
        const scalar h,
        List<vector2D>& pts,
        labelListList& loops
    )
    {
        DynamicList<vector2D> p;
        loops.setSize(reg.loops.size());
        forAll(reg.loops, loopi)
        {
            DynamicList<label> loop;
            for (const arc& a : reg.loops[loopi])
            {
                const label n = max
                (
                    a.minSegments,
                    label(std::round(mag(a.sweep)*a.radius/h))
                );
                for (label i = 0; i < n; ++i)
                {
                    const scalar phi = a.start + a.sweep*i/n;
                    loop.append(p.size());
                    p.append
                    (
                        a.centre
                      + a.radius*vector2D(std::cos(phi), std::sin(phi))
                    );
                }
            }
            loops[loopi].transfer(loop);
        }
        pts.transfer(p);
    }


    //- Signed area enclosed by a loop of arcs (Green's theorem,
    //  A = 1/2 closed integral of x dy - y dx; per arc of centre c, radius
    //  r from angle s to e = s + sweep:
    //  r cx (sin e - sin s) - r cy (cos e - cos s) + r^2 sweep) [m^2]
    scalar loopArea(const arcLoop& loop)
    {
        scalar twiceA = 0;
        for (const arc& a : loop)
        {
            const scalar s = a.start;
            const scalar e = a.start + a.sweep;
            twiceA +=
                a.radius*a.centre.x()*(std::sin(e) - std::sin(s))
              - a.radius*a.centre.y()*(std::cos(e) - std::cos(s))
              + sqr(a.radius)*a.sweep;
        }
        return 0.5*twiceA;
    }


    //- Signed (shoelace) area of the polygon loop of pts [m^2]
    scalar polygonArea(const List<vector2D>& pts, const labelList& loop)
    {
        scalar twiceA = 0;
        forAll(loop, i)
        {
            const vector2D& a = pts[loop[i]];
            const vector2D& b = pts[loop[(i + 1) % loop.size()]];
            twiceA += a.x()*b.y() - a.y()*b.x();
        }
        return 0.5*twiceA;
    }


    //- The boundary points moved so that every loop's polygon encloses
    //  the area of its curve: the points of each loop move along their
    //  arc's radius, r -> r + delta, one delta per loop (delta > 0 for an
    //  inscribed polygon: the outer surface moves out of the solid, a
    //  hole's wall into the hole); the corners where two arcs of a loop
    //  meet (a lobed pellet's valleys) stay where they are. The polygon
    //  area is quadratic in delta: Newton's method from delta = 0, with
    //  dA/ddelta = 1/2 sum over moved points of u_i x (p_i+1 - p_i-1)
    //  (u_i the unit radius), converges in 3 or 4 steps to round-off.
    //  For a full circle cut into n segments this is the closed form
    //  r' = r sqrt(2 pi/(n sin(2 pi/n))).
    List<vector2D> areaTruePoints
    (
        const region& reg,
        const List<vector2D>& pts,
        const labelListList& loops,
        const scalar h,
        scalarList& offsets
    )
    {
        List<vector2D> moved(pts);
        offsets.setSize(loops.size());
        forAll(loops, loopi)
        {
            const labelList& loop = loops[loopi];
            const arcLoop& arcs = reg.loops[loopi];

            // Unit radius of every point of the loop (zero at corners), in
            // the order sampleBoundary put them
            List<vector2D> u(loop.size(), vector2D::zero);
            label k = 0;
            for (const arc& a : arcs)
            {
                const label n = max
                (
                    a.minSegments,
                    label(std::round(mag(a.sweep)*a.radius/h))
                );
                for (label i = 0; i < n; ++i, ++k)
                {
                    if (i == 0 && arcs.size() > 1)
                    {
                        continue;
                    }
                    const scalar phi = a.start + a.sweep*i/n;
                    u[k] = vector2D(std::cos(phi), std::sin(phi));
                }
            }

            const scalar target = loopArea(arcs);
            scalar delta = 0;
            for (label iter = 0; iter < 20; ++iter)
            {
                forAll(loop, i)
                {
                    moved[loop[i]] = pts[loop[i]] + delta*u[i];
                }
                const scalar miss = polygonArea(moved, loop) - target;
                if (mag(miss) <= 1e-15*mag(target))
                {
                    break;
                }
                scalar slope = 0;
                forAll(loop, i)
                {
                    const vector2D d =
                        moved[loop[(i + 1) % loop.size()]]
                      - moved[loop[(i + loop.size() - 1) % loop.size()]];
                    slope += 0.5*(u[i].x()*d.y() - u[i].y()*d.x());
                }
                delta -= miss/slope;
            }
            offsets[loopi] = delta;
        }
        return moved;
    }


    //- Even-odd rule: is c inside the polygons?
    bool inside
    (
        const vector2D& c,
        const List<vector2D>& pts,
        const labelListList& loops
    )
    {
        bool in = false;
        for (const labelList& loop : loops)
        {
            forAll(loop, i)
            {
                const vector2D& a = pts[loop[i]];
                const vector2D& b = pts[loop[(i + 1) % loop.size()]];
                if
                (
                    ((a.y() > c.y()) != (b.y() > c.y()))
                 && c.x()
                  < a.x() + (c.y() - a.y())*(b.x() - a.x())/(b.y() - a.y())
                )
                {
                    in = !in;
                }
            }
        }
        return in;
    }


    //- Squared distance from c to the boundary polygons
    scalar boundaryDistSqr
    (
        const vector2D& c,
        const List<vector2D>& pts,
        const labelListList& loops
    )
    {
        scalar d2 = GREAT;
        for (const labelList& loop : loops)
        {
            forAll(loop, i)
            {
                const vector2D& a = pts[loop[i]];
                const vector2D ab = pts[loop[(i + 1) % loop.size()]] - a;
                const scalar t = min
                (
                    max(((c - a) & ab)/max(magSqr(ab), VSMALL), scalar(0)),
                    scalar(1)
                );
                d2 = min(d2, magSqr(c - a - t*ab));
            }
        }
        return d2;
    }


    //- Points of the triangular lattice of spacing h (one point at the
    //  origin) that lie inside the region at least h/2 from its boundary
    List<vector2D> latticePoints
    (
        const scalar h,
        const List<vector2D>& pts,
        const labelListList& loops
    )
    {
        scalar rMax = 0;
        for (const vector2D& p : pts)
        {
            rMax = max(rMax, mag(p));
        }

        const scalar dy = h*std::sqrt(3.0)/2;
        const label nx = label(rMax/h) + 1;
        const label ny = label(rMax/dy) + 1;
        const scalar minDist2 = sqr(0.5*h);

        DynamicList<vector2D> lattice;
        for (label j = -ny; j <= ny; ++j)
        {
            const scalar shift = (j % 2 == 0) ? 0 : 0.5*h;
            for (label i = -nx; i <= nx; ++i)
            {
                const vector2D c(i*h + shift, j*dy);
                if
                (
                    magSqr(c) < sqr(rMax)
                 && inside(c, pts, loops)
                 && boundaryDistSqr(c, pts, loops) >= minDist2
                )
                {
                    lattice.append(c);
                }
            }
        }
        return List<vector2D>(std::move(lattice));
    }


    //- Number of layers of the side walls
    label nLayers(const scalar height, const scalar h)
    {
        return max(label(1), label(std::round(height/h)));
    }


    //- Triangle count of the prism for edge length h
    label prismFaces(const region& reg, const scalar height, const scalar h)
    {
        List<vector2D> pts;
        labelListList loops;
        sampleBoundary(reg, h, pts, loops);
        const label nb = pts.size();
        const label ni = latticePoints(h, pts, loops).size();
        return
            2*nb*nLayers(height, h) + 2*(2*ni + nb - 2 + 2*reg.nHoles);
    }


    //- The prism of the region from z = -height/2 to height/2, with the
    //  edge length chosen to give about targetFaces triangles; volumeTrue:
    //  the boundary points moved to area-true loops (areaTruePoints), the
    //  same triangles, the flat caps' interior points and the heights as
    //  they are
    rbd::triMesh prism
    (
        const region& reg,
        const scalar height,
        const label targetFaces,
        const rbd::pelletMeshes::facets placement
    )
    {
        // Count ~ a/h^2 + b/h: side walls 2 P H/h^2, caps
        // 2 (2 A/(sqrt(3)/2 h^2) + P/h)
        const scalar F = max(targetFaces, label(1));
        const scalar a =
            2*reg.perimeter*height + 8*reg.area/std::sqrt(3.0);
        const scalar b = 2*reg.perimeter;
        scalar h = (b + std::sqrt(sqr(b) + 4*F*a))/(2*F);

        // The count is a step function of h: secant steps on n ~ 1/h^2,
        // then a scan of +-5 % about the best h
        scalar bestH = h;
        label bestMiss = labelMax;
        auto tryH = [&](const scalar hTry)
        {
            const label n = prismFaces(reg, height, hTry);
            const label miss = mag(n - label(F));
            if (miss < bestMiss)
            {
                bestMiss = miss;
                bestH = hTry;
            }
            return n;
        };
        for (label iter = 0; iter < 6 && bestMiss > 0; ++iter)
        {
            h *= std::sqrt(tryH(h)/F);
        }
        const scalar h0 = bestH;
        for (label i = -5; i <= 5 && bestMiss > 0; ++i)
        {
            tryH(h0*(1 + 0.01*i));
        }
        h = bestH;

        // Cap triangulation
        List<vector2D> bpts;
        labelListList loops;
        sampleBoundary(reg, h, bpts, loops);
        const List<vector2D> ipts = latticePoints(h, bpts, loops);

        const label nb = bpts.size();
        const label ni = ipts.size();

        List<vector2D> capPts(nb + ni);
        SubList<vector2D>(capPts, nb) = bpts;
        SubList<vector2D>(capPts, ni, nb) = ipts;
        const List<triFace> cap =
            rbd::cgalMeshTools::triangulateRegion(capPts, loops);

        // The triangles stay those of the inscribed boundary: the points
        // move by about (h/r)^2 r/12, far less than the h/2 that keeps the
        // lattice points off the boundary
        if (placement == rbd::pelletMeshes::facets::volumeTrue)
        {
            scalarList offsets;
            bpts = areaTruePoints(reg, bpts, loops, h, offsets);
        }

        // Points: side wall layers k = 0..nz (k = 0 bottom), then the
        // lattice points of the bottom and of the top cap
        const label nz = nLayers(height, h);
        pointField points((nz + 1)*nb + 2*ni);
        for (label k = 0; k <= nz; ++k)
        {
            const scalar z = -0.5*height + height*k/nz;
            forAll(bpts, i)
            {
                points[k*nb + i] = point(bpts[i].x(), bpts[i].y(), z);
            }
        }
        const label bottom0 = (nz + 1)*nb;
        const label top0 = bottom0 + ni;
        forAll(ipts, i)
        {
            points[bottom0 + i] = point(ipts[i].x(), ipts[i].y(), -0.5*height);
            points[top0 + i] = point(ipts[i].x(), ipts[i].y(), 0.5*height);
        }

        DynamicList<triFace> faces(2*nb*nz + 2*cap.size());

        // Side walls: loop edge i -> j (outer loop counter-clockwise, holes
        // clockwise) times z; (j - i) x z points out of the solid
        for (const labelList& loop : loops)
        {
            forAll(loop, li)
            {
                const label i = loop[li];
                const label j = loop[(li + 1) % loop.size()];
                for (label k = 0; k < nz; ++k)
                {
                    const label a = k*nb + i;
                    const label b = k*nb + j;
                    const label c = (k + 1)*nb + j;
                    const label d = (k + 1)*nb + i;
                    faces.append(triFace(a, b, c));
                    faces.append(triFace(a, c, d));
                }
            }
        }

        // Caps: counter-clockwise seen from +z on top, reversed below
        auto bottomIndex = [&](const label i)
        {
            return i < nb ? i : bottom0 + i - nb;
        };
        auto topIndex = [&](const label i)
        {
            return i < nb ? nz*nb + i : top0 + i - nb;
        };
        for (const triFace& t : cap)
        {
            faces.append
            (
                triFace(topIndex(t[0]), topIndex(t[1]), topIndex(t[2]))
            );
            faces.append
            (
                triFace
                (
                    bottomIndex(t[0]), bottomIndex(t[2]), bottomIndex(t[1])
                )
            );
        }

        const label expected = 2*nb*nz + 2*(2*ni + nb - 2 + 2*reg.nHoles);
        if (faces.size() != expected)
        {
            // Too few faces for the features of the cap (a trilobe of 40
            // faces): pelletShape::New reports it against the entries
            throw std::runtime_error
            (
                "the prism mesh has " + std::to_string(faces.size())
              + " triangles, expected " + std::to_string(expected)
              + ": too few faces for its cap"
            );
        }

        return rbd::triMesh(std::move(points), List<triFace>(std::move(faces)));
    }


    //- Region of a cylinder with holes at the given centres
    region holedDisk
    (
        const scalar radius,
        const List<vector2D>& holeCentres,
        const scalar holeRadius
    )
    {
        region reg;
        reg.loops.setSize(1 + holeCentres.size());
        reg.loops[0] = arcLoop(1, circle(vector2D::zero, radius, false));
        forAll(holeCentres, i)
        {
            reg.loops[1 + i] =
                arcLoop(1, circle(holeCentres[i], holeRadius, true));
        }
        reg.nHoles = holeCentres.size();
        reg.area = pi*(sqr(radius) - holeCentres.size()*sqr(holeRadius));
        reg.perimeter = twoPi*(radius + holeCentres.size()*holeRadius);
        return reg;
    }


    //- Resolved default radius (negative -> default)
    scalar lobeRadius(const label n, const scalar dl, const scalar rc)
    {
        return rc < 0 ? rbd::pelletMeshes::defaultLobeCentreRadius(n, dl) : rc;
    }

    scalar holeRadius
    (
        const scalar D,
        const label n,
        const scalar dh,
        const scalar rh
    )
    {
        return
            rh < 0
          ? rbd::pelletMeshes::defaultHoleCircleRadius(D, n, dh)
          : rh;
    }


    string positive(const char* what, const scalar x)
    {
        return
            x > 0
          ? string()
          : string(what) + " must be > 0, not " + Foam::name(x);
    }

    string positiveFaces(const label faces)
    {
        return
            faces > 0
          ? string()
          : "the target face count must be > 0, not " + Foam::name(faces);
    }

    //- First non-empty message
    string first(std::initializer_list<string> msgs)
    {
        for (const string& m : msgs)
        {
            if (!m.empty())
            {
                return m;
            }
        }
        return string();
    }

    void check(const string& msg, const char* shape)
    {
        if (!msg.empty())
        {
            FatalErrorInFunction
                << "Invalid " << shape << ": " << msg.c_str()
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * Defaults and checks * * * * * * * * * * * * //

Foam::scalar Foam::rbd::pelletMeshes::defaultLobeCentreRadius
(
    const label nLobes,
    const scalar lobeDiameter
)
{
    return 0.5*lobeDiameter/(2*std::sin(pi/max(nLobes, label(2))));
}


Foam::scalar Foam::rbd::pelletMeshes::defaultHoleCircleRadius
(
    const scalar diameter,
    const label nHoles,
    const scalar holeDiameter
)
{
    if (nHoles <= 1)
    {
        return 0;
    }
    return 0.5*(diameter + holeDiameter)/(1 + 2*std::sin(pi/nHoles));
}


Foam::string Foam::rbd::pelletMeshes::sphereError
(
    const scalar diameter,
    const label faces
)
{
    return first({positive("diameter", diameter), positiveFaces(faces)});
}


Foam::string Foam::rbd::pelletMeshes::cylinderError
(
    const scalar diameter,
    const scalar height,
    const label faces
)
{
    return first
    ({
        positive("diameter", diameter),
        positive("height", height),
        positiveFaces(faces)
    });
}


Foam::string Foam::rbd::pelletMeshes::ringError
(
    const scalar outerDiameter,
    const scalar innerDiameter,
    const scalar height,
    const label faces
)
{
    const string msg = first
    ({
        positive("outer diameter", outerDiameter),
        positive("inner diameter", innerDiameter),
        positive("height", height),
        positiveFaces(faces)
    });
    if (!msg.empty())
    {
        return msg;
    }
    if (!(innerDiameter < outerDiameter))
    {
        return
            "the inner diameter " + Foam::name(innerDiameter)
          + " must be smaller than the outer diameter "
          + Foam::name(outerDiameter);
    }
    return string();
}


Foam::string Foam::rbd::pelletMeshes::lobesError
(
    const label nLobes,
    const scalar lobeDiameter,
    const scalar height,
    const label faces,
    const scalar lobeCentreRadius
)
{
    if (nLobes != 3 && nLobes != 4)
    {
        return "the number of lobes must be 3 or 4, not " + Foam::name(nLobes);
    }
    const string msg = first
    ({
        positive("lobe diameter", lobeDiameter),
        positive("height", height),
        positiveFaces(faces)
    });
    if (!msg.empty())
    {
        return msg;
    }
    const scalar rc = lobeRadius(nLobes, lobeDiameter, lobeCentreRadius);
    if (!(rc > 0 && rc < 0.5*lobeDiameter))
    {
        return
            "the radius of the circle of lobe axes " + Foam::name(rc)
          + " must lie between 0 and half the lobe diameter "
          + Foam::name(0.5*lobeDiameter);
    }
    return string();
}


Foam::string Foam::rbd::pelletMeshes::cylinderWithHolesError
(
    const scalar diameter,
    const scalar height,
    const label nHoles,
    const scalar holeDiameter,
    const label faces,
    const scalar holeCircleRadius
)
{
    string msg = first
    ({
        positive("diameter", diameter),
        positive("height", height),
        positiveFaces(faces)
    });
    if (!msg.empty())
    {
        return msg;
    }
    if (nHoles < 0)
    {
        return "the number of holes must be >= 0, not " + Foam::name(nHoles);
    }
    if (nHoles == 0)
    {
        return string();
    }
    msg = positive("hole diameter", holeDiameter);
    if (!msg.empty())
    {
        return msg;
    }

    const scalar rh =
        holeRadius(diameter, nHoles, holeDiameter, holeCircleRadius);
    if (rh < 0)
    {
        return "the radius of the circle of hole axes must be >= 0";
    }
    if (!(rh + 0.5*holeDiameter < 0.5*diameter))
    {
        return
            "the holes (diameter " + Foam::name(holeDiameter)
          + ", axes at radius " + Foam::name(rh)
          + ") reach the outer surface (diameter " + Foam::name(diameter)
          + ")";
    }
    if (nHoles > 1 && !(2*rh*std::sin(pi/nHoles) > holeDiameter))
    {
        return
            "neighbouring holes (diameter " + Foam::name(holeDiameter)
          + ", axes at radius " + Foam::name(rh) + ") overlap";
    }
    return string();
}


// * * * * * * * * * * * * * * * * Generators  * * * * * * * * * * * * * * * //

Foam::rbd::triMesh Foam::rbd::pelletMeshes::sphere
(
    const scalar diameter,
    const label faces,
    const facets placement
)
{
    check(sphereError(diameter, faces), "sphere");

    const scalar r = 0.5*diameter;

    // Icosahedron: the cyclic permutations of (0, +-1, +-phi)
    const scalar phi = 0.5*(1 + std::sqrt(5.0));
    pointField pts(12);
    label n = 0;
    for (const scalar s1 : {-1.0, 1.0})
    {
        for (const scalar s2 : {-phi, phi})
        {
            pts[n++] = point(0, s1, s2);
            pts[n++] = point(s1, s2, 0);
            pts[n++] = point(s2, 0, s1);
        }
    }

    // Faces: triples of vertices at mutual distance 2 (the edge length),
    // oriented outward
    DynamicList<triFace> tris(20);
    for (label i = 0; i < 12; ++i)
    {
        for (label j = i + 1; j < 12; ++j)
        {
            for (label k = j + 1; k < 12; ++k)
            {
                if
                (
                    mag(mag(pts[i] - pts[j]) - 2) < 1e-9
                 && mag(mag(pts[j] - pts[k]) - 2) < 1e-9
                 && mag(mag(pts[k] - pts[i]) - 2) < 1e-9
                )
                {
                    triFace f(i, j, k);
                    if ((f.areaNormal(pts) & f.centre(pts)) < 0)
                    {
                        f.flip();
                    }
                    tris.append(f);
                }
            }
        }
    }

    triMesh m(pts/mag(pts[0])*r, List<triFace>(std::move(tris)));

    const label levels = max
    (
        label(0),
        label(std::round(std::log(scalar(faces)/20)/std::log(4.0)))
    );

    for (label level = 0; level < levels; ++level)
    {
        m = cgalMeshTools::loopSubdivision(m, 1);
        pointField p(m.points());
        for (point& x : p)
        {
            x *= r/mag(x);
        }
        m = triMesh(std::move(p), m.faces());
    }

    // Volume-true: the polyhedron scaled about the centre to the sphere's
    // volume pi d^3/6 (a sphere has no flat face to keep)
    if (placement == facets::volumeTrue)
    {
        m.scale(std::cbrt(pi*pow3(diameter)/6/m.volume()));
    }
    return m;
}


Foam::rbd::triMesh Foam::rbd::pelletMeshes::cylinder
(
    const scalar diameter,
    const scalar height,
    const label faces,
    const facets placement
)
{
    check(cylinderError(diameter, height, faces), "cylinder");
    return prism
    (
        holedDisk(0.5*diameter, List<vector2D>(), 0), height, faces, placement
    );
}


Foam::rbd::triMesh Foam::rbd::pelletMeshes::ring
(
    const scalar outerDiameter,
    const scalar innerDiameter,
    const scalar height,
    const label faces,
    const facets placement
)
{
    check
    (
        ringError(outerDiameter, innerDiameter, height, faces),
        "Raschig ring"
    );
    return prism
    (
        holedDisk
        (
            0.5*outerDiameter,
            List<vector2D>(1, vector2D::zero),
            0.5*innerDiameter
        ),
        height,
        faces,
        placement
    );
}


Foam::rbd::triMesh Foam::rbd::pelletMeshes::lobes
(
    const label nLobes,
    const scalar lobeDiameter,
    const scalar height,
    const label faces,
    const scalar lobeCentreRadius,
    const facets placement
)
{
    check
    (
        lobesError(nLobes, lobeDiameter, height, faces, lobeCentreRadius),
        "lobed cylinder"
    );

    const label n = nLobes;
    const scalar r = 0.5*lobeDiameter;
    const scalar rc = lobeRadius(nLobes, lobeDiameter, lobeCentreRadius);

    // Valley point of lobes 0 and 1, on the ray at angle pi/n:
    // |t (cos, sin)(pi/n) - (rc, 0)| = r
    const scalar s = std::sin(pi/n);
    const scalar c = std::cos(pi/n);
    const scalar t = rc*c + std::sqrt(sqr(r) - sqr(rc*s));

    // Half-angle of a lobe arc seen from its axis
    const scalar beta = std::atan2(t*s, t*c - rc);

    region reg;
    reg.nHoles = 0;
    reg.loops.setSize(1);
    arcLoop& loop = reg.loops[0];
    loop.setSize(n);
    for (label k = 0; k < n; ++k)
    {
        const scalar theta = twoPi*k/n;
        loop[k] = arc
        {
            rc*vector2D(std::cos(theta), std::sin(theta)),
            r,
            theta - beta,
            2*beta,
            3
        };
    }
    reg.area = n*(rc*r*std::sin(beta) + sqr(r)*beta);
    reg.perimeter = n*2*beta*r;

    return prism(reg, height, faces, placement);
}


Foam::rbd::triMesh Foam::rbd::pelletMeshes::cylinderWithHoles
(
    const scalar diameter,
    const scalar height,
    const label nHoles,
    const scalar holeDiameter,
    const label faces,
    const scalar holeCircleRadius,
    const facets placement
)
{
    check
    (
        cylinderWithHolesError
        (
            diameter, height, nHoles, holeDiameter, faces, holeCircleRadius
        ),
        "cylinder with holes"
    );

    const scalar rh =
        holeRadius(diameter, nHoles, holeDiameter, holeCircleRadius);

    return prism
    (
        holedDisk
        (
            0.5*diameter, prismProfile::onCircle(nHoles, rh),
            0.5*holeDiameter
        ),
        height,
        faces,
        placement
    );
}


// ************************************************************************* //

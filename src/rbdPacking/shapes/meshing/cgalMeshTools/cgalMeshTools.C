/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/IO/STL.h>

#include <array>
#include <cstdint>
#include <cmath>
#include <fstream>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "cgalMeshTools.H"
#include "boundBox.H"
#include "OSspecific.H"
#include "sigFpe.H"
#include "OStringStream.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Types * * * * * * * * * * * * * * * * //

namespace
{
    typedef CGAL::Exact_predicates_inexact_constructions_kernel kernel;
    typedef kernel::Point_3 cgalPoint;
    typedef CGAL::Surface_mesh<cgalPoint> surfaceMesh;
    typedef std::array<std::size_t, 3> soupTriangle;

    namespace PMP = CGAL::Polygon_mesh_processing;


    //- Build the CGAL mesh of a triMesh; false if Surface_mesh::add_face
    //  refuses a triangle (non-manifold configuration)
    bool buildSurfaceMesh(const Foam::rbd::triMesh& m, surfaceMesh& sm)
    {
        sm.clear();
        sm.reserve(m.nPoints(), 3*m.nFaces()/2, m.nFaces());
        for (const Foam::point& p : m.points())
        {
            sm.add_vertex(cgalPoint(p.x(), p.y(), p.z()));
        }
        for (const Foam::triFace& f : m.faces())
        {
            const surfaceMesh::Face_index fi = sm.add_face
            (
                surfaceMesh::Vertex_index(f[0]),
                surfaceMesh::Vertex_index(f[1]),
                surfaceMesh::Vertex_index(f[2])
            );
            if (fi == surfaceMesh::null_face())
            {
                return false;
            }
        }
        return true;
    }


    surfaceMesh toSurfaceMesh(const Foam::rbd::triMesh& m)
    {
        surfaceMesh sm;
        if (!buildSurfaceMesh(m, sm))
        {
            FatalErrorInFunction
                << "Cannot build a CGAL surface mesh from the triangles"
                << " (not manifold)" << Foam::exit(Foam::FatalError);
        }
        return sm;
    }


    //- Surface_mesh without removed elements -> triMesh
    Foam::rbd::triMesh fromSurfaceMesh(const surfaceMesh& sm)
    {
        Foam::pointField pts(sm.number_of_vertices());
        for (const surfaceMesh::Vertex_index v : sm.vertices())
        {
            const cgalPoint& p = sm.point(v);
            pts[Foam::label(v)] = Foam::point(p.x(), p.y(), p.z());
        }

        Foam::List<Foam::triFace> faces(sm.number_of_faces());
        Foam::label facei = 0;
        for (const surfaceMesh::Face_index f : sm.faces())
        {
            Foam::triFace& t = faces[facei++];
            int i = 0;
            for
            (
                const surfaceMesh::Vertex_index v
              : CGAL::vertices_around_face(sm.halfedge(f), sm)
            )
            {
                if (i < 3)
                {
                    t[i] = Foam::label(v);
                }
                ++i;
            }
            if (i != 3)
            {
                FatalErrorInFunction
                    << "Face with " << i << " vertices in a triangle mesh"
                    << Foam::exit(Foam::FatalError);
            }
        }
        return Foam::rbd::triMesh(std::move(pts), std::move(faces));
    }


    //- Point as text for messages
    Foam::string str(const Foam::point& p)
    {
        Foam::OStringStream os;
        os << p;
        return os.str();
    }


    //- Union-find root with path halving
    Foam::label findRoot(Foam::labelList& parent, Foam::label i)
    {
        while (parent[i] != i)
        {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }
}


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::string Foam::rbd::checkClosedSolid(const triMesh& mesh)
{
    const pointField& pts = mesh.points();
    const List<triFace>& faces = mesh.faces();
    const label nPts = pts.size();

    if (faces.empty())
    {
        return "no triangles";
    }

    // 1. Indices, degenerate index triples, unused points
    {
        std::vector<bool> used(pts.size(), false);
        forAll(faces, facei)
        {
            const triFace& f = faces[facei];
            for (const label pi : f)
            {
                if (pi < 0 || pi >= nPts)
                {
                    return
                        "triangle " + Foam::name(facei) + " refers to point "
                      + Foam::name(pi) + " of " + Foam::name(nPts);
                }
                used[pi] = true;
            }
            if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
            {
                return
                    "triangle " + Foam::name(facei)
                  + " uses the same point twice (degenerate)";
            }
        }
        const label nUnused = std::count(used.begin(), used.end(), false);
        if (nUnused)
        {
            const label pi = std::find(used.begin(), used.end(), false)
              - used.begin();
            return
                Foam::name(nUnused) + " points belong to no triangle, e.g. "
              + str(pts[pi]);
        }
    }

    // 2.-4. Edges: each must be used by exactly two triangles, once in each
    // direction. Key: undirected edge; value: uses, same-direction uses,
    // first triangle, first start point.
    struct edgeUse
    {
        label n = 0;
        label sameWay = 0;
        label face = -1;
        label start = -1;
    };
    std::unordered_map<uint64_t, edgeUse> edges(3*faces.size());

    auto key = [nPts](const label a, const label b)
    {
        return uint64_t(min(a, b))*uint64_t(nPts) + uint64_t(max(a, b));
    };

    labelList parent(identity(faces.size()));

    forAll(faces, facei)
    {
        const triFace& f = faces[facei];
        for (label i = 0; i < 3; ++i)
        {
            const label a = f[i];
            const label b = f[(i + 1) % 3];
            edgeUse& e = edges[key(a, b)];
            if (e.n == 0)
            {
                e.face = facei;
                e.start = a;
            }
            else
            {
                if (e.start == a)
                {
                    ++e.sameWay;
                }
                const label r0 = findRoot(parent, facei);
                const label r1 = findRoot(parent, e.face);
                parent[r0] = r1;
            }
            ++e.n;
        }
    }

    label nBorder = 0, nNonManifold = 0, nSameWay = 0;
    uint64_t exBorder = 0, exNonManifold = 0, exSameWay = 0;
    for (const auto& ke : edges)
    {
        const edgeUse& e = ke.second;
        if (e.n == 1)
        {
            exBorder = nBorder++ ? exBorder : ke.first;
        }
        else if (e.n > 2)
        {
            exNonManifold = nNonManifold++ ? exNonManifold : ke.first;
        }
        else if (e.sameWay)
        {
            exSameWay = nSameWay++ ? exSameWay : ke.first;
        }
    }

    auto edgeStr = [&pts, nPts](const uint64_t k)
    {
        return
            "from " + str(pts[label(k/uint64_t(nPts))])
          + " to " + str(pts[label(k % uint64_t(nPts))]);
    };

    if (nBorder)
    {
        return
            "not closed: " + Foam::name(nBorder)
          + " border edges (edges of one triangle only), e.g. "
          + edgeStr(exBorder);
    }
    if (nNonManifold)
    {
        return
            "not manifold: " + Foam::name(nNonManifold)
          + " edges shared by more than two triangles, e.g. "
          + edgeStr(exNonManifold);
    }
    if (nSameWay)
    {
        return
            "inconsistently oriented: " + Foam::name(nSameWay)
          + " edges whose two triangles run the same way, e.g. "
          + edgeStr(exSameWay);
    }

    // 5. Vertex fans: the triangles (v, a, b) around v give link edges
    // a -> b, which must form one cycle
    {
        labelList nPointFaces(nPts, 0);
        for (const triFace& f : faces)
        {
            for (const label pi : f)
            {
                ++nPointFaces[pi];
            }
        }
        labelList offset(nPts + 1, 0);
        for (label pi = 0; pi < nPts; ++pi)
        {
            offset[pi + 1] = offset[pi] + nPointFaces[pi];
        }
        labelList linkFrom(offset[nPts]), linkTo(offset[nPts]);
        labelList fill(offset.begin(), offset.end() - 1);
        for (const triFace& f : faces)
        {
            for (label i = 0; i < 3; ++i)
            {
                const label pi = f[i];
                linkFrom[fill[pi]] = f[(i + 1) % 3];
                linkTo[fill[pi]] = f[(i + 2) % 3];
                ++fill[pi];
            }
        }

        label nBad = 0, exBad = -1;
        std::unordered_map<label, label> next;
        for (label pi = 0; pi < nPts; ++pi)
        {
            next.clear();
            for (label j = offset[pi]; j < offset[pi + 1]; ++j)
            {
                next[linkFrom[j]] = linkTo[j];
            }
            // Walk the cycle from the first link point
            const label start = linkFrom[offset[pi]];
            label a = start, steps = 0;
            do
            {
                auto it = next.find(a);
                if (it == next.end())
                {
                    break;
                }
                a = it->second;
                ++steps;
            } while (a != start && steps <= nPointFaces[pi]);

            if (a != start || steps != nPointFaces[pi])
            {
                exBad = nBad++ ? exBad : pi;
            }
        }
        if (nBad)
        {
            return
                "not manifold: at " + Foam::name(nBad)
              + " vertices the triangles form more than one fan, e.g. at "
              + str(pts[exBad]);
        }
    }

    // 6. One part
    {
        label nParts = 0;
        forAll(parent, facei)
        {
            if (findRoot(parent, facei) == facei)
            {
                ++nParts;
            }
        }
        if (nParts > 1)
        {
            return
                Foam::name(nParts) + " separate parts: a pellet must be one"
                " connected solid";
        }
    }

    // 7. CGAL's view of the same (Surface_mesh::add_face refuses
    // non-manifold configurations)
    surfaceMesh sm;
    if (!buildSurfaceMesh(mesh, sm))
    {
        return "not a valid polygon mesh (CGAL Surface_mesh)";
    }
    if (!CGAL::is_valid_polygon_mesh(sm) || !CGAL::is_closed(sm))
    {
        return "not a valid closed polygon mesh (CGAL)";
    }

    // 8. Zero-area triangles
    {
        label nDegenerate = 0, exDegenerate = -1;
        forAll(faces, facei)
        {
            const triFace& f = faces[facei];
            if
            (
                CGAL::collinear
                (
                    sm.point(surfaceMesh::Vertex_index(f[0])),
                    sm.point(surfaceMesh::Vertex_index(f[1])),
                    sm.point(surfaceMesh::Vertex_index(f[2]))
                )
            )
            {
                exDegenerate = nDegenerate++ ? exDegenerate : facei;
            }
        }
        if (nDegenerate)
        {
            return
                Foam::name(nDegenerate) + " triangles of zero area, e.g. at "
              + str(faces[exDegenerate].centre(pts));
        }
    }

    // 9. Self-intersections
    if (PMP::does_self_intersect(sm))
    {
        std::vector
        <
            std::pair<surfaceMesh::Face_index, surfaceMesh::Face_index>
        > pairs;
        PMP::self_intersections(sm, std::back_inserter(pairs));

        string where;
        if (!pairs.empty())
        {
            // Surface_mesh faces are numbered as the triangles
            const label f0 = label(pairs[0].first);
            const label f1 = label(pairs[0].second);
            where =
                ", e.g. the triangles at " + str(faces[f0].centre(pts))
              + " and " + str(faces[f1].centre(pts));
        }
        return
            "self-intersecting: " + Foam::name(label(pairs.size()))
          + " pairs of triangles intersect" + where;
    }

    // 10. Orientation
    if (!PMP::is_outward_oriented(sm))
    {
        return
            "inward oriented: the triangle normals point into the solid"
            " (reverse the vertex order of every triangle, e.g. with"
            " OpenFOAM's surfaceOrient)";
    }

    // 11. Volume
    const scalar V = mesh.volume();
    if (!(V > 0))
    {
        return "encloses no positive volume (" + Foam::name(V) + " m^3)";
    }

    return string();
}


Foam::rbd::triMesh Foam::rbd::cgalMeshTools::clipByPlane
(
    const triMesh& mesh,
    const point& p,
    const vector& n
)
{
    // The cut points are constructed in doubles: two of them, or a cut
    // point and a vertex just off the plane, can round to the same point,
    // leaving zero-length edges and zero-area triangles. Those are
    // self-intersections to CGAL, and the next cut of the same pellet (a
    // pellet has a cap per contact) failed on them (an assertion on two
    // lines that do not meet, with the exact kernel too). So every cut
    // mesh leaves with its degenerate triangles removed by edge collapses
    // and flips (PMP::remove_degenerate_faces).
    //
    // A plane that holds a face of the mesh (a cap's cut face beside
    // another cap of the same pellet) can trip CGAL's corefinement of
    // coplanar faces: an assertion (parallel lines intersected, with
    // inexact constructions) on a bed of six cylinders. The plane is then
    // moved off the face along n by clipShift times the mesh's size (1 nm
    // for a 10 mm pellet), and once more by twice that, before giving up
    // with a FatalError that names the cut.
    const boundBox bb(mesh.points());
    const scalar size = bb.mag();
    string why;
    for (label attempt = 0; attempt < 3; ++attempt)
    {
        const scalar shift = attempt*clipShift*size;
        const point q(p + shift*n/max(mag(n), VSMALL));
        try
        {
            surfaceMesh sm = toSurfaceMesh(mesh);
            const kernel::Plane_3 plane(n.x(), n.y(), n.z(), -(n & q));
            PMP::clip(sm, plane, CGAL::parameters::clip_volume(true));
            PMP::triangulate_faces(sm);
            if (PMP::remove_degenerate_faces(sm))
            {
                sm.collect_garbage();
                return fromSurfaceMesh(sm);
            }
            why = "degenerate triangles left that could not be removed";
        }
        catch (const CGAL::Failure_exception& e)
        {
            why = e.what();
        }
    }

    FatalErrorInFunction
        << "CGAL could not cut a pellet's surface (" << size
        << " m across) by the plane through " << p
        << " with normal " << n << ", nor by the planes moved "
        << clipShift*size << " and " << 2*clipShift*size
        << " m along it: " << why.c_str() << nl
        << "    Set contactTreatment none, or report the case."
        << exit(FatalError);

    return triMesh();
}


Foam::rbd::triMesh Foam::rbd::cgalMeshTools::loopSubdivision
(
    const triMesh& mesh,
    const label iterations
)
{
    surfaceMesh sm = toSurfaceMesh(mesh);
    CGAL::Subdivision_method_3::Loop_subdivision
    (
        sm,
        CGAL::parameters::number_of_iterations(int(iterations))
    );
    return fromSurfaceMesh(sm);
}


Foam::List<Foam::triFace> Foam::rbd::cgalMeshTools::triangulateRegion
(
    const List<vector2D>& points,
    const labelListList& loops
)
{
    typedef CGAL::Triangulation_vertex_base_with_info_2<label, kernel> vb;
    typedef CGAL::Constrained_triangulation_face_base_2<kernel> fb;
    typedef CGAL::Triangulation_data_structure_2<vb, fb> tds;
    typedef CGAL::Constrained_Delaunay_triangulation_2
    <
        kernel,
        tds,
        CGAL::No_constraint_intersection_tag
    > cdt;
    typedef kernel::Point_2 point2;

    cdt tri;
    std::vector<cdt::Vertex_handle> handles(points.size());
    forAll(points, pi)
    {
        handles[pi] = tri.insert(point2(points[pi].x(), points[pi].y()));
        handles[pi]->info() = pi;
    }

    if (label(tri.number_of_vertices()) != points.size())
    {
        FatalErrorInFunction
            << "Coincident points: " << points.size() << " points gave "
            << tri.number_of_vertices() << " vertices"
            << exit(FatalError);
    }

    for (const labelList& loop : loops)
    {
        forAll(loop, i)
        {
            tri.insert_constraint
            (
                handles[loop[i]],
                handles[loop[(i + 1) % loop.size()]]
            );
        }
    }

    if (label(tri.number_of_vertices()) != points.size())
    {
        FatalErrorInFunction
            << "Boundary loops touch points or each other"
            << exit(FatalError);
    }

    // Even-odd rule on the face centroids
    auto inside = [&points, &loops](const vector2D& c)
    {
        bool in = false;
        for (const labelList& loop : loops)
        {
            forAll(loop, i)
            {
                const vector2D& a = points[loop[i]];
                const vector2D& b = points[loop[(i + 1) % loop.size()]];
                if
                (
                    ((a.y() > c.y()) != (b.y() > c.y()))
                 && (
                        c.x()
                      < a.x() + (c.y() - a.y())*(b.x() - a.x())/(b.y() - a.y())
                    )
                )
                {
                    in = !in;
                }
            }
        }
        return in;
    };

    DynamicList<triFace> faces(2*points.size());
    for (auto fit = tri.finite_faces_begin(); fit != tri.finite_faces_end();
        ++fit)
    {
        const triFace t
        (
            fit->vertex(0)->info(),
            fit->vertex(1)->info(),
            fit->vertex(2)->info()
        );
        const vector2D c = (points[t[0]] + points[t[1]] + points[t[2]])/3;
        if (inside(c))
        {
            faces.append(t);    // CGAL faces are counter-clockwise
        }
    }
    return List<triFace>(std::move(faces));
}


bool Foam::rbd::cgalMeshTools::readSTL
(
    const fileName& file,
    pointField& points,
    List<triFace>& faces,
    string& reason
)
{
    points.clear();
    faces.clear();

    if (!Foam::isFile(file))
    {
        reason = "cannot find file " + file;
        return false;
    }

    std::ifstream is(file, std::ios::binary);
    if (!is.good())
    {
        reason = "cannot open file " + file;
        return false;
    }

    // A binary STL (84 + 50 n bytes) is checked for vertices that are not
    // finite numbers first: CGAL merges equal points through a map, where
    // a NaN compares equal to any point, so the NaN vanished into a wrong
    // surface ("inward oriented") instead of being reported
    {
        is.seekg(0, std::ios::end);
        const std::streamoff size = is.tellg();
        std::uint32_t n = 0;
        if
        (
            size >= 84
         && is.seekg(80)
         && is.read(reinterpret_cast<char*>(&n), 4)
         && size == 84 + 50*std::streamoff(n)
        )
        {
            for (std::uint32_t t = 0; t < n; ++t)
            {
                float f[12];
                is.read(reinterpret_cast<char*>(f), sizeof(f));
                is.ignore(2);
                for (int j = 3; j < 12; ++j)
                {
                    if (!std::isfinite(f[j]))
                    {
                        reason =
                            "a vertex of triangle " + Foam::name(label(t))
                          + " of " + file + " has a coordinate that is not"
                            " a finite number";
                        return false;
                    }
                }
            }
        }
        is.clear();
        is.seekg(0);
    }

    std::vector<cgalPoint> pts;
    std::vector<soupTriangle> tris;
    bool ok = false;
    try
    {
        // A binary STL holds any 32-bit floats (NaN, or random bytes in a
        // file that is not an STL): CGAL's parser computes with them, and
        // OpenFOAM's trapping of floating-point exceptions would stop the
        // run there. The coordinates are checked below.
        const sigFpe::ignore noTrap;
        ok = CGAL::IO::read_STL(is, pts, tris);
    }
    catch (const std::exception&)
    {
        ok = false;
    }

    if (!ok)
    {
        reason = "cannot read " + file + " as an ASCII or binary STL file";
        return false;
    }
    if (tris.empty())
    {
        reason = "no triangles in " + file + " (empty or not an STL file)";
        return false;
    }

    points.setSize(pts.size());
    forAll(points, pi)
    {
        points[pi] = point(pts[pi].x(), pts[pi].y(), pts[pi].z());
        for (const scalar x : points[pi])
        {
            if (!std::isfinite(x))
            {
                reason = "a vertex of " + file + " has a coordinate that is"
                    " not a finite number";
                points.clear();
                return false;
            }
        }
    }
    faces.setSize(tris.size());
    forAll(faces, facei)
    {
        faces[facei] = triFace
        (
            label(tris[facei][0]),
            label(tris[facei][1]),
            label(tris[facei][2])
        );
    }
    return true;
}


// ************************************************************************* //

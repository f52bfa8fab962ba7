/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bedCaseWriter.H"
#include "foamFile.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"
#include <sstream>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::word Foam::rbd::bedCaseWriter::pelletFile("pellets.stl");
const Foam::word Foam::rbd::bedCaseWriter::tubeFile("tube.stl");

const Foam::word Foam::rbd::bedCaseWriter::flowRateObject("flowRate");
const Foam::word Foam::rbd::bedCaseWriter::bedBottomObject("pBedBottom");
const Foam::word Foam::rbd::bedCaseWriter::bedTopObject("pBedTop");

const Foam::vector Foam::rbd::bedCaseWriter::cellFractions
(
    0.3141, 0.4142, 0.2718
);


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- A number with 12 significant digits
    std::string num(const scalar x)
    {
        std::ostringstream os;
        os.precision(12);
        os << x;
        return os.str();
    }

    //- "(x y z)"
    std::string vec(const vector& v)
    {
        return "(" + num(v.x()) + " " + num(v.y()) + " " + num(v.z()) + ")";
    }

    //- The wall-like patches as a regex key "(a|b|c)"
    std::string anyOf(const wordList& names)
    {
        std::string s;
        for (const word& n : names)
        {
            s += (s.empty() ? "" : "|") + n;
        }
        return "\"(" + s + ")\"";
    }

    //- Background-grid cell size along each axis [m]
    vector gridSpacing(const rbd::bedCaseSettings& s)
    {
        const vector span = s.blockMax() - s.blockMin();
        return vector
        (
            span.x()/s.blockCells().x(),
            span.y()/s.blockCells().y(),
            span.z()/s.blockCells().z()
        );
    }

    //- Move \c p within its background cell to the given fractions
    point ontoCellFractions
    (
        const rbd::bedCaseSettings& s,
        const point& p,
        const vector& fractions
    )
    {
        const vector d = gridSpacing(s);
        point q;
        for (direction i = 0; i < 3; ++i)
        {
            const scalar cellIndex =
                std::floor((p[i] - s.blockMin()[i])/d[i]);
            q[i] = s.blockMin()[i] + (cellIndex + fractions[i])*d[i];
        }
        return q;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::bedCaseWriter::bedCaseWriter
(
    const fileName& caseDir,
    const bedCaseSettings& settings,
    const insideFunction& insidePellet
)
:
    caseDir_(caseDir),
    settings_(settings),
    insidePellet_(insidePellet),
    surfaces_()
{
    if (!settings_.hasBedHeight())
    {
        FatalErrorInFunction
            << "The bed height has not been given to the case settings"
            << " (bedCaseSettings::setBedHeight)" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::bedCaseWriter::addSurface
(
    const word& name,
    const fileName& file,
    const label level
)
{
    for (const word& used : wallPatches())
    {
        if (used == name)
        {
            FatalErrorInFunction
                << "Surface name '" << name << "' is taken; patches so far: "
                << wallPatches() << exit(FatalError);
        }
    }
    if (name == "inlet" || name == "outlet")
    {
        FatalErrorInFunction
            << "Surface name '" << name << "' is taken by the block mesh"
            << exit(FatalError);
    }
    surfaces_.append(surface{name, file, level});
}


Foam::wordList Foam::rbd::bedCaseWriter::wallPatches() const
{
    wordList names({"wall", "pellets"});
    for (const surface& s : surfaces_)
    {
        names.append(s.name);
    }
    return names;
}


bool Foam::rbd::bedCaseWriter::findLocationInMesh
(
    const bedCaseSettings& settings,
    const insideFunction& insidePellet,
    point& location
)
{
    const vector d = gridSpacing(settings);
    const scalar h = max(d.x(), d.z());
    const point& c = settings.floorCentre();
    const scalar R = settings.tubeRadius();

    const auto inFluid = [&](const point& p)
    {
        const scalar r = Foam::sqrt(sqr(p.x() - c.x()) + sqr(p.y() - c.y()));
        if
        (
            r > R - 2*h
         || p.z() < settings.blockMin().z() + 2*d.z()
         || p.z() > settings.blockMax().z() - 2*d.z()
         || insidePellet(p)
        )
        {
            return false;
        }
        for (direction i = 0; i < 3; ++i)
        {
            vector e(Zero);
            e[i] = h;
            if (insidePellet(p + e) || insidePellet(p - e))
            {
                return false;
            }
        }
        return true;
    };

    const auto accept = [&](const point& candidate)
    {
        const point p = ontoCellFractions(settings, candidate, cellFractions);
        if (inFluid(p))
        {
            location = p;
            return true;
        }
        return false;
    };

    // The empty sections below and above the bed
    const vector offAxis(0.5*R, 0, 0);
    if
    (
        accept(c + offAxis - vector(0, 0, 0.5*settings.inletLength()))
     || accept
        (
            c + offAxis
          + vector(0, 0, settings.bedHeight() + 0.5*settings.outletLength())
        )
    )
    {
        return true;
    }

    // Scan the whole tube, cell by cell, from the bottom
    const labelVector& n = settings.blockCells();
    for (label k = 0; k < n.z(); ++k)
    {
        for (label j = 0; j < n.y(); ++j)
        {
            for (label i = 0; i < n.x(); ++i)
            {
                const point p =
                    settings.blockMin()
                  + cmptMultiply(vector(i, j, k) + cellFractions, d);
                if (inFluid(p))
                {
                    location = p;
                    return true;
                }
            }
        }
    }
    return false;
}


Foam::fileNameList Foam::rbd::bedCaseWriter::files()
{
    return fileNameList
    ({
        "constant/triSurface/" + tubeFile,
        "system/blockMeshDict",
        "system/surfaceFeatureExtractDict",
        "system/snappyHexMeshDict",
        "system/decomposeParDict",
        "system/controlDict",
        "system/fvSchemes",
        "system/fvSolution",
        "constant/transportProperties",
        "constant/turbulenceProperties",
        "0/U",
        "0/p"
    });
}


void Foam::rbd::bedCaseWriter::writeTube(const fileName& file) const
{
    const scalar pi = constant::mathematical::pi;
    const point& c = settings_.floorCentre();
    const scalar R = settings_.tubeRadius();

    // Facets no wider than a wall cell, a multiple of 4 and at least 64;
    // vertices on the radius that gives the polygon the area of the circle
    const scalar hWall = settings_.cellSize()/pow(2.0, settings_.wallLevel());
    const label nTheta = max(label(64), 4*label(std::ceil(pi*R/(2*hWall))));
    const scalar rVertex =
        R*Foam::sqrt(2*pi/(nTheta*Foam::sin(2*pi/nTheta)));

    // Longer than the box by two cells at each end, facets about square
    const scalar dz = settings_.cellSizeZ();
    const scalar z0 = settings_.blockMin().z() - 2*dz;
    const scalar z1 = settings_.blockMax().z() + 2*dz;
    const label nZ = max
    (
        label(1),
        label(std::ceil((z1 - z0)/(2*pi*rVertex/nTheta)))
    );

    const auto vertex = [&](const label i, const label k)
    {
        const scalar theta = 2*pi*i/nTheta;
        return point
        (
            c.x() + rVertex*Foam::cos(theta),
            c.y() + rVertex*Foam::sin(theta),
            z0 + (z1 - z0)*k/nZ
        );
    };

    mkDir(file.path());
    OFstream os(file);
    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot open " << file << " for writing" << exit(FatalError);
    }
    os.precision(12);

    const auto facet = [&](const point& a, const point& b, const point& p)
    {
        vector n = (b - a) ^ (p - a);
        n /= mag(n);
        os  << "  facet normal " << n.x() << ' ' << n.y() << ' ' << n.z()
            << nl << "    outer loop" << nl;
        for (const point& v : {a, b, p})
        {
            os  << "      vertex " << v.x() << ' ' << v.y() << ' ' << v.z()
                << nl;
        }
        os  << "    endloop" << nl << "  endfacet" << nl;
    };

    // Normals point out of the tube (counter-clockwise seen from outside)
    os  << "solid wall" << nl;
    for (label k = 0; k < nZ; ++k)
    {
        for (label i = 0; i < nTheta; ++i)
        {
            const point a = vertex(i, k);
            const point b = vertex((i + 1) % nTheta, k);
            const point p = vertex((i + 1) % nTheta, k + 1);
            const point q = vertex(i, k + 1);
            facet(a, b, p);
            facet(a, p, q);
        }
    }
    os  << "endsolid wall" << nl;
}


std::string Foam::rbd::bedCaseWriter::blockMeshDict() const
{
    const point& a = settings_.blockMin();
    const point& b = settings_.blockMax();
    const labelVector& n = settings_.blockCells();
    const auto corner = [&](const scalar x, const scalar y, const scalar z)
    {
        return "    " + vec(point(x, y, z)) + "\n";
    };

    return
        "// Box around the tube; bottom and top are the inlet and outlet,\n"
        "// the sides become the tube wall where snappyHexMesh cuts them\n"
        "scale   1;\n"
        "\n"
        "vertices\n"
        "(\n"
      + corner(a.x(), a.y(), a.z()) + corner(b.x(), a.y(), a.z())
      + corner(b.x(), b.y(), a.z()) + corner(a.x(), b.y(), a.z())
      + corner(a.x(), a.y(), b.z()) + corner(b.x(), a.y(), b.z())
      + corner(b.x(), b.y(), b.z()) + corner(a.x(), b.y(), b.z())
      + ");\n"
        "\n"
        "blocks\n"
        "(\n"
        "    hex (0 1 2 3 4 5 6 7) ("
      + std::to_string(n.x()) + " " + std::to_string(n.y()) + " "
      + std::to_string(n.z()) + ") simpleGrading (1 1 1)\n"
        ");\n"
        "\n"
        "edges\n"
        "(\n"
        ");\n"
        "\n"
        "boundary\n"
        "(\n"
        "    inlet\n"
        "    {\n"
        "        type    patch;\n"
        "        faces   ((0 3 2 1));\n"
        "    }\n"
        "    outlet\n"
        "    {\n"
        "        type    patch;\n"
        "        faces   ((4 5 6 7));\n"
        "    }\n"
        "    wall\n"
        "    {\n"
        "        type    wall;\n"
        "        faces   ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));\n"
        "    }\n"
        ");\n"
        "\n"
        "mergePatchPairs\n"
        "(\n"
        ");\n";
}


std::string Foam::rbd::bedCaseWriter::surfaceFeatureExtractDict() const
{
    // Pellets and added surfaces: spheres give no edges, cylinders and
    // rings their rims. The tube needs none (see the class description).
    fileNameList stls({fileName(pelletFile)});
    for (const surface& s : surfaces_)
    {
        stls.append(s.file);
    }

    std::string t;
    for (const fileName& stl : stls)
    {
        t +=
            (t.empty() ? "" : "\n") + stl + "\n"
            "{\n"
            "    extractionMethod    extractFromSurface;\n"
            "    includedAngle       150;\n"
            "    subsetFeatures\n"
            "    {\n"
            "        nonManifoldEdges    no;\n"
            "        openEdges           no;\n"
            "    }\n"
            "    writeObj            no;\n"
            "}\n";
    }
    return t;
}


std::string Foam::rbd::bedCaseWriter::snappyHexMeshDict
(
    const point& location
) const
{
    const auto levels = [](const label l)
    {
        return "(" + std::to_string(l) + " " + std::to_string(l) + ")";
    };
    const scalar hFine =
        min(settings_.cellSize(), settings_.cellSizeZ())
       /pow(2.0, max(settings_.pelletLevel(), settings_.wallLevel()));

    // Geometry, explicit features and refinement per surface; 'name' sets
    // the patch name (else it would be the file name)
    std::string geometry, features, refinement;
    const auto add = [&]
    (
        const word& name,
        const fileName& file,
        const label level,
        const bool withFeatures
    )
    {
        geometry +=
            "    " + file + "\n"
            "    {\n"
            "        type    triSurfaceMesh;\n"
            "        name    " + name + ";\n"
            "    }\n";
        if (withFeatures)
        {
            features +=
                "        {\n"
                "            file    \"" + file.lessExt() + ".eMesh\";\n"
                "            level   " + std::to_string(level) + ";\n"
                "        }\n";
        }
        refinement +=
            "        " + name + "\n"
            "        {\n"
            "            level   " + levels(level) + ";\n"
            "            patchInfo\n"
            "            {\n"
            "                type    wall;\n"
            "            }\n"
            "        }\n";
    };
    add("pellets", pelletFile, settings_.pelletLevel(), true);
    add("wall", tubeFile, settings_.wallLevel(), false);
    for (const surface& s : surfaces_)
    {
        add(s.name, s.file, s.level, true);
    }

    return
        "castellatedMesh true;\n"
        "snap            true;\n"
        "addLayers       false;\n"
        "\n"
        "geometry\n"
        "{\n"
      + geometry
      + "}\n"
        "\n"
        "castellatedMeshControls\n"
        "{\n"
        "    maxLocalCells       20000000;\n"
        "    maxGlobalCells      100000000;\n"
        "    minRefinementCells  0;\n"
        "    maxLoadUnbalance    0.1;\n"
        "    nCellsBetweenLevels 3;\n"
        "\n"
        "    features\n"
        "    (\n"
      + features
      + "    );\n"
        "\n"
        "    refinementSurfaces\n"
        "    {\n"
      + refinement
      + "    }\n"
        "\n"
        "    resolveFeatureAngle 30;\n"
        "\n"
        "    refinementRegions\n"
        "    {\n"
        "    }\n"
        "\n"
        "    // In the fluid: computed by rbdPacking, checked against the\n"
        "    // pellets and the tube wall\n"
        "    locationInMesh " + vec(location) + ";\n"
        "\n"
        "    allowFreeStandingZoneFaces true;\n"
        "}\n"
        "\n"
        "snapControls\n"
        "{\n"
        "    nSmoothPatch            3;\n"
        "    tolerance               2.0;\n"
        "    nSolveIter              100;\n"
        "    nRelaxIter              5;\n"
        "    nFeatureSnapIter        10;\n"
        "    implicitFeatureSnap     false;\n"
        "    explicitFeatureSnap     true;\n"
        "    multiRegionFeatureSnap  false;\n"
        "}\n"
        "\n"
        "// Read by snappyHexMesh even with addLayers false\n"
        "addLayersControls\n"
        "{\n"
        "    relativeSizes               true;\n"
        "    layers\n"
        "    {\n"
        "    }\n"
        "    expansionRatio              1.0;\n"
        "    finalLayerThickness         0.3;\n"
        "    minThickness                0.1;\n"
        "    nGrow                       0;\n"
        "    featureAngle                60;\n"
        "    slipFeatureAngle            30;\n"
        "    nRelaxIter                  3;\n"
        "    nSmoothSurfaceNormals       1;\n"
        "    nSmoothNormals              3;\n"
        "    nSmoothThickness            10;\n"
        "    maxFaceThicknessRatio       0.5;\n"
        "    maxThicknessToMedialRatio   0.3;\n"
        "    minMedialAxisAngle          90;\n"
        "    nBufferCellsNoExtrude       0;\n"
        "    nLayerIter                  50;\n"
        "}\n"
        "\n"
        "// OpenFOAM's caseDicts/meshQualityDict, written out so that the\n"
        "// case stands alone; minVol scaled to the finest cell;\n"
        "// maxBoundarySkewness 4 (not 20): checkMesh fails any face\n"
        "// above 4, boundary or not (a cylinder bed had one at 4.6)\n"
        "meshQualityControls\n"
        "{\n"
        "    maxNonOrtho         65;\n"
        "    maxBoundarySkewness 4;\n"
        "    maxInternalSkewness 4;\n"
        "    maxConcave          80;\n"
        "    minVol              " + num(1e-6*pow3(hFine)) + ";\n"
        "    minTetQuality       1e-15;\n"
        "    minArea             -1;\n"
        "    minTwist            0.02;\n"
        "    minDeterminant      0.001;\n"
        "    minFaceWeight       0.05;\n"
        "    minVolRatio         0.01;\n"
        "    minTriangleTwist    -1;\n"
        "    nSmoothScale        4;\n"
        "    errorReduction      0.75;\n"
        "    relaxed\n"
        "    {\n"
        "        maxNonOrtho     75;\n"
        "    }\n"
        "}\n"
        "\n"
        "mergeTolerance  1e-6;\n";
}


std::string Foam::rbd::bedCaseWriter::decomposeParDict() const
{
    // scotch and metis are stubs in Debian's package; the bed is long and
    // thin, so slabs along the axis balance well
    const std::string n = std::to_string(settings_.nProcessors());
    return
        "numberOfSubdomains  " + n + ";\n"
        "\n"
        "method              hierarchical;\n"
        "\n"
        "hierarchicalCoeffs\n"
        "{\n"
        "    n       (1 1 " + n + ");\n"
        "    order   xyz;\n"
        "}\n";
}


std::string Foam::rbd::bedCaseWriter::controlDict() const
{
    const std::string nIter = std::to_string(settings_.nIterations());
    const point& c = settings_.floorCentre();

    const auto common = []
    {
        return
            "        type            surfaceFieldValue;\n"
            "        libs            (\"libfieldFunctionObjects.so\");\n"
            "        writeControl    timeStep;\n"
            "        writeInterval   1;\n"
            "        log             false;\n"
            "        writeFields     false;\n";
    };
    const auto plane = [&](const word& object, const scalar z)
    {
        return
            "    " + object + "\n"
            "    {\n"
          + common()
          + "        surfaceFormat   none;\n"
            "        regionType      sampledSurface;\n"
            "        name            " + object + ";\n"
            "        sampledSurfaceDict\n"
            "        {\n"
            "            type        plane;\n"
            "            planeType   pointAndNormal;\n"
            "            pointAndNormalDict\n"
            "            {\n"
            "                point   " + vec(point(c.x(), c.y(), z)) + ";\n"
            "                normal  (0 0 1);\n"
            "            }\n"
            "            interpolate false;\n"
            "        }\n"
            "        operation       areaAverage;\n"
            "        fields          (p);\n"
            "    }\n";
    };

    return
        "application     simpleFoam;\n"
        "\n"
        "startFrom       latestTime;\n"
        "startTime       0;\n"
        "stopAt          endTime;\n"
        "endTime         " + nIter + ";\n"
        "deltaT          1;\n"
        "\n"
        "writeControl    timeStep;\n"
        "writeInterval   " + nIter + ";\n"
        "purgeWrite      0;\n"
        "writeFormat     ascii;\n"
        "writePrecision  8;\n"
        "writeCompression off;\n"
        "timeFormat      general;\n"
        "timePrecision   6;\n"
        "runTimeModifiable true;\n"
        "\n"
        "// Pressure drop over the packed section: the volumetric flow\n"
        "// rate through the inlet, and the area-averaged kinematic pressure\n"
        "// on the planes of the bed's bottom and top (rbdPacking's\n"
        "// pressureDropComparison reads them)\n"
        "functions\n"
        "{\n"
        "    " + flowRateObject + "\n"
        "    {\n"
      + common()
      + "        regionType      patch;\n"
        "        name            inlet;\n"
        "        operation       sum;\n"
        "        fields          (phi);\n"
        "    }\n"
      + plane(bedBottomObject, settings_.bedBottom())
      + plane(bedTopObject, settings_.bedTop())
      + "}\n";
}


std::string Foam::rbd::bedCaseWriter::fvSchemes() const
{
    return
        "ddtSchemes\n"
        "{\n"
        "    default         steadyState;\n"
        "}\n"
        "\n"
        "gradSchemes\n"
        "{\n"
        "    default         Gauss linear;\n"
        "    grad(U)         cellLimited Gauss linear 1;\n"
        "}\n"
        "\n"
        "divSchemes\n"
        "{\n"
        "    default         none;\n"
        "    div(phi,U)      bounded Gauss linearUpwind grad(U);\n"
        "    div((nuEff*dev2(T(grad(U))))) Gauss linear;\n"
        "}\n"
        "\n"
        "laplacianSchemes\n"
        "{\n"
        "    default         Gauss linear limited corrected 0.5;\n"
        "}\n"
        "\n"
        "interpolationSchemes\n"
        "{\n"
        "    default         linear;\n"
        "}\n"
        "\n"
        "snGradSchemes\n"
        "{\n"
        "    default         limited corrected 0.5;\n"
        "}\n";
}


std::string Foam::rbd::bedCaseWriter::fvSolution() const
{
    return
        "solvers\n"
        "{\n"
        "    p\n"
        "    {\n"
        "        solver          GAMG;\n"
        "        smoother        GaussSeidel;\n"
        "        tolerance       1e-7;\n"
        "        relTol          0.01;\n"
        "    }\n"
        "    U\n"
        "    {\n"
        "        solver          smoothSolver;\n"
        "        smoother        symGaussSeidel;\n"
        "        tolerance       1e-8;\n"
        "        relTol          0.1;\n"
        "    }\n"
        "}\n"
        "\n"
        "SIMPLE\n"
        "{\n"
        "    nNonOrthogonalCorrectors 0;\n"
        "    consistent      yes;\n"
        "    residualControl\n"
        "    {\n"
        "        p           1e-4;\n"
        "        U           1e-5;\n"
        "    }\n"
        "}\n"
        "\n"
        "relaxationFactors\n"
        "{\n"
        "    equations\n"
        "    {\n"
        "        U           0.9;\n"
        "        \".*\"        0.9;\n"
        "    }\n"
        "}\n";
}


std::string Foam::rbd::bedCaseWriter::transportProperties() const
{
    return
        "transportModel  Newtonian;\n"
        "\n"
        "nu              [0 2 -1 0 0 0 0] " + num(settings_.nu()) + ";\n";
}


std::string Foam::rbd::bedCaseWriter::turbulenceProperties() const
{
    return "simulationType  laminar;\n";
}


std::string Foam::rbd::bedCaseWriter::velocityField() const
{
    const std::string U =
        "uniform " + vec(vector(0, 0, settings_.superficialVelocity()));
    return
        "// Superficial velocity " + num(settings_.superficialVelocity())
      + " m/s (Re_p = " + num(settings_.reynoldsNumber()) + ")\n"
        "dimensions      [0 1 -1 0 0 0 0];\n"
        "\n"
        "internalField   " + U + ";\n"
        "\n"
        "boundaryField\n"
        "{\n"
        "    inlet\n"
        "    {\n"
        "        type            fixedValue;\n"
        "        value           " + U + ";\n"
        "    }\n"
        "    outlet\n"
        "    {\n"
        "        type            inletOutlet;\n"
        "        inletValue      uniform (0 0 0);\n"
        "        value           " + U + ";\n"
        "    }\n"
        "    " + anyOf(wallPatches()) + "\n"
        "    {\n"
        "        type            noSlip;\n"
        "    }\n"
        "}\n";
}


std::string Foam::rbd::bedCaseWriter::pressureField() const
{
    return
        "dimensions      [0 2 -2 0 0 0 0];\n"
        "\n"
        "internalField   uniform 0;\n"
        "\n"
        "boundaryField\n"
        "{\n"
        "    inlet\n"
        "    {\n"
        "        type            zeroGradient;\n"
        "    }\n"
        "    outlet\n"
        "    {\n"
        "        type            fixedValue;\n"
        "        value           uniform 0;\n"
        "    }\n"
        "    " + anyOf(wallPatches()) + "\n"
        "    {\n"
        "        type            zeroGradient;\n"
        "    }\n"
        "}\n";
}


Foam::fileNameList Foam::rbd::bedCaseWriter::write() const
{
    point location;
    if (!findLocationInMesh(settings_, insidePellet_, location))
    {
        FatalErrorInFunction
            << "No point in the fluid for snappyHexMesh's locationInMesh:"
            << " every cell of the background grid is within one cell of a"
            << " pellet or within two cells of the tube wall" << nl
            << "    increase cellsPerDiameter (now "
            << settings_.cellsPerDiameter() << ")" << exit(FatalError);
    }
    return write(location);
}


Foam::fileNameList Foam::rbd::bedCaseWriter::write
(
    const point& location
) const
{
    const string note
    (
        "Written by rbdPacking (bedCaseWriter) for a bed of dp = "
      + num(settings_.pelletDiameter()) + " m in a tube of D = "
      + num(settings_.tubeDiameter()) + " m"
    );

    // Every file as (path, class, body); the STL is written apart
    struct caseFile
    {
        fileName path;
        word className;
        std::string body;
    };
    const List<caseFile> dictFiles
    ({
        {"system/blockMeshDict", "dictionary", blockMeshDict()},
        {
            "system/surfaceFeatureExtractDict", "dictionary",
            surfaceFeatureExtractDict()
        },
        {
            "system/snappyHexMeshDict", "dictionary",
            snappyHexMeshDict(location)
        },
        {"system/decomposeParDict", "dictionary", decomposeParDict()},
        {"system/controlDict", "dictionary", controlDict()},
        {"system/fvSchemes", "dictionary", fvSchemes()},
        {"system/fvSolution", "dictionary", fvSolution()},
        {
            "constant/transportProperties", "dictionary",
            transportProperties()
        },
        {
            "constant/turbulenceProperties", "dictionary",
            turbulenceProperties()
        },
        {"0/U", "volVectorField", velocityField()},
        {"0/p", "volScalarField", pressureField()}
    });

    DynamicList<fileName> kept;
    const auto mayWrite = [&](const fileName& relative)
    {
        if (!settings_.overwrite() && isFile(caseDir_/relative))
        {
            kept.append(relative);
            return false;
        }
        return true;
    };

    const fileName tube("constant/triSurface/" + tubeFile);
    if (mayWrite(tube))
    {
        writeTube(caseDir_/tube);
    }
    for (const caseFile& f : dictFiles)
    {
        if (mayWrite(f.path))
        {
            writeFoamFile(caseDir_/f.path, f.className, f.body, note);
        }
    }

    if (kept.size())
    {
        string names;
        for (const fileName& f : kept)
        {
            names += (names.empty() ? "" : " ") + f;
        }
        WarningInFunction
            << "Kept files that the case already has (overwrite is off):"
            << nl << "    " << names.c_str() << nl
            << "    they may not fit this bed (e.g. locationInMesh)" << endl;
    }
    if (!isFile(caseDir_/"constant/triSurface"/pelletFile))
    {
        WarningInFunction
            << "No pellet surface constant/triSurface/" << pelletFile
            << " in " << caseDir_ << " yet" << endl;
    }

    return fileNameList(std::move(kept));
}


// ************************************************************************* //

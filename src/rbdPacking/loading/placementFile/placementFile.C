/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "placementFile.H"
#include "dictionaryChecks.H"
#include "bedOutput.H"
#include "OSspecific.H"
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::placementFile::unitTolerance = 1e-6;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The line without surrounding blanks (and a DOS line end)
std::string trimmed(const std::string& s)
{
    const std::string blanks(" \t\r");
    const auto a = s.find_first_not_of(blanks);
    if (a == std::string::npos)
    {
        return std::string();
    }
    const auto b = s.find_last_not_of(blanks);
    return s.substr(a, b - a + 1);
}


//- A finite number that is the whole field, or false
bool readNumber(const std::string& field, double& value)
{
    const std::string f(trimmed(field));
    if (f.empty())
    {
        return false;
    }
    char* end = nullptr;
    value = std::strtod(f.c_str(), &end);
    return end == f.c_str() + f.size() && std::isfinite(value);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::placementFile::placementFile
(
    const dictionary& dict,
    const tube& container,
    const pelletShape& shape
)
:
    file_(dict.get<fileName>("file")),
    path_(casePath(file_)),
    x_(),
    q_(),
    lines_()
{
    const string what
    (
        "a file of initial poses, the format of pellets.csv: the header '"
      + bedOutput::pelletsHeader + "', then one pellet a line"
    );
    if (!isFile(path_))
    {
        badEntry(dict, "file", file_, what + " (cannot find " + path_ + ")");
    }
    std::ifstream is(path_);
    if (!is)
    {
        badEntry(dict, "file", file_, what + " (cannot read " + path_ + ")");
    }

    const scalar R = container.radius();
    const scalar H = container.height();
    const scalar rb = shape.boundingRadius();

    DynamicList<point> xs;
    DynamicList<quaternion> qs;
    DynamicList<label> lines;
    bool headerRead = false;
    label lineNo = 0;
    std::string raw;
    while (std::getline(is, raw))
    {
        ++lineNo;
        const std::string line(trimmed(raw));
        if (line.empty() || line[0] == '#')
        {
            continue;
        }
        const string where(path_ + " line " + Foam::name(lineNo) + ": ");
        const auto bad = [&](const string& why)
        {
            badEntry(dict, "file", file_, what + " (" + where + why + ")");
        };

        if (!headerRead)
        {
            if (line != bedOutput::pelletsHeader)
            {
                bad("the first line is '" + line + "', not the header");
            }
            headerRead = true;
            continue;
        }

        std::vector<std::string> fields;
        {
            std::istringstream ls(line);
            std::string f;
            while (std::getline(ls, f, ','))
            {
                fields.push_back(trimmed(f));
            }
        }
        if (fields.size() != 9)
        {
            bad
            (
                Foam::name(label(fields.size())) + " fields, not the 9 of '"
              + bedOutput::pelletsHeader + "'"
            );
        }

        double id = 0;
        if (!readNumber(fields[0], id) || id != std::floor(id))
        {
            bad("id '" + fields[0] + "' is not a whole number");
        }
        if (fields[1] != shape.type())
        {
            bad
            (
                "shape '" + fields[1] + "', where the pellets of this run "
                "are " + shape.type() + " (pellets/shape)"
            );
        }
        static const char* names[] = {"x", "y", "z", "qw", "qx", "qy", "qz"};
        double v[7];
        for (int k = 0; k < 7; ++k)
        {
            if (!readNumber(fields[2 + k], v[k]))
            {
                bad
                (
                    string(names[k]) + " '" + fields[2 + k] + "' is not a "
                    "finite number"
                );
            }
        }

        const point x(v[0], v[1], v[2]);
        quaternion q(v[3], vector(v[4], v[5], v[6]));
        const scalar norm = Foam::sqrt
        (
            sqr(q.w()) + magSqr(q.v())
        );
        if (Foam::mag(norm - 1) > unitTolerance)
        {
            bad
            (
                "the quaternion (qw, qx, qy, qz) has length "
              + Foam::name(norm) + ", not 1 (within "
              + Foam::name(unitTolerance) + ")"
            );
        }
        q.normalize();

        const scalar rho = tube::axialDistance(x);
        if (rho >= R || x.z() <= 0 || x.z() >= H)
        {
            bad
            (
                "the centre (" + Foam::name(x.x()) + ", " + Foam::name(x.y())
              + ", " + Foam::name(x.z()) + ") m is outside the tube: "
                "distance from the axis " + Foam::name(rho) + " m, allowed "
                "below the radius " + Foam::name(R) + " m; height allowed "
                "in (0, " + Foam::name(H) + ") m (container/diameter, "
                "height)"
            );
        }
        if (x.z() + rb > H)
        {
            bad
            (
                "the pellet reaches " + Foam::name(x.z() + rb) + " m (centre "
                "height + bounding radius " + Foam::name(rb) + " m), above "
                "the top of the container at " + Foam::name(H) + " m: a "
                "container/height of at least " + Foam::name(x.z() + rb)
              + " m holds it"
            );
        }

        xs.append(x);
        qs.append(q);
        lines.append(lineNo);
    }

    if (!headerRead || xs.empty())
    {
        badEntry
        (
            dict, "file", file_,
            what + " (" + path_ + " holds "
          + (headerRead ? "no pellet" : "no header and no pellet") + ")"
        );
    }

    x_.transfer(xs);
    q_.transfer(qs);
    lines_.transfer(lines);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::placementFile::highestCentre() const
{
    scalar z = 0;
    for (const point& x : x_)
    {
        z = max(z, x.z());
    }
    return z;
}


// ************************************************************************* //

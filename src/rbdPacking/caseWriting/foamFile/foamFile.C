/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "foamFile.H"
#include "IOobject.H"
#include "IFstream.H"
#include "IStringStream.H"
#include "OFstream.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::dictionary Foam::rbd::parseDictionary(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}


namespace
{
    //- Open \c file and write banner, FoamFile header and note
    void writeHeader
    (
        Foam::OFstream& os,
        const Foam::fileName& file,
        const Foam::word& className,
        const Foam::string& note
    )
    {
        using namespace Foam;

        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot open " << file << " for writing"
                << exit(FatalError);
        }
        os.precision(12);

        IOobject::writeBanner(os);
        os.beginBlock("FoamFile");
        os.writeKeyword("version") << "2.0" << token::END_STATEMENT << nl;
        os.writeEntry("format", word("ascii"));
        os.writeEntry("class", className);
        os.writeEntry("location", string(file.path().name()));
        os.writeEntry("object", word(file.name()));
        os.endBlock();
        IOobject::writeDivider(os) << nl;

        std::string::size_type start = 0;
        while (start < note.size())
        {
            std::string::size_type end = note.find('\n', start);
            if (end == std::string::npos)
            {
                end = note.size();
            }
            os  << "// " << note.substr(start, end - start).c_str() << nl;
            start = end + 1;
        }
        if (!note.empty())
        {
            os << nl;
        }
    }
}


void Foam::rbd::writeFoamFile
(
    const fileName& file,
    const word& className,
    const dictionary& body,
    const string& note
)
{
    mkDir(file.path());
    OFstream os(file);
    writeHeader(os, file, className, note);
    body.write(os, false);
    os << nl;
    IOobject::writeEndDivider(os);
}


void Foam::rbd::writeFoamFile
(
    const fileName& file,
    const word& className,
    const std::string& body,
    const string& note
)
{
    parseDictionary(body);

    mkDir(file.path());
    OFstream os(file);
    writeHeader(os, file, className, note);
    os  << body.c_str() << nl;
    IOobject::writeEndDivider(os);
}


Foam::dictionary Foam::rbd::readFoamFile(const fileName& file)
{
    IFstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(is)
            << "Cannot read " << file << exit(FatalIOError);
    }
    dictionary dict(is);
    dict.remove("FoamFile");
    return dict;
}


// ************************************************************************* //

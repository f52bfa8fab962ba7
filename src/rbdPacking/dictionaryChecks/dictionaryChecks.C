/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "dictionaryChecks.H"
#include "OStringStream.H"
#include "Switch.H"
#include "OSspecific.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

namespace
{
    //- "a | b | c"
    Foam::string alternatives(const Foam::wordList& words)
    {
        Foam::string s;
        for (const Foam::word& w : words)
        {
            s += (s.empty() ? "" : " | ") + w;
        }
        return s;
    }

    Foam::string inUnit(const Foam::string& what, const Foam::word& unit)
    {
        Foam::string s(what);
        if (!unit.empty() && unit != "-")
        {
            s += " [" + unit + "]";
        }
        return s;
    }

    //- What a bounded number may be: "a number > 0 [m] (below 1e+15)", or
    //  "a number in (0, hi] [m]" when hi is a real bound (below GREAT)
    Foam::string bounded
    (
        const char* lower,
        const char* open,
        const Foam::scalar hi,
        const Foam::word& unit
    )
    {
        if (hi < Foam::GREAT)
        {
            return inUnit
            (
                Foam::string("a number in ") + open + ", " + Foam::name(hi)
              + "]",
                unit
            );
        }
        return
            inUnit(Foam::string("a number ") + lower, unit)
          + " (below " + Foam::name(Foam::GREAT) + ")";
    }
}


Foam::scalar Foam::rbd::getPositive
(
    const dictionary& dict,
    const word& key,
    const word& unit,
    const scalar hi
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0 && value <= hi))
    {
        badEntry(dict, key, value, bounded("> 0", "(0", hi, unit));
    }
    return value;
}


Foam::scalar Foam::rbd::getPositiveOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const word& unit,
    const scalar hi
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!(value > 0 && value <= hi))
    {
        badEntry(dict, key, value, bounded("> 0", "(0", hi, unit));
    }
    return value;
}


Foam::scalar Foam::rbd::getNonNegativeOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const word& unit,
    const scalar hi
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!(value >= 0 && value <= hi))
    {
        badEntry(dict, key, value, bounded(">= 0", "[0", hi, unit));
    }
    return value;
}


Foam::scalar Foam::rbd::getInRangeOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const scalar lo,
    const scalar hi,
    const word& unit
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!(value >= lo && value <= hi))
    {
        badEntry
        (
            dict, key, value,
            inUnit
            (
                "a number in [" + Foam::name(lo) + ", " + Foam::name(hi)
              + "]",
                unit
            )
        );
    }
    return value;
}


Foam::label Foam::rbd::getPositiveLabel
(
    const dictionary& dict,
    const word& key
)
{
    const label value = dict.get<label>(key);
    if (value <= 0)
    {
        badEntry(dict, key, value, "a whole number > 0");
    }
    return value;
}


Foam::label Foam::rbd::getLabelOrDefault
(
    const dictionary& dict,
    const word& key,
    const label deflt,
    const label lo,
    const label hi
)
{
    const label value = dict.getOrDefault<label>(key, deflt);
    if (value < lo || value > hi)
    {
        badEntry
        (
            dict, key, value,
            hi < labelMax
          ? "a whole number in [" + Foam::name(lo) + ", " + Foam::name(hi)
          + "]"
          : "a whole number >= " + Foam::name(lo)
        );
    }
    return value;
}


bool Foam::rbd::getSwitchOrDefault
(
    const dictionary& dict,
    const word& key,
    const bool deflt
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e)
    {
        return deflt;
    }

    const string allowed("true | false (or on | off, yes | no, 1 | 0)");
    if (e->isDict())
    {
        badEntry(dict, key, "{ ... }", allowed);
    }

    const ITstream& is = e->stream();
    if (is.size() == 1)
    {
        const token& t = is[0];
        if (t.isWord())
        {
            const Switch sw(t.wordToken(), true);
            if (sw.valid())
            {
                return bool(sw);
            }
        }
        else if (t.isLabel() && (t.labelToken() == 0 || t.labelToken() == 1))
        {
            return t.labelToken() == 1;
        }
    }

    OStringStream given;
    for (const token& t : is)
    {
        given << (given.str().empty() ? "" : " ") << t;
    }
    badEntry(dict, key, given.str().c_str(), allowed);
}


Foam::word Foam::rbd::getChoiceOrDefault
(
    const dictionary& dict,
    const word& key,
    const word& deflt,
    const wordList& allowed
)
{
    const word value = dict.getOrDefault<word>(key, deflt);
    if (!allowed.found(value))
    {
        badEntry(dict, key, value, "one of " + alternatives(allowed));
    }
    return value;
}


Foam::fileName Foam::rbd::casePath(const fileName& entry)
{
    fileName path(entry);
    path.expand();
    if (!path.isAbsolute() && !getEnv("FOAM_CASE").empty())
    {
        path = fileName(getEnv("FOAM_CASE"))/path;
    }
    return path;
}


Foam::dictionary Foam::rbd::subDictOrEmpty
(
    const dictionary& dict,
    const word& key
)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (e && !e->isDict())
    {
        FatalIOErrorInFunction(dict)
            << "Bad entry '" << key << "' in " << dict.name() << nl
            << "    it is not a sub-dictionary; allowed: " << key
            << " { ... } (or no entry, for the defaults)" << nl
            << exit(FatalIOError);
    }
    return dict.subOrEmptyDict(key);
}


void Foam::rbd::checkKnownEntries
(
    const dictionary& dict,
    const wordList& known
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (!known.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << key << "' in " << dict.name() << nl
                << "    allowed: " << alternatives(known).c_str() << nl
                << exit(FatalIOError);
        }
    }
}


Foam::string Foam::rbd::inWords
(
    const UList<word>& words,
    const char* conjunction
)
{
    string s;
    forAll(words, i)
    {
        if (i > 0)
        {
            s +=
                i + 1 == words.size()
              ? " " + std::string(conjunction) + " "
              : std::string(", ");
        }
        s += words[i];
    }
    return s;
}


// ************************************************************************* //

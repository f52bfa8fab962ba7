#------------------------------------------------------------------------------
# Sourced by lib/checks.sh and lib/caseSteps.sh: what every packing's summary
# must say, whichever test ran it.
#
# releaseOverlapOf SUMMARY: prints the summary's releaseOverlap [m], the
# largest interpenetration of a pellet at its release (into the container or
# another pellet; packedBed::releasePellets), empty when it has none. The
# loading's bounds (loadingScheme) and the release rule make it 0 for every
# dictionary that is accepted: any other value is a bug.
#------------------------------------------------------------------------------

releaseOverlapOf()
{
    awk '$1 == "releaseOverlap" {sub(";", "", $2); print $2; exit}' "$1" \
        2>/dev/null
}

# releaseOverlapAllowed SUMMARY: exit 0 if the summary's releaseOverlap is
# what its loading allows: 0 for the release schemes; for scheme placement
# (pellets placed from a file, as an earlier bed left them) the exact
# interpenetration of the file's poses, which the placement check keeps
# within the touching gap, 1e-4 dp at the default contactTolerance
releaseOverlapAllowed()
{
    awk '{sub(";", "", $2)} $1 == "releaseOverlap" {v = $2; found = 1}
         $1 == "loadingScheme" {scheme = $2}
         $1 == "pelletDiameter" {dp = $2}
         END {if (!found) exit 1
              if (scheme == "placement") exit !(v + 0 >= 0 && v + 0 <= 1e-4*dp)
              exit !(v "" == "0")}' "$1" 2>/dev/null
}

#------------------------------------------------------------------------------

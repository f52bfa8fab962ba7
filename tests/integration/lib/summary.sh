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

#------------------------------------------------------------------------------

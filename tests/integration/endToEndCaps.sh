#!/bin/bash
#------------------------------------------------------------------------------
# End to end with nonspherical pellets and a contact treatment: a small bed
# of cylinders with capped contacts (cases/endToEndCaps: 6 cylinders
# d = h = 10 mm in a tube of 30 mm, cfdCase contactTreatment caps, a coarse
# mesh) goes the whole way with the built rbdPackBed and rbdPressureDrop and
# Debian's OpenFOAM v1912, with no hand editing:
#     rbdPackBed                 exit 0, status settled, releaseOverlap
#                                0; caps cut at the contacts the log and
#                                the summary count
#                                (treatedContacts > 0, the same number);
#                                every pellet of pellets.stl clear of the
#                                tube wall by more than capHeight/4 (the
#                                wall contacts are capped: without caps a
#                                pellet touches the wall)
#     foamDictionary -expand     on every written dictionary
#     blockMesh, surfaceFeatureExtract, snappyHexMesh -overwrite
#     checkMesh                  'Mesh OK.' and patches exactly inlet outlet
#                                pellets wall
#     simpleFoam                 'SIMPLE solution converged', no NaN
#     rbdPressureDrop            a positive finite dP/L, equal to
#                                (pBottom - pTop)/planeDistance of its own
#                                comparison; above 5 times the empty tube's
#                                Hagen-Poiseuille 32 nu U/D^2 (the pellets
#                                are in the mesh) and below 3 times
#                                Eisfeld-Schnitzlein's (the gaps are open);
#                                its Ergun value equals the closed form for
#                                the comparison's own porosity, U, dpv, nu
# Prints the time of every step (about 1 minute here, loaded). Runs in a
# temporary directory, removed on success, kept (and named) on failure.
#
# Usage: bash tests/integration/endToEndCaps.sh    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u

here="$(cd "$(dirname "$0")" && pwd)"

. "$here/lib/caseSteps.sh"
startCase endToEndCaps

# true if awk's condition on the named values holds
holds() { awk "BEGIN {exit !($1)}"; }

total=$(date +%s.%N)
echo "endToEndCaps in $work"

run rbdPackBed rbdPackBed
summary=postProcessing/rbdPackBed/summary
[ -f "$summary" ] || fail "no summary written"
releaseOverlapZero
[ -f constant/triSurface/pellets.stl ] || fail "no pellets.stl written"
get() { foamDictionary -entry "$1" -value "$2" 2>/dev/null; }
[ "$(get status $summary)" = settled ] || fail "status $(get status $summary)"
grep -E '^(pellets|bedHeight|bulkPorosity|bedPorosity|treatedContacts) ' \
    "$summary" | sed 's/^/    /'

# Caps: counted alike in the log and the summary, and cut
treated="$(get treatedContacts $summary)"
logged="$(sed -n 's/.*(caps at \([0-9]*\) contacts).*/\1/p' log.rbdPackBed)"
[ -n "$treated" ] && [ "$treated" -gt 0 ] \
    || fail "treatedContacts '$treated': no contact capped"
[ "$logged" = "$treated" ] \
    || fail "the log caps $logged contacts, the summary counts $treated"
R="$(get container/diameter system/packingDict | awk '{print $1/2}')"
capHeight="$(get cfdCase/capHeight system/packingDict)"
maxRho="$(awk '$1 == "vertex" {r = sqrt($2*$2 + $3*$3); if (r > m) m = r}
               END {printf "%.9g", m}' constant/triSurface/pellets.stl)"
holds "$maxRho < $R - $capHeight/4" \
    || fail "a pellet of pellets.stl reaches $maxRho m from the axis," \
            "within capHeight/4 of the wall at $R m: not capped"
echo "    pellets.stl: farthest vertex $maxRho m from the axis (R = $R m," \
     "capHeight $capHeight m)"

for f in system/blockMeshDict system/surfaceFeatureExtractDict \
         system/snappyHexMeshDict system/controlDict system/fvSchemes \
         system/fvSolution constant/transportProperties \
         constant/turbulenceProperties 0/U 0/p
do
    [ -f "$f" ] || fail "rbdPackBed did not write $f"
    foamDictionary -expand "$f" > /dev/null 2>&1 \
        || fail "foamDictionary -expand $f"
done

meshCase

run simpleFoam simpleFoam
grep -qiE '(^|[^a-z])nan([^a-z]|$)' log.simpleFoam \
    && fail "NaN in log.simpleFoam"
grep -q 'SIMPLE solution converged' log.simpleFoam \
    || fail "simpleFoam did not converge in $(get endTime system/controlDict)" \
            "iterations"
grep 'SIMPLE solution converged' log.simpleFoam | sed 's/^/    /'

run rbdPressureDrop rbdPressureDrop
sed -n '/^Pressure drop/,/E-S/p' log.rbdPressureDrop

# The comparison's top-level entries as written (full precision: the
# -value of foamDictionary rounds to 6 digits)
c=postProcessing/pressureDrop/comparison
for key in dPdLSimulated pBottom pTop planeDistance dPdLErgun \
           dPdLEisfeldSchnitzlein bedPorosity superficialVelocity \
           volumeEquivalentDiameter nu tubeDiameter
do
    v="$(awk -v k=$key '/^[a-zA-Z]/ && $1 == k {sub(";", "", $2); print $2}' $c)"
    [ -n "$v" ] || fail "no $key in the comparison"
    eval "$key=$v"
done
holds "$dPdLSimulated > 0 && $dPdLSimulated < 1e30" \
    || fail "dP/(rho L) = $dPdLSimulated: not positive and finite"
holds "($pBottom - $pTop)/$planeDistance > $dPdLSimulated*(1 - 1e-6) &&
       ($pBottom - $pTop)/$planeDistance < $dPdLSimulated*(1 + 1e-6)" \
    || fail "dPdLSimulated $dPdLSimulated is not (pBottom - pTop)/L"
emptyTube="$(awk -v n=$nu -v U=$superficialVelocity -v D=$tubeDiameter \
    'BEGIN {printf "%.8g", 32*n*U/(D*D)}')"
holds "$dPdLSimulated > 5*$emptyTube" \
    || fail "dP/(rho L) = $dPdLSimulated, not above 5 times the empty" \
            "tube's $emptyTube"
holds "$dPdLSimulated < 3*$dPdLEisfeldSchnitzlein" \
    || fail "dP/(rho L) = $dPdLSimulated, above 3 times" \
            "Eisfeld-Schnitzlein's $dPdLEisfeldSchnitzlein"
ergun="$(awk -v e=$bedPorosity -v U=$superficialVelocity \
    -v d=$volumeEquivalentDiameter -v n=$nu 'BEGIN {
        printf "%.10g", 150*n*(1 - e)^2*U/(e^3*d*d) + 1.75*(1 - e)*U*U/(e^3*d)}')"
holds "$dPdLErgun > $ergun*(1 - 1e-5) && $dPdLErgun < $ergun*(1 + 1e-5)" \
    || fail "Ergun $dPdLErgun, the closed form gives $ergun"
echo "    dP/(rho L) = $dPdLSimulated m/s^2: $(awk -v a=$dPdLSimulated \
    -v b=$emptyTube 'BEGIN {printf "%.0f", a/b}') times the empty tube's," \
    "simulated/Eisfeld-Schnitzlein $(get ratioEisfeldSchnitzlein $c)"

awk -v t="$total $(date +%s.%N)" 'BEGIN {split(t, a, " ");
    printf "    %-26s %6.1f s\n", "total", a[2] - a[1]}'

cd / && rm -rf "$work"
echo "endToEndCaps: OK"

#!/bin/bash
#------------------------------------------------------------------------------
# More pellets asked for than fit below the release height (40; 80 would not
# fit even at porosity 0.26, an error before the run): the loader stops
# when the bed reaches it, warns, and the run settles with fewer pellets:
# 'settled' true (the kinetic-energy test ended it, not endTime), 'pellets'
# below 'requestedPellets', status 'incomplete' and exit 1 with no STL;
# -acceptStatus then writes the STL. (It used to stop at the first quiet
# moment and report "Not settled by endTime" with the whole bed asleep.)
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"

cp -r "$here/cases/smallSpheres" "$tmp/a"
dict="$tmp/a/system/packingDict"
foamDictionary -entry pellets/number -set 40 "$dict" >/dev/null
foamDictionary -entry loading/releaseHeight -set 0.03 "$dict" >/dev/null
foamDictionary -entry simulation/endTime -set 20 "$dict" >/dev/null

rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1
rc=$?
check "exit status 1 (status incomplete)" \
    "[ $rc -eq 1 ] && grep -q '^Status: incomplete' $tmp/a.log"
check "log warns that the bed reached the release height" \
    "grep -q 'reached the release height with' $tmp/a.log"
check "log says settled with fewer pellets" \
    "grep -q 'Settled: .*of 40 pellets' $tmp/a.log"
out="$tmp/a/postProcessing/rbdPackBed"
n="$(foamDictionary -entry pellets -value $out/summary 2>/dev/null)"
asked="$(foamDictionary -entry requestedPellets -value $out/summary 2>/dev/null)"
settled="$(foamDictionary -entry settled -value $out/summary 2>/dev/null)"
t="$(foamDictionary -entry simulatedTime -value $out/summary 2>/dev/null)"
check "summary settled true ($settled)" "[ \"$settled\" = true ]"
check "summary pellets $n < requestedPellets $asked" \
    "[ -n \"$n\" ] && [ \"$asked\" = 40 ] && [ \"$n\" -lt 40 ]"
check "ended before endTime ($t s)" "awk 'BEGIN{exit !($t < 20)}'"
check "no STL for an incomplete bed" "[ ! -e $tmp/a/constant/triSurface/pellets.stl ]"
rbdPackBed -case "$tmp/a" -acceptStatus > "$tmp/b.log" 2>&1
rc=$?
check "-acceptStatus: exit 0 and the STL written" \
    "[ $rc -eq 0 ] && [ -s $tmp/a/constant/triSurface/pellets.stl ]"
exit $fail

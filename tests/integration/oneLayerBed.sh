#!/bin/bash
#------------------------------------------------------------------------------
# A bed about one pellet high (6 spheres in a wide tube): the default
# porosity height (bed height - 1 dp) would be empty, so the porosity is
# analysed up to the top of the bed; the run must end normally with its
# outputs (it used to stop with a FatalError after the whole simulation).
# Without rotation: a lone sphere rolling on the floor has nothing to stop
# it (no rolling resistance) and would end notSettled.
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"

cp -r "$here/cases/smallSpheres" "$tmp/a"
foamDictionary -entry container/diameter -set 0.08 "$tmp/a/system/packingDict" >/dev/null
foamDictionary -entry pellets/number -set 6 "$tmp/a/system/packingDict" >/dev/null
foamDictionary -entry pellets/rotation -add false "$tmp/a/system/packingDict" >/dev/null

rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1
rc=$?
check "exit status 0, status settled" \
    "[ $rc -eq 0 ] && [ \"\$(foamDictionary -entry status -value $tmp/a/postProcessing/rbdPackBed/summary 2>/dev/null)\" = settled ]"
check "log says the whole bed is analysed" "grep -q 'porosity analysed up to its top' $tmp/a.log"
out="$tmp/a/postProcessing/rbdPackBed"
H="$(foamDictionary -entry porosityHeight -value $out/summary 2>/dev/null)"
top="$(foamDictionary -entry bedHeight -value $out/summary 2>/dev/null)"
check "porosity height $H is the bed height $top" "[ -n \"$H\" ] && [ \"$H\" = \"$top\" ]"
check "STL written" "[ -s $tmp/a/constant/triSurface/pellets.stl ]"
exit $fail

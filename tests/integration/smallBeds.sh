#!/bin/bash
#------------------------------------------------------------------------------
# Beds of two or three nonspherical pellets settle (smallBeds.cases says
# which and why): status settled, simulated time at most 10 s (the beds
# settle in 1-5 s), fewer than 1 000 overlap corrections (the wobble of
# before made 5 000-16 000), the largest interpenetration below 0.5 % dp.
#
# Usage: bash tests/integration/smallBeds.sh <case>    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"

case="${1:?usage: smallBeds.sh <case of smallBeds.cases>}"
read -r name shape n seed model <<< \
    "$(grep -E "^$case( |$)" "$here/smallBeds.cases")"
if [ "${name:-}" != "$case" ] || [ -z "${model:-}" ]
then
    echo "smallBeds.sh: no case '$case' in smallBeds.cases" 1>&2
    exit 1
fi

case "$shape" in
    cylinder) geometry="shape cylinder; diameter 0.01; height 0.01;" ;;
    ring) geometry="shape ring; diameter 0.01; innerDiameter 0.006; height 0.01;" ;;
    trilobe) geometry="shape trilobe; lobeDiameter 0.006; height 0.01;" ;;
esac

mkdir -p "$tmp/a/system"
cat > "$tmp/a/system/packingDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object packingDict; }
container { type cylinder; diameter 0.03; height 0.06; }
pellets { $geometry number $n; density 2500; friction 0.5; restitution 0.5; }
loading { seed $seed; }
simulation { contactModel $model; endTime 10; }
EOD

rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1
rc=$?
summary="$tmp/a/postProcessing/rbdPackBed/summary"
get()
{
    foamDictionary -entry "$1" -value "$summary" 2>/dev/null
}
corrections="$(sed -n 's/.* \([0-9][0-9]*\) overlap corrections.*/\1/p' "$tmp/a.log")"
check "exit 0, status settled" "[ $rc -eq 0 ] && [ \"$(get status)\" = settled ]"
t="$(get simulatedTime)"
ov="$(get maxOverlap)"
check "settled within 10 s simulated (${t:-none} s)" \
    "[ $rc -eq 0 ] && [ -n \"$t\" ] && awk -v t=$t 'BEGIN {exit !(t < 10)}'"
check "fewer than 1000 overlap corrections (${corrections:-none})" \
    "[ -n \"$corrections\" ] && [ $corrections -lt 1000 ]"
check "largest interpenetration ${ov:-none} m below 0.5 % dp" \
    "[ $rc -eq 0 ] && [ -n \"$ov\" ] && awk -v o=$ov 'BEGIN {exit !(o < 5e-5)}'"
echo "smallBeds.$case: simulated $t s, $corrections corrections, maxOverlap $ov m, cpu $(get cpuTime) s"
exit $fail

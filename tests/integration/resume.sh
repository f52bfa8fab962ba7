#!/bin/bash
#------------------------------------------------------------------------------
# rbdPackBed -resume: a run stopped at endTime leaves a checkpoint, and the
# run resumed from it with a larger endTime gives the packing of the run
# that never stopped, bit for bit (spheres, and cylinders on meshes and as
# exact solids with the coupled friction solve); a settled run removes its checkpoint; the
# wall-clock interval writes checkpoints while running. Refused: -resume
# without a checkpoint, with an endTime not beyond the checkpoint's time,
# with a dictionary that packs differently, with a
# file that is not a checkpoint or is truncated; none of them writes any
# output.
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"

out=postProcessing/rbdPackBed

# resumeCase NAME STOP: the case $tmp/NAME-full packed in one run and
# $tmp/NAME-split stopped at endTime STOP and resumed
resumeCase()
{
    local name="$1" stop="$2" stoppedAt="${3:-$2}"
    local full="$tmp/$name-full" split="$tmp/$name-split"
    local end
    end="$(foamDictionary -entry simulation/endTime -value "$full/system/packingDict" 2>/dev/null)"

    local rc
    rbdPackBed -case "$full" > "$full.log" 2>&1
    rc=$?
    check "$name: the full run exits 0 and settles" \
        "[ $rc -eq 0 ] && [ \"\$(foamDictionary -entry settled -value $full/$out/summary 2>/dev/null)\" = true ]"
    check "$name: a settled run writes its packing and leaves no checkpoint" \
        "[ $rc -eq 0 ] && [ -s $full/$out/pellets.csv ] && [ ! -e $full/$out/checkpoint ]"

    foamDictionary "$split/system/packingDict" -entry simulation/endTime -set "$stop" >/dev/null
    rbdPackBed -case "$split" > "$split.1.log" 2>&1
    rc=$?
    check "$name: stopped at endTime $stop: exit $unsettledStatus, not settled" \
        "[ $rc -eq $unsettledStatus ] && grep -q 'Not settled by endTime' $split.1.log"
    check "$name: ... and a checkpoint written" \
        "[ -s $split/$out/checkpoint ] && grep -q 'Checkpoint at t = $stoppedAt s' $split.1.log"

    foamDictionary "$split/system/packingDict" -entry simulation/endTime -set "$end" >/dev/null
    rbdPackBed -case "$split" -resume > "$split.2.log" 2>&1
    rc=$?
    check "$name: -resume runs and says from where" \
        "[ $rc -eq 0 ] && grep -q 'Resuming from $out/checkpoint at t = $stoppedAt s' $split.2.log"
    check "$name: resumed packing = uninterrupted packing, bit for bit" \
        "[ -s $full/$out/pellets.csv ] && cmp -s $full/$out/pellets.csv $split/$out/pellets.csv"
    for key in steps simulatedTime collisions maxOverlap bulkPorosity
    do
        check "$name: same $key" \
            "v=\$(foamDictionary -entry $key -value $full/$out/summary 2>/dev/null) && [ -n \"\$v\" ] && [ \"\$v\" = \"\$(foamDictionary -entry $key -value $split/$out/summary 2>/dev/null)\" ]"
    done
    # The packing time counts the first run's up to its checkpoint
    local w1 w2 c2
    w1="$(sed -n 's/^Resuming from .* pellets released, [0-9]* steps, \([0-9.e+-]*\) s of wall time so far$/\1/p' "$split.2.log")"
    w2="$(foamDictionary -entry wallTime -value "$split/$out/summary" 2>/dev/null)"
    c2="$(foamDictionary -entry cpuTime -value "$split/$out/summary" 2>/dev/null)"
    check "$name: wall time of both runs adds up (${w1:-?} s before the resume, $w2 s in all; CPU $c2 s)" \
        "awk -v a=${w1:-0} -v b=$w2 -v c=$c2 'BEGIN {exit !(a > 0 && b > a && c > 0)}'"
    check "$name: the settled resumed run removed its checkpoint" \
        "[ $rc -eq 0 ] && [ -s $split/$out/pellets.csv ] && [ ! -e $split/$out/checkpoint ] && grep -q 'Removed $out/checkpoint' $split.2.log"
}

# Spheres (exact contacts)
cp -r "$here/cases/smallSpheres" "$tmp/spheres-full"
cp -r "$here/cases/smallSpheres" "$tmp/spheres-split"
resumeCase spheres 0.7

# Stopped mid-fill at a time off the grid of outer intervals (deltaT
# 0.025 s): the run stops at the end of the interval, 0.725 s
cp -r "$here/cases/smallSpheres" "$tmp/offGrid-full"
cp -r "$here/cases/smallSpheres" "$tmp/offGrid-split"
resumeCase offGrid 0.71 0.725

# Cylinders on 80-face meshes (contactModel mesh), and as exact solids
# (auto: prismContacts, rolling resistance), coupled resting friction
for c in cylinders-full cylinders-split exactCylinders-full exactCylinders-split
do
    cp -r "$here/cases/smallSpheres" "$tmp/$c"
    d="$tmp/$c/system/packingDict"
    foamDictionary "$d" -entry pellets/shape -set cylinder >/dev/null
    foamDictionary "$d" -entry pellets/height -set 0.01 >/dev/null
    foamDictionary "$d" -entry pellets/number -set 8 >/dev/null
    foamDictionary "$d" -entry simulation/endTime -set 8 >/dev/null
    case "$c" in
        cylinders-*) foamDictionary "$d" -entry simulation/contactModel -set mesh >/dev/null ;;
    esac
done
# Stopped while they settle (all released by 0.5 s; the meshes settled at
# 1.175 s when this was written, 2026-11-26)
resumeCase cylinders 0.6
resumeCase exactCylinders 0.6

# Checkpoints by the wall clock while the run goes on
cp -r "$here/cases/smallSpheres" "$tmp/often"
foamDictionary "$tmp/often/system/packingDict" -entry simulation/checkpointInterval -set 1e-6 >/dev/null
foamDictionary "$tmp/often/system/packingDict" -entry simulation/endTime -set 0.5 >/dev/null
rbdPackBed -case "$tmp/often" > "$tmp/often.log" 2>&1
rc=$?
check "checkpointInterval 1e-6: exit $unsettledStatus (not settled), a checkpoint at every outer interval" \
    "[ $rc -eq $unsettledStatus ] && [ \$(grep -c 'Checkpoint at t = ' $tmp/often.log) -ge 15 ] && [ -s $tmp/often/$out/checkpoint ] && [ ! -e $tmp/often/$out/checkpoint.tmp ]"
check "checkpointInterval is echoed" "grep -q 'checkpointInterval *1e-06' $tmp/often.log"

# checkpointInterval 0: none, not even at endTime
cp -r "$here/cases/smallSpheres" "$tmp/never"
foamDictionary "$tmp/never/system/packingDict" -entry simulation/checkpointInterval -set 0 >/dev/null
foamDictionary "$tmp/never/system/packingDict" -entry simulation/endTime -set 0.5 >/dev/null
rbdPackBed -case "$tmp/never" > "$tmp/never.log" 2>&1
rc=$?
check "checkpointInterval 0: the run ends at endTime as the others do (exit $unsettledStatus, pellets.csv)" \
    "[ $rc -eq $unsettledStatus ] && grep -q 'Not settled by endTime' $tmp/never.log && [ -s $tmp/never/$out/pellets.csv ]"
check "checkpointInterval 0: ... and writes no checkpoint, nor says so" \
    "[ $rc -eq $unsettledStatus ] && [ ! -e $tmp/never/$out/checkpoint ] && ! grep -q 'Checkpoint at t = ' $tmp/never.log"

# Refusals: nonzero exit, the reason, no output
refused()
{
    local name="$1" case="$2" regex="$3"
    rm -rf "$case/$out/pellets.csv" "$case/$out/summary" "$case/constant/triSurface"
    rbdPackBed -case "$case" -resume > "$case.refused.log" 2>&1
    local rc=$?
    check "$name: nonzero exit" "[ $rc -ne 0 ]"
    check "$name: says why" "grep -Eq \"$regex\" $case.refused.log"
    check "$name: no stack trace" "! grep -q 'printStack\|#1  ' $case.refused.log"
    check "$name: nothing written" \
        "[ ! -e $case/$out/pellets.csv ] && [ ! -e $case/$out/summary ] && [ ! -e $case/constant/triSurface/pellets.stl ]"
}

cp -r "$here/cases/smallSpheres" "$tmp/none"
refused "no checkpoint" "$tmp/none" "No checkpoint .*checkpoint to resume from"

cp -r "$tmp/often" "$tmp/changed"
foamDictionary "$tmp/changed/system/packingDict" -entry pellets/friction -set 0.2 >/dev/null
refused "pellets changed" "$tmp/changed" "Entry 'pellets' of .*packingDict differs from its value in the dictionary the checkpoint"

cp -r "$tmp/often" "$tmp/changedDigits"
# (sed: foamDictionary -set writes 6 digits)
sed -i 's/^\( *density *\)8030;/\18030.0004;/' "$tmp/changedDigits/system/packingDict"
refused "a change in the 8th digit" "$tmp/changedDigits" "Entry 'pellets' of .*differs"

cp -r "$tmp/often" "$tmp/changedSim"
foamDictionary "$tmp/changedSim/system/packingDict" -entry simulation/restingVelocity -set 0.02 >/dev/null
refused "simulation/restingVelocity changed" "$tmp/changedSim" "Entry 'simulation' of .*differs"

cp -r "$tmp/often" "$tmp/endTimeChanged"
foamDictionary "$tmp/endTimeChanged/system/packingDict" -entry simulation/endTime -set 0.7 >/dev/null
foamDictionary "$tmp/endTimeChanged/system/packingDict" -entry cfdCase/cellsPerDiameter -set 10 >/dev/null
rbdPackBed -case "$tmp/endTimeChanged" -resume > "$tmp/endTimeChanged.log" 2>&1
rc=$?
check "endTime and cfdCase may change: resumed to the new endTime" \
    "[ $rc -eq $unsettledStatus ] && grep -q 'Not settled by endTime' $tmp/endTimeChanged.log && grep -q 'Simulated 0.7 s' $tmp/endTimeChanged.log"

cp -r "$tmp/often" "$tmp/endTimeBefore"
foamDictionary "$tmp/endTimeBefore/system/packingDict" -entry simulation/endTime -set 0.3 >/dev/null
refused "endTime before the checkpoint's time" "$tmp/endTimeBefore" "allowed: a time beyond the checkpoint's, t = 0.5 s"

cp -r "$tmp/often" "$tmp/garbage"
echo "not a checkpoint" > "$tmp/garbage/$out/checkpoint"
refused "not a checkpoint" "$tmp/garbage" "is not an rbdPacking checkpoint"

cp -r "$tmp/often" "$tmp/truncated"
size=$(stat -c %s "$tmp/truncated/$out/checkpoint")
truncate -s $((size / 2)) "$tmp/truncated/$out/checkpoint"
refused "truncated checkpoint" "$tmp/truncated" "ends before its state does|it is damaged"

cp -r "$tmp/often" "$tmp/longer"
echo "x" >> "$tmp/longer/$out/checkpoint"
refused "checkpoint with trailing bytes" "$tmp/longer" "holds more than the state"

# A damaged size field (the number of dictionary blocks, after the magic
# and four labels): refused at once, no allocation of gigabytes
cp -r "$tmp/often" "$tmp/hugeSize"
printf '\xff\xff\xff\x7f' | dd of="$tmp/hugeSize/$out/checkpoint" bs=1 seek=41 conv=notrunc status=none
refused "damaged size field" "$tmp/hugeSize" "holds a list of 2147483647 entries"

# A fresh run (no -resume) removes the checkpoint an earlier run left
# (the exit status of an unsettled run is also that of a refusal: the log
# must say the run reached endTime; pellets.csv is the earlier run's)
cp -r "$tmp/often" "$tmp/stale"
foamDictionary "$tmp/stale/system/packingDict" -entry simulation/checkpointInterval -set 0 >/dev/null
rbdPackBed -case "$tmp/stale" > "$tmp/stale.log" 2>&1
rc=$?
check "a fresh run removes an earlier run's checkpoint" \
    "[ $rc -eq $unsettledStatus ] && grep -q 'Not settled by endTime' $tmp/stale.log && [ ! -e $tmp/stale/$out/checkpoint ] && grep -q 'of an earlier run' $tmp/stale.log"

exit $fail

#!/bin/bash
#------------------------------------------------------------------------------
# simulation/threads: the narrow phase of mesh pellets on 1, 2 and 3 threads
# gives the same packing. The ring bed of shapes.sh on meshes (ringMesh:
# 8 Raschig rings, the triangle-mesh narrow phase) is packed with threads 1, 2 and 3 (3 on a
# 2-core machine too: more threads than cores changes nothing but the
# time). Checks:
#   - each run exits 0, settles and echoes its thread count in the log
#     (the effective settings and the narrow-phase line);
#   - pellets.csv of the three runs is the same, byte for byte (the
#     contacts built on the threads are joined in a fixed order);
#   - a run stopped at endTime on 1 thread and resumed on 2 (threads
#     does not shape the packing, so -resume accepts the change) gives
#     that pellets.csv too.
# Prints each run's time.
#
# Usage: bash tests/integration/threads.sh    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"

source="$here/cases/shapes/ringMesh"
for t in 1 2 3
do
    d="$tmp/t$t"
    mkdir -p "$d"
    cp -r "$source/system" "$d/"
    foamDictionary -entry simulation/threads -set "$t" \
        "$d/system/packingDict" > /dev/null 2>&1 \
    || foamDictionary -entry simulation/threads -add "$t" \
        "$d/system/packingDict" > /dev/null
    start=$(date +%s.%N)
    rbdPackBed -case "$d" > "$d/log" 2>&1
    rc=$?
    echo "threads $t: $(echo "$(date +%s.%N) - $start" | bc) s"
    csv="$d/postProcessing/rbdPackBed/pellets.csv"
    check "threads $t: exit 0, settled, pellets.csv written" \
        "[ $rc -eq 0 ] && grep -q 'Status: settled' '$d/log' && [ -s '$csv' ]"
    check "threads $t: the log echoes it" \
        "[ $rc -eq 0 ] && grep -Eq '^ *threads +$t;' '$d/log' \
         && grep -q 'pellet pairs on $t thread' '$d/log'"
done

for t in 2 3
do
    check "threads $t: pellets.csv the same as with 1 thread" \
        "[ -s '$tmp/t1/postProcessing/rbdPackBed/pellets.csv' ] \
         && cmp -s '$tmp/t1/postProcessing/rbdPackBed/pellets.csv' \
                   '$tmp/t$t/postProcessing/rbdPackBed/pellets.csv'"
done

# Stopped at endTime 0.5 s on 1 thread, resumed to 10 s on 2
d="$tmp/resumed"
mkdir -p "$d"
cp -r "$source/system" "$d/"
foamDictionary -entry simulation/threads -set 1 "$d/system/packingDict" \
    > /dev/null 2>&1 \
|| foamDictionary -entry simulation/threads -add 1 "$d/system/packingDict" \
    > /dev/null
foamDictionary -entry simulation/endTime -set 0.5 "$d/system/packingDict" \
    > /dev/null
rbdPackBed -case "$d" > "$d/log.1" 2>&1
rc1=$?
foamDictionary -entry simulation/endTime -set 10 "$d/system/packingDict" \
    > /dev/null
foamDictionary -entry simulation/threads -set 2 "$d/system/packingDict" \
    > /dev/null
rbdPackBed -case "$d" -resume > "$d/log.2" 2>&1
rc2=$?
check "1 thread stopped at endTime, resumed on 2: the same pellets.csv" \
    "[ $rc1 -eq $unsettledStatus ] && grep -q 'Status: notSettled' '$d/log.1' \
     && [ $rc2 -eq 0 ] && grep -q 'Resuming from' '$d/log.2' \
     && grep -q 'pellet pairs on 2 threads' '$d/log.2' \
     && cmp -s '$tmp/t1/postProcessing/rbdPackBed/pellets.csv' \
               '$d/postProcessing/rbdPackBed/pellets.csv'"

exit $fail

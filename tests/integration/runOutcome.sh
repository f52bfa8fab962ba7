#!/bin/bash
#------------------------------------------------------------------------------
# How a run ends (one case of runOutcome.cases, argument: its name): the
# status in the summary and the log, the exit status, what is written for a
# bed that is not settled, Ctrl-C and -resume, re-runs in a case of an
# earlier bed, unit mistakes, a case sized to the bed, Allclean.
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"
name="$1"
out=postProcessing/rbdPackBed

# A packingDict of spheres of dp [m] in a tube of dt [m], height H [m]
spheres()
{
    local case="$1" dp="$2" n="$3" dt="$4" H="$5" loading="${6:-}"
    mkdir -p "$case/system"
    cat > "$case/system/packingDict" <<EOF
FoamFile { version 2.0; format ascii; class dictionary; object packingDict; }
container { type cylinder; diameter $dt; height $H; }
pellets { shape sphere; diameter $dp; number $n; density 2500; faces 80; }
$loading
EOF
}

status() { foamDictionary -entry status -value "$1/$out/summary" 2>/dev/null; }
noCase()
{
    [ ! -e "$1/constant/triSurface/pellets.stl" ] \
 && [ ! -e "$1/system/blockMeshDict" ] && [ ! -e "$1/system/snappyHexMeshDict" ]
}

case "$name" in
stacked)
    # Released exactly on the axis (positionDisturbance 0), spheres land
    # on one another: a tower, which must not pass as a bed
    spheres "$tmp/a" 0.003 150 0.025 0.1 "loading { positionDisturbance 0; }"
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    check "tower: exit 1" "[ $rc -eq 1 ]"
    check "tower: summary status stacked" "[ \"\$(status $tmp/a)\" = stacked ]"
    check "tower: the log says so and what to change" \
        "grep -q '^Status: stacked' $tmp/a.log && grep -q 'loading/positionDisturbance' $tmp/a.log"
    check "tower: no pellets.stl, no CFD case" "noCase $tmp/a"
    check "tower: pellets.csv written to look at" "[ -s $tmp/a/$out/pellets.csv ]"

    # -acceptStatus: the user takes the bed as it is
    rbdPackBed -case "$tmp/a" -acceptStatus > "$tmp/b.log" 2>&1; rc=$?
    check "-acceptStatus: exit 0, pellets.stl and the case written" \
        "[ $rc -eq 0 ] && [ -s $tmp/a/constant/triSurface/pellets.stl ] && [ -s $tmp/a/system/snappyHexMeshDict ] && [ \"\$(status $tmp/a)\" = stacked ]"
    ;;

randomByDefault)
    # No loading block: the default disturbance gives a random bed
    spheres "$tmp/a" 0.003 60 0.025 0.05
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    check "defaults: exit 0, status settled" \
        "[ $rc -eq 0 ] && [ \"\$(status $tmp/a)\" = settled ]"
    ro="$(foamDictionary -entry releaseOverlap -value "$tmp/a/$out/summary" 2>/dev/null)"
    check "defaults: no pellet released into another (releaseOverlap $ro)" \
        "[ \"$ro\" = 0 ]"
    check "defaults: positionDisturbance 0.3 echoed" \
        "grep -Eq '^ *positionDisturbance +0.3;' $tmp/a.log"
    # 60 spheres of 3 mm spread over the floor of a 25 mm tube: a few
    # layers, far from the 60-sphere tower of 0.18 m
    h="$(foamDictionary -entry bedHeight -value "$tmp/a/$out/summary" 2>/dev/null)"
    check "defaults: bed height $h m below 0.02 m" \
        "[ -n \"$h\" ] && awk -v h=$h 'BEGIN {exit !(h < 0.02)}'"
    ;;

incomplete)
    # 40 spheres of 10 mm do not fit below a release height of 0.05 m in
    # a 30 mm tube: settled, but with fewer pellets than asked
    cp -r "$here/cases/smallSpheres" "$tmp/a"
    foamDictionary "$tmp/a/system/packingDict" -entry container/diameter -set 0.03 >/dev/null
    foamDictionary "$tmp/a/system/packingDict" -entry pellets/number -set 40 >/dev/null
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    n="$(foamDictionary -entry pellets -value "$tmp/a/$out/summary" 2>/dev/null)"
    check "incomplete: exit 1, status incomplete, $n of 40 pellets" \
        "[ $rc -eq 1 ] && [ \"\$(status $tmp/a)\" = incomplete ] && [ -n \"$n\" ] && [ $n -lt 40 ]"
    check "incomplete: the log names the release height and what to change" \
        "grep -q 'pellets were placed: the bed reached the release height' $tmp/a.log && grep -q 'container/height' $tmp/a.log"
    check "incomplete: no CFD case" "noCase $tmp/a"
    # The bed reached the release points: every pellet there, old ones
    # included, keeps the next one out
    ro="$(foamDictionary -entry releaseOverlap -value "$tmp/a/$out/summary" 2>/dev/null)"
    check "incomplete: no pellet released into another (releaseOverlap $ro)" \
        "[ \"$ro\" = 0 ]"
    ;;

notSettled)
    # A run too short to settle: exit 1, a checkpoint and the command
    # that resumes it
    cp -r "$here/cases/smallSpheres" "$tmp/a"
    foamDictionary "$tmp/a/system/packingDict" -entry simulation/endTime -set 0.3 >/dev/null
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    check "short run: exit 1, status notSettled, checkpoint" \
        "[ $rc -eq 1 ] && [ \"\$(status $tmp/a)\" = notSettled ] && [ -s $tmp/a/$out/checkpoint ]"
    check "short run: the log gives the -resume command" \
        "grep -Fq 'rbdPackBed -case $tmp/a -resume' $tmp/a.log"
    check "short run: no CFD case" "noCase $tmp/a"
    foamDictionary "$tmp/a/system/packingDict" -entry simulation/endTime -set 6 >/dev/null
    rbdPackBed -case "$tmp/a" -resume > "$tmp/b.log" 2>&1; rc=$?
    check "resumed to endTime 6: exit 0, settled, case written" \
        "[ $rc -eq 0 ] && [ \"\$(status $tmp/a)\" = settled ] && [ -s $tmp/a/system/snappyHexMeshDict ] && [ ! -e $tmp/a/$out/checkpoint ]"
    ;;

interrupt)
    # Ctrl-C: a checkpoint at the end of the outer interval, exit 1, the
    # -resume command; the resumed run gives the uninterrupted packing
    spheres "$tmp/whole" 0.003 150 0.025 0.05
    spheres "$tmp/cut" 0.003 150 0.025 0.05
    rbdPackBed -case "$tmp/whole" > "$tmp/whole.log" 2>&1; rcWhole=$?
    rbdPackBed -case "$tmp/cut" > "$tmp/cut.log" 2>&1 &
    pid=$!
    # (the handler is set when the packing starts: wait for its first
    # progress line, then for a second of packing)
    for i in $(seq 1 600)
    do
        grep -q '^Time = ' "$tmp/cut.log" 2>/dev/null && break
        sleep 0.1
    done
    sleep 1
    kill -INT $pid
    wait $pid; rc=$?
    check "uninterrupted run settled" "[ $rcWhole -eq 0 ] && [ -s $tmp/whole/$out/pellets.csv ]"
    check "SIGINT: exit 1, status interrupted in the log, checkpoint" \
        "[ $rc -eq 1 ] && grep -q '^Status: interrupted' $tmp/cut.log && [ -s $tmp/cut/$out/checkpoint ]"
    check "SIGINT: the log gives the -resume command" \
        "grep -Fq 'rbdPackBed -case $tmp/cut -resume' $tmp/cut.log"
    check "SIGINT: nothing but the checkpoint written" \
        "noCase $tmp/cut && [ ! -e $tmp/cut/$out/pellets.csv ]"
    rbdPackBed -case "$tmp/cut" -resume > "$tmp/resume.log" 2>&1; rc=$?
    check "resumed: exit 0 and the same pellets.csv as the uninterrupted run" \
        "[ $rc -eq 0 ] && [ -s $tmp/cut/$out/pellets.csv ] && cmp -s $tmp/whole/$out/pellets.csv $tmp/cut/$out/pellets.csv"
    ;;

rerun)
    # A second bed in the case of a first one: refused without -overwrite,
    # nothing touched; with it, the earlier bed's files go
    cp -r "$here/cases/smallSpheres" "$tmp/a"
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    check "first bed: exit 0" "[ $rc -eq 0 ] && [ -s $tmp/a/system/snappyHexMeshDict ]"
    mkdir -p "$tmp/a/constant/polyMesh" "$tmp/a/100" "$tmp/a/processor0" \
        "$tmp/a/postProcessing/pressureDrop"
    touch "$tmp/a/constant/polyMesh/points"
    foamDictionary "$tmp/a/system/packingDict" -entry loading/seed -set 2 >/dev/null
    before="$(cd "$tmp/a" && find . -type f | sort | xargs md5sum)"
    rbdPackBed -case "$tmp/a" > "$tmp/b.log" 2>&1; rc=$?
    after="$(cd "$tmp/a" && find . -type f | sort | xargs md5sum)"
    check "second bed without -overwrite: exit 1, names -overwrite" \
        "[ $rc -eq 1 ] && grep -q 'holds files of an earlier bed' $tmp/b.log && grep -q 'rbdPackBed -overwrite' $tmp/b.log"
    check "second bed without -overwrite: no file changed" "[ \"\$before\" = \"\$after\" ]"
    rbdPackBed -case "$tmp/a" -overwrite > "$tmp/c.log" 2>&1; rc=$?
    check "-overwrite: exit 0, the earlier mesh, times, processors and results removed" \
        "[ $rc -eq 0 ] && [ ! -e $tmp/a/constant/polyMesh ] && [ ! -e $tmp/a/100 ] && [ ! -e $tmp/a/processor0 ] && [ ! -e $tmp/a/postProcessing/pressureDrop ]"
    # Every case file is the new bed's: the same as a fresh case of seed 2
    cp -r "$here/cases/smallSpheres" "$tmp/fresh"
    foamDictionary "$tmp/fresh/system/packingDict" -entry loading/seed -set 2 >/dev/null
    rbdPackBed -case "$tmp/fresh" > "$tmp/fresh.log" 2>&1; rcFresh=$?
    same=true
    for f in constant/triSurface/pellets.stl system/snappyHexMeshDict \
             system/blockMeshDict $out/pellets.csv
    do
        cmp -s "$tmp/a/$f" "$tmp/fresh/$f" || { same=false; echo "differs: $f"; }
    done
    check "-overwrite: pellets.stl, snappyHexMeshDict, blockMeshDict and pellets.csv as a fresh case's" \
        "[ $rcFresh -eq 0 ] && $same"
    ;;

millimetres)
    # Consistent millimetres: warned of, and the run does not pass
    spheres "$tmp/a" 3 30 25 50 "simulation { endTime 0.5; }"
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    check "mm: a warning that names millimetres and the value in metres" \
        "grep -q 'if pellets/diameter 3 is in millimetres, give 0.003' $tmp/a.log && grep -q 'container/diameter 25 m .*if it is in millimetres, give 0.025' $tmp/a.log"
    check "mm: exit 1, no CFD case" "[ $rc -eq 1 ] && noCase $tmp/a"

    # Only the pellet in mm: the tube error names both entries and the unit
    spheres "$tmp/b" 3 30 0.025 0.05
    rbdPackBed -case "$tmp/b" > "$tmp/b.log" 2>&1; rc=$?
    check "pellet in mm: the tube error names both entries, their values and the unit" \
        "[ $rc -ne 0 ] && grep -q \"Bad entry 'diameter 0.025;'\" $tmp/b.log && grep -q 'pellets/diameter 3 m); lengths are in metres: a pellet of 3 m looks like millimetres' $tmp/b.log"

    # An STL tetrahedron in mm (edges of 10 units) without scale
    mkdir -p "$tmp/c/system" "$tmp/c/constant"
    cat > "$tmp/c/system/packingDict" <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object packingDict; }
container { type cylinder; diameter 0.03; height 0.06; }
pellets { shape stl; file "constant/pellet.stl"; number 5; density 2500; }
EOF
    python3 - "$tmp/c/constant/pellet.stl" <<'PY'
import sys
v = [(0, 0, 0), (10, 0, 0), (0, 10, 0), (0, 0, 10)]
f = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
with open(sys.argv[1], 'w') as s:
    s.write('solid t\n')
    for a, b, c in f:
        s.write('facet normal 0 0 0\nouter loop\n')
        for i in (a, b, c):
            s.write('vertex %g %g %g\n' % v[i])
        s.write('endloop\nendfacet\n')
    s.write('endsolid t\n')
PY
    rbdPackBed -case "$tmp/c" > "$tmp/c.log" 2>&1; rc=$?
    check "STL in mm: a warning that names pellets/scale 0.001" \
        "[ $rc -ne 0 ] && grep -q 'if the STL pellet.stl is in millimetres, give pellets/scale 0.001' $tmp/c.log"
    ;;

caseSize)
    # The log gives the background mesh; a case mostly of empty tube is
    # warned of, naming the entries
    cp -r "$here/cases/smallSpheres" "$tmp/a"
    rbdPackBed -case "$tmp/a" > "$tmp/a.log" 2>&1; rc=$?
    check "cell count in the log, no size warning" \
        "[ $rc -eq 0 ] && grep -Eq '^CFD background mesh: [0-9]+ x [0-9]+ x [0-9]+ = [0-9]+ cells' $tmp/a.log && ! grep -q 'mostly empty tube' $tmp/a.log"
    cp -r "$here/cases/smallSpheres" "$tmp/b"
    foamDictionary "$tmp/b/system/packingDict" -entry cfdCase/outletLength -set 0.2 >/dev/null
    rbdPackBed -case "$tmp/b" > "$tmp/b.log" 2>&1; rc=$?
    check "outletLength 0.2 m (20 dp) around a 2 dp bed: a warning naming it" \
        "[ $rc -eq 0 ] && grep -q 'The CFD case is mostly empty tube: cfdCase/inletLength' $tmp/b.log && grep -q 'shorten inletLength and outletLength' $tmp/b.log"
    ;;

allclean)
    # A tutorial copied out of the project, run without the environment:
    # Allclean stops with a message instead of deleting nothing silently
    cp -r "$here/../../tutorials/spheres" "$tmp/copy"
    touch "$tmp/copy/log.rbdPackBed"
    env -i PATH=/usr/bin:/bin bash "$tmp/copy/Allclean" > "$tmp/a.log" 2>&1; rc=$?
    check "Allclean without CleanFunctions: exit 1 and says why" \
        "[ $rc -eq 1 ] && grep -q 'no CleanFunctions found' $tmp/a.log && [ -e $tmp/copy/log.rbdPackBed ]"
    # ... and with the environment it cleans
    env -i PATH=/usr/bin:/bin RBD_PACKING_DIR="$RBD_PACKING_DIR" \
        bash "$tmp/copy/Allclean" > "$tmp/b.log" 2>&1; rc=$?
    check "Allclean with RBD_PACKING_DIR: exit 0, the log removed" \
        "[ $rc -eq 0 ] && [ ! -e $tmp/copy/log.rbdPackBed ] && [ -s $tmp/copy/system/packingDict ]"
    ;;

*)
    echo "no case '$name'"; exit 2 ;;
esac

exit $fail

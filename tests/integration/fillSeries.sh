#!/bin/bash
#------------------------------------------------------------------------------
# The fill as a ParaView time series (simulation/writeInterval, fillSeries.H)
# and the pictures of the bed (bin/tools/rbdBedPictures), checked as a user
# would see them:
# - writing the series changes nothing: pellets.csv is the same with and
#   without it; off by default;
# - the series parses with VTK's own readers (Debian's python3-vtk9), holds
#   the right pellets at the right times, its last frame is pellets.csv's
#   bed, and the Tensor Glyph of pellet.vtp poses every pellet as
#   pellets.csv does (lib/fillSeriesCheck.py);
# - a run stopped at endTime and resumed writes the same series as one
#   that was not stopped;
# - a rerun without writeInterval leaves no series of the earlier run;
# - <case>.foam is there for ParaView's OpenFOAM reader;
# - rbdBedPictures writes bed.png and porosityProfiles.png, valid PNGs of a
#   sensible size.
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"
pictures="$here/../../bin/tools/rbdBedPictures"
python=/usr/bin/python3
writeInterval=0.05
deltaT=0.025

cp -r "$here/cases/smallSpheres" "$tmp/plain"
cp -r "$here/cases/smallSpheres" "$tmp/series"
foamDictionary "$tmp/series/system/packingDict" \
    -entry simulation/writeInterval -add $writeInterval >/dev/null

rbdPackBed -case "$tmp/plain" > "$tmp/plain.log" 2>&1
rcPlain=$?
rbdPackBed -case "$tmp/series" > "$tmp/series.log" 2>&1
rc=$?
out="$tmp/series/postProcessing/rbdPackBed"
fill="$out/fill"
check "both runs exit 0" "[ $rcPlain -eq 0 ] && [ $rc -eq 0 ]"
check "writeInterval echoed: 0 by default, $writeInterval when given" \
    "grep -Eq '^ *writeInterval +0;' $tmp/plain.log && grep -Eq '^ *writeInterval +$writeInterval;' $tmp/series.log"
check "off by default: no series" \
    "[ -s $tmp/plain/postProcessing/rbdPackBed/pellets.csv ] && [ ! -e $tmp/plain/postProcessing/rbdPackBed/fill ]"
check "writing the series changes nothing: the same pellets.csv" \
    "[ -s $out/pellets.csv ] && cmp -s $out/pellets.csv $tmp/plain/postProcessing/rbdPackBed/pellets.csv"
check "fill.pvd, frames and pellet.vtp written, the log says so" \
    "[ -s $fill/fill.pvd ] && [ -s $fill/fill_00000.vtp ] && [ -s $fill/pellet.vtp ] && grep -q '^Fill series: [0-9]* frames of 20 pellets' $tmp/series.log"
check "<case>.foam for ParaView's OpenFOAM reader, empty" \
    "[ -f $tmp/series/series.foam ] && [ ! -s $tmp/series/series.foam ] && [ -f $tmp/plain/plain.foam ]"

# VTK's own readers on the series
if $python -c 'import vtk' 2>/dev/null
then
    $python "$here/lib/fillSeriesCheck.py" "$tmp/series" $writeInterval \
        $deltaT > "$tmp/vtk.log" 2>&1
    rcVtk=$?
    sed 's/^/    /' "$tmp/vtk.log"
    check "the series read by VTK (python3-vtk9) matches the run" \
        "[ $rcVtk -eq 0 ]"
else
    check "python3-vtk9 installed (bin/tools/installDependencies)" false
fi

# Stopped at endTime (1 s) and resumed: the same frames at the same times,
# the same last frame
cp -r "$here/cases/smallSpheres" "$tmp/resumed"
foamDictionary "$tmp/resumed/system/packingDict" \
    -entry simulation/writeInterval -add $writeInterval >/dev/null
foamDictionary "$tmp/resumed/system/packingDict" \
    -entry simulation/endTime -set 1 >/dev/null
rbdPackBed -case "$tmp/resumed" > "$tmp/resumed1.log" 2>&1
rc1=$?
foamDictionary "$tmp/resumed/system/packingDict" \
    -entry simulation/endTime -set 6 >/dev/null
rbdPackBed -case "$tmp/resumed" -resume > "$tmp/resumed2.log" 2>&1
rc2=$?
rfill="$tmp/resumed/postProcessing/rbdPackBed/fill"
check "stopped at endTime 1 s (exit $unsettledStatus), resumed (exit 0): the same pellets.csv" \
    "[ $rc1 -eq $unsettledStatus ] && [ $rc2 -eq 0 ] && cmp -s $out/pellets.csv $tmp/resumed/postProcessing/rbdPackBed/pellets.csv"
check "resumed: the same fill.pvd (frames, times) as the run not stopped" \
    "[ -s $rfill/fill.pvd ] && cmp -s $fill/fill.pvd $rfill/fill.pvd"
last="$(sed -n 's/.*file="\([^"]*\)".*/\1/p' "$fill/fill.pvd" | tail -1)"
check "resumed: the same last frame ($last), but for the contacts" \
    "[ -n \"$last\" ] && [ -s $rfill/$last ] && diff <(sed '/Name=\"contacts\"/,/<\/DataArray>/d' $fill/$last) <(sed '/Name=\"contacts\"/,/<\/DataArray>/d' $rfill/$last) >/dev/null"
check "resumed: no frame files beyond those of fill.pvd" \
    "[ \$(ls $rfill/fill_*.vtp | wc -l) -eq \$(grep -c '<DataSet' $rfill/fill.pvd) ]"

# A rerun without writeInterval: no series of the earlier run stays
cp -r "$tmp/series" "$tmp/rerun"
foamDictionary "$tmp/rerun/system/packingDict" \
    -entry simulation/writeInterval -remove >/dev/null
rbdPackBed -case "$tmp/rerun" -overwrite > "$tmp/rerun.log" 2>&1
rc=$?
check "rerun without writeInterval: exit 0, the earlier series removed" \
    "[ $rc -eq 0 ] && [ -s $tmp/rerun/postProcessing/rbdPackBed/pellets.csv ] && [ ! -e $tmp/rerun/postProcessing/rbdPackBed/fill ]"

# Pictures
pngSize()
{
    # width height of a PNG, nothing if the file is not one
    $python -c '
import struct, sys
d = open(sys.argv[1], "rb").read(33)
if d[:8] == b"\x89PNG\r\n\x1a\n" and d[12:16] == b"IHDR":
    print(*struct.unpack(">II", d[16:24]))' "$1" 2>/dev/null
}
if $python -c 'import matplotlib, numpy' 2>/dev/null
then
    "$pictures" -case "$tmp/series" > "$tmp/pictures.log" 2>&1
    rc=$?
    sed 's/^/    /' "$tmp/pictures.log"
    check "rbdBedPictures exits 0" "[ $rc -eq 0 ]"
    for png in bed porosityProfiles
    do
        size="$(pngSize "$out/$png.png")"
        check "$png.png: a PNG of ${size:-?} pixels (400-3000 each way), over 20 kB" \
            "[ -n \"$size\" ] && [ \$(stat -c %s $out/$png.png) -gt 20000 ] && awk -v s=\"$size\" 'BEGIN {split(s, a, \" \"); exit !(a[1] >= 400 && a[2] >= 400 && a[1] <= 3000 && a[2] <= 3000)}'"
    done
    rm -f "$tmp/rerun/constant/triSurface/pellets.stl"
    "$pictures" -case "$tmp/rerun" > "$tmp/pictures2.log" 2>&1
    rc=$?
    check "rbdBedPictures without pellets.stl: spheres from pellets.csv" \
        "[ $rc -eq 0 ] && grep -q 'bounding spheres of pellets.csv' $tmp/pictures2.log && [ -n \"\$(pngSize $tmp/rerun/postProcessing/rbdPackBed/bed.png)\" ]"
    "$pictures" -case "$tmp/nowhere" > "$tmp/pictures3.log" 2>&1
    rc=$?
    check "rbdBedPictures in a case without a bed: exit 1, says why" \
        "[ $rc -eq 1 ] && grep -q 'run rbdPackBed' $tmp/pictures3.log"
else
    check "python3-matplotlib and python3-numpy installed (bin/tools/installDependencies)" false
fi

exit $fail

#!/bin/bash
#------------------------------------------------------------------------------
# The loading schemes twoColumns and fourColumns and the loading entries
# tilt, angleDisturbance, positionDisturbance and columnOffset, through
# rbdPackBed (loading.cases: one test per case, from cases/loading).
#
# Release cases: a run of 0.02 s with one pellet per column, all released at
# t = 0 and still falling freely at its end, so pellets.csv holds the
# release poses: (x, y) the column points (s, 0), (0, s), (-s, 0), (0, -s)
# (four columns) or (s, 0), (-s, 0) (two), s = columnOffset, default
# midway between its bounds (R/2 for two columns); z = releaseHeight -
# g t^2/2; the body axis tilted by 'tilt' about the world x axis,
# q = (cos(tilt/2), sin(tilt/2), 0, 0), or within angleDisturbance of that;
# offsets within positionDisturbance dp. limitsRelease: every scheme at the
# largest positionDisturbance its bounds allow (loadingScheme's
# Description), released clear of the wall and of one another.
#
# Packing cases: the whole run, twice: settled, every vertex of pellets.stl
# in the tube (to its facets' offset), largest overlap below 0.5 % dp, the
# same pellets.csv from the same dictionary and seed (bit for bit), another
# seed another bed.
#
# Usage: bash tests/integration/loading.sh <case>    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/lib/checks.sh"

case="${1:?usage: loading.sh <case of loading.cases>}"
grep -Eq "^$case( |$)" "$here/loading.cases" \
    || { echo "loading.sh: no case '$case' in loading.cases" 1>&2; exit 1; }

R=0.025
dp=0.01
rb="$(awk 'BEGIN {printf "%.12g", sqrt(2)*0.005}')"
g=9.81

# a <= b, numerically
le() { awk -v a="$1" -v b="$2" 'BEGIN {exit !(a <= b)}'; }

# setup <dir> <entry value>...: the case with these entries set
setup()
{
    local d="$1"
    shift
    cp -r "$here/cases/loading" "$d"
    while [ $# -gt 1 ]
    do
        foamDictionary "$d/system/packingDict" -entry "$1" -set "$2" \
            > /dev/null || exit 1
        shift 2
    done
}

# pack <dir> [options]: run, log to <dir>.log, print the wall time
pack()
{
    local d="$1"
    shift
    local start=$(date +%s.%N)
    rbdPackBed -case "$d" "$@" > "$d.log" 2>&1
    local status=$?
    awk -v t="$start $(date +%s.%N)" \
        'BEGIN {split(t, a, " "); printf "%.1f s\n", a[2] - a[1]}' \
        > "$d.time"
    return $status
}

get() { foamDictionary -entry "$2" -value "$1/postProcessing/rbdPackBed/summary" 2>/dev/null; }

# packToRest <dir>: the whole run, and the checks of every packing case:
# exit 0, settled with all 8 pellets, largest overlap below 0.5 % of dp
# (in $ov)
packToRest()
{
    local d="$1" status
    pack "$d"
    status=$?
    check "exit status 0 ($(cat $d.time))" "[ $status -eq 0 ]"
    check "status settled, all 8 pellets" \
        "[ \"\$(get $d status)\" = settled ] && [ \"\$(get $d pellets)\" = 8 ]"
    ov="$(get $d maxOverlap)"
    check "largest overlap $ov m below 0.5 % of dp" "le ${ov:-1} 5e-5"
}

# release <dir> <scheme> <columns> [staggered]: the short run and the
# checks every release case shares; the column offset it finds is in $s.
# staggered: a pellet may be held back a step or more by the release rule
# (it came within the proximity band of a pellet of the same release, as
# draws at a bound may): every pellet in free fall from 0.05 m since t = 0
# or later, not necessarily from t = 0
release()
{
    local d="$1" scheme="$2" nc="$3" staggered="${4:-}"
    foamDictionary "$d/system/packingDict" -entry pellets/number -set "$nc" > /dev/null
    foamDictionary "$d/system/packingDict" -entry simulation/deltaT -set 0.001 > /dev/null
    foamDictionary "$d/system/packingDict" -entry simulation/endTime -set 0.02 > /dev/null
    foamDictionary "$d/system/packingDict" -entry loading/releaseHeight -set 0.05 > /dev/null
    foamDictionary "$d/system/packingDict" -entry loading/scheme -set "$scheme" > /dev/null
    pack "$d" -acceptStatus
    local status=$?
    check "$scheme: the short run exits 0 with -acceptStatus ($(cat $d.time))" "[ $status -eq 0 ]"
    csv="$d/postProcessing/rbdPackBed/pellets.csv"
    check "$scheme: $nc pellets released, one per column" \
        "[ \$(tail -n +2 $csv 2>/dev/null | wc -l) -eq $nc ]"
    # The simulated time, and every pellet still at z = releaseHeight - g t^2/2
    t="$(get "$d" simulatedTime)"
    if [ -z "$staggered" ]
    then
        check "$scheme: simulated $t s, every pellet in free fall from 0.05 m" \
            "awk -F, -v t=$t -v g=$g 'NR > 1 {z = 0.05 - 0.5*g*t*t; if ((\$5 - z)^2 > 1e-18) bad = 1} END {exit bad || t < 0.019}' $csv"
    else
        check "$scheme: simulated $t s, every pellet in free fall from 0.05 m, released at t = 0 or later" \
            "awk -F, -v t=$t -v g=$g 'NR > 1 {z = 0.05 - 0.5*g*t*t; if (\$5 < z - 1e-9 || \$5 > 0.05) bad = 1} END {exit bad || t < 0.019}' $csv"
    fi
    # The column offset the log echoes
    s="$(awk '$1 == "columnOffset" {sub(";", "", $2); print $2; exit}' $d.log)"
}

case "$case" in
fourColumnsRelease)
    setup "$tmp/a" loading/columnOffset 0.012 loading/tilt 30
    release "$tmp/a" fourColumns 4
    check "log echoes columnOffset 0.012" "[ \"$s\" = 0.012 ]"
    # Each column point (s, 0), (0, s), (-s, 0), (0, -s) holds one pellet,
    # to round-off
    for p in "0.012 0" "0 0.012" "-0.012 0" "0 -0.012"
    do
        check "one pellet at (x y) = ($p)" \
            "[ \$(awk -F, -v p='$p' 'BEGIN {split(p, c, \" \")} NR > 1 && (\$3 - c[1])^2 + (\$4 - c[2])^2 < 1e-24' $csv | wc -l) -eq 1 ]"
    done
    # Tilt 30 about world x: q = (cos 15, sin 15, 0, 0)
    check "every axis tilted by 30 degrees about world x" \
        "awk -F, 'NR > 1 {pi = atan2(0, -1); w = cos(pi/12); a = sin(pi/12); if ((\$6 - w)^2 + (\$7 - a)^2 + \$8^2 + \$9^2 > 1e-20) bad = 1} END {exit bad}' $csv"
    ;;

twoColumnsRelease)
    setup "$tmp/a" loading/tilt 60 loading/positionDisturbance 0.3 \
        loading/angleDisturbance 20 loading/seed 3
    release "$tmp/a" twoColumns 2
    s0="$(awk -v R=$R 'BEGIN {printf "%.6g", R/2}')"
    check "default columnOffset $s = R/2 = $s0 (midway between r_b + 0.3 dp and R - r_b - 0.3 dp)" \
        "awk -v a=$s -v b=$s0 'BEGIN {exit !((a - b)^2 < 1e-18)}'"
    # Pellet k from column k: (s, 0) then (-s, 0); within 0.3 dp of it,
    # and moved from it (the disturbance is drawn)
    check "pellets within positionDisturbance 0.3 dp of (s, 0) and (-s, 0), and off them" \
        "awk -F, -v s=$s -v d=$dp 'NR > 1 {cx = (NR == 2 ? s : -s); r = sqrt((\$3 - cx)^2 + \$4^2); if (r > 0.3*d*(1 + 1e-9)) bad = 1; if (r > 1e-6*d) moved++} END {exit bad || moved != 2}' $csv"
    # Angle between q and q0 = (cos 30, sin 30, 0, 0) (tilt 60):
    # 2 acos|q . q0| <= 20 degrees, and not 0
    check "orientations within angleDisturbance 20 degrees of the 60 degree tilt, and off it" \
        "awk -F, 'NR > 1 {pi = atan2(0, -1); d = \$6*cos(pi/6) + \$7*sin(pi/6); if (d < 0) d = -d; if (d > 1) d = 1; a = 2*atan2(sqrt(1 - d*d), d)*180/pi; print \"    angle to the tilted pose \" a \" deg\" > \"/dev/stderr\"; if (a > 20 + 1e-9) bad = 1; if (a > 1e-6) moved++} END {exit bad || moved != 2}' $csv"
    # Same dictionary and seed: the same poses; another seed: others
    cp -r "$here/cases/loading" "$tmp/b"
    cp "$tmp/a/system/packingDict" "$tmp/b/system/packingDict"
    pack "$tmp/b" -acceptStatus
    check "same dictionary and seed: the same pellets.csv" \
        "cmp -s $csv $tmp/b/postProcessing/rbdPackBed/pellets.csv"
    cp -r "$here/cases/loading" "$tmp/c"
    cp "$tmp/a/system/packingDict" "$tmp/c/system/packingDict"
    foamDictionary "$tmp/c/system/packingDict" -entry loading/seed -set 4 > /dev/null
    pack "$tmp/c" -acceptStatus
    check "another seed: other poses" \
        "[ -s $tmp/c/postProcessing/rbdPackBed/pellets.csv ] && ! cmp -s $csv $tmp/c/postProcessing/rbdPackBed/pellets.csv"
    ;;

limitsRelease)
    # The largest positionDisturbance [-] of each scheme, from the bounds
    # (k = 1 two columns, sqrt(2) four; layers: pitch 1.1 x 2 r_b, so
    # delta <= (1.1 r_b - r_b)), rounded down in the 7th digit
    lim()
    {
        awk -v R=$R -v r=$rb -v d=$dp -v s="$1" 'BEGIN {
            k = sqrt(2)
            if (s == "column") x = (R - r)/d
            if (s == "twoColumns") x = (R - 2*r)/(2*d)
            if (s == "fourColumns") x = (R - (1 + k)*r)/((1 + k)*d)
            if (s == "layers") x = 0.1*r/d
            printf "%.7f", x - 5e-8}'
    }
    for scheme in column twoColumns fourColumns layers
    do
        pd="$(lim $scheme)"
        nc=1
        [ $scheme = twoColumns ] && nc=2
        [ $scheme = fourColumns ] && nc=4
        # layers: lattice points within R - r_b - delta = 17.2 mm, pitch
        # 15.6 mm: the axis and a ring of six
        [ $scheme = layers ] && nc=7
        for seed in 1 2 3
        do
            d="$tmp/$scheme$seed"
            setup "$d" loading/positionDisturbance "$pd" loading/seed $seed \
                loading/spacing 1.1
            release "$d" $scheme $nc staggered
            check "$scheme, seed $seed, positionDisturbance $pd: summary releaseOverlap 0" \
                "[ \"\$(get $d releaseOverlap)\" = 0 ]"
            # Every centre within R - r_b of the axis, every two bounding
            # spheres clear (to 1e-12 m)
            check "$scheme, seed $seed: every centre within R - r_b, no two bounding spheres overlapping" \
                "awk -F, -v R=$R -v r=$rb 'NR > 1 {n++; x[n] = \$3; y[n] = \$4; z[n] = \$5} END {for (i = 1; i <= n; i++) {if (sqrt(x[i]^2 + y[i]^2) > R - r + 1e-12) exit 1; for (j = 1; j < i; j++) if (sqrt((x[i] - x[j])^2 + (y[i] - y[j])^2 + (z[i] - z[j])^2) < 2*r - 1e-12) exit 1} exit n < 1}' $csv"
        done
    done
    ;;

twoColumnsPack|fourColumnsPack)
    if [ "$case" = twoColumnsPack ]
    then
        entries="loading/scheme twoColumns loading/columnOffset 0.008 loading/tilt 60 loading/angleDisturbance 30"
    else
        entries="loading/scheme fourColumns loading/tilt 10 loading/angleDisturbance 45 loading/positionDisturbance 0.2"
    fi
    setup "$tmp/a" $entries
    setup "$tmp/b" $entries
    packToRest "$tmp/a"
    awk -F, -f "$here/lib/bedGeometry.awk" \
        "$tmp/a/postProcessing/rbdPackBed/pellets.csv" \
        "$tmp/a/constant/triSurface/pellets.stl" > "$tmp/geometry" 2>/dev/null
    geo() { awk -v k="$1" '$1 == k {print $2}' "$tmp/geometry"; }
    # (to 0.1 % dp plus the offset of pellets.stl's volume-true facets,
    # at most 1.3 % of r = 0.65 % dp for the 16-gon of these 200-face
    # cylinders: measured 0.58 and 0.65 % dp)
    check "every vertex inside the tube (largest radius $(geo maxRho) m) and above the floor (lowest $(geo minZ) m), to 0.8 % dp" \
        "[ \"$(geo pellets)\" = 8 ] && le $(geo maxRho) 0.02508 && le -8e-5 $(geo minZ)"
    pack "$tmp/b"
    check "same dictionary and seed: the same pellets.csv ($(cat $tmp/b.time))" \
        "cmp -s $tmp/a/postProcessing/rbdPackBed/pellets.csv $tmp/b/postProcessing/rbdPackBed/pellets.csv"
    echo "loading.$case: wall $(cat $tmp/a.time), cpu $(get $tmp/a cpuTime) s, bulkPorosity $(get $tmp/a bulkPorosity), maxOverlap $ov m"
    ;;
layersWaitForTheBed)
    # Scheme layers at spacing 1.1 (7 release points, limitsRelease), 16
    # cylinders of restitution 0.3 (a layer comes to rest well within the
    # longest wait, 1 s): with awakeLayers 1 (the default) the second
    # layer is released only once fewer than 7 pellets are awake, so the
    # first log line (every 5 ms) with more than 7 released shows the first
    # layer partly asleep, and the second layer still falling has woken
    # none of it; with awakeLayers 0 each point releases as soon as its
    # pellet has fallen clear, before anything sleeps
    for wait in 1 0
    do
        d="$tmp/wait$wait"
        setup "$d" loading/scheme layers loading/spacing 1.1 \
            pellets/number 16 pellets/restitution 0.3 \
            simulation/logInterval 0.005
        [ $wait = 0 ] && foamDictionary "$d/system/packingDict" \
            -entry loading/awakeLayers -add 0 > /dev/null
        pack "$d"
        status=$?
        check "awakeLayers $wait: exit status 0, settled with 16 pellets ($(cat $d.time))" \
            "[ $status -eq 0 ] && [ \"\$(get $d status)\" = settled ] && [ \"\$(get $d pellets)\" = 16 ]"
        check "awakeLayers $wait: the log echoes it" \
            "grep -Eq '^ +awakeLayers +$wait;' $d.log"
        # released and sleeping at the first line with more than 7 released
        first="$(awk '$1 == "Time" {split($6, r, "/"); for (i = 1; i < NF; i++) if ($i == "sleeping") s = $(i + 1); if (r[1] > 7) {print r[1], s; exit}}' $d.log)"
        if [ $wait = 1 ]
        then
            check "awakeLayers 1: the second layer waits for the first to sleep (released, sleeping at its release: $first)" \
                "[ -n \"$first\" ] && awk -v f='$first' 'BEGIN {split(f, a, \" \"); exit !(a[2] >= 1 && a[1] - a[2] < 14)}'"
        else
            check "awakeLayers 0: the second layer falls before anything sleeps (released, sleeping: $first)" \
                "[ -n \"$first\" ] && awk -v f='$first' 'BEGIN {split(f, a, \" \"); exit !(a[2] == 0)}'"
        fi
        ov="$(get $d maxOverlap)"
        check "awakeLayers $wait: largest overlap $ov m below 0.5 % of dp" "le ${ov:-1} 5e-5"
    done
    ;;
placementRelease|placementRepack)
    # Eight cylinders placed by a file: four at z = 20 mm on the points
    # (+-12 mm, 0), (0, +-12 mm), three at 40 mm on the diagonals, each
    # turned its own way (bounding spheres 17 mm apart or more, 19.1 mm
    # from the axis at most: clear of one another, the wall and the top),
    # and pellet 5 upright beside the upright pellet 4, 10.5 mm between
    # their axes: 0.5 mm apart, where their bounding spheres (r_b 7.07 mm)
    # overlap by 3.6 mm, so the placement check is the exact shapes'
    placement="$tmp/placement.csv"
    {
        echo 'id,shape,x,y,z,qw,qx,qy,qz'
        echo '0,cylinder,0.012,0,0.02,1,0,0,0'
        echo '1,cylinder,0,0.012,0.02,0.9659258263,0.2588190451,0,0'
        echo '2,cylinder,-0.012,0,0.02,0.7071067812,0,0.7071067812,0'
        echo '3,cylinder,0,-0.012,0.02,0.5,0.5,0.5,0.5'
        echo '4,cylinder,0.0084852814,0.0084852814,0.04,0.8660254038,0,0,0.5'
        echo '5,cylinder,-0.0020147186,0.0084852814,0.04,1,0,0,0'
        echo '6,cylinder,-0.0084852814,-0.0084852814,0.04,0,0,1,0'
        echo '7,cylinder,0.0084852814,-0.0084852814,0.04,0.5,-0.5,0.5,-0.5'
    } > "$placement"
    # place <dir> <file>: the case loaded from the file, number left out
    place()
    {
        setup "$1"
        mkdir -p "$1/constant"
        cp "$2" "$1/constant/placement.csv"
        foamDictionary "$1/system/packingDict" -entry loading -set \
            '{ scheme placement; file "constant/placement.csv"; }' > /dev/null
        foamDictionary "$1/system/packingDict" -entry pellets/number -remove > /dev/null
    }
    ;;&

placementRelease)
    # A run of 0.02 s: every pellet still in free fall from its placed
    # pose, z lowered by g t^2/2, x, y and the orientation unchanged
    place "$tmp/a" "$placement"
    foamDictionary "$tmp/a/system/packingDict" -entry simulation/deltaT -set 0.001 > /dev/null
    foamDictionary "$tmp/a/system/packingDict" -entry simulation/endTime -set 0.02 > /dev/null
    pack "$tmp/a" -acceptStatus
    status=$?
    check "the short run exits 0 with -acceptStatus ($(cat $tmp/a.time))" "[ $status -eq 0 ]"
    check "the log echoes the file's 8 poses" \
        "grep -q 'poses *8 pellets from' $tmp/a.log"
    csv="$tmp/a/postProcessing/rbdPackBed/pellets.csv"
    t="$(get "$tmp/a" simulatedTime)"
    check "8 pellets, each at its placed x, y and orientation, z lowered by g t^2/2 (t = $t s)" \
        "awk -F, -v t=$t -v g=$g 'FNR == 1 {next} NR == FNR {n++; for (k = 3; k <= 9; k++) p[\$1, k] = \$k; next} {m++; dz = 0.5*g*t*t; for (k = 3; k <= 9; k++) {e = (k == 5 ? p[\$1, k] - dz : p[\$1, k]); if ((\$k - e)^2 > 1e-18) bad = 1}} END {exit bad || n != 8 || m != 8 || t < 0.019}' $placement $csv"
    check "summary releaseOverlap 0" "[ \"\$(get $tmp/a releaseOverlap)\" = 0 ]"
    ;;

placementRepack)
    # The placement packed to rest; then its own pellets.csv placed again:
    # a bed at rest stays where it is (resting contacts hold it from the
    # first step), and settles again at once
    place "$tmp/a" "$placement"
    packToRest "$tmp/a"
    bed="$tmp/a/postProcessing/rbdPackBed/pellets.csv"
    place "$tmp/b" "$bed"
    pack "$tmp/b"
    status=$?
    check "the packed bed placed again: exit status 0, settled ($(cat $tmp/b.time))" \
        "[ $status -eq 0 ] && [ \"$(get $tmp/b status)\" = settled ]"
    moved="$(awk -F, 'FNR == 1 {next} NR == FNR {x[$1] = $3; y[$1] = $4; z[$1] = $5; next} {d = sqrt(($3 - x[$1])^2 + ($4 - y[$1])^2 + ($5 - z[$1])^2); if (d > m) m = d} END {printf "%.3g", m}' $bed $tmp/b/postProcessing/rbdPackBed/pellets.csv)"
    check "no pellet of the bed placed again moved more than 0.1 % of dp (largest $moved m)" \
        "le $moved 1e-5"
    echo "loading.$case: wall $(cat $tmp/a.time) and $(cat $tmp/b.time), maxOverlap $ov m, bed placed again moved at most $moved m"
    ;;
esac

exit $fail

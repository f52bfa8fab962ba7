#!/bin/bash
#------------------------------------------------------------------------------
# End to end, as a user runs it: a small sphere bed (cases/endToEndSpheres,
# 30 spheres of dp = 10 mm in a tube of D = 4 dp) goes the whole way with the
# built rbdPackBed and rbdPressureDrop and Debian's OpenFOAM v1912, with no
# hand editing:
#     rbdPackBed                        exit 0, summary and case files written
#     foamDictionary -expand            on every written dictionary
#     blockMesh, surfaceFeatureExtract, snappyHexMesh -overwrite
#     checkMesh                         'Mesh OK.' (it exits 0 even when a
#                                       check fails) and patches exactly
#                                       inlet outlet pellets wall
#     decomposePar, mpirun -np 2 simpleFoam -parallel -dry-run
#                                       (the decomposition of Allrun-parallel)
#     simpleFoam                        'SIMPLE solution converged', no NaN
#     rbdPressureDrop                   simulated dP/L over the packed section
#                                       within 35 % of Eisfeld-Schnitzlein
#                                       for the bed's own porosity
# Prints the time of every step. Runs in a temporary directory, removed on
# success, kept (and named) on failure. About 1 minute on this machine.
#
# The porosity is that of the whole bed, floor to top of the highest pellet
# (the section the pressure is sampled over). Beds this short scatter:
# 22-34 spheres, seeds 1-3, gave simulated/Eisfeld-Schnitzlein 1.09-1.36
# (this case, 30 spheres seed 1: 1.09). The 35 % of the issue is kept.
#
# Usage: bash tests/integration/endToEndSpheres.sh    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u

here="$(cd "$(dirname "$0")" && pwd)"
maxDeviation=0.35

for app in rbdPackBed rbdPressureDrop blockMesh snappyHexMesh simpleFoam
do
    if ! command -v "$app" >/dev/null 2>&1
    then
        echo "endToEndSpheres: no $app on PATH (./Allwmake, etc/bashrc)" 1>&2
        exit 1
    fi
done

work="$(mktemp -d "${TMPDIR:-/tmp}/endToEndSpheres.XXXXXX")"
cp -r "$here/cases/endToEndSpheres/." "$work"
cd "$work" || exit 1

fail()
{
    echo "endToEndSpheres: FAILED: $*" 1>&2
    echo "endToEndSpheres: case kept in $work" 1>&2
    exit 1
}

# run <step name> <command...>: log to log.<step name>, print the time
run()
{
    local name="$1"
    shift
    local start end
    start=$(date +%s.%N)
    if ! "$@" > "log.$name" 2>&1
    then
        tail -30 "log.$name" 1>&2
        fail "$* (see log.$name)"
    fi
    end=$(date +%s.%N)
    awk -v n="$name" -v t="$start $end" \
        'BEGIN {split(t, a, " "); printf "    %-26s %6.1f s\n", n, a[2] - a[1]}'
}

total=$(date +%s.%N)
echo "endToEndSpheres in $work"

run rbdPackBed rbdPackBed
[ -f postProcessing/rbdPackBed/summary ] || fail "no summary written"
[ -f constant/triSurface/pellets.stl ] || fail "no pellets.stl written"
grep -E '^(pellets|bedHeight|bulkPorosity|bedPorosity) ' \
    postProcessing/rbdPackBed/summary | sed 's/^/    /'

for f in system/blockMeshDict system/surfaceFeatureExtractDict \
         system/snappyHexMeshDict system/decomposeParDict \
         system/controlDict system/fvSchemes system/fvSolution \
         constant/transportProperties constant/turbulenceProperties 0/U 0/p
do
    [ -f "$f" ] || fail "rbdPackBed did not write $f"
    foamDictionary -expand "$f" > /dev/null 2>&1 \
        || fail "foamDictionary -expand $f"
done

run blockMesh blockMesh
run surfaceFeatureExtract surfaceFeatureExtract
run snappyHexMesh snappyHexMesh -overwrite
run checkMesh checkMesh

# checkMesh exits 0 even when a check fails
grep -q '^Mesh OK\.' log.checkMesh || fail "checkMesh did not say 'Mesh OK.'"
patches="$(awk '/Patch +Faces +Points/ {on=1; next}
                on && NF == 0 {exit}
                on {print $1}' log.checkMesh | sort | tr '\n' ' ')"
[ "$patches" = "inlet outlet pellets wall " ] \
    || fail "patches are '$patches', not 'inlet outlet pellets wall'"
grep -E '^ +cells:' log.checkMesh

run decomposePar decomposePar -force
mpiFlags=""
[ "$(id -u)" = 0 ] && mpiFlags="$mpiFlags --allow-run-as-root"
[ "$(nproc)" -lt 2 ] && mpiFlags="$mpiFlags --oversubscribe"
run simpleFoam.parallelDryRun \
    mpirun $mpiFlags -np 2 simpleFoam -parallel -dry-run

# Serial: on a shared 2-core machine two ranks wait on each other
run simpleFoam simpleFoam
grep -qiE '(^|[^a-z])nan([^a-z]|$)' log.simpleFoam \
    && fail "NaN in log.simpleFoam"
grep -q 'SIMPLE solution converged' log.simpleFoam \
    || fail "simpleFoam did not converge in $(foamDictionary -entry endTime \
             -value system/controlDict) iterations"
grep 'SIMPLE solution converged' log.simpleFoam | sed 's/^/    /'

run rbdPressureDrop rbdPressureDrop
sed -n '/^Pressure drop/,/E-S/p' log.rbdPressureDrop

ratio="$(foamDictionary -entry ratioEisfeldSchnitzlein -value \
         postProcessing/pressureDrop/comparison 2>/dev/null)"
[ -n "$ratio" ] || fail "no ratioEisfeldSchnitzlein in the comparison"
awk -v r="$ratio" -v m="$maxDeviation" \
    'BEGIN {exit !(r >= 1 - m && r <= 1 + m)}' \
    || fail "simulated/Eisfeld-Schnitzlein = $ratio, not within" \
            "$maxDeviation of 1"
echo "    simulated/Eisfeld-Schnitzlein = $ratio (allowed 1 +- $maxDeviation)"

awk -v t="$total $(date +%s.%N)" 'BEGIN {split(t, a, " ");
    printf "    %-26s %6.1f s\n", "total", a[2] - a[1]}'

cd / && rm -rf "$work"
echo "endToEndSpheres: OK"

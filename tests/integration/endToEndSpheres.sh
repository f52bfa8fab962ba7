#!/bin/bash
#------------------------------------------------------------------------------
# End to end, as a user runs it: a small sphere bed (cases/endToEndSpheres,
# 30 spheres of dp = 10 mm in a tube of D = 4 dp) goes the whole way with the
# built rbdPackBed and rbdPressureDrop and Debian's OpenFOAM v1912, with no
# hand editing:
#     rbdPackBed                        exit 0, summary (releaseOverlap 0)
#                                       and case files written
#     foamDictionary -expand            on every written dictionary
#     blockMesh, surfaceFeatureExtract, snappyHexMesh -overwrite
#     checkMesh                         'Mesh OK.' (it exits 0 even when a
#                                       check fails) and patches exactly
#                                       inlet outlet pellets wall
#     decomposePar, mpirun -np 2 simpleFoam -parallel -dry-run
#                                       (the decomposition of Allrun-parallel)
#     simpleFoam                        'SIMPLE solution converged', no NaN
#     rbdPressureDrop                   simulated dP/(rho L) over the whole
#                                       bed, floor to top, within 2 % of
#                                       the value this case gave (below)
# Prints the time of every step. Runs in a temporary directory, removed on
# success, kept (and named) on failure. About 1 minute on this machine.
#
# A regression value at a fixed seed. The packing is deterministic (goodRun:
# same seed, same pellets.csv bit for bit), so first the bed is checked to
# be the recorded one (bedHeight, bedPorosity to 1e-4); a change of the
# packing makes another bed, and the value no longer applies (beds this
# short scatter: 22-34 spheres, seeds 1-3, gave simulated/Eisfeld-
# Schnitzlein 1.09-1.36, so no correlation can be held to 10 %).
# Then the pressure drop of that bed, recorded 2026-12-07 with Debian's
# OpenFOAM v1912, serial snappyHexMesh and simpleFoam, with pellets.stl of
# volume-true facets, after the sphere steps no longer stopped a slow
# approach of two spheres (or a sphere and the floor) at touching and
# bounded a sphere's path along the wall made another bed of seed 1 (bed
# height 27.2 mm, porosity 0.540 floor to top; 94740 cells, converged in
# 76 iterations): dP/(rho L) = 0.0993016 m/s^2 (simulated/Eisfeld-
# Schnitzlein 1.142). With the first rule alone (e32defc: bed height 27.2
# mm, porosity 0.541; 93723 cells, 75 iterations): dP/(rho L) = 0.0916774
# (simulated/Eisfeld-Schnitzlein 1.058). The bed before it (d14fee6, the
# block pivoting's candidates from the last factor: forces that differ in
# the last bits; bed height 32.5 mm, porosity 0.615 floor to top, a loose
# top of a few spheres above the third layer; 100167 cells, 77
# iterations): dP/(rho L) = 0.0830966 m/s^2 (simulated/Eisfeld-
# Schnitzlein 1.817 over the whole bed, above the 0.97-1.38 of earlier
# beds because E-S does not describe that loose top; rbdPressureDrop's
# packed section, below porosityHeight, 0.934). The bed before that (bed
# height 27.2 mm, porosity 0.541; 94229 cells, 74 iterations): dP/(rho L)
# = 0.103577 m/s^2 (simulated/Eisfeld-Schnitzlein 1.196). The one before
# (2e87f9e, the broad phase kept per pellet; 94849 cells, 76 iterations):
# dP/(rho L) = 0.100934 m/s^2 (simulated/Eisfeld-Schnitzlein 1.381; bed
# porosity 0.5605). The bed before it: 0.103434 (E-S 1.358). With
# the inscribed 320-face spheres before (3.4 % of each sphere missing, the
# packed section's STL 0.019 more porous) it was 0.0925193 (98236 cells,
# E-S 1.214): 11.8 % lower. Measured on the bed of seed 1
# before collisionTolerance 0.1 (3b92141; 0.0693194 m/s^2, E-S 0.975), what
# moves it without a fault:
#     the same case again (4 runs)              identical to 12 digits
#     residualControl p 1e-6, U 1e-7 (114 it.)  +0.0002 %
#     pellets.stl shifted 20 um in x            -0.06 %  (snappyHexMesh
#     pellets.stl shifted 100 um in x           -0.37 %   cuts other cells;
#                                                         finest cell 625 um)
# The 2 % allowed is five times the largest of these, and a sixth of the
# seed-to-seed scatter; a 10 % error of the inlet velocity (simulated/E-S
# unchanged, as E-S uses the measured flow rate) fails it.
# When the packing or the CFD case changes on purpose, rerun, check that
# simulated/E-S stays within the scatter of such beds (0.97-1.38 seen),
# and record the new values below.
#
# Usage: bash tests/integration/endToEndSpheres.sh    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u

here="$(cd "$(dirname "$0")" && pwd)"

# The recorded bed (seed 1) and its pressure drop (see above)
refBedHeight=0.0272033      # [m]
refBedPorosity=0.540497     # [-]
refDPdL=0.0993016           # [m/s^2] dP/(rho L), floor to top of the bed
maxDeviation=0.02           # [-] relative, on refDPdL

. "$here/lib/caseSteps.sh"
startCase endToEndSpheres

total=$(date +%s.%N)
echo "endToEndSpheres in $work"

run rbdPackBed rbdPackBed
[ -f postProcessing/rbdPackBed/summary ] || fail "no summary written"
releaseOverlapZero
[ -f constant/triSurface/pellets.stl ] || fail "no pellets.stl written"
grep -E '^(pellets|bedHeight|bulkPorosity|bedPorosity) ' \
    postProcessing/rbdPackBed/summary | sed 's/^/    /'

# within: VALUE REFERENCE RELATIVE-TOLERANCE
within() { awk -v v="$1" -v r="$2" -v t="$3" \
               'BEGIN {exit !(v != "" && v - r <= t*r && r - v <= t*r)}'; }
h="$(foamDictionary -entry bedHeight -value postProcessing/rbdPackBed/summary 2>/dev/null)"
e="$(foamDictionary -entry bedPorosity -value postProcessing/rbdPackBed/summary 2>/dev/null)"
within "$h" $refBedHeight 1e-4 && within "$e" $refBedPorosity 1e-4 \
    || fail "not the recorded bed: bedHeight ${h:-?} m, bedPorosity ${e:-?}" \
            "(recorded $refBedHeight m, $refBedPorosity); the packing of" \
            "seed 1 changed, and the regression value of the pressure drop" \
            "with it: see the header of $0"

for f in system/blockMeshDict system/surfaceFeatureExtractDict \
         system/snappyHexMeshDict system/decomposeParDict \
         system/controlDict system/fvSchemes system/fvSolution \
         constant/transportProperties constant/turbulenceProperties 0/U 0/p
do
    [ -f "$f" ] || fail "rbdPackBed did not write $f"
    foamDictionary -expand "$f" > /dev/null 2>&1 \
        || fail "foamDictionary -expand $f"
done

meshCase

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

dPdL="$(foamDictionary -entry dPdLSimulated -value \
        postProcessing/pressureDrop/comparison 2>/dev/null)"
ratio="$(foamDictionary -entry ratioEisfeldSchnitzlein -value \
         postProcessing/pressureDrop/comparison 2>/dev/null)"
[ -n "$dPdL" ] || fail "no dPdLSimulated in the comparison"
within "$dPdL" $refDPdL $maxDeviation \
    || fail "simulated dP/(rho L) = $dPdL m/s^2, not within" \
            "$maxDeviation of the recorded $refDPdL (simulated/E-S ${ratio:-?})"
echo "    simulated dP/(rho L) = $dPdL m/s^2 (recorded $refDPdL," \
     "allowed +- $maxDeviation relative); simulated/E-S = ${ratio:-?}"

awk -v t="$total $(date +%s.%N)" 'BEGIN {split(t, a, " ");
    printf "    %-26s %6.1f s\n", "total", a[2] - a[1]}'

cd / && rm -rf "$work"
echo "endToEndSpheres: OK"

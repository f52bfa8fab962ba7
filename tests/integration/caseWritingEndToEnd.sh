#!/bin/bash
#------------------------------------------------------------------------------
# End to end check of src/rbdPacking/caseWriting: a hand-placed bed of 18
# spheres (dp = 10 mm) in a tube of D = 4 dp is written by bedCaseWriter
# (through build/tests/caseWritingDriver), then meshed and solved with
# Debian's OpenFOAM v1912 and no hand editing:
#     foamDictionary -expand on every written dictionary
#     blockMesh, surfaceFeatureExtract, snappyHexMesh -overwrite
#     checkMesh: 'Mesh OK.' and patches exactly inlet outlet pellets wall
#     simpleFoam -dry-run; decomposePar and mpirun -np 2 simpleFoam
#     -parallel -dry-run (the decomposition works); simpleFoam (serial:
#     on a shared 2-core machine two ranks wait on each other, 3x slower)
#     pressureDropComparison: finite, positive dP/L over the packed section
# Prints the time of every step. Runs in a temporary directory, removed on
# success, kept (and named) on failure. About 50 s on this machine.
#
# Usage: bash tests/integration/caseWritingEndToEnd.sh    (after etc/bashrc)
#------------------------------------------------------------------------------
set -u

: "${RBD_PACKING_DIR:?source etc/bashrc first}"
driver="$RBD_PACKING_DIR/build/tests/caseWritingDriver"
if [ ! -x "$driver" ]
then
    echo "caseWritingEndToEnd: no $driver; run ./Allwmake first" 1>&2
    exit 1
fi

work="$(mktemp -d "${TMPDIR:-/tmp}/caseWritingEndToEnd.XXXXXX")"
cd "$work" || exit 1

fail()
{
    echo "caseWritingEndToEnd: FAILED: $*" 1>&2
    echo "caseWritingEndToEnd: case kept in $work" 1>&2
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
        'BEGIN {split(t, a, " "); printf "    %-22s %6.1f s\n", n, a[2] - a[1]}'
}

total=$(date +%s.%N)
echo "caseWritingEndToEnd in $work"

run write "$driver" write . "nIterations 300; nProcessors 2;"

for f in system/* constant/transportProperties \
         constant/turbulenceProperties 0/U 0/p
do
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

# Missing boundary entries etc. show here in seconds
run simpleFoam.dryRun simpleFoam -dry-run

run decomposePar decomposePar -force
mpiFlags=""
[ "$(id -u)" = 0 ] && mpiFlags="$mpiFlags --allow-run-as-root"
[ "$(nproc)" -lt 2 ] && mpiFlags="$mpiFlags --oversubscribe"
run simpleFoam.parallelDryRun \
    mpirun $mpiFlags -np 2 simpleFoam -parallel -dry-run
run simpleFoam simpleFoam
grep -E 'SIMPLE solution converged|^End' log.simpleFoam | head -1
grep -q '^End' log.simpleFoam || fail "simpleFoam did not finish"

run pressureDrop "$driver" compare .
sed -n '/^Pressure drop/,$p' log.pressureDrop

awk -v t="$total $(date +%s.%N)" 'BEGIN {split(t, a, " ");
    printf "    %-22s %6.1f s\n", "total", a[2] - a[1]}'

cd / && rm -rf "$work"
echo "caseWritingEndToEnd: OK"

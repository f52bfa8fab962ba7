#------------------------------------------------------------------------------
# Sourced by the end-to-end scripts: startCase NAME (the tools on PATH,
# cases/NAME copied into a new temporary $work, cd there, $testName NAME),
# fail MESSAGE (prints it, keeps the case, exits 1),
# run STEP COMMAND... (logs to log.STEP, prints its time, fails with the
# log's tail when the command fails) and meshCase (blockMesh,
# surfaceFeatureExtract, snappyHexMesh, checkMesh: 'Mesh OK.' and exactly
# the patches inlet, outlet, pellets and wall), releaseOverlapZero (the
# summary's releaseOverlap is 0: lib/summary.sh).
#------------------------------------------------------------------------------
. "$(dirname "${BASH_SOURCE[0]}")/summary.sh"
caseStepsLib="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

startCase()
{
    testName="$1"
    local app
    for app in rbdPackBed rbdPressureDrop blockMesh snappyHexMesh simpleFoam
    do
        if ! command -v "$app" >/dev/null 2>&1
        then
            echo "$testName: no $app on PATH (./Allwmake, etc/bashrc)" 1>&2
            exit 1
        fi
    done
    work="$(mktemp -d "${TMPDIR:-/tmp}/$testName.XXXXXX")"
    cp -r "$caseStepsLib/../cases/$testName/." "$work"
    cd "$work" || exit 1
}

fail()
{
    echo "$testName: FAILED: $*" 1>&2
    echo "$testName: case kept in $work" 1>&2
    exit 1
}

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

meshCase()
{
    run blockMesh blockMesh
    run surfaceFeatureExtract surfaceFeatureExtract
    run snappyHexMesh snappyHexMesh -overwrite
    run checkMesh checkMesh

    # checkMesh exits 0 even when a check fails
    grep -q '^Mesh OK\.' log.checkMesh \
        || fail "checkMesh did not say 'Mesh OK.'"
    local patches
    patches="$(awk '/Patch +Faces +Points/ {on=1; next}
                    on && NF == 0 {exit}
                    on {print $1}' log.checkMesh | sort | tr '\n' ' ')"
    [ "$patches" = "inlet outlet pellets wall " ] \
        || fail "patches are '$patches', not 'inlet outlet pellets wall'"
    grep -E '^ +cells:' log.checkMesh
}

releaseOverlapZero()
{
    local v
    v="$(releaseOverlapOf postProcessing/rbdPackBed/summary)"
    [ "$v" = 0 ] || fail "releaseOverlap ${v:-missing} in the summary: a" \
        "pellet was released into another or into the container"
    echo "    releaseOverlap 0"
}

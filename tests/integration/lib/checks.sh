#------------------------------------------------------------------------------
# Sourced by the integration scripts: a temporary directory $tmp (removed on
# exit), and check NAME CONDITION, which prints ok/FAIL and sets $fail.
# Every check of a run includes the run's exit status (saved in a variable
# right after it, not read as $? inside the condition) and that the outputs
# it reads exist, so that a crashed run never passes a check.
# At exit, every summary written under $tmp must hold releaseOverlap 0 (no
# pellet released into another or the container; for scheme placement at
# most the touching gap: lib/summary.sh): a check
# of every packing the scripts run, which fails the script otherwise.
#------------------------------------------------------------------------------
. "$(dirname "${BASH_SOURCE[0]}")/summary.sh"
tmp="$(mktemp -d)"
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }

# releaseOverlapsZero: the check of every summary under $tmp
releaseOverlapsZero()
{
    local s v n=0 bad=0
    while IFS= read -r s
    do
        n=$((n + 1))
        v="$(releaseOverlapOf "$s")"
        if ! releaseOverlapAllowed "$s"
        then
            echo "FAIL: releaseOverlap ${v:-missing} in ${s#$tmp/}"
            bad=1
        fi
    done < <(find "$tmp" -path '*/postProcessing/rbdPackBed/summary' \
                 2>/dev/null)
    [ $n -eq 0 ] || [ $bad -eq 1 ] \
        || echo "ok: releaseOverlap as the loading allows in all $n summaries written (0; scheme placement: within the touching gap)"
    return $bad
}
trap 'rc=$?; releaseOverlapsZero || rc=1; rm -rf "$tmp"; exit $rc' EXIT
# The exit status of a run that reaches endTime without settling: the one
# place to change when that status changes
unsettledStatus=1
